/*
 * wbench.h -- what the weighted benches (wbench.c: per-degree
 * deletion tables; wbench_edits.c: re-weighting, move and set passes)
 * share: the weighted points of a dataset, both triangulations built in
 * the same hidden mode, and the whole-triangulation comparison with CGAL
 * (canonical cells and hidden set).
 */
#ifndef DD_BENCH_WBENCH_H
#define DD_BENCH_WBENCH_H

#include "bench/bench.h"
#include "cgal/cgal_rbench.h"

/* A weighted case: the points, our triangulation and CGAL's, one mode. */
typedef struct wpair {
    double *xyz, *w;
    uint32_t np;
    int discard;
    dd_tri *t;
    dd_cgal_rb *c;
} wpair;

/* Generates n points of the weighted dataset and builds both sides in
 * the mode (discard: DD_DISCARD_HIDDEN and Discard_hidden_points).  0,
 * or EXIT_INPUT after a message naming cmd (p freed).                   */
int wpair_build(const char *cmd, const char *dataset, uint32_t n, uint64_t seed, int discard, wpair *p);
void wpair_free(wpair *p);
/* The checks that differ between t and c: 1 for the cells, 1 for the
 * hidden set (O(n) each).                                               */
long wpair_compare(const dd_tri *t, const dd_cgal_rb *c);
/* "hidden points kept" or "hidden points discarded". */
const char *wmode_name(int discard);

#endif
