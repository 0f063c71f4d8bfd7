/*
 * cgal_shim.h -- the C face of the CGAL reference (DESIGN section 7).
 *
 * The only C++ in the project lives behind this header.  It wraps CGAL's
 * Delaunay_triangulation_3 with the Exact_predicates_inexact_constructions
 * kernel and Triangulation_vertex_base_with_info_3 (info = input index), so
 * the engine and the tests can compare against CGAL without C++.
 *
 * Duplicates: the shim keeps the first occurrence of a repeated point (as
 * the engine does), so vertex i exists iff point i is the first of its kind.
 * No function throws; every one returns 0 on success, nonzero on failure.
 */
#ifndef DD_CGAL_SHIM_H
#define DD_CGAL_SHIM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct dd_cgal dd_cgal;

/* Builds CGAL's DT of the n points xyz[3i..3i+2] (range insert, CGAL's own
 * spatial sort).  Returns NULL when CGAL cannot (fewer than 4 points or
 * dimension < 3).                                                         */
dd_cgal *dd_cgal_build(const double *xyz, uint32_t n);
void dd_cgal_free(dd_cgal *c);

/* Canonical form (as dd_canonical in dtdel.h): *tets is malloc'd, caller
 * frees.                                                                  */
int dd_cgal_canonical(const dd_cgal *c, int32_t **tets, size_t *ntets);

/* Canonical form of the cells incident to any of the input vertices
 * verts[0..nv) (deduplicated): the part of the triangulation a deletion
 * of their common neighbour can change.  Nonzero if one is no vertex.   */
int dd_cgal_local_canonical(const dd_cgal *c, const uint32_t *verts, size_t nv,
                            int32_t **tets, size_t *ntets);

/* CGAL's own remove() of input vertex v (triangulate-and-sew). */
int dd_cgal_remove(dd_cgal *c, uint32_t v);
/* cgal-rnd: the same triangulate-and-sew, but the temporary DT of v's
 * neighbours is built in a random order (seeded), then sewn into the hole
 * with CGAL's data structure.                                             */
int dd_cgal_remove_rnd(dd_cgal *c, uint32_t v, uint64_t seed);
/* Re-inserts input point v (which must have been removed) as vertex v. */
int dd_cgal_reinsert(dd_cgal *c, uint32_t v);
/* Inserts a new point p as input index `index`: the next one (the number
 * of points given so far), or the index of a removed vertex, reused (as
 * dd_insert numbers them).
 * Returns 0 when inserted, 2 when p equals a vertex (nothing changes, no
 * index taken: dd_insert's DD_ERR_DUPLICATE), 1 on any other failure.  */
int dd_cgal_insert(dd_cgal *c, const double p[3], uint32_t index);
/* Moves input vertex v to p with CGAL's move_if_no_collision, v keeping
 * its index.  Returns 0 when moved (or p is v's point), 2 when p is
 * another vertex's point and 3 when only coplanar points would remain
 * (nothing changes: dd_move's DD_ERR_DUPLICATE and DD_ERR_DIMENSION), 1
 * on any other failure.                                                  */
int dd_cgal_move(dd_cgal *c, uint32_t v, const double p[3]);
/* Number of input points so far (given to dd_cgal_build, then inserted). */
uint32_t dd_cgal_num_input(const dd_cgal *c);

/* CGAL's predicates, for the tests.  Signs as CGAL returns them:
 * orientation: +1 positive, -1 negative, 0 coplanar.
 * side_of_oriented_sphere(p0..p3 positively oriented, p): +1 inside.
 * coplanar_orientation: +1, -1, 0.
 * coplanar_side_of_bounded_circle: +1 inside (ON_BOUNDED_SIDE), -1 outside.
 * side_of_sphere_cell: CGAL's side_of_sphere for the cell (v0..v3), where
 *   inf_index in 0..3 names the infinite vertex (its point is ignored) or
 *   is -1 for a finite cell: +1 bounded side (conflict), -1 unbounded.    */
int dd_cgal_orientation(const double *p, const double *q, const double *r,
                        const double *s);
int dd_cgal_side_of_oriented_sphere(const double *p0, const double *p1,
                                    const double *p2, const double *p3,
                                    const double *p, int perturb);
int dd_cgal_coplanar_orientation(const double *p, const double *q,
                                 const double *r);
int dd_cgal_coplanar_side_of_bounded_circle(const double *p0,
                                            const double *p1,
                                            const double *p2,
                                            const double *p, int perturb);
int dd_cgal_side_of_sphere_cell(const double *v0, const double *v1,
                                const double *v2, const double *v3,
                                int inf_index, const double *p, int perturb);

/* "CGAL x.y.z" */
const char *dd_cgal_version(void);

#ifdef __cplusplus
}
#endif
#endif
