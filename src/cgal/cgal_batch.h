/*
 * cgal_batch.h -- CGAL's best for the batch rows of `dtdel batch-bench`
 * (issue 56): a Delaunay_triangulation_3 or a Regular_triangulation_3
 * (Epick, hidden points kept, vertex info = input index) and
 *  - insert(first, last): CGAL's range insertion of pairs (point, index),
 *    which sorts them spatially (BRIO, Hilbert) itself;
 *  - a batch of queries located as CGAL's documentation advises:
 *    CGAL::spatial_sort of the queries, then locate(p, hint) with the
 *    previous answer as the hint.
 * Times are seconds of a monotonic clock around CGAL's calls alone (the
 * conversion to CGAL's points, the copy out of the answers outside).
 * No function throws; each returns 0 on success.
 */
#ifndef DD_CGAL_BATCH_H
#define DD_CGAL_BATCH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct dd_cgalb dd_cgalb;

/* The DT (w NULL) or regular triangulation of n points, CGAL's range
 * insert, input index i for point i.  NULL if CGAL cannot.             */
dd_cgalb *dd_cgalb_build(const double *xyz, const double *w, uint32_t n);
void dd_cgalb_free(dd_cgalb *g);
/* insert(first, last) of m points (weights w on a regular one), indices
 * first, first + 1, ...; *secs the range insert alone.                  */
int dd_cgalb_insert_range(dd_cgalb *g, const double *xyz, const double *w, size_t m, uint32_t first, double *secs);
/* spatial_sort of the m queries, then a locate loop hinted by the last
 * answer (a DT only); cells[4i..] the vertices of query i's cell (-1 for
 * the infinite vertex); *secs the sort and the loop.                    */
int dd_cgalb_locate_sorted(const dd_cgalb *g, const double *q, size_t m, int32_t *cells, double *secs);
/* Canonical form (as dd_canonical): malloc'd, the caller frees.         */
int dd_cgalb_canonical(const dd_cgalb *g, int32_t **tets, size_t *ntets);

#ifdef __cplusplus
}
#endif
#endif
