/*
 * auto.c -- the default strategy (first in registry.c: dd_delete(t, v)
 * takes it), the fastest correct course by the cavity's degree d:
 *  1. gift wrapping (wrap.h), which builds only the fill's cells: narrow
 *     guesses where the link has a hub (the curves), the wide guess, O(d)
 *     a cell, only below AUTO_WIDE_BELOW_DEGREE;
 *  2. where the wrap declines (wrap.h says when), below
 *     AUTO_GRR_FROM_DEGREE the compact conflict DT (qsmall.h), the
 *     neighbours inserted nearest to q first, which builds fewer cells
 *     than a random order;
 *  3. from AUTO_GRR_FROM_DEGREE on, GRR-CONSTRUCT (grr.h) with
 *     grr-neighbor's guides, deleting first a link vertex of least degree
 *     (fewer cells built than grr-neighbor's random one of degree <= 7
 *     on the moment curve).  The paper's expected bounds are not claimed
 *     for this order; the result is the same, the perturbed DT is unique.
 * On a weighted triangulation: gift wrapping in the lifted frame, the
 * star's hidden points among the sites (docs/gift-wrap.md §13), and where
 * it declines the same conflict DTs with the power test (qdt.h).
 * The crossovers are measured by `make bench` (results/summary.md: the
 * gift-wrap, grr-neighbor and auto rows by degree), or on the curves
 * alone by `build/dtdel bench --dataset moment` (or helix); the cells
 * built by `build/dtdel delete FILE --vertex V --variant NAME --stats`.
 */
#include "auto.h"
#include "delete/qsmall.h"
#include "wrap/wrap.h"
#include "delete/grr.h"

/* From this degree on the wide guess, O(d) a cell, is slower than GRR:
 * the wrap keeps only a narrow guess that holds.                        */
#define AUTO_WIDE_BELOW_DEGREE 600
/* Below this degree scanning the compact conflict DT's few dummy cells
 * is cheaper than keeping the link DT that guides GRR's locations.     */
#define AUTO_GRR_FROM_DEGREE 40

/* Below the crossover every neighbour set fits the compact structure. */
_Static_assert(AUTO_GRR_FROM_DEGREE <= DD_QS_MAXV + 1, "auto: degree crossover above the compact DT's size");

/* Steps 2 and 3: the fill by a conflict DT, for a cavity the wrap
 * declined.                                                          */
static dd_status fill_conflict_dt(dd_del *d)
{
    if (d->degree >= AUTO_GRR_FROM_DEGREE || d->order.n > DD_QS_MAXV) return dd_grr_fill_mindeg(d);
    return dd_qs_fill_nearest(d);
}

dd_status dd_auto_wrap_first(dd_del *d, uint32_t wide_below)
{
    int declined;
    dd_status s = dd_wrap_fill(d, wide_below, &declined);
    if (s != DD_OK || !declined) return s;
    return fill_conflict_dt(d);
}

static dd_status auto_fill(dd_del *d)
{
    return dd_auto_wrap_first(d, AUTO_WIDE_BELOW_DEGREE);
}

const dd_variant dd_variant_auto = {
    "auto",
    "default: gift wrapping (narrow guesses where the link has a hub, the wide one below degree 600); where it declines, below 40 the compact conflict DT, nearest first, else GRR, least link degree first; on weighted points the same courses in the lifted frame, with the star's hidden points as sites",
    auto_fill,
    auto_fill,
};
