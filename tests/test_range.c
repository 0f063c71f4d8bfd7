/*
 * test_range.c -- the whole finite double range (DESIGN 13): every public
 * call on point sets at the edges of the doubles gives CGAL's answer.
 *
 * Sets: uniform points times 1e300, 1e-300, 1e155 (the scale whose squares
 * just overflow) and 1e-155; subnormal coordinates (integers times
 * 2^-1074, a degenerate grid among them); mixed magnitudes (1e-300 and
 * 1e300 in one set, and 1e-300, 1, 1e300); spans near DBL_MAX (the
 * coordinate differences overflow), a degenerate grid of 2^1022 steps
 * among them; cospherical integer points times 2^1000 and 2^-1070; -0.0
 * beside +0.0 (one point for both); the five-point set of issue 41; and
 * coordinates drawn from whole finite bit patterns.  On each:
 *  - dd_create equals CGAL's triangulation and dd_check passes; dd_cells
 *    is symmetric and its finite cells positive (CGAL's orientation);
 *    dd_neighbors, dd_degree, dd_incident_cells and dd_local_canonical
 *    agree with the canonical form / CGAL's local one;
 *  - dd_delete_with, every strategy of the registry, equals CGAL's
 *    remove(), and dd_reinsert restores the triangulation;
 *  - dd_delete_set (each course in test builds) equals CGAL's
 *    triangulation of the points left;
 *  - at extreme query points (the set's own and absolute ones: 1e300,
 *    1e155, DBL_MAX, subnormals, -0.0, whole bit patterns), dd_locate's
 *    cell holds the point (CGAL's orientations), dd_nearest_vertex is as
 *    near as every vertex and as CGAL's nearest_vertex (exact rationals),
 *    dd_insert equals CGAL's insert (status and cells) and dd_move equals
 *    CGAL's move_if_no_collision; both undone after.
 * The same queries, insertions and moves run on ordinary triangulations
 * (a unit cube, an integer grid).
 */
#include "testlib.h"
#include "testcgal.h"
#include <float.h>
#include <gmp.h>
#include <math.h>
#include "dtdel.h"
#include "geom/pred.h"
#include "cgal/cgal_query.h"
#include "cgal/cgal_shim.h"
#include "../datasets/datasets.h"

static int small;

/* ---- comparisons ------------------------------------------------------- */

static int same_canon(const int32_t *a, size_t na, const int32_t *b, size_t nb)
{
    return a && b && na == nb && !memcmp(a, b, 4 * na * sizeof *a);
}

/* dd_canonical(t) equals CGAL's canonical form of g. */
static int same_as(dd_tri *t, const dd_cgal *g)
{
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    int ok = dd_canonical(t, &a, &na) == DD_OK && !dd_cgal_canonical(g, &b, &nb) && same_canon(a, na, b, nb);
    free(a), free(b);
    return ok;
}

/* ---- the predicates at the ends of the range ----------------------------- */

/* A double m * 2^e with a random 53-bit m, or 0 (one in eight). */
static double coord_at(tl_rng *r, int e)
{
    if (tl_next(r) % 8 == 0) return 0.0;
    double m = (double)(tl_next(r) >> 11) * 0x1p-53 + 0.5;
    return ldexp(tl_next(r) & 1 ? -m : m, e);
}

typedef struct ptally { long tuples, bad; char first[200]; } ptally;

static void pnote(ptally *t, int ours, int ref, const char *what, int e)
{
    t->tuples++;
    if (ours != ref && t->bad++ == 0) snprintf(t->first, sizeof t->first, "%s (exponent %d): ours %d, exact %d", what, e, ours, ref);
}

/* Orientation, in-sphere (plain and perturbed), the infinite cell and
 * compare_distance on five points against CGAL's predicates and exact
 * rationals.                                                           */
static void pred_tuple(dd_pred *pr, ptally *t, double q[5][3], int e)
{
    for (int i = 0; i < 5; i++)                   /* the perturbation wants five distinct points */
        for (int j = 0; j < i; j++)
            if (q[i][0] == q[j][0] && q[i][1] == q[j][1] && q[i][2] == q[j][2]) return;
    int o = dd_orient3d(pr, q[0], q[1], q[2], q[3]);
    pnote(t, o, dd_cgal_orientation(q[0], q[1], q[2], q[3]), "orientation", e);
    pnote(t, dd_compare_distance(pr, q[4], q[0], q[1]), tl_cmp_dist_exact(q[4], q[0], q[1]), "compare_distance", e);
    if (o == 0) return;
    if (o < 0) {
        double x[3];
        memcpy(x, q[0], sizeof x), memcpy(q[0], q[1], sizeof x), memcpy(q[1], x, sizeof x);
    }
    pnote(t, dd_insphere(pr, q[0], q[1], q[2], q[3], q[4]), dd_cgal_side_of_oriented_sphere(q[0], q[1], q[2], q[3], q[4], 0),
          "insphere", e);
    pnote(t, dd_insphere_perturbed(pr, q[0], q[1], q[2], q[3], q[4]),
          dd_cgal_side_of_oriented_sphere(q[0], q[1], q[2], q[3], q[4], 1), "insphere perturbed", e);
    const double *v[4] = {q[0], q[1], q[2], q[3]};
    pnote(t, dd_inf_conflict(pr, v, 3, q[4]), dd_cgal_side_of_sphere_cell(q[0], q[1], q[2], q[3], 3, q[4], 1),
          "infinite cell", e);
}

/* Tuples at every scale from 2^-1074 to 2^1020: each coordinate's exponent
 * drawn within a window of w above the scale (w about the exact stages'
 * ranges, 2 x 140 and 2 x 260, on either side, where rescaling stops and
 * GMP takes over; and the whole range), and cospherical integer points
 * times 2^e (exactly: their in-sphere determinants are 0).              */
static void check_predicates(tl_state *st)
{
    dd_pred pr;
    dd_pred_init(&pr);
    tl_rng r = {4711};
    static const int windows[] = {0, 52, 278, 282, 518, 522, 800, 2090};
    const int rounds = small ? 3 : 12;
    for (size_t wi = 0; wi < sizeof windows / sizeof *windows; wi++) {
        ptally t = {0, 0, ""};
        for (int e = -1074; e <= 1020; e += 7)
            for (int it = 0; it < rounds; it++) {
                double q[5][3];
                const int w = windows[wi], lo = e - w / 2 < -1074 ? -1074 : e - w / 2, hi = lo + w > 1020 ? 1020 : lo + w;
                for (int i = 0; i < 5; i++)
                    for (int c = 0; c < 3; c++) q[i][c] = coord_at(&r, (int)tl_int(&r, lo, hi));
                pred_tuple(&pr, &t, q, e);
            }
        char tn[64];
        snprintf(tn, sizeof tn, "range/pred/window-2^%d", windows[wi]);
        tl_check(st, t.bad == 0, tn, "%ld of %ld differ; first: %s", t.bad, t.tuples, t.first);
    }
    double sph[3 * 64];
    const int ns = tl_sphere_points(50, sph, 64);
    ptally t = {0, 0, ""};
    for (int e = -1074; e <= 1016; e += 3)
        for (int it = 0; it < rounds; it++) {
            double q[5][3];
            for (int i = 0; i < 5; i++)
                for (int c = 0; c < 3; c++) q[i][c] = ldexp(sph[3 * tl_int(&r, 0, ns - 1) + c], e);
            pred_tuple(&pr, &t, q, e);
        }
    tl_check(st, t.bad == 0, "range/pred/cosphere-times-2^e", "%ld of %ld differ; first: %s", t.bad, t.tuples, t.first);
    dd_pred_clear(&pr);
}

/* ---- the sets ------------------------------------------------------------ */

typedef struct rset {
    char name[48];
    double *p;
    uint32_t n;
} rset;

static rset new_set(const char *name, uint32_t n)
{
    rset s;
    snprintf(s.name, sizeof s.name, "%s", name);
    s.p = malloc(3 * (size_t)(n ? n : 1) * sizeof *s.p);
    s.n = n;
    return s;
}

/* A finite double from a whole random bit pattern. */
static double any_double(tl_rng *r)
{
    for (;;) {
        uint64_t b = tl_next(r);
        double x;
        memcpy(&x, &b, sizeof x);
        if (isfinite(x)) return x;
    }
}

/* n points uniform in [-f/2, f/2)^3. */
static rset scaled(const char *name, uint32_t n, double f, uint64_t seed)
{
    rset s = new_set(name, n);
    tl_rng r = {seed};
    for (size_t i = 0; i < 3 * (size_t)n; i++) s.p[i] = (2 * tl_unif(&r) - 1) * (0.5 * f);
    return s;
}

/* Integer points times 2^e: uniform in [-k, k]^3 (k > 0), or the grid
 * {0..-k}^3 (k < 0, all of it).                                          */
static rset ints_times(const char *name, int64_t k, uint32_t n, int e, uint64_t seed)
{
    tl_rng r = {seed};
    if (k < 0) n = (uint32_t)((1 - k) * (1 - k) * (1 - k));
    rset s = new_set(name, n);
    for (uint32_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            int64_t v = k > 0 ? tl_int(&r, -k, k) : (int64_t)(c == 0 ? i % (uint32_t)(1 - k) : c == 1 ? i / (uint32_t)(1 - k) % (uint32_t)(1 - k) : i / (uint32_t)((1 - k) * (1 - k)));
            s.p[3 * i + c] = ldexp((double)v, e);
        }
    return s;
}

/* Half the points times a, half times b (a third times 1 when mid). */
static rset mixed(const char *name, uint32_t n, double a, double b, int mid, uint64_t seed)
{
    rset s = scaled(name, n, 1.0, seed);
    for (uint32_t i = 0; i < n; i++) {
        double f = mid && i % 3 == 2 ? 1.0 : i % (mid ? 3u : 2u) == 0 ? a : b;
        for (int c = 0; c < 3; c++) s.p[3 * i + c] *= f;
    }
    return s;
}

/* Cospherical integer points times 2^e. */
static rset sphere_times(const char *name, int64_t r2, int e)
{
    double buf[3 * 512];
    int n = tl_sphere_points(r2, buf, 512);
    rset s = new_set(name, (uint32_t)n);
    for (int i = 0; i < 3 * n; i++) s.p[i] = ldexp(buf[i], e);
    return s;
}

static rset make_set(int k, uint32_t n)
{
    tl_rng r = {1000 + (uint64_t)k};
    switch (k) {
    case 0: return scaled("x1e300", n, 1e300, 1);
    case 1: return scaled("x1e-300", n, 1e-300, 2);
    case 2: return scaled("x1e155", n, 1e155, 3);
    case 3: return scaled("x1e-155", n, 1e-155, 4);
    case 4: return ints_times("subnormal", 1 << 20, n, -1074, 5);
    case 5: return ints_times("subnormal-grid", -4, 0, -1074, 6);
    case 6: return ints_times("subnormal-wide", (int64_t)1 << 51, n, -1074, 7);
    case 7: return mixed("mixed-1e-300-1e300", n, 1e-300, 1e300, 0, 8);
    case 8: return mixed("mixed-three", n, 1e-300, 1e300, 1, 9);
    case 9: {                     /* [-DBL_MAX, DBL_MAX)^3: differences overflow */
        rset s = scaled("span-max", n, 2.0, 10);
        for (size_t i = 0; i < 3 * (size_t)n; i++) s.p[i] *= DBL_MAX;
        return s;
    }
    case 10: {                    /* the grid {-2..2}^3 times 2^1022: its differences reach 2^1024 */
        rset s = ints_times("grid-x2^1022", -4, 0, 0, 11);
        for (uint32_t i = 0; i < 3 * s.n; i++) s.p[i] = ldexp(s.p[i] - 2, 1022);
        return s;
    }
    case 11: return sphere_times("cosphere-x2^1000", 54, 1000);
    case 12: return sphere_times("cosphere-x2^-1070", 54, -1070);
    case 13: {                    /* {-1, 0, 1}^3 with zeros of both signs, each point twice */
        rset s = new_set("minus-zero", 54);
        for (uint32_t i = 0; i < 54; i++)
            for (int c = 0; c < 3; c++) {
                uint32_t j = i % 27, d = c == 0 ? j % 3 : c == 1 ? j / 3 % 3 : j / 9;
                double x = (double)d - 1.0;
                s.p[3 * i + c] = x == 0 && (tl_next(&r) & 1) ? -0.0 : x;
            }
        return s;
    }
    case 14: {
        rset s = new_set("five", 5);
        const double f[15] = {0, 0, 0, 1e300, 0, 0, 0, 1e300, 0, 0, 0, 1e300, -1e300, -1e300, -1e300};
        memcpy(s.p, f, sizeof f);
        return s;
    }
    case 15: {
        rset s = new_set("bits", n);
        for (size_t i = 0; i < 3 * (size_t)n; i++) s.p[i] = any_double(&r);
        return s;
    }
    case 16: {                    /* whole bit patterns of two decades' exponents: 1e±300 and 1 */
        rset s = new_set("bits-clustered", n);
        for (size_t i = 0; i < 3 * (size_t)n; i++) {
            int e = (int)(i / 3 % 3) == 0 ? -1000 : i / 3 % 3 == 1 ? 0 : 996;
            s.p[i] = ldexp(tl_unif(&r) - 0.5, e + (int)tl_int(&r, -4, 4));
        }
        return s;
    }
    case 17: return scaled("unit", n, 1.0, 12);
    case 18: return ints_times("grid", -5, 0, 0, 13);
    default: return new_set("", 0);
    }
}
#define NUM_SETS 19
#define FIRST_ORDINARY 17

/* ---- query points -------------------------------------------------------- */

/* The queries for set s: absolute extremes, points of the set (vertices,
 * midpoints), and random points in and beyond its box.  Returns how many. */
static uint32_t queries(const rset *s, double (*q)[3], uint32_t max, uint64_t seed)
{
    static const double fixed[][3] = {
        {1e300, 0, 0}, {0, 1e300, 0}, {-1e300, -1e300, 1e300}, {1e155, 0, 0}, {0, 0, -1e156},
        {1e200, 0, 0}, {DBL_MAX, DBL_MAX, DBL_MAX}, {-DBL_MAX, DBL_MAX, -DBL_MAX}, {DBL_MAX, 0, 0},
        {4.9e-324, 0, 0}, {-4.9e-324, 4.9e-324, -0.0}, {-0.0, -0.0, -0.0}, {1e-300, 1e-300, 1e-300},
        {DBL_MIN, -DBL_MIN, DBL_MIN}, {0.5, 0.5, 0.5}, {1e-155, 1e155, -1e300}, {0.25, 1e-310, 0.75},
        {-1e300, 1e-300, 4.9e-324}, {1e308, -1e308, 1e308}};
    uint32_t k = 0;
    for (size_t i = 0; i < sizeof fixed / sizeof *fixed && k < max; i++) memcpy(q[k++], fixed[i], sizeof q[0]);
    tl_rng r = {seed};
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t i = 0; i < s->n; i++)
        for (int c = 0; c < 3; c++) lo[c] = fmin(lo[c], s->p[3 * i + c]), hi[c] = fmax(hi[c], s->p[3 * i + c]);
    for (int j = 0; j < 4 && k < max; j++) q[k][0] = any_double(&r), q[k][1] = any_double(&r), q[k++][2] = any_double(&r);
    for (int j = 0; j < 14 && k < max; j++) {
        const double *a = s->p + 3 * (size_t)tl_int(&r, 0, s->n - 1), *b = s->p + 3 * (size_t)tl_int(&r, 0, s->n - 1);
        for (int c = 0; c < 3; c++) {
            double u = tl_unif(&r), half = 0.5 * hi[c] - 0.5 * lo[c], mid = 0.5 * hi[c] + 0.5 * lo[c];
            switch (j % 5) {
            case 0: q[k][c] = a[c]; break;                                  /* a vertex's point */
            case 1: q[k][c] = 0.5 * a[c] + 0.5 * b[c]; break;               /* an edge's midpoint */
            case 2: q[k][c] = mid + (2 * u - 1) * half; break;              /* in the box */
            case 3: q[k][c] = mid + (4 * u - 2) * half; break;              /* around the box */
            default: q[k][c] = c == 0 ? a[c] : c == 1 ? b[c] : mid; break; /* mixed coordinates */
            }
            if (!isfinite(q[k][c])) q[k][c] = a[c];
        }
        k++;
    }
    return k;
}

/* ---- the checks ---------------------------------------------------------- */

/* dd_cells symmetric and positive; the star queries against the canonical
 * form; dd_local_canonical against CGAL's.                               */
static void check_reads(tl_state *st, const rset *s, dd_tri *t, const dd_cgal *g)
{
    char tn[128];
    int32_t *v = NULL, *nb = NULL, *canon = NULL;
    size_t nc = 0, ncanon = 0;
    long asym = 0, negative = 0, bad_star = 0, bad_local = 0;
    if (dd_cells(t, &v, &nb, &nc) != DD_OK || dd_canonical(t, &canon, &ncanon) != DD_OK) {
        snprintf(tn, sizeof tn, "range/%s/reads", s->name);
        tl_check(st, 0, tn, "dd_cells or dd_canonical failed");
        return;
    }
    for (size_t c = 0; c < nc; c++) {
        int finite = 1;
        for (int i = 0; i < 4; i++) {
            const int32_t d = nb[4 * c + i];
            int back = 0;
            for (int j = 0; j < 4 && d >= 0 && (size_t)d < nc; j++) back |= nb[4 * d + j] == (int32_t)c;
            asym += !back;
            finite &= v[4 * c + i] >= 0;
        }
        if (finite) {
            const double *q[4];
            for (int i = 0; i < 4; i++) q[i] = s->p + 3 * (size_t)v[4 * c + i];
            negative += dd_cgal_orientation(q[0], q[1], q[2], q[3]) <= 0;
        }
    }
    uint32_t *nbr = malloc((size_t)(s->n + 1) * sizeof *nbr);
    int32_t (*inc)[4] = malloc(nc * sizeof *inc);
    for (uint32_t w = 0; w < s->n; w++) {
        if (!dd_is_vertex(t, w)) continue;
        /* from the canonical form: cells and distinct neighbours of w */
        uint32_t cells = 0, deg = 0;
        uint8_t *seen = calloc(s->n + 1, 1);
        for (size_t c = 0; c < ncanon; c++) {
            int has = 0;
            for (int i = 0; i < 4; i++) has |= canon[4 * c + i] == (int32_t)w;
            if (!has) continue;
            cells++;
            for (int i = 0; i < 4; i++) {
                int32_t x = canon[4 * c + i];
                uint32_t slot = x < 0 ? s->n : (uint32_t)x;
                if (x != (int32_t)w && !seen[slot]) seen[slot] = 1, deg++;
            }
        }
        uint32_t kn = dd_neighbors(t, w, nbr, s->n + 1), ki = dd_incident_cells(t, w, inc, (uint32_t)nc);
        int ok = kn == deg - seen[s->n] && ki == cells && dd_degree(t, w) == deg && dd_on_hull(t, w) == seen[s->n];
        for (uint32_t j = 0; j < kn && j < s->n && ok; j++) ok = nbr[j] < s->n && seen[nbr[j]];
        bad_star += !ok;
        free(seen);
    }
    for (uint32_t w = 0; w + 2 < s->n && w < 12; w++) {
        uint32_t vs[3] = {w, w + 1, w + 2};
        int32_t *a = NULL, *b = NULL;
        size_t na = 0, nbb = 0;
        if (!dd_is_vertex(t, w) || !dd_is_vertex(t, w + 1) || !dd_is_vertex(t, w + 2)) continue;
        bad_local += dd_local_canonical(t, vs, 3, &a, &na) != DD_OK || dd_cgal_local_canonical(g, vs, 3, &b, &nbb) ||
                     !same_canon(a, na, b, nbb);
        free(a), free(b);
    }
    snprintf(tn, sizeof tn, "range/%s/reads", s->name);
    tl_check(st, !asym && !negative && !bad_star && !bad_local, tn,
             "%ld facets without their partner, %ld cells not positive, %ld stars and %ld local forms wrong", asym,
             negative, bad_star, bad_local);
    free(nbr), free(inc), free(v), free(nb), free(canon);
}

/* Every strategy deletes a few vertices; each result equals CGAL's remove()
 * and dd_reinsert restores the triangulation.                            */
static void check_deletions(tl_state *st, const rset *s, dd_tri *t, dd_cgal *g)
{
    char tn[128], why[256] = "";
    long bad = 0, done = 0;
    const uint32_t k = small ? 2 : 5;
    tl_rng r = {s->n * 7 + 1};
    tl_courses courses = tl_courses_all();
    for (uint32_t j = 0; j < k && !bad; j++) {
        uint32_t v = (uint32_t)tl_int(&r, 0, s->n - 1);
        if (!dd_is_vertex(t, v)) continue;
        if (dd_cgal_remove(g, v)) {
            snprintf(why, sizeof why, "CGAL cannot remove %u", v);
            bad++;
            break;
        }
        for (size_t i = 0; dd_variant_name(i) && !bad; i++) {
            if (small && (i + j) % 3) continue;
            const char *var = dd_variant_name(i);
            tl_course_next(&courses, t);
            dd_status ds = dd_delete_with(t, v, var);
            if (ds == DD_ERR_DIMENSION && s->n <= 5) continue;
            int same = ds == DD_OK && same_as(t, g);
            dd_status rs = ds == DD_OK ? dd_reinsert(t, v) : DD_OK;
            if (!same || rs != DD_OK || dd_check(t) != DD_OK) {
                snprintf(why, sizeof why, "%s deleting %u: status %s (%s), equal to CGAL %d, reinsert %s", var, v,
                         dd_status_name(ds), dd_errmsg(t), same, dd_status_name(rs));
                bad++;
            }
            done++;
        }
        dd_cgal_reinsert(g, v);
        if (!bad && !same_as(t, g)) {
            snprintf(why, sizeof why, "after re-inserting %u: differs from CGAL", v);
            bad++;
        }
    }
    snprintf(tn, sizeof tn, "range/%s/delete", s->name);
    tl_check(st, !bad, tn, "%s (%ld deletions)", why, done);
}

/* A set of about 40% of the vertices (not vertex `keep`), deleted by each
 * course, against CGAL's DT of the points left (the deleted ones made
 * copies of `keep`, which CGAL merges).                                  */
static void check_delete_set(tl_state *st, const rset *s)
{
    char tn[128], msg[256];
    if (s->n < 12) return;
    for (int course = 0; course <= 2; course++) {
#ifndef DD_TEST_BUILD
        if (course) continue;
#endif
        dd_tri *t;
        if (dd_create(&t, s->p, s->n, msg, sizeof msg) != DD_OK) return;
#ifdef DD_TEST_BUILD
        dd_test_control(t, DD_TEST_SET_COURSE, course);
#endif
        uint32_t keep = 0, *vs = malloc((size_t)s->n * sizeof *vs), k = 0;
        while (!dd_is_vertex(t, keep)) keep++;
        tl_rng r = {s->n + (uint64_t)course};
        for (uint32_t i = 0; i < s->n; i++)
            if (i != keep && dd_is_vertex(t, i) && tl_unif(&r) < 0.4) vs[k++] = i;
        dd_status ds = dd_delete_set(t, vs, k);
        double *left = malloc(3 * (size_t)s->n * sizeof *left);
        memcpy(left, s->p, 3 * (size_t)s->n * sizeof *left);
        uint8_t *gone = calloc(s->n, 1);
        for (uint32_t j = 0; j < k; j++) gone[vs[j]] = 1;
        for (uint32_t i = 0; i < s->n; i++)   /* duplicates of a deleted point go too */
            if (gone[dd_alias(t, i)]) memcpy(left + 3 * (size_t)i, s->p + 3 * (size_t)keep, 3 * sizeof *left);
        free(gone);
        dd_cgal *g = dd_cgal_build(left, s->n);
        int ok = g && ds == DD_OK && dd_check(t) == DD_OK && same_as(t, g);
        snprintf(tn, sizeof tn, "range/%s/delete-set/%s", s->name,
                 course == 0 ? "cheaper" : course == 1 ? "one-by-one" : "rebuild");
        tl_check(st, ok, tn, "status %s (%s), %u of %u deleted", dd_status_name(ds), dd_errmsg(t), k, s->n);
        dd_cgal_free(g);
        free(vs), free(left);
        dd_free(t);
    }
}

/* Location and nearest vertex at every query point. */
static void check_queries(tl_state *st, const rset *s, dd_tri *t, double (*q)[3], uint32_t nq)
{
    char tn[128], why[256] = "";
    dd_cgalq *cq = dd_cgalq_build(s->p, s->n, 0);
    long bad_loc = 0, bad_near = 0;
    for (uint32_t k = 0; k < nq; k++) {
        int32_t cell[4];
        dd_status ls = dd_locate(t, q[k], cell);
        if (ls != DD_OK || !tl_holds(t, cell, q[k])) {
            if (!bad_loc++)
                snprintf(why, sizeof why, "locate (%g, %g, %g): %s", q[k][0], q[k][1], q[k][2], dd_status_name(ls));
        }
        uint32_t v = UINT32_MAX;
        double a[3];
        int ok = dd_nearest_vertex(t, q[k], &v) == DD_OK && dd_point(t, v, a) == DD_OK;
        for (uint32_t w = 0; w < s->n && ok; w++)
            if (dd_is_vertex(t, w)) ok = tl_cmp_dist_exact(q[k], a, s->p + 3 * (size_t)w) <= 0;
        int64_t c = cq ? dd_cgalq_nearest(cq, q[k]) : -1;
        ok = ok && c >= 0 && c < s->n && tl_cmp_dist_exact(q[k], a, s->p + 3 * c) == 0;
        if (!ok && !bad_near++)
            snprintf(why, sizeof why, "nearest (%g, %g, %g): %u, CGAL's %lld", q[k][0], q[k][1], q[k][2], v,
                     (long long)c);
    }
    snprintf(tn, sizeof tn, "range/%s/locate-nearest", s->name);
    tl_check(st, !bad_loc && !bad_near, tn, "%ld of %u located cells do not hold their point, %ld nearest wrong; %s",
             bad_loc, nq, bad_near, why);
    dd_cgalq_free(cq);
}

/* dd_insert of each query point against CGAL's insert, then removed again
 * from both.                                                             */
static void check_inserts(tl_state *st, const rset *s, dd_tri *t, dd_cgal *g, double (*q)[3], uint32_t nq)
{
    char tn[128], why[256] = "";
    long bad = 0;
    for (uint32_t k = 0; k < nq && !bad; k++) {
        uint32_t idx = UINT32_MAX;
        dd_status is = dd_insert(t, q[k], &idx);
        int cs = is == DD_OK ? dd_cgal_insert(g, q[k], idx) : dd_cgal_insert(g, q[k], dd_num_input(t));
        int ok = (is == DD_OK && cs == 0) || (is == DD_ERR_DUPLICATE && cs == 2);
        ok = ok && same_as(t, g) && dd_check(t) == DD_OK;
        if (ok && is == DD_OK) {
            dd_status ds = dd_delete(t, idx);
            ok = ds == DD_OK && !dd_cgal_remove(g, idx) && same_as(t, g);
        }
        if (!ok) {
            snprintf(why, sizeof why, "insert (%g, %g, %g): status %s (%s), CGAL %d", q[k][0], q[k][1], q[k][2],
                     dd_status_name(is), dd_errmsg(t), cs);
            bad++;
        }
    }
    snprintf(tn, sizeof tn, "range/%s/insert", s->name);
    tl_check(st, !bad, tn, "%s", why);
}

/* dd_move of a few vertices to query points against CGAL's move, then
 * moved back in both.                                                    */
static void check_moves(tl_state *st, const rset *s, dd_tri *t, dd_cgal *g, double (*q)[3], uint32_t nq)
{
    char tn[128], why[256] = "";
    long bad = 0, moved = 0;
    tl_rng r = {s->n * 13 + 5};
    for (uint32_t k = 0; k < nq && !bad; k++) {
        if (small && k % 2) continue;
        uint32_t v = (uint32_t)tl_int(&r, 0, s->n - 1);
        if (!dd_is_vertex(t, v)) continue;
        double old[3];
        dd_point(t, v, old);
        dd_status ms = dd_move(t, v, q[k]);
        int cs = dd_cgal_move(g, v, q[k]);
        int ok = (ms == DD_OK && cs == 0) || (ms == DD_ERR_DUPLICATE && cs == 2) ||
                 (ms == DD_ERR_DIMENSION && cs == 3);
        ok = ok && same_as(t, g) && dd_check(t) == DD_OK;
        if (ok && ms == DD_OK) {
            moved++;
            dd_status bs = dd_move(t, v, old);
            ok = bs == DD_OK && !dd_cgal_move(g, v, old) && same_as(t, g);
        }
        if (!ok) {
            snprintf(why, sizeof why, "move %u to (%g, %g, %g): status %s (%s), CGAL %d", v, q[k][0], q[k][1],
                     q[k][2], dd_status_name(ms), dd_errmsg(t), cs);
            bad++;
        }
    }
    snprintf(tn, sizeof tn, "range/%s/move", s->name);
    tl_check(st, !bad, tn, "%s (%ld moved)", why, moved);
}

static void check_set(tl_state *st, const rset *s, int ordinary)
{
    char tn[128], msg[256];
    dd_tri *t;
    dd_status cs = dd_create(&t, s->p, s->n, msg, sizeof msg);
    dd_cgal *g = dd_cgal_build(s->p, s->n);
    snprintf(tn, sizeof tn, "range/%s/create", s->name);
    int ok = cs == DD_OK && g && same_as(t, g) && dd_check(t) == DD_OK;
    tl_check(st, ok, tn, "status %s (%s), CGAL %s", dd_status_name(cs), cs == DD_OK ? dd_errmsg(t) : msg,
             g ? "built" : "refused");
    if (!ok) {
        if (cs == DD_OK) dd_free(t);
        dd_cgal_free(g);
        return;
    }
    double q[64][3];
    uint32_t nq = queries(s, q, 64, s->n + 99);
    if (!ordinary) {
        check_reads(st, s, t, g);
        check_deletions(st, s, t, g);
        check_delete_set(st, s);
    }
    check_queries(st, s, t, q, nq);
    check_inserts(st, s, t, g, q, nq);
    check_moves(st, s, t, g, q, nq);
    dd_cgal_free(g);
    dd_free(t);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    small = argc > 1 && !strcmp(argv[1], "small");
    const uint32_t n = small ? 40 : 150;
    check_predicates(&st);
    for (int k = 0; k < NUM_SETS; k++) {
        rset s = make_set(k, n);
        check_set(&st, &s, k >= FIRST_ORDINARY);
        free(s.p);
    }
    return tl_finish(&st);
}
