/*
 * move.c -- dd_move: a vertex moved to a new point, keeping its index.
 *
 * Three courses, one result (DT of the moved set, CGAL's):
 *  1. the relocation filter: when no cell changes, the move only writes
 *     the point, O(star) (mesh/flip.c, with no flip);
 *  2. a few 2-3 and 3-2 flips around the moved vertex (mesh/flip.c);
 *  3. where those cannot, the new point is inserted as a temporary vertex w, walking
 *     from v's star (a small move lands next to it), v is deleted with the
 *     default strategy, and w takes v's id.  Inserting first means no
 *     deletion is ever refused for leaving too few points; a moved set
 *     that is all coplanar is refused (the insertion undone by deleting
 *     w, which restores the unique DT of the old set).
 * All or nothing: a failure leaves the triangulation as it was.
 */
#include "dtdel.h"
#include "delete/delete.h"

#include <math.h>
#include <string.h>

/* The registry (variants/registry.c): the first entry is the default. */
extern const dd_variant *const dd_variant_table[];

/* Gives vertex w's cells, point and location to v (w's id is free after):
 * the cells of star, or with star NULL every live cell, O(cells) but
 * without memory (the list of w's star could not be made).              */
static void rename_vertex(dd_tri *t, uint32_t w, uint32_t v, const dd_vec *star)
{
    const size_t n = star ? star->n : t->ncell;
    for (size_t k = 0; k < n; k++) {
        uint32_t *tv = dd_tv(t, star ? star->a[k] : (uint32_t)k);
        if (tv[0] == DD_DEAD) continue;
        for (int i = 0; i < 4; i++)
            if (tv[i] == w) tv[i] = v;
    }
    memcpy(t->xyz + 3 * (size_t)v, t->xyz + 3 * (size_t)w, 3 * sizeof *t->xyz);
    t->vcell[v] = t->vcell[w];
    t->vcell[w] = DD_NONE;
}

/* Course 2: insert p as vertex w = t->nvid (not an input index: the id
 * is borrowed), delete v, rename w to v.                                 */
static dd_status move_by_reinsertion(dd_tri *t, uint32_t v, const double p[3])
{
    dd_status s = dd_reserve_vertex(t);
    if (s != DD_OK) return dd_fail(t, s, "out of memory");
    const uint32_t w = t->nvid++;                /* an id in use until renamed */
    memcpy(t->xyz + 3 * (size_t)w, p, 3 * sizeof *p);
    t->vcell[w] = DD_NONE;
    t->v2in[w] = t->v2in[v];                     /* for messages and seeds */
    if ((s = dd_insert_vertex_at(t, w, t->vcell[v])) != DD_OK) {
        t->nvid--;
        if (s == DD_ERR_DUPLICATE)
            return dd_fail(t, s, "moving point %u: the new point is the point of another vertex", t->v2in[v]);
        return s;
    }
    const dd_variant *var = dd_variant_table[0];
    s = dd_del_vertex(t, v, var);
    if (s != DD_OK) {
        char why[sizeof t->err];
        memcpy(why, t->err, sizeof why);
        if (dd_del_vertex(t, w, var) != DD_OK)
            return dd_fail(t, DD_ERR_INTERNAL, "moving point %u failed and could not be undone: %s", t->v2in[v], why);
        t->nvid--;
        memcpy(t->err, why, sizeof why);
        if (s == DD_ERR_DIMENSION) return dd_fail(t, s, "moving point %u would leave only coplanar points", t->v2in[v]);
        return s;
    }
    /* v is gone now: the move must finish, memory or not */
    rename_vertex(t, w, v, dd_star_cells(t, w, &t->conflict) == DD_OK ? &t->conflict : NULL);
    t->nvid--;
    t->moves_redone++;
    return DD_OK;
}

static dd_status move_vertex(dd_tri *t, uint32_t input, const double p[3])
{
    if (t->wt) return dd_fail(t, DD_ERR_UNSUPPORTED, "dd_move on a weighted triangulation is not supported yet");
    for (int c = 0; c < 3; c++) {
        if (isnan(p[c])) return dd_fail(t, DD_ERR_NAN, "coordinate %c of the new point is NaN", "xyz"[c]);
        if (isinf(p[c])) return dd_fail(t, DD_ERR_INFINITE, "coordinate %c of the new point is infinite", "xyz"[c]);
    }
    uint32_t v;
    dd_status s = dd_del_resolve(t, input, &v);
    if (s != DD_OK) return s;
    const double *x = dd_pt(t, v);
    if (x[0] == p[0] && x[1] == p[1] && x[2] == p[2]) return DD_OK;
    int flips;
    if (dd_move_by_flips(t, v, p, &flips, &s)) {
        dd_grid_note(t, v);
        if (flips) t->moves_flipped++;
        else t->moves_kept++;
        return DD_OK;
    }
    if (s != DD_OK) return dd_fail(t, s, "out of memory");
    s = move_by_reinsertion(t, v, p);
    if (s == DD_OK) dd_grid_note(t, v);
    return s;
}

dd_status dd_move(dd_tri *t, uint32_t input, const double p[3])
{
    dd_edit_begin(t);
    return dd_edit_end(t, move_vertex(t, input, p));
}
