/*
 * auto.c -- the default strategy, a dispatcher over the fastest correct
 * choice by the cavity's kind and degree (so that dd_delete(t, v, NULL)
 * is that choice):
 *  - below degree 64: gift wrapping (wrap.h), which builds only the
 *    fill's cells (unless it declines: a hull vertex with coplanar points
 *    on its new hull facets);
 *  - otherwise, below degree 40, the compact conflict DT (qsmall.c) with
 *    the neighbours inserted nearest to q first;
 *  - from 40 on, grr-hashing.
 * The crossovers are where the bench and the warm harness find them:
 * gift wrapping against the conflict DT on uniform interior vertices
 * (degree [12,16) 2.8 vs 3.4 us, [40,48) 36 vs 65 us, [48,64) 58 vs 86 us,
 * repeated deletions of the same vertices), the conflict DT against
 * grr-hashing on the helix and uniform rows.  Nearest-first rather than
 * random order for the conflict DT: on the bench's low-degree inputs it
 * builds about a fifth fewer cells (uniform, degree ~15: 1090 vs 1346
 * over 12 deletions; `dtdel delete --stats`).
 */
#include "auto.h"
#include "../src/qsmall.h"
#include "../src/wrap.h"

#define AUTO_WRAP_BELOW_DEGREE 64
#define AUTO_GRR_FROM_DEGREE 40

/* Below the crossover every neighbour set fits the compact structure. */
_Static_assert(AUTO_GRR_FROM_DEGREE <= DD_QS_MAXV + 1, "auto: degree crossover above the compact DT's size");

extern const dd_variant dd_variant_grr_hashing;

dd_status dd_auto_conflict_dt(dd_del *d)
{
    if (d->degree >= AUTO_GRR_FROM_DEGREE) return dd_variant_grr_hashing.fill_cavity(d);
    dd_qs_order_nearest(d);
    dd_status s = dd_del_pick_base(d, d->order.a, d->order.n);
    if (s != DD_OK) return s;
    return dd_qs_fill(d);
}

static dd_status auto_fill(dd_del *d)
{
    if (d->degree < AUTO_WRAP_BELOW_DEGREE) {
        int declined;
        dd_status s = dd_wrap_fill(d, &declined);
        if (s != DD_OK || !declined) return s;
    }
    return dd_auto_conflict_dt(d);
}

const dd_variant dd_variant_auto = {
    "auto",
    "default: below degree 64 gift wrapping; else below 40 the compact conflict DT, nearest first; else grr-hashing",
    auto_fill,
};
