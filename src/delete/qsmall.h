/*
 * qsmall.h -- the compact conflict DT: DT(x)_q(P) for cavities of at most
 * DD_QS_MAXV neighbours, in storage sized for them (paper 4.1, DESIGN 6).
 *
 * The same algorithm as the generic conflict DT of qdt.c
 * (CREATEQCONFLICTDT, then QCONFLICTDTINSERT of each point located by
 * scanning the dummy cells), in a representation built for a cavity of a
 * few dozen points, so that the whole structure stays in L1 cache:
 *  - local vertex numbers: 0..k-1 for the neighbours in insertion order,
 *    DD_QS_INF and DD_QS_QD for the infinite and the dummy vertex; the
 *    points are copied next to each other;
 *  - a cell is 12 bytes: four 8-bit vertices and four 16-bit neighbours
 *    (4 * cell + facet);
 *  - the star of a new point is glued through a direct edge table indexed
 *    by the two local vertex numbers (no hashing), left empty after each
 *    star since every edge of a cavity boundary is met exactly twice;
 *  - the conflict test for a non-dummy cell goes through the lifted
 *    filter of src/geom/lift.h (points lifted relative to q once per
 *    deletion) and falls back to the exact perturbed predicates of
 *    pred.c, so every answer equals dd_cell_conflict's on the same cell.
 * When the structure is complete its fill cells (the non-dummy ones) are
 * exported into d->qdt / d->fill with vertex ids, for the framework's sew.
 *
 * On a weighted t (issue 44) it is the conflict regular triangulation of
 * qdt.h: the local points carry their weights, every test is CGAL's
 * perturbed power test (no lifted filter), and the star's hidden points
 * (the sites after the neighbours) go in last, skipped when hidden or
 * duplicates.  The choice is made once per deletion.
 */
#ifndef DD_QSMALL_H
#define DD_QSMALL_H

#include "delete/delete.h"
#include "geom/lift.h"   /* the lifted filter, which the wrap takes from here too */

#define DD_QS_MAXV 62     /* neighbours handled: local numbers 0..61     */

/* Builds DT(x)_q of d->order[0..n) (d->order[0..3] the base, the rest in
 * insertion order; n = d->order.n <= DD_QS_MAXV) and lists its fill in
 * d->qdt / d->fill.  Counts located cells in d->locate_steps and cells
 * built in d->qdt->tets_created.  Weighted t: the base among the
 * neighbours (dd_qdt_weighted_base), the hidden sites after them.        */
dd_status dd_qs_fill(dd_del *d);

/* auto's small-cavity fill, weighted or not: the neighbours nearest to q
 * first (dd_qs_order_nearest), the base picked, dd_qs_fill; on a
 * weighted t whose neighbours are coplanar, dd_full_fill_power.
 * DD_ERR_INTERNAL when d->order.n > DD_QS_MAXV (sites, hidden ones
 * included: the caller takes GRR then).                                 */
dd_status dd_qs_fill_nearest(dd_del *d);

/* Sorts q's neighbours at the front of d->order (at most DD_QS_MAXV
 * entries; the hidden sites after them stay in place) by increasing distance to q
 * (rounded squared distances; ties keep their order): an insertion order
 * for the compact conflict DT that builds fewer cells than a random one
 * (auto.c).                                                              */
void dd_qs_order_nearest(dd_del *d);

struct dd_qs;
void dd_qs_free(struct dd_qs *s);

#endif
