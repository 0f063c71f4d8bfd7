/*
 * power.c -- the power predicates of regular triangulations (DESIGN 12;
 * signs in power.h), as CGAL's Regular_triangulation_3 evaluates them.
 *
 * The power test runs a filter (power.h's dd_power_filter: CGAL's
 * semi-static one), then exact stages in turn: small integers in 128-bit
 * arithmetic (grids with small integer weights); the points scaled
 * exactly into the filter's range, filtered again, then bounded by a
 * dynamic filter (power_dynamic); GMP integers last.  The 3+1 test runs
 * CGAL's filter, small integers and GMP; power distances a filter and
 * GMP.  For GMP every double is m 2^e with an integer m of at most 53
 * bits, so with s the smallest power of two that every coordinate is a
 * multiple of and every weight a multiple of the square of, coordinates
 * / s and weights / s^2 are integers, every lifted entry |x - y|^2 + w -
 * w' is an integer, and every determinant is exact.  The power test is
 * homogeneous (coordinates of degree 1, weights of degree 2), so the
 * scalings keep every sign.
 *
 * The perturbation (Devillers & Teillaud 2011, as CGAL's
 * side_of_oriented_power_sphere and side_of_oriented_power_circle apply
 * it) is applied on top, only when the exact sign is 0.  The points are
 * sorted by bare point with std::sort's order for CGAL's five or four
 * pointers: libstdc++ sorts so few elements by insertion, which keeps
 * equal points in argument order; so does sort_by_point here.
 */
#include "geom/power.h"

#include <stdint.h>

/* ---- exact stage ----------------------------------------------------- */

/* The exponent of x's lowest set bit: x is an odd multiple of 2^e. */
static int low_exponent(double x)
{
    int e;
    const double f = frexp(x, &e);              /* x = f 2^e, |f| in [.5, 1) */
    const int64_t m = (int64_t)ldexp(f, 53);    /* exact 53-bit integer      */
    return e - 53 + __builtin_ctzll((uint64_t)(m < 0 ? -m : m));
}

/* out = x / 2^s, exactly (an integer by the choice of s). */
static void set_scaled(mpz_t out, double x, int s)
{
    if (x == 0.0) {
        mpz_set_ui(out, 0);
        return;
    }
    int e;
    const double f = frexp(x, &e);
    mpz_set_si(out, (long)(int64_t)ldexp(f, 53));
    const int sh = e - 53 - s;
    if (sh > 0) mpz_mul_2exp(out, out, (mp_bitcnt_t)sh);
    else if (sh < 0) mpz_tdiv_q_2exp(out, out, (mp_bitcnt_t)(-sh));   /* exact */
}

/* Loads the n weighted points (n <= 5) as integers: point i's coordinates
 * into z[4i .. 4i+2] and its weight into z[4i+3], coordinates divided by
 * 2^e and weights by 2^2e, e the largest exponent that keeps all of them
 * integers: each coordinate below 2^2098 and each weight below 2^3172,
 * inside the bounds of pred.h's DD_PRED_LIMBS.                           */
static void load_weighted(mpz_ptr *z, const double *const *pts, const double *w, int n)
{
    int e = INT32_MAX;
    for (int i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++)
            if (pts[i][c] != 0) {
                const int l = low_exponent(pts[i][c]);
                if (l < e) e = l;
            }
        if (w[i] != 0) {
            const int l = low_exponent(w[i]);
            const int half = l >= 0 ? l / 2 : -((1 - l) / 2);   /* floor(l / 2) */
            if (half < e) e = half;
        }
    }
    if (e == INT32_MAX) e = 0;
    for (int i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++) set_scaled(z[4 * i + c], pts[i][c], e);
        set_scaled(z[4 * i + 3], w[i], 2 * e);
    }
}

/* A GMP stage of this file: fn on the n weighted points loaded by
 * load_weighted, in pred.h's scratch (dd_pred_exact: the context's own
 * when reserved, else one on the stack; nothing allocates).             */
typedef struct gmp_job {
    const double *const *pts;
    const double *w;
    int n;
    int (*fn)(mpz_ptr *z);
} gmp_job;

static int load_then(mpz_ptr *z, const void *arg)
{
    const gmp_job *j = arg;
    load_weighted(z, j->pts, j->w, j->n);
    return j->fn(z);
}

static int run_gmp(dd_pred *ctx, const double *const *pts, const double *w, int n, int (*fn)(mpz_ptr *z))
{
    const gmp_job j = {pts, w, n, fn};
    return dd_pred_exact(ctx, NULL, 0, load_then, &j, NULL);
}

/* Turns the loaded points 0..n-2 into rows relative to point n-1 (the
 * query t): Pi - T and |Pi - T|^2 + Wt - Wi, in place.                   */
static void lift_rows(mpz_ptr *z, int n)
{
    const int t = 4 * (n - 1);
    for (int i = 0; i < n - 1; i++) {
        mpz_ptr *r = &z[4 * i];
        for (int c = 0; c < 3; c++) mpz_sub(r[c], r[c], z[t + c]);
        mpz_sub(r[3], z[t + 3], r[3]);
        for (int c = 0; c < 3; c++) mpz_addmul(r[3], r[c], r[c]);
    }
}


/* ---- small integers: exact in 128-bit arithmetic --------------------------
 *
 * Grids with small integer weights are where exact zeros are common.  When
 * the points are integers below 2^20 and the weights integers below 2^40,
 * after the exact scaling of load_weighted, every row difference is below
 * 2^21, every lifted entry below 3 2^42 + 2^41 < 2^44, the 3x3 minors
 * below 6 2^63 and the 4x4 determinant below 2^112: __int128 holds them. */
#define SMALL_COORD_BITS 20
#define SMALL_WEIGHT_BITS 40

typedef __int128 i128;

/* The n weighted points as integers x[i][0..2], weight x[i][3] (scaled as
 * load_weighted scales them): 1, or 0 when they are not that small.      */
static int small_ints(const double *const *pts, const double *w, int n, int64_t x[][4])
{
    int e = INT32_MAX;
    for (int i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++)
            if (pts[i][c] != 0) {
                const int l = low_exponent(pts[i][c]);
                if (l < e) e = l;
            }
        if (w[i] != 0) {
            const int l = low_exponent(w[i]);
            const int half = l >= 0 ? l / 2 : -((1 - l) / 2);
            if (half < e) e = half;
        }
    }
    if (e == INT32_MAX) e = 0;
    for (int i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++) {
            if (pts[i][c] != 0 && ilogb(pts[i][c]) - e >= SMALL_COORD_BITS) return 0;
            x[i][c] = (int64_t)ldexp(pts[i][c], -e);
        }
        if (w[i] != 0 && ilogb(w[i]) - 2 * e >= SMALL_WEIGHT_BITS) return 0;
        x[i][3] = (int64_t)ldexp(w[i], -2 * e);
    }
    return 1;
}

/* Rows of points 0..n-2 relative to point n-1, lifted, as lift_rows. */
static void lift_rows_small(int64_t x[][4], int n, i128 d[][4])
{
    const int64_t *t = x[n - 1];
    for (int i = 0; i < n - 1; i++) {
        for (int c = 0; c < 3; c++) d[i][c] = x[i][c] - t[c];
        d[i][3] = d[i][0] * d[i][0] + d[i][1] * d[i][1] + d[i][2] * d[i][2] + (t[3] - x[i][3]);
    }
}

static int sign128(i128 v) { return (v > 0) - (v < 0); }

/* det[[a0 a1 a2][b0 b1 b2][c0 c1 c2]] for entries below 2^44, 2^21, 2^21
 * in some order (products of three stay below 2^89).                   */
static i128 det3_small(const i128 *a, const i128 *b, const i128 *c, int i, int j, int k)
{
    return a[i] * (b[j] * c[k] - b[k] * c[j]) - a[j] * (b[i] * c[k] - b[k] * c[i]) +
           a[k] * (b[i] * c[j] - b[j] * c[i]);
}

static int power_small(int64_t x[5][4])
{
    i128 d[4][4];
    lift_rows_small(x, 5, d);
    i128 det = 0;
    for (int i = 0; i < 4; i++) {   /* Laplace along the lift column */
        const i128 *m[3];
        for (int j = 0, k = 0; j < 4; j++)
            if (j != i) m[k++] = d[j];
        const i128 minor = det3_small(m[0], m[1], m[2], 0, 1, 2);
        det += (i & 1) ? d[i][3] * minor : -(d[i][3] * minor);
    }
    return -sign128(det);
}

/* ---- exact rescaling and a dynamic filter ---------------------------------
 *
 * The power test is homogeneous: coordinates times 2^k and weights times
 * 2^2k keep its sign, exactly while every nonzero value stays a normal
 * double.  Points near the ends of the double range (where the filter's
 * guards refuse them) are scaled so that every |coordinate| and |weight|
 * is below 2 and the largest of them near 1, then filtered again: by the
 * static filter, then by a dynamic bound (power_dynamic), which decides
 * most nearly degenerate tuples that the static bound leaves.            */

/* The determinant of dd_power_filter, in the same order, on the scaled
 * points, with its permanent P along the same evaluation: absolute values,
 * the lift column replaced by L = |d|^2 + |w - wi|.  Error: each product
 * term carries at most 3u from its three rounded differences, 6u L from
 * its lift ((dx^2 + dy^2) + dz^2) + dw (one rounding in each difference,
 * square and sum), and 9 roundings of the evaluation (2 in the 2x2
 * minors, 3 in the 3x3, 4 in the last sum): under 18u P to first order,
 * under 24u P with the rounding of P.  Underflow: every entry is below 52,
 * so an operation that underflows (error at most 2^-1075) moves the
 * determinant by under 2^-1075 52^3, under 1e-300 for all of them.      */
static int power_dynamic(const double x[5][3], const double ws[5])
{
    double d[4][3], a[4][3], l[4], L[4];
    for (int i = 0; i < 4; i++) {
        for (int c = 0; c < 3; c++) {
            d[i][c] = x[i][c] - x[4][c];
            a[i][c] = fabs(d[i][c]);
        }
        const double s = (d[i][0] * d[i][0] + d[i][1] * d[i][1]) + d[i][2] * d[i][2], dw = ws[4] - ws[i];
        l[i] = s + dw;
        L[i] = s + fabs(dw);
    }
    const double m01 = d[1][0] * d[0][1] - d[0][0] * d[1][1], p01 = a[1][0] * a[0][1] + a[0][0] * a[1][1];
    const double m02 = d[2][0] * d[0][1] - d[0][0] * d[2][1], p02 = a[2][0] * a[0][1] + a[0][0] * a[2][1];
    const double m03 = d[3][0] * d[0][1] - d[0][0] * d[3][1], p03 = a[3][0] * a[0][1] + a[0][0] * a[3][1];
    const double m12 = d[2][0] * d[1][1] - d[1][0] * d[2][1], p12 = a[2][0] * a[1][1] + a[1][0] * a[2][1];
    const double m13 = d[3][0] * d[1][1] - d[1][0] * d[3][1], p13 = a[3][0] * a[1][1] + a[1][0] * a[3][1];
    const double m23 = d[3][0] * d[2][1] - d[2][0] * d[3][1], p23 = a[3][0] * a[2][1] + a[2][0] * a[3][1];
    const double m012 = m12 * d[0][2] - m02 * d[1][2] + m01 * d[2][2];
    const double m013 = m13 * d[0][2] - m03 * d[1][2] + m01 * d[3][2];
    const double m023 = m23 * d[0][2] - m03 * d[2][2] + m02 * d[3][2];
    const double m123 = m23 * d[1][2] - m13 * d[2][2] + m12 * d[3][2];
    const double p012 = p12 * a[0][2] + p02 * a[1][2] + p01 * a[2][2];
    const double p013 = p13 * a[0][2] + p03 * a[1][2] + p01 * a[3][2];
    const double p023 = p23 * a[0][2] + p03 * a[2][2] + p02 * a[3][2];
    const double p123 = p23 * a[1][2] + p13 * a[2][2] + p12 * a[3][2];
    const double det = m123 * l[0] - m023 * l[1] + m013 * l[2] - m012 * l[3];
    const double per = p123 * L[0] + p023 * L[1] + p013 * L[2] + p012 * L[3];
    const double bound = 2.6645352591003757e-15 * per + 1e-300;
    if (det > bound) return -1;
    if (det < -bound) return 1;
    return DD_FILTER_UNSURE;
}

static int power_rescaled(dd_pred *ctx, const double *const *pts, const double *w)
{
    int cmax = INT32_MIN, cmin = INT32_MAX, wmax = INT32_MIN, wmin = INT32_MAX;
    for (int i = 0; i < 5; i++) {
        for (int c = 0; c < 3; c++)
            if (pts[i][c] != 0) {
                const int l = ilogb(pts[i][c]);
                cmax = l > cmax ? l : cmax;
                cmin = l < cmin ? l : cmin;
            }
        if (w[i] != 0) {
            const int l = ilogb(w[i]);
            wmax = l > wmax ? l : wmax;
            wmin = l < wmin ? l : wmin;
        }
    }
    if (cmax == INT32_MIN) return DD_FILTER_UNSURE;
    int top = cmax;   /* |coordinates| < 2^(top+1), |weights| < 2^(2 top + 1) */
    if (wmax != INT32_MIN && (wmax + 1) / 2 > top) top = (wmax + 1) / 2;
    const int k = -top;
    if (cmin + k < -1022 || (wmin != INT32_MAX && wmin + 2 * k < -1022)) return DD_FILTER_UNSURE;
    double x[5][3], ws[5];
    for (int i = 0; i < 5; i++) {
        for (int c = 0; c < 3; c++) x[i][c] = ldexp(pts[i][c], k);
        ws[i] = ldexp(w[i], 2 * k);
    }
    const int f = dd_power_filter(ctx, x[0], x[1], x[2], x[3], x[4], ws);
    return f != DD_FILTER_UNSURE ? f : power_dynamic((const double(*)[3])x, ws);
}

/* The power test of the five points loaded in z (a gmp_job's fn). */
static int power_z(mpz_ptr *z)
{
    lift_rows(z, 5);
    mpz_ptr *const rows[4] = {&z[0], &z[4], &z[8], &z[12]};
    return -dd_mpz_sign_det4(rows, &z[20]);
}

int dd_power_exact(dd_pred *ctx, const double *p0, const double *p1, const double *p2, const double *p3,
                   const double *p, const double w[5])
{
    ctx->insphere_exact++;
    const double *pts[5] = {p0, p1, p2, p3, p};
    int64_t x[5][4];
    if (small_ints(pts, w, 5, x)) return power_small(x);
    const int f = power_rescaled(ctx, pts, w);
    if (f != DD_FILTER_UNSURE) return f;
    return run_gmp(ctx, pts, w, 5, power_z);
}

/* CGAL's static filter of the 3+1 power test (which decides only in the
 * xy projection): the lifted 3x3 determinant in CGAL's order, then the
 * 2D orientation, each against CGAL's bound and guards.                  */
static int power_coplanar_filter(const double *p0, const double *p1, const double *p2, const double *p,
                                 const double w[4])
{
    const double *v[3] = {p0, p1, p2};
    double d[3][4], maxx = 0, maxy = 0, maxz = 0, maxw = 0;
    for (int i = 0; i < 3; i++) {
        const double dx = v[i][0] - p[0], dy = v[i][1] - p[1], dz = v[i][2] - p[2], dw = w[3] - w[i];
        d[i][0] = dx;
        d[i][1] = dy;
        d[i][3] = ((dx * dx + dy * dy) + dz * dz) + dw;
        if (fabs(dx) > maxx) maxx = fabs(dx);
        if (fabs(dy) > maxy) maxy = fabs(dy);
        if (fabs(dz) > maxz) maxz = fabs(dz);
        if (fabs(dw) > maxw) maxw = fabs(dw);
    }
    const double lo = maxx < maxy ? maxx : maxy, hi = dd_max3(maxx, maxy, maxz);
    if (!(lo >= 2.92391967062015793913e-74) || (maxw < 8.54930624023949352313e-148 && maxw != 0) ||
        !(hi <= 7.23700557733225980357e+75) || !(maxw <= 5.23742497263382350320e+151))
        return DD_FILTER_UNSURE;
    /* determinant(a00..a22), rows (dx, dy, lift) */
    const double m01 = d[0][0] * d[1][1] - d[1][0] * d[0][1];
    const double m02 = d[0][0] * d[2][1] - d[2][0] * d[0][1];
    const double m12 = d[1][0] * d[2][1] - d[2][0] * d[1][1];
    const double det = m01 * d[2][3] - m02 * d[1][3] + m12 * d[0][3];
    const double h2 = hi * hi;
    const double eps = 3.04426660386257731823e-14 * ((maxx * maxy) * (maxw > h2 ? maxw : h2));
    const int cmp = det > eps ? 1 : det < -eps ? -1 : 0;
    if (cmp == 0) return DD_FILTER_UNSURE;
    const double ax = p0[0] - p2[0], by = p1[1] - p2[1], bx = p1[0] - p2[0], ay = p0[1] - p2[1];
    const double m5 = fabs(ax) > fabs(bx) ? fabs(ax) : fabs(bx), m6 = fabs(by) > fabs(ay) ? fabs(by) : fabs(ay);
    const double lo2 = m5 < m6 ? m5 : m6, hi2 = m5 > m6 ? m5 : m6;
    if (!(lo2 >= 5.00368081960964690982e-147) || !(hi2 <= 7.23700557733225980357e+75)) return DD_FILTER_UNSURE;
    const double o = ax * by - bx * ay, eps2 = 8.88720573725927976811e-16 * (m5 * m6);
    if (o > eps2) return cmp;
    if (o < -eps2) return -cmp;
    return DD_FILTER_UNSURE;
}

/* The 3+1 power test on small integers (small_ints), CGAL's projections. */
static int power_coplanar_small(int64_t x[4][4])
{
    static const int proj[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    i128 d[3][4];
    lift_rows_small(x, 4, d);
    for (int k = 0; k < 3; k++) {
        const int i = proj[k][0], j = proj[k][1];
        const int cmp = sign128(det3_small(d[0], d[1], d[2], i, j, 3));
        if (cmp == 0 && k < 2) continue;
        const i128 o = (i128)(x[0][i] - x[2][i]) * (x[1][j] - x[2][j]) - (i128)(x[1][i] - x[2][i]) * (x[0][j] - x[2][j]);
        return cmp * sign128(o);
    }
    return 0;
}

/* CGAL's 3+1 power test of the four points loaded in z (a gmp_job's fn):
 * the lifted 3x3 determinant in the xy projection, else xz, else yz,
 * times the 2D orientation of the first three in that projection.      */
static int power_coplanar_z(mpz_ptr *z)
{
    static const int proj[3][2] = {{0, 1}, {0, 2}, {1, 2}};   /* xy, xz, yz: CGAL's order */
    lift_rows(z, 4);
    for (int k = 0; k < 3; k++) {
        const int i = proj[k][0], j = proj[k][1];
        mpz_ptr a[3] = {z[i], z[j], z[3]}, b[3] = {z[4 + i], z[4 + j], z[7]}, c[3] = {z[8 + i], z[8 + j], z[11]};
        const int cmp = dd_mpz_sign_det3(a, b, c, &z[16]);
        if (cmp == 0 && k < 2) continue;
        /* (p0_i - p2_i)(p1_j - p2_j) - (p1_i - p2_i)(p0_j - p2_j) */
        mpz_sub(z[20], z[i], z[8 + i]);
        mpz_sub(z[21], z[4 + j], z[8 + j]);
        mpz_sub(z[22], z[4 + i], z[8 + i]);
        mpz_sub(z[23], z[j], z[8 + j]);
        mpz_mul(z[24], z[20], z[21]);
        mpz_submul(z[24], z[22], z[23]);
        return cmp * mpz_sgn(z[24]);
    }
    return 0;
}

int dd_power_coplanar(dd_pred *ctx, const double *p0, const double *p1, const double *p2, const double *p,
                      const double w[4])
{
    const int f = power_coplanar_filter(p0, p1, p2, p, w);
    if (f != DD_FILTER_UNSURE) return f;
    const double *pts[4] = {p0, p1, p2, p};
    int64_t x[4][4];
    if (small_ints(pts, w, 4, x)) return power_coplanar_small(x);
    return run_gmp(ctx, pts, w, 4, power_coplanar_z);
}

/* ---- perturbation ------------------------------------------------------ */

/* Sorts idx[0..n-1] by the bare points pts[idx[k]] (dd_lex_cmp),
 * keeping equal points in index order (insertion sort, as libstdc++'s
 * std::sort on so few elements).                                        */
static void sort_by_point(int *idx, const double *const *pts, int n)
{
    for (int i = 1; i < n; i++) {
        const int x = idx[i];
        int j = i - 1;
        while (j >= 0 && dd_lex_cmp(pts[x], pts[idx[j]]) < 0) {
            idx[j + 1] = idx[j];
            j--;
        }
        idx[j + 1] = x;
    }
}

int dd_power_symbolic(dd_pred *ctx, const double *p0, const double *p1, const double *p2, const double *p3,
                      const double *p, const double w[5])
{
    (void)w;   /* the perturbation's leading terms are orientations */
    DD_COUNT(ctx, perturbed);
    const double *pts[5] = {p0, p1, p2, p3, p};
    int idx[5] = {0, 1, 2, 3, 4};
    sort_by_point(idx, pts, 5);
    for (int i = 4; i > 1; --i) {
        const int k = idx[i];
        if (k == 4) return -1;   /* p0..p3 positively oriented, not coplanar */
        const double *v[4] = {p0, p1, p2, p3};
        v[k] = p;
        const int o = dd_orient3d(ctx, v[0], v[1], v[2], v[3]);
        if (o != 0) return o;
    }
    return -1;   /* CGAL asserts this is unreachable; its release answer */
}

int dd_power_perturbed(dd_pred *ctx, const double *p0, const double *p1, const double *p2, const double *p3,
                       const double *p, const double w[5])
{
    int s = dd_power_filter(ctx, p0, p1, p2, p3, p, w);
    if (s == DD_FILTER_UNSURE) s = dd_power_exact(ctx, p0, p1, p2, p3, p, w);
    return s != 0 ? s : dd_power_symbolic(ctx, p0, p1, p2, p3, p, w);
}

/* CGAL's side_of_oriented_power_circle(p0, p1, p2, p, perturb = true),
 * coplanar_orientation(p0, p1, p2) positive.                            */
static int oriented_power_circle(dd_pred *ctx, const double *p0, const double *p1, const double *p2,
                                 const double *p, const double w[4])
{
    const int s = dd_power_coplanar(ctx, p0, p1, p2, p, w);
    if (s != 0) return s;
    DD_COUNT(ctx, perturbed);
    const double *pts[4] = {p0, p1, p2, p};
    int idx[4] = {0, 1, 2, 3};
    sort_by_point(idx, pts, 4);
    for (int i = 3; i > 1; --i) {
        const int k = idx[i];
        if (k == 3) return -1;   /* p0 p1 p2 positively oriented, not collinear */
        const double *v[3] = {p0, p1, p2};
        v[k] = p;
        const int o = dd_orient_coplanar(ctx, v[0], v[1], v[2]);
        if (o != 0) return o;
    }
    return -1;   /* CGAL asserts this is unreachable; its release answer */
}

int dd_power_circle_perturbed(dd_pred *ctx, const double *p0, const double *p1, const double *p2,
                              const double *p, const double w[4])
{
    if (dd_orient_coplanar(ctx, p0, p1, p2) > 0) return oriented_power_circle(ctx, p0, p1, p2, p, w);
    const double ws[4] = {w[0], w[2], w[1], w[3]};
    return oriented_power_circle(ctx, p0, p2, p1, p, ws);
}

int dd_power_infinite(dd_pred *ctx, const double *a, const double *b, const double *c, const double *p,
                      const double w[4])
{
    const int o = dd_orient3d(ctx, a, b, c, p);
    if (o != 0) return o;
    return dd_power_circle_perturbed(ctx, a, b, c, p, w);
}

/* ---- power distances ---------------------------------------------------- */

/* Filter: each squared distance is within 6u of its value (pred.c's
 * distance filter), the weights' difference within u (|wa| + |wb|), the
 * two final sums add u each relative to their operands; so the error is
 * below 12u S (with room), S = A + B + |wa| + |wb| computed, while S lies in
 * [1e-290, 1e300]: no overflow, and any underflowed term is far below the
 * bound.                                                                 */
static int power_distance_filter(const double *p, const double *a, double wa, const double *b, double wb)
{
    double A = 0, B = 0;
    for (int c = 0; c < 3; c++) {
        const double x = p[c] - a[c], y = p[c] - b[c];
        A += x * x;
        B += y * y;
    }
    const double d = (A - B) - (wa - wb);
    const double S = (A + B) + (fabs(wa) + fabs(wb));
    if (S >= 1e-290 && S <= 1e300) {
        const double err = 1.3322676295501878e-15 * S;
        if (d > err) return 1;
        if (d < -err) return -1;
    }
    return DD_FILTER_UNSURE;
}

/* pow(p, a) - pow(p, b) of p, a, b loaded in z (a gmp_job's fn). */
static int distance_z(mpz_ptr *z)
{
    mpz_sub(z[12], z[11], z[7]);   /* Wb - Wa */
    for (int c = 0; c < 3; c++) {
        mpz_sub(z[13], z[c], z[4 + c]);
        mpz_addmul(z[12], z[13], z[13]);
        mpz_sub(z[13], z[c], z[8 + c]);
        mpz_submul(z[12], z[13], z[13]);
    }
    return mpz_sgn(z[12]);
}

int dd_power_compare_distance(dd_pred *ctx, const double *p, const double *a, double wa, const double *b,
                              double wb)
{
    const int f = power_distance_filter(p, a, wa, b, wb);
    if (f != DD_FILTER_UNSURE) return f;
    const double *pts[3] = {p, a, b};
    const double w[3] = {0, wa, wb};
    return run_gmp(ctx, pts, w, 3, distance_z);
}
