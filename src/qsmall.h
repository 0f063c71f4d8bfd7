/*
 * qsmall.h -- the compact conflict DT: DT(x)_q(P) for cavities of at most
 * DD_QS_MAXV neighbours, in storage sized for them (paper 4.1, DESIGN 6).
 *
 * The same algorithm as the generic conflict DT of delete.c
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
 *  - the conflict test for a non-dummy cell goes through a filter on a
 *    per-cell cached lifted hyperplane (see qsmall.c) and falls back to
 *    the exact perturbed predicates of pred.c, so every answer equals
 *    dd_cell_conflict's on the same cell.
 * When the structure is complete its fill cells (the non-dummy ones) are
 * exported into d->qdt / d->fill with vertex ids, for the framework's sew.
 */
#ifndef DD_QSMALL_H
#define DD_QSMALL_H

#include "delete.h"

#define DD_QS_MAXV 62     /* neighbours handled: local numbers 0..61     */

/* Builds DT(x)_q of d->order[0..n) (d->order[0..3] the base, the rest in
 * insertion order; n = d->order.n <= DD_QS_MAXV) and lists its fill in
 * d->qdt / d->fill.  Counts located cells in d->locate_steps and cells
 * built in d->qdt->tets_created.                                         */
dd_status dd_qs_fill(dd_del *d);

/* Sorts d->order (at most DD_QS_MAXV entries) by increasing distance to q
 * (rounded squared distances; ties keep their order).  An insertion order
 * for the compact conflict DT that builds fewer cells than a random one
 * on the bench's inputs (auto.c).                                        */
void dd_qs_order_nearest(dd_del *d);

/* The centre C (relative to q) of the sphere through q and the points
 * with lifts a, b, c ((x - q, |x - q|^2)), for the shifted lifts
 * |x - q|^2 - 2 (x - q).C of nearly cospherical cavities (qsmall.c,
 * wrap.c); 0 when it is not finite and below 1e50.                       */
int dd_shift_centre(const double *a, const double *b, const double *c, double C[3]);

void dd_qs_free(struct dd_qs *s);

#endif
