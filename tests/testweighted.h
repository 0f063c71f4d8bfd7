/*
 * testweighted.h -- what the weighted tests share: weighted point sets
 * and their generators (uniform weights, a molecule, protecting balls,
 * weighted curves, the degenerate integer grid), the comparison of a
 * triangulation with CGAL's Regular_triangulation_3 (cells and hidden
 * set), dd_check with its message, and a snapshot of what a refused
 * edit must leave as it was.  Include after testlib.h.
 */
#ifndef DD_TESTWEIGHTED_H
#define DD_TESTWEIGHTED_H

#include <math.h>
#include "dtdel.h"
#include "cgal/cgal_regular.h"

/* ---- weighted point sets -------------------------------------------------- */

typedef struct wset {
    double *p, *w;
    uint32_t n, cap;
} wset;

static inline void ws_add(wset *s, double x, double y, double z, double w)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 256;
        s->p = realloc(s->p, 3 * (size_t)s->cap * sizeof *s->p);
        s->w = realloc(s->w, (size_t)s->cap * sizeof *s->w);
        if (!s->p || !s->w) exit(1);
    }
    s->p[3 * (size_t)s->n] = x, s->p[3 * (size_t)s->n + 1] = y, s->p[3 * (size_t)s->n + 2] = z;
    s->w[s->n++] = w;
}

static inline void ws_free(wset *s)
{
    free(s->p), free(s->w);
    memset(s, 0, sizeof *s);
}

/* n uniform points in the unit cube, weights uniform in [0, scale h^2),
 * h = n^(-1/3) the mean spacing: scale 0.01 hides few, 10 most.         */
static inline wset gen_uniform(uint32_t n, double scale, uint64_t seed)
{
    wset s = {0};
    tl_rng r = {seed};
    const double h = pow((double)n, -1.0 / 3);
    for (uint32_t i = 0; i < n; i++) {
        const double x = tl_unif(&r), y = tl_unif(&r), z = tl_unif(&r);
        ws_add(&s, x, y, z, scale * h * h * tl_unif(&r));
    }
    return s;
}

/* Atoms of radii 1.2 to 1.9 (weight r^2) on a jittered lattice of
 * spacing 1.5: overlapping balls, as a molecule's.                      */
static inline wset gen_molecule(uint32_t side, uint64_t seed)
{
    wset s = {0};
    tl_rng r = {seed};
    for (uint32_t i = 0; i < side; i++)
        for (uint32_t j = 0; j < side; j++)
            for (uint32_t k = 0; k < side; k++) {
                const double rad = 1.2 + 0.7 * tl_unif(&r);
                ws_add(&s, 1.5 * i + 0.6 * (tl_unif(&r) - 0.5), 1.5 * j + 0.6 * (tl_unif(&r) - 0.5),
                       1.5 * k + 0.6 * (tl_unif(&r) - 0.5), rad * rad);
            }
    return s;
}

/* Protecting balls: points every h along a circle, a helix and a
 * segment (sharp features) with weight (0.6 h)^2, and nvol unweighted
 * points in the box around them.                                       */
static inline wset gen_protecting(uint32_t per_curve, uint32_t nvol, uint64_t seed)
{
    wset s = {0};
    tl_rng r = {seed};
    const double pi = 3.14159265358979323846;
    const double h = 2 * pi / per_curve, w = 0.36 * h * h;
    for (uint32_t i = 0; i < per_curve; i++) {
        const double a = 2 * pi * i / per_curve;
        ws_add(&s, cos(a), sin(a), 0, w);
        ws_add(&s, 0.5 * cos(3 * a), 0.5 * sin(3 * a), -1 + a / pi, w);
        ws_add(&s, -1.2 + 2.4 * i / per_curve, 0.3, 0.8, w);
    }
    for (uint32_t i = 0; i < nvol; i++)
        ws_add(&s, 3 * tl_unif(&r) - 1.5, 3 * tl_unif(&r) - 1.5, 3 * tl_unif(&r) - 1.5, 0);
    return s;
}

/* The moment curve (t, t^2, t^3) or a helix, with random weights of the
 * order of the squared spacing.                                        */
static inline wset gen_curve(uint32_t n, int helix, uint64_t seed)
{
    wset s = {0};
    tl_rng r = {seed};
    for (uint32_t i = 0; i < n; i++) {
        const double t = (double)i / n;
        if (helix) ws_add(&s, cos(20 * t), sin(20 * t), t, 0.01 * tl_unif(&r));
        else ws_add(&s, t, t * t, t * t * t, 0.3 * tl_unif(&r) / ((double)n * n));
    }
    return s;
}

/* The integer grid side^3 with integer weights in 0..2 (power ties),
 * plus extra points at grid positions with other weights, and (dups)
 * every third extra an exact duplicate of an earlier point.            */
static inline wset gen_grid(uint32_t side, uint32_t extra, int dups, uint64_t seed)
{
    wset s = {0};
    tl_rng r = {seed};
    for (uint32_t i = 0; i < side; i++)
        for (uint32_t j = 0; j < side; j++)
            for (uint32_t k = 0; k < side; k++) ws_add(&s, i, j, k, (double)tl_int(&r, 0, 2));
    const uint32_t base = s.n;
    for (uint32_t e = 0; e < extra; e++) {
        const uint32_t i = (uint32_t)tl_int(&r, 0, base - 1);
        const double *q = s.p + 3 * (size_t)i;
        double w = (double)tl_int(&r, 0, 3);
        if (dups && e % 3 == 0) w = s.w[i];         /* an exact duplicate */
        else if (!dups && w == s.w[i]) w += 0.5;    /* another weight     */
        ws_add(&s, q[0], q[1], q[2], w);
    }
    return s;
}

/* ---- comparisons ------------------------------------------------------------- */

/* The cells of t equal c's; then both hidden lists in *ha (t's) and *hb
 * (c's), the caller's to free.  0 with why filled otherwise.            */
static inline int ws_same_cells(const dd_tri *t, const dd_cgal_rt *c, uint32_t **ha, size_t *nha, uint32_t **hb,
                                size_t *nhb, char *why, size_t nwhy)
{
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    int ok = 0;
    *ha = *hb = NULL;
    *nha = *nhb = 0;
    if (dd_canonical(t, &a, &na) != DD_OK || dd_cgal_rt_canonical(c, &b, &nb))
        snprintf(why, nwhy, "no canonical form");
    else if (na != nb || memcmp(a, b, 4 * na * sizeof *a))
        snprintf(why, nwhy, "cells differ: %zu here, %zu in CGAL", na, nb);
    else if (dd_hidden(t, ha, nha) != DD_OK || dd_cgal_rt_hidden(c, hb, nhb))
        snprintf(why, nwhy, "no hidden list");
    else
        ok = 1;
    free(a), free(b);
    return ok;
}

static inline int same_as_cgal(const dd_tri *t, const dd_cgal_rt *c, char *why, size_t nwhy)
{
    uint32_t *ha, *hb;
    size_t nha, nhb;
    int ok = ws_same_cells(t, c, &ha, &nha, &hb, &nhb, why, nwhy);
    if (ok && (nha != nhb || (nha && memcmp(ha, hb, nha * sizeof *ha)))) {
        snprintf(why, nwhy, "hidden sets differ: %zu here, %zu in CGAL", nha, nhb);
        ok = 0;
    }
    free(ha), free(hb);
    return ok;
}

static inline int checked(const dd_tri *t, char *why, size_t nwhy)
{
    char msg[256];
    if (dd_check_msg(t, msg, sizeof msg) == DD_OK) return 1;
    snprintf(why, nwhy, "dd_check: %.200s", msg);
    return 0;
}

/* s built here (t) and in CGAL (c), hidden points kept or discarded, and
 * the two equal; 0 with why filled otherwise (either may then be NULL). */
static inline int ws_build(const wset *s, int keep, dd_tri **t, dd_cgal_rt **c, char *why, size_t nwhy)
{
    char msg[256];
    *t = NULL;
    *c = dd_cgal_rt_build(s->p, s->w, s->n, !keep);
    if (!*c) return snprintf(why, nwhy, "CGAL could not build"), 0;
    if (dd_create_ex(t, s->p, s->w, s->n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg) != DD_OK)
        return snprintf(why, nwhy, "build: %.200s", msg), 0;
    return same_as_cgal(*t, *c, why, nwhy);
}

/* A random vertex of t among its input indices, or UINT32_MAX. */
static inline uint32_t ws_random_vertex(const dd_tri *t, tl_rng *r)
{
    const uint32_t np = dd_num_input(t);
    for (int tries = 0; tries < 100000; tries++) {
        const uint32_t v = (uint32_t)tl_int(r, 0, np - 1);
        if (dd_is_vertex(t, v)) return v;
    }
    return UINT32_MAX;
}

/* After the k-th deletion, of v, from t and c: t valid, equal to c, and v
 * neither a vertex nor hidden; 0 with why filled otherwise.             */
static inline int ws_deleted_ok(const dd_tri *t, const dd_cgal_rt *c, uint32_t v, uint32_t k, char *why, size_t nwhy)
{
    char w2[256];
    if (!checked(t, w2, sizeof w2) || !same_as_cgal(t, c, w2, sizeof w2)) {
        snprintf(why, nwhy, "after deleting %u (step %u): %.200s", v, k, w2);
        return 0;
    }
    if (dd_is_vertex(t, v) || dd_is_hidden(t, v)) {
        snprintf(why, nwhy, "after deleting %u (step %u): still a vertex or hidden", v, k);
        return 0;
    }
    return 1;
}

/* Snapshot of what a refused edit must not change. */
typedef struct shot { int32_t *cells; size_t n; uint32_t *hid; size_t nh; uint32_t np, nv; } shot;

static inline shot take_shot(const dd_tri *t)
{
    shot s = {0};
    dd_canonical(t, &s.cells, &s.n);
    dd_hidden(t, &s.hid, &s.nh);
    s.np = dd_num_input(t);
    s.nv = dd_num_vertices(t);
    return s;
}

static inline int unchanged(const dd_tri *t, const shot *s)
{
    shot now = take_shot(t);
    const int same = now.n == s->n && !memcmp(now.cells, s->cells, 4 * s->n * sizeof *s->cells) &&
                     now.nh == s->nh && (!s->nh || !memcmp(now.hid, s->hid, s->nh * sizeof *s->hid)) &&
                     now.np == s->np && now.nv == s->nv;
    free(now.cells), free(now.hid);
    return same;
}

static inline void shot_free(shot *s) { free(s->cells), free(s->hid); }

/* ---- allocation failures (test builds) ---------------------------------------- */

#ifdef DD_TEST_BUILD
/* A vertex v of s's triangulation (hidden points kept) whose deletion
 * brings a hidden point back (CGAL says so), and in *after CGAL's
 * triangulation of s with v removed (the caller frees it); UINT32_MAX
 * and NULL if there is none.                                           */
static inline uint32_t ws_releasing_vertex(const wset *s, dd_cgal_rt **after)
{
    char msg[256];
    dd_tri *t = NULL;
    *after = NULL;
    if (dd_create_ex(&t, s->p, s->w, s->n, 0, msg, sizeof msg) != DD_OK) return UINT32_MAX;
    uint32_t found = UINT32_MAX;
    for (uint32_t v = 0; v < s->n && found == UINT32_MAX; v++) {
        if (!dd_is_vertex(t, v)) continue;
        dd_cgal_rt *c = dd_cgal_rt_build(s->p, s->w, s->n, 0);
        uint32_t *h0 = NULL, *h1 = NULL;
        size_t n0 = 0, n1 = 0;
        dd_cgal_rt_hidden(c, &h0, &n0);
        const int r = dd_cgal_rt_remove(c, v);
        dd_cgal_rt_hidden(c, &h1, &n1);
        free(h0), free(h1);
        if (r == 0 && n1 < n0) found = v, *after = c;
        else dd_cgal_rt_free(c);
    }
    dd_free(t);
    return found;
}

/* A call whose allocations ws_fault_each refuses in turn: start makes
 * the triangulation it starts from, run makes it (k: the allocation
 * refused in this round, for calls that vary with it).                  */
typedef struct ws_fault_call {
    dd_tri *(*start)(const void *arg);
    dd_status (*run)(dd_tri *t, const void *arg, long k);
    const void *arg;
} ws_fault_call;

/* The k-th allocation of the call refused, for k = 1, 2, ... until the
 * call makes fewer: each refusal must say DD_ERR_NOMEM and change
 * nothing, the retry must succeed, and every result must equal c.
 * Returns the refusals seen; *bad gets the rounds that went wrong (the
 * first printed on stderr under tn).                                   */
static inline long ws_fault_each(const char *tn, const ws_fault_call *call, const dd_cgal_rt *c, long *bad)
{
    char why[256];
    long nomem = 0;
    *bad = 0;
    for (long k = 1; k < 100000; k++) {
        dd_tri *t = call->start(call->arg);
        shot before = take_shot(t);
        dd_test_control(NULL, DD_TEST_ALLOC_FAIL, k);
        const dd_status ds = call->run(t, call->arg, k);
        const long left = dd_test_control(NULL, DD_TEST_ALLOC_FAIL, 0);
        int ok = 1;
        why[0] = 0;
        if (ds == DD_ERR_NOMEM) {
            nomem++;
            ok = unchanged(t, &before) && checked(t, why, sizeof why);
            if (!ok && !why[0]) snprintf(why, sizeof why, "allocation %ld: changed by the failure", k);
            if (ok && call->run(t, call->arg, k) != DD_OK)
                ok = 0, snprintf(why, sizeof why, "allocation %ld: retry failed (%s)", k, dd_errmsg(t));
        } else if (ds != DD_OK) {
            ok = 0, snprintf(why, sizeof why, "allocation %ld: %s (%s)", k, dd_status_name(ds), dd_errmsg(t));
        }
        if (ok) ok = checked(t, why, sizeof why) && same_as_cgal(t, c, why, sizeof why);
        if (!ok && !(*bad)++) fprintf(stderr, "  %s: allocation %ld: %s\n", tn, k, why);
        shot_free(&before);
        dd_free(t);
        if (left > 0) break;             /* the call made fewer than k */
    }
    return nomem;
}

typedef dd_status (*ws_delete_fn)(dd_tri *t, uint32_t v, const char *variant);

/* The deletion of v from s (hidden points kept) as a ws_fault_call. */
typedef struct ws_fault_del {
    const wset *s;
    uint32_t v;
    ws_delete_fn del;
    const char *const *vars;
    size_t nvars;
} ws_fault_del;

static inline dd_tri *ws_fault_del_start(const void *arg)
{
    const ws_fault_del *f = arg;
    char msg[256];
    dd_tri *t = NULL;
    dd_create_ex(&t, f->s->p, f->s->w, f->s->n, 0, msg, sizeof msg);
    return t;
}

static inline dd_status ws_fault_del_run(dd_tri *t, const void *arg, long k)
{
    const ws_fault_del *f = arg;
    return f->del(t, f->v, f->vars[(size_t)k % f->nvars]);
}

/* Each allocation of the deletion of v from s (hidden points kept) refused
 * in turn, by vars[k % nvars] at the k-th (ws_fault_each); c is CGAL
 * after removing v.  Checks that some were refused and none went wrong;
 * returns the refusals seen.                                            */
static inline long ws_fault_delete(tl_state *st, const char *tn, const wset *s, uint32_t v, const dd_cgal_rt *c,
                                   ws_delete_fn del, const char *const *vars, size_t nvars)
{
    const ws_fault_del f = {s, v, del, vars, nvars};
    const ws_fault_call call = {ws_fault_del_start, ws_fault_del_run, &f};
    long bad;
    const long nomem = ws_fault_each(tn, &call, c, &bad);
    tl_check(st, bad == 0 && nomem > 0, tn, "%ld bad of %ld refusals", bad, nomem);
    return nomem;
}
#endif

#endif
