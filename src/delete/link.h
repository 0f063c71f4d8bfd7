/*
 * link.h -- the link DT DT^l(Q_i) and LINKDTDELETE (paper 4.1-4.2).
 *
 * The link of q is a triangulated 2-sphere: one triangle per cell of q's
 * star (the facet opposite q).  It behaves like a 2D Delaunay
 * triangulation whose in-circle test for triangle abc and point w is the
 * in-sphere test of the tetrahedron (a,b,c,q) and w (with CGAL's rule when
 * one of a,b,c is the infinite vertex): deleting a link vertex is a
 * Delaunay deletion on that sphere.  On a weighted t (issue 44) the link
 * is q's in the regular triangulation and the test is the power test of
 * (a,b,c,q) with the weights (CGAL's perturbed one), the rest unchanged:
 * the ear argument only uses the lifting, which the weights change.
 *
 * Encoding (as the mesh, one dimension down): triangle t has vertices
 * lv[3t+0..2] and neighbours ln[3t+k] = 3u+j, u the triangle across the
 * edge opposite vertex k, j that edge's index in u; ln[ln[e]] == e.  Every
 * triangle is oriented as seen from q: orient3d(a, b, c, q) > 0 for a
 * finite one (the facet order of mesh.h).  Dead triangles have
 * lv[3t] == DD_DEAD.  Per vertex (indexed by vertex id): ltri[v], a live
 * triangle holding v, and deg[v], v's degree in the link.
 */
#ifndef DD_LINK_H
#define DD_LINK_H

#include "mesh/mesh.h"

/* Holes of up to this many ring vertices are clipped into Delaunay ears
 * on the stack (O(k^3) tests at worst, few in practice); larger ones go
 * through link.c's fill_by_dt, a small 3D DT, O(k log k) expected.     */
#define DD_LINK_EARS_UPTO 12

typedef struct dd_link {
    uint32_t *lv, *ln;
    uint32_t ntri, cap;
    uint32_t *ltri, *deg;       /* per vertex id, capacity vcap        */
    uint32_t vcap;
    /* LINKDTDELETE scratch and result */
    uint32_t *ring, *ring_tri, *ring_out;   /* the hole polygon         */
    uint32_t *newtri;           /* the k-2 new triangles, as 3 ids each */
    uint32_t ring_cap;
    uint32_t *rpos, *rmark;     /* per vertex: ring position, valid when
                                   rmark == rgen                        */
    uint32_t rgen, inf_rpos;
    int inf_in_link;            /* the infinite vertex is a link vertex */
    dd_tri *scratch;            /* DT(ring + q) when infinity appears   */
    uint32_t nnew;              /* triangles created by the last delete */
    uint32_t nring;             /* p's degree at the last delete        */
    int weighted;               /* t is weighted: the power test (below) */
} dd_link;

void dd_link_free(dd_link *l);

/* Builds the link of d->q from its star (delete.h); O(degree).          */
struct dd_del;
dd_status dd_link_extract(dd_link *l, struct dd_del *d);

/* LINKDTDELETE: removes vertex p (finite, of degree k >= 3) from the link
 * and re-triangulates its hole by the Delaunay rule above.  Degrees 3..7
 * use straight-line code; larger holes clip Delaunay ears.  When q leaves
 * the interior of the hull of the remaining points, the infinite vertex
 * enters the link in p's hole (link.c, fill_by_dt).  The new
 * triangles are l->ring_tri[0 .. l->nnew).                               */
dd_status dd_link_delete(dd_link *l, struct dd_del *d, uint32_t p);

#endif
