/*
 * dtq_only.c -- DT(x)-only (paper 5, variants table): the conflict DT of
 * q's neighbours built in random order, without a guide.
 *
 * Point location: no guide means no idea where the next point lands, so
 * each point is located by scanning the dummy cells of the conflict DT for
 * one in conflict with it (there always is one: the point becomes a link
 * vertex, so it destroys at least one link triangle).  Robust (only the
 * exact conflict test is used) and O(size of the link) per point.  A
 * cavity of at most DD_QS_MAXV neighbours is built by the same algorithm
 * in the compact structure of qsmall.h.
 */
#include "delete/qsmall.h"
#include "delete/qdt.h"

static dd_status dtq_only_fill(dd_del *d)
{
    dd_status s = DD_OK;
    dd_del_shuffle(d, d->order.a, d->order.n);
    s = dd_del_pick_base(d, d->order.a, d->order.n);
    if (s != DD_OK) return s;
    if (d->order.n <= DD_QS_MAXV) return dd_qs_fill(d);
    dd_qdt_reset(d, 1);
    DD_PHASE_BEGIN(d);
    s = dd_qdt_create(d);
    DD_PHASE_END(d, DD_PH_CONFLICT);
    for (size_t k = 4; k < d->order.n && s == DD_OK; k++) {
        uint32_t v = d->order.a[k], c = 0;
        s = dd_qdt_scan(d, v, &c);
        DD_PHASE_END(d, DD_PH_LOCATE);
        if (s == DD_OK) s = dd_qdt_insert(d, v, c);
        DD_PHASE_END(d, DD_PH_CONFLICT);
    }
    if (s == DD_OK) s = dd_qdt_collect_fill(d);
    return s;
}

/* The weighted fill: the conflict RT (qdt.h) of the neighbours in random
 * order, then the star's hidden points in random order.                */
static dd_status dtq_only_fill_weighted(dd_del *d)
{
    const size_t nn = d->nbr.n;
    dd_del_shuffle(d, d->order.a, nn);
    dd_del_shuffle(d, d->order.a + nn, d->order.n - nn);
    dd_status s = dd_qdt_weighted_base(d);
    if (s == DD_ERR_COPLANAR) return dd_full_fill_power(d);
    if (s != DD_OK) return s;
    if (d->order.n <= DD_QS_MAXV) return dd_qs_fill(d);
    dd_qdt_reset(d, 1);
    DD_PHASE_BEGIN(d);
    s = dd_qdt_create_power(d);
    DD_PHASE_END(d, DD_PH_CONFLICT);
    for (size_t k = 4; k < nn && s == DD_OK; k++) {
        uint32_t v = d->order.a[k], c = 0;
        s = dd_qdt_scan_power(d, v, &c);
        DD_PHASE_END(d, DD_PH_LOCATE);
        if (s == DD_OK) s = dd_qdt_insert_power(d, v, c);
        DD_PHASE_END(d, DD_PH_CONFLICT);
    }
    if (s == DD_OK) s = dd_qdt_insert_hidden(d);
    if (s == DD_OK) s = dd_qdt_collect_fill(d);
    return s;
}

const dd_variant dd_variant_dtq_only = {
    "dtq-only",
    "conflict DT of the neighbours in random order, no guide (scan location)",
    dtq_only_fill,
    dtq_only_fill_weighted,
};
