/*
 * gift_wrap.c -- the cavity of an interior vertex filled by gift wrapping
 * (wrap.h): the fill cells found one by one from the link, no conflict DT.
 * Not a variant of the paper: the low-degree fast path of auto.c, listed
 * on its own so that the bench times it and the tests check it at every
 * degree.  A hull vertex goes to auto's strategy for hull vertices:
 * wrap.c does not handle the infinite vertex.
 */
#include "../src/wrap.h"

extern const dd_variant dd_variant_auto;

static dd_status gift_wrap_fill(dd_del *d)
{
    if (d->on_hull) return dd_variant_auto.fill_cavity(d);
    return dd_wrap_fill(d);
}

const dd_variant dd_variant_gift_wrap = {
    "gift-wrap",
    "interior vertices: the fill found cell by cell from the link by gift wrapping (hull vertices: as auto)",
    gift_wrap_fill,
};
