/*
 * batch_read.c -- the whole-array reads of dtdel.h: dd_locate_many,
 * dd_nearest_many, dd_points, dd_cells_vertices.  Read-only like query.c:
 * the scratch (a dd_reader, the order of the queries) is the call's own,
 * so any number may run at once on one triangulation.
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

/* Locates the m queries along a Hilbert curve, each walk from the last
 * answer; cells[i] (when not NULL) the cell of query i, nearest[i] (when
 * not NULL) its nearest vertex's input index.                           */
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
    if (dd_spatial_order(xyz, ids, k, 0) != DD_OK) {
        dd_mfree(ids);
        return DD_ERR_NOMEM;
    }
    dd_reader r;
    dd_reader_init(&r);
    dd_status s = DD_OK;
    uint32_t c = k ? dd_start_near(t, xyz + 3 * (size_t)ids[0]) : DD_NONE;
    for (uint32_t j = 0; j < k && s == DD_OK; j++) {
        const uint32_t i = ids[j];
        const double *p = xyz + 3 * (size_t)i;
        if (j + 1 < k) __builtin_prefetch(xyz + 3 * (size_t)ids[j + 1]);
        s = dd_walk_read(t, &r, p, c, &c);
        if (s != DD_OK) break;
        if (cells) cells[i] = (dd_cell_id)c;
        if (!nearest) continue;
        uint32_t v;
        s = t->wt ? dd_nearest_power_from(t, &r, p, c, &v) : dd_nearest_from(t, &r, p, c, &v);
        if (s == DD_OK) nearest[i] = t->v2in[v];
    }
    dd_reader_done(&r);
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
