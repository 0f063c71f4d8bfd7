/*
 * lift_pass.h -- the lifted filter over a whole frame: the evaluations
 * and passes that the gift wrap (src/wrap/) runs over the rows of q's
 * neighbours, in scalars, SSE2, AVX2 (lift_simd.c) and single precision
 * (lift_f32.c), and the comparisons of their values with lift.h's bounds.
 *
 * Owns:
 *  - the rows of a frame in columns, L[i][k] = coordinate i of
 *    (x_k - q, |x_k - q|^2), padded with NaN to a multiple of four
 *    (dd_lift_rows, lift.c), and the frame's lexicographic ranks, which
 *    feed the perturbation's rule (dd_lex_ranks, lift.c);
 *  - the pencil of a facet (a, b, c) (docs/gift-wrap.md §2): the minors
 *    m of the rows B = L[b] - L[a], C = L[c] - L[a], the normal N, with
 *    o(P) = N . P = orient3d(a, b, c, p) for P = L[p] - L[a], and T =
 *    K(N), with t(P) = T . P; K(X) the cofactors of det4(B, C, X, P) =
 *    K(X) . P, the in-sphere determinant of a, b, c, x, p (lift.h);
 *  - the certified signs: a value beyond its bound (dd_lift_sure);
 *  - the passes over the frame's points: the least t/o beyond a facet,
 *    the points near a plane, the check of a candidate apex.
 *
 * Invariant: o is evaluated by one sequence of operations on every path
 * (dd_lift_row_o; lane by lane in lift_simd.c; the SSE2 minors and
 * cofactors are the scalar ones' products, sums and signs, bit for bit),
 * so lift.h's orientation bound covers every pass, and K . P
 * (dd_lift_dot4) has at most the roundings its in-sphere bound counts.
 * A sign certified here is the exact determinant's; what a pass only
 * ranks (a least quotient, the single-precision passes) may round.
 * tests/test_filters.c checks each path against the exact signs.
 */
#ifndef DD_LIFT_PASS_H
#define DD_LIFT_PASS_H

#include "geom/fp.h"
#include "geom/lift.h"

#include <stddef.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

/* The AVX2 passes (lift_simd.c, lift_f32.c) exist on x86-64 with gcc or
 * clang; a caller takes them only when the CPU has AVX2 (and FMA for the
 * single-precision ones: __builtin_cpu_supports).                       */
#if defined(__GNUC__) && defined(__x86_64__)
#define DD_LIFT_AVX2 1
#endif

/* Answers of the passes that are not a point's number.                  */
#define DD_LIFT_NONE UINT32_MAX          /* no point beyond the facet        */
#define DD_LIFT_TIE (UINT32_MAX - 3)     /* two least quotients equal        */
#define DD_LIFT_BEHIND (UINT32_MAX - 4)  /* single precision: all behind     */

/* ---- certified signs ----------------------------------------------------- */

/* +1 or -1 when the value v is beyond its bound err (lift.h), the exact
 * determinant's sign; 0 when it certifies nothing (NaN included).       */
static inline int dd_lift_sure(double v, double err)
{
    return (v > err) - (v < -err);
}

/* v surely positive, surely negative, not sure: the parts of
 * dd_lift_sure, for the branch-free passes.                              */
static inline int dd_lift_sure_pos(double v, double err) { return v > err; }
static inline int dd_lift_sure_neg(double v, double err) { return v < -err; }
static inline int dd_lift_unsure(double v, double err) { return !(v > err) && !(v < -err); }

/* ---- the pencil ---------------------------------------------------------- */

#ifdef __SSE2__
/* dd_lift_cofactors of X = (x01, x23), in registers: the same products,
 * sums and signs, bit for bit, two at a time.                           */
static inline void dd_lift_cofactors_sse2(double K[4], __m128d x01, __m128d x23, const double m[6])
{
    enum { M01, M02, M03, M12, M13, M23 };
    const __m128d neg0 = _mm_set_pd(0.0, -0.0);
    __m128d a = _mm_mul_pd(_mm_shuffle_pd(x01, x01, 1), _mm_set1_pd(m[M23]));
    __m128d b = _mm_mul_pd(_mm_unpacklo_pd(x23, x23), _mm_setr_pd(m[M13], m[M03]));
    __m128d c = _mm_mul_pd(_mm_unpackhi_pd(x23, x23), _mm_setr_pd(m[M12], m[M02]));
    _mm_storeu_pd(K, _mm_xor_pd(_mm_add_pd(_mm_sub_pd(a, b), c), neg0));
    a = _mm_mul_pd(_mm_unpacklo_pd(x01, x01), _mm_setr_pd(m[M13], m[M12]));
    b = _mm_mul_pd(_mm_unpackhi_pd(x01, x01), _mm_setr_pd(m[M03], m[M02]));
    c = _mm_mul_pd(_mm_shuffle_pd(x23, x23, 1), _mm_set1_pd(m[M01]));
    _mm_storeu_pd(K + 2, _mm_xor_pd(_mm_add_pd(_mm_sub_pd(a, b), c), neg0));
}

/* dd_lift_minors, two at a time: the same products and differences.    */
static inline void dd_lift_minors_sse2(double m[6], const double B[4], const double C[4])
{
    const __m128d b01 = _mm_loadu_pd(B), b23 = _mm_loadu_pd(B + 2), c01 = _mm_loadu_pd(C), c23 = _mm_loadu_pd(C + 2);
    const __m128d b12 = _mm_shuffle_pd(b01, b23, 1), c12 = _mm_shuffle_pd(c01, c23, 1);
    _mm_storeu_pd(m, _mm_sub_pd(_mm_mul_pd(_mm_unpacklo_pd(b01, b01), c12),
                                _mm_mul_pd(b12, _mm_unpacklo_pd(c01, c01))));
    _mm_storeu_pd(m + 2, _mm_sub_pd(_mm_mul_pd(b01, _mm_shuffle_pd(c23, c23, 1)),
                                    _mm_mul_pd(_mm_shuffle_pd(b23, b23, 1), c01)));
    _mm_storeu_pd(m + 4, _mm_sub_pd(_mm_mul_pd(b12, _mm_unpackhi_pd(c23, c23)),
                                    _mm_mul_pd(_mm_unpackhi_pd(b23, b23), c12)));
}
#endif

/* The cofactors K(X) (dd_lift_cofactors), with SSE2 where there is. */
static inline void dd_lift_vcofactors(double K[4], const double X[4], const double m[6])
{
#ifdef __SSE2__
    dd_lift_cofactors_sse2(K, _mm_loadu_pd(X), _mm_loadu_pd(X + 2), m);
#else
    dd_lift_cofactors(K, X, m);
#endif
}

/* The six minors of B, C (dd_lift_minors), with SSE2 where there is. */
static inline void dd_lift_vminors(double m[6], const double B[4], const double C[4])
{
#ifdef __SSE2__
    dd_lift_minors_sse2(m, B, C);
#else
    dd_lift_minors(m, B, C);
#endif
}

/* The normal N = (m12, -m02, m01, 0) of the minors: o(P) = N . P.      */
static inline void dd_lift_normal_of(const double m[6], double N[4])
{
    N[0] = m[3]; N[1] = -m[1]; N[2] = m[0]; N[3] = 0;
}

/* Point k's row P = L[k] - A (A: the row of the facet's first corner)
 * and o(P) = N . P: the one evaluation of o on every path.              */
static inline double dd_lift_row_o(double *const *L, uint32_t k, const double A[4], const double N[4], double P[4])
{
    for (int i = 0; i < 4; i++) P[i] = L[i][k] - A[i];
    return P[0] * N[0] + P[1] * N[1] + P[2] * N[2];
}

/* o of a row X already made: dd_lift_row_o's sum. */
static inline double dd_lift_o(const double X[4], const double N[4])
{
    return X[0] * N[0] + X[1] * N[1] + X[2] * N[2];
}

/* Facet (a, b, c)'s pencil in the rows L: minors m of B, C, the normal N
 * and T = K(N), rows taken from a.                                      */
static inline void dd_lift_pencil(double *const *L, uint32_t a, uint32_t b, uint32_t c, double m[6], double N[4],
                                  double T[4])
{
    const double ax = L[0][a], ay = L[1][a], az = L[2][a], aw = L[3][a];
    double B[4] = {L[0][b] - ax, L[1][b] - ay, L[2][b] - az, L[3][b] - aw};
    double C[4] = {L[0][c] - ax, L[1][c] - ay, L[2][c] - az, L[3][c] - aw};
    dd_lift_vminors(m, B, C);
#ifdef __SSE2__
    /* N made in registers and handed over in them: written in scalars
     * and read back in pairs, it would wait for the stores to commit (no
     * store forwarding from two writes to one read).                     */
    const __m128d m01 = _mm_loadu_pd(m), m23 = _mm_loadu_pd(m + 2);
    const __m128d n01 = _mm_xor_pd(_mm_shuffle_pd(m23, m01, 3), _mm_set_pd(-0.0, 0.0));   /* (m3, -m1) */
    const __m128d n23 = _mm_unpacklo_pd(m01, _mm_setzero_pd());                             /* (m0, 0)   */
    _mm_storeu_pd(N, n01);
    _mm_storeu_pd(N + 2, n23);
    dd_lift_cofactors_sse2(T, n01, n23, m);
#else
    dd_lift_normal_of(m, N);
    dd_lift_cofactors(T, N, m);
#endif
}

/* The normal N of plane (a, b, c), rows from a, as dd_lift_pencil has
 * it (the lift column left out: N does not use it).                    */
static inline void dd_lift_normal(double *const *L, uint32_t a, uint32_t b, uint32_t c, double N[4])
{
    const double B[3] = {L[0][b] - L[0][a], L[1][b] - L[1][a], L[2][b] - L[2][a]};
    const double C[3] = {L[0][c] - L[0][a], L[1][c] - L[1][a], L[2][c] - L[2][a]};
    /* dd_lift_minors' m[3], m[1], m[0] (dd_lift_normal_of), alone */
    N[0] = B[1] * C[2] - B[2] * C[1];
    N[1] = -(B[0] * C[2] - B[2] * C[0]);
    N[2] = B[0] * C[1] - B[1] * C[0];
    N[3] = 0;
}

/* ---- scalar passes -------------------------------------------------------- */

/* The first k, from <= k < end, whose o to the plane of normal N through
 * the row A is unsure (|o| <= oerr) with `unsure`, else not surely
 * behind (o >= -oerr); end if none.  O(end - from).                     */
static inline uint32_t dd_lift_next(double *const *L, const double A[4], const double N[4], double oerr,
                                    uint32_t from, uint32_t end, int unsure)
{
    for (uint32_t k = from; k < end; k++) {
        double P[4], o = dd_lift_row_o(L, k, A, N, P);
        if (unsure ? dd_lift_unsure(o, oerr) : !dd_lift_sure_neg(o, oerr)) return k;
    }
    return end;
}

/* Of the points ks[0..nk) (NULL: 0..nk), the one surely beyond the facet
 * of pencil N, T (rows from a) of least t/o, DD_LIFT_TIE when two such
 * quotients are equal, DD_LIFT_NONE when none is beyond; *unsure: how
 * many had unsure orientation.  No data-dependent branch; O(nk).        */
static inline uint32_t dd_lift_least_ratio(double *const *L, uint32_t a, const double N[4], const double T[4],
                                           double oerr, const uint32_t *ks, uint32_t nk, uint32_t *unsure)
{
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
    double br = 1.0 / 0.0;
    uint32_t best = DD_LIFT_NONE, uns = 0;
    int tie = 0;
    for (uint32_t i = 0; i < nk; i++) {
        const uint32_t k = ks ? ks[i] : i;
        double P[4], ok = dd_lift_row_o(L, k, A, N, P);
        int pos = dd_lift_sure_pos(ok, oerr);
        uns += !pos & (ok >= -oerr);       /* NaN: neither */
        double r = pos ? dd_lift_dot4(T, P) / ok : 1.0 / 0.0;
        tie |= pos & (r == br);
        best = r < br ? k : best;
        br = r < br ? r : br;
    }
    *unsure = uns;
    return tie ? DD_LIFT_TIE : best;
}

/* The points 0..n: o[k] = o(k) where k is surely beyond the facet of
 * pencil N, T (rows from a), else -1; returns the one of least t/o
 * (DD_LIFT_NONE if none; ties to the first), *unsure the number of
 * unsure orientations.  No data-dependent branch; O(n).                 */
static inline uint32_t dd_lift_least_beyond(double *const *L, uint32_t n, uint32_t a, const double N[4],
                                            const double T[4], double oerr, double *o, int *unsure)
{
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
    int uns = 0;
    double lo = 1.0 / 0.0;
    uint32_t best = DD_LIFT_NONE;
    for (uint32_t k = 0; k < n; k++) {
        double P[4], ok = dd_lift_row_o(L, k, A, N, P), tk = dd_lift_dot4(T, P);
        int pos = dd_lift_sure_pos(ok, oerr);
        uns += !pos & (ok >= -oerr);       /* NaN: neither */
        o[k] = pos ? ok : -1.0;                 /* > oerr: a candidate */
        double lam = pos ? tk / ok : 1.0 / 0.0;
        int better = lam < lo;
        lo = better ? lam : lo;
        best = better ? k : best;
    }
    *unsure = uns;
    return best;
}

/* Whether every point k < n with o[k] > oerr (dd_lift_least_beyond's
 * candidates) is surely outside the sphere of the cell whose cofactors
 * are K (rows from a): K . P > ierr.  No data-dependent branch; O(n).   */
static inline int dd_lift_all_outside(double *const *L, uint32_t n, uint32_t a, const double N[4], const double K[4],
                                      const double *o, double oerr, double ierr)
{
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
    int bad = 0;
    for (uint32_t k = 0; k < n; k++) {
        double P[4];
        dd_lift_row_o(L, k, A, N, P);
        double det = dd_lift_dot4(K, P);
        bad |= dd_lift_sure_pos(o[k], oerr) & !dd_lift_sure_pos(det, ierr);
    }
    return !bad;
}

/* ---- the frame's rows and ranks (lift.c) --------------------------------- */

/* Writes the rows of pts[0..n) relative to q into the columns L[0..3]
 * (room for n rounded up to a multiple of four: the padding is NaN) and
 * returns the frame (m, the bounds, the integer modes).  O(n).          */
dd_lift_frame dd_lift_rows(double *const *L, const double *const *pts, uint32_t n, const double *q);
/* The same for weighted points (lift.h's weighted lift): wt[k] the weight
 * of pts[k], qw q's; *wmax = W, the largest |w_x - w_q| as rounded (NaN
 * or +inf when one overflows).  The frame returned is dd_lift_rows' for
 * the same points (modes and bounds of the unweighted lift, which these
 * rows are when W = 0); the caller takes dd_lift_power_err otherwise.   */
dd_lift_frame dd_lift_rows_power(double *const *L, const double *const *pts, const double *wt, uint32_t n,
                                 const double *q, double qw, double *wmax);

/* rank[k]: the position of pts[k] in the lexicographic order of
 * pts[0..n) (dd_lex_cmp; the points distinct), the ranks that
 * dd_lift_symbolic takes.  tmp: room for n.  O(n log n) comparisons.   */
void dd_lex_ranks(const double *const *pts, uint32_t n, uint32_t *tmp, uint32_t *rank);

/* 1 when this build contracts a * b - c * d into a fused multiply-add
 * (fp.h: clang under -ffp-contract=fast), which voids every bound.      */
int dd_fp_fused(void);

/* ---- AVX2 passes in doubles (lift_simd.c) --------------------------------
 * Each evaluates o as dd_lift_row_o, lane by lane, so it agrees with the
 * scalar passes on every point; the rows are padded with NaN to a
 * multiple of four, and a lane of padding is never a candidate, never
 * unsure and never behind.  Only where the CPU has AVX2.                */
#ifdef DD_LIFT_AVX2
/* dd_lift_least_ratio over 0..n, four points a vector: the point surely
 * beyond of least t/o, DD_LIFT_TIE, DD_LIFT_NONE; *unsure: whether points
 * other than a and the facet's two other corners had unsure o.          */
uint32_t dd_lift_guess_avx2(double *const *L, uint32_t n, uint32_t a, const double N[4], const double T[4],
                            double oerr, int *unsure);
/* The same without the count of unsure orientations. */
uint32_t dd_lift_guess_lean_avx2(double *const *L, uint32_t n, uint32_t a, const double N[4], const double T[4],
                                 double oerr);
/* dd_lift_next from `from` to n, rows from a: the first k unsure (or not
 * surely behind); n if none.                                             */
uint32_t dd_lift_next_avx2(double *const *L, uint32_t n, uint32_t a, const double N[4], double oerr, uint32_t from,
                           int unsure);
/* Whether every point k < end but x, y, z is surely behind the plane of
 * normal N through y (o < -oerr, rows from y).                          */
int dd_lift_all_behind_avx2(double *const *L, uint32_t end, uint32_t x, uint32_t y, uint32_t z, const double N[4],
                            double oerr);
#endif

/* ---- single precision (lift_f32.c) ---------------------------------------
 * The rows in units of the frame's size m (the lift column in m^2),
 * rounded to floats, and passes over them that only rank: a caller
 * checks each answer in doubles.  Only for DD_LIFT_F32_MIN <= m <=
 * DD_LIFT_F32_MAX, where the scales stay finite; with AVX2 and FMA.      */
#define DD_LIFT_F32_MIN 1e-50
#define DD_LIFT_F32_MAX 1e50

/* Whether a frame of size m may have float rows. */
static inline int dd_lift_f32_ok(double m)
{
    return m >= DD_LIFT_F32_MIN && m <= DD_LIFT_F32_MAX;
}

/* The scales that take N and T (dd_lift_pencil) to the float rows'
 * units: N, T's first three and T's lift coordinate.                    */
typedef struct dd_lift_f32_scale {
    double sn, st, st3;
} dd_lift_f32_scale;

/* Writes the float rows F[0..3] of the rows L[0..3] of a frame of size m
 * (dd_lift_f32_ok), padded with NaN to a multiple of eight, and returns
 * the scales.  O(n).                                                     */
dd_lift_f32_scale dd_lift_f32_rows(double *const *L, uint32_t n, double m, float *const *F);

#ifdef DD_LIFT_AVX2
/* The point surely beyond the facet of pencil N, T (rows from a) of least
 * t/o in single precision, DD_LIFT_BEHIND when every point but the
 * facet's corners is behind, or DD_LIFT_NONE: abstains when a point
 * other than the corners is within the band of the plane, or on a tie.  */
uint32_t dd_lift_guess_f32(float *const *F, uint32_t n, uint32_t a, const double N[4], const double T[4],
                           dd_lift_f32_scale sc);
/* The hull step's point around edge ab in single precision (the point
 * furthest counter-clockwise seen along ab), or DD_LIFT_NONE.            */
uint32_t dd_lift_inf_f32(float *const *F, uint32_t n, uint32_t a, uint32_t b);
#endif

#endif
