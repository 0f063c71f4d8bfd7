/*
 * cgal_rbench.h -- CGAL's Regular_triangulation_3 as the bench's reference
 * for weighted edits (issue 44, DESIGN 10 and 12): the kernel, vertex base
 * and cell bases of cgal_regular.h, both hidden-point policies, but every
 * vertex handle kept per input index, so that a timed call is CGAL's
 * remove(vh), move(vh, wp) or insert(wp, hint) alone.  The bookkeeping
 * that names the vertices and hidden points by input index after an edit
 * (the hidden points a removal brings back, the vertices an insertion
 * hides) runs after the clock stops and costs O(the edit's region), never
 * O(n).
 *
 * Each input index is in one state: a vertex, a kept hidden point, or
 * none (removed, forgotten under Discard_hidden_points, or an exact
 * duplicate collapsed at build, as cgal_regular.h collapses them).  An
 * index whose state is none may be given a weighted point again
 * (dd_cgal_rb_insert), so a deleted vertex comes back under its own index
 * and a moved one keeps it.  Times are seconds of a monotonic clock
 * around CGAL's call.  No function throws; each returns 0 on success.
 */
#ifndef DD_CGAL_RBENCH_H
#define DD_CGAL_RBENCH_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct dd_cgal_rb dd_cgal_rb;

enum { DD_RB_NONE = 0, DD_RB_VERTEX = 1, DD_RB_HIDDEN = 2 };

/* The regular triangulation of the n weighted points (CGAL's range insert,
 * input index i for point i); discard_hidden: 1 forgets hidden points.
 * NULL when CGAL cannot (fewer than 4 points, less than 3D, not finite). */
dd_cgal_rb *dd_cgal_rb_build(const double *xyz, const double *w, uint32_t n, int discard_hidden);
void dd_cgal_rb_free(dd_cgal_rb *c);
/* DD_RB_NONE, DD_RB_VERTEX or DD_RB_HIDDEN (NONE for an unknown index). */
int dd_cgal_rb_state(const dd_cgal_rb *c, uint32_t i);

/* CGAL's remove() of vertex i, timed alone into *secs.  Hidden points of
 * its star that are no longer hidden become vertices again under their
 * indices (dd_cgal_rb_released lists them).  0 done; 1 when i is no
 * vertex or on failure; 3 when the vertices left would span less than 3D
 * (refused, nothing changed).                                           */
int dd_cgal_rb_remove(dd_cgal_rb *c, uint32_t i, double *secs);
/* The indices the last dd_cgal_rb_remove made vertices again, and the
 * finite neighbours the removed vertex had (both valid until the next
 * edit).  Their union holds every vertex of the cells the removal made. */
size_t dd_cgal_rb_released(const dd_cgal_rb *c, const uint32_t **idx);
size_t dd_cgal_rb_last_neighbors(const dd_cgal_rb *c, const uint32_t **idx);

/* CGAL's insert(wp, hint) of (p, w) under index i (its state must be
 * none; i below the build's n), timed alone into *secs; hint: an input
 * index whose vertex starts the walk (UINT32_MAX or a non-vertex: the
 * last vertex made).  The point may end hidden (or forgotten), and may
 * hide vertices.  0 done; 2 when (p, w) is a vertex's weighted point
 * (nothing changes); 1 on any other failure.                            */
int dd_cgal_rb_insert(dd_cgal_rb *c, uint32_t i, const double p[3], double w, uint32_t hint, double *secs);
/* Moves vertex i to (p, w), keeping its index: CGAL's move(vh, wp) where
 * it gives the reference result (remove, then insert: DESIGN 12), else
 * remove(vh) then insert(wp, hint at a former neighbour), *fell_back 1.
 * move() is used when (checked untimed, by CGAL's own locate and conflict
 * search) the new point lands in no vertex, is not hidden, hides no
 * vertex, and, with hidden points kept, neither its conflict zone nor
 * the star of i holds a hidden point (move() drops those); a pure
 * re-weighting always falls back (move() ignores a weight change at the
 * same position).  *secs: CGAL's calls alone.  0 done; 1 on failure; 2
 * when (p, w) is another vertex's weighted point; 3 as remove.         */
int dd_cgal_rb_move(dd_cgal_rb *c, uint32_t i, const double p[3], double w, double *secs, int *fell_back);

/* Canonical cells (as dd_canonical), the sorted kept hidden indices as
 * CGAL's cells store them, and the canonical cells incident to the
 * vertices vs[0..k) (as dd_local_canonical; 1 if one is no vertex).
 * Arrays malloc'd, caller frees.  The first two are O(n).               */
int dd_cgal_rb_canonical(const dd_cgal_rb *c, int32_t **tets, size_t *ntets);
int dd_cgal_rb_hidden(const dd_cgal_rb *c, uint32_t **idx, size_t *n);
int dd_cgal_rb_local_canonical(const dd_cgal_rb *c, const uint32_t *vs, size_t k, int32_t **tets, size_t *ntets);

#ifdef __cplusplus
}
#endif
#endif
