/*
 * cgal_query.h -- CGAL's counterparts of dtdel's location calls, for the
 * bench and the tests: a Delaunay_triangulation_3 (Epick, vertex info =
 * input index) with CGAL's default location (a walk from a hint) or with
 * Fast_location (CGAL's Delaunay hierarchy), and its insert(p, hint),
 * locate and nearest_vertex.  Every call returns 0 on success.
 */
#ifndef DD_CGAL_QUERY_H
#define DD_CGAL_QUERY_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct dd_cgalq dd_cgalq;

/* DT of the n points (range insert), fast = 1: with Fast_location.
 * NULL if CGAL cannot (fewer than 4 points or dimension < 3).           */
dd_cgalq *dd_cgalq_build(const double *xyz, uint32_t n, int fast);
void dd_cgalq_free(dd_cgalq *c);
/* insert(p, hint) with the last inserted vertex as the hint (the way a
 * mesh generator inserts a sequence), vertex info = index.              */
int dd_cgalq_insert(dd_cgalq *c, const double p[3], uint32_t index);
/* Removes the vertex of input index `index` (CGAL's remove()).          */
int dd_cgalq_remove(dd_cgalq *c, uint32_t index);
/* move_if_no_collision of the vertex of input index `index` to p; 1 if
 * p is another vertex's point (nothing moved).                          */
int dd_cgalq_move(dd_cgalq *c, uint32_t index, const double p[3]);
/* remove(first, last) of the vertices of the k input indices idx.       */
int dd_cgalq_remove_set(dd_cgalq *c, const uint32_t *idx, size_t k);
/* locate(p): the four vertices' indices of the cell found, -1 for the
 * infinite vertex.                                                      */
int dd_cgalq_locate(const dd_cgalq *c, const double p[3], int32_t cell[4]);
/* nearest_vertex(p): its index, or -1.                                  */
int64_t dd_cgalq_nearest(const dd_cgalq *c, const double p[3]);
/* Canonical form (as dd_canonical): malloc'd, the caller frees.         */
int dd_cgalq_canonical(const dd_cgalq *c, int32_t **tets, size_t *ntets);

#ifdef __cplusplus
}
#endif
#endif
