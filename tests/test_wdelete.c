/*
 * test_wdelete.c -- deletion from a regular (weighted Delaunay)
 * triangulation against CGAL's Regular_triangulation_3::remove()
 * (src/cgal/cgal_regular.h, dd_cgal_rt_remove), issue 44's first slice:
 *  - deletion sequences on uniform weighted points (few to most hidden),
 *    the degenerate integer grid with small integer weights (power ties,
 *    equal positions with different weights), the moment curve and the
 *    helix with weights, and a molecule-like packing: after every step
 *    the cells and the hidden set equal CGAL's and dd_check passes, in
 *    both hidden modes, for every strategy that deletes weighted points
 *    (auto through dd_delete, gift-wrap, sew-full), the wrap's courses
 *    taken in turn (test builds: scalar, no single precision, spoiled
 *    single precision, narrower guesses), on the grid also with exact
 *    duplicates, and on protecting balls;
 *  - a hull vertex whose finite neighbours and star's hidden points all
 *    lie on one plane (the framework's forced fill; the hidden points
 *    stay hidden), and the same with nothing below the plane
 *    (DD_ERR_DIMENSION, as CGAL ends in 2D), every strategy above;
 *  - the gift wrap's weighted filter bound (dd_lift_power_err) against
 *    the exact power test;
 *  - zero weights: the same cells as the unweighted triangulation after
 *    every step, the wrap taking the same course (gift-wrap, auto);
 *  - the strategies that do not yet refuse with DD_ERR_UNSUPPORTED and a
 *    message naming them, nothing changed; so do dd_delete_set and
 *    dd_reinsert; a hidden point is no vertex to delete;
 *  - every allocation of a deletion that releases hidden points refused
 *    in turn (test builds), by sew-full, auto and gift-wrap in turn:
 *    DD_ERR_NOMEM, nothing changed, then the deletion succeeds with
 *    CGAL's result.
 * Argument "small": smaller sizes (the sanitizer build).
 */
#include "testlib.h"
#include <math.h>
#include "dtdel.h"
#include "dtdel_stats.h"
#include "cgal/cgal_regular.h"
#include "testweighted.h"
#include "geom/lift_pass.h"
#include "geom/power.h"
#include "mesh/hidden.h"

static int small;
static const double q_origin[3] = {0, 0, 0};

/* Builds s in one hidden mode here and in CGAL, then deletes `ndel`
 * random vertices with strategy `variant` (NULL: dd_delete, the
 * default), comparing with CGAL's remove() and checking after every
 * step.  Counts the hidden points that came back.                      */
static void delete_case(tl_state *st, const char *name, const wset *s, uint32_t ndel, const char *variant, int keep)
{
    char tn[200], why[256] = "";
    snprintf(tn, sizeof tn, "delete/%s/%s/%s", name, variant ? variant : "default", keep ? "keep" : "discard");
    dd_tri *t;
    dd_cgal_rt *c;
    int ok = ws_build(s, keep, &t, &c, why, sizeof why);
    tl_rng r = {0x5eed + s->n + (uint64_t)keep};
    uint32_t done = 0, back = 0;
    tl_courses cs = tl_courses_all();               /* the wrap's courses, in turn (test builds) */
    for (uint32_t k = 0; k < ndel && ok && dd_num_vertices(t) > 8; k++) {
        const uint32_t v = ws_random_vertex(t, &r);
        const uint32_t nv = dd_num_vertices(t);
        tl_course_next(&cs, t);
        const dd_status ds = variant ? dd_delete_with(t, v, variant) : dd_delete(t, v);
        const int cr = dd_cgal_rt_remove(c, v);
        if (ds != DD_OK || cr != 0) {
            ok = 0, snprintf(why, sizeof why, "deleting %u: %s (%s); CGAL %d", v, dd_status_name(ds), dd_errmsg(t), cr);
            break;
        }
        back += dd_num_vertices(t) + 1 - nv;
        done++;
        ok = ws_deleted_ok(t, c, v, k, why, sizeof why);
    }
    if (ok && done == 0) ok = 0, snprintf(why, sizeof why, "nothing deleted");
    tl_check(st, ok, tn, "%s", why);
    if (ok) fprintf(stderr, "  %s: %u deletions, %u hidden points came back\n", tn, done, back);
    dd_free(t);
    dd_cgal_rt_free(c);
}

/* NULL: dd_delete, the default strategy (auto). */
static const char *const supported[] = {NULL, "gift-wrap", "sew-full"};

static void delete_all(tl_state *st, const char *name, const wset *s, uint32_t ndel)
{
    for (int keep = 1; keep >= 0; keep--)
        for (size_t k = 0; k < sizeof supported / sizeof *supported; k++)
            delete_case(st, name, s, ndel, supported[k], keep);
}

/* ---- the weighted filter ------------------------------------------------------- */

/* The wrap's weighted bound (geom/lift.h, dd_lift_power_err) is sound:
 * frames of five weighted points lifted at a sixth (dd_lift_rows_power),
 * the determinant evaluated as the wrap does (minors, cofactors, K . P);
 * whenever it is beyond the bound its sign is minus dd_power_exact's.
 * Frames: random, nearly on one power sphere (the fifth weight chosen
 * to put it on the sphere of the first four, then rounded), weights far
 * beyond m^2, tiny and huge magnitudes; and the bound is +inf where a
 * weight difference overflows.                                          */
static void power_bound_case(tl_state *st)
{
    dd_pred pr;
    dd_pred_init(&pr);
    tl_rng r = {0xb0b};
    long certified = 0, wrong = 0, trials = small ? 20000 : 200000, infs = 0;
    double col[4][8], *L[4] = {col[0], col[1], col[2], col[3]};
    for (long k = 0; k < trials && !wrong; k++) {
        const double sc = ldexp(1, (int)tl_int(&r, -60, 60)), wsc = sc * sc * ldexp(1, (int)tl_int(&r, -20, 40));
        double q[3], p[5][3], w[5], qw = wsc * (tl_unif(&r) - 0.5);
        for (int i = 0; i < 3; i++) q[i] = sc * (tl_unif(&r) - 0.5);
        for (int j = 0; j < 5; j++) {
            for (int i = 0; i < 3; i++) p[j][i] = q[i] + sc * (tl_unif(&r) - 0.5);
            w[j] = wsc * (tl_unif(&r) - 0.5);
        }
        const double *pts[5] = {p[0], p[1], p[2], p[3], p[4]};
        double W;
        dd_lift_frame f = dd_lift_rows_power(L, pts, w, 5, q, qw, &W);
        if (k % 2) {   /* the fifth nearly on the power sphere of the first four */
            double B[4], C[4], X[4], P[4], m[6], K[4];
            for (int i = 0; i < 4; i++) B[i] = L[i][1] - L[i][0], C[i] = L[i][2] - L[i][0], X[i] = L[i][3] - L[i][0];
            for (int i = 0; i < 4; i++) P[i] = L[i][4] - L[i][0];
            dd_lift_minors(m, B, C);
            dd_lift_cofactors(K, X, m);
            if (K[3] != 0) {
                /* then moved by 2^-20 to 2^-50 of the lift's size: near the bound */
                const double lift = f.m * f.m + fabs(L[3][4]);
                w[4] += (K[0] * P[0] + K[1] * P[1] + K[2] * P[2] + K[3] * P[3]) / K[3] +
                        (tl_unif(&r) - 0.5) * ldexp(lift, -(int)tl_int(&r, 20, 50));
                f = dd_lift_rows_power(L, pts, w, 5, q, qw, &W);
            }
        }
        const double err = dd_lift_power_err(f.m, W);
        double B[4], C[4], X[4], P[4], m[6], K[4];
        for (int i = 0; i < 4; i++) {
            B[i] = L[i][1] - L[i][0], C[i] = L[i][2] - L[i][0], X[i] = L[i][3] - L[i][0], P[i] = L[i][4] - L[i][0];
        }
        dd_lift_minors(m, B, C);
        dd_lift_cofactors(K, X, m);
        const int s = dd_lift_sure(dd_lift_dot4(K, P), err);
        if (!s) continue;
        certified++;
        const double wt[5] = {w[0], w[1], w[2], w[3], w[4]};
        if (s != -dd_power_exact(&pr, p[0], p[1], p[2], p[3], p[4], wt)) wrong++;
    }
    const double big[3] = {1, 2, 3};
    const double *one[1] = {big};
    const double ww[1] = {1e308};
    double W;
    dd_lift_frame f = dd_lift_rows_power(L, one, ww, 1, q_origin, -1e308, &W);
    infs = dd_lift_power_err(f.m, W) == 1.0 / 0.0;
    tl_check(st, !wrong && certified > trials / 10 && infs, "filter/weighted-bound",
             "%ld wrong of %ld certified (%ld frames); overflowed weights: bound %s", wrong, certified, trials,
             infs ? "+inf" : "finite");
    if (!wrong) fprintf(stderr, "  filter/weighted-bound: %ld of %ld frames certified, all right\n", certified, trials);
    dd_pred_clear(&pr);
}

/* ---- zero weights ----------------------------------------------------------------- */

/* Zero weights: the weighted triangulation of s's points (every weight 0)
 * and the unweighted one of the same points, the same deletions by
 * `variant` in both: after every step the same cells, and the same
 * course of the wrap (dd_last_delete_stats: its statistics, the same
 * course and guesses, the unweighted wrap bit for bit).              */
static void zero_weights_case(tl_state *st, const char *name, const wset *s0, uint32_t ndel, const char *variant)
{
    char tn[200], why[256] = "", msg[256];
    snprintf(tn, sizeof tn, "zero-weights/%s/%s", name, variant);
    double *zw = calloc(s0->n, sizeof *zw);
    dd_tri *t = NULL, *u = NULL;
    int ok = zw && dd_create_ex(&t, s0->p, zw, s0->n, 0, msg, sizeof msg) == DD_OK &&
             dd_create_ex(&u, s0->p, NULL, s0->n, 0, msg, sizeof msg) == DD_OK;
    if (!ok) snprintf(why, sizeof why, "build: %.200s", msg);
    tl_rng r = {0x2e70 + s0->n};
    uint32_t done = 0;
    for (uint32_t k = 0; k < ndel && ok && dd_num_vertices(t) > 8; k++) {
        const uint32_t v = ws_random_vertex(t, &r);
        const dd_status a = dd_delete_with(t, v, variant), b = dd_delete_with(u, v, variant);
        if (a != DD_OK || b != DD_OK) {
            ok = 0, snprintf(why, sizeof why, "deleting %u: %s / %s (%s)", v, dd_status_name(a), dd_status_name(b),
                             dd_errmsg(a != DD_OK ? t : u));
            break;
        }
        dd_delete_stats sa, sb;
        dd_last_delete_stats(t, &sa);
        dd_last_delete_stats(u, &sb);
        int32_t *ca = NULL, *cb = NULL;
        size_t na = 0, nb = 0;
        dd_canonical(t, &ca, &na);
        dd_canonical(u, &cb, &nb);
        ok = na == nb && ca && cb && !memcmp(ca, cb, 4 * na * sizeof *ca);
        if (!ok) snprintf(why, sizeof why, "after deleting %u: cells differ (%zu, %zu)", v, na, nb);
        if (ok && (sa.nstrategy != sb.nstrategy || memcmp(sa.strategy, sb.strategy, sa.nstrategy * sizeof *sa.strategy)))
            ok = 0, snprintf(why, sizeof why, "after deleting %u: the wrap took another course", v);
        if (ok) ok = checked(t, why, sizeof why);
        free(ca), free(cb);
        done++;
    }
    if (ok && done == 0) ok = 0, snprintf(why, sizeof why, "nothing deleted");
    tl_check(st, ok, tn, "%s", why);
    dd_free(t);
    dd_free(u);
    free(zw);
}

/* ---- a hull vertex over a flat star with hidden points ---------------------- */

/* The 3x3 grid {0,2,4}^2 on the plane z = 0 (weight 0), four points on
 * that plane inside its triangles with weight -3 (hidden: their lifted
 * points lie above the grid's, whose squares are cocircular, so the
 * diagonals are the perturbation's), q = (2,2,2) above, whose finite
 * neighbours are the nine grid points, and with `below` the point
 * (2,2,-2) under the plane.  Indices: grid 0-8, hidden 9-12, q 13,
 * below 14.                                                             */
static wset flat_star_set(int below)
{
    wset s = {0};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) ws_add(&s, 2 * i, 2 * j, 0, 0);
    ws_add(&s, 1, 0.5, 0, -3);
    ws_add(&s, 3.5, 1, 0, -3);
    ws_add(&s, 3, 3.5, 0, -3);
    ws_add(&s, 0.5, 3, 0, -3);
    ws_add(&s, 2, 2, 2, 0);
    if (below) ws_add(&s, 2, 2, -2, 0);
    return s;
}

/* How many kept hidden points of t live in a cell of input point q's
 * star (hidden.c's lists): those the deletion of q takes.              */
static uint32_t hidden_in_star(const dd_tri *t, uint32_t q)
{
    uint32_t *h = NULL, n = 0;
    size_t nh = 0;
    const uint32_t qv = t->in2v[q];
    if (dd_hidden(t, &h, &nh) != DD_OK) return 0;
    for (size_t k = 0; k < nh; k++) {
        const uint32_t c = t->hid->cell[t->in2v[h[k]]];
        for (int i = 0; i < 4; i++) n += dd_tv(t, c)[i] == qv;
    }
    free(h);
    return n;
}

/* Deleting q (13) from flat_star_set(1) with `variant` (NULL: dd_delete):
 * the forced fill of the framework runs, the hidden points the star
 * holds stay hidden (re-homed below the plane), and the result is
 * CGAL's, cells and hidden set, in both hidden modes.  Without the point
 * below, every point left is on the plane: DD_ERR_DIMENSION, nothing
 * changed, as CGAL (whose remove() leaves dimension 2).                */
static void flat_star_case(tl_state *st, const char *variant, int keep)
{
    char tn[160], why[256] = "", msg[256];
    snprintf(tn, sizeof tn, "flat-star/%s/%s", variant ? variant : "default", keep ? "keep" : "discard");
    wset s = flat_star_set(1);
    dd_tri *t = NULL;
    dd_cgal_rt *c = dd_cgal_rt_build(s.p, s.w, s.n, !keep);
    int ok = c && dd_create_ex(&t, s.p, s.w, s.n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg) == DD_OK;
    if (!ok) snprintf(why, sizeof why, "build: %.200s", c ? msg : "CGAL failed");
    if (ok) ok = same_as_cgal(t, c, why, sizeof why);
    uint32_t instar = 0;
    if (ok && keep) {
        for (uint32_t i = 9; i <= 12 && ok; i++)
            if (!dd_is_hidden(t, i)) ok = 0, snprintf(why, sizeof why, "point %u is not hidden", i);
        instar = hidden_in_star(t, 13);
        if (ok && !instar) ok = 0, snprintf(why, sizeof why, "no hidden point in q's star: the case tests nothing");
    }
    if (ok) {
        const dd_status ds = variant ? dd_delete_with(t, 13, variant) : dd_delete(t, 13);
        const int cr = dd_cgal_rt_remove(c, 13);
        dd_delete_stats ds_stats;
        dd_last_delete_stats(t, &ds_stats);
        if (ds != DD_OK || cr != 0)
            ok = 0, snprintf(why, sizeof why, "deleting q: %s (%s); CGAL %d", dd_status_name(ds), dd_errmsg(t), cr);
        else if (!ds_stats.forced_fill)
            ok = 0, snprintf(why, sizeof why, "the forced fill did not run");
        else
            ok = checked(t, why, sizeof why) && same_as_cgal(t, c, why, sizeof why);
        for (uint32_t i = 9; i <= 12 && ok && keep; i++)
            if (!dd_is_hidden(t, i)) ok = 0, snprintf(why, sizeof why, "point %u came back", i);
    }
    tl_check(st, ok, tn, "%s", why);
    if (ok && keep) fprintf(stderr, "  %s: %u hidden points in q's star stayed hidden\n", tn, instar);
    dd_free(t);
    dd_cgal_rt_free(c);
    ws_free(&s);

    snprintf(tn, sizeof tn, "flat-star/%s/%s/all-coplanar-left", variant ? variant : "default", keep ? "keep" : "discard");
    s = flat_star_set(0);
    t = NULL;
    c = dd_cgal_rt_build(s.p, s.w, s.n, !keep);
    ok = c && dd_create_ex(&t, s.p, s.w, s.n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg) == DD_OK;
    if (!ok) snprintf(why, sizeof why, "build: %.200s", c ? msg : "CGAL failed");
    if (ok) {
        shot before = take_shot(t);
        const dd_status ds = variant ? dd_delete_with(t, 13, variant) : dd_delete(t, 13);
        const int cr = dd_cgal_rt_remove(c, 13);
        ok = ds == DD_ERR_DIMENSION && cr == 3 && unchanged(t, &before) && checked(t, why, sizeof why);
        if (!ok && !why[0])
            snprintf(why, sizeof why, "%s (%s), CGAL %d", dd_status_name(ds), dd_errmsg(t), cr);
        shot_free(&before);
    }
    tl_check(st, ok, tn, "%s", why);
    dd_free(t);
    dd_cgal_rt_free(c);
    ws_free(&s);
}

/* ---- refusals ------------------------------------------------------------------ */

static void refusals_case(tl_state *st)
{
    wset s = gen_uniform(small ? 200 : 500, 3, 9);
    char msg[256], why[256] = "";
    dd_tri *t = NULL;
    if (dd_create_ex(&t, s.p, s.w, s.n, 0, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, "refuse/setup", "%s", msg);
        ws_free(&s);
        return;
    }
    shot before = take_shot(t);
    uint32_t v = 0;
    while (!dd_is_vertex(t, v)) v++;
    struct { const char *name; dd_status got, want; } cases[] = {
        {"delete-unknown", dd_delete(t, s.n + 5), DD_ERR_UNKNOWN_VERTEX},
        {"delete-unknown-variant", dd_delete_with(t, v, "no-such"), DD_ERR_UNKNOWN_VARIANT},
    };
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        char tn[160];
        snprintf(tn, sizeof tn, "refuse/weighted/%s", cases[k].name);
        tl_check(st, cases[k].got == cases[k].want && unchanged(t, &before) && dd_errmsg(t)[0], tn,
                 "status %s (want %s), errmsg '%s'", dd_status_name(cases[k].got), dd_status_name(cases[k].want),
                 dd_errmsg(t));
    }
    tl_check(st, checked(t, why, sizeof why), "refuse/weighted/check-after", "%s", why);
    shot_free(&before);
    dd_free(t);
    ws_free(&s);
}

/* Exact copies of a hidden point (issue 44): the cube's corners, its
 * centre with weight 1, then copies of the centre with weight 0 inserted
 * (all hidden).  Deleting the centre releases them: CGAL's remove makes
 * the first copy a vertex and keeps nothing of the others (its insert of
 * a vertex's exact weighted point); the shim names the vertex by the
 * lowest index.  Every strategy, both modes, 2 and 3 copies.            */
static const char *const all_vars[] = {NULL, "gift-wrap", "sew-full", "grr-edge", "grr-neighbor", "grr-hashing",
                                       "grr-brio", "guide-only", "dtq-only"};

static void copies_case(tl_state *st)
{
    const char *const *vars = all_vars;
    for (int keep = 0; keep < 2; keep++)
        for (uint32_t ncopy = 2; ncopy <= 3; ncopy++)
            for (size_t vi = 0; vi < sizeof all_vars / sizeof *all_vars; vi++) {
                char tn[160], why[256] = "", msg[256];
                snprintf(tn, sizeof tn, "copies/%u/%s/%s", ncopy, vars[vi] ? vars[vi] : "default",
                         keep ? "keep" : "discard");
                wset s = {0};
                for (int k = 0; k < 8; k++) ws_add(&s, k & 1, (k >> 1) & 1, (k >> 2) & 1, 0);
                ws_add(&s, 0.5, 0.5, 0.5, 1);
                dd_tri *t = NULL;
                dd_cgal_rt *c = dd_cgal_rt_build(s.p, s.w, s.n, !keep);
                int ok = c && dd_create_ex(&t, s.p, s.w, s.n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg) == DD_OK;
                if (!ok) snprintf(why, sizeof why, "build: %.200s", c ? msg : "CGAL failed");
                const double mid[3] = {0.5, 0.5, 0.5};
                for (uint32_t k = 0; k < ncopy && ok; k++) {
                    uint32_t idx = 0;
                    ok = dd_insert_weighted(t, mid, 0, &idx) == DD_OK && idx == 9 + k &&
                         dd_cgal_rt_insert(c, mid, 0, 9 + k) == 0;
                    if (!ok) snprintf(why, sizeof why, "inserting copy %u: %s", k, dd_errmsg(t));
                }
                if (ok) ok = same_as_cgal(t, c, why, sizeof why);
                if (ok) {
                    const dd_status ds = vars[vi] ? dd_delete_with(t, 8, vars[vi]) : dd_delete(t, 8);
                    const int cr = dd_cgal_rt_remove(c, 8);
                    ok = ds == DD_OK && cr == 0;
                    if (!ok) snprintf(why, sizeof why, "deleting 8: %s (%s); CGAL %d", dd_status_name(ds), dd_errmsg(t), cr);
                }
                if (ok) ok = checked(t, why, sizeof why) && same_as_cgal(t, c, why, sizeof why);
                if (ok && keep) {
                    ok = dd_is_vertex(t, 9) && !dd_is_hidden(t, 10) && !dd_is_vertex(t, 10);
                    if (!ok) snprintf(why, sizeof why, "9 should be the vertex, 10 forgotten");
                }
                tl_check(st, ok, tn, "%s", why);
                dd_free(t);
                dd_cgal_rt_free(c);
                ws_free(&s);
            }
}

/* The cells equal CGAL's, CGAL's hidden list is in {9, 10} and not
 * empty (cgal_has[k]: it lists 9 + k), and the engine hides both 9 and
 * 10: 0 with why filled if not.                                        */
static int kept_both_copies(const dd_tri *t, const dd_cgal_rt *c, int cgal_has[2], char *why, size_t nwhy)
{
    uint32_t *ha, *hb;
    size_t nha, nhb;
    int ok = ws_same_cells(t, c, &ha, &nha, &hb, &nhb, why, nwhy);
    if (ok && (nha != 2 || ha[0] != 9 || ha[1] != 10)) {
        snprintf(why, nwhy, "the engine should keep both copies 9 and 10 hidden (%zu hidden)", nha);
        ok = 0;
    } else if (ok && (nhb < 1 || nhb > 2 || hb[0] < 9 || hb[nhb - 1] > 10)) {
        snprintf(why, nwhy, "CGAL should hide 9 or 10 or both (%zu hidden)", nhb);
        ok = 0;
    }
    for (size_t k = 0; ok && k < nhb; k++) cgal_has[hb[k] - 9] = 1;
    free(ha), free(hb);
    return ok;
}

/* Copies CGAL's remove() drops and the engine keeps (dtdel.h: dd_delete):
 * the cube's corners, its centre 8 with weight 1.5, copies 9 and 10 of
 * a = (0.45, 0.4, 0.2; 0) and b = (0.55, 0.4, 0.2; 0.2), inserted in this
 * order, all hidden by 8.  Without 8, a is no vertex (b hides it) but
 * is one of the corners' and a's own triangulation: CGAL's remove()
 * re-inserts its star's hidden points one at a time, so when a comes
 * before b, 9 is a vertex for a while, 10 is dropped as its exact copy,
 * and b hides 9 again.  The engine builds the result at once and keeps
 * both copies hidden, the cells equal to CGAL's; forgetting the copies
 * CGAL dropped (dd_delete of a hidden point) makes the two equal.  Every
 * strategy, both modes (discarding, nothing is hidden: equal at once). */
static void dropped_copy_case(tl_state *st)
{
    for (int keep = 0; keep < 2; keep++)
        for (size_t vi = 0; vi < sizeof all_vars / sizeof *all_vars; vi++) {
            char tn[160], why[256] = "", msg[256];
            snprintf(tn, sizeof tn, "copies/dropped/%s/%s", all_vars[vi] ? all_vars[vi] : "default",
                     keep ? "keep" : "discard");
            wset s = {0};
            for (int k = 0; k < 8; k++) ws_add(&s, k & 1, (k >> 1) & 1, (k >> 2) & 1, 0);
            ws_add(&s, 0.5, 0.5, 0.5, 1.5);
            ws_add(&s, 0.45, 0.4, 0.2, 0);
            dd_tri *t = NULL;
            dd_cgal_rt *c = dd_cgal_rt_build(s.p, s.w, s.n, !keep);
            int ok = c && dd_create_ex(&t, s.p, s.w, s.n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg) == DD_OK;
            if (!ok) snprintf(why, sizeof why, "build: %.200s", c ? msg : "CGAL failed");
            const double pts[2][4] = {{0.45, 0.4, 0.2, 0}, {0.55, 0.4, 0.2, 0.2}};
            for (uint32_t k = 0; k < 2 && ok; k++) {
                uint32_t idx = 0;
                ok = dd_insert_weighted(t, pts[k], pts[k][3], &idx) == DD_OK && idx == 10 + k &&
                     dd_cgal_rt_insert(c, pts[k], pts[k][3], 10 + k) == 0;
                if (!ok) snprintf(why, sizeof why, "inserting %u: %s", 10 + k, dd_errmsg(t));
            }
            if (ok) ok = same_as_cgal(t, c, why, sizeof why);
            if (ok && keep) {
                ok = dd_is_hidden(t, 9) && dd_is_hidden(t, 10) && dd_is_hidden(t, 11);
                if (!ok) snprintf(why, sizeof why, "9, 10 and 11 should be hidden before");
            }
            if (ok) {
                const dd_status ds = all_vars[vi] ? dd_delete_with(t, 8, all_vars[vi]) : dd_delete(t, 8);
                const int cr = dd_cgal_rt_remove(c, 8);
                ok = ds == DD_OK && cr == 0 && checked(t, why, sizeof why);
                if (!ok && !why[0]) snprintf(why, sizeof why, "deleting 8: %s (%s); CGAL %d", dd_status_name(ds), dd_errmsg(t), cr);
            }
            int has[2] = {0, 0};
            if (ok && keep) {
                ok = dd_is_vertex(t, 11) && kept_both_copies(t, c, has, why, sizeof why);
                if (!ok && !why[0]) snprintf(why, sizeof why, "11 should be a vertex");
                for (uint32_t k = 0; ok && k < 2; k++)              /* forget what CGAL dropped */
                    if (!has[k]) ok = dd_delete(t, 9 + k) == DD_OK;
            }
            if (ok) ok = same_as_cgal(t, c, why, sizeof why);
            tl_check(st, ok, tn, "%s%s", why, keep && !(has[0] && has[1]) ? " (CGAL dropped a copy)" : "");
            dd_free(t);
            dd_cgal_rt_free(c);
            ws_free(&s);
        }
}

/* Exact copies of a hidden point on a facet shared by two cells (issue
 * 44): A (0,0,0; 3), B, C on z = 0, D (1,1,3) and E (1,1,-3) make the
 * cells ABCD and ABCE, four far points around; 9 and 10 are copies of
 * (1,1,0; -5), on facet ABC, hidden.  CGAL keeps a hidden point in the
 * first cell of its closure its walk from the hint enters:
 * dd_cgal_rt_insert_in starts the walk in ABCD for one copy and in ABCE
 * for the other (in both orders), so CGAL keeps them in different cells,
 * the engine wherever its own walk ends.  The result must not depend on
 * it: deleting A (both cells in its star) makes 9 a vertex and forgets
 * 10; deleting D (ABC on its link) keeps both hidden, then deleting A
 * releases 9; deleting D then E keeps both.  Every strategy, both modes,
 * each step equal to CGAL.                                              */
static void shared_facet_case(tl_state *st)
{
    static const char *const vars[] = {NULL, "gift-wrap", "sew-full", "grr-edge", "grr-neighbor", "grr-hashing",
                                        "grr-brio", "guide-only", "dtq-only"};
    static const uint32_t seqs[3][3] = {{0, UINT32_MAX}, {3, 0, UINT32_MAX}, {3, 4, UINT32_MAX}};
    static const char *const seqname[3] = {"A", "D-A", "D-E"};
    static const double pts[9][4] = {{0, 0, 0, 3},     {4, 0, 0, 0},     {0, 4, 0, 0},
                                     {1, 1, 3, 0},     {1, 1, -3, 0},    {-20, -20, -20, 0},
                                     {40, -20, -20, 0}, {-20, 40, -20, 0}, {0, 0, 40, 0}};
    static const uint32_t abcd[4] = {0, 1, 2, 3}, abce[4] = {0, 1, 2, 4};
    for (int keep = 0; keep < 2; keep++)
        for (int order = 0; order < 2; order++)
            for (int q = 0; q < 3; q++)
                for (size_t vi = 0; vi < sizeof vars / sizeof *vars; vi++) {
                    char tn[160], why[256] = "", msg[256];
                    snprintf(tn, sizeof tn, "shared-facet/%s/%s/%s/%s", order ? "E-first" : "D-first", seqname[q],
                             vars[vi] ? vars[vi] : "default", keep ? "keep" : "discard");
                    wset s = {0};
                    for (int k = 0; k < 9; k++) ws_add(&s, pts[k][0], pts[k][1], pts[k][2], pts[k][3]);
                    dd_tri *t = NULL;
                    dd_cgal_rt *c = dd_cgal_rt_build(s.p, s.w, s.n, !keep);
                    int ok = c && dd_create_ex(&t, s.p, s.w, s.n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg) == DD_OK;
                    if (!ok) snprintf(why, sizeof why, "build: %.200s", c ? msg : "CGAL failed");
                    const double mid[3] = {1, 1, 0};
                    for (uint32_t k = 0; k < 2 && ok; k++) {
                        uint32_t idx = 0;
                        ok = dd_insert_weighted(t, mid, -5, &idx) == DD_OK && idx == 9 + k &&
                             dd_cgal_rt_insert_in(c, mid, -5, 9 + k, (k ^ (uint32_t)order) ? abce : abcd) == 0;
                        if (!ok) snprintf(why, sizeof why, "inserting copy %u: %s", k, dd_errmsg(t));
                    }
                    if (ok) ok = same_as_cgal(t, c, why, sizeof why);
                    if (ok && keep) {
                        ok = dd_is_hidden(t, 9) && dd_is_hidden(t, 10);
                        if (!ok) snprintf(why, sizeof why, "9 and 10 should be hidden");
                    }
                    for (int k = 0; ok && seqs[q][k] != UINT32_MAX; k++) {
                        const uint32_t v = seqs[q][k];
                        const dd_status ds = vars[vi] ? dd_delete_with(t, v, vars[vi]) : dd_delete(t, v);
                        const int cr = dd_cgal_rt_remove(c, v);
                        ok = ds == DD_OK && cr == 0;
                        if (!ok)
                            snprintf(why, sizeof why, "deleting %u: %s (%s); CGAL %d", v, dd_status_name(ds), dd_errmsg(t), cr);
                        if (ok) ok = checked(t, why, sizeof why) && same_as_cgal(t, c, why, sizeof why);
                    }
                    if (ok && keep) {
                        const int released = q < 2;
                        ok = released ? dd_is_vertex(t, 9) && !dd_is_hidden(t, 10) && !dd_is_vertex(t, 10)
                                      : dd_is_hidden(t, 9) && dd_is_hidden(t, 10);
                        if (!ok)
                            snprintf(why, sizeof why, "%s", released ? "9 should be the vertex, 10 forgotten"
                                                                     : "9 and 10 should stay hidden");
                    }
                    tl_check(st, ok, tn, "%s", why);
                    dd_free(t);
                    dd_cgal_rt_free(c);
                    ws_free(&s);
                }
}

/* ---- allocation failures ---------------------------------------------------------- */

#ifdef DD_TEST_BUILD
static dd_status delete_with(dd_tri *t, uint32_t v, const char *variant) { return dd_delete_with(t, v, variant); }

static void fault_case(tl_state *st)
{
    wset s = gen_uniform(small ? 80 : 150, 3, 21);
    dd_cgal_rt *c;
    const uint32_t v = ws_releasing_vertex(&s, &c);
    if (v == UINT32_MAX) {
        tl_check(st, 0, "fault/weighted-delete", "no vertex releases a hidden point");
        ws_free(&s);
        return;
    }
    static const char *const fvar[3] = {"sew-full", NULL, "gift-wrap"};   /* NULL: auto, the wrap */
    const long nomem = ws_fault_delete(st, "fault/weighted-delete", &s, v, c, delete_with, fvar, 3);
    fprintf(stderr, "  fault/weighted-delete: %ld allocations refused in turn\n", nomem);
    dd_cgal_rt_free(c);
    ws_free(&s);
}
#endif

int main(int argc, char **argv)
{
    small = argc > 1 && !strcmp(argv[1], "small");
    tl_state st = {0, 0};
    const uint32_t n = small ? 300 : 1000, nd = small ? 40 : 120;
    const double scales[] = {0.01, 1, 3, 10};
    for (size_t k = 0; k < sizeof scales / sizeof *scales; k++) {
        char name[64];
        snprintf(name, sizeof name, "uniform-w%g", scales[k]);
        wset s = gen_uniform(n, scales[k], 100 + k);
        delete_all(&st, name, &s, nd);
        ws_free(&s);
    }
    wset s = gen_grid(small ? 4 : 6, small ? 30 : 120, 0, 5);
    delete_all(&st, "grid", &s, s.n);
    ws_free(&s);
    s = gen_grid(small ? 4 : 6, small ? 30 : 120, 1, 6);
    delete_all(&st, "grid-duplicates", &s, s.n);
    ws_free(&s);
    s = gen_protecting(small ? 24 : 40, small ? 100 : 200, 7);
    delete_all(&st, "protecting", &s, nd);
    ws_free(&s);
    s = gen_uniform(small ? 300 : 1000, 1, 8);
    zero_weights_case(&st, "uniform", &s, nd, "gift-wrap");
    zero_weights_case(&st, "uniform", &s, nd, "auto");
    ws_free(&s);
    s = gen_grid(small ? 4 : 6, 0, 0, 9);
    zero_weights_case(&st, "grid", &s, s.n, "gift-wrap");
    ws_free(&s);
    s = gen_curve(small ? 100 : 400, 1, 10);
    zero_weights_case(&st, "helix", &s, nd, "auto");
    ws_free(&s);
    s = gen_molecule(small ? 5 : 7, 1);
    delete_all(&st, "molecule", &s, nd);
    ws_free(&s);
    s = gen_curve(small ? 100 : 200, 0, 3);
    delete_all(&st, "moment-curve", &s, nd);
    ws_free(&s);
    s = gen_curve(small ? 200 : 500, 1, 4);
    delete_all(&st, "helix", &s, nd);
    ws_free(&s);
    for (int keep = 1; keep >= 0; keep--)
        for (size_t k = 0; k < sizeof supported / sizeof *supported; k++) flat_star_case(&st, supported[k], keep);
    power_bound_case(&st);
    refusals_case(&st);
    copies_case(&st);
    dropped_copy_case(&st);
    shared_facet_case(&st);
#ifdef DD_TEST_BUILD
    fault_case(&st);
#endif
    return tl_finish(&st);
}
