/*
 * cgal_regular.h -- the C face of CGAL's Regular_triangulation_3 (DESIGN 7,
 * 12): the reference for weighted points.
 *
 * It wraps Regular_triangulation_3 over Exact_predicates_inexact_
 * constructions_kernel, with info = input index on vertices, and keeps
 * hidden points (CGAL's default cell base, Keep_hidden_points) or forgets
 * them (Discard_hidden_points), as chosen at creation.  Hidden points are
 * reported by input index.  No function throws; each returns 0 on success,
 * nonzero on failure.
 *
 * Equal points: exact duplicates given to dd_cgal_rt_build (same position,
 * same weight) are collapsed first, the first index kept (as the Delaunay
 * shim keeps the first of equal points); the later copies are neither
 * vertices nor hidden.  Equal positions with different weights go to CGAL
 * as they are: the heaviest hides the others (CGAL's insert).
 */
#ifndef DD_CGAL_REGULAR_H
#define DD_CGAL_REGULAR_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct dd_cgal_rt dd_cgal_rt;

/* CGAL's regular triangulation of the n weighted points (xyz[3i..3i+2],
 * w[i]), built by CGAL's range insert (its own spatial sort), input index
 * i for point i.  discard_hidden: 1 forgets hidden points.  NULL when CGAL
 * cannot (fewer than 4 points, or the vertices span less than 3D).       */
dd_cgal_rt *dd_cgal_rt_build(const double *xyz, const double *w, uint32_t n, int discard_hidden);
void dd_cgal_rt_free(dd_cgal_rt *c);

/* Canonical cells (as dd_canonical: each cell's four input indices sorted,
 * -1 for the infinite vertex, the list sorted) and the sorted input
 * indices of the kept hidden points.  Arrays malloc'd, caller frees.
 * dd_cgal_rt_hidden fails (1) when CGAL hides a weighted point a number
 * of times other than the indices the handle lists for it: its copies
 * were dropped in a way the handle did not follow.                      */
int dd_cgal_rt_canonical(const dd_cgal_rt *c, int32_t **tets, size_t *ntets);
int dd_cgal_rt_hidden(const dd_cgal_rt *c, uint32_t **idx, size_t *n);
/* The sorted input indices of the vertices (malloc'd, caller frees). */
int dd_cgal_rt_vertices(const dd_cgal_rt *c, uint32_t **idx, size_t *n);

/* Inserts (p, w) as input index `index` (the next one: the number of
 * points given so far), hinted by the cell of the last inserted vertex,
 * as Mesh_3 inserts.  It may end hidden (or forgotten when discarding),
 * and may hide vertices.  0 on success; 2 when (p, w) equals a vertex's
 * weighted point exactly (CGAL returns that vertex: nothing changes, no
 * index taken); 1 on any other failure.  An exact duplicate of a kept
 * hidden point is hidden again, as CGAL does, under the new index.      */
int dd_cgal_rt_insert(dd_cgal_rt *c, const double p[3], double w, uint32_t index);
/* As dd_cgal_rt_insert, CGAL's walk starting from the finite cell whose
 * vertices are the input indices cell[0..4) (any order), as
 * insert(p, that cell) does; 1 also when there is no such cell.  Where
 * a hidden point lying on a face shared by several cells is kept is the
 * first of them that CGAL's walk from the hint enters, so this chooses
 * it (tests: the engine's result must not depend on it).  O(n).        */
int dd_cgal_rt_insert_in(dd_cgal_rt *c, const double p[3], double w, uint32_t index, const uint32_t cell[4]);
/* Number of input points given so far. */
uint32_t dd_cgal_rt_num_input(const dd_cgal_rt *c);

/* CGAL's Regular_triangulation_3::remove() of the vertex of input index
 * input_index (issue 44): the hidden points of its star that are no
 * longer hidden become vertices again (Keep_hidden_points), the others
 * stay hidden; read the result with dd_cgal_rt_canonical and
 * dd_cgal_rt_hidden.  0 done; 1 when input_index is no vertex (hidden,
 * removed, unknown) or on failure; 3 when the vertices left would span
 * less than 3D (then the triangulation is no longer usable).  Finding
 * the vertex is O(n).                                                   */
int dd_cgal_rt_remove(dd_cgal_rt *c, uint32_t input_index);

/* Forgets the kept hidden point of input index input_index (the
 * reference of dd_delete on a hidden point): its weighted point leaves
 * the hidden list of its cell; no cell changes.  0 done; 1 when it is no
 * kept hidden point.  O(n).                                             */
int dd_cgal_rt_forget(dd_cgal_rt *c, uint32_t input_index);

/* The reference of a weighted move (DESIGN 12): the point of input index
 * input_index (a vertex, or a kept hidden point) removed (remove(), or
 * forgotten), then (p, w) inserted under the same index, which may end
 * hidden (forgotten when discarding) and may hide others.  0 done (also
 * when (p, w) is its own weighted point: nothing changes); 2 when (p, w)
 * is exactly another point's weighted point that is a vertex, before or
 * after the removal (CGAL's insert would return that vertex, and the
 * index would be lost): before, nothing changes; after (a point the
 * removal brought back), the point is put back by insert(), and the
 * exact copies of the points brought back that remove() dropped stay
 * dropped, as with CGAL's remove() then insert(); 1 when the index is neither a
 * vertex nor a kept hidden point, or on failure; 3 as remove.  O(n).   */
int dd_cgal_rt_move(dd_cgal_rt *c, uint32_t input_index, const double p[3], double w);

/* (p, w) inserted again under input index `index`, one given before and
 * removed or forgotten since (the reference of dd_reinsert): as
 * dd_cgal_rt_insert otherwise.  0 done, 2 a vertex's weighted point
 * (nothing changes), 1 when the index is in the triangulation or on
 * failure.  O(n).                                                       */
int dd_cgal_rt_insert_as(dd_cgal_rt *c, const double p[3], double w, uint32_t index);

/* As dd_cgal_rt_move, where the removal may leave fewer than 4 vertices
 * or only coplanar ones: CGAL's remove() then drops the dimension (the
 * hidden points it re-inserts, and then (p, w), may raise it again).  0
 * done, the triangulation in 3D; 3 when it ends in less than 3D (then no
 * longer usable); 1 and 2 as dd_cgal_rt_move.  O(n).                   */
int dd_cgal_rt_move_any_dim(dd_cgal_rt *c, uint32_t input_index, const double p[3], double w);

#ifdef __cplusplus
}
#endif
#endif
