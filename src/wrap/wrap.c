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
