/*
 * auto.c -- the default strategy: below degree 40 the compact conflict DT
 * (qsmall.c) with the neighbours inserted nearest to q first; from 40 on,
 * grr-hashing.  The crossover is where the bench (make bench, helix and
 * uniform rows) finds the fixed cost of the link DT paid back by guided
 * point location; below it, scanning the few dummy cells is cheaper than
 * maintaining the link.  Nearest-first rather than random order: on the
 * bench's low-degree inputs it builds about a fifth fewer cells (uniform,
 * degree ~15: 1090 vs 1346 over 12 deletions; `dtdel delete --stats`).
 * Not a variant of the paper: a dispatcher over two of its algorithms, so
 * that dd_delete(t, v, NULL) is the fastest correct choice.
 */
#include "../src/qsmall.h"

#define AUTO_GRR_FROM_DEGREE 40

/* Below the crossover every neighbour set fits the compact structure. */
_Static_assert(AUTO_GRR_FROM_DEGREE <= DD_QS_MAXV + 1, "auto: degree crossover above the compact DT's size");

extern const dd_variant dd_variant_grr_hashing;

static dd_status auto_fill(dd_del *d)
{
    if (d->degree >= AUTO_GRR_FROM_DEGREE)
        return dd_variant_grr_hashing.fill_cavity(d);
    dd_qs_order_nearest(d);
    dd_status s = dd_del_pick_base(d, d->order.a, d->order.n);
    if (s != DD_OK) return s;
    return dd_qs_fill(d);
}

const dd_variant dd_variant_auto = {
    "auto",
    "default: below degree 40 the compact conflict DT, nearest neighbours first; grr-hashing from 40 on",
    auto_fill,
};
