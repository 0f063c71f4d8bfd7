/*
 * wrap.c -- gift wrapping of a cavity (see wrap.h).
 *
 * Owns: struct dd_wrap (kept in d->wrap across deletions: no allocation
 * once warm), the local numbering of the neighbours (the infinite vertex
 * is number n), the table of open facets, the scans that find the fill
 * cell on a facet, the cells it writes into the mesh (over the star's,
 * kept aside in case the fill is not kept: w_run) and the matching it
 * hands to the sew (d->sew_out).
 *
 * An open facet is a triangle (a, b, c) of local numbers whose fill cell
 * on the positive side (orient3d(a, b, c, p) > 0) is still unknown.  The
 * link triangles start open, oriented towards q (mesh.h: the facet
 * opposite q in a star cell, in dd_facet order, has q on its positive
 * side); each new cell (a, b, c, p) closes the facet it was found from
 * and, for each other facet, closes it if it is open already or opens it
 * reversed.  A triangle meets at most two cells, so a facet closed twice
 * means a broken input and the deletion stops before touching the mesh.
 * A hull vertex adds cells with the infinite vertex: a finite facet with
 * no point beyond it becomes a hull facet, and a facet through the
 * infinite vertex is wrapped around its hull edge (w_scan_inf).
 */
#include "wrap/wrap_int.h"








void dd_wrap_free(struct dd_wrap *w)
{
    if (!w) return;
    free(w->pt);
    for (int i = 0; i < 4; i++) free(w->lift[i]), free(w->flift[i]);
    free(w->o); free(w->tmp); free(w->lexr); free(w->loc);
    free(w->fs);
    free(w->tri); free(w->own); free(w->out); free(w->closed); free(w->stack); free(w->lcell); free(w->keep);
    free(w->adj); free(w->nadj); free(w->seen); free(w->cand); free(w->code);
    free(w);
}

int w_grow(void **p, size_t n, size_t size)
{
    void *q = realloc(*p, n * size);
    if (!q) return 0;
    *p = q;
    return 1;
}

/* Room for n neighbours, and local numbers for vertex ids below nv. */
static dd_status w_reserve_n(struct dd_wrap *w, uint32_t n, uint32_t nv)
{
    if (n > w->cap_n) {
        uint32_t cap = w->cap_n ? w->cap_n : 64;
        while (cap < n) cap *= 2;
        if (!w_grow((void **)&w->pt, cap, sizeof *w->pt) || !w_grow((void **)&w->o, cap, sizeof *w->o) ||
            !w_grow((void **)&w->tmp, cap, sizeof *w->tmp) || !w_grow((void **)&w->lexr, cap, sizeof *w->lexr))
            return DD_ERR_NOMEM;
        for (int i = 0; i < 4; i++)
            if (!w_grow((void **)&w->lift[i], cap, sizeof *w->lift[i]) ||
                !w_grow((void **)&w->flift[i], cap, sizeof *w->flift[i]))
                return DD_ERR_NOMEM;
        if (!w_grow((void **)&w->adj, (size_t)cap * W_ADJ_CAP, sizeof *w->adj) ||
            !w_grow((void **)&w->nadj, cap, sizeof *w->nadj) || !w_grow((void **)&w->seen, cap, sizeof *w->seen) ||
            !w_grow((void **)&w->cand, cap, sizeof *w->cand))
            return DD_ERR_NOMEM;
        memset(w->seen, 0, cap * sizeof *w->seen);
        w->stamp = 0;
        w->cap_n = cap;
    }
    if (nv > w->cap_loc) {
        if (!w_grow((void **)&w->loc, nv, sizeof *w->loc)) return DD_ERR_NOMEM;
        w->cap_loc = nv;
    }
    return DD_OK;
}

























const char *const dd_wrap_stat_names[DD_WS_COUNT] = {
    "wrap: course (1 proved, 2 refuted, 3 scanned, 4 declined)",
    "wrap: last guess (0 wide, 1 short lists, 2 two steps)",
    "wrap: narrow guesses refuted",
    "wrap: integer lifts (1), integer cofactors (2)",
    "wrap: guessed again on shifted lifts",
    "wrap: guesses in single precision",
    "wrap: ... made in doubles instead",
    "wrap: a single-precision guess refuted",
    "wrap: hull steps in single precision",
    "wrap: ... made in doubles instead",
    "wrap: tests left to the exact predicates",
};

static void w_free_scratch(void *w) { dd_wrap_free(w); }
static const dd_scratch_kind w_kind = {"gift wrapping", w_free_scratch};

static dd_status w_get(dd_del *d, struct dd_wrap **out)
{
    struct dd_wrap *w = dd_del_scratch(d, &w_kind);
    if (!w) {
        w = calloc(1, sizeof *w);
        if (!w) return DD_ERR_NOMEM;
#ifdef W_AVX2
        w->has_avx2 = __builtin_cpu_supports("avx2");
        w->has_fma = __builtin_cpu_supports("fma");
#endif
        dd_status s = dd_del_keep_scratch(d, &w_kind, w);
        if (s != DD_OK) return s;
    }
    *out = w;
    return DD_OK;
}

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
static dd_status w_keep_star(dd_del *d, struct dd_wrap *w)
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
static void w_drop_fill(dd_del *d, struct dd_wrap *w)
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
static dd_status w_open_link(dd_del *d, struct dd_wrap *w, uint32_t *start, int *hub)
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
static dd_status w_run(dd_del *d, struct dd_wrap *w, int guess, uint32_t start, int *outcome)
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


dd_status dd_wrap_fill(dd_del *d, uint32_t wide_below, int *declined)
{
    dd_tri *t = d->t;
    *declined = 0;
    struct dd_wrap *w;
    dd_status s = w_get(d, &w);
    dd_del_strategy_stats(d, dd_wrap_stat_names, DD_WS_COUNT);
    if (s == DD_OK) s = w_reserve_n(w, (uint32_t)d->order.n, t->nvid);
    if (s == DD_OK) s = dd_vec_room(&d->order, 1);
    if (s != DD_OK) return s;
    if (d->order.n + 1 >= DD_WRAP_CODE_LEN) {        /* no keys (w_fkey) */
        d->sstat[DD_WS_COURSE] = DD_WRAP_DECLINED;
        *declined = 1;
        return DD_OK;
    }
    if (d->order.n >= 64 && (s = w_code_reserve(w, (uint32_t)d->order.n + 1)) != DD_OK) return s;
    d->fill.n = 0;                       /* no fill cell made yet (w_drop_fill) */
    w->ncell0 = t->ncell;
    DD_PHASE_BEGIN(d);
    if ((s = w_keep_star(d, w)) != DD_OK) return s;
    w->avx2 = w->has_avx2;
#ifdef DD_TEST_BUILD
    w->avx2 = w->avx2 && !t->testctl[DD_TEST_SCALAR];   /* dtdel_stats.h */
#endif
    d->order.a[d->order.n] = DD_INF;     /* DD_INF's local number is n: gid[n] */
    const uint32_t *gid = d->order.a;
    const uint32_t n = w->n = (uint32_t)d->order.n;
    w->lead = 0;                         /* the neighbour of least id (w_open_link) */
    for (uint32_t k = 0; k < n; k++) {
        w->pt[k] = dd_pt(t, gid[k]);
        w->loc[gid[k]] = k;
        w->lead = gid[k] < gid[w->lead] ? k : w->lead;
    }
    w_lift(w, d->qp);
    w->unf0 = w_unfiltered(&d->qdt->pred);
    d->sstat[DD_WS_INTEGER] = w->exact ? 1u : w->kexact ? 2u : 0u;
    w->cosph = 0;                                    /* w_cospherical may set it */
    w->lean = w->avx2 && !w->oexact && n >= W_LEAN_FROM;
    /* The lean guess and the hull step in single precision first
     * (w_guess_f32_avx2, w_inf_f32).  The sanitizer build makes them only
     * for input points of index 0 mod 4, and spoils some of their answers
     * for 4 mod 8 (w_guess_f32, w_scan_inf).  A refuted guess is made
     * again in doubles; the hull steps, each proved in doubles (and on
     * the x, y, z the shifted lifts keep), stay in floats.              */
    w->flift_ok = w->lean && w->has_fma && w->m >= 1e-50 && w->m <= 1e50;
#ifdef DD_TEST_BUILD
    w->flift_ok = w->flift_ok && !t->testctl[DD_TEST_NO_SINGLE];
    w->f32_spoil = t->testctl[DD_TEST_SPOIL_SINGLE] != 0;
#endif
    w->f32 = w->flift_ok;
    w->f32_kept = w->f32_back = w->inf_kept = w->inf_back = 0;
    w->f32_ready = 0;
    /* The sanitizer build also narrows both narrow guesses to the
     * shortest lists of a facet's corners, with no second step, for
     * input points of index 3 mod 4: there they are refuted much more often,
     * and the wide guess after them is tested too (tests: wrap-narrow). */
#ifdef DD_TEST_BUILD
    w->narrower = t->testctl[DD_TEST_NARROWER] != 0;
#else
    w->narrower = 0;
#endif
    /* Guess, then prove (filters on).  The guessed fill takes for each
     * finite facet the point of least t/o beyond it (wrap_guess: one pass,
     * no check against the other points; points of unsure orientation
     * decided and compared with it by w_scan_exact), or, for a hull
     * vertex, the infinite vertex when every other point is behind the
     * facet (surely, by the guess's own pass, or by w_scan_exact with
     * the flat-hull check of points in its plane, w_flat_hull); facets
     * through the infinite
     * vertex get the Jarvis step of the scans (w_scan_inf), which is
     * certified.  The guess is kept when
     *  - each finite cell is positively oriented (its point beyond by the
     *    filter, or exactly), each facet between two cells is met from
     *    opposite sides, and the link
     *    triangles are the free facets, each met once (w_run).  For an
     *    interior vertex the cells then cover every point of the cavity
     *    exactly once (the degree of the map: each point is covered by as
     *    many positive cells as the link winds round it, once).  For a
     *    hull vertex, the infinite cells' facets are facets of the hull
     *    of the neighbours (all points behind them), forming a patch of
     *    that hull bounded by the link's hull edges, oriented: the patch
     *    the scans find.  The finite cells' boundary is then the same
     *    chain as that of the true fill, and by the same degree argument
     *    they tile the part of the cavity inside conv(S \ q);
     *  - and every facet between two finite fill cells is locally Delaunay
     *    (w_run, w_conflicts).  The link triangles are so already, facing
     *    cells of DT(S) whose spheres hold no point, and the facets on the
     *    new hull are convex edges and faces, all points being behind.
     * A triangulation of conv(S \ q) whose facets are all locally Delaunay
     * (perturbed) is its Delaunay triangulation, so the guess is then
     * exactly the fill the scans would find, at the cost of one pass per
     * cell instead of two and no branch per point.  Otherwise the scans
     * wrap from scratch.                                                 */
    int guess = w->ierr != 1.0 / 0.0, outcome = W_WRONG_GUESS;   /* no guess: scan */
    w->narrow = DD_GUESS_WIDE;
    uint32_t start;
    int hub = 0;                                     /* see w_open_link */
    s = w_open_link(d, w, &start, guess && n >= W_NARROW_FROM ? &hub : NULL);
    /* Integer neighbours all on one sphere (the cosphere): every guess
     * among them ties (W_TIE) and is refuted, narrow ones after building
     * cells, and the scans then wrap in the perturbation's mode.  With
     * integer cofactors (w->kexact) w_cospherical is exact in doubles and
     * 128-bit integers, and stops at the first point off the sphere, so
     * it is asked first there and the scans wrap at once: cosphere degree
     * 64-95, 4 deletions, where 2 narrow and 1 wide guess were refuted
     * before the scans (callgrind).  On rounded lifts it would take the
     * exact expansions on nearly cospherical points (the sphere).        */
    if (s == DD_OK && guess && w->kexact && (w->cosph = w_cospherical(w, &d->qdt->pred, d->star.n))) guess = 0;
    size_t refuted = 0;                              /* cells of a refuted guess */
    d->sstat[DD_WS_COURSE] = guess ? DD_WRAP_PROVED : DD_WRAP_SCANNED;
    if (s == DD_OK && guess) {
        /* Narrow guesses first where the link has a hub, the short lists
         * then two steps (w_guess_narrow); a refuted one costs its cells
         * so far, then the next is tried.  From wide_below neighbours on
         * the guess over every neighbour is not tried: taken as refuted,
         * it leaves the cavity to the scans if cospherical, else to the
         * caller (below).                                              */
        w->narrow = hub ? DD_GUESS_SHORT : DD_GUESS_WIDE;
        for (;;) {
            if (w->narrow == DD_GUESS_WIDE && n >= wide_below) break;
            d->sstat[DD_WS_GUESS] = (uint32_t)w->narrow;
            s = w_run(d, w, 1, start, &outcome);
            if (s != DD_OK || outcome != W_WRONG_GUESS) break;
            refuted += d->fill.n;
            if (w->narrow == DD_GUESS_WIDE) {
                /* Nearly cospherical neighbours (points sampled on a
                 * sphere): their quotients t/o differ by less than the
                 * rounding of the plain lifts, and a guess among them is
                 * refuted (sphere, degree [48,96): every deletion, then
                 * declined to GRR, 4.8x a re-insertion).  Guessed once
                 * more on the shifted lifts, where t measures the
                 * distance from the sphere.  A lean guess refuted is
                 * made again in full: there, or on the same lifts.      */
                d->sstat[DD_WS_SINGLE_REFUTED] |= w->f32 && w->f32_kept > 0;
                if (!w->shifted && n >= DD_SHIFT_FROM && w_shift(w)) d->sstat[DD_WS_SHIFT_GUESS] = 1;
                else if (!w->lean) break;
                w->lean = w->f32 = 0;
            } else {
                d->sstat[DD_WS_NARROW_REFUTED]++;
                w->narrow = w->narrow == DD_GUESS_SHORT ? DD_GUESS_TWO_STEP : DD_GUESS_WIDE;
            }
            if ((s = w_open_link(d, w, &start, w->narrow != DD_GUESS_WIDE ? &hub : NULL)) != DD_OK) break;
        }
        if (s == DD_OK && outcome == W_DONE) goto done;
        d->sstat[DD_WS_COURSE] = DD_WRAP_REFUTED;
    }
    /* A guess that declined is final: the budget is spent for the scans
     * too, and W_BAIL is a flat hull case the scans would not settle
     * either.  So is a refuted guess from W_EXACT_FROM neighbours on,
     * unless they are cospherical.  The link triangles are still the
     * first records (w_open_link), for w_cospherical.                   */
    if (s == DD_OK && outcome != W_DECLINED) {
        if (!w->kexact) w->cosph = w_cospherical(w, &d->qdt->pred, d->star.n);   /* else asked above */
        if (guess && n >= W_EXACT_FROM && !w->cosph) outcome = W_DECLINED;
        else if (guess) s = w_open_link(d, w, &start, NULL);
    }
    if (s == DD_OK && outcome != W_DECLINED) s = w_run(d, w, 0, start, &outcome);
    if (s != DD_OK) {
        w_drop_fill(d, w);
        return s;
    }
done:
    d->sstat[DD_WS_EXPANSIONS] = w->nexact;
    d->sstat[DD_WS_SINGLE] = w->f32_kept;
    d->sstat[DD_WS_SINGLE_BACK] = w->f32_back;
    d->sstat[DD_WS_HULL_SINGLE] = w->inf_kept;
    d->sstat[DD_WS_HULL_BACK] = w->inf_back;
    if (outcome == W_DECLINED) {
        w_drop_fill(d, w);
        d->sstat[DD_WS_COURSE] = DD_WRAP_DECLINED;
        *declined = 1;
        return DD_OK;
    }
    d->fill_in_mesh = 1;
    d->qdt->tets_created = d->fill.n + refuted;
    DD_PHASE_END(d, DD_PH_CONFLICT);
    return DD_OK;
}
