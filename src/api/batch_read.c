/*
 * batch_read.c -- the whole-array reads of dtdel.h: dd_locate_many,
 * dd_nearest_many, dd_points, dd_cells_vertices.  Read-only like query.c:
 * the scratch (a dd_reader a thread, the order of the queries) is the
 * call's own, so any number may run at once on one triangulation.  The
 * queries go in chunks to the triangulation's threads (dd_set_threads).
 */
#include "dtdel.h"
#include "mesh/mesh.h"
#include "mesh/hidden.h"
#include "dtdel/alloc.h"

#include <math.h>
#include <string.h>

static int bad_point(const double *p, dd_status *s)
{
    for (int c = 0; c < 3; c++)
        if (!isfinite(p[c])) {
            if (*s == DD_OK) *s = isnan(p[c]) ? DD_ERR_NAN : DD_ERR_INFINITE;
            return 1;
        }
    return 0;
}

/* Queries in a chunk: each chunk's walks start afresh (dd_start_near,
 * the reader's generator reset), so the answers do not depend on which
 * thread took the chunk, nor on how many there are.                     */
#define READ_CHUNK 4096u

/* One call's queries, in Hilbert order (ids[0..k)), chunk by chunk. */
typedef struct read_job {
    const dd_tri *t;
    const double *xyz;
    const uint32_t *ids;
    uint32_t k;
    dd_cell_id *cells;
    uint32_t *nearest;
    unsigned nth;
    dd_status *st;            /* a status a thread */
} read_job;

/* Chunk `ch`'s queries with reader r; DD_ERR_NOMEM. */
static dd_status answer_chunk(const read_job *b, dd_reader *r, uint32_t ch)
{
    const dd_tri *t = b->t;
    const uint32_t j0 = ch * READ_CHUNK, j1 = b->k - j0 < READ_CHUNK ? b->k : j0 + READ_CHUNK;
    r->rng = 0x9E3779B97F4A7C15ull;
    uint32_t c = dd_start_near(t, b->xyz + 3 * (size_t)b->ids[j0]);
    for (uint32_t j = j0; j < j1; j++) {
        const uint32_t i = b->ids[j];
        const double *p = b->xyz + 3 * (size_t)i;
        if (j + 1 < j1) __builtin_prefetch(b->xyz + 3 * (size_t)b->ids[j + 1]);
        dd_status s = dd_walk_read(t, r, p, c, &c);
        if (s != DD_OK) return s;
        if (b->cells) b->cells[i] = (dd_cell_id)c;
        if (!b->nearest) continue;
        uint32_t v;
        s = t->wt ? dd_nearest_power_from(t, r, p, c, &v) : dd_nearest_from(t, r, p, c, &v);
        if (s != DD_OK) return s;
        b->nearest[i] = t->v2in[v];
    }
    return DD_OK;
}

/* Thread j: chunks j, j + nth, ... */
static void answer_chunks(void *arg, unsigned j)
{
    const read_job *b = arg;
    dd_reader r;
    dd_reader_init(&r);
    dd_status s = DD_OK;
    for (uint32_t ch = j, nch = (b->k + READ_CHUNK - 1) / READ_CHUNK; ch < nch && s == DD_OK; ch += b->nth)
        s = answer_chunk(b, &r, ch);
    dd_reader_done(&r);
    b->st[j] = s;
}

/* Locates the m queries along a Hilbert curve, each walk from the last
 * answer of its chunk; cells[i] (when not NULL) the cell of query i,
 * nearest[i] (when not NULL) its nearest vertex's input index.  The
 * chunks go to t's threads.                                             */
static dd_status query_many(const dd_tri *t, const double *xyz, size_t m, dd_cell_id *cells, uint32_t *nearest)
{
    if (m == 0) return DD_OK;
    if (m >= UINT32_MAX - 8) return DD_ERR_NOMEM;
    uint32_t *ids = dd_malloc(m * sizeof *ids);
    if (!ids) return DD_ERR_NOMEM;
    dd_status bad = DD_OK;
    uint32_t k = 0;
    for (uint32_t i = 0; i < (uint32_t)m; i++) {
        if (!bad_point(xyz + 3 * (size_t)i, &bad)) ids[k++] = i;
        else if (cells) cells[i] = -1;
        else nearest[i] = UINT32_MAX;
    }
    const uint32_t nch = (k + READ_CHUNK - 1) / READ_CHUNK;
    read_job b = {t, xyz, ids, k, cells, nearest, t->nthreads < nch ? t->nthreads : nch, NULL};
    if (b.nth < 1) b.nth = 1;
    b.st = dd_malloc(b.nth * sizeof *b.st);
    if (!b.st || dd_spatial_order_threads(xyz, ids, k, 0, t->nthreads) != DD_OK) {
        dd_mfree(ids);
        dd_mfree(b.st);
        return DD_ERR_NOMEM;
    }
    dd_status s = DD_OK;
    if (k > 0) {
        dd_run_threads(b.nth, answer_chunks, &b);
        for (unsigned j = 0; j < b.nth; j++)
            if (b.st[j] != DD_OK) s = b.st[j];
    }
    dd_mfree(b.st);
    dd_mfree(ids);
    return s != DD_OK ? s : bad;
}

dd_status dd_locate_many(const dd_tri *t, const double *xyz, size_t m, dd_cell_id *cells)
{
    return query_many(t, xyz, m, cells, NULL);
}

dd_status dd_nearest_many(const dd_tri *t, const double *xyz, size_t m, uint32_t *nearest)
{
    return query_many(t, xyz, m, NULL, nearest);
}

dd_status dd_points(const dd_tri *t, double *xyz, double *w)
{
    for (uint32_t i = 0; i < t->np; i++) {
        const uint32_t v = t->in2v[i];
        const int there = v != DD_NONE && (t->vcell[v] != DD_NONE || dd_hidden_has(t, v));
        double *x = xyz + 3 * (size_t)i;
        if (there) memcpy(x, dd_pt(t, v), 3 * sizeof *x);
        else x[0] = x[1] = x[2] = NAN;
        if (w) w[i] = !there ? NAN : t->wt ? t->wt[v] : 0.0;
    }
    return DD_OK;
}

dd_status dd_cells_vertices(const dd_tri *t, const dd_cell_id *ids, size_t n, int32_t *verts)
{
    for (size_t k = 0; k < n; k++) {
        const dd_cell_id c = ids[k];
        if (!dd_cell_alive(t, c)) return DD_ERR_UNKNOWN_CELL;
        const uint32_t *tv = dd_tv(t, (uint32_t)c);
        for (int i = 0; i < 4; i++) verts[4 * k + (size_t)i] = dd_input_index(t, tv[i]);
    }
    return DD_OK;
}
