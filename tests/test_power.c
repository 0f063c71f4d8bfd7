/*
 * test_power.c -- the power predicates (src/geom/power.h) return CGAL's
 * signs (DESIGN 12).
 *
 * Against CGAL through the shim (src/cgal/cgal_rpred.h), on weighted
 * tuples drawn from: uniform random points and weights; integer grids
 * with small integer weights (power ties, a query at a vertex's position
 * with another weight or the same); tuples whose lifted points lie on one
 * plane (the exact power test is 0: the perturbation decides); integer
 * points of spheres with zero or equal weights; hull facets with coplanar
 * queries (the infinite cell's power circle).  Each degenerate tuple also
 * scaled exactly (coordinates by 2^k, weights by 2^2k, k from -537 to
 * 500) and translated by 2^30; then extreme ones: coordinates near
 * 2^+-1000 and subnormal, weights up to +-1e300.
 *
 * Compared: the exact sign with the kernel's power test; the perturbed
 * sign with Regular_triangulation_3's side_of_oriented_power_sphere(...,
 * true), and on a sample with side_of_power_sphere on the cell of a
 * four-point regular triangulation; the infinite cell with CGAL's rule
 * (orientation, then side_of_bounded_power_circle) for every rotation of
 * the facet, and on a sample with side_of_power_sphere on the infinite
 * cell of a regular triangulation; the 3+1 power test; power distances.
 * The filter, whenever sure, against the exact sign.  With zero weights,
 * every predicate against its Delaunay counterpart of pred.h.
 * "small" (the sanitizer run) takes a quarter of the tuples.
 */
#include "testlib.h"
#include "geom/power.h"
#include "cgal/cgal_shim.h"
#include "cgal/cgal_rpred.h"

#include <math.h>

typedef struct tally { long n, bad; char first[320]; } tally;

enum { T_EXACT, T_PERT, T_CELL, T_FILTER, T_ZERO, T_INF, T_INFROT, T_INFCELL, T_COP4, T_CIRCLE, T_DIST, NT };
static const char *const tname[NT] = {"exact",  "perturbed",  "rt-cell",  "filter",  "zero-weights", "infinite",
                                      "inf-rotations", "rt-inf-cell", "power-test-3+1", "power-circle", "distance"};

typedef struct run {
    dd_pred pr;
    tl_rng r;
    tally t[NT];
    long tuples, zeros, filter_sure, cell_skipped, infcell_skipped;
    int sample;         /* every sample-th tuple goes to CGAL's RT cells */
    const char *where;  /* the current set, for the first mismatch       */
} run;

static void note(run *R, int k, int ours, int ref, const double *const *v, const double *w, int n)
{
    tally *t = &R->t[k];
    t->n++;
    if (ours == ref || t->bad++) return;
    int len = snprintf(t->first, sizeof t->first, "%s: ours %d, CGAL %d at", R->where, ours, ref);
    for (int i = 0; i < n && len < (int)sizeof t->first; i++)
        len += snprintf(t->first + len, sizeof t->first - (size_t)len, " (%a %a %a; %a)", v[i][0], v[i][1],
                        v[i][2], w[i]);
}

static int same_point(const double *a, const double *b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

/* Every comparison on the finite cell (v0..v3) and query v4. */
static void check5(run *R, const double in[5][3], const double win[5])
{
    double v[5][3], w[5];
    memcpy(v, in, sizeof v);
    memcpy(w, win, sizeof w);
    const int o = dd_cgal_orientation(v[0], v[1], v[2], v[3]);
    if (o == 0) return;
    if (o < 0) {   /* positively oriented: swap the first two */
        double s[3];
        memcpy(s, v[0], sizeof s);
        memcpy(v[0], v[1], sizeof s);
        memcpy(v[1], s, sizeof s);
        const double sw = w[0];
        w[0] = w[1];
        w[1] = sw;
    }
    const double *q[5] = {v[0], v[1], v[2], v[3], v[4]};
    R->tuples++;
    const int ex = dd_power_exact(&R->pr, q[0], q[1], q[2], q[3], q[4], w);
    note(R, T_EXACT, ex, dd_cgal_power_test(q[0], q[1], q[2], q[3], q[4], w), q, w, 5);
    const int f = dd_power_filter(&R->pr, q[0], q[1], q[2], q[3], q[4], w);
    if (f != DD_FILTER_UNSURE) {
        R->filter_sure++;
        note(R, T_FILTER, f, ex, q, w, 5);
    }
    const int pt = dd_power_perturbed(&R->pr, q[0], q[1], q[2], q[3], q[4], w);
    note(R, T_PERT, pt, dd_cgal_power_sphere(q[0], q[1], q[2], q[3], q[4], w, 1), q, w, 5);
    if (ex == 0) {
        R->zeros++;
        note(R, T_PERT, dd_power_symbolic(&R->pr, q[0], q[1], q[2], q[3], q[4], w), pt, q, w, 5);
    }
    if (R->tuples % R->sample == 0) {
        int res;
        if (dd_cgal_power_cell(q[0], q[1], q[2], q[3], q[4], w, &res) == 0) note(R, T_CELL, pt, res, q, w, 5);
        else R->cell_skipped++;
    }
    note(R, T_DIST, dd_power_compare_distance(&R->pr, q[4], q[0], w[0], q[1], w[1]),
         dd_cgal_power_compare_distance(q[4], q[0], w[0], q[1], w[1]), q, w, 5);
    int apart = 1;   /* pred.h's Delaunay predicates take five distinct points */
    for (int k = 0; k < 4; k++) apart &= !same_point(q[k], q[4]);
    if (apart && w[0] == 0 && w[1] == 0 && w[2] == 0 && w[3] == 0 && w[4] == 0) {
        note(R, T_ZERO, ex, dd_insphere(&R->pr, q[0], q[1], q[2], q[3], q[4]), q, w, 5);
        note(R, T_ZERO, pt, dd_insphere_perturbed(&R->pr, q[0], q[1], q[2], q[3], q[4]), q, w, 5);
        note(R, T_ZERO, dd_power_compare_distance(&R->pr, q[4], q[0], 0, q[1], 0),
             dd_compare_distance(&R->pr, q[4], q[0], q[1]), q, w, 5);
    }
}

/* Every comparison on the infinite cell over the hull facet (a, b, c)
 * (a, b, c, then the infinite vertex, positively oriented) and query p. */
static void check_facet(run *R, const double in[4][3], const double win[4])
{
    if (dd_cgal_coplanar_orientation(in[0], in[1], in[2]) == 0) return;
    const double *q[4] = {in[0], in[1], in[2], in[3]};
    const double *w = win;
    R->tuples++;
    const int o = dd_cgal_orientation(q[0], q[1], q[2], q[3]);
    const int ref = o != 0 ? o : dd_cgal_power_circle(q[0], q[1], q[2], q[3], w, 1);
    const int ours = dd_power_infinite(&R->pr, q[0], q[1], q[2], q[3], w);
    note(R, T_INF, ours, ref, q, w, 4);
    const double wr1[4] = {w[1], w[2], w[0], w[3]}, wr2[4] = {w[2], w[0], w[1], w[3]};
    note(R, T_INFROT, dd_power_infinite(&R->pr, q[1], q[2], q[0], q[3], wr1), ref, q, w, 4);
    note(R, T_INFROT, dd_power_infinite(&R->pr, q[2], q[0], q[1], q[3], wr2), ref, q, w, 4);
    if (o == 0) {
        const int ex = dd_power_coplanar(&R->pr, q[0], q[1], q[2], q[3], w);
        note(R, T_COP4, ex, dd_cgal_power_test4(q[0], q[1], q[2], q[3], w), q, w, 4);
        if (ex == 0) R->zeros++;
        const double ws[4] = {w[0], w[2], w[1], w[3]};
        note(R, T_CIRCLE, dd_power_circle_perturbed(&R->pr, q[0], q[2], q[1], q[3], ws),
             dd_cgal_power_circle(q[0], q[2], q[1], q[3], ws, 1), q, w, 4);
    }
    if (R->tuples % R->sample == 0 || o == 0) {
        int res;
        if (dd_cgal_power_infinite(q[0], q[1], q[2], q[3], w, &res) == 0) note(R, T_INFCELL, ours, res, q, w, 4);
        else R->infcell_skipped++;
    }
    int apart = 1;
    for (int k = 0; k < 3; k++) apart &= !same_point(q[k], q[3]);
    if (apart && w[0] == 0 && w[1] == 0 && w[2] == 0 && w[3] == 0) {
        const double *cell[4] = {q[0], q[1], q[2], NULL};
        note(R, T_ZERO, ours, dd_inf_conflict(&R->pr, cell, 3, q[3]), q, w, 4);
    }
}

/* ---- exact scalings --------------------------------------------------- */

/* Coordinates times 2^k plus t (exact for the integer sets below), weights
 * times 2^2k: the power signs are unchanged.                            */
static void scale_pts(double *out, const double *in, int n, int k, double t, double *wout, const double *win)
{
    for (int i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++) out[3 * i + c] = ldexp(in[3 * i + c], k) + t;
        wout[i] = ldexp(win[i], 2 * k);
    }
}

static const int scales[] = {0, -537, -300, 300, 500};

static void check5_scaled(run *R, const double v[5][3], const double w[5], int translate)
{
    for (size_t s = 0; s < sizeof scales / sizeof *scales; s++) {
        double x[5][3], wx[5];
        scale_pts(&x[0][0], &v[0][0], 5, scales[s], 0, wx, w);
        check5(R, (const double(*)[3])x, wx);
    }
    if (translate) {
        double x[5][3], wx[5];
        scale_pts(&x[0][0], &v[0][0], 5, 0, 0x1p30, wx, w);
        check5(R, (const double(*)[3])x, wx);
    }
}

static void check_facet_scaled(run *R, const double v[4][3], const double w[4])
{
    for (size_t s = 0; s < sizeof scales / sizeof *scales; s++) {
        double x[4][3], wx[4];
        scale_pts(&x[0][0], &v[0][0], 4, scales[s], 0, wx, w);
        check_facet(R, (const double(*)[3])x, wx);
    }
    double x[4][3], wx[4];
    scale_pts(&x[0][0], &v[0][0], 4, 0, 0x1p30, wx, w);
    check_facet(R, (const double(*)[3])x, wx);
}

/* ---- point sources ------------------------------------------------------ */

static void rand_point(tl_rng *r, double p[3], int lo, int hi)
{
    for (int c = 0; c < 3; c++) p[c] = (double)tl_int(r, lo, hi);
}

/* Uniform random points in [-1, 1]^3, weights of the given kind:
 * 0 zero, 1 in [0, 0.05), 2 in [-0.05, 0.05), 3 in [-1e300, 1e300].    */
static void uniform_set(run *R, int count, int kind)
{
    for (int i = 0; i < count; i++) {
        double v[5][3], w[5];
        for (int k = 0; k < 5; k++) {
            for (int c = 0; c < 3; c++) v[k][c] = 2 * tl_unif(&R->r) - 1;
            w[k] = kind == 0 ? 0 : kind == 1 ? 0.05 * tl_unif(&R->r)
                 : kind == 2 ? 0.1 * tl_unif(&R->r) - 0.05 : (2 * tl_unif(&R->r) - 1) * 1e300;
        }
        check5(R, (const double(*)[3])v, w);
    }
}

/* Grid points of {0..g}^3 with integer weights in [0, wmax]; mode 1: the
 * query at a vertex's position with another weight, mode 2: with the
 * same weight (identical weighted points).                              */
static void grid_set(run *R, int count, int g, int wmax, int mode)
{
    for (int i = 0; i < count; i++) {
        double v[5][3], w[5];
        for (int k = 0; k < 5; k++) {
            int again;
            do {
                rand_point(&R->r, v[k], 0, g);
                again = 0;
                for (int j = 0; j < k; j++) again |= same_point(v[j], v[k]);
            } while (again);
            w[k] = (double)tl_int(&R->r, 0, wmax);
        }
        if (mode) {
            const int j = (int)tl_int(&R->r, 0, 3);
            memcpy(v[4], v[j], sizeof v[4]);
            w[4] = mode == 2 ? w[j] : w[j] + (double)tl_int(&R->r, 1, 3) * (tl_int(&R->r, 0, 1) ? 1 : -1);
        }
        check5_scaled(R, (const double(*)[3])v, w, i % 4 == 0);
    }
}

/* Five integer points whose lifted points lie on the plane h(x) = a.x + b:
 * w = |x|^2 - h(x), so the exact power test is 0.  With jitter, the
 * query's weight is moved by one unit or one ulp: nearly degenerate.    */
static void lifted_plane_set(run *R, int count, int jitter)
{
    for (int i = 0; i < count; i++) {
        double v[5][3], w[5];
        const double a[3] = {(double)tl_int(&R->r, -4, 4), (double)tl_int(&R->r, -4, 4),
                             (double)tl_int(&R->r, -4, 4)};
        const double b = (double)tl_int(&R->r, -20, 20);
        for (int k = 0; k < 5; k++) {
            rand_point(&R->r, v[k], -6, 6);
            w[k] = v[k][0] * v[k][0] + v[k][1] * v[k][1] + v[k][2] * v[k][2] - (a[0] * v[k][0] + a[1] * v[k][1] +
                                                                                 a[2] * v[k][2] + b);
        }
        if (jitter == 1) w[4] += tl_int(&R->r, 0, 1) ? 1 : -1;
        if (jitter == 2) w[4] = nextafter(w[4], tl_int(&R->r, 0, 1) ? INFINITY : -INFINITY);
        if (jitter == 3) v[4][(int)tl_int(&R->r, 0, 2)] += tl_int(&R->r, 0, 1) ? 0x1p-40 : -0x1p-40;
        check5_scaled(R, (const double(*)[3])v, w, i % 4 == 0);
    }
}

/* Integer points of one sphere, every weight wc (zero, or all equal). */
static void sphere_set(run *R, int count, int64_t r2, double wc)
{
    double *pts = malloc(3 * 4000 * sizeof(double));
    int n = tl_sphere_points(r2, pts, 4000);
    if (n > 4000) n = 4000;
    pool pl = {pts, n};
    for (int i = 0; i < count && n >= 5; i++) {
        double v[5][3];
        const double w[5] = {wc, wc, wc, wc, wc};
        tl_pick(&R->r, &pl, 5, v);
        check5_scaled(R, (const double(*)[3])v, w, i % 4 == 0);
    }
    free(pts);
}

/* A point of the integer plane n.x = d (|n| small), coordinates in
 * [-6, 6] for the two free axes.  0 when the third is not an integer.   */
static int plane_point(tl_rng *r, const int n[3], int d, double p[3])
{
    int ax = n[2] ? 2 : n[1] ? 1 : 0;   /* solved axis */
    int s = 0;
    for (int c = 0; c < 3; c++)
        if (c != ax) {
            p[c] = (double)tl_int(r, -6, 6);
            s += n[c] * (int)p[c];
        }
    if ((d - s) % n[ax] != 0) return 0;
    p[ax] = (double)((d - s) / n[ax]);
    return 1;
}

/* Hull facets (a, b, c) of integer planes, queries in the plane (3 out of
 * 4) or off it; weights small integers, or (lifted) on a plane of the
 * lifted space so the coplanar power test is 0.                          */
static void facet_set(run *R, int count)
{
    static const int planes[][4] = {{0, 0, 1, 0}, {0, 1, 0, 2}, {1, 0, 0, -1}, {1, 1, 1, 4},
                                    {2, -1, 3, 1}, {1, 1, 0, 0},  {0, 1, -1, 3}};
    for (int i = 0; i < count; i++) {
        const int *pl = planes[tl_int(&R->r, 0, (int64_t)(sizeof planes / sizeof *planes) - 1)];
        const int n[3] = {pl[0], pl[1], pl[2]};
        double v[4][3], w[4];
        for (int k = 0; k < 4; k++) {
            int again;
            do {
                again = !plane_point(&R->r, n, pl[3], v[k]);
                for (int j = 0; j < k; j++) again |= same_point(v[j], v[k]);
            } while (again);
        }
        if (tl_int(&R->r, 0, 3) == 0) v[3][tl_int(&R->r, 0, 2)] += tl_int(&R->r, 0, 1) ? 1 : -1;
        const int kind = (int)tl_int(&R->r, 0, 3);
        const double a[3] = {(double)tl_int(&R->r, -3, 3), (double)tl_int(&R->r, -3, 3),
                             (double)tl_int(&R->r, -3, 3)};
        const double b = (double)tl_int(&R->r, -9, 9);
        for (int k = 0; k < 4; k++) {
            if (kind == 0) w[k] = 0;
            else if (kind == 1) w[k] = (double)tl_int(&R->r, 0, 3);
            else w[k] = v[k][0] * v[k][0] + v[k][1] * v[k][1] + v[k][2] * v[k][2] -
                        (a[0] * v[k][0] + a[1] * v[k][1] + a[2] * v[k][2] + b);
        }
        if (kind == 3 && tl_int(&R->r, 0, 1)) {   /* the query at a vertex's position */
            const int j = (int)tl_int(&R->r, 0, 2);
            memcpy(v[3], v[j], sizeof v[3]);
            w[3] = w[j] + (double)tl_int(&R->r, -1, 1);
        }
        /* the facet as a hull facet: (a, b, c) and a point beyond */
        check_facet_scaled(R, (const double(*)[3])v, w);
    }
}

/* Extreme magnitudes: random points times 2^e (e = 1000, -1000, or
 * subnormal -1070), weights of several magnitudes, up to +-1e300.       */
static void extreme_set(run *R, int count)
{
    static const int exps[] = {1000, 600, -1000, -1070, 0};
    static const double wmag[] = {0, 1e300, 1e-300, 0x1p-1074, 1};
    for (int i = 0; i < count; i++) {
        const int e = exps[tl_int(&R->r, 0, 4)];
        const double wm = wmag[tl_int(&R->r, 0, 4)];
        double v[5][3], w[5];
        for (int k = 0; k < 5; k++) {
            for (int c = 0; c < 3; c++) v[k][c] = ldexp(2 * tl_unif(&R->r) - 1, e);
            w[k] = wm * (2 * tl_unif(&R->r) - 1);
            if (tl_int(&R->r, 0, 3) == 0) w[k] = wm;   /* equal weights */
        }
        check5(R, (const double(*)[3])v, w);
        /* and a hull facet with a query in its plane: z = const, exactly */
        double f[4][3], fw[4] = {w[0], w[1], w[2], w[3]};
        for (int k = 0; k < 4; k++) {
            memcpy(f[k], v[k], sizeof f[k]);
            f[k][2] = v[0][2];
        }
        check_facet(R, (const double(*)[3])f, fw);
    }
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    const int q = argc > 1 && strcmp(argv[1], "small") == 0 ? 4 : 1;
    static run R;
    dd_pred_init(&R.pr);
    R.r.s = 4343;
    R.sample = 8;

    R.where = "uniform";
    for (int kind = 0; kind < 4; kind++) uniform_set(&R, 20000 / q, kind);
    R.where = "grid";
    grid_set(&R, 8000 / q, 3, 2, 0);
    grid_set(&R, 4000 / q, 2, 1, 0);
    grid_set(&R, 4000 / q, 4, 6, 0);
    R.where = "grid/equal-position";
    grid_set(&R, 2000 / q, 3, 3, 1);
    grid_set(&R, 1000 / q, 3, 3, 2);
    R.where = "lifted-plane";
    for (int j = 0; j < 4; j++) lifted_plane_set(&R, 3000 / q, j);
    R.where = "cosphere";
    static const int64_t radii2[] = {3, 9, 25, 50, 81, 169};
    for (size_t i = 0; i < sizeof radii2 / sizeof *radii2; i++) {
        sphere_set(&R, 600 / q, radii2[i], 0);
        sphere_set(&R, 200 / q, radii2[i], 7);
    }
    R.where = "facet";
    facet_set(&R, 8000 / q);
    R.where = "extreme";
    extreme_set(&R, 8000 / q);

    long total = 0;
    for (int k = 0; k < NT; k++) {
        char name[64];
        snprintf(name, sizeof name, "power/%s", tname[k]);
        total += R.t[k].n;
        tl_check(&st, R.t[k].n > 0 && R.t[k].bad == 0, name, "%ld of %ld differ; first %s", R.t[k].bad, R.t[k].n,
                 R.t[k].first);
        fprintf(stderr, "  %-14s %8ld compared, %ld mismatches\n", tname[k], R.t[k].n, R.t[k].bad);
    }
    fprintf(stderr, "  %ld tuples (%ld exactly degenerate), %ld comparisons; filter sure on %ld; "
            "RT cells skipped %ld finite, %ld infinite\n",
            R.tuples, R.zeros, total, R.filter_sure, R.cell_skipped, R.infcell_skipped);
    tl_check(&st, R.zeros > 1000 / q, "power/degenerate-count", "only %ld exactly degenerate tuples", R.zeros);
    dd_pred_clear(&R.pr);
    return tl_finish(&st);
}
