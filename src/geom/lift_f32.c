/*
 * lift_f32.c -- the lifted filter in single precision (lift_pass.h): the
 * float rows of a frame and the AVX2 passes over them, eight points a
 * vector: the least t/o beyond a facet (docs/gift-wrap.md §6) and the
 * hull step's point (§5).
 *
 * Invariant: these passes only rank.  Each answer is a point the caller
 * checks in doubles (the wrap: w_make_cell, w_all_behind) or refutes by
 * its proof; nothing is certified in floats, so no bound covers them and
 * they use fused multiply-adds (fp.h).  The single-precision guess
 * abstains near the plane (DD_LIFT_F32_BAND), where the floats' rounding
 * could misplace a point.  Called only when the CPU has AVX2 and FMA.
 */
#include "geom/lift_pass.h"

/* The float rows: x_k - q over m and |x_k - q|^2 over m^2 (at most 1 and
 * 3), rounded to floats, padded with NaN to a multiple of eight; and the
 * scales that take N and T (dd_lift_pencil) to the same units: N's
 * entries are at most 8m^2, T's O(m^5) (xyz) and O(m^4) (lift), so that
 * o and t are O(1) or less there.  O(n).                                */
dd_lift_f32_scale dd_lift_f32_rows(double *const *L, uint32_t n, double m, float *const *F)
{
    const double s = 1.0 / m, s2 = s * s;
    const dd_lift_f32_scale sc = {s2, s2 * s2 * s, s2 * s2};   /* N: 8m^2; T: O(m^5), O(m^4) */
    for (int i = 0; i < 4; i++) {
        const double *Li = L[i], f = i < 3 ? s : s2;
        float *Fi = F[i];
        uint32_t k = 0;
        for (; k < n; k++) Fi[k] = (float)(Li[k] * f);
        for (; k % 8; k++) Fi[k] = NAN;
    }
    return sc;
}

#ifdef DD_LIFT_AVX2
#include <immintrin.h>

/* The single-precision guess abstains when a point other than the
 * facet's corners lies within DD_LIFT_F32_BAND max|N_i| of its plane (o in the
 * float lifts' units): the rounding of the floats, about 1e-7 of o's
 * terms, could move o past 0 there.                                     */
#define DD_LIFT_F32_BAND 1e-6f

/* The sum of x's eight lanes. */
__attribute__((target("avx2"))) static inline uint32_t sum_lanes(__m256i x)
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
 * DD_LIFT_NONE, when a point other than a, b, c lies within `band` of the plane
 * (where the floats could misplace it) or two lanes tie; with no point
 * beyond and none in the band it answers DD_LIFT_BEHIND (a hull facet, which
 * the caller then proves in doubles).  A point not beyond gets an
 * all-ones o, a NaN quotient that neither compares below the least nor
 * is taken by the min; the band's count is made in integers.  O(n).      */
__attribute__((target("avx2,fma"), always_inline)) static inline uint32_t
least_ratio_f32(float *const *F, uint32_t n, uint32_t a, const float nf[3], const float tf[4], float band)
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
    if (k - sum_lanes(out) != 3) return DD_LIFT_NONE;
    if (!(_mm256_cvtss_f32(lo) < INFINITY)) return DD_LIFT_BEHIND;
    if (lane & (lane - 1)) return DD_LIFT_NONE;
    uint32_t ix[8];
    _mm256_storeu_si256((__m256i *)ix, bi);
    return ix[__builtin_ctz(lane)];
}

/* The lean guess in single precision: the pencil N, T taken to the float
 * rows' units by sc, the band scaled by max|N_i|.                        */
__attribute__((target("avx2,fma"))) uint32_t dd_lift_guess_f32(float *const *F, uint32_t n, uint32_t a,
                                                               const double N[4], const double T[4],
                                                               dd_lift_f32_scale sc)
{
    const double sn = sc.sn, st = sc.st, st3 = sc.st3;
    const float nf[3] = {(float)(N[0] * sn), (float)(N[1] * sn), (float)(N[2] * sn)};
    const float tf[4] = {(float)(T[0] * st), (float)(T[1] * st), (float)(T[2] * st), (float)(T[3] * st3)};
    float mn = fabsf(nf[0]) > fabsf(nf[1]) ? fabsf(nf[0]) : fabsf(nf[1]);
    mn = fabsf(nf[2]) > mn ? fabsf(nf[2]) : mn;
    return least_ratio_f32(F, n, a, nf, tf, DD_LIFT_F32_BAND * mn);
}

/* Each lane: the point (u, wv) of number kv, if pt, replaces the lane's
 * best (*bu, *bw, *bi) when counter-clockwise of it, or when the lane has
 * none yet (*has).                                                      */
__attribute__((target("avx2,fma"))) static inline void take_ccw(__m256 u, __m256 wv, __m256 kv, __m256 pt,
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
#define CCW_FOLD(u, w, i, h, PERM)                                                                  \
    take_ccw(PERM(u), PERM(w), PERM(i), PERM(h), &(u), &(w), &(i), &(h))
#define SWAP128(x) _mm256_permute2f128_ps(x, x, 1)
#define SWAP64(x) _mm256_permute_ps(x, 0x4e)
#define SWAP32(x) _mm256_permute_ps(x, 0xb1)

/* The hull step's point (docs §5) in single precision, eight points a
 * vector: the point furthest round the hull edge ab, or DD_LIFT_NONE.  Seen
 * along ab (each point's offset from b projected on E1, E2, perpendicular
 * to B = a - b, E1 x E2 a positive multiple of B), x is beyond the plane
 * of b, a, p iff x is counter-clockwise of p, so the facet's point is the
 * furthest counter-clockwise.  Each lane keeps its furthest in two sets
 * that take the vectors in turn (two independent chains of compares),
 * then the sets and the lanes are folded, vectors again.  Only a guess:
 * the wrap takes it when every other point is surely behind its plane
 * in doubles (dd_lift_all_behind_avx2), else makes the step in doubles.
 * O(n).     */
__attribute__((target("avx2,fma"))) uint32_t dd_lift_inf_f32(float *const *F, uint32_t n, uint32_t a, uint32_t b)
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
        if (c) take_ccw(u, wv, kv, pt, &bu[1], &bw[1], &bi[1], &has[1]);
        else take_ccw(u, wv, kv, pt, &bu[0], &bw[0], &bi[0], &has[0]);
        kv = _mm256_add_ps(kv, eight);
    }
    take_ccw(bu[1], bw[1], bi[1], has[1], &bu[0], &bw[0], &bi[0], &has[0]);
    __m256 u = bu[0], v = bw[0], ix = bi[0], h = has[0];
    CCW_FOLD(u, v, ix, h, SWAP128);
    CCW_FOLD(u, v, ix, h, SWAP64);
    CCW_FOLD(u, v, ix, h, SWAP32);
    return _mm256_movemask_ps(h) & 1 ? (uint32_t)_mm256_cvtss_f32(ix) : DD_LIFT_NONE;
}
#undef CCW_FOLD
#undef SWAP128
#undef SWAP64
#undef SWAP32
#endif
