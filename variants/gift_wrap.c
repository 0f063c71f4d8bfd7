/*
 * gift_wrap.c -- the cavity filled by gift wrapping (wrap.h): the fill
 * cells found one by one from the link, no conflict DT.  Not a variant of
 * the paper: the low-degree fast path of auto.c, listed on its own so
 * that the bench times it and the tests check it at every degree.  When
 * the wrap declines (wrap.h: a nearly degenerate cavity of 40 neighbours
 * or more, or a rare flat hull case), auto's conflict-DT strategies fill
 * the cavity.
 */
#include "auto.h"

/* auto's own choice, with the wide guess at every degree; on a weighted
 * t the same courses in the lifted frame.                            */
static dd_status gift_wrap_fill(dd_del *d)
{
    return dd_auto_wrap_first(d, UINT32_MAX);
}

const dd_variant dd_variant_gift_wrap = {
    "gift-wrap",
    "the fill found cell by cell from the link by gift wrapping (nearly degenerate from degree 40: as auto without it; weighted: in the lifted frame, the star's hidden points as sites)",
    gift_wrap_fill,
    gift_wrap_fill,
};
