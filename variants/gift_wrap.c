/*
 * gift_wrap.c -- the cavity filled by gift wrapping (wrap.h): the fill
 * cells found one by one from the link, no conflict DT.  Not a variant of
 * the paper: the low-degree fast path of auto.c, listed on its own so
 * that the bench times it and the tests check it at every degree.  When
 * the wrap declines (a hull vertex with coplanar points on its new hull
 * facets), auto's conflict-DT strategies fill the cavity.
 */
#include "auto.h"
#include "../src/wrap.h"

static dd_status gift_wrap_fill(dd_del *d)
{
    int declined;
    dd_status s = dd_wrap_fill(d, &declined);
    if (s != DD_OK || !declined) return s;
    return dd_auto_conflict_dt(d);
}

const dd_variant dd_variant_gift_wrap = {
    "gift-wrap",
    "the fill found cell by cell from the link by gift wrapping (coplanar hull cases: as auto without it)",
    gift_wrap_fill,
};
