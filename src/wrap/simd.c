/*
 * simd.c -- the gift wrap's AVX2 passes (docs/gift-wrap.md §5, §6): the
 * wide guess, full and lean, in doubles four points a vector; the lean
 * guess and the hull step in single precision, eight points a vector;
 * and the passes that look for the points near a plane (w_next_avx2,
 * w_all_behind_avx2).
 *
 * Invariant: o is evaluated with w_row_o's operations lane by lane, bit
 * for bit, so the orientation bound of lift.c covers these passes and a
 * pass agrees with the scalar code on every point; a lane of the NaN
 * padding is never a candidate, never unsure and never behind.  The
 * single-precision passes only rank: each answer is checked in doubles
 * (w_make_cell, w_all_behind) or refuted by the proof, and made again in
 * doubles.  Called only when the CPU has AVX2 (w->avx2), the single-
 * precision passes only when it has FMA too (w->flift_ok).
 */
#include "wrap/wrap_int.h"

#ifdef W_AVX2
#include <immintrin.h>

/* The single-precision guess abstains when a point other than the
 * facet's corners lies within W_F32_BAND max|N_i| of its plane (o in the
 * float lifts' units): the rounding of the floats, about 1e-7 of o's
 * terms, could move o past 0 there.                                     */
#define W_F32_BAND 1e-6f

/* The wide guess (docs §6 WIDE), four points a vector: the point beyond
 * the facet (o > oerr, o as w_row_o) of least quotient t/o, W_TIE when a
 * quotient equals the least so far or two lanes end equal (only the
 * perturbation could break such a tie: the guess is refuted at once),
 * W_NONE when no point is beyond.  A point not beyond gets a NaN
 * quotient, which is never equal to the least, nor less.  Quotients, not
 * cross products: a guess needs no exact order, and a running minimum
 * keeps the loop's carried dependency to one min.  *unsure (unless
 * `lean`): whether points other than a, b, c have |o| <= oerr (a, b, c
 * always do); w_guess_apex then decides those exactly.  The lifts are
 * padded with NaN to a multiple of four.  O(n).                          */
__attribute__((target("avx2"), always_inline)) static inline uint32_t
w_guess_body(double *const *L, uint32_t n, uint32_t a, const double N[4], const double T[4], double oerr, int *unsure,
             const int lean)
{
    const __m256d ax = _mm256_set1_pd(L[0][a]), ay = _mm256_set1_pd(L[1][a]), az = _mm256_set1_pd(L[2][a]),
                  aw = _mm256_set1_pd(L[3][a]);
    const __m256d n0 = _mm256_set1_pd(N[0]), n1 = _mm256_set1_pd(N[1]), n2 = _mm256_set1_pd(N[2]);
    const __m256d t0 = _mm256_set1_pd(T[0]), t1 = _mm256_set1_pd(T[1]), t2 = _mm256_set1_pd(T[2]),
                  t3 = _mm256_set1_pd(T[3]), er = _mm256_set1_pd(oerr), four = _mm256_set1_pd(4),
                  inf = _mm256_set1_pd(1.0 / 0.0), sign = _mm256_set1_pd(-0.0),
                  nan = _mm256_set1_pd(NAN);
    __m256d br = inf, bi = _mm256_setzero_pd(), tie = bi;
    __m256i uns = _mm256_setzero_si256();            /* per lane: unsure orientations */
    __m256d kv = _mm256_setr_pd(0, 1, 2, 3);
    for (uint32_t k = 0; k < n; k += 4) {
        __m256d P0 = _mm256_sub_pd(_mm256_loadu_pd(L[0] + k), ax), P1 = _mm256_sub_pd(_mm256_loadu_pd(L[1] + k), ay);
        __m256d P2 = _mm256_sub_pd(_mm256_loadu_pd(L[2] + k), az), P3 = _mm256_sub_pd(_mm256_loadu_pd(L[3] + k), aw);
        __m256d ok = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(P0, n0), _mm256_mul_pd(P1, n1)), _mm256_mul_pd(P2, n2));
        __m256d tk = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(P0, t0), _mm256_mul_pd(P1, t1)),
                                   _mm256_add_pd(_mm256_mul_pd(P2, t2), _mm256_mul_pd(P3, t3)));
        __m256d pos = _mm256_cmp_pd(ok, er, _CMP_GT_OQ);
        if (!lean)
            uns = _mm256_sub_epi64(uns, _mm256_castpd_si256(_mm256_cmp_pd(_mm256_andnot_pd(sign, ok), er, _CMP_LE_OQ)));
        __m256d r = _mm256_blendv_pd(nan, _mm256_div_pd(tk, ok), pos);   /* NaN: never equal, less or least */
        tie = _mm256_or_pd(tie, _mm256_cmp_pd(r, br, _CMP_EQ_OQ));
        bi = _mm256_blendv_pd(bi, kv, _mm256_cmp_pd(r, br, _CMP_LT_OQ));
        br = _mm256_min_pd(r, br);
        kv = _mm256_add_pd(kv, four);
    }
    __m128i u = _mm_add_epi64(_mm256_castsi256_si128(uns), _mm256_extracti128_si256(uns, 1));
    *unsure = lean || _mm_cvtsi128_si64(_mm_add_epi64(u, _mm_unpackhi_epi64(u, u))) != 3;
    if (_mm256_movemask_pd(tie)) return W_TIE;
    /* the least lane, without a branch on which lane holds it */
    __m256d lo = _mm256_min_pd(br, _mm256_permute2f128_pd(br, br, 1));
    lo = _mm256_min_pd(lo, _mm256_permute_pd(lo, 5));
    if (_mm256_cvtsd_f64(lo) == 1.0 / 0.0) return W_NONE;
    unsigned at = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(br, lo, _CMP_EQ_OQ));
    if (at & (at - 1)) return W_TIE;                 /* two lanes equal */
    double vi[4];
    _mm256_storeu_pd(vi, bi);
    return (uint32_t)vi[__builtin_ctz(at)];
}

/* The full wide guess: w_guess_body counting the unsure orientations.  */
__attribute__((target("avx2"))) uint32_t w_guess_avx2(double *const *L, uint32_t n, uint32_t a, const double N[4],
                                                      const double T[4], double oerr, int *unsure)
{
    return w_guess_body(L, n, a, N, T, oerr, unsure, 0);
}

/* The lean wide guess (w->lean, from W_LEAN_FROM neighbours on): no count
 * of unsure orientations, so w_guess_apex neither decides such points
 * exactly nor takes the pass as proof that a hull facet has every point
 * behind it (w_all_behind does).  Where such a point is the apex the
 * proof refutes the guess, and the full one is made (w_next_guess).     */
__attribute__((target("avx2"))) uint32_t w_guess_lean_avx2(double *const *L, uint32_t n, uint32_t a,
                                                           const double N[4], const double T[4], double oerr)
{
    int unsure;                                      /* not counted */
    return w_guess_body(L, n, a, N, T, oerr, &unsure, 1);
}

/* The sum of x's eight lanes. */
__attribute__((target("avx2"))) static inline uint32_t w_hsum_epi32(__m256i x)
{
    __m128i s = _mm_add_epi32(_mm256_castsi256_si128(x), _mm256_extracti128_si256(x, 1));
    s = _mm_add_epi32(s, _mm_shuffle_epi32(s, 0x4E));
    s = _mm_add_epi32(s, _mm_shuffle_epi32(s, 0xB1));
    return (uint32_t)_mm_cvtsi128_si32(s);
}

/* The lean guess in single precision (docs §6), eight points a vector,
 * over the float lifts F with the pencil nf, tf in their units: the point
 * beyond the facet of least t/o, o and t as fused multiply-adds less a's
 * (o(a) is then a rounding error, well inside the band).  It abstains,
 * W_NONE, when a point other than a, b, c lies within `band` of the plane
 * (where the floats could misplace it) or two lanes tie; with no point
 * beyond and none in the band it answers W_BEHIND (a hull facet, which
 * w_all_behind then proves in doubles).  A point not beyond gets an
 * all-ones o, a NaN quotient that neither compares below the least nor
 * is taken by the min; the band's count is made in integers.  O(n).      */
__attribute__((target("avx2,fma"), always_inline)) static inline uint32_t
w_guess_f32_avx2(float *const *F, uint32_t n, uint32_t a, const float nf[3], const float tf[4], float band)
{
    const __m256 n0 = _mm256_set1_ps(nf[0]), n1 = _mm256_set1_ps(nf[1]), n2 = _mm256_set1_ps(nf[2]);
    const __m256 t0 = _mm256_set1_ps(tf[0]), t1 = _mm256_set1_ps(tf[1]), t2 = _mm256_set1_ps(tf[2]),
                 t3 = _mm256_set1_ps(tf[3]), er = _mm256_set1_ps(band);
    /* |o| > band compared as integers (non-negative floats order as
     * their bits; the NaN padding's are above any band's), off the
     * floating-point compare's ports                                     */
    const __m256i erb = _mm256_castps_si256(er), abs = _mm256_set1_epi32(0x7fffffff), eight = _mm256_set1_epi32(8);
    /* a's dot products, taken from each lane's                        */
    const __m256 A0 = _mm256_set1_ps(F[0][a]), A1 = _mm256_set1_ps(F[1][a]), A2 = _mm256_set1_ps(F[2][a]),
                 A3 = _mm256_set1_ps(F[3][a]);
    const __m256 an = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(A0, n0), _mm256_mul_ps(A1, n1)), _mm256_mul_ps(A2, n2));
    const __m256 at = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(A0, t0), _mm256_mul_ps(A1, t1)),
                                    _mm256_add_ps(_mm256_mul_ps(A2, t2), _mm256_mul_ps(A3, t3)));
    __m256 br = _mm256_set1_ps(INFINITY);        /* a constant: 1.0f / 0.0f divides at run time */
    __m256i bi = _mm256_setzero_si256(), out = _mm256_setzero_si256(), kv = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    uint32_t k = 0;
    for (; k < n; k += 8) {
        const __m256 P0 = _mm256_loadu_ps(F[0] + k), P1 = _mm256_loadu_ps(F[1] + k), P2 = _mm256_loadu_ps(F[2] + k),
                     P3 = _mm256_loadu_ps(F[3] + k);
        __m256 ok = _mm256_fmadd_ps(P2, n2, _mm256_fmadd_ps(P1, n1, _mm256_fmsub_ps(P0, n0, an)));
        __m256 tk = _mm256_fmadd_ps(P3, t3,
                                    _mm256_fmadd_ps(P2, t2, _mm256_fmadd_ps(P1, t1, _mm256_fmsub_ps(P0, t0, at))));
        out = _mm256_sub_epi32(out, _mm256_cmpgt_epi32(_mm256_and_si256(_mm256_castps_si256(ok), abs), erb));
        /* a point not beyond: o all ones, a NaN, and so its quotient,
         * which neither compares below br nor is taken by the min       */
        __m256 r = _mm256_div_ps(tk, _mm256_or_ps(ok, _mm256_cmp_ps(ok, er, _CMP_NGT_UQ)));
        bi = _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(bi), _mm256_castsi256_ps(kv),
                                                  _mm256_cmp_ps(r, br, _CMP_LT_OQ)));
        br = _mm256_min_ps(r, br);
        kv = _mm256_add_epi32(kv, eight);
    }
    /* the least lane, and the count */
    __m256 lo = _mm256_min_ps(br, _mm256_permute2f128_ps(br, br, 1));
    lo = _mm256_min_ps(lo, _mm256_permute_ps(lo, 0x4e));
    lo = _mm256_min_ps(lo, _mm256_permute_ps(lo, 0xb1));
    const unsigned lane = (unsigned)_mm256_movemask_ps(_mm256_cmp_ps(br, lo, _CMP_EQ_OQ));
    /* a, b, c only near the plane; a point beyond (else all behind); one
     * least lane                                                         */
    if (k - w_hsum_epi32(out) != 3) return W_NONE;
    if (!(_mm256_cvtss_f32(lo) < INFINITY)) return W_BEHIND;
    if (lane & (lane - 1)) return W_NONE;
    uint32_t ix[8];
    _mm256_storeu_si256((__m256i *)ix, bi);
    return ix[__builtin_ctz(lane)];
}

/* o of points k .. k + 3 (w_row_o's operations, bit for bit), the rows
 * taken from (ax, ay, az) and N = (n0, n1, n2): the passes of w_next_avx2
 * and w_all_behind_avx2.                                                */
__attribute__((target("avx2"))) static inline __m256d w_o4_avx2(double *const *L, uint32_t k, __m256d ax, __m256d ay,
                                                                __m256d az, __m256d n0, __m256d n1, __m256d n2)
{
    const __m256d P0 = _mm256_sub_pd(_mm256_loadu_pd(L[0] + k), ax), P1 = _mm256_sub_pd(_mm256_loadu_pd(L[1] + k), ay),
                  P2 = _mm256_sub_pd(_mm256_loadu_pd(L[2] + k), az);
    return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(P0, n0), _mm256_mul_pd(P1, n1)), _mm256_mul_pd(P2, n2));
}

/* w_next_to with AVX2, four points a vector: the first k >= from, k < n,
 * unsure (|o| <= oerr) with `unsure`, else not surely behind (o >=
 * -oerr); n if none.  A lane of the padding past n is returned as n.    */
__attribute__((target("avx2"))) uint32_t w_next_avx2(double *const *L, uint32_t n, uint32_t a, const double N[4],
                                                     double oerr, uint32_t from, int unsure)
{
    const __m256d ax = _mm256_set1_pd(L[0][a]), ay = _mm256_set1_pd(L[1][a]), az = _mm256_set1_pd(L[2][a]);
    const __m256d n0 = _mm256_set1_pd(N[0]), n1 = _mm256_set1_pd(N[1]), n2 = _mm256_set1_pd(N[2]),
                  er = _mm256_set1_pd(oerr), ner = _mm256_set1_pd(-oerr), sign = _mm256_set1_pd(-0.0);
    uint32_t k = from & ~3u;
    unsigned before = (1u << (from - k)) - 1;        /* lanes before `from` */
    for (; k < n; k += 4) {
        const __m256d ok = w_o4_avx2(L, k, ax, ay, az, n0, n1, n2);
        __m256d hit = unsure ? _mm256_cmp_pd(_mm256_andnot_pd(sign, ok), er, _CMP_LE_OQ)
                             : _mm256_cmp_pd(ok, ner, _CMP_NLT_UQ);
        unsigned m = (unsigned)_mm256_movemask_pd(hit) & ~before;
        before = 0;
        if (m) {
            uint32_t k1 = k + (uint32_t)__builtin_ctz(m);
            return k1 < n ? k1 : n;
        }
    }
    return n;
}

/* The lean guess in single precision (w->f32): the pencil N, T taken to
 * the float lifts' units (w_lift_f32, made at the first call of the
 * deletion), the band scaled by max|N_i|; a point, W_BEHIND, or W_NONE
 * (abstained: the guess is made in doubles).  Test builds answer a wrong
 * point on one guess in 16 (W_F32_SPOIL), which the proof must refute.  */
__attribute__((target("avx2,fma"))) uint32_t w_guess_f32(struct dd_wrap *w, uint32_t a, const double N[4],
                                                         const double T[4])
{
    float *const *F = w_flift(w);                    /* and the scales */
    const double sn = w->f32_sn, st = w->f32_st, st3 = w->f32_st3;
    const float nf[3] = {(float)(N[0] * sn), (float)(N[1] * sn), (float)(N[2] * sn)};
    const float tf[4] = {(float)(T[0] * st), (float)(T[1] * st), (float)(T[2] * st), (float)(T[3] * st3)};
    float mn = fabsf(nf[0]) > fabsf(nf[1]) ? fabsf(nf[0]) : fabsf(nf[1]);
    mn = fabsf(nf[2]) > mn ? fabsf(nf[2]) : mn;
    const uint32_t p = w_guess_f32_avx2(F, w->n, a, nf, tf, W_F32_BAND * mn);
    if (p < w->n && W_F32_SPOIL(w) && w->f32_kept % 16 == 15) return (p + 1 + w->f32_kept % 5) % w->n;
    return p;
}

/* w_all_behind with AVX2, one pass of four points a vector (w_o4_avx2),
 * the lanes from `end` on left out: it counts the points not surely
 * behind and compares the count with that of the corners among them (o
 * of each evaluated again by w_row_o: the same answer, bit for bit), so
 * no lane is masked by its number.  O(end).                             */
__attribute__((target("avx2"))) int w_all_behind_avx2(double *const *L, uint32_t end, uint32_t x, uint32_t y,
                                                      uint32_t z, const double N[4], double oerr)
{
    const __m256d ax = _mm256_set1_pd(L[0][y]), ay = _mm256_set1_pd(L[1][y]), az = _mm256_set1_pd(L[2][y]);
    const __m256d n0 = _mm256_set1_pd(N[0]), n1 = _mm256_set1_pd(N[1]), n2 = _mm256_set1_pd(N[2]),
                  ner = _mm256_set1_pd(-oerr);
    __m256i cnt = _mm256_setzero_si256();            /* per lane: not surely behind */
    uint32_t k = 0;
    for (; k + 4 <= end; k += 4) {
        const __m256d ok = w_o4_avx2(L, k, ax, ay, az, n0, n1, n2);
        cnt = _mm256_sub_epi64(cnt, _mm256_castpd_si256(_mm256_cmp_pd(ok, ner, _CMP_NLT_UQ)));
    }
    if (k < end) {                                   /* the lanes before end */
        const __m256d ok = w_o4_avx2(L, k, ax, ay, az, n0, n1, n2);
        const __m256i in = _mm256_cmpgt_epi64(_mm256_set1_epi64x((long long)end),
                                              _mm256_add_epi64(_mm256_set1_epi64x(k), _mm256_setr_epi64x(0, 1, 2, 3)));
        cnt = _mm256_sub_epi64(cnt, _mm256_and_si256(in, _mm256_castpd_si256(_mm256_cmp_pd(ok, ner, _CMP_NLT_UQ))));
    }
    __m128i c = _mm_add_epi64(_mm256_castsi256_si128(cnt), _mm256_extracti128_si256(cnt, 1));
    const long long total = _mm_cvtsi128_si64(_mm_add_epi64(c, _mm_unpackhi_epi64(c, c)));
    const double A[4] = {L[0][y], L[1][y], L[2][y], L[3][y]};
    const uint32_t corner[3] = {x, y, z};
    long long corners = 0;
    for (int i = 0; i < 3; i++) {
        double P[4];
        corners += corner[i] < end && !(w_row_o(L, corner[i], A, N, P) < -oerr);
    }
    return total == corners;
}

/* Each lane: the point (u, wv) of number kv, if pt, replaces the lane's
 * best (*bu, *bw, *bi) when counter-clockwise of it, or when the lane has
 * none yet (*has).                                                      */
__attribute__((target("avx2,fma"))) static inline void w_ccw_take(__m256 u, __m256 wv, __m256 kv, __m256 pt,
                                                                  __m256 *bu, __m256 *bw, __m256 *bi, __m256 *has)
{
    const __m256 ccw = _mm256_cmp_ps(_mm256_fmsub_ps(*bu, wv, _mm256_mul_ps(*bw, u)), _mm256_setzero_ps(), _CMP_GT_OQ);
    const __m256 take = _mm256_and_ps(pt, _mm256_blendv_ps(pt, ccw, *has));
    *bu = _mm256_blendv_ps(*bu, u, take);
    *bw = _mm256_blendv_ps(*bw, wv, take);
    *bi = _mm256_blendv_ps(*bi, kv, take);
    *has = _mm256_or_ps(*has, take);
}

/* Each lane of (u, w, i, h) against the one PERM brings to it.          */
#define W_CCW_FOLD(u, w, i, h, PERM)                                                                  \
    w_ccw_take(PERM(u), PERM(w), PERM(i), PERM(h), &(u), &(w), &(i), &(h))
#define W_SWAP128(x) _mm256_permute2f128_ps(x, x, 1)
#define W_SWAP64(x) _mm256_permute_ps(x, 0x4e)
#define W_SWAP32(x) _mm256_permute_ps(x, 0xb1)

/* The hull step's point (docs §5) in single precision, eight points a
 * vector: the point furthest round the hull edge ab, or W_NONE.  Seen
 * along ab (each point's offset from b projected on E1, E2, perpendicular
 * to B = a - b, E1 x E2 a positive multiple of B), x is beyond the plane
 * of b, a, p iff x is counter-clockwise of p, so the facet's point is the
 * furthest counter-clockwise.  Each lane keeps its furthest in two sets
 * that take the vectors in turn (two independent chains of compares),
 * then the sets and the lanes are folded, vectors again.  Only a guess:
 * w_scan_inf takes it when every other point is surely behind its plane
 * in doubles (w_all_behind), else makes the step in doubles.  O(n).     */
__attribute__((target("avx2,fma"))) uint32_t w_inf_f32(float *const *F, uint32_t n, uint32_t a, uint32_t b)
{
    const float B[3] = {F[0][a] - F[0][b], F[1][a] - F[1][b], F[2][a] - F[2][b]};
    const float ax0 = fabsf(B[0]), ax1 = fabsf(B[1]), ax2 = fabsf(B[2]);
    float E1[3];                                     /* B x the axis B is least along */
    if (ax0 <= ax1 && ax0 <= ax2) { E1[0] = 0; E1[1] = B[2]; E1[2] = -B[1]; }
    else if (ax1 <= ax2) { E1[0] = -B[2]; E1[1] = 0; E1[2] = B[0]; }
    else { E1[0] = B[1]; E1[1] = -B[0]; E1[2] = 0; }
    const float E2[3] = {B[1] * E1[2] - B[2] * E1[1], B[2] * E1[0] - B[0] * E1[2], B[0] * E1[1] - B[1] * E1[0]};
    const __m256 b0 = _mm256_set1_ps(F[0][b]), b1 = _mm256_set1_ps(F[1][b]), b2 = _mm256_set1_ps(F[2][b]);
    const __m256 e10 = _mm256_set1_ps(E1[0]), e11 = _mm256_set1_ps(E1[1]), e12 = _mm256_set1_ps(E1[2]);
    const __m256 e20 = _mm256_set1_ps(E2[0]), e21 = _mm256_set1_ps(E2[1]), e22 = _mm256_set1_ps(E2[2]);
    const __m256 fa = _mm256_set1_ps((float)a), fb = _mm256_set1_ps((float)b), eight = _mm256_set1_ps(8);
    __m256 bu[2], bw[2], bi[2], has[2];
    for (int c = 0; c < 2; c++) bu[c] = bw[c] = bi[c] = has[c] = _mm256_setzero_ps();
    __m256 kv = _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7);
    for (uint32_t k = 0, c = 0; k < n; k += 8, c ^= 1) {
        const __m256 v0 = _mm256_sub_ps(_mm256_loadu_ps(F[0] + k), b0),
                     v1 = _mm256_sub_ps(_mm256_loadu_ps(F[1] + k), b1),
                     v2 = _mm256_sub_ps(_mm256_loadu_ps(F[2] + k), b2);
        const __m256 u = _mm256_fmadd_ps(v2, e12, _mm256_fmadd_ps(v1, e11, _mm256_mul_ps(v0, e10)));
        const __m256 wv = _mm256_fmadd_ps(v2, e22, _mm256_fmadd_ps(v1, e21, _mm256_mul_ps(v0, e20)));
        /* a point: not a, b, nor the NaN padding                        */
        const __m256 notab = _mm256_and_ps(_mm256_cmp_ps(kv, fa, _CMP_NEQ_OQ), _mm256_cmp_ps(kv, fb, _CMP_NEQ_OQ));
        const __m256 pt = _mm256_and_ps(notab, _mm256_cmp_ps(u, u, _CMP_ORD_Q));
        /* set c, named: as &bu[c] the sets would go through the stack */
        if (c) w_ccw_take(u, wv, kv, pt, &bu[1], &bw[1], &bi[1], &has[1]);
        else w_ccw_take(u, wv, kv, pt, &bu[0], &bw[0], &bi[0], &has[0]);
        kv = _mm256_add_ps(kv, eight);
    }
    w_ccw_take(bu[1], bw[1], bi[1], has[1], &bu[0], &bw[0], &bi[0], &has[0]);
    __m256 u = bu[0], v = bw[0], ix = bi[0], h = has[0];
    W_CCW_FOLD(u, v, ix, h, W_SWAP128);
    W_CCW_FOLD(u, v, ix, h, W_SWAP64);
    W_CCW_FOLD(u, v, ix, h, W_SWAP32);
    return _mm256_movemask_ps(h) & 1 ? (uint32_t)_mm256_cvtss_f32(ix) : W_NONE;
}
#undef W_CCW_FOLD
#undef W_SWAP128
#undef W_SWAP64
#undef W_SWAP32
#endif
