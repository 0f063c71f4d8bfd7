/*
 * cgal_refine.h -- CGAL's side of the refinement bench (dtdel
 * refine-bench): a Delaunay_triangulation_3 (Epick, vertex info = input
 * index, cell info = a stamp) refined by its best method: the largest
 * queued cell's point is inserted with find_conflicts from that cell (in
 * conflict with it when the point is its circumcentre; else located from
 * it) and insert_in_hole, and the new cells, read off the hole's
 * boundary, are queued by the caller's rule.  Every call returns 0 on
 * success, nonzero on failure.
 */
#ifndef DD_CGAL_REFINE_H
#define DD_CGAL_REFINE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct dd_cgalr dd_cgalr;

/* The refinement rule (src/bench/refine_rule.h): q, the cell's points in
 * ascending input index; 1 if queued, with the point c to insert and the
 * priority *r2 (larger first, ties to the lexicographically smaller
 * sorted vertex indices).                                               */
typedef int (*dd_cgalr_rule)(const double *const q[4], const double lo[3], const double hi[3], double c[3],
                             double *r2);

/* DT of the n points (range insert); NULL if CGAL cannot.               */
dd_cgalr *dd_cgalr_build(const double *xyz, uint32_t n);
void dd_cgalr_free(dd_cgalr *g);
/* Queues every finite cell by the rule, then inserts the point of the
 * largest live queued cell, k times (fewer if the queue runs dry), the
 * new points numbered n, n + 1, ...; *done: how many were inserted.    */
int dd_cgalr_refine(dd_cgalr *g, uint32_t k, const double lo[3], const double hi[3], dd_cgalr_rule rule,
                    uint32_t *done);
/* Seconds the loop spent in the triangulation's part: the location of a
 * point not in conflict with its cell, find_conflicts, insert_in_hole. */
double dd_cgalr_core_seconds(const dd_cgalr *g);
/* Canonical form (as dd_canonical): malloc'd, the caller frees.         */
int dd_cgalr_canonical(const dd_cgalr *g, int32_t **tets, size_t *ntets);

#ifdef __cplusplus
}
#endif
#endif
