/*
 * test_rt_shim.c -- the CGAL regular-triangulation shim (cgal_regular.h)
 * checked against facts that do not come from CGAL: with zero weights it
 * is the engine's Delaunay triangulation (DESIGN 12); its cells form the
 * lower hull of the lifted points and its hidden points lie strictly
 * above it, by exact rational arithmetic; every input index is a vertex
 * or hidden (keep mode); equal positions go to the heaviest; insertion
 * numbers and hides points as a fresh build of the same points does.
 */
#include "testlib.h"
#include "testcgal.h"
#include "cgal/cgal_regular.h"

#include <gmp.h>
#include <math.h>

static tl_state st;

/* ---- exact lifted-plane test ------------------------------------------- */

/* lift(p, w) = |p|^2 - w, exactly. */
static void lift(mpq_t out, const double *p, double w)
{
    mpq_t x;
    mpq_init(x);
    mpq_set_d(out, -w);
    for (int k = 0; k < 3; k++) {
        mpq_set_d(x, p[k]);
        mpq_mul(x, x, x);
        mpq_add(out, out, x);
    }
    mpq_clear(x);
}

/* The affine function h(x) = c0 x + c1 y + c2 z + c3 through the lifted
 * vertices of the finite cell pts[0..3] (weights w), in c; 0 if the cell
 * is flat.                                                               */
static int lifted_plane(const double *pts[4], const double w[4], mpq_t c[4])
{
    mpq_t m[4][5], f, t;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 5; j++) mpq_init(m[i][j]);
    mpq_inits(f, t, NULL);
    for (int i = 0; i < 4; i++) { /* rows: x y z 1 | lift */
        for (int k = 0; k < 3; k++) mpq_set_d(m[i][k], pts[i][k]);
        mpq_set_ui(m[i][3], 1, 1);
        lift(m[i][4], pts[i], w[i]);
    }
    int flat = 0;
    for (int col = 0; col < 4 && !flat; col++) { /* Gauss-Jordan */
        int piv = -1;
        for (int i = col; i < 4 && piv < 0; i++)
            if (mpq_sgn(m[i][col]) != 0) piv = i;
        if (piv < 0) { flat = 1; break; }
        for (int j = 0; j < 5; j++) mpq_swap(m[col][j], m[piv][j]);
        for (int i = 0; i < 4; i++) {
            if (i == col || mpq_sgn(m[i][col]) == 0) continue;
            mpq_div(f, m[i][col], m[col][col]);
            for (int j = col; j < 5; j++) {
                mpq_mul(t, f, m[col][j]);
                mpq_sub(m[i][j], m[i][j], t);
            }
        }
    }
    for (int k = 0; k < 4 && !flat; k++) mpq_div(c[k], m[k][4], m[k][k]);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 5; j++) mpq_clear(m[i][j]);
    mpq_clears(f, t, NULL);
    return !flat;
}

/* sign(lift(q) - h(q)) for the plane c of lifted_plane. */
static int above_plane(mpq_t c[4], const double *q, double wq)
{
    mpq_t h, t;
    mpq_inits(h, t, NULL);
    mpq_set(h, c[3]);
    for (int k = 0; k < 3; k++) {
        mpq_set_d(t, q[k]);
        mpq_mul(t, t, c[k]);
        mpq_add(h, h, t);
    }
    lift(t, q, wq);
    mpq_sub(t, t, h);
    int s = mpq_sgn(t);
    mpq_clears(h, t, NULL);
    return s;
}

/* Does the finite cell hold q (exact orientations, closed)? */
static int cell_holds(const double *x[4], const double *q)
{
    int o = dd_cgal_orientation(x[0], x[1], x[2], x[3]);
    for (int i = 0; i < 4; i++) {
        const double *y[4] = {x[0], x[1], x[2], x[3]};
        y[i] = q;
        if (dd_cgal_orientation(y[0], y[1], y[2], y[3]) * o < 0) return 0;
    }
    return 1;
}

/* ---- data ----------------------------------------------------------------- */

static void random_weighted(uint32_t n, double wmax, uint64_t seed, double *xyz, double *w)
{
    tl_rng r = {seed};
    for (uint32_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++) xyz[3 * i + k] = tl_unif(&r);
        w[i] = wmax * tl_unif(&r);
    }
}

static int same_cells(const int32_t *a, size_t na, const int32_t *b, size_t nb)
{
    return na == nb && memcmp(a, b, 4 * na * sizeof *a) == 0;
}

/* ---- tests -------------------------------------------------------------- */

/* Zero weights: the regular triangulation is the engine's Delaunay one. */
static void test_zero_weights(const char *ds, uint32_t n)
{
    uint32_t np;
    double *xyz = tl_gen(ds, n, 7, &np);
    double *w = calloc(np, sizeof *w);
    dd_tri *t = NULL;
    char name[96];
    snprintf(name, sizeof name, "zero-weights/%s/%u", ds, np);
    dd_cgal_rt *c = dd_cgal_rt_build(xyz, w, np, 0);
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0, nh = 1;
    uint32_t *h = NULL;
    int ok = c != NULL && dd_create(&t, xyz, np, NULL, 0) == DD_OK && dd_canonical(t, &a, &na) == DD_OK &&
             dd_cgal_rt_canonical(c, &b, &nb) == 0 && dd_cgal_rt_hidden(c, &h, &nh) == 0;
    tl_check(&st, ok && same_cells(a, na, b, nb) && nh == 0, name, "%zu vs %zu cells, %zu hidden", na, nb, nh);
    free(a); free(b); free(h);
    dd_free(t);
    dd_cgal_rt_free(c);
    free(xyz); free(w);
}

/* The lifted-hull facts for CGAL's answer on (xyz, w): every vertex or
 * hidden point lies on or above every finite cell's lifted plane, every
 * hidden point strictly above the plane of a cell that holds it, and in
 * keep mode the vertices and hidden points partition the indices.      */
static void check_lower_hull(const char *name, const double *xyz, const double *w, uint32_t n, int discard)
{
    dd_cgal_rt *c = dd_cgal_rt_build(xyz, w, n, discard);
    int32_t *cells = NULL;
    uint32_t *hid = NULL, *ver = NULL;
    size_t nc = 0, nh = 0, nv = 0;
    if (c == NULL || dd_cgal_rt_canonical(c, &cells, &nc) || dd_cgal_rt_hidden(c, &hid, &nh) ||
        dd_cgal_rt_vertices(c, &ver, &nv)) {
        tl_check(&st, 0, name, "shim failed");
        dd_cgal_rt_free(c);
        return;
    }
    char tn[128];
    int sorted = 1;
    for (size_t i = 1; i < nh; i++) sorted &= hid[i - 1] < hid[i];
    snprintf(tn, sizeof tn, "%s/hidden-sorted", name);
    tl_check(&st, sorted, tn, "hidden indices not increasing");
    snprintf(tn, sizeof tn, "%s/partition", name);
    if (discard) {
        tl_check(&st, nh == 0, tn, "%zu hidden kept in discard mode", nh);
    } else {
        char *seen = calloc(n, 1);
        int dup = 0;
        for (size_t i = 0; i < nv; i++) dup |= seen[ver[i]]++;
        for (size_t i = 0; i < nh; i++) dup |= seen[hid[i]]++;
        tl_check(&st, !dup && nv + nh == n, tn, "%zu vertices + %zu hidden of %u", nv, nh, n);
        fprintf(stderr, "  %s: %zu vertices, %zu hidden\n", name, nv, nh);
        free(seen);
    }
    /* every point given (forgotten ones too) on or above every plane */
    int bad = 0, flat = 0;
    char *is_h = calloc(n, 1), *held = calloc(n, 1);
    for (size_t i = 0; i < nh; i++) is_h[hid[i]] = 1;
    for (size_t k = 0; k < nc; k++) {
        const int32_t *cl = cells + 4 * k;
        if (cl[0] < 0) continue;
        const double *x[4];
        double cw[4];
        for (int j = 0; j < 4; j++) { x[j] = xyz + 3 * cl[j]; cw[j] = w[cl[j]]; }
        mpq_t pl[4];
        for (int j = 0; j < 4; j++) mpq_init(pl[j]);
        if (!lifted_plane(x, cw, pl)) flat = 1;
        for (uint32_t q = 0; q < n && !flat; q++) {
            int s = above_plane(pl, xyz + 3 * q, w[q]);
            if (s < 0) bad++;
            if (is_h[q] && s > 0 && cell_holds(x, xyz + 3 * q)) held[q] = 1;
        }
        for (int j = 0; j < 4; j++) mpq_clear(pl[j]);
    }
    snprintf(tn, sizeof tn, "%s/lower-hull", name);
    tl_check(&st, !bad && !flat, tn, "%d points below a cell's lifted plane, flat cell %d", bad, flat);
    int unheld = 0;
    for (size_t i = 0; i < nh; i++) unheld += !held[hid[i]];
    snprintf(tn, sizeof tn, "%s/hidden-above", name);
    tl_check(&st, unheld == 0, tn, "%d hidden points on or below the hull", unheld);
    free(is_h); free(held);
    free(cells); free(hid); free(ver);
    dd_cgal_rt_free(c);
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Keep and discard modes on random weights, few to many hidden. */
static void test_random(uint32_t n, double wmax, uint64_t seed)
{
    double *xyz = malloc(3 * n * sizeof *xyz), *w = malloc(n * sizeof *w);
    random_weighted(n, wmax, seed, xyz, w);
    char name[96];
    for (int discard = 0; discard <= 1; discard++) {
        snprintf(name, sizeof name, "random/%u/w%g/%s", n, wmax, discard ? "discard" : "keep");
        check_lower_hull(name, xyz, w, n, discard);
    }
    /* both modes give the same cells on a build (hidden stays hidden) */
    dd_cgal_rt *k = dd_cgal_rt_build(xyz, w, n, 0), *d = dd_cgal_rt_build(xyz, w, n, 1);
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    int ok = k && d && !dd_cgal_rt_canonical(k, &a, &na) && !dd_cgal_rt_canonical(d, &b, &nb);
    snprintf(name, sizeof name, "random/%u/w%g/modes-agree", n, wmax);
    tl_check(&st, ok && same_cells(a, na, b, nb), name, "%zu vs %zu cells", na, nb);
    free(a); free(b);
    dd_cgal_rt_free(k); dd_cgal_rt_free(d);
    free(xyz); free(w);
}

/* A 4x4x4 grid, weight 0; five positions repeated heavier, five lighter,
 * three exact duplicates.  Heavier copies are vertices and hide their
 * originals; lighter copies are hidden; duplicates are neither.         */
static void test_equal_positions(void)
{
    const uint32_t g = 64, n = g + 13;
    double xyz[3 * 77], w[77];
    for (uint32_t i = 0; i < g; i++) {
        xyz[3 * i] = i % 4; xyz[3 * i + 1] = (i / 4) % 4; xyz[3 * i + 2] = i / 16;
        w[i] = 0;
    }
    const uint32_t heavy[5] = {5, 21, 22, 42, 63}, light[5] = {0, 10, 26, 37, 50}, dup[3] = {1, 21, 26};
    uint32_t m = g;
    for (int i = 0; i < 5; i++, m++) { memcpy(xyz + 3 * m, xyz + 3 * heavy[i], 24); w[m] = 0.25; }
    for (int i = 0; i < 5; i++, m++) { memcpy(xyz + 3 * m, xyz + 3 * light[i], 24); w[m] = -0.25; }
    for (int i = 0; i < 3; i++, m++) { memcpy(xyz + 3 * m, xyz + 3 * dup[i], 24); w[m] = w[dup[i]]; }
    /* expected hidden: the 5 heavy originals, the 5 light copies */
    uint32_t want[10];
    for (int i = 0; i < 5; i++) { want[i] = heavy[i]; want[5 + i] = g + 5 + (uint32_t)i; }
    qsort(want, 10, sizeof *want, cmp_u32);
    dd_cgal_rt *c = dd_cgal_rt_build(xyz, w, n, 0);
    uint32_t *hid = NULL, *ver = NULL;
    size_t nh = 0, nv = 0;
    int ok = c && !dd_cgal_rt_hidden(c, &hid, &nh) && !dd_cgal_rt_vertices(c, &ver, &nv);
    tl_check(&st, ok && nh == 10 && memcmp(hid, want, sizeof want) == 0, "equal-positions/hidden",
             "%zu hidden", nh);
    int dup_vertex = 0;
    for (size_t i = 0; i < nv; i++) dup_vertex |= ver[i] >= g + 10;
    tl_check(&st, ok && nv == g && !dup_vertex, "equal-positions/vertices", "%zu vertices", nv);
    free(hid); free(ver);
    dd_cgal_rt_free(c);
}

/* Insertions one by one, in either mode, give the cells (and, keeping,
 * the hidden set) of a fresh build of all points so far; an exact
 * duplicate of a vertex takes no index, one of a hidden point is hidden. */
static void test_insert(int discard)
{
    const uint32_t n0 = 60;
    uint32_t n1 = 100;
    double xyz[3 * 102], w[102];
    random_weighted(n1, 0.1, 11, xyz, w);
    dd_cgal_rt *c = dd_cgal_rt_build(xyz, w, n0, discard);
    int bad = c == NULL;
    for (uint32_t i = n0; i < n1 && !bad; i++) {
        bad |= dd_cgal_rt_insert(c, xyz + 3 * i, w[i], i) != 0 || dd_cgal_rt_num_input(c) != i + 1;
        dd_cgal_rt *f = dd_cgal_rt_build(xyz, w, i + 1, 0);
        int32_t *a = NULL, *b = NULL;
        uint32_t *ha = NULL, *hb = NULL;
        size_t na = 0, nb = 0, nha = 0, nhb = 0;
        bad |= f == NULL || dd_cgal_rt_canonical(c, &a, &na) || dd_cgal_rt_canonical(f, &b, &nb) ||
               dd_cgal_rt_hidden(c, &ha, &nha) || dd_cgal_rt_hidden(f, &hb, &nhb);
        bad |= !same_cells(a, na, b, nb);
        if (!discard) bad |= nha != nhb || (nha && memcmp(ha, hb, nha * sizeof *ha) != 0);
        else bad |= nha != 0;
        free(a); free(b); free(ha); free(hb);
        dd_cgal_rt_free(f);
    }
    char name[64];
    snprintf(name, sizeof name, "insert/%s/as-fresh-build", discard ? "discard" : "keep");
    tl_check(&st, !bad, name, "an insertion differs from a fresh build");
    uint32_t *ver = NULL, *hid = NULL;
    size_t nv = 0, nh = 0;
    bad = c == NULL || dd_cgal_rt_vertices(c, &ver, &nv) || dd_cgal_rt_hidden(c, &hid, &nh);
    if (!bad && nv > 0) {
        uint32_t v = ver[nv / 2];
        bad |= dd_cgal_rt_insert(c, xyz + 3 * v, w[v], n1) != 2 || dd_cgal_rt_num_input(c) != n1;
    }
    snprintf(name, sizeof name, "insert/%s/duplicate-vertex", discard ? "discard" : "keep");
    tl_check(&st, !bad, name, "not refused with 2");
    /* the same position, heavier: a new vertex, the old one hidden (or
     * forgotten); its weight hides some neighbours too                 */
    if (!bad && nv > 0) {
        uint32_t v = ver[nv / 3], *h2 = NULL, *v2 = NULL;
        size_t nh2 = 0, nv2 = 0;
        int ok = dd_cgal_rt_insert(c, xyz + 3 * v, w[v] + 1, n1) == 0 && dd_cgal_rt_num_input(c) == n1 + 1 &&
                 !dd_cgal_rt_vertices(c, &v2, &nv2) && !dd_cgal_rt_hidden(c, &h2, &nh2);
        int has_new = 0, has_old = 0, old_hidden = 0;
        for (size_t k = 0; ok && k < nv2; k++) has_new |= v2[k] == n1, has_old |= v2[k] == v;
        for (size_t k = 0; ok && k < nh2; k++) old_hidden |= h2[k] == v;
        snprintf(name, sizeof name, "insert/%s/heavier-at-vertex", discard ? "discard" : "keep");
        tl_check(&st, ok && has_new && !has_old && old_hidden == !discard, name,
                 "new vertex %d, old vertex %d, old hidden %d", has_new, has_old, old_hidden);
        free(h2), free(v2);
        n1++;
    }
    if (!discard) {
        uint32_t *h2 = NULL;
        size_t nh2 = 0;
        int ok = !bad && nh > 0;
        if (ok) {
            uint32_t q = hid[0];
            free(hid);
            hid = NULL;
            ok = !dd_cgal_rt_hidden(c, &hid, &nh) && dd_cgal_rt_insert(c, xyz + 3 * q, w[q], n1) == 0 &&
                 !dd_cgal_rt_hidden(c, &h2, &nh2) && nh2 == nh + 1 && h2[nh2 - 1] == n1;
        }
        tl_check(&st, ok, "insert/keep/duplicate-hidden", "%zu -> %zu hidden", nh, nh2);
        free(h2);
    }
    free(ver); free(hid);
    dd_cgal_rt_free(c);
}

/* Refusals: too few points, a NaN or infinite weight, a wrong index. */
static void test_refusals(void)
{
    double xyz[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}, w[5] = {0, 0, 0, 0, 0};
    tl_check(&st, dd_cgal_rt_build(xyz, w, 3, 0) == NULL, "refuse/three-points", "built");
    w[2] = NAN;
    tl_check(&st, dd_cgal_rt_build(xyz, w, 5, 0) == NULL, "refuse/nan-weight", "built");
    w[2] = INFINITY;
    tl_check(&st, dd_cgal_rt_build(xyz, w, 5, 0) == NULL, "refuse/inf-weight", "built");
    w[2] = 0;
    dd_cgal_rt *c = dd_cgal_rt_build(xyz, w, 5, 0);
    double p[3] = {0.2, 0.2, 0.2};
    tl_check(&st, c && dd_cgal_rt_insert(c, p, 0, 7) == 1 && dd_cgal_rt_insert(c, p, NAN, 5) == 1 &&
                      dd_cgal_rt_num_input(c) == 5,
             "refuse/insert", "accepted a bad index or weight");
    dd_cgal_rt_free(c);
}

int main(int argc, char **argv)
{
    int small = argc > 1 && strcmp(argv[1], "small") == 0;
    test_zero_weights("uniform", small ? 200 : 2000);
    test_zero_weights("grid", 64);
    test_zero_weights("cosphere", 100);
    test_random(small ? 40 : 80, 0.02, 1);
    test_random(small ? 40 : 80, 0.05, 2);
    test_random(small ? 40 : 80, 0.5, 3);
    test_equal_positions();
    test_insert(0);
    test_insert(1);
    test_refusals();
    return tl_finish(&st);
}
