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

#include "delete/delete.h"

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

/* The lifted in-sphere filter of qsmall.c (and wrap.c): the error bound
 * of a determinant of lifted differences for points within m of q in
 * each coordinate (derivation above det4_rows in qsmall.c); +inf outside
 * 1e-55 <= m <= 1e55, where the filter must not answer.                 */
static inline double dd_lift_err(double m)
{
    return m >= 1e-55 && m <= 1e55 ? 1e-11 * m * m * m * m * m : 1.0 / 0.0;
}

/* Shifted lifts for nearly cospherical cavities (qsmall.c): for the points
 * pts[0..n), within m of q, and the plain lifts a, b, c ((x - q,
 * |x - q|^2)) of three of them, writes the shifted fourth coordinates to
 * w[0..n) and returns their filter bound; 0 when the centre is not finite
 * or the bound is not below err.  Worth trying from DD_SHIFT_FROM points
 * on.                                                                    */
#define DD_SHIFT_FROM 7
double dd_shift_lifts(const double *const *pts, uint32_t n, const double *q, const double *a, const double *b,
                      const double *c, double m, double err, double *w);

struct dd_qs;
void dd_qs_free(struct dd_qs *s);

#endif
