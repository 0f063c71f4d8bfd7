/*
 * pred.h -- exact, symbolically perturbed geometric predicates (DESIGN 3).
 *
 * Owns: the four predicates of CGAL's Delaunay_triangulation_3 with CGAL's
 * sign conventions, each as a semi-static floating-point filter (CGAL's
 * error bounds) followed by an exact evaluation in GMP integers; and the
 * symbolic perturbation that CGAL applies when the exact sign is zero.
 *
 * Invariant: for every input of doubles, every function here returns the
 * sign CGAL's predicate returns.  Nothing here allocates, GMP included
 * (it aborts the process when it cannot): the GMP stages work in a
 * scratch sized once for the largest numbers the double range allows
 * (DD_PRED_LIMBS), the context's own when dd_pred_reserve made it, else
 * one on the stack of the exact stage (dd_pred_exact).
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

#include "geom/fp.h"   /* first: no contraction from here on */

#include <math.h>
#include <stdint.h>
#include <gmp.h>

#include "dtdel/types.h"

#define DD_PRED_SCRATCH 48

/* The GMP stages' integers are bounded by the double range.  The points
 * of one call are shifted by their smallest binary exponent (>= -1074),
 * so each coordinate is an integer below 2^(1024+1074) = 2^2098, a
 * difference below 2^2099, a squared norm (or a weighted point's lift
 * |p|^2 - w, w any finite double, on the same scale) below 2^4200, and
 * a product of degree k in the differences below 2^(2099k + 7) with its
 * sum of at most 5! monomials.  The largest degree formed is 7 (the
 * coplanar in-circle test: |pq x pr|^2, degree 4, times a 3x3 minor);
 * DD_PRED_BITS allows 8.  GMP writes a product into a destination of
 * the limbs of both factors plus one (mpz_addmul), without reallocating
 * it when it has that many, and keeps its temporaries of this size on
 * the stack (TMP_ALLOC): so with DD_PRED_LIMBS limbs a number, no GMP
 * call here allocates.  tests/test_fault.c counts GMP's allocations to
 * check it.                                                             */
#define DD_PRED_BITS (8 * 2100)
#define DD_PRED_LIMBS ((DD_PRED_BITS + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS + 4)

typedef struct dd_pred {
    mpz_t z[DD_PRED_SCRATCH];   /* exact-stage scratch, reused: usable
                                   when z_ready                          */
    mp_limb_t *limbs;           /* z's limbs, DD_PRED_LIMBS each, when
                                   dd_pred_reserve made them (GMP never
                                   reallocates them); NULL before       */
    int z_ready;                /* z usable (reserved); a context of one
                                   call (a read-only query's, mesh.h
                                   dd_reader) is not: it costs O(1), and
                                   its GMP stages take a stack scratch  */
    /* tests past the filters (the exact stages), in every build: the gift
     * wrap's budget counts them (wrap_int.h, w_spent)                        */
    uint64_t orient_exact, insphere_exact;
#ifdef DD_COUNTERS
    uint64_t orient_calls, insphere_calls;
    uint64_t perturbed;
#endif
} dd_pred;

#ifdef DD_COUNTERS
#define DD_COUNT(ctx, field) ((ctx)->field++)
#else
#define DD_COUNT(ctx, field) ((void)0)
#endif

/* ---- stage 1, the semi-static filters (inline: the hot loops call them
 * directly and fall back to dd_orient3d / dd_insphere when unsure).  The
 * determinant in doubles, in the same evaluation order as CGAL's
 * determinant(), accepted when its magnitude exceeds CGAL's certified
 * error bound for that order, with CGAL's underflow and overflow guards.
 * They return the exact sign, or DD_FILTER_UNSURE.                      */
#define DD_FILTER_UNSURE 2

static inline double dd_min3(double a, double b, double c)
{
    double m = a < b ? a : b;
    return m < c ? m : c;
}

static inline double dd_max3(double a, double b, double c)
{
    double m = a > b ? a : b;
    return m > c ? m : c;
}

/* The 3x3 determinant of rows pq, pr, ps in CGAL's evaluation order
 * (its determinant(a00..a22)): the filter's value, and the plain
 * floating-point orientation of dd_orient3d_det.                         */
static inline double dd_det3_rows(double pqx, double pqy, double pqz, double prx, double pry, double prz,
                                  double psx, double psy, double psz)
{
    double m01 = pqx * pry - prx * pqy;
    double m02 = pqx * psy - psx * pqy;
    double m12 = prx * psy - psx * pry;
    return m01 * psz - m02 * prz + m12 * pqz;
}

/* orient3d(p, q, r, s) in plain floating point, unfiltered: its sign is
 * only a guess (CGAL's inexact_orientation; mesh.c's first walk).      */
static inline double dd_orient3d_det(const double *p, const double *q, const double *r, const double *s)
{
    return dd_det3_rows(q[0] - p[0], q[1] - p[1], q[2] - p[2], r[0] - p[0], r[1] - p[1], r[2] - p[2],
                        s[0] - p[0], s[1] - p[1], s[2] - p[2]);
}

static inline int dd_orient3d_filter(dd_pred *ctx, const double *p, const double *q,
                                     const double *r, const double *s)
{
    (void)ctx;
    DD_COUNT(ctx, orient_calls);
    double pqx = q[0] - p[0], pqy = q[1] - p[1], pqz = q[2] - p[2];
    double prx = r[0] - p[0], pry = r[1] - p[1], prz = r[2] - p[2];
    double psx = s[0] - p[0], psy = s[1] - p[1], psz = s[2] - p[2];
    double maxx = fabs(pqx), maxy = fabs(pqy), maxz = fabs(pqz);
    double a;
    if ((a = fabs(prx)) > maxx) maxx = a;
    if ((a = fabs(psx)) > maxx) maxx = a;
    if ((a = fabs(pry)) > maxy) maxy = a;
    if ((a = fabs(psy)) > maxy) maxy = a;
    if ((a = fabs(prz)) > maxz) maxz = a;
    if ((a = fabs(psz)) > maxz) maxz = a;
    double det = dd_det3_rows(pqx, pqy, pqz, prx, pry, prz, psx, psy, psz);
    double eps = 5.1107127829973299e-15 * maxx * maxy * maxz;
    double lo = dd_min3(maxx, maxy, maxz), hi = dd_max3(maxx, maxy, maxz);
    if (lo < 1e-97) {
        if (lo == 0) return 0;
    } else if (hi < 1e102) {
        if (det > eps) return 1;
        if (det < -eps) return -1;
    }
    return DD_FILTER_UNSURE;
}

static inline int dd_insphere_filter(dd_pred *ctx, const double *p, const double *q,
                                     const double *r, const double *s, const double *t)
{
    (void)ctx;
    DD_COUNT(ctx, insphere_calls);
    double ptx = p[0] - t[0], pty = p[1] - t[1], ptz = p[2] - t[2];
    double qtx = q[0] - t[0], qty = q[1] - t[1], qtz = q[2] - t[2];
    double rtx = r[0] - t[0], rty = r[1] - t[1], rtz = r[2] - t[2];
    double stx = s[0] - t[0], sty = s[1] - t[1], stz = s[2] - t[2];
    double pt2 = ptx * ptx + pty * pty + ptz * ptz;
    double qt2 = qtx * qtx + qty * qty + qtz * qtz;
    double rt2 = rtx * rtx + rty * rty + rtz * rtz;
    double st2 = stx * stx + sty * sty + stz * stz;
    double maxx = fabs(ptx), maxy = fabs(pty), maxz = fabs(ptz), a;
    if ((a = fabs(qtx)) > maxx) maxx = a;
    if ((a = fabs(rtx)) > maxx) maxx = a;
    if ((a = fabs(stx)) > maxx) maxx = a;
    if ((a = fabs(qty)) > maxy) maxy = a;
    if ((a = fabs(rty)) > maxy) maxy = a;
    if ((a = fabs(sty)) > maxy) maxy = a;
    if ((a = fabs(qtz)) > maxz) maxz = a;
    if ((a = fabs(rtz)) > maxz) maxz = a;
    if ((a = fabs(stz)) > maxz) maxz = a;
    double eps = 1.2466136531027298e-13 * maxx * maxy * maxz;
    double lo = dd_min3(maxx, maxy, maxz), hi = dd_max3(maxx, maxy, maxz);
    /* CGAL's 4x4 determinant(pt, rt, qt, st) evaluation order:
     * rows a0=pt, a1=rt, a2=qt, a3=st; aij = row i, column j.             */
    double m01 = rtx * pty - ptx * rty;
    double m02 = qtx * pty - ptx * qty;
    double m03 = stx * pty - ptx * sty;
    double m12 = qtx * rty - rtx * qty;
    double m13 = stx * rty - rtx * sty;
    double m23 = stx * qty - qtx * sty;
    double m012 = m12 * ptz - m02 * rtz + m01 * qtz;
    double m013 = m13 * ptz - m03 * rtz + m01 * stz;
    double m023 = m23 * ptz - m03 * qtz + m02 * stz;
    double m123 = m23 * rtz - m13 * qtz + m12 * stz;
    double det = m123 * pt2 - m023 * rt2 + m013 * qt2 - m012 * st2;
    if (lo < 1e-58) {
        if (lo == 0) return 0;
    } else if (hi < 1e61) {
        eps *= hi * hi;
        if (det > eps) return 1;
        if (det < -eps) return -1;
    }
    return DD_FILTER_UNSURE;
}

/* Readies ctx in O(1): counters zeroed, no GMP scratch (its GMP stages
 * take one on the stack, about DD_PRED_SCRATCH * DD_PRED_LIMBS * 8 =
 * 100 KB, in a frame of their own).  dd_pred_clear frees what it took.
 * A context is used by one thread at a time: each read-only call of the
 * public API takes one of its own.                                      */
void dd_pred_init(dd_pred *ctx);
/* Gives ctx a GMP scratch of its own, sized for every input (z_ready):
 * the contexts of the edits, made with their triangulation.  O(1) when
 * it has one; DD_ERR_NOMEM (ctx as it was).                             */
dd_status dd_pred_reserve(dd_pred *ctx);
void dd_pred_clear(dd_pred *ctx);

/* The exact stages' determinants, shared by pred.c and power.c:
 * dd_mpz_det2: r = a*d - b*c (tmp scratch).  dd_mpz_sign_det3: the sign
 * of det[[a0 a1 a2][b0 b1 b2][c0 c1 c2]], its value left in s[1]
 * (scratch s[0..3]).  dd_mpz_sign_det4: the sign of the 4x4 determinant
 * of rows r[0..3] (scratch s[0..9]).  They allocate nothing when the
 * numbers have room (dd_pred_exact's scratch always has).              */
void dd_mpz_det2(mpz_t r, const mpz_t a, const mpz_t b, const mpz_t c, const mpz_t d, mpz_t tmp);
int dd_mpz_sign_det3(mpz_ptr *a, mpz_ptr *b, mpz_ptr *c, mpz_ptr *s);
int dd_mpz_sign_det4(mpz_ptr *const r[4], mpz_ptr *s);

/* A GMP stage: f(z, arg) with z[0..DD_PRED_SCRATCH) integers of
 * DD_PRED_LIMBS limbs (ctx's reserved scratch, else one on the stack),
 * the npts (<= 5) points loaded into z[0 .. 3 npts) as x / 2^emin,
 * emin the smallest binary exponent of their nonzero coordinates (so
 * integers; *emin_out gets it when not NULL).  Returns f's result.  For
 * every exact stage on GMP integers, so that none allocates.            */
typedef int (*dd_exact_fn)(mpz_ptr *z, const void *arg);
int dd_pred_exact(dd_pred *ctx, const double *const *pts, int npts, dd_exact_fn f, const void *arg,
                  int *emin_out);

int dd_orient3d(dd_pred *ctx, const double *p, const double *q,
                const double *r, const double *s);
int dd_insphere(dd_pred *ctx, const double *p, const double *q,
                const double *r, const double *s, const double *t);
int dd_orient_coplanar(dd_pred *ctx, const double *p, const double *q,
                       const double *r);
int dd_incircle_coplanar(dd_pred *ctx, const double *p, const double *q,
                         const double *r, const double *t);

/* The exact stages alone, for callers that ran the filter themselves and
 * got DD_FILTER_UNSURE.                                                   */
int dd_orient3d_unfiltered(dd_pred *ctx, const double *p, const double *q,
                           const double *r, const double *s);
int dd_insphere_unfiltered(dd_pred *ctx, const double *p, const double *q,
                           const double *r, const double *s, const double *t);

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
/* Its perturbation alone, when dd_insphere(p0..p3, p) is exactly 0: the
 * rule of lift.h's dd_lift_symbolic_top on the five points' own order.  */
int dd_insphere_symbolic(dd_pred *ctx, const double *p0, const double *p1,
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
/* sign(|p - a|^2 - |p - b|^2), exactly: +1 when b is nearer p than a,
 * -1 when a is, 0 at equal distances.  Filtered, then GMP.               */
int dd_compare_distance(dd_pred *ctx, const double *p, const double *a, const double *b);

int dd_inf_conflict(dd_pred *ctx, const double *const v[4], int k,
                    const double *p);

#endif
