/*
 * test_regular.c -- regular (weighted Delaunay) triangulations against
 * CGAL's Regular_triangulation_3 (src/cgal/cgal_regular.h):
 *  - construction, cells and hidden set identical to CGAL's, in both
 *    hidden modes, on uniform weighted points from few to most hidden, a
 *    molecule-like packing, protecting balls along curves with volume
 *    points, the moment curve and the helix with weights, and an integer
 *    grid with small integer weights (power ties, equal positions with
 *    different weights, exact duplicates);
 *  - insertion sequences that hide new points and swallow vertices,
 *    compared with CGAL after every step on the degenerate grid, and
 *    dd_insert (weight 0) on a weighted triangulation;
 *  - zero weights give dd_create's Delaunay triangulation;
 *  - bad weights and coordinates refused with their status, nothing
 *    changed; deletion by a strategy without a weighted fill (test_wdelete.c
 *    tests the others), set deletion, reinsert and move refused with
 *    DD_ERR_UNSUPPORTED, nothing changed;
 *  - the read calls (dd_weight, dd_is_hidden, dd_hidden, dd_is_vertex,
 *    dd_nearest_vertex by power distance) against brute force;
 *  - dd_check after every step.
 * Argument "small": smaller sizes (the sanitizer build).
 */
#include "testlib.h"
#include <gmp.h>
#include <math.h>
#include "dtdel.h"
#include "cgal/cgal_regular.h"
#include "testcgal.h"
#include "testweighted.h"

static int small;

/* The read calls against the input and brute force: weights, the
 * partition of the indices into vertices, hidden points and the rest
 * (duplicates; forgotten points when discarding), dd_hidden sorted and
 * equal to dd_is_hidden, and nearest vertices by power distance.       */
static int reads_agree(const dd_tri *t, const wset *s, int keep, uint64_t seed, char *why, size_t nwhy)
{
    uint32_t *h = NULL;
    size_t nh = 0, k = 0;
    if (dd_hidden(t, &h, &nh) != DD_OK) return snprintf(why, nwhy, "dd_hidden failed"), 0;
    int ok = 1;
    const uint32_t n = dd_num_input(t);
    for (uint32_t i = 0; i < n && ok; i++) {
        double w = -1;
        const int hid = dd_is_hidden(t, i), vert = dd_is_vertex(t, i);
        const int listed = k < nh && h[k] == i;
        k += (size_t)listed;
        if (dd_weight(t, i, &w) != DD_OK || (i < s->n && w != s->w[i]))
            ok = 0, snprintf(why, nwhy, "dd_weight(%u) = %g, not %g", i, w, i < s->n ? s->w[i] : 0.0);
        else if (hid != listed)
            ok = 0, snprintf(why, nwhy, "dd_is_hidden(%u) = %d but dd_hidden %s it", i, hid, listed ? "lists" : "omits");
        else if (hid && vert)
            ok = 0, snprintf(why, nwhy, "point %u is both hidden and a vertex", i);
        else if (keep && !hid && !vert && dd_alias(t, i) == i)
            ok = 0, snprintf(why, nwhy, "point %u is neither vertex, hidden nor a duplicate", i);
    }
    if (ok && k != nh) ok = 0, snprintf(why, nwhy, "dd_hidden lists indices out of order or range");
    double wq = 0;
    if (ok && dd_weight(t, n, &wq) != DD_ERR_ARG) ok = 0, snprintf(why, nwhy, "dd_weight past the end");
    free(h);
    /* nearest by power: random points, vertex positions, grid nodes */
    tl_rng r = {seed};
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t i = 0; i < s->n; i++)
        for (int c = 0; c < 3; c++) lo[c] = fmin(lo[c], s->p[3 * i + c]), hi[c] = fmax(hi[c], s->p[3 * i + c]);
    const int nq = small ? 20 : 60;
    for (int q = 0; q < nq && ok; q++) {
        double p[3];
        for (int c = 0; c < 3; c++) {
            const double u = lo[c] - 0.2 * (hi[c] - lo[c]) + 1.4 * (hi[c] - lo[c]) * tl_unif(&r);
            p[c] = q % 3 == 1 ? round(u) : u;     /* grid nodes: ties on the grid */
        }
        if (q % 3 == 0) memcpy(p, s->p + 3 * (size_t)tl_int(&r, 0, s->n - 1), sizeof p);
        uint32_t v;
        double pv[3], wv, pb[3], wb;
        if (dd_nearest_vertex(t, p, &v) != DD_OK || dd_point(t, v, pv) != DD_OK) {
            ok = 0, snprintf(why, nwhy, "dd_nearest_vertex failed or gave no vertex");
            break;
        }
        dd_weight(t, v, &wv);
        for (uint32_t i = 0; i < n && ok; i++) {
            if (!dd_is_vertex(t, i)) continue;
            dd_point(t, i, pb);
            dd_weight(t, i, &wb);
            if (tl_cmp_power_exact(p, pb, wb, pv, wv) < 0)
                ok = 0, snprintf(why, nwhy, "query %d: vertex %u is nearer in power distance than %u", q, i, v);
        }
    }
    return ok;
}

/* ---- construction ------------------------------------------------------------ */

/* Builds s in both modes and compares with CGAL's; reads and dd_check. */
static void build_case(tl_state *st, const char *name, const wset *s)
{
    for (int keep = 1; keep >= 0; keep--) {
        char tn[160], why[256] = "", msg[256];
        snprintf(tn, sizeof tn, "build/%s/%s", name, keep ? "keep" : "discard");
        dd_tri *t = NULL;
        dd_cgal_rt *c = dd_cgal_rt_build(s->p, s->w, s->n, !keep);
        const dd_status cs = dd_create_ex(&t, s->p, s->w, s->n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg);
        int ok = 0;
        if (cs != DD_OK || !c)
            snprintf(why, sizeof why, "dd_create_ex: %.200s; CGAL %s", cs ? msg : "ok", c ? "ok" : "failed");
        else
            ok = checked(t, why, sizeof why) && same_as_cgal(t, c, why, sizeof why) &&
                 reads_agree(t, s, keep, 7, why, sizeof why);
        uint32_t *h = NULL;
        size_t nh = 0;
        if (ok) dd_hidden(t, &h, &nh);
        free(h);
        tl_check(st, ok, tn, "%s", why);
        if (ok) fprintf(stderr, "  %s: %u points, %u vertices, %zu hidden\n", tn, s->n, dd_num_vertices(t), nh);
        dd_free(t);
        dd_cgal_rt_free(c);
    }
}

/* ---- insertion ---------------------------------------------------------------- */

/* Builds the first n0 points of s, then inserts the others one at a time
 * with dd_insert_weighted, comparing with CGAL's insert after every
 * `every` steps (1: each) and checking the triangulation.              */
static void insert_case(tl_state *st, const char *name, const wset *s, uint32_t n0, uint32_t every)
{
    for (int keep = 1; keep >= 0; keep--) {
        char tn[160], why[256] = "", msg[256];
        snprintf(tn, sizeof tn, "insert/%s/%s", name, keep ? "keep" : "discard");
        dd_tri *t = NULL;
        dd_cgal_rt *c = dd_cgal_rt_build(s->p, s->w, n0, !keep);
        int ok = c && dd_create_ex(&t, s->p, s->w, n0, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg) == DD_OK;
        if (!ok) snprintf(why, sizeof why, "build: %.200s", msg);
        uint32_t hidden_new = 0, dups = 0, swallowed = 0;
        wset given = {0};                  /* the points by input index */
        for (uint32_t i = 0; i < n0; i++) ws_add(&given, s->p[3 * i], s->p[3 * i + 1], s->p[3 * i + 2], s->w[i]);
        for (uint32_t i = n0; i < s->n && ok; i++) {
            const uint32_t before = dd_num_vertices(t), np = dd_num_input(t);
            uint32_t idx = UINT32_MAX;
            const dd_status is = dd_insert_weighted(t, s->p + 3 * (size_t)i, s->w[i], &idx);
            const int cr = dd_cgal_rt_insert(c, s->p + 3 * (size_t)i, s->w[i], dd_cgal_rt_num_input(c));
            if (is != DD_OK) {
                ok = 0, snprintf(why, sizeof why, "insert %u: %s", i, dd_errmsg(t));
                break;
            }
            const int dup = dd_num_input(t) == np;      /* no index taken */
            if ((cr == 2) != dup || (cr != 0 && cr != 2) || (dup && !dd_is_vertex(t, idx))) {
                /* CGAL's Weighted_point_3 == compares bare points only: a
                 * shim that tests a vertex with it, not the weights too,
                 * calls a point at a vertex's position with another weight
                 * a duplicate.                                          */
                ok = 0, snprintf(why, sizeof why, "insert %u: a duplicate %s here, the shim says %d%s", i,
                                 dup ? "" : "not", cr,
                                 cr == 2 ? " (a vertex's position with another weight: the shim must compare "
                                           "weights too, Weighted_point_3's == does not)" : "");
                break;
            }
            dups += cr == 2;
            if (!dup) ws_add(&given, s->p[3 * i], s->p[3 * i + 1], s->p[3 * i + 2], s->w[i]);
            if (cr != 2 && !dd_is_vertex(t, idx)) hidden_new++;
            if (dd_num_vertices(t) < before + (dd_is_vertex(t, idx) ? 1u : 0u)) swallowed++;
            if ((i - n0) % every == 0 || i + 1 == s->n)
                ok = checked(t, why, sizeof why) && same_as_cgal(t, c, why, sizeof why);
            if (!ok) {
                char w2[256];
                snprintf(w2, sizeof w2, "after inserting point %u: %.200s", i, why);
                memcpy(why, w2, sizeof why);
            }
        }
        if (ok) ok = reads_agree(t, &given, keep, 11, why, sizeof why);
        ws_free(&given);
        tl_check(st, ok, tn, "%s", why);
        if (ok)
            fprintf(stderr, "  %s: %u inserted: %u hidden on arrival, %u swallowed some, %u duplicates\n", tn,
                    s->n - n0, hidden_new, swallowed, dups);
        dd_free(t);
        dd_cgal_rt_free(c);
    }
}

/* dd_insert on a weighted t inserts weight 0: CGAL's insert of (p, 0). */
static void insert_zero_case(tl_state *st)
{
    wset s = gen_uniform(small ? 300 : 1000, 3, 41);
    char why[256] = "", msg[256];
    dd_tri *t = NULL;
    dd_cgal_rt *c = dd_cgal_rt_build(s.p, s.w, s.n, 0);
    int ok = c && dd_create_ex(&t, s.p, s.w, s.n, 0, msg, sizeof msg) == DD_OK;
    tl_rng r = {5};
    for (int k = 0; k < 50 && ok; k++) {
        const double p[3] = {tl_unif(&r), tl_unif(&r), tl_unif(&r)};
        uint32_t idx;
        double w = -1;
        ok = dd_insert(t, p, &idx) == DD_OK && !dd_cgal_rt_insert(c, p, 0, dd_cgal_rt_num_input(c)) &&
             dd_weight(t, idx, &w) == DD_OK && w == 0;
        if (!ok) snprintf(why, sizeof why, "insert %d: %s (weight %g)", k, dd_errmsg(t), w);
    }
    if (ok) ok = checked(t, why, sizeof why) && same_as_cgal(t, c, why, sizeof why);
    tl_check(st, ok, "insert/dd_insert-weight-zero", "%s", why);
    dd_free(t);
    dd_cgal_rt_free(c);
    ws_free(&s);
}

/* ---- zero weights, refusals ---------------------------------------------------- */

static int same_canonical(const dd_tri *a, const dd_tri *b)
{
    int32_t *x = NULL, *y = NULL;
    size_t nx = 0, ny = 0;
    const int same = dd_canonical(a, &x, &nx) == DD_OK && dd_canonical(b, &y, &ny) == DD_OK && nx == ny &&
                     !memcmp(x, y, 4 * nx * sizeof *x);
    free(x), free(y);
    return same;
}

static void zero_weights_case(tl_state *st, const char *name, const wset *s)
{
    char tn[160], why[256] = "", msg[256];
    snprintf(tn, sizeof tn, "zero-weights/%s", name);
    double *z = calloc(s->n, sizeof *z);
    dd_tri *a = NULL, *b = NULL;
    int ok = dd_create_ex(&a, s->p, z, s->n, 0, msg, sizeof msg) == DD_OK &&
             dd_create(&b, s->p, s->n, msg, sizeof msg) == DD_OK;
    if (!ok) snprintf(why, sizeof why, "%s", msg);
    else if (!same_canonical(a, b)) ok = 0, snprintf(why, sizeof why, "cells differ from dd_create's");
    else if (dd_num_vertices(a) != dd_num_vertices(b)) ok = 0, snprintf(why, sizeof why, "vertex counts differ");
    else if (!dd_is_weighted(a) || dd_is_weighted(b)) ok = 0, snprintf(why, sizeof why, "dd_is_weighted wrong");
    else ok = checked(a, why, sizeof why);
    tl_check(st, ok, tn, "%s", why);
    dd_free(a), dd_free(b);
    free(z);
}

/* Bad input to dd_create_ex: the status, no triangulation, a message. */
static void bad_create_case(tl_state *st)
{
    wset s = gen_uniform(50, 1, 3);
    struct { const char *name; int weight; double v; dd_status want; } cases[] = {
        {"weight-nan", 1, NAN, DD_ERR_NAN},           {"weight-inf", 1, INFINITY, DD_ERR_INFINITE},
        {"weight-minus-inf", 1, -INFINITY, DD_ERR_INFINITE}, {"coordinate-nan", 0, NAN, DD_ERR_NAN},
        {"coordinate-inf", 0, -INFINITY, DD_ERR_INFINITE}};
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        char tn[160], msg[256] = "";
        snprintf(tn, sizeof tn, "refuse/create/%s", cases[k].name);
        const double keep = cases[k].weight ? s.w[17] : s.p[3 * 17 + 1];
        if (cases[k].weight) s.w[17] = cases[k].v; else s.p[3 * 17 + 1] = cases[k].v;
        dd_tri *t = (dd_tri *)&s;      /* must be set to NULL */
        const dd_status got = dd_create_ex(&t, s.p, s.w, s.n, 0, msg, sizeof msg);
        tl_check(st, got == cases[k].want && !t && strstr(msg, "17"), tn, "status %s, message '%s'",
                 dd_status_name(got), msg);
        if (cases[k].weight) s.w[17] = keep; else s.p[3 * 17 + 1] = keep;
    }
    dd_tri *t = NULL;
    char msg[256];
    tl_check(st, dd_create_ex(&t, s.p, s.w, s.n, 1u << 7, msg, sizeof msg) == DD_ERR_ARG && !t,
             "refuse/create/unknown-flag", "%s", msg);
    /* all positions in a plane, weights or not */
    for (uint32_t i = 0; i < s.n; i++) s.p[3 * i + 2] = 0.5;
    tl_check(st, dd_create_ex(&t, s.p, s.w, s.n, 0, msg, sizeof msg) == DD_ERR_COPLANAR && !t,
             "refuse/create/coplanar", "%s", msg);
    ws_free(&s);
}

/* Snapshot of what an edit must not change. */
static void refusals_case(tl_state *st)
{
    wset s = gen_uniform(small ? 200 : 500, 3, 9);
    char msg[256];
    dd_tri *t = NULL;
    if (dd_create_ex(&t, s.p, s.w, s.n, 0, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, "refuse/setup", "%s", msg);
        return;
    }
    shot before = take_shot(t);
    const double p[3] = {0.5, 0.5, 0.5}, nanp[3] = {0.5, NAN, 0.5}, infp[3] = {INFINITY, 0.5, 0.5};
    uint32_t idx = 12345;
    struct { const char *name; dd_status got, want; } cases[] = {
        {"insert-nan-weight", dd_insert_weighted(t, p, NAN, &idx), DD_ERR_NAN},
        {"insert-inf-weight", dd_insert_weighted(t, p, INFINITY, &idx), DD_ERR_INFINITE},
        {"insert-minus-inf-weight", dd_insert_weighted(t, p, -INFINITY, &idx), DD_ERR_INFINITE},
        {"insert-nan-point", dd_insert_weighted(t, nanp, 0.1, &idx), DD_ERR_NAN},
        {"insert-inf-point", dd_insert_weighted(t, infp, 0.1, &idx), DD_ERR_INFINITE},
        {"dd_insert-nan-point", dd_insert(t, nanp, &idx), DD_ERR_NAN},
    };
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        char tn[160];
        snprintf(tn, sizeof tn, "refuse/weighted/%s", cases[k].name);
        tl_check(st, cases[k].got == cases[k].want && unchanged(t, &before) && dd_errmsg(t)[0], tn,
                 "status %s (want %s), errmsg '%s'", dd_status_name(cases[k].got), dd_status_name(cases[k].want),
                 dd_errmsg(t));
    }
    char why[256] = "";
    tl_check(st, checked(t, why, sizeof why), "refuse/weighted/check-after", "%s", why);
    dd_free(t);
    shot_free(&before);
    /* dd_insert_weighted on an unweighted t */
    dd_create(&t, s.p, s.n, msg, sizeof msg);
    before = take_shot(t);
    tl_check(st, dd_insert_weighted(t, p, 1, &idx) == DD_ERR_UNSUPPORTED && unchanged(t, &before),
             "refuse/unweighted/insert-weighted", "%s", dd_errmsg(t));
    double w = -1;
    tl_check(st, !dd_is_weighted(t) && dd_weight(t, 3, &w) == DD_OK && w == 0 && !dd_is_hidden(t, 3),
             "unweighted/reads", "weight %g", w);
    shot_free(&before);
    dd_free(t);
    ws_free(&s);
}

/* Exact duplicates and equal positions through insertion: a vertex's own
 * weighted point changes nothing and names that vertex; a lighter point
 * at its position is hidden; a heavier one swallows it.                */
static void equal_positions_case(tl_state *st)
{
    wset s = gen_grid(4, 0, 1, 3);
    char msg[256], why[256] = "";
    for (uint32_t i = 0; i < s.n; i++) s.w[i] = 0.25;
    dd_tri *t = NULL;
    int ok = dd_create_ex(&t, s.p, s.w, s.n, 0, msg, sizeof msg) == DD_OK;
    const uint32_t v = 21;                                /* an inner node */
    const double *q = s.p + 3 * v;
    uint32_t i1 = 0, i2 = 0, i3 = 0;
    shot before = take_shot(t);
    ok = ok && dd_is_vertex(t, v) && dd_insert_weighted(t, q, 0.25, &i1) == DD_OK && i1 == v && unchanged(t, &before);
    if (!ok) snprintf(why, sizeof why, "the exact duplicate: index %u, not %u, or a change", i1, v);
    if (ok && !(dd_insert_weighted(t, q, 0.1, &i2) == DD_OK && i2 == s.n && dd_is_hidden(t, i2) && dd_is_vertex(t, v)))
        ok = 0, snprintf(why, sizeof why, "the lighter point is not hidden");
    if (ok && !(dd_insert_weighted(t, q, 0.5, &i3) == DD_OK && i3 == s.n + 1 && dd_is_vertex(t, i3) &&
                !dd_is_vertex(t, v) && dd_is_hidden(t, v) && dd_is_hidden(t, i2)))
        ok = 0, snprintf(why, sizeof why, "the heavier point did not swallow the vertex");
    /* the same on the hull: corner node 0 (an extreme point) */
    const double *q0 = s.p;
    uint32_t j1 = 0, j2 = 0;
    if (ok && !(dd_insert_weighted(t, q0, 0.1, &j1) == DD_OK && dd_is_hidden(t, j1) && dd_is_vertex(t, 0) &&
                dd_on_hull(t, 0)))
        ok = 0, snprintf(why, sizeof why, "a lighter point at a hull vertex is not hidden");
    if (ok && !(dd_insert_weighted(t, q0, 1.0, &j2) == DD_OK && dd_is_vertex(t, j2) && dd_on_hull(t, j2) &&
                dd_is_hidden(t, 0) && dd_is_hidden(t, j1)))
        ok = 0, snprintf(why, sizeof why, "a heavier point at a hull vertex did not take its place");
    if (ok) ok = checked(t, why, sizeof why);
    if (ok) {       /* keep mode is order-free: CGAL's build of every point given */
        const double extra[4][4] = {{q[0], q[1], q[2], 0.1}, {q[0], q[1], q[2], 0.5}, {q0[0], q0[1], q0[2], 0.1},
                                    {q0[0], q0[1], q0[2], 1.0}};
        for (int k = 0; k < 4; k++) ws_add(&s, extra[k][0], extra[k][1], extra[k][2], extra[k][3]);
        dd_cgal_rt *c = dd_cgal_rt_build(s.p, s.w, s.n, 0);
        ok = c && same_as_cgal(t, c, why, sizeof why);
        dd_cgal_rt_free(c);
    }
    tl_check(st, ok, "insert/equal-positions", "%s", why);
    shot_free(&before);
    dd_free(t);
    ws_free(&s);
}

/* ---- allocation failures (issue 46) ------------------------------------------ */

#ifdef DD_TEST_BUILD
/* The allocations op makes (process-wide count). */
static long count_allocs(void) { return dd_test_control(NULL, DD_TEST_ALLOC_COUNT, 0); }

/* Each allocation of dd_create_ex (both modes) and of dd_insert_weighted
 * (a point hidden on arrival, one that swallows vertices and re-homes
 * hidden points, one outside the hull) refused in turn: DD_ERR_NOMEM,
 * nothing changed, dd_check passes; ASan sees no leak.  Then the same
 * call succeeds.                                                        */
static void fault_case(tl_state *st)
{
    wset s = gen_uniform(small ? 80 : 200, 3, 77);
    char msg[256], why[256] = "";
    long survived = 0;
    int ok = 1;
    for (int keep = 1; keep >= 0 && ok; keep--) {
        dd_tri *t = NULL;
        count_allocs();
        ok = dd_create_ex(&t, s.p, s.w, s.n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg) == DD_OK;
        const long n = count_allocs();
        dd_free(t);
        for (long k = 1; k <= n && ok; k++) {
            t = NULL;
            dd_test_control(NULL, DD_TEST_ALLOC_FAIL, k);
            const dd_status r = dd_create_ex(&t, s.p, s.w, s.n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg);
            dd_test_control(NULL, DD_TEST_ALLOC_FAIL, 0);
            if (r == DD_ERR_NOMEM && !t) survived++;
            else if (r == DD_OK) ok = checked(t, why, sizeof why);     /* a way without it */
            else ok = 0, snprintf(why, sizeof why, "create, allocation %ld refused: %s", k, dd_status_name(r));
            dd_free(t);
        }
    }
    const double pts[3][4] = {{0.5, 0.5, 0.5, 0.0}, {0.4, 0.6, 0.5, 0.2}, {1.5, 0.5, 0.5, 0.0}};
    for (int q = 0; q < 3 && ok; q++) {
        dd_tri *t = NULL;
        uint32_t idx;
        dd_create_ex(&t, s.p, s.w, s.n, 0, msg, sizeof msg);
        count_allocs();
        ok = dd_insert_weighted(t, pts[q], pts[q][3], &idx) == DD_OK;
        const long n = count_allocs();
        dd_free(t);
        for (long k = 1; k <= n && ok; k++) {
            dd_create_ex(&t, s.p, s.w, s.n, 0, msg, sizeof msg);
            shot before = take_shot(t);
            dd_test_control(NULL, DD_TEST_ALLOC_FAIL, k);
            const dd_status r = dd_insert_weighted(t, pts[q], pts[q][3], &idx);
            const long left = dd_test_control(NULL, DD_TEST_ALLOC_FAIL, 0);
            if (left > 0) ok = 0, snprintf(why, sizeof why, "insert %d: allocation %ld never came", q, k);
            else if (r == DD_ERR_NOMEM && unchanged(t, &before) && checked(t, why, sizeof why)) survived++;
            else if (r != DD_OK) ok = 0, snprintf(why, sizeof why, "insert %d, allocation %ld: %s", q, k, dd_errmsg(t));
            if (ok && dd_insert_weighted(t, pts[q], pts[q][3], &idx) != DD_OK)
                ok = 0, snprintf(why, sizeof why, "insert %d fails after allocation %ld was refused", q, k);
            if (ok) ok = checked(t, why, sizeof why);
            shot_free(&before);
            dd_free(t);
        }
    }
    tl_check(st, ok && survived > 0, "fault/weighted", "%s (%ld survived)", why, survived);
    fprintf(stderr, "  fault/weighted: %ld injected failures survived\n", survived);
    ws_free(&s);
}
#endif

int main(int argc, char **argv)
{
    small = argc > 1 && !strcmp(argv[1], "small");
    tl_state st = {0, 0};
    const uint32_t n = small ? 400 : 3000;
    const double scales[] = {0.01, 0.3, 1, 3, 10};
    for (size_t k = 0; k < sizeof scales / sizeof *scales; k++) {
        char name[64];
        snprintf(name, sizeof name, "uniform-w%g", scales[k]);
        wset s = gen_uniform(n, scales[k], 100 + k);
        build_case(&st, name, &s);
        ws_free(&s);
    }
    wset s = gen_molecule(small ? 6 : 11, 1);
    build_case(&st, "molecule", &s);
    ws_free(&s);
    s = gen_protecting(small ? 60 : 200, small ? 200 : 1500, 2);
    build_case(&st, "protecting-balls", &s);
    ws_free(&s);
    s = gen_curve(small ? 200 : 1000, 0, 3);
    build_case(&st, "moment-curve", &s);
    ws_free(&s);
    s = gen_curve(small ? 300 : 2000, 1, 4);
    build_case(&st, "helix", &s);
    ws_free(&s);
    s = gen_grid(small ? 5 : 8, small ? 60 : 300, 1, 5);
    build_case(&st, "grid", &s);
    insert_case(&st, "grid", &s, s.n / 3, 1);
    ws_free(&s);
    s = gen_uniform(small ? 600 : 4000, 3, 6);
    insert_case(&st, "uniform-w3", &s, s.n / 2, small ? 50 : 200);
    ws_free(&s);
    s = gen_molecule(small ? 5 : 8, 7);
    insert_case(&st, "molecule", &s, s.n / 4, small ? 20 : 50);
    ws_free(&s);
    insert_zero_case(&st);
    equal_positions_case(&st);
    s = gen_uniform(n, 1, 8);
    zero_weights_case(&st, "uniform", &s);
    ws_free(&s);
    s = gen_grid(small ? 5 : 7, 0, 1, 9);
    zero_weights_case(&st, "grid", &s);
    ws_free(&s);
    bad_create_case(&st);
    refusals_case(&st);
#ifdef DD_TEST_BUILD
    fault_case(&st);
#endif
    return tl_finish(&st);
}
