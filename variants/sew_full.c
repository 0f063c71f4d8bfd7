/*
 * sew_full.c -- triangulate and sew with our own engine: the full DT of
 * q's neighbours in random order (visibility walk from the last cell),
 * then its cells in conflict with q are sewn in.  The C analogue of
 * CGAL-rnd: it separates engine speed from algorithm.
 */
#include "delete/delete.h"

static dd_status sew_full_fill(dd_del *d)
{
    dd_del_shuffle(d, d->order.a, d->order.n);
    dd_status s = dd_del_pick_base(d, d->order.a, d->order.n);
    if (s != DD_OK) return s;
    dd_qdt_reset(d, 0);
    DD_PHASE_BEGIN(d);
    s = dd_full_build(d);
    DD_PHASE_END(d, DD_PH_CONFLICT);
    if (s == DD_OK) s = dd_full_collect_fill(d);
    DD_PHASE_END(d, DD_PH_CONFLICT);
    return s;
}

const dd_variant dd_variant_sew_full = {
    "sew-full",
    "full DT of the neighbours in random order, then sew (our CGAL-rnd)",
    sew_full_fill,
    dd_full_fill_power,
};
