/*
 * hidden_move.h -- what the weighted edits of issue 44 need from the mesh
 * beyond an insertion and a deletion: a kept hidden point forgotten (a
 * hidden point deleted), a weighted move repaired by flips (the
 * relocation filter and flip.c's loop with power tests, and the hidden
 * points of the cells flipped), and the regular
 * triangulation rebuilt without a set of points (dd_delete_set's other
 * course).  Hidden points stay hidden.c's: this file reads its lists
 * (hidden.h's dd_hidset) and changes them only through the same steps.
 */
#ifndef DD_HIDDEN_MOVE_H
#define DD_HIDDEN_MOVE_H

#include "mesh/mesh.h"
#include "mesh/hidden.h"

/* A small set of cell ids on the stack, for flip.c's repair: open
 * addressing over DD_SET_SLOTS slots, DD_NONE empty (memset to 0xff),
 * never more than half full (the caller bounds it).  It stands in for
 * the per-cell marks t->stamp, whose reads and writes miss the cache on
 * cells scattered through the mesh.                                    */
#define DD_SET_SLOTS 256

/* Adds cell c to set: 1 if it was not there. */
static inline int dd_cellset_add(uint32_t *set, uint32_t c)
{
    uint32_t k = (c * 0x9E3779B1u) >> 24;
    while (set[k] != DD_NONE) {
        if (set[k] == c) return 0;
        k = (k + 1) & (DD_SET_SLOTS - 1);
    }
    set[k] = c;
    return 1;
}

/* Whether cell c is in set. */
static inline int dd_cellset_has(const uint32_t *set, uint32_t c)
{
    for (uint32_t k = (c * 0x9E3779B1u) >> 24; set[k] != DD_NONE; k = (k + 1) & (DD_SET_SLOTS - 1))
        if (set[k] == c) return 1;
    return 0;
}

/* Forgets kept hidden point v (dd_hidden_has(t, v)): it leaves its
 * cell's list and the list of all; *cell receives that cell, so that
 * dd_hidden_add(t, *cell, v) puts it back (the room it used is still
 * there: that call cannot fail then).  No cell changes.  O(length of
 * its cell's list).                                                    */
void dd_hidden_forget(dd_tri *t, uint32_t v, uint32_t *cell);

/* What a weighted move changes (dd_move_power_by_flips picks it): v's
 * point, or only its weight, down or up.  A weight alone turns no cell;
 * a lighter v (lift raised) leaves the link facets of its star locally
 * regular, a heavier one (lift lowered) the hidden points of its star
 * hidden (flip.c, dd_hidden_flips_hold).                               */
enum { DD_MOVE_POINT = 1, DD_MOVE_LIGHTER = 2, DD_MOVE_HEAVIER = 3 };

/* Moves vertex v of the weighted t to (p, w) and repairs the mesh by
 * 2-3 and 3-2 flips with power tests (flip.c): 1 when that yields the
 * state a removal of v and an insertion of (p, w) reach, in either
 * hidden mode (*flips of them; 0 flips: the relocation filter), else 0
 * with the mesh, the hidden points and v's point and weight unchanged.
 * It yields that state when every star cell stays positively oriented
 * (or, v's point moved, at most DD_UNTURN_MAX turned cells are flipped
 * away first by flip.c's unturn, each flip's new cells positive: the
 * mesh is a triangulation of the same vertices again), Lawson's loop
 * ends with every facet locally regular (the mesh is then
 * the regular triangulation of its vertices: none was hidden anew, v
 * included) and, hidden points kept, each stays hidden in a cell (see
 * dd_hidden_flips_hold, which also declines a star point with v's new
 * weighted point), and no two of the star's hidden points are exact
 * copies (dd_hidden_star_copies).  Exact, perturbation included.
 * O(star) plus O(1) a flip and a hidden point of a cell flipped;
 * t->conflict as scratch; *err DD_ERR_NOMEM (and 0) when out of
 * memory.  *inside, set either way: 1 when the star test showed that no
 * vertex but v has point p (p is v's own point, or every cell of v's
 * star, after the flips that removed turned cells, is finite and
 * positively oriented with v at p: p lies inside that star, where v is
 * the only vertex), so that a removal of v and an insertion
 * of (p, w) can skip their duplicate check against other vertices.  */
int dd_move_power_by_flips(dd_tri *t, uint32_t v, const double p[3], double w, int *flips, int *inside,
                           dd_status *err);

/* 1 if the cells star[0..n) (v's star, hidden points kept) hold two
 * hidden points with the same weighted point.  A removal of v may bring
 * one back and forget the others (hidden.h: no vertex has a hidden
 * exact copy), and an insertion hide it again: a state flips cannot
 * reach, so dd_move_power_by_flips declines such a move.  0 at once
 * when v's bound nin is below 2; else O(k^2) in the k points listed.   */
int dd_hidden_star_copies(const dd_tri *t, uint32_t v, const uint32_t *star, size_t n);

/* For dd_move_power_by_flips of vertex v, hidden points kept, before
 * it commits: the cells gone[0..) (the dd_cellset gone_set, NULL when
 * gone is empty) replaced by the
 * others of made[0..), and v's point or weight changed (how, a
 * DD_MOVE_*) in the live cells of its star t->conflict.  1 if every
 * kept hidden point stays hidden: one of a live star cell still in its
 * closure (always when only the weight changed) and not in power
 * conflict with it (always when v is heavier: the lifted plane of the
 * cell at a point x of its closure moves by l_v(x) >= 0, the point's
 * barycentric coordinate, times the fall of v's lift, so x, not below
 * it before, is not below it after, with the same sign when l_v(x) =
 * 0; untested then); one of a gone cell,
 * or of a star cell that no longer holds it, in the closure of a live
 * made or star cell and not in conflict with it, that cell its new
 * home, written to homes as (point, cell) pairs.  Else 0 (a point
 * comes back, left the changed region, or carries v's new weighted
 * point); *err DD_ERR_NOMEM (and 0) when homes cannot grow.  nin[v] == 0 skips the lists of v's star.
 * Reads only.  O(star + made) a point re-homed.                       */
int dd_hidden_flips_hold(dd_tri *t, uint32_t v, const dd_vec *made, const dd_vec *gone, const uint32_t *gone_set,
                         int how, dd_vec *homes, dd_status *err);

/* After the flips committed (the cells gone[0..) dead): each point of
 * homes off its old cell's list, the gone cells' lists emptied, each
 * point of homes in its new cell's list (room reserved
 * by dd_hidden_room) and counted in its corners' stars (nin).
 * O(homes + gone).                                                    */
void dd_hidden_flips_rehome(dd_tri *t, const dd_vec *gone, const dd_vec *homes);

/* Replaces the cells of the weighted t by the regular triangulation of
 * its points but the vertex ids ids[0..n) (sorted ascending): every
 * vertex and, when hidden points are kept, every kept hidden point not
 * listed, inserted in id order (the construction's BRIO + Hilbert
 * order) by CGAL's rule into a scratch triangulation whose cells and
 * hidden points are then swapped in; the listed points are neither
 * vertices nor hidden after.  A failure changes nothing: DD_ERR_NOMEM;
 * DD_ERR_COPLANAR when the points left are (the caller checks first);
 * DD_ERR_DUPLICATE when two points left are the same weighted point
 * (the caller deletes one at a time instead).  O(kept log kept)
 * expected, as construction.                                          */
dd_status dd_rebuild_power_without(dd_tri *t, const uint32_t *ids, size_t n);

#endif
