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

/* The conflict DT's steps under one test (qdt.h): the in-sphere or the
 * power test.                                                          */
typedef struct qdt_steps {
    dd_status (*create)(dd_del *d);
    dd_status (*scan)(dd_del *d, uint32_t v, uint32_t *cell);
    dd_status (*insert)(dd_del *d, uint32_t v, uint32_t start);
} qdt_steps;

static const qdt_steps in_sphere = {dd_qdt_create, dd_qdt_scan, dd_qdt_insert};
static const qdt_steps power = {dd_qdt_create_power, dd_qdt_scan_power, dd_qdt_insert_power};

/* The conflict DT of d->order.a[0 .. n), its base first: created on the
 * base, then each later point located by a scan of the dummy cells and
 * inserted.  Inlined into each fill with its table, so the calls stay
 * direct (the loop is the variant's timed work).                       */
__attribute__((always_inline)) static inline dd_status build_by_scan(dd_del *d, const qdt_steps *q, size_t n)
{
    dd_qdt_reset(d, 1);
    DD_PHASE_BEGIN(d);
    dd_status s = q->create(d);
    DD_PHASE_END(d, DD_PH_CONFLICT);
    for (size_t k = 4; k < n && s == DD_OK; k++) {
        uint32_t v = d->order.a[k], c = 0;
        s = q->scan(d, v, &c);
        DD_PHASE_END(d, DD_PH_LOCATE);
        if (s == DD_OK) s = q->insert(d, v, c);
        DD_PHASE_END(d, DD_PH_CONFLICT);
    }
    return s;
}

static dd_status dtq_only_fill(dd_del *d)
{
    dd_del_shuffle(d, d->order.a, d->order.n);
    dd_status s = dd_del_pick_base(d, d->order.a, d->order.n);
    if (s != DD_OK) return s;
    if (d->order.n <= DD_QS_MAXV) return dd_qs_fill(d);
    s = build_by_scan(d, &in_sphere, d->order.n);
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
    s = build_by_scan(d, &power, nn);
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
