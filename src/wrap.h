/*
 * wrap.h -- a cavity filled by gift wrapping: the low-degree fast path of
 * auto.c, not an algorithm of the paper.
 *
 * The fill of q's cavity is exactly the set of cells of DT(P) (P = q's
 * neighbours, perturbed as CGAL does) in conflict with q, and these cells
 * tile the star of q.  So every link triangle abc, seen from q's side, is
 * a facet of exactly one fill cell abcp, where p is the point of P on
 * that side of abc whose sphere through a, b, c holds no other such point
 * (or the infinite vertex, when q is on the hull and no point is on that
 * side); the same holds for every facet between two fill cells.  Gift
 * wrapping finds the fill cell by cell from the link, with no conflict
 * test against q and no cell built that is not kept, where DT(x)_q builds
 * every cell of DT(x)_q(P_i) for every i: about five times the fill at
 * degree 15.
 *
 * The wrap first guesses, with no check, and keeps the guess when it
 * proves to be a triangulation of the cavity whose facets are all
 * locally Delaunay: then it is DT(S \ q)'s fill.  Otherwise the certified
 * scans wrap: each comparison filtered (wrap.c) and else decided by the
 * exact perturbed predicates of pred.c.  Either way the fill is exactly
 * the one the other strategies build.
 *
 * Cost: the wide guess scans P for each fill cell, O(d) lifted dot
 * products (four points at a time with AVX2), so O(d * |fill|), about
 * d^2: cheaper than the conflict DT, and than GRR below degree ~600.
 * Where the link has a hub (a vertex of more than 32 link neighbours: the
 * curves), narrow guesses come first, each cell's point taken among the
 * known neighbours of its facet's corners in DT(P): a few points a cell,
 * O(|fill|) in all, about 1.6-1.8 times a re-insertion on the curves at
 * every degree (wrap.c, w_guess_narrow).
 */
#ifndef DD_WRAP_H
#define DD_WRAP_H

#include "delete.h"

/* Makes the fill of the cavity of d->q in the mesh (d->fill), over the
 * star's cells and past them in new ones, glued to each other, and the
 * sew's matching (d->sew_out; d->fill_in_mesh); d->order holds d->nbr
 * and is sorted by vertex id.  It declines (*declined = 1, DD_OK; the
 * star written back and the new cells given back, the mesh as it was,
 * d->fill empty) for a cavity of 40 neighbours or more, not all on one
 * sphere, whose guess is refuted or whose exact tests pass the budget
 * (wrap.c, W_EXACT_FROM), and for the flat hull cases that its checks do
 * not settle (every neighbour in one plane; wrap.c, W_BAIL).  From
 * wide_below neighbours on it does not try the wide guess, so it
 * declines there too unless a narrow guess holds (or the neighbours are
 * cospherical: the scans, whose in-sphere tests are the perturbation's
 * alone).  Flat hull
 * faces are otherwise triangulated by the perturbation's coplanar rules
 * (wrap_scan_inf, w_flat_hull).
 * DD_ERR_INTERNAL (with a message) if the fill does not close, which only
 * a broken triangulation can cause (the mesh as it was as well).       */
dd_status dd_wrap_fill(dd_del *d, uint32_t wide_below, int *declined);

void dd_wrap_free(struct dd_wrap *w);

#endif
