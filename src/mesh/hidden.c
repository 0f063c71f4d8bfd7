/*
 * hidden.c -- the hidden points of a regular triangulation: where they
 * live, how an edit takes them out of the cells it replaces and re-homes
 * them, and the validator's proof that each is hidden (hidden.h).
 *
 * Invariant: see hidden.h.  Every allocation happens in the steps that
 * may fail (dd_hidden_add, dd_hidden_take_region, dd_hidden_take), before
 * any list changes; dd_hidden_settle only writes into room reserved.
 */
#include "mesh/hidden.h"
#include "dtdel/alloc.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

dd_status dd_hidden_init(dd_tri *t, int keep)
{
    dd_hidset *h = dd_calloc(1, sizeof *h);
    if (!h) return DD_ERR_NOMEM;
    h->keep = keep;
    t->hid = h;
    return DD_OK;
}

void dd_hidden_free(dd_tri *t)
{
    dd_hidset *h = t->hid;
    if (!h) return;
    dd_mfree(h->head);
    dd_mfree(h->next);
    dd_mfree(h->cell);
    dd_mfree(h->at);
    dd_mfree(h->nin);
    dd_vec_free(&h->all);
    dd_vec_free(&h->taken);
    dd_vec_free(&h->seen);
    dd_mfree(h);
    t->hid = NULL;
}

/* head covers at least ncells cells (new entries empty). */
static dd_status room_cells(dd_hidset *h, size_t ncells)
{
    if (ncells <= h->ncap) return DD_OK;
    size_t cap = h->ncap ? h->ncap : 64;
    while (cap < ncells) cap += cap / 2 + 1;
    if (cap > UINT32_MAX - 8) cap = UINT32_MAX - 8;
    uint32_t *a = dd_realloc(h->head, cap * sizeof *a);
    if (!a) return DD_ERR_NOMEM;
    for (size_t c = h->ncap; c < cap; c++) a[c] = DD_NONE;
    h->head = a;
    h->ncap = (uint32_t)cap;
    return DD_OK;
}

/* The per-vertex arrays cover at least nv vertex ids (new ids not
 * hidden).  A refusal leaves the arrays valid, vcap unchanged.          */
static dd_status room_vertices(dd_hidset *h, size_t nv)
{
    if (nv <= h->vcap) return DD_OK;
    size_t cap = h->vcap ? h->vcap : 64;
    while (cap < nv) cap *= 2;
    uint32_t **arr[4] = {&h->next, &h->cell, &h->at, &h->nin};
    for (int k = 0; k < 4; k++) {
        uint32_t *a = dd_realloc(*arr[k], cap * sizeof *a);
        if (!a) return DD_ERR_NOMEM;
        *arr[k] = a;
    }
    for (size_t v = h->vcap; v < cap; v++) h->cell[v] = DD_NONE, h->nin[v] = 0;
    h->vcap = (uint32_t)cap;
    return DD_OK;
}

/* Counts a point in or out of the stars of finite cell c's vertices
 * (nin, see hidden.h): d = 1 or -1 (as unsigned).                      */
static void count_in_stars(const dd_tri *t, dd_hidset *h, uint32_t c, uint32_t d)
{
    const uint32_t *w = dd_tv(t, c);
    for (int j = 0; j < 4; j++) h->nin[w[j]] += d;
}

/* Puts v on finite cell c's list (room reserved; v on no list). */
static void put(const dd_tri *t, dd_hidset *h, uint32_t c, uint32_t v)
{
    count_in_stars(t, h, c, 1);
    h->cell[v] = c;
    h->next[v] = h->head[c];
    h->head[c] = v;
}

/* Makes v a hidden point in c (room reserved, also in all). */
static void hide(const dd_tri *t, dd_hidset *h, uint32_t c, uint32_t v)
{
    h->at[v] = (uint32_t)h->all.n;
    h->all.a[h->all.n++] = v;
    put(t, h, c, v);
}

dd_status dd_hidden_add(dd_tri *t, uint32_t c, uint32_t v)
{
    dd_hidset *h = t->hid;
    if (!h->keep) return DD_OK;
    dd_status s = room_cells(h, (size_t)c + 1);
    if (s == DD_OK) s = room_vertices(h, (size_t)(v < t->nvid ? t->nvid : v + 1));
    if (s == DD_OK) s = dd_vec_room(&h->all, 1);
    if (s != DD_OK) return s;
    hide(t, h, c, v);
    return DD_OK;
}

/* Moves the lists of cells[0..n) to taken (room reserved). */
static void take_lists(const dd_tri *t, dd_hidset *h, const uint32_t *cells, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        const uint32_t c = cells[i];
        if (c >= h->ncap) continue;
        for (uint32_t v = h->head[c], nx; v != DD_NONE; v = nx) {
            nx = h->next[v];
            h->taken.a[h->taken.n++] = v;
            h->next[v] = DD_NONE;               /* no start of its own (settle) */
            count_in_stars(t, h, c, (uint32_t)-1);
        }
        h->head[c] = DD_NONE;
    }
}

/* Notes the finite vertices of cells[0..n) in seen (room reserved) and
 * returns how many hidden points their lists hold: one pass, the cells'
 * records in cache from the conflict search.                            */
static size_t note_vertices(dd_tri *t, dd_hidset *h, const uint32_t *cells, size_t n)
{
    uint32_t *seen = h->seen.a + h->seen.n;
    const uint32_t *head = h->head, *next = h->next, ncap = h->keep ? h->ncap : 0;
    size_t m = 0, k = 0;
    for (size_t i = 0; i < n; i++) {
        const uint32_t c = cells[i], *w = dd_tv(t, c);
        for (int j = 0; j < 4; j++) {
            seen[m] = w[j];
            m += w[j] != DD_INF;
        }
        if (c < ncap)
            for (uint32_t v = head[c]; v != DD_NONE; v = next[v]) k++;
    }
    h->seen.n += m;
    return k;
}

dd_status dd_hidden_take_region(dd_tri *t)
{
    dd_hidset *h = t->hid;
    const size_t nc = t->conflict.n;
    dd_status s = dd_vec_room(&h->seen, 4 * nc);
    if (s != DD_OK) return s;
    const size_t k = note_vertices(t, h, t->conflict.a, nc);
    if (h->keep) {
        /* new cells get ids below ncell + boundary.n; swallowed vertices
         * join all (at most 4 a cell); the new point's id is below nvid + 1 */
        s = room_cells(h, (size_t)t->ncell + t->boundary.n);
        if (s == DD_OK) s = room_vertices(h, (size_t)t->nvid + 1);
        if (s == DD_OK) s = dd_vec_room(&h->all, 4 * nc);
        if (s == DD_OK) s = dd_vec_room(&h->taken, k);
    }
    if (s != DD_OK) {
        h->seen.n = 0;
        return s;
    }
    if (k) take_lists(t, h, t->conflict.a, nc);
    return DD_OK;
}

/* Moves the lists of cells[0..n), the star of vertex q, to taken (room
 * reserved), each point with the outside facet across the facet of its
 * cell opposite q in next[] (the point is on no list while taken): after
 * the deletion that facet's neighbour is the new cell over the point's
 * old link triangle, where dd_hidden_settle starts its walk.            */
static void take_star_lists(dd_tri *t, dd_hidset *h, const uint32_t *cells, size_t n, uint32_t q)
{
    for (size_t i = 0; i < n; i++) {
        const uint32_t c = cells[i];
        uint32_t v = h->head[c];
        if (v == DD_NONE) continue;
        const uint32_t out = dd_tn(t, c)[dd_slot_of(dd_tv(t, c), q)];
        while (v != DD_NONE) {
            const uint32_t nx = h->next[v];
            h->taken.a[h->taken.n++] = v;
            h->next[v] = out;
            count_in_stars(t, h, c, (uint32_t)-1);
            v = nx;
        }
        h->head[c] = DD_NONE;
    }
}

dd_status dd_hidden_take(dd_tri *t, const uint32_t *cells, size_t n, uint32_t q, const uint32_t **pts, size_t *npts)
{
    dd_hidset *h = t->hid;
    const size_t before = h->taken.n;
    if (h->keep) {
        /* every point taken is hidden and taken once: room for all of
         * them (seldom grown) spares a counting pass over the cells;
         * heads for every cell id spare a bounds test a cell; counts for
         * every vertex id let q's say that its star holds none         */
        dd_status s = room_vertices(h, t->nvid);
        if (s == DD_OK && h->nin[q] != 0) {
            if ((s = dd_vec_room(&h->taken, h->all.n)) == DD_OK) s = room_cells(h, t->ncell);
            if (s == DD_OK) take_star_lists(t, h, cells, n, q);
        }
        if (s != DD_OK) return s;
    }
    *pts = h->taken.n > before ? h->taken.a + before : NULL;   /* no pointer arithmetic on NULL */
    *npts = h->taken.n - before;
    return DD_OK;
}

dd_status dd_hidden_room(dd_tri *t, size_t ncells)
{
    dd_hidset *h = t->hid;
    if (!h->keep) return DD_OK;
    dd_status s = room_cells(h, ncells);
    return s == DD_OK ? room_vertices(h, t->nvid) : s;
}

void dd_hidden_release(dd_tri *t, uint32_t v)
{
    dd_hidset *h = t->hid;
    for (size_t k = 0; k < h->taken.n; k++)
        if (h->taken.a[k] == v) {
            h->taken.a[k] = h->taken.a[--h->taken.n];
            break;
        }
    const uint32_t i = h->at[v], last = h->all.a[--h->all.n];
    h->all.a[i] = last;
    h->at[last] = i;
    h->cell[v] = DD_NONE;
}

/* A finite cell whose closure holds p, walked to from `start`.  A point
 * kept hidden lies in the closed hull, so the walk ends in a finite cell;
 * should it end in an infinite one (p on the hull's boundary cannot make
 * it), the finite cell across its hull facet is taken.                 */
static dd_status home_of(dd_tri *t, const double *p, uint32_t start, uint32_t *c)
{
    dd_status s = dd_walk_locate(t, p, start, c);
    if (s == DD_OK && dd_is_infinite_cell(t, *c)) *c = dd_tn(t, *c)[dd_index_of(t, *c, DD_INF)] >> 2;
    return s;
}

/* Where the walk re-homing taken point v starts: the cell across the
 * outside facet noted when v was taken (take_star_lists), a new cell
 * over v's old link triangle, when there is one; else `prev`.          */
static uint32_t walk_start(const dd_tri *t, const dd_hidset *h, uint32_t v, uint32_t prev)
{
    const uint32_t out = h->next[v];
    if (out == DD_NONE || dd_tv(t, out >> 2)[0] == DD_DEAD) return prev;
    const uint32_t c = dd_tn(t, out >> 2)[out & 3] >> 2;
    return dd_tv(t, c)[0] == DD_DEAD ? prev : c;
}

dd_status dd_hidden_settle(dd_tri *t)
{
    dd_hidset *h = t->hid;
    uint32_t start = t->hint, c;
    dd_status s = DD_OK;
    for (size_t k = 0; k < h->seen.n; k++) {
        const uint32_t x = h->seen.a[k], xc = t->vcell[x];
        if (xc == DD_NONE || dd_tv(t, xc)[0] != DD_DEAD) continue;
        t->vcell[x] = DD_NONE;                  /* swallowed: no vertex now */
        t->nvert--;
        if (!h->keep) continue;
        if ((s = home_of(t, dd_pt(t, x), start, &c)) != DD_OK) break;
        hide(t, h, c, x);
        start = c;
    }
    h->seen.n = 0;
    for (size_t k = 0; k < h->taken.n && s == DD_OK; k++) {
        const uint32_t v = h->taken.a[k];
        if ((s = home_of(t, dd_pt(t, v), walk_start(t, h, v, start), &c)) != DD_OK) break;
        put(t, h, c, v);
        start = c;
    }
    h->taken.n = 0;
    return s;
}

static int cmp_u32(const void *a, const void *b)
{
    const uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

dd_status dd_hidden_inputs(const dd_tri *t, uint32_t **idx, size_t *n)
{
    *idx = NULL;
    *n = 0;
    const size_t m = dd_hidden_count(t);
    if (m == 0) return DD_OK;
    uint32_t *a = dd_malloc(m * sizeof *a);
    if (!a) return DD_ERR_NOMEM;
    for (size_t k = 0; k < m; k++) a[k] = t->v2in[t->hid->all.a[k]];
    qsort(a, m, sizeof *a, cmp_u32);
    *idx = a;
    *n = m;
    return DD_OK;
}

/* Whether p lies in the closure of finite cell c (exact orientations). */
static int holds(const dd_tri *t, dd_pred *pr, uint32_t c, const double *p)
{
    const uint32_t *v = dd_tv(t, c);
    for (int i = 0; i < 4; i++) {
        const double *q[4] = {dd_pt(t, v[0]), dd_pt(t, v[1]), dd_pt(t, v[2]), dd_pt(t, v[3])};
        q[i] = p;
        if (dd_orient3d(pr, q[0], q[1], q[2], q[3]) < 0) return 0;
    }
    return 1;
}

/* The validator's failure: its message in msg (if not NULL). */
static dd_status refute(char *msg, size_t msglen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static dd_status refute(char *msg, size_t msglen, const char *fmt, ...)
{
    if (msg && msglen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, msglen, fmt, ap);
        va_end(ap);
    }
    return DD_ERR_INTERNAL;
}
#define REFUTE(...) refute(msg, msglen, __VA_ARGS__)

/* One hidden point v on cell c's list: the invariants of hidden.h. */
static dd_status check_point(const dd_tri *t, dd_pred *pr, uint32_t c, uint32_t v, char *msg, size_t msglen)
{
    const dd_hidset *h = t->hid;
    const int in = (int)t->v2in[v];
    if (v >= t->nvid || h->cell[v] != c) return REFUTE("hidden point id %u is on cell %u's list but not there", v, c);
    if (t->vcell[v] != DD_NONE) return REFUTE("hidden point %d is also a vertex", in);
    if (h->at[v] >= h->all.n || h->all.a[h->at[v]] != v) return REFUTE("hidden point %d is not in the list of all", in);
    if (dd_is_infinite_cell(t, c)) return REFUTE("hidden point %d is kept in infinite cell %u", in, c);
    if (!holds(t, pr, c, dd_pt(t, v))) return REFUTE("hidden point %d lies outside its cell %u", in, c);
    if (dd_cell_power_conflict_on(t, pr, c, dd_pt(t, v), t->wt[v]))
        return REFUTE("point %d is kept hidden but is in conflict with its cell %u: not hidden", in, c);
    /* A vertex's position is in the closure of a cell only as one of
     * its corners: a hidden exact copy of a vertex's weighted point would
     * sit at one (CGAL keeps none: its insert on that vertex adds nothing). */
    const double *p = dd_pt(t, v);
    for (uint32_t j = 0; j < 4; j++) {
        const uint32_t u = dd_tv(t, c)[j];
        const double *q = dd_pt(t, u);
        if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2] && t->wt[u] == t->wt[v])
            return REFUTE("hidden point %d is an exact copy of vertex %d's weighted point", in, (int)t->v2in[u]);
    }
    return DD_OK;
}

dd_status dd_hidden_check(const dd_tri *t, dd_pred *pr, char *msg, size_t msglen)
{
    const dd_hidset *h = t->hid;
    if (!h) return DD_OK;
    if (h->taken.n || h->seen.n) return REFUTE("hidden points left waiting to be re-homed");
    if (!h->keep) return h->all.n ? REFUTE("hidden points kept though they are forgotten") : DD_OK;
    size_t count = 0;
    for (uint32_t c = 0; c < h->ncap; c++) {
        if (h->head[c] == DD_NONE) continue;
        if (c >= t->ncell || dd_tv(t, c)[0] == DD_DEAD) return REFUTE("dead cell %u keeps hidden points", c);
        size_t k = 0;
        for (uint32_t v = h->head[c]; v != DD_NONE; v = h->next[v], k++) {
            if (++count > h->all.n) return REFUTE("the hidden lists hold more points than the %zu hidden", h->all.n);
            dd_status s = check_point(t, pr, c, v, msg, msglen);
            if (s != DD_OK) return s;
        }
        for (int j = 0; j < 4; j++)      /* nin bounds the star's points from above (hidden.h) */
            if (h->nin[dd_tv(t, c)[j]] < k)
                return REFUTE("vertex %u's star has %zu hidden points in cell %u, its count says %u",
                              t->v2in[dd_tv(t, c)[j]], k, c, h->nin[dd_tv(t, c)[j]]);
    }
    if (count != h->all.n) return REFUTE("%zu hidden points recorded, %zu in the cells' lists", h->all.n, count);
    return DD_OK;
}

size_t dd_hidden_bytes(const dd_tri *t)
{
    const dd_hidset *h = t->hid;
    if (!h) return 0;
    return sizeof *h + (size_t)h->ncap * sizeof(uint32_t) + 4 * (size_t)h->vcap * sizeof(uint32_t)
         + (h->all.cap + h->taken.cap + h->seen.cap) * sizeof(uint32_t);
}
