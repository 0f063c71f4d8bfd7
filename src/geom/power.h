/*
 * power.h -- exact, symbolically perturbed predicates of regular (weighted
 * Delaunay) triangulations (DESIGN 12), with the signs of CGAL's
 * Regular_triangulation_3 over Exact_predicates_inexact_constructions_kernel.
 *
 * Owns: the power test of a weighted point against the power sphere of a
 * cell (finite and infinite), CGAL's symbolic perturbation of it, the
 * coplanar power-circle test of an infinite cell, and the exact comparison
 * of power distances.  A weighted point (x, w) lifts to (x, |x|^2 - w); with
 * every weight zero each function here returns exactly what its Delaunay
 * counterpart of pred.h returns.
 *
 * Invariant: for every input of finite doubles (coordinates and weights
 * anywhere in the double range, subnormals included) every function
 * returns CGAL's sign.  Nothing here allocates, GMP included: the GMP
 * stages run in pred.h's scratch (dd_pred_exact), whose bounds cover the
 * weighted lifts.
 *
 * Signs ("conflict": inserting p would destroy the cell):
 *   power test of the positively oriented cell (p0,p1,p2,p3) and p:
 *     +1 conflict (p inside the power sphere), -1 not, 0 on it.  It is
 *     CGAL's Power_side_of_oriented_power_sphere_3(p0,p1,p2,p3,p): minus
 *     the sign of det(rows Pi - P, |Pi - P|^2 + w - wi), i = 0..3.
 *   w[i] is the weight of the i-th point argument, the query's last.
 */
#ifndef DD_POWER_H
#define DD_POWER_H

#include "geom/fp.h"   /* first: no contraction from here on */
#include "geom/pred.h"

#include <math.h>

/* ---- stage 1: CGAL's semi-static filter of the power test (its
 * Static_filters Power_side_of_oriented_power_sphere_3, 4+1 points): the
 * determinant in doubles in CGAL's evaluation order, accepted beyond
 * CGAL's certified bound 1.67106803095990471147e-13 * maxx*maxy*maxz *
 * max(maxw, max^2), maxw the largest |w - wi|, with CGAL's underflow and
 * overflow guards.  A zero coordinate column (all five points share an
 * x, y or z) makes the determinant exactly 0.  Returns the exact sign or
 * DD_FILTER_UNSURE.                                                      */
static inline int dd_power_filter(dd_pred *ctx, const double *p0, const double *p1, const double *p2,
                                  const double *p3, const double *p, const double w[5])
{
    (void)ctx;
    DD_COUNT(ctx, insphere_calls);
    const double tx = p[0], ty = p[1], tz = p[2], tw = w[4];
    double d[4][4];
    const double *v[4] = {p0, p1, p2, p3};
    double maxx = 0, maxy = 0, maxz = 0, maxw = 0;
    for (int i = 0; i < 4; i++) {
        const double dx = v[i][0] - tx, dy = v[i][1] - ty, dz = v[i][2] - tz, dw = tw - w[i];
        d[i][0] = dx;
        d[i][1] = dy;
        d[i][2] = dz;
        d[i][3] = ((dx * dx + dy * dy) + dz * dz) + dw;
        if (fabs(dx) > maxx) maxx = fabs(dx);
        if (fabs(dy) > maxy) maxy = fabs(dy);
        if (fabs(dz) > maxz) maxz = fabs(dz);
        if (fabs(dw) > maxw) maxw = fabs(dw);
    }
    const double lo = dd_min3(maxx, maxy, maxz), hi = dd_max3(maxx, maxy, maxz);
    if (lo == 0) return 0;
    /* NaN (an overflowed difference) fails every comparison below. */
    if (!(lo >= 1.05893684636332247212e-59) || (maxw < 1.12134724458589890404e-118 && maxw != 0) ||
        !(hi <= 3.21387608851797948065e+60) || !(maxw <= 1.03289995123476274781e+121))
        return DD_FILTER_UNSURE;
    /* CGAL's determinant(a00..a33), rows a0..a3 = d[0..3]. */
    const double m01 = d[1][0] * d[0][1] - d[0][0] * d[1][1];
    const double m02 = d[2][0] * d[0][1] - d[0][0] * d[2][1];
    const double m03 = d[3][0] * d[0][1] - d[0][0] * d[3][1];
    const double m12 = d[2][0] * d[1][1] - d[1][0] * d[2][1];
    const double m13 = d[3][0] * d[1][1] - d[1][0] * d[3][1];
    const double m23 = d[3][0] * d[2][1] - d[2][0] * d[3][1];
    const double m012 = m12 * d[0][2] - m02 * d[1][2] + m01 * d[2][2];
    const double m013 = m13 * d[0][2] - m03 * d[1][2] + m01 * d[3][2];
    const double m023 = m23 * d[0][2] - m03 * d[2][2] + m02 * d[3][2];
    const double m123 = m23 * d[1][2] - m13 * d[2][2] + m12 * d[3][2];
    const double det = m123 * d[0][3] - m023 * d[1][3] + m013 * d[2][3] - m012 * d[3][3];
    const double h2 = hi * hi;
    const double eps = 1.67106803095990471147e-13 * (((maxx * maxy) * maxz) * (maxw > h2 ? maxw : h2));
    if (det > eps) return -1;
    if (det < -eps) return 1;
    return DD_FILTER_UNSURE;
}

/* The power test's exact sign, unperturbed, for any finite doubles (the
 * filter is not run).  Cell positively oriented.                        */
int dd_power_exact(dd_pred *ctx, const double *p0, const double *p1, const double *p2, const double *p3,
                   const double *p, const double w[5]);

/* CGAL's symbolic perturbation of the power test (its
 * side_of_oriented_power_sphere with perturb = true), for when the exact
 * sign is 0: the five sorted by bare point (dd_lex_cmp, ties in argument
 * order); from the largest down, p first gives -1, a vertex gives the
 * orientation of the cell with that vertex replaced by p, when nonzero.
 * Never 0.                                                              */
int dd_power_symbolic(dd_pred *ctx, const double *p0, const double *p1, const double *p2, const double *p3,
                      const double *p, const double w[5]);

/* Filter, exact, symbolic in turn: a finite cell's conflict test (CGAL's
 * side_of_power_sphere(c, p, true)).  Never 0.                          */
int dd_power_perturbed(dd_pred *ctx, const double *p0, const double *p1, const double *p2, const double *p3,
                       const double *p, const double w[5]);

/* CGAL's side_of_power_sphere(c, p, true) for an infinite cell whose
 * finite facet is (a, b, c), listed as mesh.h's dd_facet lists it
 * (orient3d(a, b, c, x) > 0 iff x is on the infinite vertex's side); w
 * the weights of a, b, c, p.  +1 conflict (p beyond the facet, or in its
 * plane and inside its perturbed power circle), -1 not.  Never 0.       */
int dd_power_infinite(dd_pred *ctx, const double *a, const double *b, const double *c, const double *p,
                      const double w[4]);

/* CGAL's power_test(p0, p1, p2, p) for four coplanar weighted points
 * (Power_side_of_oriented_power_sphere_3, 3+1 points): the lifted 3x3
 * determinant in the xy projection, else xz, else yz, times the
 * orientation of p0 p1 p2 in that projection.  Exact, unperturbed.     */
int dd_power_coplanar(dd_pred *ctx, const double *p0, const double *p1, const double *p2, const double *p,
                      const double w[4]);

/* CGAL's side_of_bounded_power_circle(p0, p1, p2, p, perturb = true) for
 * four coplanar weighted points, p0 p1 p2 not collinear: +1 inside, -1
 * outside, independent of the order of p0, p1, p2.  Never 0.           */
int dd_power_circle_perturbed(dd_pred *ctx, const double *p0, const double *p1, const double *p2,
                              const double *p, const double w[4]);

/* Exact sign of pow(p, a) - pow(p, b), pow(p, a) = |p - a|^2 - wa: -1
 * when a is strictly nearer in power distance, 0 at a tie (CGAL's
 * compare_power_distance(p, a, b)).  Filtered, then exact.             */
int dd_power_compare_distance(dd_pred *ctx, const double *p, const double *a, double wa, const double *b,
                              double wb);

#endif
