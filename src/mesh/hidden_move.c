/*
 * hidden_move.c -- a kept hidden point forgotten, and the hidden points
 * of a weighted move repaired by flips (hidden_move.h; DESIGN 12,
 * issue 44).
 *
 * A weighted move repaired by flips (flip.c) asks here whether every
 * kept hidden point of the cells it changed stays hidden, and where; a
 * move that cannot be repaired so goes through a removal and an
 * insertion (src/move.c).  Hidden points are hidden.c's; this file reads
 * a cell's lists, unlinks one point and moves the points of the cells a
 * flip replaced, keeping hidden.h's invariants.
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

/* Whether hidden points a and b carry the same weighted point. */
static int same_weighted(const dd_tri *t, uint32_t a, uint32_t b)
{
    const double *x = dd_pt(t, a), *y = dd_pt(t, b);
    return x[0] == y[0] && x[1] == y[1] && x[2] == y[2] && t->wt[a] == t->wt[b];
}

int dd_hidden_star_copies(const dd_tri *t, uint32_t v, const uint32_t *star, size_t n)
{
    const dd_hidset *h = t->hid;
    if (!h || !h->keep || v >= h->vcap || h->nin[v] < 2) return 0;   /* no list yet: none */
    for (size_t i = 0; i < n; i++)
        for (uint32_t a = h->head[star[i]]; a != DD_NONE; a = h->next[a]) {
            for (uint32_t b = h->next[a]; b != DD_NONE; b = h->next[b])
                if (same_weighted(t, a, b)) return 1;
            for (size_t j = i + 1; j < n; j++)
                for (uint32_t b = h->head[star[j]]; b != DD_NONE; b = h->next[b])
                    if (same_weighted(t, a, b)) return 1;
        }
    return 0;
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

/* Kept hidden point x of live cell c stays there: in c's closure (when
 * checked) and not in power conflict with it.                          */
static int stays_in(dd_tri *t, uint32_t c, uint32_t x, int check_closure)
{
    const double *p = dd_pt(t, x);
    return (!check_closure || holds(t, c, p)) && !dd_cell_power_conflict_fast(t, c, p, t->wt[x]);
}

int dd_hidden_flips_hold(dd_tri *t, const dd_vec *made, const dd_vec *gone, dd_mark gone_mark, int moved,
                         dd_vec *homes, dd_status *err)
{
    const dd_hidset *h = t->hid;
    const dd_vec *star = &t->conflict;
    homes->n = 0;
    for (size_t k = 0; k < star->n; k++) {
        const uint32_t c = star->a[k];
        if (c >= h->ncap || t->stamp[c] == gone_mark) continue;
        for (uint32_t x = h->head[c]; x != DD_NONE; x = h->next[x])
            if (!stays_in(t, c, x, moved)) return 0;
    }
    for (size_t k = 0; k < gone->n; k++) {
        const uint32_t g = gone->a[k];
        if (g >= h->ncap) continue;
        for (uint32_t x = h->head[g]; x != DD_NONE; x = h->next[x]) {
            uint32_t home = DD_NONE;
            for (size_t m = 0; m < made->n && home == DD_NONE; m++) {
                const uint32_t c = made->a[m];
                if (t->stamp[c] != gone_mark && holds(t, c, dd_pt(t, x))) home = c;
            }
            if (home == DD_NONE || !stays_in(t, home, x, 0)) return 0;
            if ((*err = dd_vec_room(homes, 2)) != DD_OK) return 0;
            homes->a[homes->n++] = x;
            homes->a[homes->n++] = home;
        }
    }
    return 1;
}

void dd_hidden_flips_rehome(dd_tri *t, const dd_vec *gone, const dd_vec *homes)
{
    dd_hidset *h = t->hid;
    for (size_t k = 0; k < gone->n; k++)
        if (gone->a[k] < h->ncap) h->head[gone->a[k]] = DD_NONE;
    for (size_t k = 0; k < homes->n; k += 2) {
        const uint32_t x = homes->a[k], c = homes->a[k + 1];
        h->next[x] = h->head[c];
        h->head[c] = x;
        h->cell[x] = c;
        for (int j = 0; j < 4; j++) h->nin[dd_tv(t, c)[j]]++;   /* c's corners' bounds (hidden.h) */
    }
}
