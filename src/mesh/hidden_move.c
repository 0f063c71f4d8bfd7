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

/* Whether points a and b carry the same weighted point. */
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
        for (uint32_t a = star[i] < h->ncap ? h->head[star[i]] : DD_NONE; a != DD_NONE; a = h->next[a]) {
            for (uint32_t b = h->next[a]; b != DD_NONE; b = h->next[b])
                if (same_weighted(t, a, b)) return 1;
            for (size_t j = i + 1; j < n; j++)
                for (uint32_t b = star[j] < h->ncap ? h->head[star[j]] : DD_NONE; b != DD_NONE; b = h->next[b])
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

/* Kept hidden point x is not in power conflict with live cell c. */
static int stays_hidden(dd_tri *t, uint32_t c, uint32_t x)
{
    return !dd_cell_power_conflict_fast(t, c, dd_pt(t, x), t->wt[x]);
}

/* Whether cell c is one the flips replaced (gone_set NULL: none). */
static int is_gone(const uint32_t *gone_set, uint32_t c)
{
    return gone_set && dd_cellset_has(gone_set, c);
}

/* A live cell of the changed region (made, then the star's) whose
 * closure holds p, or DD_NONE.                                        */
static uint32_t find_home(dd_tri *t, const dd_vec *made, const uint32_t *gone_set, const double *p)
{
    const dd_vec *star = &t->conflict;
    for (size_t m = 0; m < made->n; m++) {
        const uint32_t c = made->a[m];
        if (!is_gone(gone_set, c) && holds(t, c, p)) return c;
    }
    for (size_t m = 0; m < star->n; m++) {
        const uint32_t c = star->a[m];
        if (!is_gone(gone_set, c) && !dd_is_infinite_cell(t, c) && holds(t, c, p)) return c;
    }
    return DD_NONE;
}

/* Hidden point x, whose cell is gone or no longer holds it, gets a new
 * home: 1 when one holds it and it stays hidden there, the pair
 * (x, home) then on homes; 0 otherwise (or out of memory: *err).     */
static int rehome(dd_tri *t, const dd_vec *made, const uint32_t *gone_set, uint32_t x, dd_vec *homes, dd_status *err)
{
    const uint32_t home = find_home(t, made, gone_set, dd_pt(t, x));
    if (home == DD_NONE || !stays_hidden(t, home, x)) return 0;
    if ((*err = dd_vec_room(homes, 2)) != DD_OK) return 0;
    homes->a[homes->n++] = x;
    homes->a[homes->n++] = home;
    return 1;
}

int dd_hidden_flips_hold(dd_tri *t, uint32_t v, const dd_vec *made, const dd_vec *gone, const uint32_t *gone_set,
                         int how, dd_vec *homes, dd_status *err)
{
    const dd_hidset *h = t->hid;
    const dd_vec *star = &t->conflict;
    const int none = v >= h->vcap || h->nin[v] == 0;    /* no list of v's star holds a point */
    homes->n = 0;
    /* A star point with v's new weighted point: the reference's removal
     * may bring it back and its insertion then refuse (v, p, w), or
     * hide it under a vertex with its point, a state flips cannot give. */
    for (size_t k = 0; k < star->n && !none; k++) {
        const uint32_t c = star->a[k];
        if (c >= h->ncap || h->head[c] == DD_NONE) continue;
        const int live = !is_gone(gone_set, c);
        for (uint32_t x = h->head[c]; x != DD_NONE; x = h->next[x]) {
            if (same_weighted(t, x, v)) return 0;
            if (!live) continue;                              /* the loop below */
            if (how == DD_MOVE_HEAVIER) {
#ifdef DD_TEST_BUILD
                if (!stays_hidden(t, c, x)) __builtin_trap();   /* the argument in hidden_move.h */
#endif
            } else if (how != DD_MOVE_POINT || holds(t, c, dd_pt(t, x))) {
                if (!stays_hidden(t, c, x)) return 0;
            } else if (!rehome(t, made, gone_set, x, homes, err)) {
                return 0;
            }
        }
    }
    for (size_t k = 0; k < gone->n; k++) {
        const uint32_t g = gone->a[k], *gv = dd_tv(t, g);
        if (g >= h->ncap || (none && (gv[0] == v || gv[1] == v || gv[2] == v || gv[3] == v))) continue;
        for (uint32_t x = h->head[g]; x != DD_NONE; x = h->next[x])
            if (same_weighted(t, x, v) || !rehome(t, made, gone_set, x, homes, err)) return 0;
    }
    return 1;
}

/* Takes x off the list of its cell c. */
static void unlink_point(dd_hidset *h, uint32_t c, uint32_t x)
{
    if (h->head[c] == x) {
        h->head[c] = h->next[x];
        return;
    }
    uint32_t u = h->head[c];
    while (h->next[u] != x) u = h->next[u];
    h->next[u] = h->next[x];
}

void dd_hidden_flips_rehome(dd_tri *t, const dd_vec *gone, const dd_vec *homes)
{
    dd_hidset *h = t->hid;
    for (size_t k = 0; k < homes->n; k += 2) unlink_point(h, h->cell[homes->a[k]], homes->a[k]);
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
