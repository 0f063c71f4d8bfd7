/*
 * qdt.h -- the conflict regular triangulation (weighted t, issue 44):
 * the conflict DT of delete.h with the power test in place of the
 * in-sphere test, for the strategies that delete weighted points.
 *
 * Let S be the sites inserted so far (q's neighbours first, then the
 * star's hidden points, delete.h: d->order).  d->qdt holds the cells of
 * RT(S) in power conflict with (q, d->qw), closed by dummy cells: the
 * dummy cell (a,b,c,DD_QD) stands for the cell (b,a,c,q) of RT(S + q)
 * (q's star there) and is tested as that ordinary cell, with q's point
 * and weight (dd_qdt_power_conflict).  Inserting a site is Bowyer-Watson
 * with that test, exactly as in the unweighted conflict DT.  Why it
 * holds with weights: the argument of paper 4.1 only uses that the
 * triangulations are the projections of lower hulls of lifted points, and
 * the weighted lift (p, |p|^2 - w) is such a lift.
 *
 * The hidden points of the star (sites after the neighbours) are
 * inserted after every neighbour (dd_qdt_insert_hidden).  Each lies in a
 * cell of q's star, whose cells are those of RT(N + q) for any S holding
 * the neighbours N, so it is hidden in RT(S + q): it is in conflict with
 * no dummy cell, its conflict region in RT(S) lies among the cells in
 * conflict with q, and every vertex it swallows is an earlier hidden
 * point.  A point in conflict with no cell is hidden in RT(S) (under the
 * perturbation, the lifted point above every cell's plane is above the
 * lower hull): it is not inserted and stays hidden (the framework
 * re-homes it).  A point with the position and weight of a vertex is a
 * duplicate, not inserted either (dd_insert_power's rule).  A neighbour
 * is never hidden: a vertex of RT(X) is a vertex of RT(Y) for Y in X.
 */
#ifndef DD_QDT_H
#define DD_QDT_H

#include "delete/delete.h"

/* The power conflict test of (p, wp) with a cell of d->qdt that holds
 * the infinite or the dummy vertex (the rule above, CGAL's perturbed
 * predicates).                                                          */
int dd_qdt_power_conflict_outer(const dd_del *d, uint32_t c, const double *p, double wp);

/* 1 if (p, wp) is in power conflict with cell c of d->qdt (a conflict
 * RT, or a full RT of sites): the finite test inlined, the others by
 * dd_qdt_power_conflict_outer.  Never used on an unweighted t.          */
__attribute__((always_inline)) static inline int dd_qdt_power_conflict(const dd_del *d, uint32_t c,
                                                                     const double *p, double wp)
{
    dd_tri *x = d->qdt;
    const uint32_t *v = dd_tv(x, c);
    if ((v[0] < DD_QD) & (v[1] < DD_QD) & (v[2] < DD_QD) & (v[3] < DD_QD)) {
        const double *a = dd_pt(x, v[0]), *b = dd_pt(x, v[1]);
        const double *e = dd_pt(x, v[2]), *f = dd_pt(x, v[3]);
        const double w[5] = {x->wt[v[0]], x->wt[v[1]], x->wt[v[2]], x->wt[v[3]], wp};
        int r = dd_power_filter(&x->pred, a, b, e, f, p, w);
        if (r == DD_FILTER_UNSURE) r = dd_power_exact(&x->pred, a, b, e, f, p, w);
        if (r == 0) r = dd_power_symbolic(&x->pred, a, b, e, f, p, w);
        return r > 0;
    }
    return dd_qdt_power_conflict_outer(d, c, p, wp);
}

/* Picks d->base among q's neighbours (d->order[0 .. d->nbr.n)), the
 * hidden points left in place: the base is never deleted from the link,
 * so it must be a link vertex.  DD_ERR_COPLANAR when the neighbours are
 * coplanar (q on the hull, the hidden points giving the 3rd dimension):
 * then the caller takes dd_full_fill_power.                            */
dd_status dd_qdt_weighted_base(dd_del *d);

/* CREATEQCONFLICTDT with the power test: RT of the four base points,
 * its cells not in power conflict with q replaced by dummy cells.       */
dd_status dd_qdt_create_power(dd_del *d);
/* QCONFLICTDTINSERT with the power test: Bowyer-Watson of site v from
 * `start`, a cell in power conflict with it (d->qdt a conflict RT or a
 * full RT).                                                             */
dd_status dd_qdt_insert_power(dd_del *d, uint32_t v, uint32_t start);
/* Unguided location: the first dummy cell in power conflict with v. */
dd_status dd_qdt_scan_power(dd_del *d, uint32_t v, uint32_t *cell);
/* Inserts the hidden sites d->order[d->nbr.n ..) after the neighbours:
 * each duplicate or hidden one is skipped, the others located by a scan
 * of the cells without the dummy vertex and inserted.  O(cells) each.   */
dd_status dd_qdt_insert_hidden(dd_del *d);

#endif
