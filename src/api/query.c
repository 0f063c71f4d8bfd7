/*
 * query.c -- the public calls that read the triangulation without changing
 * it: a vertex's point, a snapshot of the cells with their neighbours,
 * the cells around a vertex, exact point location and the exact nearest
 * vertex (dtdel.h).  Each answer is in input indices, -1 for the infinite
 * vertex.  None writes to the triangulation, so any number may run at
 * once on one (dtdel.h, threads): their scratch is a dd_reader of their
 * own (mesh.h), and a failure is told by the status alone.
 */
#include "dtdel.h"
#include "delete/delete.h"
#include "dtdel/alloc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static dd_status check_point(const double p[3])
{
    for (int c = 0; c < 3; c++) {
        if (isnan(p[c])) return DD_ERR_NAN;
        if (isinf(p[c])) return DD_ERR_INFINITE;
    }
    return DD_OK;
}

dd_status dd_point(const dd_tri *t, uint32_t v, double p[3])
{
    if (v >= t->np || t->v2in[t->in2v[v]] != v || t->vcell[t->in2v[v]] == DD_NONE) return DD_ERR_UNKNOWN_VERTEX;
    memcpy(p, dd_pt(t, t->in2v[v]), 3 * sizeof *p);
    return DD_OK;
}

/* Live cells are numbered in storage order; number[c] for each. */
dd_status dd_cells(const dd_tri *t, int32_t **verts, int32_t **nbrs, size_t *ncells)
{
    *verts = *nbrs = NULL;
    *ncells = 0;
    uint32_t *number = dd_malloc(((size_t)t->ncell + 1) * sizeof *number);
    int32_t *v = dd_malloc(4 * ((size_t)t->nlive + 1) * sizeof *v), *n = dd_malloc(4 * ((size_t)t->nlive + 1) * sizeof *n);
    if (!number || !v || !n) {
        dd_mfree(number), dd_mfree(v), dd_mfree(n);
        return DD_ERR_NOMEM;
    }
    size_t k = 0;
    for (uint32_t c = 0; c < t->ncell; c++) number[c] = dd_tv(t, c)[0] == DD_DEAD ? UINT32_MAX : (uint32_t)k++;
    for (uint32_t c = 0; c < t->ncell; c++) {
        if (number[c] == UINT32_MAX) continue;
        const size_t m = number[c];
        for (int i = 0; i < 4; i++) {
            v[4 * m + i] = dd_input_index(t, dd_tv(t, c)[i]);
            n[4 * m + i] = (int32_t)number[dd_tn(t, c)[i] >> 2];
        }
    }
    dd_mfree(number);
    *verts = v;
    *nbrs = n;
    *ncells = k;
    return DD_OK;
}

uint32_t dd_incident_cells(const dd_tri *t, uint32_t v, int32_t (*out)[4], uint32_t max)
{
    const uint32_t id = dd_vertex_of(t, v);
    if (id == DD_NONE) return 0;
    dd_reader r;
    dd_reader_init(&r);
    uint32_t n = 0;
    if (dd_star_read(t, &r, id, &r.star) == DD_OK) {
        n = (uint32_t)r.star.n;
        for (size_t k = 0; k < r.star.n && k < max; k++)
            for (int i = 0; i < 4; i++) out[k][i] = dd_input_index(t, dd_tv(t, r.star.a[k])[i]);
    }
    dd_reader_done(&r);
    return n;
}

/* The cell of p (dd_walk_read from a start near p). */
static dd_status locate_cell(const dd_tri *t, dd_reader *r, const double p[3], uint32_t *cell)
{
    dd_status s = check_point(p);
    if (s != DD_OK) return s;
    return dd_walk_read(t, r, p, dd_start_near(t, p), cell);
}

dd_status dd_locate(const dd_tri *t, const double p[3], int32_t cell[4])
{
    uint32_t c;
    dd_reader r;
    dd_reader_init(&r);
    dd_status s = locate_cell(t, &r, p, &c);
    dd_reader_done(&r);
    if (s != DD_OK) return s;
    for (int i = 0; i < 4; i++) cell[i] = dd_input_index(t, dd_tv(t, c)[i]);
    return DD_OK;
}

dd_status dd_nearest_vertex(const dd_tri *t, const double p[3], uint32_t *v)
{
    uint32_t c, w;
    dd_reader r;
    dd_reader_init(&r);
    dd_status s = locate_cell(t, &r, p, &c);
    if (s == DD_OK) s = t->wt ? dd_nearest_power_from(t, &r, p, c, &w) : dd_nearest_from(t, &r, p, c, &w);
    dd_reader_done(&r);
    if (s == DD_OK) *v = t->v2in[w];
    return s;
}
