/*
 * test_batch.c -- the hinted and whole-array calls (dtdel.h): dd_insert_from,
 * dd_insert_weighted_from, dd_insert_many, dd_move_many, dd_locate_many,
 * dd_nearest_many, dd_points, dd_cells_vertices.
 *
 * Each edit equals CGAL's result (cells; hidden set where weighted) and
 * the same edits made one call at a time (cells and indices), on uniform,
 * grid (cospherical, equal distances), molecule and wgrid data, hidden
 * points kept and discarded.  Bad batches (a NaN at position k, a vertex
 * listed twice, an unknown vertex, two equal targets, a target on a
 * vertex that does not move) are refused with the status and the
 * position, the triangulation unchanged (canonical form, hidden set,
 * counts, points).  The reads are checked exactly: a cell whose closure
 * holds the point (CGAL's orientations), no vertex strictly nearer (exact
 * rationals).  A batch of 0 succeeds and changes nothing.
 */
#include "testlib.h"
#include "testcgal.h"
#include "testweighted.h"
#include "cgal/cgal_regular.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static tl_state st = {0, 0};

/* ---- helpers ---------------------------------------------------------------- */

static dd_tri *create(const double *p, const double *w, uint32_t n, unsigned flags)
{
    dd_tri *t = NULL;
    char msg[256];
    if (dd_create_ex(&t, p, w, n, flags, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "create: %s\n", msg);
        exit(1);
    }
    return t;
}

/* Whether input point i of t is the weighted point (q, w). */
static int same_weighted(const dd_tri *t, uint32_t i, const double *q, double w)
{
    double p[4 * 1];
    double *all = malloc(4 * (size_t)dd_num_input(t) * sizeof *all);
    int same = 0;
    if (all && dd_points(t, all, all + 3 * (size_t)dd_num_input(t)) == DD_OK) {
        memcpy(p, all + 3 * (size_t)i, 3 * sizeof *p);
        p[3] = all[3 * (size_t)dd_num_input(t) + i];
        same = !memcmp(p, q, 3 * sizeof *p) && p[3] == w;
    }
    free(all);
    return same;
}

static int same_cells(const dd_tri *a, const dd_tri *b)
{
    int32_t *x = NULL, *y = NULL;
    size_t nx = 0, ny = 0;
    int ok = dd_canonical(a, &x, &nx) == DD_OK && dd_canonical(b, &y, &ny) == DD_OK && nx == ny &&
             !memcmp(x, y, 4 * nx * sizeof *x);
    free(x), free(y);
    if (ok && dd_is_weighted(a)) {
        uint32_t *ha = NULL, *hb = NULL;
        size_t na = 0, nb = 0;
        ok = dd_hidden(a, &ha, &na) == DD_OK && dd_hidden(b, &hb, &nb) == DD_OK && na == nb &&
             (!na || !memcmp(ha, hb, na * sizeof *ha));
        free(ha), free(hb);
    }
    return ok;
}

/* Every input point's coordinates (dd_points), then whether t's cells
 * are CGAL's DT of them (all present: no index names no point).        */
static int same_as_cgal_dt(const dd_tri *t, char *why, size_t nwhy)
{
    const uint32_t np = dd_num_input(t);
    double *p = malloc(3 * (size_t)np * sizeof *p);
    int ok = p && dd_points(t, p, NULL) == DD_OK;
    for (size_t i = 0; ok && i < 3 * (size_t)np; i++) ok = !isnan(p[i]);
    if (!ok) {
        free(p);
        return snprintf(why, nwhy, "dd_points failed or a point is missing"), 0;
    }
    dd_cgal *c = dd_cgal_build(p, np);
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    ok = c && dd_canonical(t, &a, &na) == DD_OK && !dd_cgal_canonical(c, &b, &nb) && na == nb &&
         !memcmp(a, b, 4 * na * sizeof *a);
    if (!ok) snprintf(why, nwhy, "cells differ from CGAL's: %zu here, %zu there", na, nb);
    free(a), free(b), free(p);
    dd_cgal_free(c);
    return ok;
}

/* As same_as_cgal_dt for a weighted t with hidden points kept. */
static int same_as_cgal_rt(const dd_tri *t, char *why, size_t nwhy)
{
    const uint32_t np = dd_num_input(t);
    double *p = malloc(3 * (size_t)np * sizeof *p), *w = malloc((size_t)np * sizeof *w);
    int ok = p && w && dd_points(t, p, w) == DD_OK;
    uint32_t i = 0;
    while (ok && i < np && !isnan(w[i])) i++;
    if (!ok || i < np) {
        free(p), free(w);
        return snprintf(why, nwhy, "no point %u", i), 0;
    }
    dd_cgal_rt *c = dd_cgal_rt_build(p, w, np, 0);
    ok = c && same_as_cgal(t, c, why, nwhy);
    if (!c) snprintf(why, nwhy, "no CGAL triangulation");
    dd_cgal_rt_free(c);
    free(p), free(w);
    return ok;
}

static int valid(const dd_tri *t, char *why, size_t nwhy)
{
    char msg[256];
    if (dd_check_msg(t, msg, sizeof msg) == DD_OK) return 1;
    snprintf(why, nwhy, "dd_check: %.200s", msg);
    return 0;
}

/* A snapshot of t that a refused edit must leave: cells, hidden set,
 * counts (shot) and every point (dd_points).                            */
typedef struct snap { shot s; double *p; uint32_t np; } snap;
static snap snap_take(const dd_tri *t)
{
    snap s = {take_shot(t), NULL, dd_num_input(t)};
    s.p = malloc(4 * (size_t)s.np * sizeof *s.p + 1);
    dd_points(t, s.p, s.p + 3 * (size_t)s.np);
    return s;
}
static int snap_same(const dd_tri *t, const snap *s)
{
    snap now = snap_take(t);
    int same = unchanged(t, &s->s) && now.np == s->np;
    for (size_t i = 0; same && i < 4 * (size_t)s->np; i++)
        same = (isnan(now.p[i]) && isnan(s->p[i])) || now.p[i] == s->p[i];
    shot_free(&now.s);
    free(now.p);
    return same;
}
static void snap_free(snap *s) { shot_free(&s->s), free(s->p); }

/* ---- dd_insert_from --------------------------------------------------------- */

static void test_insert_from(void)
{
    uint32_t np;
    double *p = tl_gen("uniform", 2000, 3, &np);
    dd_tri *a = create(p, NULL, 1000, 0), *b = create(p, NULL, 1000, 0);
    tl_rng r = {5};
    int ok = 1;
    char why[256] = "";
    for (uint32_t i = 1000; i < np && ok; i++) {
        uint32_t ia, ib;
        dd_cell_id hint = (dd_cell_id)tl_int(&r, 0, dd_cell_end(a) - 1);
        while (!dd_cell_alive(a, hint)) hint = (dd_cell_id)tl_int(&r, 0, dd_cell_end(a) - 1);
        ok = dd_insert_from(a, p + 3 * (size_t)i, hint, &ia) == DD_OK && dd_insert(b, p + 3 * (size_t)i, &ib) == DD_OK &&
             ia == ib;
        if (!ok) snprintf(why, sizeof why, "point %u: %s", i, dd_errmsg(a));
    }
    ok = ok && same_cells(a, b) && valid(a, why, sizeof why);
    tl_check(&st, ok, "insert-from/random-hints", "%s", why);

    /* the refinement loop's hint: a cell the point is in conflict with */
    snap s = snap_take(a);
    uint32_t idx = 7;
    const double q[3] = {0.5, 0.5, 0.5};
    dd_status e = dd_insert_from(a, q, dd_cell_end(a) + 5, &idx);
    tl_check(&st, e == DD_ERR_UNKNOWN_CELL && idx == 7 && snap_same(a, &s), "insert-from/unknown-cell", "status %s",
             dd_status_name(e));
    const double bad[3] = {0.5, NAN, 0.5};
    e = dd_insert_from(a, bad, dd_cell_end(a) + 5, &idx);
    tl_check(&st, e == DD_ERR_NAN && snap_same(a, &s), "insert-from/nan-before-hint", "status %s", dd_status_name(e));
    e = dd_insert_from(a, p, -1, &idx);
    tl_check(&st, e == DD_ERR_DUPLICATE && snap_same(a, &s), "insert-from/duplicate", "status %s", dd_status_name(e));
    snap_free(&s);
    dd_free(a), dd_free(b);

    /* weighted, from a cell of the last edit */
    wset ws = gen_uniform(1500, 1.0, 9);
    a = create(ws.p, ws.w, 700, 0), b = create(ws.p, ws.w, 700, 0);
    ok = 1;
    for (uint32_t i = 700; i < ws.n && ok; i++) {
        const dd_cell_id *made;
        size_t nm;
        dd_created_cells(a, &made, &nm);
        uint32_t ia, ib;
        ok = dd_insert_weighted_from(a, ws.p + 3 * (size_t)i, ws.w[i], nm ? made[0] : -1, &ia) == DD_OK &&
             dd_insert_weighted(b, ws.p + 3 * (size_t)i, ws.w[i], &ib) == DD_OK && ia == ib;
    }
    ok = ok && same_cells(a, b) && same_as_cgal_rt(a, why, sizeof why);
    tl_check(&st, ok, "insert-weighted-from/last-cells", "%s", why);
    dd_free(a), dd_free(b);
    ws_free(&ws);
    free(p);
}

/* ---- dd_insert_many ------------------------------------------------------- */

/* Inserts pts[0..m) into a (batch) and b (one at a time, merging what
 * dd_insert refuses as a duplicate, as the batch does); same cells and
 * indices.                                                               */
static int batch_equals_single(dd_tri *a, dd_tri *b, const double *pts, const double *w, uint32_t m, char *why,
                               size_t nwhy)
{
    uint32_t *ia = malloc((m + 1) * sizeof *ia);
    size_t merged = 0, single = 0;
    int relaxed = 0;
    dd_status s = dd_insert_many(a, pts, w, m, ia, &merged);
    if (s != DD_OK) {
        snprintf(why, nwhy, "dd_insert_many: %s: %s", dd_status_name(s), dd_errmsg(a));
        free(ia);
        return 0;
    }
    int ok = 1;
    for (uint32_t i = 0; i < m && ok; i++) {
        uint32_t ib = UINT32_MAX, e = 0;
        const double *q = pts + 3 * (size_t)i;
        while (e < i && (memcmp(pts + 3 * (size_t)e, q, 3 * sizeof *q) || (w && w[e] != w[i]))) e++;
        if (e < i) {                              /* an earlier one of the batch: merged */
            ok = ia[i] == ia[e];
            if (!ok) snprintf(why, nwhy, "point %u: index %u, its earlier copy %u's %u", i, ia[i], e, ia[e]);
            single++;
            continue;
        }
        const uint32_t np = dd_num_input(b);
        s = w || dd_is_weighted(b) ? dd_insert_weighted(b, q, w ? w[i] : 0.0, &ib) : dd_insert(b, q, &ib);
        if (s == DD_ERR_DUPLICATE) {              /* the vertex there: its index */
            s = dd_nearest_vertex(b, q, &ib);
            single++;
        } else if (s == DD_OK && dd_is_weighted(b) && ib < np) {   /* a vertex's weighted point */
            single++;
        } else if (s == DD_OK && ib != ia[i] && dd_is_hidden(b, ib) && same_weighted(a, ia[i], q, w[i])) {
            ib = ia[i];                           /* dtdel.h: merged with a vertex hidden since */
            single++;
            relaxed = 1;
        }
        ok = s == DD_OK && (ib == ia[i] || relaxed);   /* after one, indices shift */
        if (!ok) snprintf(why, nwhy, "point %u: batch index %u, single %u (%s)", i, ia[i], ib, dd_status_name(s));
    }
    if (ok && !relaxed && merged != single) {
        snprintf(why, nwhy, "merged %zu, single refused %zu", merged, single);
        ok = 0;
    }
    if (ok && !relaxed && !same_cells(a, b))     /* relaxed: against CGAL alone */
        ok = 0, snprintf(why, nwhy, "cells differ from one at a time");
    free(ia);
    return ok && valid(a, why, nwhy);
}

/* base points, then m new ones of which some repeat a vertex and some an
 * earlier one of the batch; dels vertices deleted first (reused ids).   */
static void insert_many_case(const char *name, const double *p, uint32_t n, uint32_t m, uint32_t dels, unsigned flags)
{
    char tn[128], why[256] = "";
    dd_tri *a = create(p, NULL, n, flags), *b = create(p, NULL, n, flags);
    for (uint32_t k = 0; k < dels; k++) {
        dd_delete(a, 3 * k + 1);
        dd_delete(b, 3 * k + 1);
    }
    double *q = malloc(3 * (size_t)m * sizeof *q);
    memcpy(q, p + 3 * (size_t)n, 3 * (size_t)m * sizeof *q);
    for (uint32_t i = 5; i < m; i += 17) memcpy(q + 3 * (size_t)i, p + 3 * (size_t)(i % n), 3 * sizeof *q);
    for (uint32_t i = 11; i < m; i += 23) memcpy(q + 3 * (size_t)i, q + 3 * (size_t)(i / 2), 3 * sizeof *q);
    int ok = batch_equals_single(a, b, q, NULL, m, why, sizeof why);
    if (ok && !dels) ok = same_as_cgal_dt(a, why, sizeof why);
    snprintf(tn, sizeof tn, "insert-many/%s", name);
    tl_check(&st, ok, tn, "%s", why);
    free(q);
    dd_free(a), dd_free(b);
}

static void insert_many_weighted(const char *name, const wset *s, uint32_t n, int keep)
{
    char tn[128], why[256] = "";
    const unsigned flags = keep ? 0 : DD_DISCARD_HIDDEN;
    dd_tri *a = create(s->p, s->w, n, flags), *b = create(s->p, s->w, n, flags);
    int ok = batch_equals_single(a, b, s->p + 3 * (size_t)n, s->w + n, s->n - n, why, sizeof why);
    if (ok && keep) ok = same_as_cgal_rt(a, why, sizeof why);
    snprintf(tn, sizeof tn, "insert-many/%s/%s", name, keep ? "keep" : "discard");
    tl_check(&st, ok, tn, "%s", why);
    dd_free(a), dd_free(b);
}

static void test_insert_many(void)
{
    uint32_t np;
    double *p = tl_gen("uniform", 6000, 11, &np);
    insert_many_case("uniform", p, 4000, 2000, 0, 0);
    insert_many_case("uniform-larger-than-t", p, 300, 5000, 0, 0);
    insert_many_case("uniform-reused-ids", p, 4000, 2000, 200, 0);
    insert_many_case("uniform-stable-indices", p, 4000, 2000, 200, DD_STABLE_INDICES);
    free(p);
    p = tl_gen("grid", 4096, 1, &np);          /* 16^3: cospherical */
    insert_many_case("grid", p, np / 2, np - np / 2, 0, 0);
    free(p);
    wset mol = gen_molecule(9, 4);
    insert_many_case("molecule-points", mol.p, mol.n / 3, mol.n - mol.n / 3, 0, 0);
    for (int keep = 1; keep >= 0; keep--) {
        insert_many_weighted("molecule", &mol, mol.n / 3, keep);
        wset g = gen_grid(9, 300, 0, 7);
        insert_many_weighted("wgrid", &g, 200, keep);
        ws_free(&g);
        wset u = gen_uniform(4000, 3.0, 8);
        insert_many_weighted("wuniform", &u, 1000, keep);
        ws_free(&u);
    }
    ws_free(&mol);

    /* refusals: nothing changes, the position named */
    p = tl_gen("uniform", 600, 2, &np);
    dd_tri *t = create(p, NULL, 500, 0);
    snap s = snap_take(t);
    double q[3 * 100];
    memcpy(q, p + 1500, sizeof q);
    q[3 * 37 + 1] = NAN;
    uint32_t idx[100];
    dd_status e = dd_insert_many(t, q, NULL, 100, idx, NULL);
    tl_check(&st, e == DD_ERR_NAN && strstr(dd_errmsg(t), "point 37 ") && snap_same(t, &s), "insert-many/nan-at-37",
             "%s: %s", dd_status_name(e), dd_errmsg(t));
    q[3 * 37 + 1] = 0.5;
    q[3 * 99] = -INFINITY;
    e = dd_insert_many(t, q, NULL, 100, idx, NULL);
    tl_check(&st, e == DD_ERR_INFINITE && strstr(dd_errmsg(t), "point 99 ") && snap_same(t, &s),
             "insert-many/infinite-at-99", "%s: %s", dd_status_name(e), dd_errmsg(t));
    const double w1[1] = {0.0};
    e = dd_insert_many(t, q, w1, 1, idx, NULL);
    tl_check(&st, e == DD_ERR_UNSUPPORTED && snap_same(t, &s), "insert-many/weights-on-unweighted", "%s",
             dd_status_name(e));
    size_t merged = 9;
    e = dd_insert_many(t, q, NULL, 0, idx, &merged);
    tl_check(&st, e == DD_OK && merged == 0 && snap_same(t, &s), "insert-many/empty", "%s", dd_status_name(e));
    snap_free(&s);
    dd_free(t);
    free(p);
}

/* ---- dd_move_many ------------------------------------------------------- */

/* Every vertex moved by a small random step (a smoothing pass), plus, for
 * swap, two vertices exchanging places and one moving onto the old point
 * of another that moves too.                                             */
static void move_targets(const dd_tri *t, uint32_t np, double step, int swap, tl_rng *r, uint32_t *vs, double *q,
                         uint32_t *m)
{
    uint32_t k = 0;
    for (uint32_t v = 0; v < np; v++) {
        if (!dd_is_vertex(t, v)) continue;
        double x[3];
        dd_point(t, v, x);
        vs[k] = v;
        for (int c = 0; c < 3; c++) q[3 * (size_t)k + (size_t)c] = x[c] + step * (tl_unif(r) - 0.5);
        k++;
    }
    if (swap && k > 10) {
        dd_point(t, vs[4], q + 3 * 3);      /* 3 <-> 4 */
        dd_point(t, vs[3], q + 3 * 4);
        dd_point(t, vs[6], q + 3 * 5);      /* 5 onto 6's, 6 elsewhere */
        q[3 * 6] += 1e-3;
    }
    *m = k;
}

/* One pass of m moves one at a time, in the given order (discard mode's
 * reference); the first status that is not DD_OK.                       */
static dd_status moves_one_at_a_time(dd_tri *b, const uint32_t *vs, const double *q, const double *w, uint32_t m)
{
    dd_status s = DD_OK;
    for (uint32_t i = 0; i < m && s == DD_OK; i++) s = dd_move_weighted(b, vs[i], q + 3 * (size_t)i, w[i]);
    return s;
}

static void move_many_case(const char *name, const double *p, const double *w, uint32_t n, double step, int keep)
{
    char tn[128], why[256] = "";
    const unsigned flags = keep ? 0 : DD_DISCARD_HIDDEN;
    dd_tri *t = create(p, w, n, flags), *b = w && !keep ? create(p, w, n, flags) : NULL;
    const uint32_t np = dd_num_input(t);
    uint32_t *vs = malloc(np * sizeof *vs), m;
    double *q = malloc(3 * (size_t)np * sizeof *q), *nw = malloc(np * sizeof *nw);
    tl_rng r = {77};
    move_targets(t, np, step, keep, &r, vs, q, &m);
    for (uint32_t i = 0; i < m; i++) nw[i] = w ? w[vs[i]] * (keep ? 0.5 + tl_unif(&r) : 1.0) : 0;
    int ok = 1;
    for (int pass = 0; pass < 2 && ok; pass++) {
        dd_status want = b ? moves_one_at_a_time(b, vs, q, nw, m) : DD_OK;
        snap before = snap_take(t);
        dd_status s = dd_move_many(t, vs, q, w ? nw : NULL, m);
        ok = s == want && (want == DD_OK || snap_same(t, &before));
        if (!ok) snprintf(why, sizeof why, "pass %d: %s (wanted %s): %s", pass, dd_status_name(s),
                          dd_status_name(want), dd_errmsg(t));
        snap_free(&before);
        if (want != DD_OK) break;
        if (ok && b && !same_cells(t, b)) ok = 0, snprintf(why, sizeof why, "pass %d: not as one at a time", pass);
        for (uint32_t i = 0; i < 3 * m; i++) q[i] += step * 0.1;
    }
    if (ok) ok = valid(t, why, sizeof why);
    if (ok) ok = !w ? same_as_cgal_dt(t, why, sizeof why) : keep ? same_as_cgal_rt(t, why, sizeof why) : 1;
    snprintf(tn, sizeof tn, "move-many/%s%s", name, w ? keep ? "/keep" : "/discard" : "");
    tl_check(&st, ok, tn, "%s", why);
    free(vs), free(q), free(nw);
    dd_free(t), dd_free(b);
}

static void test_move_many(void)
{
    uint32_t np;
    double *p = tl_gen("uniform", 3000, 21, &np);
    move_many_case("uniform", p, NULL, np, 0.01, 1);
    move_many_case("uniform-large-steps", p, NULL, np, 0.3, 1);
    free(p);
    p = tl_gen("grid", 1728, 1, &np);
    move_many_case("grid", p, NULL, np, 0.0, 1);     /* only the swaps: still a grid */
    free(p);
    wset mol = gen_molecule(8, 3);
    move_many_case("molecule-points", mol.p, NULL, mol.n, 0.2, 1);
    move_many_case("molecule", mol.p, mol.w, mol.n, 0.2, 1);
    move_many_case("molecule", mol.p, mol.w, mol.n, 0.2, 0);
    wset u = gen_uniform(2500, 3.0, 4);
    move_many_case("wuniform", u.p, u.w, u.n, 0.01, 1);
    move_many_case("wuniform", u.p, u.w, u.n, 0.01, 0);
    ws_free(&u);
    wset g = gen_grid(8, 100, 0, 3);
    move_many_case("wgrid", g.p, g.w, g.n, 0.0, 1);
    ws_free(&g);

    /* refusals */
    dd_tri *t = create(mol.p, NULL, mol.n, 0);
    snap s = snap_take(t);
    uint32_t vs[50];
    double q[150];
    for (uint32_t i = 0; i < 50; i++) {
        vs[i] = 2 * i;
        dd_point(t, vs[i], q + 3 * i);
        q[3 * i] += 0.01;
    }
    struct { const char *name; int what; dd_status want; const char *pos; } bad[] = {
        {"nan-at-17", 0, DD_ERR_NAN, "point 17 "}, {"listed-twice", 1, DD_ERR_ARG, "at 8 and 30"},
        {"unknown-vertex", 2, DD_ERR_UNKNOWN_VERTEX, "at 44 "}, {"same-targets", 3, DD_ERR_DUPLICATE, "at 2 and 9"},
        {"onto-fixed-vertex", 4, DD_ERR_DUPLICATE, "point 1,"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        uint32_t v2[50];
        double q2[150];
        memcpy(v2, vs, sizeof v2);
        memcpy(q2, q, sizeof q2);
        switch (bad[k].what) {
        case 0: q2[3 * 17 + 2] = NAN; break;
        case 1: v2[30] = v2[8]; break;
        case 2: v2[44] = dd_num_input(t) + 3; break;
        case 3: memcpy(q2 + 27, q2 + 6, 3 * sizeof *q2); break;
        case 4: dd_point(t, 1, q2 + 3 * 40); break;
        }
        dd_status e = dd_move_many(t, v2, q2, NULL, 50);
        char tn[96], want[64];
        snprintf(tn, sizeof tn, "move-many/refused/%s", bad[k].name);
        snprintf(want, sizeof want, "%s", bad[k].pos);
        if (bad[k].what == 4) snprintf(want, sizeof want, "onto point 1,");
        tl_check(&st, e == bad[k].want && strstr(dd_errmsg(t), want) && snap_same(t, &s), tn, "%s: %s",
                 dd_status_name(e), dd_errmsg(t));
    }
    tl_check(&st, dd_move_many(t, vs, q, NULL, 0) == DD_OK && snap_same(t, &s), "move-many/empty", "changed");
    const double w1[1] = {1.0};
    tl_check(&st, dd_move_many(t, vs, q, w1, 1) == DD_ERR_UNSUPPORTED && snap_same(t, &s),
             "move-many/weights-on-unweighted", "not refused");
    snap_free(&s);
    dd_free(t);
    ws_free(&mol);
}

/* ---- the reads ---------------------------------------------------------------- */

static void test_reads(const char *name, const double *p, const double *w, uint32_t n)
{
    char tn[128], why[256] = "";
    dd_tri *t = create(p, w, n, 0);
    enum { Q = 3000 };
    double *q = malloc(3 * Q * sizeof *q);
    tl_rng r = {31};
    for (int i = 0; i < Q; i++) {
        const double *x = p + 3 * (size_t)tl_int(&r, 0, n - 1);   /* near the points, some on them */
        for (int c = 0; c < 3; c++) q[3 * i + c] = i % 7 == 0 ? x[c] : x[c] + 0.3 * (tl_unif(&r) - 0.5);
    }
    q[3 * 100 + 1] = NAN;
    dd_cell_id *cells = malloc(Q * sizeof *cells);
    uint32_t *near = malloc(Q * sizeof *near);
    dd_status sl = dd_locate_many(t, q, Q, cells), sn = dd_nearest_many(t, q, Q, near);
    int ok = sl == DD_ERR_NAN && sn == DD_ERR_NAN && cells[100] == -1 && near[100] == UINT32_MAX;
    if (!ok) snprintf(why, sizeof why, "the NaN query: %s %s", dd_status_name(sl), dd_status_name(sn));
    int32_t *cv = malloc(4 * Q * sizeof *cv);
    for (int i = 0; i < Q && ok; i++) {
        if (i == 100) continue;
        ok = dd_cells_vertices(t, cells + i, 1, cv + 4 * i) == DD_OK && tl_holds(t, cv + 4 * i, q + 3 * i);
        if (!ok) snprintf(why, sizeof why, "query %d: cell %lld does not hold it", i, (long long)cells[i]);
    }
    /* no vertex strictly nearer (brute force over every vertex, exact) */
    for (int i = 0; i < Q && ok; i += 10) {
        if (i == 100) continue;
        double a[3], b[3], wa = 0, wb = 0;
        dd_point(t, near[i], a);
        if (w) dd_weight(t, near[i], &wa);
        for (uint32_t v = 0; v < n && ok; v++) {
            if (!dd_is_vertex(t, v)) continue;
            dd_point(t, v, b);
            if (w) dd_weight(t, v, &wb);
            ok = tl_cmp_power_exact(q + 3 * i, b, wb, a, wa) >= 0;
            if (!ok) snprintf(why, sizeof why, "query %d: vertex %u nearer than %u", i, v, near[i]);
        }
    }
    snprintf(tn, sizeof tn, "locate-nearest-many/%s", name);
    tl_check(&st, ok, tn, "%s", why);

    /* dd_cells_vertices of the created cells, against dd_cell */
    const dd_cell_id *made;
    size_t nm;
    dd_created_cells(t, &made, &nm);
    int32_t *mv = malloc((4 * nm + 4) * sizeof *mv);
    ok = dd_cells_vertices(t, made, nm, mv) == DD_OK;
    for (size_t k = 0; k < nm && ok; k++) {
        int32_t v4[4];
        ok = dd_cell(t, made[k], v4, NULL) == DD_OK && !memcmp(v4, mv + 4 * k, sizeof v4);
    }
    dd_cell_id dead[2] = {made[0], dd_cell_end(t)};
    ok = ok && dd_cells_vertices(t, dead, 2, mv) == DD_ERR_UNKNOWN_CELL;
    snprintf(tn, sizeof tn, "cells-vertices/%s", name);
    tl_check(&st, ok, tn, "mismatch");

    /* dd_points after deletions: NaN for the deleted, the rest exact */
    dd_delete(t, 3);
    double *pts = malloc(3 * (size_t)n * sizeof *pts), *ws = malloc(n * sizeof *ws);
    ok = dd_points(t, pts, ws) == DD_OK && isnan(pts[9]) && isnan(ws[3]);
    for (uint32_t i = 0; i < n && ok; i++) {
        double x[3];
        if (dd_point(t, i, x) != DD_OK) continue;
        ok = !memcmp(x, pts + 3 * (size_t)i, sizeof x) && ws[i] == (w ? w[i] : 0.0);
    }
    snprintf(tn, sizeof tn, "points/%s", name);
    tl_check(&st, ok, tn, "mismatch");
    tl_check(&st, dd_locate_many(t, q, 0, cells) == DD_OK && dd_nearest_many(t, q, 0, near) == DD_OK,
             "locate-nearest-many/empty", "m = 0 refused");
    free(pts), free(ws), free(mv), free(cv), free(q), free(cells), free(near);
    dd_free(t);
}

int main(void)
{
    test_insert_from();
    test_insert_many();
    test_move_many();
    uint32_t np;
    double *p = tl_gen("uniform", 3000, 41, &np);
    test_reads("uniform", p, NULL, np);
    free(p);
    p = tl_gen("grid", 1000, 1, &np);
    test_reads("grid", p, NULL, np);
    free(p);
    wset mol = gen_molecule(7, 5);
    test_reads("molecule-weighted", mol.p, mol.w, mol.n);
    ws_free(&mol);
    return tl_finish(&st);
}
