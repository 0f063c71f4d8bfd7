/*
 * lift.c -- the parts of the lifted filter that are not inline (lift.h):
 * the classification of a frame from its points, and the shifted lifts.
 *
 * Invariant: as lift.h's; the shifted lifts change no determinant, only
 * the fourth column's magnitudes and so the bound.
 */
#include "geom/lift.h"
#include "geom/expansion.h"

#include <math.h>

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
