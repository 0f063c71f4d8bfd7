/*
 * cgal_rpred.h -- CGAL's predicates of regular triangulations, exposed to
 * C for the tests of src/geom/power.h (DESIGN 7, 12).
 *
 * Every call evaluates CGAL's own code over Exact_predicates_inexact_
 * constructions_kernel on weighted points (p, w): the kernel's power test
 * and power-distance comparison, and Regular_triangulation_3's perturbed
 * rules (its protected side_of_oriented_power_sphere and
 * side_of_bounded_power_circle, and its public side_of_power_sphere on a
 * cell of a small regular triangulation that holds the cell's points).
 * Signs are CGAL's enums as ints: +1 ON_POSITIVE_SIDE / ON_BOUNDED_SIDE
 * (conflict), -1 the other side, 0 on.  No function throws.
 */
#ifndef DD_CGAL_RPRED_H
#define DD_CGAL_RPRED_H

#ifdef __cplusplus
extern "C" {
#endif

/* Power_side_of_oriented_power_sphere_3(p0, p1, p2, p3, p); w[4] is p's. */
int dd_cgal_power_test(const double *p0, const double *p1, const double *p2, const double *p3,
                       const double *p, const double w[5]);
/* The same with 3 + 1 points (coplanar). */
int dd_cgal_power_test4(const double *p0, const double *p1, const double *p2, const double *p,
                        const double w[4]);
/* Regular_triangulation_3::side_of_oriented_power_sphere(p0..p3, p, perturb). */
int dd_cgal_power_sphere(const double *p0, const double *p1, const double *p2, const double *p3,
                         const double *p, const double w[5], int perturb);
/* Regular_triangulation_3::side_of_bounded_power_circle(p0, p1, p2, p, perturb). */
int dd_cgal_power_circle(const double *p0, const double *p1, const double *p2, const double *p,
                         const double w[4], int perturb);
/* side_of_power_sphere(c, p, true) where c is the finite cell of the
 * regular triangulation of the four weighted points p0..p3 (any
 * orientation).  0 on success, *res the sign; nonzero when CGAL's
 * triangulation of the four is not one tetrahedron.                    */
int dd_cgal_power_cell(const double *p0, const double *p1, const double *p2, const double *p3,
                       const double *p, const double w[5], int *res);
/* side_of_power_sphere(c, p, true) where c is the infinite cell over the
 * facet (a, b, c) of a regular triangulation of a, b, c and a fourth
 * point made on the side of the facet away from where orient3d(a, b, c,
 * .) > 0; w the weights of a, b, c, p.  0 on success, *res the sign;
 * nonzero when no such fourth point was found in doubles.               */
int dd_cgal_power_infinite(const double *a, const double *b, const double *c, const double *p,
                           const double w[4], int *res);
/* compare_power_distance_3(p, (a, wa), (b, wb)): -1, 0, +1. */
int dd_cgal_power_compare_distance(const double *p, const double *a, double wa, const double *b, double wb);

#ifdef __cplusplus
}
#endif
#endif
