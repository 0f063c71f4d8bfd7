/*
 * lift.c -- the parts of the lifted filter that are not inline (lift.h,
 * lift_pass.h): the classification of a frame from its points, the
 * shifted lifts, a frame's rows in columns and its lexicographic ranks.
 *
 * Invariant: as lift.h's; the shifted lifts change no determinant, only
 * the fourth column's magnitudes and so the bound.
 */
#include "geom/lift_pass.h"
#include "geom/expansion.h"
#include "geom/pred.h"

#include <math.h>
#include <string.h>

dd_lift_frame dd_lift_frame_of(const double *q, const double *const *pts, uint32_t n)
{
    double m = 0, l[4];
    for (uint32_t k = 0; k < n; k++) m = dd_lift_max(m, dd_lift_row(l, pts[k], q));
    int integral = m <= DD_LIFT_INT_O && dd_lift_is_int3(q);   /* beyond the largest limit no mode holds */
    for (uint32_t k = 0; k < n && integral; k++) integral = dd_lift_is_int3(pts[k]);
    return dd_lift_classify(integral, m);
}

/* The centre C of the sphere through q and the lifted points a, b, c
 * solves 2 (x - q) . C = |x - q|^2 for x = a, b, c (Cramer's rule on the
 * rounded lifts: any finite C keeps every determinant, a good one only
 * makes the shifted lifts small).                                        */
double dd_shift_lifts(const double *const *pts, uint32_t n, const double *q, const double *a, const double *b,
                      const double *c, double m, double err, double *w)
{
    double bc[3] = {b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0]};
    double ca[3] = {c[1] * a[2] - c[2] * a[1], c[2] * a[0] - c[0] * a[2], c[0] * a[1] - c[1] * a[0]};
    double ab[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    if (!(m >= DD_LIFT_M_MIN && m <= 0x1p150)) return 0;
    double den = 2 * (a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2]), C[3], M = 0;
    for (int i = 0; i < 3; i++) {
        C[i] = (a[3] * bc[i] + b[3] * ca[i] + c[3] * ab[i]) / den;
        if (!(fabs(C[i]) <= 0x1p150)) return 0;    /* also NaN, inf */
    }
    for (uint32_t k = 0; k < n; k++) {
        w[k] = dd_exp_shifted_lift(pts[k], q, C);
        if (fabs(w[k]) > M) M = fabs(w[k]);
    }
    double e = 5e-12 * m * m * m * M;
    return e >= 1e-290 && M >= 1e-300 && e < err ? e : 0;
}

/* ---- the rows of a frame, its ranks (lift_pass.h) ------------------------ */

/* The rows as dd_lift_row makes them, in columns; integrality as
 * dd_lift_frame_of tests it (a mode needs m <= DD_LIFT_INT_O).          */
dd_lift_frame dd_lift_rows(double *const *L, const double *const *pts, uint32_t n, const double *q)
{
    double m = 0;
    int integral = dd_lift_is_int3(q);
    for (uint32_t k = 0; k < n; k++) {
        const double *p = pts[k];
        for (int i = 0; i < 3; i++) {
            L[i][k] = p[i] - q[i];
            m = dd_lift_max(m, fabs(L[i][k]));
        }
        integral = integral && dd_lift_is_int3(p);
        L[3][k] = L[0][k] * L[0][k] + L[1][k] * L[1][k] + L[2][k] * L[2][k];
    }
    for (uint32_t k = n; k % 4; k++)               /* the AVX2 passes' padding */
        for (int i = 0; i < 4; i++) L[i][k] = NAN;
    return dd_lift_classify(integral, m);
}

/* As dd_lift_rows, the fourth coordinate less dw = wt[k] - qw (lift.h's
 * weighted lift).  O(n).                                                 */
dd_lift_frame dd_lift_rows_power(double *const *L, const double *const *pts, const double *wt, uint32_t n,
                                 const double *q, double qw, double *wmax)
{
    double m = 0, W = 0;
    int integral = dd_lift_is_int3(q);
    for (uint32_t k = 0; k < n; k++) {
        const double *p = pts[k];
        for (int i = 0; i < 3; i++) {
            L[i][k] = p[i] - q[i];
            m = dd_lift_max(m, fabs(L[i][k]));
        }
        integral = integral && dd_lift_is_int3(p);
        const double dw = wt[k] - qw;
        W = dd_lift_max(W, fabs(dw));
        L[3][k] = (L[0][k] * L[0][k] + L[1][k] * L[1][k] + L[2][k] * L[2][k]) - dw;
    }
    for (uint32_t k = n; k % 4; k++)               /* the AVX2 passes' padding */
        for (int i = 0; i < 4; i++) L[i][k] = NAN;
    *wmax = W;
    return dd_lift_classify(integral, m);
}

/* Index sort by dd_lex_cmp: insertion while short, else bottom-up
 * merges through tmp and rank; then rank inverts the order.           */
void dd_lex_ranks(const double *const *pts, uint32_t n, uint32_t *tmp, uint32_t *rank)
{
    uint32_t *a = tmp, *b = rank;
    for (uint32_t k = 0; k < n; k++) a[k] = k;
    for (uint32_t i = 1; i < n && n <= 32; i++) {
        uint32_t v = a[i], j = i;
        for (; j > 0 && dd_lex_cmp(pts[a[j - 1]], pts[v]) > 0; j--) a[j] = a[j - 1];
        a[j] = v;
    }
    for (uint32_t width = 1; n > 32 && width < n; width *= 2) {
        for (uint32_t lo = 0; lo < n; lo += 2 * width) {
            uint32_t mid = lo + width < n ? lo + width : n, hi = lo + 2 * width < n ? lo + 2 * width : n;
            uint32_t i = lo, j = mid, k = lo;
            while (i < mid && j < hi) b[k++] = dd_lex_cmp(pts[a[j]], pts[a[i]]) < 0 ? a[j++] : a[i++];
            while (i < mid) b[k++] = a[i++];
            while (j < hi) b[k++] = a[j++];
        }
        uint32_t *x = a;
        a = b;
        b = x;
    }
    if (a == rank) memcpy(tmp, a, n * sizeof *a);
    for (uint32_t k = 0; k < n; k++) rank[tmp[k]] = k;
}

/* x * x - x * x is 0 unless contracted into fma(x, x, -(x * x)), the
 * rounding error of x * x, not 0 for this x; volatile, so that it is
 * evaluated at run time, as the filters are.                            */
int dd_fp_fused(void)
{
    volatile double v = 1.0 + 0x1p-30;
    const double x = v;
    volatile double r = x * x - x * x;
    return r != 0;
}
