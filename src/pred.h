/*
 * pred.h -- exact, symbolically perturbed geometric predicates (DESIGN 3).
 *
 * Owns: the four predicates of CGAL's Delaunay_triangulation_3 with CGAL's
 * sign conventions, each as a semi-static floating-point filter (CGAL's
 * error bounds) followed by an exact evaluation in GMP integers; and the
 * symbolic perturbation that CGAL applies when the exact sign is zero.
 *
 * Invariant: for every input of doubles, every function here returns the
 * sign CGAL's predicate returns.  Nothing here allocates after
 * dd_pred_init; the GMP scratch lives in the dd_pred context.
 *
 * Signs:
 *   orient3d(p,q,r,s)   = sign det[q-p; r-p; s-p]; +1 for the unit
 *                         tetrahedron (0,e1,e2,e3).  Never perturbed.
 *   insphere(p,q,r,s,t) = +1 when t is inside the sphere through the
 *                         positively oriented p,q,r,s; -1 outside; 0 on.
 *   orient_coplanar(p,q,r): 2D orientation in the xy projection, else yz,
 *                         else xz (CGAL's coplanar_orientation).
 *   incircle_coplanar(p,q,r,t): +1 inside the circle through p,q,r, -1
 *                         outside, 0 on; independent of the order p,q,r.
 * The _perturbed versions never return 0 for distinct points.
 */
#ifndef DD_PRED_H
#define DD_PRED_H

#include <stdint.h>
#include <gmp.h>

#define DD_PRED_SCRATCH 48

typedef struct dd_pred {
    mpz_t z[DD_PRED_SCRATCH];   /* exact-stage scratch, reused            */
#ifdef DD_COUNTERS
    uint64_t orient_calls, orient_exact;
    uint64_t insphere_calls, insphere_exact;
    uint64_t perturbed;
#endif
} dd_pred;

#ifdef DD_COUNTERS
#define DD_COUNT(ctx, field) ((ctx)->field++)
#else
#define DD_COUNT(ctx, field) ((void)0)
#endif

void dd_pred_init(dd_pred *ctx);
void dd_pred_clear(dd_pred *ctx);

int dd_orient3d(dd_pred *ctx, const double *p, const double *q,
                const double *r, const double *s);
int dd_insphere(dd_pred *ctx, const double *p, const double *q,
                const double *r, const double *s, const double *t);
int dd_orient_coplanar(dd_pred *ctx, const double *p, const double *q,
                       const double *r);
int dd_incircle_coplanar(dd_pred *ctx, const double *p, const double *q,
                         const double *r, const double *t);

/* Lexicographic order on (x, y, z): -1, 0, +1. */
static inline int dd_lex_cmp(const double *a, const double *b)
{
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    if (a[1] != b[1]) return a[1] < b[1] ? -1 : 1;
    if (a[2] != b[2]) return a[2] < b[2] ? -1 : 1;
    return 0;
}

/* CGAL's side_of_oriented_sphere(p0..p3, p, perturb=true): p0..p3
 * positively oriented, all five points distinct.  +1 inside, -1 outside. */
int dd_insphere_perturbed(dd_pred *ctx, const double *p0, const double *p1,
                          const double *p2, const double *p3,
                          const double *p);
/* CGAL's coplanar_side_of_bounded_circle(p0,p1,p2,p, perturb=true):
 * +1 inside, -1 outside; p0,p1,p2 not collinear, all four coplanar.     */
int dd_incircle_coplanar_perturbed(dd_pred *ctx, const double *p0,
                                   const double *p1, const double *p2,
                                   const double *p);
/* CGAL's side_of_sphere for a cell whose vertex k is the infinite vertex:
 * v[k] is ignored, the other three are the hull facet.  +1 when p is in
 * conflict with the cell (beyond the facet, or in its plane and inside its
 * perturbed circle), -1 otherwise.                                        */
int dd_inf_conflict(dd_pred *ctx, const double *const v[4], int k,
                    const double *p);

#endif
