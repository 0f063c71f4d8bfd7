/*
 * weighted.c -- the public calls of dtdel.h on weighted points (DESIGN
 * 12): whether t is weighted, a point's weight, the hidden points, and
 * the insertion of a weighted point.  Thin: the mesh layer inserts
 * (regular.c) and keeps the hidden points (hidden.c).
 */
#include "dtdel.h"
#include "mesh/mesh.h"
#include "mesh/hidden.h"
#include "api/api_int.h"

#include <math.h>
#include <string.h>

int dd_is_weighted(const dd_tri *t) { return t->wt != NULL; }

dd_status dd_weight(const dd_tri *t, uint32_t i, double *w)
{
    if (i >= t->np) return DD_ERR_ARG;
    *w = t->wt ? t->wt[t->in2v[i]] : 0;
    return DD_OK;
}

int dd_is_hidden(const dd_tri *t, uint32_t i)
{
    if (i >= t->np) return 0;
    const uint32_t v = t->in2v[i];
    return t->v2in[v] == i && dd_hidden_has(t, v);
}

dd_status dd_hidden(const dd_tri *t, uint32_t **idx, size_t *n) { return dd_hidden_inputs(t, idx, n); }

/* The new point takes the next vertex id and input index (indices are
 * never reused on a weighted t: deletion is not there yet, and a point
 * forgotten keeps its index).  A vertex's exact weighted point takes
 * none: *index names that vertex and nothing changes, as CGAL's insert
 * returns it (an exact copy of a hidden point is hidden, under its own
 * index, as in CGAL).                                                   */
static dd_status insert_weighted(dd_tri *t, const double p[3], double w, dd_cell_id hint, uint32_t *index)
{
    if (!t->wt)
        return dd_fail(t, DD_ERR_UNSUPPORTED, "dd_insert_weighted needs a weighted triangulation (dd_create_ex)");
    uint32_t start;
    dd_status s = dd_insert_start(t, p, hint, &start);
    if (s != DD_OK) return s;
    if (isnan(w)) return dd_fail(t, DD_ERR_NAN, "the weight is NaN");
    if (isinf(w)) return dd_fail(t, DD_ERR_INFINITE, "the weight is infinite");
    s = dd_reserve_vertex(t);
    if (s != DD_OK) return dd_fail(t, s, "out of memory or too many points");
    const uint32_t v = t->nvid;
    memcpy(t->xyz + 3 * (size_t)v, p, 3 * sizeof *p);
    t->wt[v] = w;
    t->vcell[v] = DD_NONE;
    t->v2in[v] = t->np;
    dd_fate fate;
    uint32_t dup = DD_NONE;
    if ((s = dd_insert_power(t, v, start, 1, &fate, &dup)) != DD_OK) return s;
    if (fate == DD_FATE_DUPLICATE) {          /* nothing changed: that vertex */
        *index = t->v2in[dup];
        return DD_OK;
    }
    t->in2v[t->np] = v;
    t->nvid++;
    if (fate == DD_FATE_VERTEX) dd_grid_note(t, v);
    *index = t->np++;
    return DD_OK;
}

dd_status dd_insert_weighted_from(dd_tri *t, const double p[3], double w, dd_cell_id hint, uint32_t *index)
{
    dd_edit_begin(t);
    return dd_edit_end(t, insert_weighted(t, p, w, hint, index));
}

dd_status dd_insert_weighted(dd_tri *t, const double p[3], double w, uint32_t *index)
{
    return dd_insert_weighted_from(t, p, w, -1, index);
}
