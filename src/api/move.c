/*
 * move.c -- dd_move and dd_move_weighted: a vertex moved to a new point
 * (and weight), keeping its index.
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
 *
 * On a weighted t (DESIGN 12, issue 44) the reference is a removal of v
 * then an insertion of the new weighted point: in keep mode the regular
 * triangulation of the moved point set, in discard mode also what is
 * forgotten (the points the new one hides once v is gone, or the new one
 * itself).  Two courses:
 *  1. the relocation filter and a few 2-3 and 3-2 flips with power tests
 *     (mesh/flip.c, dd_move_power_by_flips): when v's star stays
 *     positive (or is made so by flipping away a turned cell or two
 *     first), the flips make every facet locally regular and every
 *     kept hidden point stays hidden (re-homed in the cells flipped),
 *     nothing is hidden anew: the reference's state, O(star) plus O(1)
 *     a flip;
 *  2. else exactly the reference's order: v deleted with the default
 *     strategy (its star's hidden points come back or are re-homed),
 *     then its id inserted at (p, w) by CGAL's rule, which may hide it,
 *     or hide others.  Removing first is what makes discard mode right:
 *     inserting first could forget a vertex that only v's presence hid.
 *     An insertion that fails puts v back where it was (the regular
 *     triangulation of the points in t is unique, and in discard mode v
 *     put back hides nothing).  Where removing v first would leave fewer
 *     than 4 or only coplanar points, the moved set is rebuilt instead
 *     (move_by_rebuild: CGAL's result, through its lower dimensions).
 * A kept hidden point moves too: forgotten, then inserted at (p, w).
 */
#include "dtdel.h"
#include "delete/delete.h"
#include "mesh/hidden_move.h"

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

/* ---- weighted moves ------------------------------------------------------ */

/* Inserts id v, its point and weight written, by CGAL's rule, the walk
 * from `start`; a duplicate of a vertex's weighted point is refused
 * (DD_ERR_DUPLICATE) with nothing changed.  *vertex: v is a vertex.    */
static dd_status insert_moved(dd_tri *t, uint32_t v, uint32_t start, int *vertex)
{
    dd_fate fate;
    uint32_t dup = DD_NONE;
    dd_status s = dd_insert_power(t, v, start, 0, &fate, &dup);
    if (s == DD_OK && fate == DD_FATE_DUPLICATE)
        return dd_fail(t, DD_ERR_DUPLICATE, "moving point %u: the new weighted point is point %u's", t->v2in[v],
                       t->v2in[dup]);
    *vertex = s == DD_OK && fate == DD_FATE_VERTEX;
    return s;
}

/* Writes (p, w) as id v's point and weight. */
static void set_point(dd_tri *t, uint32_t v, const double p[3], double w)
{
    memcpy(t->xyz + 3 * (size_t)v, p, 3 * sizeof *p);
    t->wt[v] = w;
}

/* Kept hidden point v moved: forgotten, then inserted at (p, w); on a
 * failure put back in its cell (the room it used is still there).     */
static dd_status move_hidden(dd_tri *t, uint32_t v, const double p[3], double w)
{
    const double old[3] = {dd_pt(t, v)[0], dd_pt(t, v)[1], dd_pt(t, v)[2]}, wold = t->wt[v];
    uint32_t cell;
    int vertex = 0;
    dd_hidden_forget(t, v, &cell);
    set_point(t, v, p, w);
    dd_status s = insert_moved(t, v, cell, &vertex);
    if (s != DD_OK) {
        set_point(t, v, old, wold);
        (void)dd_hidden_add(t, cell, v);
        return s;
    }
    if (vertex) dd_grid_note(t, v);
    return DD_OK;
}

/* The vertex other than v whose weighted point is exactly (p, w), or
 * DD_NONE: a vertex's position lies in a cell's closure only as one of
 * its corners, so the cell a walk from v's star finds for p tells.  A
 * walk that does not end answers DD_NONE (the insertion reports it).  */
static uint32_t vertex_with(dd_tri *t, uint32_t v, const double p[3], double w)
{
    uint32_t c;
    if (dd_walk_locate(t, p, t->vcell[v], &c) != DD_OK || dd_is_outer_cell(t, c)) return DD_NONE;
    for (int k = 0; k < 4; k++) {
        const uint32_t u = dd_tv(t, c)[k];
        const double *x = dd_pt(t, u);
        if (u != v && x[0] == p[0] && x[1] == p[1] && x[2] == p[2] && t->wt[u] == w) return u;
    }
    return DD_NONE;
}

/* Course 2 where removing v first would leave fewer than 4 or only
 * coplanar points (nothing changed yet): CGAL's remove() drops to
 * dimension 2 or less, re-inserts the hidden points, and the insertion
 * of (p, w) raises the dimension again.  Each of those steps gives the
 * regular triangulation of the points it has, so its result is the
 * regular triangulation of the moved point set, here rebuilt from
 * scratch (mesh/rebuild_power.c) with v at (p, w): in keep mode the
 * unique one, with the same hidden set.  In discard mode nothing is
 * forgotten on either side: the points left other than v span a plane
 * (or a triangle) on which they are all vertices, and a point off that
 * plane hides none of them, nor is it hidden (it is an extreme point),
 * which is CGAL's cone from (p, w) over the plane.  Every finite cell
 * holds v here, so the deletion would have been O(n) too; the rebuild
 * is O(n log n).  A moved set that is still coplanar is refused
 * (DD_ERR_DIMENSION, as CGAL ends in dimension 2); so is an exact copy
 * of a weighted point among the hidden points (DD_ERR_DUPLICATE: the
 * rebuild cannot order them as CGAL's re-insertion does; another
 * vertex's point is refused by the caller first).  A failure leaves
 * t as it was.                                                         */
static dd_status move_by_rebuild(dd_tri *t, uint32_t v, const double p[3], double w)
{
    const double old[3] = {dd_pt(t, v)[0], dd_pt(t, v)[1], dd_pt(t, v)[2]}, wold = t->wt[v];
    set_point(t, v, p, w);
    dd_status s = dd_rebuild_power_without(t, NULL, 0);
    if (s == DD_OK) {
        if (t->vcell[v] != DD_NONE) dd_grid_note(t, v);
        t->moves_redone++;
        return DD_OK;
    }
    set_point(t, v, old, wold);
    if (s == DD_ERR_COPLANAR || s == DD_ERR_COLLINEAR || s == DD_ERR_TOO_FEW)
        return dd_fail(t, DD_ERR_DIMENSION, "moving point %u would leave only coplanar points", t->v2in[v]);
    if (s == DD_ERR_DUPLICATE)
        return dd_fail(t, s, "moving point %u: the moved point set, rebuilt as removing it first would leave "
                       "fewer than 4 or only coplanar points, holds two equal weighted points", t->v2in[v]);
    return s;
}

/* Course 2 of a weighted move (see the top): v deleted, then inserted at
 * (p, w); a failure of the insertion puts v back.  Onto another vertex's
 * weighted point it is refused before the deletion, as the reference
 * refuses it with nothing changed: deleting first would forget for good
 * the exact copies of the points the deletion releases (delete.c).  Onto
 * a point the deletion itself releases, the insertion is refused after
 * it, as CGAL's remove() then insert() are, and v is put back.  inside:
 * the flips' star test showed that no vertex but v has point p (hidden_move.h,
 * dd_move_power_by_flips), so the walk that looks for one is skipped.   */
static dd_status move_by_removal(dd_tri *t, uint32_t v, const double p[3], double w, int inside)
{
    const double old[3] = {dd_pt(t, v)[0], dd_pt(t, v)[1], dd_pt(t, v)[2]}, wold = t->wt[v];
    const uint32_t dup = inside ? DD_NONE : vertex_with(t, v, p, w);
    if (dup != DD_NONE)
        return dd_fail(t, DD_ERR_DUPLICATE, "moving point %u: the new weighted point is point %u's", t->v2in[v],
                       t->v2in[dup]);
    dd_status s = dd_del_vertex(t, v, dd_variant_table[0]);
    if (s == DD_ERR_DIMENSION) return move_by_rebuild(t, v, p, w);
    if (s != DD_OK) return s;
    set_point(t, v, p, w);
    int vertex = 0;
    s = insert_moved(t, v, t->hint, &vertex);
    if (s != DD_OK) {
        char why[sizeof t->err];
        memcpy(why, t->err, sizeof why);
        set_point(t, v, old, wold);
        int back = 0;
        if (insert_moved(t, v, t->hint, &back) != DD_OK || !back)
            return dd_fail(t, DD_ERR_INTERNAL, "moving point %u failed and could not be undone: %s", t->v2in[v], why);
        memcpy(t->err, why, sizeof why);
        return s;
    }
    if (vertex) dd_grid_note(t, v);
    t->moves_redone++;
    return DD_OK;
}

static dd_status check_point(dd_tri *t, const double p[3])
{
    for (int c = 0; c < 3; c++) {
        if (isnan(p[c])) return dd_fail(t, DD_ERR_NAN, "coordinate %c of the new point is NaN", "xyz"[c]);
        if (isinf(p[c])) return dd_fail(t, DD_ERR_INFINITE, "coordinate %c of the new point is infinite", "xyz"[c]);
    }
    return DD_OK;
}

/* Asks for vertex id v (a vertex id, not DD_NONE) 's words the move
 * reads next, at once: each is in an array of its own, and v is anywhere
 * in the mesh.  No weights on an unweighted t; no word of hidden.c (a
 * vertex is found no hidden point by its vcell).                       */
static void prefetch_vertex(const dd_tri *t, uint32_t v)
{
    __builtin_prefetch(t->v2in + v);
    __builtin_prefetch(t->vcell + v);
    __builtin_prefetch(t->xyz + 3 * (size_t)v);
    __builtin_prefetch(t->xyz + 3 * (size_t)v + 2);
    if (t->wt) __builtin_prefetch(t->wt + v);
}

/* dd_move_weighted; keep_weight: dd_move's (w ignored, v's kept). */
static dd_status move_weighted(dd_tri *t, uint32_t input, const double p[3], double w, int keep_weight)
{
    if (!t->wt)
        return dd_fail(t, DD_ERR_UNSUPPORTED, "dd_move_weighted needs a weighted triangulation (dd_create_ex)");
    dd_status s = check_point(t, p);
    if (s != DD_OK) return s;
    uint32_t v = input < t->np ? t->in2v[input] : DD_NONE;
    if (v != DD_NONE) prefetch_vertex(t, v);
    /* a vertex (vcell set) is no hidden point: its hidden.c word unread */
    const int hidden = v != DD_NONE && t->v2in[v] == input && t->vcell[v] == DD_NONE && dd_hidden_has(t, v);
    if (!hidden && (s = dd_del_resolve(t, input, &v)) != DD_OK) return s;
    if (keep_weight) w = t->wt[v];
    if (isnan(w)) return dd_fail(t, DD_ERR_NAN, "the new weight is NaN");
    if (isinf(w)) return dd_fail(t, DD_ERR_INFINITE, "the new weight is infinite");
    const double *x = dd_pt(t, v);
    if (x[0] == p[0] && x[1] == p[1] && x[2] == p[2] && t->wt[v] == w) return DD_OK;
    if (hidden) return move_hidden(t, v, p, w);
    int flips, inside;
    if (dd_move_power_by_flips(t, v, p, w, &flips, &inside, &s)) {
        dd_grid_note(t, v);
        if (flips) t->moves_flipped++;
        else t->moves_kept++;
        return DD_OK;
    }
    if (s != DD_OK) return dd_fail(t, s, "out of memory");
    return move_by_removal(t, v, p, w, inside);
}

dd_status dd_move_weighted(dd_tri *t, uint32_t v, const double p[3], double w)
{
    dd_edit_begin(t);
    return dd_edit_end(t, move_weighted(t, v, p, w, 0));
}

/* ---- dd_move ----------------------------------------------------------------- */

static dd_status move_vertex(dd_tri *t, uint32_t input, const double p[3])
{
    if (t->wt) return move_weighted(t, input, p, 0.0, 1);
    if (input < t->np && t->in2v[input] != DD_NONE) prefetch_vertex(t, t->in2v[input]);
    dd_status s = check_point(t, p);
    if (s != DD_OK) return s;
    uint32_t v;
    s = dd_del_resolve(t, input, &v);
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
