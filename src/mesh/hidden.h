/*
 * hidden.h -- the hidden points of a regular triangulation (DESIGN 12):
 * the one module that knows where they live.  Every other file asks it;
 * none walks its lists.
 *
 * A weighted point is hidden when its lifted point (p, |p|^2 - w) lies
 * above the lower hull of the lifted vertices (under the perturbation):
 * it is no vertex, and CGAL's default cell base keeps it in the cell that
 * contains it.  So do we, with DD_DISCARD_HIDDEN (Mesh_3's compact cell
 * base) forgetting it instead.
 *
 * Where they live.  Per cell, a singly linked list of the hidden points
 * whose point lies in the cell's closure (head[c], then next[v]), as
 * CGAL's Regular_triangulation_cell_base_3 keeps them; per hidden point
 * its cell (cell[v], DD_NONE when v is not hidden), so that "is v
 * hidden" and "where is v" are O(1); and a dense list of them (all[],
 * with at[v] the position of v) so that listing them is O(h).  Per
 * vertex, nin[x] bounds from above the hidden points in the cells
 * through x (each point counts once for each corner of its cell; a point
 * forgotten by dd_hidden_forget is not taken off): 0 lets a deletion of
 * x skip its star's lists.  Cost: 4 bytes a cell and 20 a vertex id,
 * only in weighted triangulations that keep hidden points; nothing in
 * the others (t->hid is NULL there).
 *
 * Which cell.  A point on a face shared by several cells (a facet, an
 * edge, a vertex's position) is kept in whichever of them the walk that
 * placed it ended in.  CGAL keeps it in the first cell of its closure
 * that its locate enters from the hint (insert(p, hint); the hidden point
 * visitor's chain from the new vertex's cell; remove()'s re-insertions
 * from the cell across v's facet): a walk trying facets in the order of
 * CGAL's own vertex numbering of each cell (its stochastic part draws
 * from a generator seeded afresh in each call), so the cell depends on
 * the caller's hint and on that numbering, neither of which the engine
 * has.  The cells and the hidden set never depend on it: a kept point is
 * looked at again only when a deletion's star holds its cell, and
 *  - a point that can come back lies inside the star's union (one on
 *    its boundary would be a vertex on a face of a cell the deletion
 *    keeps), where every cell whose closure holds it is in the star: all
 *    its exact copies are taken whatever cell keeps them; one comes back,
 *    the others are forgotten (no vertex has a hidden exact copy);
 *  - a point on a face stays hidden whichever of its cells is asked: the
 *    power distances to the orthospheres of two cells sharing the face
 *    differ by an affine function that vanishes on it, also under the
 *    symbolic perturbation, which is one of the weights.
 * test_wdelete's shared_facet_case makes CGAL keep two copies in two
 * cells (dd_cgal_rt_insert_in) and compares.
 *
 * Edits.  An insertion whose conflict region is about to be replaced
 * takes the lists of those cells and notes their vertices
 * (dd_hidden_take_region, before the mesh changes: the only step that
 * can fail); once the star is in, dd_hidden_settle turns the vertices it
 * swallowed into hidden points (or forgets them) and re-homes every
 * point taken, each by an exact walk from the new star, as CGAL's
 * Hidden_point_visitor does.  A deletion (issue 44) does the same with
 * the deleted vertex's star: dd_hidden_take(cells, q) hands it the star's
 * hidden points, it decides which come back as vertices
 * (dd_hidden_release for those), and dd_hidden_settle re-homes the rest
 * in the new cells, each walk starting at the new cell over the link
 * triangle of the cell it was taken from.  Cost: one walk of a few
 * cells per point re-homed.
 *
 * Invariants (dd_hidden_check proves them): a dead cell's list is empty;
 * a cell at or past ncap has an empty list; cell[v] == c iff v is on c's
 * list, and then v is no vertex, its point is in the closure of the
 * finite cell c, and (p, w) is not in conflict with c: hidden; and no
 * vertex carries v's weighted point exactly (CGAL keeps no such copy).
 */
#ifndef DD_HIDDEN_H
#define DD_HIDDEN_H

#include "mesh/mesh.h"

typedef struct dd_hidset {
    int keep;               /* 0: DD_DISCARD_HIDDEN, the lists stay empty */
    uint32_t *head, ncap;   /* per cell: its first hidden point or DD_NONE */
    uint32_t *next, *cell, *at, vcap;   /* per vertex id (see above)     */
    uint32_t *nin;          /* per vertex id: at least the number of
                               hidden points in the cells of its star   */
    dd_vec all;             /* the hidden vertex ids, in no order        */
    dd_vec taken;           /* points taken, waiting to be re-homed      */
    dd_vec seen;            /* vertices of the cells replaced            */
} dd_hidset;

/* Makes t weighted's hidden-point state (keep: 1 keeps hidden points,
 * 0 forgets them).  DD_ERR_NOMEM.                                       */
dd_status dd_hidden_init(dd_tri *t, int keep);
void dd_hidden_free(dd_tri *t);

/* 1 if vertex id v is a kept hidden point.  O(1). */
static inline int dd_hidden_has(const dd_tri *t, uint32_t v)
{
    const dd_hidset *h = t->hid;
    return h && v < h->vcap && h->cell[v] != DD_NONE;
}

/* Number of kept hidden points. */
static inline size_t dd_hidden_count(const dd_tri *t) { return t->hid ? t->hid->all.n : 0; }

/* Hides the new point v (no vertex, not hidden) in cell c, a finite cell
 * whose closure holds it; a no-op when hidden points are forgotten.
 * DD_ERR_NOMEM, nothing changed.  O(1) amortised.                       */
dd_status dd_hidden_add(dd_tri *t, uint32_t c, uint32_t v);

/* Before the conflict cells t->conflict are replaced by the star over
 * t->boundary: reserves room (the lists of the new cells, the scratch),
 * then takes the hidden points of those cells and notes their vertices.
 * DD_ERR_NOMEM with nothing changed; after success the caller must
 * replace the cells and call dd_hidden_settle.  O(region + its hidden
 * points).                                                              */
dd_status dd_hidden_take_region(dd_tri *t);

/* Takes the hidden points of the live cells cells[0..n), the star of
 * vertex q, into the list to re-home (their lists emptied), and returns
 * them in *pts, *npts (valid until the next call here).  Each remembers
 * the facet outside the star across its cell's facet opposite q, where
 * dd_hidden_settle starts the walk that re-homes it.  DD_ERR_NOMEM with
 * nothing changed.  For deletions (issue 44): a point it takes must be
 * released or re-homed.  O(n) loads, no writes when none is hidden.   */
dd_status dd_hidden_take(dd_tri *t, const uint32_t *cells, size_t n, uint32_t q, const uint32_t **pts,
                         size_t *npts);

/* Makes room for hidden points in cells of id below ncells, so that a
 * deletion's dd_hidden_settle can re-home points in the cells it makes
 * (issue 44).  DD_ERR_NOMEM with nothing changed; a no-op when hidden
 * points are forgotten.                                                 */
dd_status dd_hidden_room(dd_tri *t, size_t ncells);

/* Removes taken point v from the points to re-home and from the hidden
 * set (it becomes a vertex again, or is forgotten).  O(taken).         */
void dd_hidden_release(dd_tri *t, uint32_t v);

/* After the cells are replaced (t->hint a new cell): every noted vertex
 * whose cell link died (swallowed) stops being a vertex and is hidden,
 * or forgotten; every taken point is re-homed in a cell of the new mesh
 * by an exact walk.  Cannot fail on a valid mesh (room was reserved);
 * DD_ERR_INTERNAL if a walk does not end.                               */
dd_status dd_hidden_settle(dd_tri *t);

/* The input indices of the kept hidden points, sorted, in *idx
 * (dd_malloc'd; NULL when none).  DD_ERR_NOMEM.  O(h log h).           */
dd_status dd_hidden_inputs(const dd_tri *t, uint32_t **idx, size_t *n);

/* The validator's part (dd_mesh_check): the invariants above, on the
 * predicates pr.  DD_OK, or DD_ERR_INTERNAL with what is wrong in msg. */
dd_status dd_hidden_check(const dd_tri *t, dd_pred *pr, char *msg, size_t msglen);

/* Bytes held (capacity). */
size_t dd_hidden_bytes(const dd_tri *t);

#endif
