/*
 * refine_rule.h -- the rule of the refinement bench (dtdel refine-bench)
 * and of its test: which cells are queued, with what priority, and
 * which point refines them.  One C function, so that our loop and
 * CGAL's (src/cgal/cgal_refine.cpp, which gets it as a callback) queue
 * the same cells in the same order and insert the same points, bit for
 * bit: both must then end in the same triangulation.
 *
 * A finite cell is queued when its circumcentre, computed in plain
 * doubles from its vertices taken in ascending input index, lies in the
 * box [lo, hi]; its priority is the squared circumradius, larger first;
 * ties go to the cell whose sorted vertex indices are lexicographically
 * smaller (refine_before).
 */
#ifndef DD_REFINE_RULE_H
#define DD_REFINE_RULE_H

#include <stdint.h>

/* q[0..3]: the cell's points in ascending input index.  Writes the
 * circumcentre to c and its squared radius to *r2; returns 1 if the cell
 * is queued (centre in [lo, hi], finite), else 0.                       */
static inline int refine_rule(const double *const q[4], const double lo[3], const double hi[3], double c[3],
                              double *r2)
{
    double u[3], v[3], w[3];
    for (int k = 0; k < 3; k++) {
        u[k] = q[1][k] - q[0][k];
        v[k] = q[2][k] - q[0][k];
        w[k] = q[3][k] - q[0][k];
    }
    const double vw[3] = {v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2], v[0] * w[1] - v[1] * w[0]};
    const double wu[3] = {w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]};
    const double uv[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double den = 2 * (u[0] * vw[0] + u[1] * vw[1] + u[2] * vw[2]);
    const double lu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2], lv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2],
                 lw = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    double d[3];
    for (int k = 0; k < 3; k++) d[k] = (lu * vw[k] + lv * wu[k] + lw * uv[k]) / den;
    *r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    int in = den != 0 && *r2 < 1e300;
    for (int k = 0; k < 3; k++) {
        c[k] = q[0][k] + d[k];
        in &= c[k] >= lo[k] && c[k] <= hi[k];
    }
    return in;
}

/* Whether the entry (r2a, a[4] sorted) comes out of the queue before
 * (r2b, b[4]).                                                          */
static inline int refine_before(double r2a, const int32_t a[4], double r2b, const int32_t b[4])
{
    if (r2a != r2b) return r2a > r2b;
    for (int k = 0; k < 4; k++)
        if (a[k] != b[k]) return a[k] < b[k];
    return 0;
}

#endif
