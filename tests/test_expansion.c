/*
 * test_expansion.c -- the expansion-arithmetic predicates (expansion.h)
 * return the exact signs of the determinants, and DD_EXP_UNSAFE exactly
 * outside their safe range.
 *
 * Compares dd_orient3d_exp and dd_insphere_exp, where their stage A
 * decides, with pred.h's dd_orient3d and dd_insphere (a filter, then
 * dd_*_exp, then GMP: exact for every double), and where a later stage
 * decides with the determinant in GMP integers (independent of
 * dd_*_exp), on >= 10^6 tuples of five points: integer grids, integer
 * points on spheres (cospherical: both must say 0), moment-curve points
 * (t, t^2, t^3) with t = i/1024,
 * uniform random doubles, rounded points of the unit sphere, exactly
 * coplanar random doubles (inexact differences, determinant 0: the
 * raw-coordinate stage), mixed and wide magnitudes, generic integer points
 * of a sphere of radius ~2^26 and 53-bit points of an exact tilted plane
 * (exact zeros whose double and double-double evaluations round: these
 * stress the error bounds of stages A and C -- shrinking those bounds by
 * 2^-3 resp. 2^-8 makes this test fail), integer points of spheres of
 * norm 3001, 2^19 - 1 and 2^19 + 4321 (exact zeros on either side of the
 * 20-bit limit of stage B's integer evaluation), and five corners of
 * cubes of side 2^k - 1 (the integer evaluation's largest values: a limit
 * raised past 20 bits overflows and fails), each perturbed by one ulp in
 * some rounds, translated by 1e6 or 1e15 and scaled by powers of two.
 * Checks that every stage of both predicates ran, that coordinates
 * outside the safe range (1e-200, 1e200, NaN, ...) give DD_EXP_UNSAFE,
 * and that the range limits themselves are handled.  The tuples are run
 * twice: with stage C's run-time choice (hardware FMA when the CPU has
 * it) and with its plain TWO-PRODUCT forced (dd_exp_force_plain), so both
 * copies of stage C are checked on an FMA machine.
 *
 * Arguments: "small" (sanitizer builds) runs 10^5 tuples; "--bench"
 * prints ns per call of dd_insphere_exp against dd_insphere on tuples that
 * fail pred.c's filter (and the stage mix), then runs the checks.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L   /* clock_gettime under -std=c11 */
#endif
#include "testlib.h"
#include "geom/pred.h"
#include "geom/expansion.h"

#include <math.h>
#include <gmp.h>
#include <mpfr.h>
#include <time.h>

typedef struct tally {
    long tuples, mismatches;
    long zeros;                       /* exact zeros seen (insphere)        */
    long unsafe;                      /* tuples outside a safe range        */
    long stage[2][5];                 /* [orient/insphere][stage]           */
    char first[320];
} tally;

/* ---- generators ------------------------------------------------------------ */

enum kind {
    K_GRID, K_SPHERE, K_MOMENT, K_UNIFORM, K_UNIT_SPHERE, K_PLANE, K_MIXED,
    K_WIDE, K_BIG_SPHERE, K_TILTED, K_MID_SPHERE, K_NKINDS
};
static const char *const kind_name[K_NKINDS] = {
    "grid", "sphere", "moment-curve", "uniform", "unit-sphere",
    "coplanar-inexact", "mixed-magnitude", "wide-exponent",
    "big-sphere", "tilted-plane", "mid-sphere"
};


static pool spheres[6];
static const int64_t sphere_r2[6] = {9, 50, 81, 338, 3000, 12345};
static pool big_sphere;
/* Norms 3001, 2^19 - 1 and 2^19 + 4321: differences of up to about 2^13,
 * just under 2^20, and just over it, around the 20-bit limit of stage B's
 * integer evaluation (expansion.c, insphere_int).                        */
static pool mid_spheres[3];
static const int64_t mid_norm[3] = {3001, (1LL << 19) - 1, (1LL << 19) + 4321};

static int64_t int_sqrt(int64_t v)   /* floor(sqrt(v)), v >= 0 */
{
    int64_t s = (int64_t)sqrt((double)v);
    while (s * s > v) s--;
    while ((s + 1) * (s + 1) <= v) s++;
    return s;
}

/* n points (a^2+b^2-c^2-d^2, 2(ad+bc), 2(bd-ac)) with a^2+b^2+c^2+d^2 = r:
 * integer points of the sphere of radius r (Euler's four-square identity). */
static pool four_square_sphere(tl_rng *r, int64_t radius, int n)
{
    pool pl = {malloc(3 * (size_t)n * sizeof(double)), 0};
    int64_t m = int_sqrt(radius);
    while (pl.n < n) {
        int64_t a = tl_int(r, -m, m), b = tl_int(r, -m, m), c = tl_int(r, -m, m);
        int64_t d2 = radius - a * a - b * b - c * c;
        if (d2 < 0) continue;
        int64_t d = int_sqrt(d2);
        if (d * d != d2) continue;
        double *p = pl.p + 3 * pl.n++;
        p[0] = (double)(a * a + b * b - c * c - d * d);
        p[1] = (double)(2 * (a * d + b * c));
        p[2] = (double)(2 * (b * d - a * c));
    }
    return pl;
}


/* A random double in [-1, 1) with all 53 bits used, times 2^e. */
static double rnd(tl_rng *r, int e)
{
    return ldexp(2.0 * tl_unif(r) - 1.0, e);
}

/* Fills q with a tuple of the given kind; returns 1 when the points are
 * known to be exactly cospherical (or five coplanar: insphere 0).        */
static int generate(tl_rng *r, int kind, double q[5][3])
{
    switch (kind) {
    case K_GRID: {
        int k = (int)tl_int(r, 1, 4);
        for (int i = 0; i < 5; i++)
            for (int c = 0; c < 3; c++) q[i][c] = (double)tl_int(r, -k, k);
        return 0;
    }
    case K_SPHERE:
        tl_pick(r, &spheres[tl_int(r, 0, 5)], 5, q);
        return 1;
    case K_MOMENT: {
        /* five nearby parameters: a tiny, nearly degenerate determinant */
        int64_t i0 = tl_int(r, -4096, 4096);
        int64_t span = tl_int(r, 4, 64);
        int64_t used[5];
        for (int i = 0; i < 5; i++) {
            int again;
            do {
                used[i] = i0 + tl_int(r, 0, span);
                again = 0;
                for (int j = 0; j < i; j++) again |= used[j] == used[i];
            } while (again);
            double t = (double)used[i] / 1024.0;
            q[i][0] = t; q[i][1] = t * t; q[i][2] = t * t * t;
        }
        return 0;
    }
    case K_UNIFORM:
        for (int i = 0; i < 5; i++)
            for (int c = 0; c < 3; c++) q[i][c] = rnd(r, 0);
        return 0;
    case K_UNIT_SPHERE:
        /* rounded points of the unit sphere: cospherical up to rounding */
        for (int i = 0; i < 5; i++) {
            double th = 6.283185307179586 * tl_unif(r), z = 2.0 * tl_unif(r) - 1.0;
            double rho = sqrt(1.0 - z * z);
            q[i][0] = rho * cos(th); q[i][1] = rho * sin(th); q[i][2] = z;
        }
        return 0;
    case K_PLANE: {
        /* an exact plane through random 53-bit doubles of several
         * binades: differences inexact, both determinants exactly 0     */
        int which = (int)tl_int(r, 0, 3);
        for (int i = 0; i < 5; i++) {
            double x = rnd(r, (int)tl_int(r, -6, 3)), y = rnd(r, (int)tl_int(r, -6, 3));
            switch (which) {
            case 0: q[i][0] = x; q[i][1] = y; q[i][2] = x; break;          /* z = x  */
            case 1: q[i][0] = x; q[i][1] = 2.0 * x; q[i][2] = y; break;    /* y = 2x */
            case 2: q[i][0] = 0.375; q[i][1] = x; q[i][2] = y; break;      /* x = c  */
            default: q[i][0] = x; q[i][1] = y; q[i][2] = -0.5 * y; break;  /* z=-y/2 */
            }
        }
        return 1;
    }
    case K_MIXED: {
        /* an exact plane again, the points of very different sizes */
        for (int i = 0; i < 5; i++) {
            int e = (int)tl_int(r, -80, 0);
            double x = rnd(r, e), y = rnd(r, e - (int)tl_int(r, 0, 30));
            q[i][0] = x; q[i][1] = y; q[i][2] = y;                         /* z = y  */
        }
        return 1;
    }
    case K_WIDE: /* every coordinate its own exponent, within range */
        for (int i = 0; i < 5; i++)
            for (int c = 0; c < 3; c++) q[i][c] = rnd(r, (int)tl_int(r, -110, 110));
        return 0;
    case K_BIG_SPHERE:
        /* generic integer points of a sphere of radius ~2^26: exactly
         * cospherical, and ~135-bit determinants, so doubles and double-
         * doubles both round (stresses the stage A and C error bounds)  */
        tl_pick(r, &big_sphere, 5, q);
        return 1;
    case K_MID_SPHERE:
        /* integer points of spheres of norm up to ~2^19: exactly
         * cospherical, the heads integers of 10 to 21 bits              */
        tl_pick(r, &mid_spheres[tl_int(r, 0, 2)], 5, q);
        return 1;
    default: { /* K_TILTED: the plane z = x + y through 53-bit points of
                * several binades, x + y exact: inexact differences, and
                * rounding everywhere, determinants exactly 0              */
        int swap = (int)tl_int(r, 0, 1);   /* or the plane x = z + y */
        for (int i = 0; i < 5; i++) {
            int e = (int)tl_int(r, -5, 0);
            double x = ldexp(1.0 + 0.5 * tl_unif(r), e);           /* [1, 1.5) 2^e */
            double ulp = ldexp(1.0, e - 52);
            double y = ulp * (double)tl_int(r, -(1LL << 48), 1LL << 48);  /* |y| < 2^(e-4) */
            q[i][0] = x; q[i][1] = y; q[i][2] = x + y;
            if (swap) { double t = q[i][0]; q[i][0] = q[i][2]; q[i][2] = t; }
        }
        return 1;
    }
    }
}

/* Transforms.  Exact ones keep degeneracies; the 1e6/1e15 translations of
 * non-integer points round (the points then are what they are).         */
static int transform(tl_rng *r, double q[5][3])
{
    int choice = (int)tl_int(r, 0, 5);
    int exact = 1;
    double off = 0.0, scale = 1.0;
    switch (choice) {
    case 0: break;
    case 1: off = 1e6; break;
    case 2: off = 1e15; break;
    case 3: scale = ldexp(1.0, (int)tl_int(r, -100, 100)); break;
    case 4: off = 1e6; scale = ldexp(1.0, (int)tl_int(r, -30, 30)); break;
    default: scale = ldexp(1.0, (int)tl_int(r, -5, 5)); break;
    }
    double sgn[3] = {tl_int(r, 0, 1) ? 1.0 : -1.0, tl_int(r, 0, 1) ? 1.0 : -1.0,
                     tl_int(r, 0, 1) ? 1.0 : -1.0};
    for (int i = 0; i < 5; i++)
        for (int c = 0; c < 3; c++) {
            double x = q[i][c] + sgn[c] * off;
            if (x - sgn[c] * off != q[i][c]) exact = 0;
            q[i][c] = x * scale;
        }
    return exact;
}

/* Moves one coordinate by one ulp. */
static void perturb(tl_rng *r, double q[5][3])
{
    int i = (int)tl_int(r, 0, 4), c = (int)tl_int(r, 0, 2);
    q[i][c] = nextafter(q[i][c], tl_int(r, 0, 1) ? INFINITY : -INFINITY);
}

/* ---- comparison ------------------------------------------------------------ */

static void note(tally *t, int which, int ours, int stage, int gmp, const char *what,
                 double q[5][3])
{
    t->stage[which][stage]++;
    if (ours != gmp && t->mismatches++ == 0)
        snprintf(t->first, sizeof t->first,
                 "%s: ours %d (stage %d), GMP %d at (%a,%a,%a) (%a,%a,%a) ...",
                 what, ours, stage, gmp, q[0][0], q[0][1], q[0][2], q[1][0], q[1][1], q[1][2]);
}

/* The documented safe range: expected DD_EXP_UNSAFE outside it. */
static int in_range(double q[5][3], int n, double lim)
{
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            double a = fabs(q[i][c]);
            if (!(a <= lim) || (a != 0.0 && a < 1.0 / lim)) return 0;
        }
    return 1;
}

/* ---- an independent exact reference --------------------------------------- */

/* pred.c's dd_orient3d / dd_insphere hand what their filter cannot decide
 * to dd_*_exp itself: for the tuples that reach our stages B-D they are
 * no independent reference.  These determinants are, in GMP integers:
 * every nonzero coordinate is an integer multiple of 2^lo, lo the lowest
 * ilogb(x) - 52 of the tuple, so x 2^-lo is an integer (a double below
 * 2^1023 in the safe ranges) and the determinant of the scaled points has
 * the same sign.                                                          */
static mpz_t ex_x[4][3], ex_lift, ex_m, ex_t, ex_u, ex_d, ex_base[3];

/* ex_x[i] = (rows[i] - base) 2^-lo, exactly (pts: rows then base). */
static void exact_rows(const double *const *pts, int n)
{
    int lo = 0, any = 0;
    for (int i = 0; i <= n; i++)
        for (int c = 0; c < 3; c++)
            if (pts[i][c] != 0.0 && (!any || ilogb(pts[i][c]) - 52 < lo)) {
                lo = ilogb(pts[i][c]) - 52;
                any = 1;
            }
    for (int c = 0; c < 3; c++) mpz_set_d(ex_base[c], ldexp(pts[n][c], -lo));
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            mpz_set_d(ex_x[i][c], ldexp(pts[i][c], -lo));
            mpz_sub(ex_x[i][c], ex_x[i][c], ex_base[c]);
        }
}

/* out = ex_x[i] . (ex_x[j] x ex_x[k]). */
static void exact_det3(mpz_t out, int i, int j, int k)
{
    mpz_set_ui(out, 0);
    for (int c = 0; c < 3; c++) {
        int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
        mpz_mul(ex_t, ex_x[j][c1], ex_x[k][c2]);
        mpz_mul(ex_u, ex_x[j][c2], ex_x[k][c1]);
        mpz_sub(ex_t, ex_t, ex_u);
        mpz_addmul(out, ex_t, ex_x[i][c]);
    }
}

/* sign det[q-p; r-p; s-p] (expansion.h). */
static int exact_orient3d(const double *p, const double *q, const double *r,
                          const double *s)
{
    const double *pts[4] = {q, r, s, p};
    exact_rows(pts, 3);
    exact_det3(ex_d, 0, 1, 2);
    return mpz_sgn(ex_d);
}

/* sign det of the lifted rows p-t, r-t, q-t, s-t (expansion.h), along
 * the lift column: -L0 M0 + L1 M1 - L2 M2 + L3 M3.                      */
static int exact_insphere(const double *p, const double *q, const double *r,
                          const double *s, const double *t)
{
    static const int others[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    const double *pts[5] = {p, r, q, s, t};
    exact_rows(pts, 4);
    mpz_set_ui(ex_d, 0);
    for (int i = 0; i < 4; i++) {
        mpz_mul(ex_lift, ex_x[i][0], ex_x[i][0]);
        mpz_addmul(ex_lift, ex_x[i][1], ex_x[i][1]);
        mpz_addmul(ex_lift, ex_x[i][2], ex_x[i][2]);
        exact_det3(ex_m, others[i][0], others[i][1], others[i][2]);
        if (i & 1) mpz_addmul(ex_d, ex_lift, ex_m);
        else mpz_submul(ex_d, ex_lift, ex_m);
    }
    return mpz_sgn(ex_d);
}

static void exact_init(void)
{
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 3; c++) mpz_init(ex_x[i][c]);
    for (int c = 0; c < 3; c++) mpz_init(ex_base[c]);
    mpz_inits(ex_lift, ex_m, ex_t, ex_u, ex_d, (mpz_ptr)0);
}

static void exact_clear(void)
{
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 3; c++) mpz_clear(ex_x[i][c]);
    for (int c = 0; c < 3; c++) mpz_clear(ex_base[c]);
    mpz_clears(ex_lift, ex_m, ex_t, ex_u, ex_d, (mpz_ptr)0);
}

/* Our sign against pred.c's (filter + dd_*_exp + GMP) where stage A
 * decided, against the MPFR determinant where a later stage did.        */
static void compare(dd_pred *pr, tally *t, double q[5][3])
{
    int st, o, g;
    double q4[5][3] = {{0}};
    t->tuples++;
    int o3ok = in_range(q, 5, 0x1p260), insok = in_range(q, 5, 0x1p140);
    o = dd_orient3d_exp_staged(q[0], q[1], q[2], q[3], &st);
    g = st >= DD_EXP_STAGE_B ? exact_orient3d(q[0], q[1], q[2], q[3])
                             : dd_orient3d(pr, q[0], q[1], q[2], q[3]);
    memcpy(q4, q, 4 * sizeof q[0]);
    note(t, 0, o, st, in_range(q4, 4, 0x1p260) ? g : DD_EXP_UNSAFE, "orient3d(0123)", q);
    o = dd_orient3d_exp_staged(q[4], q[2], q[1], q[3], &st);
    g = st >= DD_EXP_STAGE_B ? exact_orient3d(q[4], q[2], q[1], q[3])
                             : dd_orient3d(pr, q[4], q[2], q[1], q[3]);
    memcpy(q4[0], q[4], sizeof q[4]);
    memcpy(q4[4], q[0], sizeof q[0]);
    note(t, 0, o, st, in_range(q4, 4, 0x1p260) ? g : DD_EXP_UNSAFE, "orient3d(4213)", q);
    o = dd_insphere_exp_staged(q[0], q[1], q[2], q[3], q[4], &st);
    g = st >= DD_EXP_STAGE_B ? exact_insphere(q[0], q[1], q[2], q[3], q[4])
                             : dd_insphere(pr, q[0], q[1], q[2], q[3], q[4]);
    note(t, 1, o, st, insok ? g : DD_EXP_UNSAFE, "insphere(01234)", q);
    if (g == 0) t->zeros++;
    o = dd_insphere_exp_staged(q[4], q[0], q[3], q[1], q[2], &st);
    g = st >= DD_EXP_STAGE_B ? exact_insphere(q[4], q[0], q[3], q[1], q[2])
                             : dd_insphere(pr, q[4], q[0], q[3], q[1], q[2]);
    note(t, 1, o, st, insok ? g : DD_EXP_UNSAFE, "insphere(40312)", q);
    t->unsafe += !o3ok + !insok;
}

/* One named check per kind: plain, perturbed by one ulp, transformed.
 * tag prefixes the names ("" or "plain/").                               */
static void run_kind(tl_state *st, dd_pred *pr, tl_rng *r, int kind, long rounds,
                     const char *tag, tally *total)
{
    tally t;
    memset(&t, 0, sizeof t);
    long cosph = 0, cosph_zero = 0;
    for (long it = 0; it < rounds; it++) {
        double q[5][3];
        int degenerate = generate(r, kind, q);
        int exact = transform(r, q);
        int pert = (it % 4) == 3;
        if (pert) perturb(r, q);
        compare(pr, &t, q);
        if (degenerate && exact && !pert && in_range(q, 5, 0x1p140)) {
            int s1;
            cosph++;
            cosph_zero += dd_insphere_exp_staged(q[0], q[1], q[2], q[3], q[4], &s1) == 0
                          && dd_insphere(pr, q[0], q[1], q[2], q[3], q[4]) == 0;
        }
    }
    char name[96];
    snprintf(name, sizeof name, "expansion/%s%s", tag, kind_name[kind]);
    tl_check(st, t.mismatches == 0, name, "%ld of %ld tuples differ from GMP; first: %s",
             t.mismatches, t.tuples, t.first);
    if (kind == K_SPHERE || kind == K_PLANE || kind == K_MIXED || kind == K_BIG_SPHERE
        || kind == K_TILTED || kind == K_MID_SPHERE) {
        snprintf(name, sizeof name, "expansion/%s%s-exact-zero", tag, kind_name[kind]);
        tl_check(st, cosph > rounds / 4 && cosph_zero == cosph, name,
                 "%ld of %ld exactly degenerate tuples gave insphere 0", cosph_zero, cosph);
    }
    total->tuples += t.tuples;
    total->unsafe += t.unsafe;
    total->mismatches += t.mismatches;
    for (int w = 0; w < 2; w++)
        for (int s = 0; s < 5; s++) total->stage[w][s] += t.stage[w][s];
}

/* ---- the integer stage's limit -------------------------------------------- */

/* Five corners of a cube of side M = 2^k - 1 are cospherical; with one of
 * them as t the heads are 0 or +-M and the cofactors reach 3 M^3 (row
 * (M, M, M) against two edges): the largest values stage B's integer
 * evaluation can meet for k = 20, and past 2^63 from k = 21 on, where it
 * must not be used.  Every 5-subset, in two orders, at k = 10, 20, 21, 22
 * and 30, must give insphere 0 (raising the 20-bit limit fails here).   */
static void check_cube_corners(tl_state *st)
{
    static const int ks[5] = {10, 20, 21, 22, 30};
    long wrong = 0, n = 0;
    char first[160] = "";
    for (int ki = 0; ki < 5; ki++) {
        double m = ldexp(1.0, ks[ki]) - 1.0;
        for (int mask = 0; mask < 256; mask++) {
            if (__builtin_popcount((unsigned)mask) != 5) continue;
            double q[5][3];
            int k = 0;
            for (int c = 0; c < 8; c++)
                if (mask >> c & 1) {
                    for (int x = 0; x < 3; x++) q[k][x] = (c >> x & 1) ? m : 0.0;
                    k++;
                }
            for (int order = 0; order < 2; order++) {
                int s = order ? dd_insphere_exp(q[4], q[2], q[0], q[3], q[1])
                              : dd_insphere_exp(q[0], q[1], q[2], q[3], q[4]);
                n++;
                if (s != 0 && wrong++ == 0)
                    snprintf(first, sizeof first, "k = %d, corners 0x%02x, order %d: %d", ks[ki], mask, order, s);
            }
        }
    }
    tl_check(st, wrong == 0, "expansion/cube-corners-integer-limit", "%ld of %ld cospherical corner tuples nonzero; first: %s",
             wrong, n, first);
}

/* ---- safe range ------------------------------------------------------------- */

static void check_range(tl_state *st, dd_pred *pr, tl_rng *r)
{
    static const double bad_ins[] = {1e-200, -1e200, 0x1p-141, -0x1.fffffffffffffp-141,
                                     0x1.0000000000001p140, 1e300, 4.9e-324, 1e-43};
    static const double bad_o3[] = {1e-200, -1e200, 0x1p-261, 0x1.0000000000001p260,
                                    1e300, -4.9e-324, 1e-80};
    long wrong = 0, n = 0;
    char first[160] = "";
    for (int it = 0; it < 20000; it++) {
        double q[5][3];
        generate(r, (int)tl_int(r, 0, K_NKINDS - 1), q);
        int i = (int)tl_int(r, 0, 4), c = (int)tl_int(r, 0, 2);
        double bi = bad_ins[it % 8], bo = bad_o3[it % 7];
        if (it % 50 == 0) bi = bo = (it % 100 == 0) ? NAN : -INFINITY;
        double keep = q[i][c];
        q[i][c] = bi;
        int s = dd_insphere_exp(q[0], q[1], q[2], q[3], q[4]);
        n++;
        if (s != DD_EXP_UNSAFE && wrong++ == 0)
            snprintf(first, sizeof first, "insphere with %a gave %d", bi, s);
        q[i][c] = bo;
        if (i < 4) {
            s = dd_orient3d_exp(q[0], q[1], q[2], q[3]);
            n++;
            if (s != DD_EXP_UNSAFE && wrong++ == 0)
                snprintf(first, sizeof first, "orient3d with %a gave %d", bo, s);
        }
        q[i][c] = keep;
    }
    tl_check(st, wrong == 0, "expansion/unsafe-range", "%ld of %ld out-of-range calls not UNSAFE; first: %s",
             wrong, n, first);

    /* The range limits themselves and the ordinary range [1e-30, 1e30]:
     * decided, and equal to GMP, also for mixed magnitudes.               */
    tally t;
    memset(&t, 0, sizeof t);
    long unsafe = 0;
    for (int it = 0; it < 40000; it++) {
        double q[5][3];
        int mode = it % 4;
        for (int i = 0; i < 5; i++)
            for (int c = 0; c < 3; c++) {
                double lim = (it & 4) ? 0x1p140 : 0x1p-140;
                double k = (double)(tl_int(r, 0, 1) ? 1 : -1) * (double)tl_int(r, 1, 4);
                if (mode == 0) q[i][c] = tl_int(r, 0, 3) == 0 ? 0.0 : (it & 4) ? lim * k / 4.0 : lim * k;
                else if (mode == 1) q[i][c] = rnd(r, (int)tl_int(r, -95, 99));   /* ~1e-30 .. 1e30 */
                else if (mode == 2) q[i][c] = tl_int(r, 0, 1) ? 1e-30 * (double)tl_int(r, 1, 3) : 1e30 * (double)tl_int(r, -3, 3);
                else q[i][c] = tl_int(r, 0, 1) ? lim : -0x1p-140 * (1.0 + tl_unif(r));
            }
        if (mode == 0 && (it & 8)) { q[0][0] = 0x1p140; q[1][1] = 0x1p-140; }
        int s;
        int o = dd_insphere_exp_staged(q[0], q[1], q[2], q[3], q[4], &s);
        if (o == DD_EXP_UNSAFE) unsafe++;
        t.tuples++;
        note(&t, 1, o, s, dd_insphere(pr, q[0], q[1], q[2], q[3], q[4]), "insphere at limits", q);
        /* orient at its own limits */
        double f = (it & 4) ? 0x1p120 : 0x1p-120;   /* 2^140 * 2^120 = 2^260 */
        double q4[4][3];
        for (int i = 0; i < 4; i++)
            for (int c = 0; c < 3; c++) q4[i][c] = q[i][c] * f;
        o = dd_orient3d_exp_staged(q4[0], q4[1], q4[2], q4[3], &s);
        if (o == DD_EXP_UNSAFE) unsafe++;
        double q5[5][3];
        memcpy(q5, q4, sizeof q4);
        memcpy(q5[4], q[4], sizeof q5[4]);
        note(&t, 0, o, s, dd_orient3d(pr, q4[0], q4[1], q4[2], q4[3]), "orient3d at limits", q5);
    }
    tl_check(st, t.mismatches == 0 && unsafe == 0, "expansion/range-limits",
             "%ld UNSAFE, %ld of %ld differ from GMP; first: %s", unsafe, t.mismatches,
             t.tuples, t.first);
}

/* ---- bench ------------------------------------------------------------------ */

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

/* pred.c's insphere filter, copied to pick tuples that reach its GMP stage. */
static int filter_fails(const double *p, const double *q, const double *r,
                        const double *s, const double *t)
{
    double v[4][3];
    const double *pts[4] = {p, q, r, s};
    double mx[3] = {0, 0, 0};
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 3; c++) {
            v[i][c] = pts[i][c] - t[c];
            if (fabs(v[i][c]) > mx[c]) mx[c] = fabs(v[i][c]);
        }
    double pt2 = v[0][0] * v[0][0] + v[0][1] * v[0][1] + v[0][2] * v[0][2];
    double qt2 = v[1][0] * v[1][0] + v[1][1] * v[1][1] + v[1][2] * v[1][2];
    double rt2 = v[2][0] * v[2][0] + v[2][1] * v[2][1] + v[2][2] * v[2][2];
    double st2 = v[3][0] * v[3][0] + v[3][1] * v[3][1] + v[3][2] * v[3][2];
    double eps = 1.2466136531027298e-13 * mx[0] * mx[1] * mx[2];
    double a = mx[0], b = mx[1], c = mx[2], tt;
    if (a > c) { tt = a; a = c; c = tt; }
    if (b > c) { tt = b; b = c; c = tt; } else if (b < a) { tt = a; a = b; b = tt; }
    const double *P = v[0], *Q = v[1], *R = v[2], *S = v[3];
    double m01 = R[0] * P[1] - P[0] * R[1], m02 = Q[0] * P[1] - P[0] * Q[1];
    double m03 = S[0] * P[1] - P[0] * S[1], m12 = Q[0] * R[1] - R[0] * Q[1];
    double m13 = S[0] * R[1] - R[0] * S[1], m23 = S[0] * Q[1] - Q[0] * S[1];
    double m012 = m12 * P[2] - m02 * R[2] + m01 * Q[2];
    double m013 = m13 * P[2] - m03 * R[2] + m01 * S[2];
    double m023 = m23 * P[2] - m03 * Q[2] + m02 * S[2];
    double m123 = m23 * R[2] - m13 * Q[2] + m12 * S[2];
    double det = m123 * pt2 - m023 * rt2 + m013 * qt2 - m012 * st2;
    if (a < 1e-58) return a != 0;
    if (c >= 1e61) return 1;
    eps *= c * c;
    return !(det > eps || det < -eps);
}

static void bench_kind(dd_pred *pr, int kind, int perturbed, const char *label)
{
    enum { N = 4000, REPS = 25 };
    static double tup[N][5][3];
    tl_rng r = {777 + (uint64_t)kind};
    int n = 0;
    for (long tries = 0; n < N && tries < 200L * N; tries++) {
        double q[5][3];
        generate(&r, kind, q);
        if (perturbed) perturb(&r, q);
        if (!filter_fails(q[0], q[1], q[2], q[3], q[4])) continue;
        memcpy(tup[n++], q, sizeof q);
    }
    if (n == 0) { fprintf(stderr, "%-32s no tuple fails the filter\n", label); return; }
    long stage[5] = {0};
    for (int i = 0; i < n; i++) {
        int s;
        dd_insphere_exp_staged(tup[i][0], tup[i][1], tup[i][2], tup[i][3], tup[i][4], &s);
        stage[s]++;
    }
    /* warm up, then alternate: best of three rounds each (shared hosts) */
    long sum = 0;
    double ne = 1e30, ng = 1e30;
    for (int round = 0; round < 4; round++) {
        double t0 = now_ns();
        for (int k = 0; k < REPS; k++)
            for (int i = 0; i < n; i++)
                sum += dd_insphere_exp(tup[i][0], tup[i][1], tup[i][2], tup[i][3], tup[i][4]);
        double t1 = now_ns();
        for (int k = 0; k < REPS; k++)
            for (int i = 0; i < n; i++)
                sum += dd_insphere(pr, tup[i][0], tup[i][1], tup[i][2], tup[i][3], tup[i][4]);
        double t2 = now_ns();
        if (round == 0) continue;
        if ((t1 - t0) / ((double)REPS * n) < ne) ne = (t1 - t0) / ((double)REPS * n);
        if ((t2 - t1) / ((double)REPS * n) < ng) ng = (t2 - t1) / ((double)REPS * n);
    }
    fprintf(stderr, "%-32s %5d  exp %7.1f ns  gmp %7.1f ns  x%5.1f   A/B/C/D %ld/%ld/%ld/%ld  (%ld)\n",
            label, n, ne, ng, ng / ne, stage[1], stage[2], stage[3], stage[4], sum & 1);
}

static void bench(dd_pred *pr)
{
    fprintf(stderr, "# insphere on tuples failing pred.c's filter: ns per call, best of 3\n"
                    "# (tuples, exp = dd_insphere_exp, gmp = dd_insphere = filter + GMP)\n");
    bench_kind(pr, K_MOMENT, 0, "moment-curve t=i/1024");
    bench_kind(pr, K_MOMENT, 1, "moment-curve, 1 ulp");
    bench_kind(pr, K_GRID, 0, "integer grid");
    bench_kind(pr, K_SPHERE, 0, "integer sphere (cospherical)");
    bench_kind(pr, K_SPHERE, 1, "integer sphere, 1 ulp");
    bench_kind(pr, K_MID_SPHERE, 0, "sphere r up to 2^19 (cospherical)");
    bench_kind(pr, K_BIG_SPHERE, 0, "big sphere r~2^26 (cospherical)");
    bench_kind(pr, K_BIG_SPHERE, 1, "big sphere, 1 ulp");
    bench_kind(pr, K_UNIT_SPHERE, 0, "unit sphere, rounded");
    bench_kind(pr, K_TILTED, 0, "tilted plane (exact 0, tails)");
    bench_kind(pr, K_TILTED, 1, "tilted plane, 1 ulp");
    bench_kind(pr, K_PLANE, 0, "coplanar, inexact differences");
    bench_kind(pr, K_MIXED, 0, "coplanar, mixed magnitudes");
}

/* ---- main ------------------------------------------------------------------- */

/* dd_exp_shifted_lift against MPFR at 2000 bits (exact here): within
 * 2u of |w|, on nearly cospherical points where w cancels to ~1e-16 of
 * its terms, on random ones, and on exact zeros.                         */
static void shifted_lift(tl_state *st, tl_rng *r, long rounds)
{
    long bad = 0, zeros = 0;
    double worst = 0;
    mpfr_t X, W, T, C2;
    mpfr_inits2(2000, X, W, T, C2, (mpfr_ptr)0);
    for (long i = 0; i < rounds; i++) {
        double x[3], q[3], c[3];
        int kind = (int)(i % 3);
        for (int k = 0; k < 3; k++) {
            q[k] = 2 * tl_unif(r) - 1;
            c[k] = kind == 2 ? 0.0 : 2 * tl_unif(r) - 1;
        }
        if (kind == 0) {       /* x on the sphere of centre q + c through q */
            double d[3], n = 0;
            for (int k = 0; k < 3; k++) { d[k] = 2 * tl_unif(r) - 1; n += d[k] * d[k]; }
            double rad = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
            for (int k = 0; k < 3; k++) x[k] = q[k] + c[k] + rad * d[k] / sqrt(n);
        } else {
            for (int k = 0; k < 3; k++) x[k] = kind == 2 && i % 6 == 5 ? q[k] : 2 * tl_unif(r) - 1;
        }
        mpfr_set_zero(W, 1);
        for (int k = 0; k < 3; k++) {      /* W += X (X - 2c), X = x - q */
            mpfr_set_d(X, x[k], MPFR_RNDN);
            mpfr_sub_d(X, X, q[k], MPFR_RNDN);
            mpfr_set_d(C2, c[k], MPFR_RNDN);
            mpfr_mul_2ui(C2, C2, 1, MPFR_RNDN);
            mpfr_sub(T, X, C2, MPFR_RNDN);
            mpfr_mul(T, T, X, MPFR_RNDN);
            mpfr_add(W, W, T, MPFR_RNDN);
        }
        double v = dd_exp_shifted_lift(x, q, c);
        mpfr_sub_d(T, W, v, MPFR_RNDN);
        double err = fabs(mpfr_get_d(T, MPFR_RNDN)), w = fabs(mpfr_get_d(W, MPFR_RNDN));
        if (w == 0) zeros++;
        if (err > 0x1p-52 * w) bad++;
        else if (w > 0 && err / w > worst) worst = err / w;
    }
    mpfr_clears(X, W, T, C2, (mpfr_ptr)0);
    tl_check(st, bad == 0 && zeros > 0, "expansion/shifted-lift-within-2u",
             "%ld of %ld beyond 2u |w| (%ld exact zeros, worst within: %.2g)", bad, rounds, zeros, worst);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    int small = 0, do_bench = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "small") == 0) small = 1;
        if (strcmp(argv[i], "--bench") == 0) do_bench = 1;
    }
    dd_pred pr;
    dd_pred_init(&pr);
    exact_init();
    for (int i = 0; i < 6; i++) {
        spheres[i].p = malloc(3 * 20000 * sizeof(double));
        spheres[i].n = tl_sphere_points(sphere_r2[i], spheres[i].p, 20000);
    }
    {
        tl_rng rs = {99};
        big_sphere = four_square_sphere(&rs, (1LL << 26) + 4321, 600);
        for (int i = 0; i < 3; i++) mid_spheres[i] = four_square_sphere(&rs, mid_norm[i], 600);
    }
    if (do_bench) bench(&pr);
    {
        tl_rng rl = {777};
        shifted_lift(&st, &rl, small ? 20000 : 200000);
    }

    tl_rng r = {20240611};
    long per_kind = small ? 10000 : 100000;   /* 11 kinds: >= 10^5 or 10^6 tuples */
    tally total;
    memset(&total, 0, sizeof total);
#ifdef DD_TEST_BUILD
    int fma = dd_exp_force_plain(0);          /* the run-time choice */
#else
    int fma = __builtin_cpu_supports("fma");
#endif
    printf("# stage C TWO-PRODUCT: %s\n", fma ? "hardware FMA" : "Dekker (no FMA)");
    for (int k = 0; k < K_NKINDS; k++) run_kind(&st, &pr, &r, k, per_kind, "", &total);
    tl_check(&st, total.tuples >= (small ? 100000 : 1000000), "expansion/at-least-1e6-tuples",
             "only %ld tuples", total.tuples);
    /* Every stage of both predicates must have run (and agreed). */
    long minimum = small ? 20 : 200;
    for (int w = 0; w < 2; w++)
        for (int s = DD_EXP_STAGE_A; s <= DD_EXP_STAGE_D; s++) {
            char name[64];
            snprintf(name, sizeof name, "expansion/%s-stage-%c-exercised",
                     w ? "insphere" : "orient3d", 'A' + s - 1);
            tl_check(&st, total.stage[w][s] >= minimum, name, "stage ran %ld times",
                     total.stage[w][s]);
        }
    printf("# %ld tuples (%ld predicate inputs out of range); orient3d stages A/B/C/D %ld/%ld/%ld/%ld, insphere %ld/%ld/%ld/%ld\n",
           total.tuples, total.unsafe, total.stage[0][1], total.stage[0][2], total.stage[0][3],
           total.stage[0][4], total.stage[1][1], total.stage[1][2], total.stage[1][3],
           total.stage[1][4]);

    /* The same tuples again with stage C's plain TWO-PRODUCT forced: on a
     * CPU with FMA the pass above ran stage C's fma copy, so both copies
     * are compared with GMP.  Both are exact, so each tuple must also be
     * decided at the same stage as above.                                */
#ifdef DD_TEST_BUILD
    {
        tl_rng rp = {20240611};
        tally plain;
        memset(&plain, 0, sizeof plain);
        int plain_fma = dd_exp_force_plain(1);
        for (int k = 0; k < K_NKINDS; k++)
            run_kind(&st, &pr, &rp, k, per_kind, "plain/", &plain);
        dd_exp_force_plain(0);
        tl_check(&st, memcmp(plain.stage, total.stage, sizeof plain.stage) == 0
                 && plain.stage[0][DD_EXP_STAGE_C] >= minimum
                 && plain.stage[1][DD_EXP_STAGE_C] >= minimum,
                 "expansion/plain-same-stages",
                 "stage C ran %ld / %ld times (orient3d / insphere), %ld / %ld with the run-time choice",
                 plain.stage[0][DD_EXP_STAGE_C], plain.stage[1][DD_EXP_STAGE_C],
                 total.stage[0][DD_EXP_STAGE_C], total.stage[1][DD_EXP_STAGE_C]);
        printf("# plain pass: stage C TWO-PRODUCT %s\n", plain_fma ? "FMA (build targets FMA)" : "Dekker");
    }
#endif
    check_range(&st, &pr, &r);
    check_cube_corners(&st);

    for (int i = 0; i < 6; i++) free(spheres[i].p);
    free(big_sphere.p);
    for (int i = 0; i < 3; i++) free(mid_spheres[i].p);
    dd_pred_clear(&pr);
    exact_clear();
    return tl_finish(&st);
}
