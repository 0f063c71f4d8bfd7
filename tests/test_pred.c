/*
 * test_pred.c -- our predicates return CGAL's signs (DESIGN 3).
 *
 * Compares every predicate of pred.h with CGAL's (through the shim) on
 * random tuples built to be degenerate -- integer points on spheres and
 * circles, small grids, coplanar and cocircular sets in the three axis
 * planes, hull facets with coplanar query points -- and on random
 * non-degenerate ones, each also translated and scaled by 1e16 and by a
 * tiny factor (1e-200, or 2^-660 where coplanarity must survive).  At least
 * 10^5 degenerate tuples.
 */
#include "testlib.h"
#include "mesh/mesh.h"
#include "cgal/cgal_shim.h"

#include <math.h>

typedef struct tally { long tuples, mismatches; char first[256]; } tally;

static void note(tally *t, int ours, int cgal, const char *what)
{
    t->tuples++;
    if (ours != cgal && t->mismatches++ == 0)
        snprintf(t->first, sizeof t->first, "%s: ours %d, CGAL %d", what, ours, cgal);
}

/* Point sources ----------------------------------------------------------- */



static void transform(double pts[][3], int k, double scale, const double off[3])
{
    for (int i = 0; i < k; i++)
        for (int c = 0; c < 3; c++) pts[i][c] = (pts[i][c] + off[c]) * scale;
}

/* 3D tests on 5 points: orientation, insphere (perturbed and not). */
static void test_3d(dd_pred *pr, tally *t, double q[5][3])
{
    note(t, dd_orient3d(pr, q[0], q[1], q[2], q[3]),
         dd_cgal_orientation(q[0], q[1], q[2], q[3]), "orientation");
    int o = dd_orient3d(pr, q[0], q[1], q[2], q[3]);
    if (o == 0) return;
    if (o < 0) { double s[3]; memcpy(s, q[0], sizeof s); memcpy(q[0], q[1], sizeof s); memcpy(q[1], s, sizeof s); }
    note(t, dd_insphere(pr, q[0], q[1], q[2], q[3], q[4]),
         dd_cgal_side_of_oriented_sphere(q[0], q[1], q[2], q[3], q[4], 0), "insphere");
    note(t, dd_insphere_perturbed(pr, q[0], q[1], q[2], q[3], q[4]),
         dd_cgal_side_of_oriented_sphere(q[0], q[1], q[2], q[3], q[4], 1), "insphere perturbed");
    /* The same tetrahedron as an infinite cell: q[k] plays the infinite
     * vertex, q[4] the query.                                              */
    for (int k = 0; k < 4; k++) {
        const double *v[4] = {q[0], q[1], q[2], q[3]};
        if (dd_orient_coplanar(pr, v[dd_facet[k][0]], v[dd_facet[k][1]], v[dd_facet[k][2]]) == 0) continue;
        note(t, dd_inf_conflict(pr, v, k, q[4]),
             dd_cgal_side_of_sphere_cell(q[0], q[1], q[2], q[3], k, q[4], 1), "infinite cell");
    }
}

/* 2D tests on 4 coplanar points: coplanar orientation, in-circle. */
static void test_2d(dd_pred *pr, tally *t, double q[4][3])
{
    note(t, dd_orient_coplanar(pr, q[0], q[1], q[2]),
         dd_cgal_coplanar_orientation(q[0], q[1], q[2]), "coplanar orientation");
    if (dd_orient_coplanar(pr, q[0], q[1], q[2]) == 0) return;
    note(t, dd_incircle_coplanar(pr, q[0], q[1], q[2], q[3]),
         dd_cgal_coplanar_side_of_bounded_circle(q[0], q[1], q[2], q[3], 0), "in-circle");
    note(t, dd_incircle_coplanar_perturbed(pr, q[0], q[1], q[2], q[3]),
         dd_cgal_coplanar_side_of_bounded_circle(q[0], q[1], q[2], q[3], 1), "in-circle perturbed");
}

/* 3D tuples are also scaled by 1e-200 (rounded: nearly degenerate); 2D ones
 * by 2^-660 only, an exact scaling, so coplanar sets stay coplanar (CGAL's
 * coplanar predicates require it).                                       */
static const double scales[3] = {1.0, 1e16, 1e-200};
static const double scales2d[3] = {1.0, 1e16, 0x1p-660};

static void run_3d(tl_state *st, dd_pred *pr, tl_rng *r, const char *name, const pool *pl, int rounds, long *degenerate)
{
    tally t = {0, 0, ""};
    for (int it = 0; it < rounds; it++) {
        double q[5][3];
        tl_pick(r, pl, 5, q);
        double off[3] = {(double)tl_int(r, -3, 3), (double)tl_int(r, -3, 3), (double)tl_int(r, -3, 3)};
        transform(q, 5, scales[it % 3], off);
        test_3d(pr, &t, q);
    }
    if (degenerate) *degenerate += t.tuples;
    tl_check(st, t.mismatches == 0 && t.tuples > rounds, name, "%ld of %ld differ from CGAL; first: %s",
             t.mismatches, t.tuples, t.first);
}

static void run_2d(tl_state *st, dd_pred *pr, tl_rng *r, const char *name, const pool *pl, int rounds, long *degenerate)
{
    tally t = {0, 0, ""};
    for (int it = 0; it < rounds; it++) {
        double q[4][3];
        tl_pick(r, pl, 4, q);
        double off[3] = {(double)tl_int(r, -3, 3), (double)tl_int(r, -3, 3), (double)tl_int(r, -3, 3)};
        transform(q, 4, scales2d[it % 3], off);
        test_2d(pr, &t, q);
    }
    if (degenerate) *degenerate += t.tuples;
    tl_check(st, t.mismatches == 0 && t.tuples > rounds, name, "%ld of %ld differ from CGAL; first: %s",
             t.mismatches, t.tuples, t.first);
}

/* Integer points of a circle of radius^2 r2 in the plane axis = level. */
static pool circle_pool(int64_t r2, int axis, double level)
{
    pool pl = {malloc(3 * 4096 * sizeof(double)), 0};
    for (int64_t a = -2000; a <= 2000 && pl.n < 4096; a++) {
        int64_t b2 = r2 - a * a;
        if (b2 < 0) continue;
        int64_t b = (int64_t)llround(sqrt((double)b2));
        if (b * b != b2) continue;
        for (int s = -1; s <= 1; s += 2) {
            if (b == 0 && s > 0) continue;
            double *p = pl.p + 3 * pl.n++;
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            p[axis] = level; p[u] = (double)a; p[v] = (double)(s * b);
        }
    }
    return pl;
}

static pool grid_pool(int k, int flat_axis)
{
    pool pl = {malloc(3 * (size_t)(k * k * k) * sizeof(double)), 0};
    for (int x = 0; x < k; x++)
        for (int y = 0; y < k; y++)
            for (int z = 0; z < k; z++) {
                int c[3] = {x, y, z};
                if (flat_axis >= 0 && c[flat_axis] != 0) continue;
                double *p = pl.p + 3 * pl.n++;
                p[0] = x; p[1] = y; p[2] = z;
            }
    return pl;
}

int main(void)
{
    tl_state st = {0, 0};
    dd_pred pr;
    dd_pred_init(&pr);
    tl_rng r = {12345};
    long degenerate = 0;

    /* Cospherical: integer points on spheres of several radii. */
    static const int64_t radii2[] = {3, 9, 25, 50, 75, 81, 121, 169, 338, 3000};
    for (size_t i = 0; i < sizeof radii2 / sizeof *radii2; i++) {
        pool pl = {malloc(3 * 20000 * sizeof(double)), 0};
        pl.n = tl_sphere_points(radii2[i], pl.p, 20000);
        char name[64];
        snprintf(name, sizeof name, "pred/cosphere-r2=%lld", (long long)radii2[i]);
        if (pl.n >= 8) run_3d(&st, &pr, &r, name, &pl, 4000, &degenerate);
        free(pl.p);
    }
    /* Small grids: coplanar, cospherical and collinear tuples everywhere. */
    for (int k = 2; k <= 5; k++) {
        pool pl = grid_pool(k, -1);
        char name[64];
        snprintf(name, sizeof name, "pred/grid-%d", k);
        run_3d(&st, &pr, &r, name, &pl, 8000, &degenerate);
        free(pl.p);
    }
    /* Coplanar grids in each axis plane (exercises the xy, yz, xz cases). */
    for (int axis = 0; axis < 3; axis++) {
        pool pl = grid_pool(5, axis);
        char name[64];
        snprintf(name, sizeof name, "pred/coplanar-grid-axis%d", axis);
        run_2d(&st, &pr, &r, name, &pl, 8000, &degenerate);
        free(pl.p);
    }
    /* Cocircular: integer points on circles in each axis plane. */
    static const int64_t cr2[] = {25, 65, 325, 1105};
    for (int axis = 0; axis < 3; axis++)
        for (size_t i = 0; i < sizeof cr2 / sizeof *cr2; i++) {
            pool pl = circle_pool(cr2[i], axis, (double)(axis + 1));
            char name[64];
            snprintf(name, sizeof name, "pred/cocircle-r2=%lld-axis%d", (long long)cr2[i], axis);
            run_2d(&st, &pr, &r, name, &pl, 3000, &degenerate);
            free(pl.p);
        }
    /* Non-degenerate: uniform random doubles. */
    {
        pool pl = {malloc(3 * 5000 * sizeof(double)), 5000};
        for (int i = 0; i < 3 * 5000; i++) pl.p[i] = tl_unif(&r);
        run_3d(&st, &pr, &r, "pred/uniform", &pl, 20000, NULL);
        free(pl.p);
        /* random points of one axis plane: coplanar, in general position */
        for (int axis = 0; axis < 3; axis++) {
            pool pl2 = {malloc(3 * 2000 * sizeof(double)), 2000};
            for (int i = 0; i < 2000; i++)
                for (int c = 0; c < 3; c++) pl2.p[3 * i + c] = c == axis ? 0.5 : tl_unif(&r);
            char name[64];
            snprintf(name, sizeof name, "pred/uniform-plane-axis%d", axis);
            run_2d(&st, &pr, &r, name, &pl2, 3000, NULL);
            free(pl2.p);
        }
    }
    tl_check(&st, degenerate >= 100000, "pred/at-least-1e5-degenerate-tuples",
             "only %ld degenerate tuples compared", degenerate);
    printf("# %ld degenerate tuples compared with CGAL\n", degenerate);
    dd_pred_clear(&pr);
    return tl_finish(&st);
}
