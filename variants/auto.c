/*
 * auto.c -- the default strategy: dtq-only below degree 40, grr-hashing
 * from 40 on.  The crossover is where the bench (make bench, helix and
 * uniform rows) finds the fixed cost of the link DT paid back by guided
 * point location; below it, scanning the few dummy cells is cheaper than
 * maintaining the link.  Not a variant of the paper: a dispatcher over two
 * of them, so that dd_delete(t, v, NULL) is the fastest correct choice.
 */
#include "../src/delete.h"

#define AUTO_GRR_FROM_DEGREE 40

extern const dd_variant dd_variant_dtq_only, dd_variant_grr_hashing;

static dd_status auto_fill(dd_del *d)
{
    const dd_variant *v = d->degree >= AUTO_GRR_FROM_DEGREE ? &dd_variant_grr_hashing : &dd_variant_dtq_only;
    return v->fill_cavity(d);
}

const dd_variant dd_variant_auto = {
    "auto",
    "default: dtq-only below degree 40, grr-hashing from 40 on",
    auto_fill,
};
