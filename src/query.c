/*
 * query.c -- the public calls that read the triangulation without changing
 * it: a vertex's point, a snapshot of the cells with their neighbours,
 * the cells around a vertex, exact point location and the exact nearest
 * vertex (dtdel.h).  Each answer is in input indices, -1 for the infinite
 * vertex; none changes the triangulation (the location grid apart, which
 * is scratch: mesh/locate.c).
 */
#include "delete/delete.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static dd_status check_point(dd_tri *t, const double p[3])
{
    for (int c = 0; c < 3; c++) {
        if (isnan(p[c])) return dd_fail(t, DD_ERR_NAN, "coordinate %c of the query is NaN", "xyz"[c]);
        if (isinf(p[c])) return dd_fail(t, DD_ERR_INFINITE, "coordinate %c of the query is infinite", "xyz"[c]);
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
    uint32_t *number = malloc(((size_t)t->ncell + 1) * sizeof *number);
    int32_t *v = malloc(4 * ((size_t)t->nlive + 1) * sizeof *v), *n = malloc(4 * ((size_t)t->nlive + 1) * sizeof *n);
    if (!number || !v || !n) {
        free(number), free(v), free(n);
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
    free(number);
    *verts = v;
    *nbrs = n;
    *ncells = k;
    return DD_OK;
}

uint32_t dd_incident_cells(dd_tri *t, uint32_t v, int32_t (*out)[4], uint32_t max)
{
    dd_del *d;
    if (dd_del_star_of(t, v, &d) != DD_OK) return 0;
    for (size_t k = 0; k < d->star.n && k < max; k++)
        for (int i = 0; i < 4; i++) out[k][i] = dd_input_index(t, dd_tv(t, d->star.a[k])[i]);
    return (uint32_t)d->star.n;
}

/* The cell of p (dd_walk_locate from a start near p). */
static dd_status locate_cell(dd_tri *t, const double p[3], uint32_t *cell)
{
    t->err[0] = 0;
    dd_status s = check_point(t, p);
    if (s != DD_OK) return s;
    if ((s = dd_grid_ready(t)) != DD_OK) return dd_fail(t, s, "out of memory");
    return dd_walk_locate(t, p, dd_start_near(t, p), cell);
}

dd_status dd_locate(dd_tri *t, const double p[3], int32_t cell[4])
{
    uint32_t c;
    dd_status s = locate_cell(t, p, &c);
    if (s != DD_OK) return dd_end_call(t, s);
    for (int i = 0; i < 4; i++) cell[i] = dd_input_index(t, dd_tv(t, c)[i]);
    return DD_OK;
}

dd_status dd_nearest_vertex(dd_tri *t, const double p[3], uint32_t *v)
{
    uint32_t c, w;
    dd_status s = locate_cell(t, p, &c);
    if (s == DD_OK) s = dd_nearest_from(t, p, c, &w);
    if (s == DD_OK) *v = t->v2in[w];
    return dd_end_call(t, s);
}
