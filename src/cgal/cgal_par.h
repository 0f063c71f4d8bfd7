/*
 * cgal_par.h -- the anchor of the parallel construction rows of `dtdel
 * build-bench --threads N` (issue 59): CGAL's Delaunay_triangulation_3
 * with Parallel_tag (TBB, its Spatial_lock_grid_3 over the points'
 * bounding box), Epick, vertex info = input index, built by the range
 * insert of (point, index) pairs on at most N threads (tbb::global_control).
 * No function throws; each returns 0 (or non-NULL) on success.
 */
#ifndef DD_CGAL_PAR_H
#define DD_CGAL_PAR_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct dd_cgalp dd_cgalp;

/* The DT of n points on `threads` threads; *secs the construction alone
 * (the lock grid and the range insert).  NULL if CGAL cannot.          */
dd_cgalp *dd_cgalp_build(const double *xyz, uint32_t n, unsigned threads, double *secs);
void dd_cgalp_free(dd_cgalp *g);
/* Canonical form (as dd_canonical): malloc'd, the caller frees.         */
int dd_cgalp_canonical(const dd_cgalp *g, int32_t **tets, size_t *ntets);

#ifdef __cplusplus
}
#endif

#endif
