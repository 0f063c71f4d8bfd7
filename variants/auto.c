/*
 * auto.c -- the default strategy, a dispatcher over the fastest correct
 * choice by the cavity's degree (so that dd_delete(t, v, NULL) is that
 * choice):
 *  - gift wrapping (wrap.h), which builds only the fill's cells: where
 *    the link has a hub (the curves), narrow guesses first, over the
 *    known neighbours of each facet's corners, a few points a cell; the
 *    wide guess, over every neighbour (O(d) a cell), only below degree
 *    600 (AUTO_WIDE_BELOW_DEGREE); unless it declines (a refuted guess
 *    from 40 neighbours on, a degenerate cavity past its budget of exact
 *    tests, both unless the neighbours are cospherical; a hull whose
 *    neighbours all lie in one plane; from degree 600, no narrow guess
 *    that holds);
 *  - where it declines, below degree 40, the compact conflict DT (qsmall.c)
 *    with the neighbours inserted nearest to q first;
 *  - from 40 on, GRR-CONSTRUCT with grr-neighbor's guides but the link
 *    vertex of least degree deleted first (a random one among those),
 *    not a random one of degree <= 7.
 * The crossovers: gift wrapping beats the conflict DT on every
 * low-degree row of `make bench` (47bce1d: uniform [12,16) 2.96 vs 4.27
 * us, sphere [4,8) 0.8 vs 1.9 us).  Since it guesses and proves (wrap.c)
 * it also beats grr-neighbor up to degree 255 (median of 5 repetitions,
 * gift-wrap vs auto then grr-neighbor: moment [150,256) 63 vs 133 us,
 * helix [96,256) 81 vs 153 us), and on to degree 300 where the guess
 * holds (median of 5 deletions per vertex, 3 to 12 vertices, gift-wrap
 * vs grr-neighbor: moment n = 256, degree 256: 115-141 vs 161-171 us;
 * helix n = 16000, degree 241-286: 116-164 vs 184-209 us).  Since the
 * guess decides the points of unsure orientation (wrap.c, wrap_guess) it
 * holds on the nearly degenerate curves too, where it was refuted and the
 * wrap declined (helix n = 64000, degree 404-563, and moment n = 264-512:
 * a point nearly in a facet's plane is its apex), so wrapping stays ahead
 * to degree ~600 (median of 5, 3 to 6 vertices, gift-wrap vs
 * grr-neighbor: helix n = 64000, degree 404: 314 vs 339 us, degree 563:
 * 349-369 vs 409-426 us; moment n = 300: 112-118 vs 170-181 us, n = 512:
 * 285-303 vs 300-328 us; n = 768: 688-708 vs 481-499 us, where the
 * O(n) guess a cell tells).  grr-neighbor is the fastest GRR from
 * degree 64 on in the bench runs of 47bce1d and 81975a5 (moment, degree
 * 1023: 2370x and 2231x against 1926x and 1811x for grr-hashing).
 * Least degree first: on the moment curve nearly every link vertex has
 * degree 4, and deleting those of degree 3 first builds 18% fewer cells
 * (degree 511: 2493 against ~3040; degree 1023: 4991 against ~6100;
 * `dtdel delete --stats`), and deletes faster (moment n = 1024, median of
 * 8 vertices x 5 repetitions, three alternated runs: deletion/re-insertion
 * 3.60-4.13 against 3.97-4.41 for grr-neighbor).  The expected bounds of
 * the paper's random order are not claimed for it; the result is the
 * same, the perturbed DT being unique.
 * Nearest-first rather than random order for the conflict DT: on the
 * bench's low-degree inputs it builds about a fifth fewer cells (uniform,
 * degree ~15: 1090 vs 1346 over 12 deletions; `dtdel delete --stats`).
 */
#include "auto.h"
#include "delete/qsmall.h"
#include "wrap/wrap.h"
#include "delete/grr.h"

/* The narrow guesses hold on the curves at every degree of the bench
 * (wrap.c), where wrapping then beats GRR: moment n = 1024, degree
 * ~1020, median of 5 deletions of 4 vertices, gift-wrap 347-540 us
 * against 722-766 us for auto (then GRR from degree 600) and 791-1438 us
 * for grr-neighbor in the same runs, 2.0-2.2 against 4.3-4.8 times a
 * re-insertion.  Without a narrow guess that holds, the wide guess's
 * O(d) a cell loses to GRR from degree ~600 (above).                   */
#define AUTO_WIDE_BELOW_DEGREE 600
#define AUTO_GRR_FROM_DEGREE 40

/* Below the crossover every neighbour set fits the compact structure. */
_Static_assert(AUTO_GRR_FROM_DEGREE <= DD_QS_MAXV + 1, "auto: degree crossover above the compact DT's size");

static uint32_t mindeg_sample(dd_grr *g, uint32_t *guide)
{
    uint32_t u = dd_grr_sample_mindeg(g);
    *guide = dd_grr_lowest_neighbour(g, u);
    return u;
}

static const dd_grr_policy mindeg_policy = {mindeg_sample, 0, 0};

dd_status dd_auto_conflict_dt(dd_del *d)
{
    if (d->degree >= AUTO_GRR_FROM_DEGREE) return dd_grr_construct(d, &mindeg_policy);
    dd_qs_order_nearest(d);
    dd_status s = dd_del_pick_base(d, d->order.a, d->order.n);
    if (s != DD_OK) return s;
    return dd_qs_fill(d);
}

dd_status dd_auto_wrap_first(dd_del *d, uint32_t wide_below)
{
    int declined;
    dd_status s = dd_wrap_fill(d, wide_below, &declined);
    if (s != DD_OK || !declined) return s;
    return dd_auto_conflict_dt(d);
}

static dd_status auto_fill(dd_del *d)
{
    return dd_auto_wrap_first(d, AUTO_WIDE_BELOW_DEGREE);
}

const dd_variant dd_variant_auto = {
    "auto",
    "default: gift wrapping (narrow guesses where the link has a hub, the wide one below degree 600); where it declines, below 40 the compact conflict DT, nearest first, else GRR, least link degree first",
    auto_fill,
};
