/*
 * relocate.c -- the relocation filter: whether moving a vertex changes no
 * combinatorics (Devillers, de Castro, Teillaud et al., "Filtering
 * relocations on a Delaunay triangulation", SGP 2009, whose certificates
 * these are, decided exactly here rather than by tolerance regions).
 *
 * Moving vertex v to p changes only the cells of v's star and the signs
 * that involve v.  The mesh with v's point replaced is the perturbed
 * DT(S - v + p) iff it is still a triangulation and every facet is
 * locally Delaunay (the Delaunay lemma, which the perturbation keeps):
 *  - every finite cell of the star positively oriented (the other cells
 *    keep their points, hence their orientation);
 *  - every facet of a star cell locally Delaunay under the perturbed
 *    conflict test, infinite cells included: across a hull facet this is
 *    the hull's local convexity, which makes the boundary of the finite
 *    cells a convex surface again.
 * The perturbation depends on the lexicographic rank of v, which the move
 * changes: every test is made with v at p, so each sign is the one the
 * moved set defines.
 */
#include "mesh/mesh.h"

/* Whether every star cell's facet is locally Delaunay, v at its new
 * point: across each facet, the vertex opposite it (if finite) is not in
 * conflict with the cell; when that vertex is the infinite one, the
 * cell's own opposite vertex is tested against the infinite neighbour.  */
static int star_locally_delaunay(dd_tri *t, const dd_vec *star)
{
    for (size_t k = 0; k < star->n; k++) {
        const uint32_t c = star->a[k];
        for (uint32_t i = 0; i < 4; i++) {
            const uint32_t f = dd_tn(t, c)[i], n = f >> 2, o = dd_tv(t, n)[f & 3];
            if (o != DD_INF) {
                if (dd_cell_conflict(t, c, dd_pt(t, o))) return 0;
            } else if (dd_tv(t, c)[i] != DD_INF && dd_cell_conflict(t, n, dd_pt(t, dd_tv(t, c)[i]))) {
                return 0;
            }
        }
    }
    return 1;
}

int dd_relocation_keeps(dd_tri *t, uint32_t v, const double p[3], dd_status *err)
{
    *err = dd_star_cells(t, v, &t->conflict);
    if (*err != DD_OK) return 0;
    double *x = t->xyz + 3 * (size_t)v, old[3] = {x[0], x[1], x[2]};
    x[0] = p[0], x[1] = p[1], x[2] = p[2];
    int keep = 1;
    for (size_t k = 0; k < t->conflict.n && keep; k++) {
        const uint32_t *w = dd_tv(t, t->conflict.a[k]);
        if (w[0] == DD_INF || w[1] == DD_INF || w[2] == DD_INF || w[3] == DD_INF) continue;
        keep = dd_orient3d(&t->pred, dd_pt(t, w[0]), dd_pt(t, w[1]), dd_pt(t, w[2]), dd_pt(t, w[3])) > 0;
    }
    keep = keep && star_locally_delaunay(t, &t->conflict);
    if (!keep) x[0] = old[0], x[1] = old[1], x[2] = old[2];
    return keep;
}
