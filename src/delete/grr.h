/*
 * grr.h -- GRR-CONSTRUCT, guided randomized reinsertion (paper 4.2).
 *
 * Deletes the neighbours of q from the link DT one by one (LINKDTDELETE),
 * in an order chosen by the variant's sampling policy, recording a guide
 * for each; then builds the conflict DT of the four base points
 * (CREATEQCONFLICTDT) and re-inserts the deleted points in reverse order
 * (QCONFLICTDTINSERT), each located from its guide:
 *   - a vertex guide g (a link neighbour of p when p was deleted): gp is an
 *     edge of DT(P_i), so the cell around g that the segment g->p enters,
 *     or the link triangle at g it crosses, is destroyed by p; the cells
 *     of the conflict DT around g are tested and the first one in conflict
 *     with p starts Bowyer-Watson.  Cost: the degree of g.
 *   - a triangle guide abc (a triangle created by p's link deletion): the
 *     dummy cell (a,b,c,q_d) exists when p comes back and is destroyed by
 *     it; a hash table keyed by the vertex triple finds it in O(1).
 * The iterative loop here is the paper's recursion unrolled.  The base
 * points are never sampled, and neither is the infinite vertex.
 *
 * On a weighted t (issue 44) the same construction builds the conflict
 * regular triangulation of qdt.h: the link deletions and the locations
 * use the power test (link.c, and each location's compiled power copy,
 * chosen once per point), the base is taken among the neighbours, and
 * the star's hidden points follow the neighbours (dd_qdt_insert_hidden).
 * When the neighbours alone are coplanar the fill is sew-full's
 * (dd_full_fill_power).
 */
#ifndef DD_GRR_H
#define DD_GRR_H

#include "delete/delete.h"
#include "delete/link.h"

#define DD_LOWDEG 7   /* "low degree" in the paper's sampling rules */

typedef struct dd_grr dd_grr;

typedef struct dd_grr_policy {
    /* Chooses the next link vertex to delete.  For vertex guides, *guide
     * receives a finite link neighbour of it.                              */
    uint32_t (*sample)(dd_grr *g, uint32_t *guide);
    int triangle_guide;   /* guide = a triangle created by the deletion    */
    int full_dt;          /* build the full DT(P) (guide-only), not DT(x)  */
} dd_grr_policy;

/* GRR-CONSTRUCT: fills d->qdt and d->fill, on a weighted t or not. */
dd_status dd_grr_construct(dd_del *d, const dd_grr_policy *pol);

/* GRR-CONSTRUCT with grr-neighbor's guides, deleting first a link vertex
 * of least degree (dd_grr_sample_mindeg): auto's fill for large
 * cavities the wrap declines, weighted or not.                         */
dd_status dd_grr_fill_mindeg(dd_del *d);

/* ---- for sampling policies ------------------------------------------------ */

/* The paper's low-degree vertex sampling: a random link vertex of degree
 * <= 7, or (a counted fallback) a random remaining one when none is left. */
uint32_t dd_grr_sample_lowdeg(dd_grr *g);
/* A random link vertex of the least degree (base points excluded) if that
 * is <= 7, or (the same counted fallback) a random remaining one.      */
uint32_t dd_grr_sample_mindeg(dd_grr *g);
/* GRR-Edge's sampling (paper 5): u drawn uniformly among the link
 * vertices of degree <= 7, then its guide v uniformly among u's finite
 * neighbours with deg(u) + deg(v) <= 15; up to 8 draws of u.  Fallback
 * (counted): the last u drawn with its lowest-degree finite neighbour as
 * guide, or a random remaining vertex when none of degree <= 7 is left. */
uint32_t dd_grr_sample_edge(dd_grr *g, uint32_t *guide);
/* Link degree of v. */
uint32_t dd_grr_degree(const dd_grr *g, uint32_t v);
/* The finite neighbour of v of lowest degree. */
uint32_t dd_grr_lowest_neighbour(const dd_grr *g, uint32_t v);

/* ---- for constructions other than GRR-CONSTRUCT (grr-brio) --------------- */

/* Extracts the link of d->q and fills the sampling sets.  On a weighted
 * t the caller has picked the base among the neighbours
 * (dd_qdt_weighted_base).                                              */
dd_status dd_grr_begin(dd_del *d, dd_grr **out);
dd_link *dd_grr_link(dd_grr *g);
/* The link vertices still deletable (base points excluded). */
const uint32_t *dd_grr_remaining(const dd_grr *g, size_t *n);
/* LINKDTDELETE of p plus the bookkeeping of the sampling sets. */
dd_status dd_grr_delete_point(dd_grr *g, uint32_t p);
/* A cell of the conflict DT in conflict with p, found from the vertex
 * guide (or by a counted scan when the guide is DD_NONE or fails).       */
dd_status dd_grr_locate(dd_grr *g, uint32_t guide, uint32_t p, uint32_t *cell);

#endif
