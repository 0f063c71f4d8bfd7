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

/* A live cell of the changed region (made, then the star's) whose
 * closure holds p, or DD_NONE.                                        */
static uint32_t find_home(dd_tri *t, const dd_vec *made, dd_mark gone_mark, const double *p)
{
    const dd_vec *star = &t->conflict;
    for (size_t m = 0; m < made->n; m++) {
        const uint32_t c = made->a[m];
        if (t->stamp[c] != gone_mark && holds(t, c, p)) return c;
    }
    for (size_t m = 0; m < star->n; m++) {
        const uint32_t c = star->a[m];
        if (t->stamp[c] != gone_mark && !dd_is_infinite_cell(t, c) && holds(t, c, p)) return c;
    }
    return DD_NONE;
}

/* Hidden point x, whose cell is gone or no longer holds it, gets a new
 * home: 1 when one holds it and it stays hidden there, the pair
 * (x, home) then on homes; 0 otherwise (or out of memory: *err).     */
static int rehome(dd_tri *t, const dd_vec *made, dd_mark gone_mark, uint32_t x, dd_vec *homes, dd_status *err)
{
    const uint32_t home = find_home(t, made, gone_mark, dd_pt(t, x));
    if (home == DD_NONE || !stays_hidden(t, home, x)) return 0;
    if ((*err = dd_vec_room(homes, 2)) != DD_OK) return 0;
    homes->a[homes->n++] = x;
    homes->a[homes->n++] = home;
    return 1;
}

/* x and y carry the same weighted point. */
static int same_point(const dd_tri *t, uint32_t x, uint32_t y)
{
    const double *a = dd_pt(t, x), *b = dd_pt(t, y);
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2] && t->wt[x] == t->wt[y];
}

/* Bound on the hidden points of a star compared for exact copies; more
 * of them go the reference's way (a removal and an insertion).        */
#define DD_HOLD_SEEN 64

int dd_hidden_flips_hold(dd_tri *t, uint32_t v, const dd_vec *made, const dd_vec *gone, dd_mark gone_mark, int moved,
                         dd_vec *homes, dd_status *err)
{
    const dd_hidset *h = t->hid;
    const dd_vec *star = &t->conflict;
    const int none = v < h->vcap && h->nin[v] == 0;     /* no list of v's star holds a point */
    uint32_t seen[DD_HOLD_SEEN], nseen = 0;
    homes->n = 0;
    /* The star's points are those the reference's removal takes: two
     * exact copies among them (one would be forgotten if they came
     * back), or a copy of v's new weighted point, and the flips could
     * not give its state.                                              */
    for (size_t k = 0; k < star->n && !none; k++) {
        const uint32_t c = star->a[k];
        if (c >= h->ncap) continue;
        const int live = t->stamp[c] != gone_mark;
        for (uint32_t x = h->head[c]; x != DD_NONE; x = h->next[x]) {
            if (nseen == DD_HOLD_SEEN || same_point(t, x, v)) return 0;
            for (uint32_t a = 0; a < nseen; a++)
                if (same_point(t, x, seen[a])) return 0;
            seen[nseen++] = x;
            if (!live) continue;                              /* the loop below */
            if (!moved || holds(t, c, dd_pt(t, x))) {
                if (!stays_hidden(t, c, x)) return 0;
            } else if (!rehome(t, made, gone_mark, x, homes, err)) {
                return 0;
            }
        }
    }
    for (size_t k = 0; k < gone->n; k++) {
        const uint32_t g = gone->a[k], *gv = dd_tv(t, g);
        if (g >= h->ncap || (none && (gv[0] == v || gv[1] == v || gv[2] == v || gv[3] == v))) continue;
        for (uint32_t x = h->head[g]; x != DD_NONE; x = h->next[x])
            if (same_point(t, x, v) || !rehome(t, made, gone_mark, x, homes, err)) return 0;
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
