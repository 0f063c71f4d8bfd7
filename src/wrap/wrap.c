/*
 * wrap.c -- the gift wrap's driver (docs/gift-wrap.md §3 FILL):
 * dd_wrap_fill numbers and lifts the neighbours, guesses the fill and
 * proves it, falls back on the certified scans, and hands the fill to the
 * sew or declines.
 *
 * Owns: the wrap's scratch as the deletion context keeps it across
 * deletions (w_kind, dd_wrap_free), its per-neighbour arrays, and the
 * names of the statistics (dd_wrap_stat_names).
 *
 * Invariant: dd_wrap_fill returns with the fill in the mesh
 * (d->fill_in_mesh, d->sew_out for the sew), or with the mesh as it was
 * (declined, or an error): every other course ends in w_drop_fill.
 */
#include "wrap/wrap_int.h"
#include "dtdel/alloc.h"

/* Frees the wrap's scratch (NULL: nothing).                             */
void dd_wrap_free(struct dd_wrap *w)
{
    if (!w) return;
    dd_mfree(w->pt);
    for (int i = 0; i < 4; i++) dd_mfree(w->lift[i]), dd_mfree(w->flift[i]);
    dd_mfree(w->o); dd_mfree(w->wgt); dd_mfree(w->tmp); dd_mfree(w->lexr); dd_mfree(w->loc);
    dd_mfree(w->fs);
    dd_mfree(w->tri); dd_mfree(w->own); dd_mfree(w->out); dd_mfree(w->closed); dd_mfree(w->stack); dd_mfree(w->lcell); dd_mfree(w->keep);
    dd_mfree(w->adj); dd_mfree(w->nadj); dd_mfree(w->seen); dd_mfree(w->cand); dd_mfree(w->hubs); dd_mfree(w->code);
    dd_mfree(w);
}

/* Room for n neighbours in the per-neighbour arrays (doubling, by
 * mesh.h's dd_grow), and local numbers for vertex ids below nv.  The
 * capacity stays a multiple of eight: the rows' padding (lift_pass.h).  */
static dd_status w_reserve_n(struct dd_wrap *w, uint32_t n, uint32_t nv)
{
    if (n > w->cap_n) {
        uint32_t cap = w->cap_n ? w->cap_n : 64;
        while (cap < n) cap *= 2;
        if (dd_grow(&w->pt, cap, sizeof *w->pt) || dd_grow(&w->o, cap, sizeof *w->o) ||
            dd_grow(&w->wgt, cap, sizeof *w->wgt) ||
            dd_grow(&w->tmp, cap, sizeof *w->tmp) || dd_grow(&w->lexr, cap, sizeof *w->lexr))
            return DD_ERR_NOMEM;
        for (int i = 0; i < 4; i++)
            if (dd_grow(&w->lift[i], cap, sizeof *w->lift[i]) ||
                dd_grow(&w->flift[i], cap, sizeof *w->flift[i]))
                return DD_ERR_NOMEM;
        if (dd_grow(&w->adj, (size_t)cap * W_ADJ_CAP, sizeof *w->adj) ||
            dd_grow(&w->nadj, cap, sizeof *w->nadj) || dd_grow(&w->seen, cap, sizeof *w->seen) ||
            dd_grow(&w->cand, cap, sizeof *w->cand) || dd_grow(&w->hubs, cap, sizeof *w->hubs))
            return DD_ERR_NOMEM;
        memset(w->seen, 0, cap * sizeof *w->seen);
        w->stamp = 0;
        w->cap_n = cap;
    }
    if (nv > w->cap_loc) {
        if (dd_grow(&w->loc, nv, sizeof *w->loc)) return DD_ERR_NOMEM;
        w->cap_loc = nv;
    }
    return DD_OK;
}

/* The names of the DD_WS_* statistics, in their order (wrap.h).         */
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

/* The scratch kind by which the deletion context keeps and frees it.    */
static void w_free_scratch(void *w) { dd_wrap_free(w); }
static const dd_scratch_kind w_kind = {"gift wrapping", w_free_scratch};

/* Makes the wrap's scratch at the first deletion, with the CPU's
 * features, and gives it to d to keep.                                   */
static dd_status w_new_scratch(dd_del *d, struct dd_wrap **out)
{
    struct dd_wrap *w = *out = dd_calloc(1, sizeof *w);
    if (!w) return DD_ERR_NOMEM;
#ifdef W_AVX2
    w->has_avx2 = __builtin_cpu_supports("avx2");
    w->has_fma = __builtin_cpu_supports("fma");
#endif
    return dd_del_keep_scratch(d, &w_kind, w);
}

/* The wrap's scratch, kept in d across deletions, with room for this
 * cavity's neighbours; the statistics named.                            */
static dd_status w_scratch(dd_del *d, struct dd_wrap **out)
{
    dd_status s = (*out = dd_del_scratch(d, &w_kind)) ? DD_OK : w_new_scratch(d, out);
    dd_del_strategy_stats(d, dd_wrap_stat_names, DD_WS_COUNT);
    if (s == DD_OK) s = w_reserve_n(*out, (uint32_t)d->order.n, d->t->nvid);
    if (s == DD_OK) s = dd_vec_room(&d->order, 1);
    return s;
}

/* One deletion's course through the wrap (dd_wrap_fill).                */
struct w_course {
    int guess;                    /* guessing (the filters apply)         */
    int hub;                      /* the link has a hub (w_open_link)     */
    uint32_t start;               /* the record the next wrap starts from */
    int outcome;                  /* W_DONE, W_DECLINED, W_WRONG_GUESS    */
    size_t refuted;               /* cells made by refuted guesses        */
};

/* With hidden points among the sites (a weighted t), the sites in the
 * order of their local numbers: q's neighbours (d->nbr, whose order
 * collect_star made), then the star's hidden points (d->hpts);
 * fill_step's choice of a base may have mixed them.  The regular fill a
 * declined wrap leaves to (dd_full_fill_power) picks its base again.
 * Without hidden points d->order stays as it is, as on an unweighted t.
 * O(n).                                                                */
static void w_sites_in_order(dd_del *d)
{
    memcpy(d->order.a, d->nbr.a, d->nbr.n * sizeof *d->nbr.a);
    if (d->hpts.n) memcpy(d->order.a + d->nbr.n, d->hpts.a, d->hpts.n * sizeof *d->hpts.a);
}

/* Numbers the neighbours (d->order's order; the infinite vertex is n),
 * lifts them, and sets the deletion's modes: AVX2, the lean and
 * single-precision passes, the test controls.  The star is kept aside
 * first (w_keep_star), so that a wrap that is not kept can restore it.  */
static dd_status w_begin(dd_del *d, struct dd_wrap *w, struct w_course *c)
{
    dd_tri *t = d->t;
    dd_status s = DD_OK;
    if (d->order.n >= 64 && (s = w_code_reserve(w, (uint32_t)d->order.n + 1)) != DD_OK) return s;
    d->fill.n = 0;                                  /* no fill cell made yet (w_drop_fill) */
    w->ncell0 = t->ncell;
    DD_PHASE_BEGIN(d);
    if ((s = w_keep_star(d, w)) != DD_OK) return s;
    const int weighted = t->wt != NULL;
    if (weighted && d->hpts.n) w_sites_in_order(d);
    d->order.a[d->order.n] = DD_INF;                /* gid[n]: the infinite vertex */
    const uint32_t *gid = d->order.a, n = w->n = (uint32_t)d->order.n;
    w->nlink = (uint32_t)d->nbr.n;                  /* n on an unweighted t */
    w->lead = 0;                                    /* the neighbour of least id */
    for (uint32_t k = 0; k < n; k++) {
        w->pt[k] = dd_pt(t, gid[k]);
        w->loc[gid[k]] = k;
        w->lead = gid[k] < gid[w->lead] && k < w->nlink ? k : w->lead;
    }
    if (weighted)
        for (uint32_t k = 0; k < n; k++) w->wgt[k] = t->wt[gid[k]];
    w_lift(w, d->qp, d->qw, weighted);
    w->unf0 = w_unfiltered(&d->qdt->pred);
    d->sstat[DD_WS_INTEGER] = w->exact ? 1u : w->kexact ? 2u : 0u;
    w->cosph = 0;
    w->narrow = DD_GUESS_WIDE;
    w->avx2 = w->has_avx2 && !W_TESTCTL(t, DD_TEST_SCALAR);
    w->lean = w->avx2 && !w->oexact && n >= W_LEAN_FROM;
    /* the float lifts' scales stay finite (dd_lift_f32_ok) */
    w->flift_ok = w->lean && w->has_fma && dd_lift_f32_ok(w->m) && !w->wbig && !W_TESTCTL(t, DD_TEST_NO_SINGLE);
#ifdef DD_TEST_BUILD
    w->narrower = W_TESTCTL(t, DD_TEST_NARROWER);
    w->f32_spoil = W_TESTCTL(t, DD_TEST_SPOIL_SINGLE);
#endif
    w->f32 = w->flift_ok;
    w->f32_kept = w->f32_back = w->inf_kept = w->inf_back = 0;
    w->f32_ready = 0;
    c->guess = w->ierr != 1.0 / 0.0;                /* filters off: scan */
    return DD_OK;
}

/* After a refuted guess, the next one (docs/gift-wrap.md §3 FILL): the
 * short lists, then two steps, then the wide guess; a wide guess once
 * more on shifted lifts where they are tighter, or else in full doubles
 * after a lean one.  After refuted narrow guesses the wide one is made
 * in full doubles at once: such cavities are the curves', where a point
 * nearly in a facet's plane is often its apex and the lean and
 * single-precision guesses are refuted in turn.  0: none left.          */
static int w_next_guess(dd_del *d, struct dd_wrap *w)
{
    if (w->narrow != DD_GUESS_WIDE) {
        d->sstat[DD_WS_NARROW_REFUTED]++;
        w->narrow = w->narrow == DD_GUESS_SHORT ? DD_GUESS_TWO_STEP : DD_GUESS_WIDE;
        if (w->narrow == DD_GUESS_WIDE) w->lean = w->f32 = 0;
        return 1;
    }
    d->sstat[DD_WS_SINGLE_REFUTED] |= w->f32 && w->f32_kept > 0;
    if (!w->shifted && w->n >= DD_SHIFT_FROM && w_shift(w)) d->sstat[DD_WS_SHIFT_GUESS] = 1;
    else if (!w->lean) return 0;
    w->lean = w->f32 = 0;
    return 1;
}

/* Opens the link, then guesses the fill and proves it (docs §3 FILL, §7),
 * when the filters apply and the neighbours are not all on one sphere
 * (asked first with integer cofactors, where it is cheap and exact:
 * every guess there would tie).  Narrow guesses first where the link has
 * a hub, then the wide one, unless n >= wide_below; each refuted guess
 * costs its cells so far (c->refuted).  c->outcome: W_DONE (the fill is
 * in the mesh), W_DECLINED, or W_WRONG_GUESS (refuted, or not guessed). */
static dd_status w_guess_then_prove(dd_del *d, struct dd_wrap *w, uint32_t wide_below, struct w_course *c)
{
    dd_status s = w_open_link(d, w, &c->start, c->guess && w->n >= W_NARROW_FROM ? &c->hub : NULL);
    if (s == DD_OK && c->guess && w->kexact && (w->cosph = w_cospherical(w, &d->qdt->pred, d->star.n))) c->guess = 0;
    d->sstat[DD_WS_COURSE] = c->guess ? DD_WRAP_PROVED : DD_WRAP_SCANNED;
    if (s != DD_OK || !c->guess) return s;
    w->narrow = c->hub ? DD_GUESS_SHORT : DD_GUESS_WIDE;
    while (w->narrow != DD_GUESS_WIDE || w->n < wide_below) {
        d->sstat[DD_WS_GUESS] = (uint32_t)w->narrow;
        if ((s = w_run(d, w, 1, c->start, &c->outcome)) != DD_OK || c->outcome != W_WRONG_GUESS) break;
        c->refuted += d->fill.n;
        if (!w_next_guess(d, w)) break;
        if ((s = w_open_link(d, w, &c->start, w->narrow != DD_GUESS_WIDE ? &c->hub : NULL)) != DD_OK) break;
    }
    if (s != DD_OK || c->outcome != W_DONE) d->sstat[DD_WS_COURSE] = DD_WRAP_REFUTED;
    return s;
}

/* The certified scans' wrap (docs §3 FILL), after no guess or a refuted
 * one.  A guess that declined is final (the budget is spent, or a flat
 * hull case the scans would not settle either), and so is a refuted
 * guess from W_EXACT_FROM neighbours on unless the neighbours are
 * cospherical (docs §10).  w_cospherical reads the link triangles,
 * still the first records.                                              */
static dd_status w_scan_fill(dd_del *d, struct dd_wrap *w, struct w_course *c)
{
    if (c->outcome == W_DECLINED) return DD_OK;
    if (!w->kexact) w->cosph = w_cospherical(w, &d->qdt->pred, d->star.n);   /* else asked already */
    if (c->guess && w->n >= W_EXACT_FROM && !w->cosph) {
        c->outcome = W_DECLINED;
        return DD_OK;
    }
    dd_status s = c->guess ? w_open_link(d, w, &c->start, NULL) : DD_OK;
    return s == DD_OK ? w_run(d, w, 0, c->start, &c->outcome) : s;
}

/* Hands the fill over to the sew (d->fill_in_mesh), or, declined or
 * failed, restores the star; the statistics.                           */
static dd_status w_finish(dd_del *d, struct dd_wrap *w, dd_status s, const struct w_course *c, int *declined)
{
    if (s != DD_OK) {
        w_drop_fill(d, w);
        return s;
    }
    d->sstat[DD_WS_EXPANSIONS] = w->nexact;
    d->sstat[DD_WS_SINGLE] = w->f32_kept;
    d->sstat[DD_WS_SINGLE_BACK] = w->f32_back;
    d->sstat[DD_WS_HULL_SINGLE] = w->inf_kept;
    d->sstat[DD_WS_HULL_BACK] = w->inf_back;
    if (c->outcome == W_DECLINED) {
        w_drop_fill(d, w);
        d->sstat[DD_WS_COURSE] = DD_WRAP_DECLINED;
        *declined = 1;
        return DD_OK;
    }
    d->fill_in_mesh = 1;
    d->qdt->tets_created = d->fill.n + c->refuted;
    DD_PHASE_END(d, DD_PH_CONFLICT);
    return DD_OK;
}

/* See wrap.h.  The steps: the scratch; no facet keys, decline; number,
 * lift and set the modes; guess and prove; else scan; hand over.       */
dd_status dd_wrap_fill(dd_del *d, uint32_t wide_below, int *declined)
{
    struct dd_wrap *w;
    struct w_course c = {.outcome = W_WRONG_GUESS};
    *declined = 0;
    dd_status s = w_scratch(d, &w);
    if (s != DD_OK) return s;
    if (d->order.n + 1 >= DD_WRAP_CODE_LEN) {       /* no keys (w_fkey) */
        d->sstat[DD_WS_COURSE] = DD_WRAP_DECLINED;
        *declined = 1;
        return DD_OK;
    }
    if ((s = w_begin(d, w, &c)) != DD_OK) return s;
    s = w_guess_then_prove(d, w, wide_below, &c);
    if (s == DD_OK && c.outcome != W_DONE) s = w_scan_fill(d, w, &c);
    return w_finish(d, w, s, &c, declined);
}
