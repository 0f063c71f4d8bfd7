/*
 * bdst.h -- a spanning tree of maximum degree 3 of a triangulated 2-sphere,
 * in linear time (paper 4.2 "BRIO sampling": the guide T_i of GRR-BRIO,
 * the bounded-degree spanning tree of Choi [10]; DESIGN 6, paragraph
 * "Degree-3 spanning tree of a triangulated sphere").
 *
 * Input: nv vertices 0..nv-1 and ntri = 2*nv - 4 triangles tri[3k..3k+2],
 * consistently oriented: every directed edge a->b appears in exactly one
 * triangle and b->a in exactly one other.  Either orientation (inward or
 * outward) is accepted; only consistency matters.
 *
 * Output: parent[v] for every vertex (parent[root] = UINT32_MAX) of a
 * spanning tree whose edges are edges of the triangulation and in which
 * every vertex has degree <= 3 (the root has degree 1); optionally order[],
 * the vertices in breadth-first order from the root, children in the
 * order they were attached.
 *
 * Method: a canonical ordering v1..vn (de Fraysseix-Pach-Pollack) found by
 * peeling chordless contour vertices, then one pass over v3..vn that gives
 * each vk a parent among its earlier neighbours (see bdst.c for the rule
 * and the proof that no vertex ever gets a third child).
 *
 * Cost: O(nv) time (tests/test_bdst prints the time a vertex), about
 * 170 bytes a vertex of workspace, no allocation once the workspace has
 * grown to the largest nv seen.  The workspace holds all scratch state; no
 * globals.
 */
#ifndef DD_BDST_H
#define DD_BDST_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum dd_bdst_status {
    DD_BDST_OK = 0,
    DD_BDST_ENOMEM,    /* the workspace could not grow                      */
    DD_BDST_EARG,      /* ws, tri or parent is NULL                         */
    DD_BDST_ESIZE,     /* nv < 4, ntri != 2*nv - 4, or nv > DD_BDST_MAX_NV  */
    DD_BDST_EROOT,     /* root_hint >= nv and not UINT32_MAX                */
    DD_BDST_EVERTEX,   /* a triangle names a vertex >= nv or repeats one    */
    DD_BDST_EEDGE,     /* a directed edge appears twice, or without its
                          reverse: not a consistently oriented closed
                          surface, or two triangles share 3 vertices/edges  */
    DD_BDST_ELINK,     /* the triangles around a vertex do not form one
                          disc (pinched or isolated vertex)                 */
    DD_BDST_ETOPO,     /* closed oriented manifold with Euler
                          characteristic 2 but not connected: not a sphere  */
    DD_BDST_EINTERNAL, /* the degree bound broke: a bug, please report it   */
    DD_BDST_NUM_STATUS
} dd_bdst_status;

/* Largest accepted nv: the 6*nv half-edges must fit in 32 bits.          */
#define DD_BDST_MAX_NV (UINT32_MAX / 8u)

typedef struct dd_bdst_ws dd_bdst_ws;

/* A workspace, reusable across calls of any size (NULL if out of memory).
 * It grows on demand and never shrinks; one per thread.                  */
dd_bdst_ws *dd_bdst_ws_new(void);
void dd_bdst_ws_free(dd_bdst_ws *ws);

/* The spanning tree described above.  root_hint is the root (v1 of the
 * canonical ordering) or UINT32_MAX for "any" (then tri[0] is used).
 * order may be NULL.  Returns DD_BDST_OK (0) or one of the codes above;
 * on failure parent[] and order[] are left untouched.  The input is
 * checked in O(nv): counts, indices, edge pairing, vertex links and
 * connectivity, which together certify a triangulated (simplicial) sphere. */
int dd_bdst(dd_bdst_ws *ws, const uint32_t *tri, uint32_t ntri, uint32_t nv,
            uint32_t root_hint, uint32_t *parent, uint32_t *order);

/* Testing aids.  Seed 0 (the default) peels the contour vertices in LIFO
 * order; any other seed draws the vertex to peel pseudo-randomly, so that
 * other canonical orderings, and rule (C) of bdst.c, get exercised.  The
 * tree stays a function of (seed, input, root_hint).                     */
void dd_bdst_ws_set_seed(dd_bdst_ws *ws, uint64_t seed);
/* After a successful call: how many vertices got their parent by rule
 * (A) two-vertex path, (B) covered vertex, (C) fallback c_l (bdst.c);
 * counts[0] + counts[1] + counts[2] = nv - 2.                           */
void dd_bdst_ws_rule_counts(const dd_bdst_ws *ws, uint32_t counts[3]);

/* A short fixed name for a status ("ok", "size", "edge", ...).          */
const char *dd_bdst_status_name(int status);

#ifdef __cplusplus
}
#endif

#endif
