/*
 * hidden_move.c -- a kept hidden point forgotten, and the relocation
 * filter of a weighted move (hidden_move.h; DESIGN 12, issue 44).
 *
 * The filter is the weighted counterpart of flip.c's star test, without
 * flips: a weighted move either changes nothing but v's point and weight
 * (tested here, exactly) or goes through a removal and an insertion
 * (src/move.c).  Hidden points are hidden.c's; this file reads a cell's
 * list and unlinks one point, keeping hidden.h's invariants.
 */
#include "mesh/hidden_move.h"

void dd_hidden_forget(dd_tri *t, uint32_t v, uint32_t *cell)
{
    dd_hidset *h = t->hid;
    const uint32_t c = h->cell[v];
    if (h->head[c] == v) {
        h->head[c] = h->next[v];
    } else {
        uint32_t u = h->head[c];
        while (h->next[u] != v) u = h->next[u];
        h->next[u] = h->next[v];
    }
    const uint32_t i = h->at[v], last = h->all.a[--h->all.n];
    h->all.a[i] = last;
    h->at[last] = i;
    h->cell[v] = DD_NONE;
    *cell = c;
}

/* Whether p lies in the closure of finite cell c (exact orientations). */
static int holds(dd_tri *t, uint32_t c, const double *p)
{
    const uint32_t *v = dd_tv(t, c);
    for (int i = 0; i < 4; i++) {
        const double *q[4] = {dd_pt(t, v[0]), dd_pt(t, v[1]), dd_pt(t, v[2]), dd_pt(t, v[3])};
        q[i] = p;
        if (dd_orient3d(&t->pred, q[0], q[1], q[2], q[3]) < 0) return 0;
    }
    return 1;
}

/* Every hidden point kept in the cells cells[0..n) still in its cell's
 * closure and not in power conflict with it.                          */
static int hidden_stay(dd_tri *t, const uint32_t *cells, size_t n)
{
    const dd_hidset *h = t->hid;
    if (!h->keep) return 1;
    for (size_t k = 0; k < n; k++) {
        const uint32_t c = cells[k];
        if (c >= h->ncap) continue;
        for (uint32_t x = h->head[c]; x != DD_NONE; x = h->next[x])
            if (!holds(t, c, dd_pt(t, x)) || dd_cell_power_conflict_fast(t, c, dd_pt(t, x), t->wt[x])) return 0;
    }
    return 1;
}

/* Facet j of star cell c is locally regular: the apex across it is not
 * in power conflict with c; across a hull facet (apex DD_INF), c's own
 * apex is not in conflict with the infinite cell.  The rule flip.c's
 * Lawson loop applies with the in-sphere test.                        */
static int locally_regular(dd_tri *t, uint32_t c, uint32_t j)
{
    const uint32_t g = dd_tn(t, c)[j], n = g >> 2, o = dd_tv(t, n)[g & 3];
    if (o != DD_INF) return !dd_cell_power_conflict_fast(t, c, dd_pt(t, o), t->wt[o]);
    const uint32_t x = dd_tv(t, c)[j];
    return x == DD_INF || !dd_cell_power_conflict_fast(t, n, dd_pt(t, x), t->wt[x]);
}

/* The star t->conflict (marked with epoch ep) with v at its new point:
 * positive finite cells, locally regular facets (each shared facet
 * once), hidden points staying.                                        */
static int star_stays(dd_tri *t, dd_mark ep)
{
    const dd_vec *star = &t->conflict;
    for (size_t k = 0; k < star->n; k++) {
        const uint32_t c = star->a[k], *w = dd_tv(t, c);
        if (dd_is_infinite_cell(t, c)) continue;
        if (dd_orient3d(&t->pred, dd_pt(t, w[0]), dd_pt(t, w[1]), dd_pt(t, w[2]), dd_pt(t, w[3])) <= 0) return 0;
    }
    for (size_t k = 0; k < star->n; k++) {
        const uint32_t c = star->a[k];
        for (uint32_t j = 0; j < 4; j++) {
            const uint32_t n = dd_tn(t, c)[j] >> 2;
            if (t->stamp[n] == ep && n < c) continue;      /* tested from n */
            if (!locally_regular(t, c, j)) return 0;
        }
    }
    return hidden_stay(t, star->a, star->n);
}

int dd_move_power_in_place(dd_tri *t, uint32_t v, const double p[3], double w, dd_status *err)
{
    *err = dd_star_cells(t, v, &t->conflict);
    if (*err != DD_OK) return 0;
    const dd_mark ep = t->stamp[t->vcell[v]];
    double *x = t->xyz + 3 * (size_t)v;
    const double old[3] = {x[0], x[1], x[2]}, wold = t->wt[v];
    x[0] = p[0], x[1] = p[1], x[2] = p[2];
    t->wt[v] = w;
    if (star_stays(t, ep)) return 1;
    x[0] = old[0], x[1] = old[1], x[2] = old[2];
    t->wt[v] = wold;
    return 0;
}
