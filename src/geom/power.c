/*
 * power.c -- the power predicates of regular triangulations (DESIGN 12;
 * signs in power.h), as CGAL's Regular_triangulation_3 evaluates them.
 *
 * Each predicate runs a filter (power.h's dd_power_filter: CGAL's
 * semi-static one), then an exact evaluation in GMP integers: every
 * double is m 2^e with an integer m of at most 53 bits, so with s the
 * smallest power of two that every coordinate is a multiple of and every
 * weight a multiple of the square of, coordinates / s and weights / s^2
 * are integers, every lifted entry |x - y|^2 + w - w' is an integer, and
 * every determinant is exact.  The power test is homogeneous (coordinates
 * of degree 1, weights of degree 2), so the scaling keeps every sign.
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

/* ctx->z made if it is not: the same scratch, made the same way, as
 * pred.c's GMP stages (nothing else touches it between calls).         */
static void ready_scratch(dd_pred *ctx)
{
    if (!ctx->z_ready) {
        for (int i = 0; i < DD_PRED_SCRATCH; i++) mpz_init2(ctx->z[i], 256);
        ctx->z_ready = 1;
    }
}

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
 * integers.  Returns the scratch as an array of pointers in zp.          */
static void load_weighted(dd_pred *ctx, const double *const *pts, const double *w, int n, mpz_ptr *zp)
{
    ready_scratch(ctx);
    for (int i = 0; i < DD_PRED_SCRATCH; i++) zp[i] = ctx->z[i];
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
        for (int c = 0; c < 3; c++) set_scaled(zp[4 * i + c], pts[i][c], e);
        set_scaled(zp[4 * i + 3], w[i], 2 * e);
    }
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

/* r = a d - b c */
static void det2(mpz_t r, const mpz_t a, const mpz_t b, const mpz_t c, const mpz_t d, mpz_t tmp)
{
    mpz_mul(r, a, d);
    mpz_mul(tmp, b, c);
    mpz_sub(r, r, tmp);
}

/* det[[a0 a1 a2][b0 b1 b2][c0 c1 c2]] into s[1]; scratch s[0..3]. */
static int sign_det3(mpz_ptr *a, mpz_ptr *b, mpz_ptr *c, mpz_ptr *s)
{
    det2(s[0], b[1], b[2], c[1], c[2], s[3]);
    mpz_mul(s[1], a[0], s[0]);
    det2(s[0], b[0], b[2], c[0], c[2], s[3]);
    mpz_submul(s[1], a[1], s[0]);
    det2(s[0], b[0], b[1], c[0], c[1], s[3]);
    mpz_addmul(s[1], a[2], s[0]);
    return mpz_sgn(s[1]);
}

/* Sign of the 4x4 determinant of rows r[0..3]; scratch s[0..9]. */
static int sign_det4(mpz_ptr *const r[4], mpz_ptr *s)
{
    mpz_set_ui(s[9], 0);
    for (int i = 0; i < 4; i++) {   /* Laplace along the last column */
        mpz_ptr m[3][3];
        for (int j = 0, k = 0; j < 4; j++) {
            if (j == i) continue;
            for (int c = 0; c < 3; c++) m[k][c] = r[j][c];
            k++;
        }
        sign_det3(m[0], m[1], m[2], s);
        if ((i & 1) == 1) mpz_addmul(s[9], r[i][3], s[1]);   /* (-1)^(i+3) */
        else mpz_submul(s[9], r[i][3], s[1]);
    }
    return mpz_sgn(s[9]);
}

int dd_power_exact(dd_pred *ctx, const double *p0, const double *p1, const double *p2, const double *p3,
                   const double *p, const double w[5])
{
    ctx->insphere_exact++;
    const double *pts[5] = {p0, p1, p2, p3, p};
    mpz_ptr z[DD_PRED_SCRATCH];
    load_weighted(ctx, pts, w, 5, z);
    lift_rows(z, 5);
    mpz_ptr *const rows[4] = {&z[0], &z[4], &z[8], &z[12]};
    return -sign_det4(rows, &z[20]);
}

int dd_power_coplanar(dd_pred *ctx, const double *p0, const double *p1, const double *p2, const double *p,
                      const double w[4])
{
    static const int proj[3][2] = {{0, 1}, {0, 2}, {1, 2}};   /* xy, xz, yz: CGAL's order */
    const double *pts[4] = {p0, p1, p2, p};
    mpz_ptr z[DD_PRED_SCRATCH];
    load_weighted(ctx, pts, w, 4, z);
    lift_rows(z, 4);
    int cmp = 0;
    for (int k = 0; k < 3; k++) {
        const int i = proj[k][0], j = proj[k][1];
        mpz_ptr a[3] = {z[i], z[j], z[3]}, b[3] = {z[4 + i], z[4 + j], z[7]}, c[3] = {z[8 + i], z[8 + j], z[11]};
        cmp = sign_det3(a, b, c, &z[16]);
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

int dd_power_compare_distance(dd_pred *ctx, const double *p, const double *a, double wa, const double *b,
                              double wb)
{
    const int f = power_distance_filter(p, a, wa, b, wb);
    if (f != DD_FILTER_UNSURE) return f;
    const double *pts[3] = {p, a, b};
    const double w[3] = {0, wa, wb};
    mpz_ptr z[DD_PRED_SCRATCH];
    load_weighted(ctx, pts, w, 3, z);
    mpz_sub(z[12], z[11], z[7]);                 /* Wb - Wa */
    for (int c = 0; c < 3; c++) {
        mpz_sub(z[13], z[c], z[4 + c]);
        mpz_addmul(z[12], z[13], z[13]);
        mpz_sub(z[13], z[c], z[8 + c]);
        mpz_submul(z[12], z[13], z[13]);
    }
    return mpz_sgn(z[12]);
}
