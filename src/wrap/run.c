/*
 * run.c -- the wrap itself.
 */
#include "wrap/wrap_int.h"

static dd_status w_broken(dd_del *d, const char *what)
{
    return dd_fail(d->t, DD_ERR_INTERNAL, "gift wrapping the cavity of point %u: %s", d->t->v2in[d->q], what);
}

/* Room for `room` fill cells in all, `made` of them made already (in the
 * star's cells, then in new ones: see w_run).                          */
static dd_status w_reserve_fill(dd_del *d, struct dd_wrap *w, size_t made, size_t room)
{
    const size_t S = d->star.n, more = (room > S ? room - S : 0) - (made > S ? made - S : 0);
    dd_status s = dd_reserve_cells(d->t, (uint32_t)more);
    if (s == DD_OK) s = dd_vec_reserve(&d->fill, room);
    if (s == DD_OK) s = dd_vec_reserve(&d->sew_out, 4 * room);
    if (s == DD_OK && 4 * room > w->cap_lcell) {
        if (!w_grow((void **)&w->lcell, 4 * room, sizeof *w->lcell)) return DD_ERR_NOMEM;
        w->cap_lcell = (uint32_t)(4 * room);
    }
    return s;
}

/* Keeps the star's cells as they are (w->keep), before w_run writes the
 * fill over them.                                                      */
dd_status w_keep_star(dd_del *d, struct dd_wrap *w)
{
    const size_t words = DD_CELL_WORDS * d->star.n;
    if (words > w->cap_keep) {
        if (!w_grow((void **)&w->keep, words, sizeof *w->keep)) return DD_ERR_NOMEM;
        w->cap_keep = words;
    }
    for (size_t k = 0; k < d->star.n; k++)
        memcpy(w->keep + DD_CELL_WORDS * k, dd_tv(d->t, d->star.a[k]), DD_CELL_WORDS * sizeof *w->keep);
    return DD_OK;
}

/* Drops the fill cells made so far (w_run): the star's cells written
 * back, the cells made past them given back (dd_unmake_cells), the mesh
 * as it was.                                                           */
void w_drop_fill(dd_del *d, struct dd_wrap *w)
{
    const size_t S = d->star.n, F = d->fill.n;
    for (size_t k = 0; k < F && k < S; k++)
        memcpy(dd_tv(d->t, d->star.a[k]), w->keep + DD_CELL_WORDS * k, DD_CELL_WORDS * sizeof *w->keep);
    if (F > S) dd_unmake_cells(d->t, d->fill.a + S, F - S, w->ncell0);
    d->fill.n = 0;
}

/* Opens the link triangles, oriented towards q, as the first records (all
 * in the table) and returns the record the wrap starts from, *start: of
 * the triangles through `lead`, the neighbour of least vertex id (for a
 * hull vertex the infinite vertex, so that the wrap's first step is
 * w_scan_inf: where it cannot settle the hull, W_BAIL, every
 * neighbour in one plane or one of its checks failing, the wrap declines
 * before any other work), the one whose two other corners have the
 * least ids, rotated to begin with its least id.  That choice goes by
 * vertex ids, not by the local numbers (the order in which collect_star
 * met the neighbours), so the whole wrap, and so the order and rotation
 * of the fill cells, does not depend on how the star was stored: the
 * same deletion repeated is the same computation (the facet table's
 * layout and the guesses' lanes apart, which decide nothing).  The
 * neighbours were sorted by id for that before (a rank sort, 2% of a
 * deletion at bunny degree 72, callgrind).
 * With hub not NULL it also makes the known neighbours at the start (see
 * w_guess_narrow): the link's edges between finite vertices.  The link
 * triangles make a closed oriented surface, where each edge is met once
 * in each direction: each triangle gives each corner the next one, and
 * every neighbour of a vertex comes once.  *hub: whether the link has a
 * hub.                                                                   */
dd_status w_open_link(dd_del *d, struct dd_wrap *w, uint32_t *start, int *hub)
{
    dd_tri *t = d->t;
    const uint32_t n = w->n, inf = n;
    w_drop_fill(d, w);   /* d->qdt is not reset: the wrap uses only its predicates */
    w->nrec = 0;
    /* Sized for 6n records: a wrap opens 2.9n (the curves) to 4.7n
     * (uniform points, degree 48-63: up to 5.2n) with the link's; sized
     * for 4n, the table grew and took its records again in most wraps
     * there (callgrind: 2.5% of a deletion).                             */
    dd_status s = w_ftab_reset(w, 6 * (size_t)n);
    if (s != DD_OK) return s;
    if ((s = w_reserve_recs(w, d->star.n)) != DD_OK) return s;
    if (hub) memset(w->nadj, 0, n * sizeof *w->nadj);
    const int puts = hub && w->hub_last;             /* else count them (see below) */
    uint64_t kmin = UINT64_MAX;
    uint32_t rmin = 0;
    const uint32_t *gid = d->order.a;                /* gid[inf] = DD_INF, above all */
    /* The start is a triangle through `lead`: for a hull vertex the
     * infinite vertex, else the neighbour of least id (each neighbour is
     * a corner of the link).                                             */
    const uint32_t lead = d->on_hull ? inf : w->lead;
    /* Every vertex of a star cell but q is a neighbour (collect_star), so
     * w->loc holds the local number of each finite link vertex.         */
    for (size_t k = 0; k < d->star.n; k++) {
        uint32_t c = d->star.a[k];
        const uint32_t *v = dd_tv(t, c);
        int i = dd_index_of(t, c, d->q);
        uint32_t lv[3];
        for (int j = 0; j < 3; j++) {
            uint32_t g = v[dd_facet[i][j]];
            lv[j] = g == DD_INF ? inf : w->loc[g];
        }
        if (puts)
            w_adj_link(w, lv, inf);
        else if (hub)
            for (int j = 0; j < 3; j++) {
                uint32_t u = lv[j == 2 ? 0 : j + 1];
                if (lv[j] != inf && u != inf) w->nadj[lv[j]] = (uint8_t)(w->nadj[lv[j]] + (w->nadj[lv[j]] < W_ADJ_FULL));
            }
        int found;
        uint32_t *val = w_fslot_of(w, w_fkey(w, lv[0], lv[1], lv[2]), &found);
        if (found) return w_broken(d, "a link triangle appears twice");
        if ((lv[0] == lead) | (lv[1] == lead) | (lv[2] == lead)) {
            /* the ids of the other two corners (the lead's own is the largest
             * of the three, DD_INF, or the least): least, then largest */
            uint32_t g0 = gid[lv[0]], g1 = gid[lv[1]], g2 = gid[lv[2]];
            dd_sort3u(&g0, &g1, &g2);
            uint64_t key = lead == inf ? (uint64_t)g0 << 32 | g1 : (uint64_t)g1 << 32 | g2;
            if (key < kmin) { kmin = key; rmin = w->nrec; }
        }
        w->out[w->nrec] = dd_tn(t, c)[(uint32_t)i];
        w_open(w, val, lv[0], lv[1], lv[2], W_NONE);
    }
    if (w->nrec == 0) return w_broken(d, "no link triangle");
    if (hub) {
        /* Without the last link's hub the puts were counted only (on
         * uniform points and the bunny, no hubs, they were a third of this
         * function); the lists are made here, from the records, where a
         * count shows a hub.  A pass of its own: testing each put cost 25%
         * more (callgrind).                                              */
        *hub = 0;
        for (uint32_t k = 0; k < n && !*hub; k++) *hub = w->nadj[k] == W_ADJ_FULL;
        if (*hub && !puts) {                     /* the lists, from the records */
            memset(w->nadj, 0, n * sizeof *w->nadj);
            for (uint32_t r = 0; r < w->nrec; r++) w_adj_link(w, w->tri[r], inf);
        }
        w->hub_last = *hub;
    }
    uint32_t *st = w->tri[rmin];
    while (gid[st[0]] > gid[st[1]] || gid[st[0]] > gid[st[2]]) {   /* rotate: same orientation */
        uint32_t x0 = st[0];
        st[0] = st[1]; st[1] = st[2]; st[2] = x0;
    }
    *start = rmin;
    return DD_OK;
}

/* Whether (a, b, c) is a rotation of triangle r: the same orientation.  */
static inline int w_same_turn(const uint32_t r[3], uint32_t a, uint32_t b)
{
    return (r[0] == a && r[1] == b) | (r[1] == a && r[2] == b) | (r[2] == a && r[0] == b);
}

/* The wrap from record `start`: each open facet gives the cell on its
 * open side, found by wrap_scan (w_scan_inf through the infinite
 * vertex) or, when `guess`, by wrap_guess.  The cells are made in the
 * mesh and glued to each other there: the k-th (d->fill.a[k]) over the
 * k-th cell of the star, kept in w->keep (w_keep_star), then, past the
 * star, in new cells; a record's `own` is facet 4k+j of the k-th.  Each
 * facet of a new cell goes in d->sew_out for the sew: a link triangle's
 * outside facet, or DD_NONE inside the fill.  Nothing outside the
 * cavity reaches these cells until the sew glues them, and a fill that
 * is not kept is dropped (w_drop_fill): the star written back, the mesh
 * as it was.  Against building it in d->qdt and copying it over the
 * star's cells at the sew (callgrind, 300 deletions): uniform degree
 * 24-31, 18.80M -> 17.91M instructions, bunny degree 32-47 11.63M ->
 * 11.08M (made in free cells: 18.17M, 11.23M; deletion / re-insertion,
 * alternated runs, uniform 24-31: 1.76 -> 1.72).  Made in free cells
 * instead (not over the star), the fill took whatever the free list
 * held, the star's cells went on it, and the cells of a region scattered
 * over memory: deleting 10% of 10^6 uniform points in random order, one
 * after another, cost 15.1 against 9.9 us a deletion.
 * *outcome: W_DONE, W_DECLINED (see dd_wrap_fill), or
 * W_WRONG_GUESS: the guesses did not make a triangulation of the cavity
 * (a facet without a point beyond, a triangle met from the wrong side or
 * by a third cell, a fill too large).                                    */
dd_status w_run(dd_del *d, struct dd_wrap *w, int guess, uint32_t start, int *outcome)
{
    dd_tri *t = d->t;
    dd_pred *pr = &d->qdt->pred;                 /* the predicates' counters */
    const uint32_t n = w->n, inf = n, *gid = d->order.a;
    size_t room = 4 * (size_t)n + 16;                /* fill cells, grown below */
    dd_status s = w_reserve_fill(d, w, 0, room);
    if (s != DD_OK) return s;
    *outcome = W_DONE;
#define W_WRONG(why) do { if (guess) { *outcome = W_WRONG_GUESS; return DD_OK; } return w_broken(d, why); } while (0)
    uint32_t ns = 0, nlink = 0;
    double mb[6] = {0}, N[4], T[4], K[4] = {0};     /* guess: the new cell's pencil */
    w->stack[ns++] = start;
    size_t limit = 8 * (size_t)n * n + 64;          /* |fill| is O(n^2) */
    while (ns > 0) {
        uint32_t r = w->stack[--ns];
        if (w->closed[r]) continue;
        w->closed[r] = 1;
        uint32_t a = w->tri[r][0], b = w->tri[r][1], e = w->tri[r][2], p;
        int single = 0;                         /* p chosen in single precision */
        if (n >= W_EXACT_FROM && w_spent(w, pr) > 2 * (uint64_t)n) {
            *outcome = W_DECLINED;              /* see W_EXACT_FROM */
            return DD_OK;
        }
        if (a == inf || b == inf || e == inf) {
            while (e != inf) {                  /* rotate: same orientation */
                uint32_t a0 = a;
                a = b; b = e; e = a0;
            }
            p = w_scan_inf(w, pr, a, b);
        } else if (guess) {
            w_pencil(w, a, b, e, mb, N, T);
            p = w_guess_apex(w, pr, a, b, e, mb, N, T, d->on_hull, &single);
        } else {
            p = w_scan_apex(w, pr, a, b, e, d->on_hull);
        }
        if (p == W_BAIL) {
            *outcome = W_DECLINED;
            return DD_OK;
        }
        if (p == W_NONE || p == W_TIE) W_WRONG("an open facet has no point beyond it");
        size_t fp = d->fill.n;
        if (fp >= limit) W_WRONG("the fill does not close");
        if (fp == room && (s = w_reserve_fill(d, w, fp, room *= 2)) != DD_OK) return s;
        uint32_t m = fp < d->star.n ? d->star.a[fp] : dd_new_cell(t), lv[4] = {a, b, e, p};
        d->fill.a[d->fill.n++] = m;              /* at once: w_drop_fill */
        uint32_t *tv = dd_tv(t, m), *tn = dd_tn(t, m), *so = d->sew_out.a + 4 * fp;
        const uint32_t *fill = d->fill.a;
        for (int i = 0; i < 4; i++) {
            tv[i] = gid[lv[i]];                  /* gid[inf] = DD_INF */
            w->lcell[4 * fp + i] = lv[i];
        }
        const int finite = a != inf && b != inf && e != inf && p != inf;
        if (w->narrow && finite) {
            w_adj_edge(w, p, a);
            w_adj_edge(w, p, b);
            w_adj_edge(w, p, e);
        }
        if (guess && finite) {                   /* for w_conflicts */
            double *const *L = w->lift;
            double X[4] = {L[0][p] - L[0][a], L[1][p] - L[1][a], L[2][p] - L[2][a], L[3][p] - L[3][a]};
            w_cofactors(K, X, mb);
            /* a single-precision guess's point surely beyond abc (o as
             * w_row_o has it; the other guesses' points are so already) */
            if (single && !(X[0] * N[0] + X[1] * N[1] + X[2] * N[2] > w->oerr)) W_WRONG("");
        }
        /* A guess must be locally Delaunay on each facet it shares with a
         * finite fill cell (see dd_wrap_fill); the scans' cells are so.  */
#define W_CHECK_FACET(own)                                                                 \
        if (guess && finite && (own) != W_NONE && w->lcell[own] != inf &&                \
            w_conflicts(w, pr, lv, K, w->lcell[own]))                               \
            W_WRONG("")
        W_CHECK_FACET(w->own[r]);
        if (w->own[r] != W_NONE) {
            const uint32_t f = 4 * fill[w->own[r] >> 2] + (w->own[r] & 3);
            tn[3] = f;
            *dd_fn(t, f) = 4 * m + 3;
            so[3] = DD_NONE;
        } else {
            tn[3] = DD_NONE;
            so[3] = w->out[r];
            nlink++;
        }
        if ((s = w_reserve_recs(w, 3)) != DD_OK) return s;
        uint64_t key[3];                             /* facet j's: the cell's less lv[j] */
        const uint64_t *kw = w->kword, set = kw[a] ^ kw[b] ^ kw[e] ^ kw[p];
        for (uint32_t j = 0; j < 3; j++) key[j] = set ^ kw[lv[j]];
        for (uint32_t j = 0; j < 3; j++) {
            uint32_t f0 = lv[dd_facet[j][0]], f1 = lv[dd_facet[j][1]], f2 = lv[dd_facet[j][2]];
            int found;
            uint32_t *val = w_fslot_of(w, key[j], &found);
            if (found) {                         /* its other side is known */
                uint32_t o = *val;
                if (w->closed[o]) W_WRONG("a triangle bounds three cells");
                /* The new cell must lie on the record's open side.       */
                if (!w_same_turn(w->tri[o], f0, f1)) W_WRONG("a triangle is met from the wrong side");
                W_CHECK_FACET(w->own[o]);
                w->closed[o] = 1;
                if (w->own[o] != W_NONE) {
                    const uint32_t f = 4 * fill[w->own[o] >> 2] + (w->own[o] & 3);
                    tn[j] = f;
                    *dd_fn(t, f) = 4 * m + j;
                    so[j] = DD_NONE;
                } else {
                    tn[j] = DD_NONE;
                    so[j] = w->out[o];
                    nlink++;
                }
                continue;
            }
            tn[j] = DD_NONE;
            so[j] = DD_NONE;
            w->stack[ns++] = w->nrec;
            w_open(w, val, f1, f0, f2, 4 * (uint32_t)fp + j);   /* reversed: open outwards */
        }
    }
    /* Each link triangle closed at most once (above), so all of them
     * exactly once: the sew needs no matching of its own.               */
    if (nlink != d->star.n) W_WRONG("the fill does not cover the link");
#undef W_CHECK_FACET
#undef W_WRONG
    return DD_OK;
}
