/*
 * qdt.c -- the conflict DT DT(x)_q(P_i) of paper 4.1 (CREATEQCONFLICTDT,
 * QCONFLICTDTINSERT) and the full DT(P) that triangulate-and-sew builds,
 * both in d->qdt, a scratch triangulation that borrows the main one's
 * points (delete.h describes the dummy vertex DD_QD and its cells).
 *
 * Invariant: after dd_qdt_create and each dd_qdt_insert, d->qdt is
 * DT(x)_q of the points inserted so far, closed by dummy cells; d->fill
 * is only valid after dd_qdt_collect_fill / dd_full_collect_fill.
 */
#include "delete/delete.h"
#include "delete/qdt.h"
#include "mesh/hidden.h"

#include <string.h>

/* ---- the conflict DT ----------------------------------------------------- */

void dd_qdt_reset(dd_del *d, int qd)
{
    dd_clear_cells(d->qdt);
    d->qdt->qd_point = qd ? d->qp : NULL;
    d->qdt->tets_created = 0;
    d->fill.n = 0;
}

/* CREATEQCONFLICTDT: DT of the four base points, then the cells not in
 * conflict with q (weighted: in power conflict with (q, w_q)) are replaced
 * by the star of the dummy vertex: exactly a Bowyer-Watson step whose
 * "conflict region" is the complement.  A handful of cells, so a test per
 * cell may choose the predicate.                                          */
static dd_status create(dd_del *d, int weighted)
{
    dd_tri *x = d->qdt;
    dd_status s = dd_reserve_cells(x, 16);
    if (s != DD_OK) return s;
    uint32_t b[4];
    memcpy(b, d->base, sizeof b);
    dd_make_first_cells(x, b);
    dd_mark ep = dd_new_epoch(x, 2);
    x->conflict.n = x->boundary.n = 0;
    for (uint32_t c = 0; c < x->ncell && s == DD_OK; c++)
        if (!(weighted ? dd_qdt_power_conflict(d, c, d->qp, d->qw) : dd_cell_conflict(x, c, d->qp))) {
            x->stamp[c] = ep;
            s = dd_vec_push(&x->conflict, c);
        }
    for (size_t k = 0; k < x->conflict.n && s == DD_OK; k++) {
        uint32_t c = x->conflict.a[k];
        for (uint32_t i = 0; i < 4 && s == DD_OK; i++)
            if (x->stamp[dd_tn(x, c)[i] >> 2] != ep)
                s = dd_vec_push(&x->boundary, 4 * c + i);
    }
    if (s == DD_OK) s = dd_reserve_star(x);
    if (s != DD_OK) return s;
    dd_fill_star(x, DD_QD);
    return DD_OK;
}

dd_status dd_qdt_create(dd_del *d) { return create(d, 0); }

/* QCONFLICTDTINSERT */
dd_status dd_qdt_insert(dd_del *d, uint32_t v, uint32_t start)
{
    dd_tri *x = d->qdt;
    dd_status s = dd_find_conflicts(x, dd_pt(x, v), start);
    if (s == DD_OK) s = dd_reserve_star(x);
    if (s != DD_OK) return s;
    dd_fill_star(x, v);
    return DD_OK;
}

static int has_qd(const dd_tri *x, uint32_t c)
{
    return dd_index_of(x, c, DD_QD) >= 0;
}

dd_status dd_qdt_scan(dd_del *d, uint32_t v, uint32_t *cell)
{
    dd_tri *x = d->qdt;
    const double *p = dd_pt(x, v);
    for (uint32_t c = 0; c < x->ncell; c++) {
        if (dd_tv(x, c)[0] == DD_DEAD || !has_qd(x, c)) continue;
        d->locate_steps++;
        if (dd_cell_conflict(x, c, p)) { *cell = c; return DD_OK; }
    }
    return dd_fail(d->t, DD_ERR_INTERNAL, "no dummy cell of the conflict DT conflicts with point %u",
                   d->t->v2in[v]);
}

dd_status dd_qdt_collect_fill(dd_del *d)
{
    dd_tri *x = d->qdt;
    d->fill.n = 0;
    dd_status s = DD_OK;
    for (uint32_t c = 0; c < x->ncell && s == DD_OK; c++)
        if (dd_tv(x, c)[0] != DD_DEAD && !has_qd(x, c)) s = dd_vec_push(&d->fill, c);
    return s;
}

dd_status dd_full_build(dd_del *d)
{
    dd_tri *x = d->qdt;
    dd_status s = dd_reserve_cells(x, (uint32_t)(8 * d->nbr.n + 16));
    if (s != DD_OK) return s;
    uint32_t b[4];
    memcpy(b, d->base, sizeof b);
    dd_make_first_cells(x, b);
    for (size_t k = 0; k < d->order.n && s == DD_OK; k++) {
        uint32_t v = d->order.a[k];
        if (v == d->base[0] || v == d->base[1] || v == d->base[2] || v == d->base[3]) continue;
        s = dd_insert_vertex(x, v);
    }
    return s;
}

dd_status dd_full_collect_fill(dd_del *d)
{
    dd_tri *x = d->qdt;
    d->fill.n = 0;
    dd_status s = DD_OK;
    for (uint32_t c = 0; c < x->ncell && s == DD_OK; c++)
        if (dd_tv(x, c)[0] != DD_DEAD && dd_cell_conflict(x, c, d->qp))
            s = dd_vec_push(&d->fill, c);
    return s;
}

/* ---- the full regular triangulation of P (weighted t) -------------------- */

dd_status dd_full_build_power(dd_del *d)
{
    dd_tri *x = d->qdt;
    dd_status s = DD_OK;
    if (!x->hid) s = dd_hidden_init(x, 0);   /* x forgets what it hides */
    if (s == DD_OK) s = dd_reserve_cells(x, (uint32_t)(8 * d->order.n + 16));
    if (s != DD_OK) return s;
    uint32_t b[4];
    memcpy(b, d->base, sizeof b);
    dd_make_first_cells(x, b);
    for (size_t k = 0; k < d->order.n && s == DD_OK; k++) {
        uint32_t v = d->order.a[k], dup;
        if (v == d->base[0] || v == d->base[1] || v == d->base[2] || v == d->base[3]) continue;
        dd_fate fate;
        s = dd_insert_power(x, v, DD_NONE, 0, &fate, &dup);
    }
    return s;
}

dd_status dd_full_collect_fill_power(dd_del *d)
{
    dd_tri *x = d->qdt;
    d->fill.n = 0;
    dd_status s = DD_OK;
    for (uint32_t c = 0; c < x->ncell && s == DD_OK; c++)
        if (dd_tv(x, c)[0] != DD_DEAD && dd_cell_power_conflict_fast(x, c, d->qp, d->qw))
            s = dd_vec_push(&d->fill, c);
    return s;
}

dd_status dd_full_fill_power(dd_del *d)
{
    const size_t nn = d->nbr.n;
    dd_del_shuffle(d, d->order.a, nn);                    /* the neighbours, */
    dd_del_shuffle(d, d->order.a + nn, d->order.n - nn);  /* then the hidden */
    dd_status s = dd_del_pick_base(d, d->order.a, d->order.n);
    if (s != DD_OK) return s;
    dd_qdt_reset(d, 0);
    DD_PHASE_BEGIN(d);
    s = dd_full_build_power(d);
    if (s == DD_OK) s = dd_full_collect_fill_power(d);
    DD_PHASE_END(d, DD_PH_CONFLICT);
    return s;
}

/* ---- the conflict regular triangulation (qdt.h) --------------------------- */

int dd_qdt_power_conflict_outer(const dd_del *d, uint32_t c, const double *p, double wp)
{
    const dd_tri *x = d->qdt;
    const uint32_t *v = dd_tv(x, c);
    const double *q[4];
    double w[5];
    int k = -1, kd = -1;
    for (int i = 0; i < 4; i++) {
        if (v[i] == DD_INF) { k = i; q[i] = NULL; w[i] = 0; }
        else if (v[i] == DD_QD) { kd = i; q[i] = d->qp; w[i] = d->qw; }
        else { q[i] = dd_pt(x, v[i]); w[i] = x->wt[v[i]]; }
    }
    if (kd >= 0) {               /* dummy cell: swap the first two others */
        int a = kd == 0 ? 1 : 0, b = kd <= 1 ? 2 : 1;
        const double *s = q[a]; q[a] = q[b]; q[b] = s;
        double ws = w[a]; w[a] = w[b]; w[b] = ws;
        if (k == a) k = b; else if (k == b) k = a;
    }
    dd_pred *pr = (dd_pred *)&x->pred;
    w[4] = wp;
    if (k < 0) return dd_power_perturbed(pr, q[0], q[1], q[2], q[3], p, w) > 0;
    const int a = dd_facet[k][0], b = dd_facet[k][1], e = dd_facet[k][2];
    const double wf[4] = {w[a], w[b], w[e], wp};
    return dd_power_infinite(pr, q[a], q[b], q[e], p, wf) > 0;
}

dd_status dd_qdt_weighted_base(dd_del *d)
{
    return dd_del_pick_base(d, d->order.a, d->nbr.n);
}

dd_status dd_qdt_create_power(dd_del *d) { return create(d, 1); }

/* The conflict region of (p, wp) from c0 (in conflict), as mesh.c's
 * search: region cells stamped ep in x->conflict, boundary facets in
 * x->boundary, cells found not in conflict stamped ep + 1.              */
static dd_status find_power_region(dd_del *d, const double *p, double wp, uint32_t c0)
{
    dd_tri *x = d->qdt;
    dd_mark ep = dd_new_epoch(x, 2), tested = (dd_mark)(ep + 1);
    x->stack.n = x->conflict.n = x->boundary.n = 0;
    x->stamp[c0] = ep;
    dd_status s = dd_vec_push(&x->stack, c0);
    while (s == DD_OK && x->stack.n > 0) {
        uint32_t c = x->stack.a[--x->stack.n];
        s = dd_vec_push(&x->conflict, c);
        for (uint32_t i = 0; i < 4 && s == DD_OK; i++) {
            uint32_t nb = dd_tn(x, c)[i] >> 2;
            if (x->stamp[nb] == ep) continue;
            if (x->stamp[nb] != tested && dd_qdt_power_conflict(d, nb, p, wp)) {
                x->stamp[nb] = ep;
                s = dd_vec_push(&x->stack, nb);
            } else {
                x->stamp[nb] = tested;
                s = dd_vec_push(&x->boundary, 4 * c + i);
            }
        }
    }
    return s;
}

dd_status dd_qdt_insert_power(dd_del *d, uint32_t v, uint32_t start)
{
    dd_tri *x = d->qdt;
    dd_status s = find_power_region(d, dd_pt(x, v), x->wt[v], start);
    if (s == DD_OK) s = dd_reserve_star(x);
    if (s != DD_OK) return s;
    dd_fill_star(x, v);
    return DD_OK;
}

dd_status dd_qdt_scan_power(dd_del *d, uint32_t v, uint32_t *cell)
{
    dd_tri *x = d->qdt;
    const double *p = dd_pt(x, v);
    const double wp = x->wt[v];
    for (uint32_t c = 0; c < x->ncell; c++) {
        if (dd_tv(x, c)[0] == DD_DEAD || !has_qd(x, c)) continue;
        d->locate_steps++;
        if (dd_qdt_power_conflict_outer(d, c, p, wp)) { *cell = c; return DD_OK; }
    }
    return dd_fail(d->t, DD_ERR_INTERNAL, "no dummy cell of the conflict RT conflicts with point %u",
                   d->t->v2in[v]);
}

/* 1 if site u is a vertex of d->qdt now (vcell[u] is meaningful only
 * then: no live cell of this deletion holds a site never inserted or
 * swallowed since).                                                     */
static int is_qdt_vertex(const dd_tri *x, uint32_t u)
{
    const uint32_t c = x->vcell[u];
    return c < x->ncell && dd_tv(x, c)[0] != DD_DEAD && dd_index_of(x, c, u) >= 0;
}

/* 1 if an earlier site d->order[0 .. k) is a vertex with v's point and
 * weight (dd_insert_power's duplicate rule).                          */
static int is_duplicate(const dd_del *d, size_t k, uint32_t v)
{
    const dd_tri *x = d->qdt;
    const double *p = dd_pt(x, v);
    for (size_t j = 0; j < k; j++) {
        const uint32_t u = d->order.a[j];
        const double *o = dd_pt(x, u);
        if (dd_lex_cmp(o, p) == 0 && x->wt[u] == x->wt[v] &&
            is_qdt_vertex(x, u))
            return 1;
    }
    return 0;
}

dd_status dd_qdt_insert_hidden(dd_del *d)
{
    dd_tri *x = d->qdt;
    dd_status s = DD_OK;
    for (size_t k = d->nbr.n; k < d->order.n && s == DD_OK; k++) {
        const uint32_t v = d->order.a[k];
        if (is_duplicate(d, k, v)) continue;
        const double *p = dd_pt(x, v);
        const double wp = x->wt[v];
        uint32_t c0 = DD_NONE;
        for (uint32_t c = 0; c < x->ncell && c0 == DD_NONE; c++) {
            if (dd_tv(x, c)[0] == DD_DEAD || has_qd(x, c)) continue;
            d->locate_steps++;
            if (dd_qdt_power_conflict(d, c, p, wp)) c0 = c;
        }
        if (c0 != DD_NONE) s = dd_qdt_insert_power(d, v, c0);
    }
    return s;
}
