/*
 * hidden_move.h -- what the weighted edits of issue 44 need from the mesh
 * beyond an insertion and a deletion: a kept hidden point forgotten (a
 * hidden point deleted), the relocation filter of a weighted move (the
 * star's power tests and its hidden points), and the regular
 * triangulation rebuilt without a set of points (dd_delete_set's other
 * course).  Hidden points stay hidden.c's: this file reads its lists
 * (hidden.h's dd_hidset) and changes them only through the same steps.
 */
#ifndef DD_HIDDEN_MOVE_H
#define DD_HIDDEN_MOVE_H

#include "mesh/mesh.h"
#include "mesh/hidden.h"

/* Forgets kept hidden point v (dd_hidden_has(t, v)): it leaves its
 * cell's list and the list of all; *cell receives that cell, so that
 * dd_hidden_add(t, *cell, v) puts it back (the room it used is still
 * there: that call cannot fail then).  No cell changes.  O(length of
 * its cell's list).                                                    */
void dd_hidden_forget(dd_tri *t, uint32_t v, uint32_t *cell);

/* The relocation filter of a weighted move: vertex v of the weighted t
 * moved in place to (p, w) when that changes no cell and no hidden
 * point's cell, and then returns 1 (its point and weight written).
 * The test, exact and perturbed: every finite cell of v's star is
 * positively oriented with v at p; every facet of a star cell is
 * locally regular (the apex across it is not in power conflict with
 * the cell, CGAL's rule for infinite cells included); and every hidden
 * point kept in a star cell still lies in its closure and is not in
 * power conflict with it.  Then the mesh is the regular triangulation
 * of its vertices (the regular lemma), and each hidden point is hidden
 * where it is: the state a removal and an insertion would reach, in
 * either hidden mode (nothing is hidden or forgotten anew).  Else 0,
 * nothing changed.  t->conflict as scratch; *err DD_ERR_NOMEM (and 0)
 * when out of memory.  O(star + its hidden points) tests.              */
int dd_move_power_in_place(dd_tri *t, uint32_t v, const double p[3], double w, dd_status *err);

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
