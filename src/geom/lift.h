/*
 * lift.h -- the lifted filter: signs of determinants of points lifted
 * relative to the deleted vertex q, and CGAL's 3D perturbation on ranks.
 *
 * Owns, for the fills that work in a frame centred at q (the compact
 * conflict DT, src/delete/qsmall.c, and the gift wrap, src/wrap/):
 *  - the lift L[x] = (x - q, |x - q|^2) in doubles (dd_lift_row) and the
 *    evaluations the bounds are derived for: qsmall's 4x4 determinant
 *    (dd_lift_det4) and the wrap's pencil (dd_lift_minors,
 *    dd_lift_cofactors, dd_lift_orient, dd_lift_dot4);
 *  - the error bounds of the in-sphere and orientation filters on those
 *    evaluations (dd_lift_err, dd_lift_orient_err), with their derivation;
 *  - the integer modes, where the evaluations are exact, their limits
 *    (DD_LIFT_INT_M, _O, _K), the classification of a frame
 *    (dd_lift_classify, dd_lift_frame_of) and the exact sign of an
 *    integer K . P (dd_lift_sign_kp);
 *  - the shifted lifts for nearly cospherical frames (dd_shift_lifts);
 *  - the rule of the 3D symbolic perturbation (DESIGN 3) on ranks
 *    (dd_lift_top2, dd_lift_symbolic, dd_lift_symbolic_top), which
 *    pred.c's dd_insphere_symbolic applies too: one statement of it.
 *
 * Invariant: a sign this file certifies -- a value beyond its bound, or
 * any value in an integer mode that holds -- is the sign of the exact
 * determinant of the points, hence pred.h's unperturbed predicate on
 * them; a value within its bound certifies nothing and the caller asks
 * pred.h.  dd_lift_symbolic returns dd_insphere_symbolic's sign for the
 * same five points whenever the ranks order them as dd_lex_cmp does and
 * the orientations it is handed are orient3d's.
 *
 * Signs in the lifted frame (m = max |x_k - q_k| over the frame's points):
 *   dd_lift_det4(L[v0..v3], L[p]) = det4(L[vi] - L[p])  has the sign of
 *       -insphere(v0, v1, v2, v3, p): negative when p is inside the
 *       sphere of the positively oriented v0..v3;
 *   with rows B = L[b] - L[a], C = L[c] - L[a], X = L[x] - L[a],
 *   P = L[p] - L[a]: det4(B, C, X, P) = K(X) . P, K = dd_lift_cofactors,
 *       the same sign as dd_lift_det4 of (a, b, c, x) and p, and
 *       o(P) = dd_lift_orient(minors of B, C; P) = orient3d(a, b, c, p).
 * (Translating every row by -q and adding to the lift column a
 * combination of the first three changes no determinant.)
 */
#ifndef DD_LIFT_H
#define DD_LIFT_H

#include "geom/fp.h"   /* first: no contraction from here on */

#include <math.h>
#include <stdint.h>

/* ---- the lift and the evaluations ------------------------------------ */

/* The larger of a and b; NaN if either is NaN, or if b is infinite (a
 * frame with such a point has no filter: dd_lift_err(NaN) is +inf, as
 * for m = +inf).  Free of branches, which the frame's sizes would
 * mispredict: b - b is 0 for a finite b, NaN otherwise.                 */
static inline double dd_lift_max(double a, double b)
{
    return (b > a ? b : a) + (b - b);
}

/* l = (x - q, |x - q|^2), each coordinate difference rounded once and the
 * norm of the rounded differences rounded as evaluated here.  Returns
 * max |x_i - q_i| (rounded): the point's share of the frame's m.         */
static inline double dd_lift_row(double l[4], const double *x, const double *q)
{
    l[0] = x[0] - q[0];
    l[1] = x[1] - q[1];
    l[2] = x[2] - q[2];
    l[3] = l[0] * l[0] + l[1] * l[1] + l[2] * l[2];
    return dd_lift_max(dd_lift_max(fabs(l[0]), fabs(l[1])), fabs(l[2]));
}

/* det4(r[i] - p), i = 0..3, of lifted rows: 2x2 minors of the first two
 * columns and of the last two, then their six products summed.  At most
 * 8 roundings on any product path after the row differences (the bound
 * allows 10).                                                            */
static inline double dd_lift_det4(const double *const r[4], const double *p)
{
    double a[4][4];
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++) a[i][k] = r[i][k] - p[k];
    double m01 = a[0][0] * a[1][1] - a[1][0] * a[0][1], m02 = a[0][0] * a[2][1] - a[2][0] * a[0][1];
    double m03 = a[0][0] * a[3][1] - a[3][0] * a[0][1], m12 = a[1][0] * a[2][1] - a[2][0] * a[1][1];
    double m13 = a[1][0] * a[3][1] - a[3][0] * a[1][1], m23 = a[2][0] * a[3][1] - a[3][0] * a[2][1];
    double n01 = a[0][2] * a[1][3] - a[1][2] * a[0][3], n02 = a[0][2] * a[2][3] - a[2][2] * a[0][3];
    double n03 = a[0][2] * a[3][3] - a[3][2] * a[0][3], n12 = a[1][2] * a[2][3] - a[2][2] * a[1][3];
    double n13 = a[1][2] * a[3][3] - a[3][2] * a[1][3], n23 = a[2][2] * a[3][3] - a[3][2] * a[2][3];
    return ((m01 * n23 - m02 * n13) + (m03 * n12 + m12 * n03)) - (m13 * n02 - m23 * n01);
}

/* The six 2x2 minors of rows B and C (lifted differences from a facet's
 * first corner): m[0..5] = minors of columns 01, 02, 03, 12, 13, 23.    */
static inline void dd_lift_minors(double m[6], const double B[4], const double C[4])
{
    m[0] = B[0] * C[1] - B[1] * C[0];
    m[1] = B[0] * C[2] - B[2] * C[0];
    m[2] = B[0] * C[3] - B[3] * C[0];
    m[3] = B[1] * C[2] - B[2] * C[1];
    m[4] = B[1] * C[3] - B[3] * C[1];
    m[5] = B[2] * C[3] - B[3] * C[2];
}

/* The cofactors K(X) along the last row of det4(B, C, X, P), from the
 * minors m of B, C: det4(B, C, X, P) = K . P (dd_lift_dot4).             */
static inline void dd_lift_cofactors(double K[4], const double X[4], const double m[6])
{
    K[0] = -(X[1] * m[5] - X[2] * m[4] + X[3] * m[3]);
    K[1] = X[0] * m[5] - X[2] * m[2] + X[3] * m[1];
    K[2] = -(X[0] * m[4] - X[1] * m[2] + X[3] * m[0]);
    K[3] = X[0] * m[3] - X[1] * m[1] + X[2] * m[0];
}

/* K . P, summed left to right. */
static inline double dd_lift_dot4(const double K[4], const double P[4])
{
    return P[0] * K[0] + P[1] * K[1] + P[2] * K[2] + P[3] * K[3];
}

/* o(P) = N . P with the normal N = (m[3], -m[1], m[0]) of the minors of
 * B, C: orient3d(a, b, c, p) for P = L[p] - L[a].                        */
static inline double dd_lift_orient(const double m[6], const double P[4])
{
    return P[0] * m[3] + P[1] * -m[1] + P[2] * m[0];
}

/* ---- the bounds ---------------------------------------------------------
 *
 * Entries.  With m = max |x_k - q_k| over the frame's points (q included,
 * at 0) and u = 2^-53: a lift's first three coordinates are at most m
 * with errors at most um, its fourth at most 3m^2 with error at most
 * 5u * 3m^2 (the differences' errors squared, the squares, two sums); a
 * row difference adds one rounding.  So the rows' entries are at most 2m
 * (columns 0-2) and 3m^2 (column 3), with absolute errors at most
 * 2u * 2m and 12u * 3m^2.
 *
 * In-sphere.  A 4x4 determinant of such rows is a sum of 24 products of
 * one entry of each column.  The entries' errors move it by at most
 * 24 * (2m)^3 * 3m^2 * 18u (relative 2u three times and 12u once); the
 * evaluation, with at most 10 roundings on any product path
 * (dd_lift_det4; the pencil's cofactors and dot product: 9), adds at
 * most gamma_10 * 576 m^5.  In all below 1.8e-12 m^5: the filter answers
 * only beyond 1e-11 m^5.
 *
 * Orientation.  orient3d(a, b, c, p) = det3 of the first three columns
 * of the rows B, C, P: 6 products of entries at most 2m with errors at
 * most 4um, moved by at most 6 * 3 * (2m)^2 * 4um = 288u m^3; the
 * evaluation (minors, then a 3-term dot product: 5 roundings) adds at
 * most gamma_5 * 48 m^3 < 241u m^3.  In all below 6e-14 m^3: the filter
 * answers only beyond 1e-13 m^3.
 *
 * Range.  Both only for 1e-55 <= m <= 1e55: no overflow (576 m^5 stays
 * below 1e300) and the underflow errors (at most a few 2^-1074 per
 * operation) far below the bounds; elsewhere (and for a NaN m) the bound
 * is +inf and the exact predicates decide every test.                   */
#define DD_LIFT_M_MIN 1e-55
#define DD_LIFT_M_MAX 1e55

/* The in-sphere bound for lifted rows in a frame of size m (+inf outside
 * the range).                                                            */
static inline double dd_lift_err(double m)
{
    return m >= DD_LIFT_M_MIN && m <= DD_LIFT_M_MAX ? 1e-11 * m * m * m * m * m : 1.0 / 0.0;
}

/* The orientation bound on the same rows (+inf outside the range). */
static inline double dd_lift_orient_err(double m)
{
    return m >= DD_LIFT_M_MIN && m <= DD_LIFT_M_MAX ? 1e-13 * m * m * m : 1.0 / 0.0;
}

/* ---- the weighted lift ----------------------------------------------------
 *
 * A regular triangulation's lift (DESIGN 12) relative to the deleted
 * point (q, w_q): L[x] = (x - q, |x - q|^2 - (w_x - w_q)), the fourth
 * coordinate evaluated as (|x - q|^2 as dd_lift_row has it) - dw, dw =
 * w_x - w_q rounded once.  With every dw exactly 0 it is the unweighted
 * lift, bit for bit.  The determinants of these rows are the power tests'
 * (minus their sign: dd_power_exact's rows are the same up to a
 * translation and combinations of the first three columns).
 *
 * Bound.  With W = max |dw|: the fourth coordinate is at most 3m^2 + W
 * (1 + u); its error, 5u 3m^2 for the norm, u W for dw and u (3m^2 + W)
 * (1 + 5u) for the subtraction, is below 6u (3m^2 + W).  So with
 * 3 M2 = 1.25 (3m^2 + W) the entries of the fourth column are at most
 * 3 M2 with errors at most 5u 3 M2: the in-sphere derivation above holds
 * with 3m^2 replaced by 3 M2 for that column.  Each of its terms is a
 * product of the three coordinate columns (m each) and the fourth, so the
 * bound is 1e-11 m^3 M2.  The orientation bound, on the first three
 * columns only, is unchanged.  Range: m as above, and M2 at most 1e110
 * (NaN and an overflowed dw included: +inf, no filter).                 */
static inline double dd_lift_power_err(double m, double W)
{
    const double M2 = 1.25 * (m * m + W / 3);
    return m >= DD_LIFT_M_MIN && m <= DD_LIFT_M_MAX && M2 <= 1e110 ? 1e-11 * m * m * m * M2 : 1.0 / 0.0;
}

/* l = (x - q, |x - q|^2 - dw): the weighted lift above, the norm as
 * dd_lift_row has it and dw = w_x - w_q as the caller rounded it once.
 * Returns max |x_i - q_i| (rounded), as dd_lift_row; the caller keeps
 * W = max |dw| for dd_lift_power_err.  Rows of a frame whose own point
 * q is a corner (its row exactly 0, as in flip.c's star tests) enter
 * dd_lift_minors, dd_lift_cofactors and dd_lift_dot4 as they are: no
 * row difference, so fewer roundings and smaller entries than the
 * derivation allows, and the bound holds.                              */
static inline double dd_lift_row_power(double l[4], const double *x, const double *q, double dw)
{
    const double m = dd_lift_row(l, x, q);
    l[3] -= dw;
    return m;
}

/* ---- the integer modes --------------------------------------------------
 *
 * When q and every point of the frame have integer coordinates, each
 * difference x_k - q with |x_k - q| <= m <= 2^53 is an integer computed
 * exactly (two integral doubles that close differ by a representable
 * integer), and so is every lift: the rows' entries are integers at most
 * 2m (columns 0-2) and 3m^2 (column 3).  A sum of products of integers
 * is exact in doubles while every partial sum stays below 2^53.
 *
 * Integer lifts, m <= DD_LIFT_INT_M = 400.  The 2x2 minors are at most
 * 8m^2 (columns 0-2) and 12m^3 (with column 3), o at most 48m^3, the
 * cofactors K at most 72m^4, and every in-sphere determinant, as
 * dd_lift_det4 or K . P, at most 576m^5 <= 5.9e15 < 2^53 (up to m = 434).
 * Every evaluation above is exact: the bounds are 0, and a 0 is an exact
 * zero (orient3d 0; in-sphere: the perturbation's alone).
 *
 * Integer orientations, m <= DD_LIFT_INT_O = 2^15.  o alone (minors at
 * most 8m^2 times entries at most 2m, three terms: at most 48m^3 <=
 * 1.6e15) is exact: the orientation bound is 0, the in-sphere bound not.
 *
 * Integer cofactors, m <= DD_LIFT_INT_K = 2^11.  The cofactors K (at
 * most 72m^4 <= 1.3e15) are exact integers; K . P has products below
 * 2^51 * 2^24 = 2^75, summed exactly in 128-bit integers by
 * dd_lift_sign_kp.  Without 128-bit integers the limit is 0: the mode
 * holds only with integer lifts, where K . P is exact in doubles.       */
#define DD_LIFT_INT_M 400.0
#define DD_LIFT_INT_O 32768.0
#if defined(__SIZEOF_INT128__)
#define DD_LIFT_INT_K 2048.0
#else
#define DD_LIFT_INT_K 0.0
#endif

enum {
    DD_LIFT_EXACT = 1,    /* integer lifts: every evaluation exact       */
    DD_LIFT_OEXACT = 2,   /* orientations o exact                        */
    DD_LIFT_KEXACT = 4    /* cofactors K exact, K . P by dd_lift_sign_kp */
};

/* A frame: its size, its exact modes and the bounds that follow (0 where
 * the mode makes the evaluation exact, +inf where the filter is off).   */
typedef struct dd_lift_frame {
    double m;             /* max |x_k - q_k| over the points            */
    double ierr;          /* in-sphere bound (dd_lift_det4, K . P)      */
    double oerr;          /* orientation bound (dd_lift_orient)         */
    unsigned modes;       /* DD_LIFT_EXACT | DD_LIFT_OEXACT | DD_LIFT_KEXACT */
} dd_lift_frame;

/* 1 if x is a finite integer (every double of magnitude >= 2^52 is one;
 * below, adding and removing 2^52 rounds to an integer).                  */
static inline int dd_lift_is_int(double x)
{
    double a = fabs(x);
    return a >= 0x1p52 ? a <= 0x1.fffffffffffffp1023 : (a + 0x1p52) - 0x1p52 == a;
}

/* 1 if the three coordinates of x are finite integers. */
static inline int dd_lift_is_int3(const double *x)
{
    return dd_lift_is_int(x[0]) & dd_lift_is_int(x[1]) & dd_lift_is_int(x[2]);
}

/* The frame of size m whose points (q included) are all integers when
 * `integral`: which modes hold and the bounds.                           */
static inline dd_lift_frame dd_lift_classify(int integral, double m)
{
    dd_lift_frame f;
    unsigned e = integral && m <= DD_LIFT_INT_M, o = integral && m <= DD_LIFT_INT_O;
    unsigned k = e || (integral && m <= DD_LIFT_INT_K);
    f.m = m;
    f.modes = (e ? DD_LIFT_EXACT : 0u) | (o ? DD_LIFT_OEXACT : 0u) | (k ? DD_LIFT_KEXACT : 0u);
    f.ierr = e ? 0.0 : dd_lift_err(m);
    f.oerr = o ? 0.0 : dd_lift_orient_err(m);
    return f;
}

/* The frame of q and pts[0..n): m as dd_lift_row computes it, and
 * integrality (dd_lift_is_int3) only where a mode could hold, m at most
 * DD_LIFT_INT_O, the largest limit.  O(n).                               */
dd_lift_frame dd_lift_frame_of(const double *q, const double *const *pts, uint32_t n);

/* The sign of K . P, exactly, for K and P of a frame in DD_LIFT_KEXACT
 * (integer entries, |K_i| < 2^51, |P_i| < 2^24).                          */
static inline int dd_lift_sign_kp(const double K[4], const double P[4])
{
#if defined(__SIZEOF_INT128__)
    __int128 s = 0;
    for (int i = 0; i < 4; i++) s += (__int128)(int64_t)K[i] * (int64_t)P[i];
    return (s > 0) - (s < 0);
#else
    double s = dd_lift_dot4(K, P);                 /* DD_LIFT_EXACT: exact */
    return (s > 0) - (s < 0);
#endif
}

/* ---- the shifted lifts --------------------------------------------------
 *
 * For nearly cospherical frames (points sampled on a sphere through q),
 * where every determinant is tiny next to m^5 and the plain filter always
 * abstains.  Replacing the fourth column by
 *     w'[x] = |x - q|^2 - 2 (x - q) . C
 * for any fixed C subtracts multiples of the first three columns: no
 * determinant changes.  With C the centre (relative to q) of the sphere
 * through q and three lifted points a, b, c, w' is about the distance of
 * x from that sphere, far below m^2.  Each w' is computed from its exact
 * expansion within 4u |w'| (dd_exp_shifted_lift: 2u), so with M = max |w'|
 * the entries of column 3 are at most 2M with errors at most 10u M; with
 * the 6u of columns 0-2 and the 10u of the evaluation the error is below
 *     21u * 24 * (2m)^3 * 2M < 9e-13 m^3 M,
 * and the shifted filter answers only beyond 5e-12 m^3 M.  Underflow:
 * a w' loses at most about 1e-322 to it, which moves a determinant by at
 * most 4e-320 m^3, so M >= 1e-300 and a bound >= 1e-290 keep it
 * negligible; m and |C| at most 2^150 keep dd_exp_shifted_lift in its
 * range (and m >= DD_LIFT_M_MIN).                                        */

/* For the points pts[0..n), within m of q, and the plain lifts a, b, c of
 * three of them: writes the shifted fourth coordinates to w[0..n) and
 * returns their bound; 0 (keep the plain lifts) when the centre is not
 * finite or the bound is not below err.  Costs an exact expansion a
 * point, which fewer than DD_SHIFT_FROM points do not pay back.          */
#define DD_SHIFT_FROM 7
double dd_shift_lifts(const double *const *pts, uint32_t n, const double *q, const double *a, const double *b,
                      const double *c, double m, double err, double *w);

/* ---- the 3D perturbation on ranks ---------------------------------------
 *
 * DESIGN 3: five cospherical points, the cell v0..v3 positively oriented
 * and the query y.  Of the five, take the lexicographically largest: if
 * it is y, y is outside (-1); if it is vk, the answer is orient3d of the
 * cell with vk replaced by y (+1: inside), unless that is 0; then the
 * same with the second largest.  Two steps decide for distinct points.
 * Only the order matters, so any ranks consistent with dd_lex_cmp serve
 * (the five points' own, or a whole frame's).                           */

/* The positions (0..4) of the largest and the second largest of five
 * distinct ranks rk[0..4] (cell vertices 0..3, the query 4).             */
static inline void dd_lift_top2(const uint32_t rk[5], int top[2])
{
    int t0 = 0;
    for (int i = 1; i < 5; i++)
        if (rk[i] > rk[t0]) t0 = i;
    int t1 = t0 == 0 ? 1 : 0;
    for (int i = 0; i < 5; i++)
        if (i != t0 && rk[i] > rk[t1]) t1 = i;
    top[0] = t0;
    top[1] = t1;
}

/* orient3d of the cell with its vertex k (0..3) replaced by the query. */
typedef int (*dd_lift_orient_fn)(void *ctx, int k);

/* The rule from the positions (0..4) of the largest and the second
 * largest of the five, t0 and t1: the perturbed in-sphere sign (+1
 * inside, -1 outside) of the query for a cell whose exact in-sphere
 * determinant is 0, with the caller's orientations.  Starts at step
 * `from` (0; 1 when the caller has found the first step's orientation to
 * be 0).  Inline, so that a static `orient` is called directly (and
 * inlined) where its address is a constant.                              */
static inline int dd_lift_symbolic_top(int t0, int t1, int from, dd_lift_orient_fn orient, void *ctx)
{
    for (int step = from; step < 2; step++) {
        const int k = step == 0 ? t0 : t1;
        if (k == 4) return -1;                     /* the query itself */
        int o = orient(ctx, k);
        if (o != 0) return o;
    }
    return -1;   /* not reached for distinct points (CGAL asserts) */
}

/* The same from the ranks rk of (v0, v1, v2, v3, y). */
static inline int dd_lift_symbolic(const uint32_t rk[5], int from, dd_lift_orient_fn orient, void *ctx)
{
    int top[2];
    dd_lift_top2(rk, top);
    return dd_lift_symbolic_top(top[0], top[1], from, orient, ctx);
}

#endif
