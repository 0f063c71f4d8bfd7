/*
 * lift_simd.c -- the AVX2 passes of the lifted filter in doubles (lift_pass.h),
 * four points a vector: the least t/o beyond a facet, full and lean
 * (docs/gift-wrap.md §6 WIDE), and the passes that look for the points
 * near a plane (dd_lift_next_avx2, dd_lift_all_behind_avx2).
 *
 * Invariant: o is evaluated with dd_lift_row_o's operations lane by lane,
 * bit for bit, so lift.h's orientation bound covers these passes and a
 * pass agrees with the scalar ones on every point; a lane of the NaN
 * padding is never a candidate, never unsure and never behind.  Called
 * only when the CPU has AVX2.
 */
#include "geom/lift_pass.h"

#ifdef DD_LIFT_AVX2
#include <immintrin.h>

/* The wide guess (docs §6 WIDE), four points a vector: the point beyond
 * the facet (o > oerr, o as dd_lift_row_o) of least quotient t/o, DD_LIFT_TIE when a
 * quotient equals the least so far or two lanes end equal (only the
 * perturbation could break such a tie: the guess is refuted at once),
 * DD_LIFT_NONE when no point is beyond.  A point not beyond gets a NaN
 * quotient, which is never equal to the least, nor less.  Quotients, not
 * cross products: a guess needs no exact order, and a running minimum
 * keeps the loop's carried dependency to one min.  *unsure (unless
 * `lean`): whether points other than a, b, c have |o| <= oerr (a, b, c
 * always do); the caller then decides those exactly.  The rows are
 * padded with NaN to a multiple of four.  O(n).                          */
__attribute__((target("avx2"), always_inline)) static inline uint32_t
least_ratio_lanes(double *const *L, uint32_t n, uint32_t a, const double N[4], const double T[4], double oerr, int *unsure,
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
    if (_mm256_movemask_pd(tie)) return DD_LIFT_TIE;
    /* the least lane, without a branch on which lane holds it */
    __m256d lo = _mm256_min_pd(br, _mm256_permute2f128_pd(br, br, 1));
    lo = _mm256_min_pd(lo, _mm256_permute_pd(lo, 5));
    if (_mm256_cvtsd_f64(lo) == 1.0 / 0.0) return DD_LIFT_NONE;
    unsigned at = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(br, lo, _CMP_EQ_OQ));
    if (at & (at - 1)) return DD_LIFT_TIE;                 /* two lanes equal */
    double vi[4];
    _mm256_storeu_pd(vi, bi);
    return (uint32_t)vi[__builtin_ctz(at)];
}

/* The full wide guess: least_ratio_lanes counting the unsure orientations.  */
__attribute__((target("avx2"))) uint32_t dd_lift_guess_avx2(double *const *L, uint32_t n, uint32_t a, const double N[4],
                                                      const double T[4], double oerr, int *unsure)
{
    return least_ratio_lanes(L, n, a, N, T, oerr, unsure, 0);
}

/* The lean wide guess: no count of unsure orientations, so its caller
 * can neither decide such points exactly nor take the pass as proof
 * that every point is behind a hull facet (dd_lift_all_behind_avx2 can). */
__attribute__((target("avx2"))) uint32_t dd_lift_guess_lean_avx2(double *const *L, uint32_t n, uint32_t a,
                                                           const double N[4], const double T[4], double oerr)
{
    int unsure;                                      /* not counted */
    return least_ratio_lanes(L, n, a, N, T, oerr, &unsure, 1);
}

/* o of points k .. k + 3 (dd_lift_row_o's operations, bit for bit), the rows
 * taken from (ax, ay, az) and N = (n0, n1, n2): the passes of dd_lift_next_avx2
 * and dd_lift_all_behind_avx2.                                                */
__attribute__((target("avx2"))) static inline __m256d eval_o4(double *const *L, uint32_t k, __m256d ax, __m256d ay,
                                                                __m256d az, __m256d n0, __m256d n1, __m256d n2)
{
    const __m256d P0 = _mm256_sub_pd(_mm256_loadu_pd(L[0] + k), ax), P1 = _mm256_sub_pd(_mm256_loadu_pd(L[1] + k), ay),
                  P2 = _mm256_sub_pd(_mm256_loadu_pd(L[2] + k), az);
    return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(P0, n0), _mm256_mul_pd(P1, n1)), _mm256_mul_pd(P2, n2));
}

/* dd_lift_next with AVX2 (rows from a), four points a vector: the first k >= from, k < n,
 * unsure (|o| <= oerr) with `unsure`, else not surely behind (o >=
 * -oerr); n if none.  A lane of the padding past n is returned as n.    */
__attribute__((target("avx2"))) uint32_t dd_lift_next_avx2(double *const *L, uint32_t n, uint32_t a, const double N[4],
                                                     double oerr, uint32_t from, int unsure)
{
    const __m256d ax = _mm256_set1_pd(L[0][a]), ay = _mm256_set1_pd(L[1][a]), az = _mm256_set1_pd(L[2][a]);
    const __m256d n0 = _mm256_set1_pd(N[0]), n1 = _mm256_set1_pd(N[1]), n2 = _mm256_set1_pd(N[2]),
                  er = _mm256_set1_pd(oerr), ner = _mm256_set1_pd(-oerr), sign = _mm256_set1_pd(-0.0);
    uint32_t k = from & ~3u;
    unsigned before = (1u << (from - k)) - 1;        /* lanes before `from` */
    for (; k < n; k += 4) {
        const __m256d ok = eval_o4(L, k, ax, ay, az, n0, n1, n2);
        /* unsure: not |o| > oerr, so a NaN o is unsure, as in dd_lift_next */
        __m256d hit = unsure ? _mm256_cmp_pd(_mm256_andnot_pd(sign, ok), er, _CMP_NGT_UQ)
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

/* Every point but x, y, z surely behind, with AVX2: one pass of four points a vector (eval_o4),
 * the lanes from `end` on left out: it counts the points not surely
 * behind and compares the count with that of the corners among them (o
 * of each evaluated again by dd_lift_row_o: the same answer, bit for bit), so
 * no lane is masked by its number.  O(end).                             */
__attribute__((target("avx2"))) int dd_lift_all_behind_avx2(double *const *L, uint32_t end, uint32_t x, uint32_t y,
                                                      uint32_t z, const double N[4], double oerr)
{
    const __m256d ax = _mm256_set1_pd(L[0][y]), ay = _mm256_set1_pd(L[1][y]), az = _mm256_set1_pd(L[2][y]);
    const __m256d n0 = _mm256_set1_pd(N[0]), n1 = _mm256_set1_pd(N[1]), n2 = _mm256_set1_pd(N[2]),
                  ner = _mm256_set1_pd(-oerr);
    __m256i cnt = _mm256_setzero_si256();            /* per lane: not surely behind */
    uint32_t k = 0;
    for (; k + 4 <= end; k += 4) {
        const __m256d ok = eval_o4(L, k, ax, ay, az, n0, n1, n2);
        cnt = _mm256_sub_epi64(cnt, _mm256_castpd_si256(_mm256_cmp_pd(ok, ner, _CMP_NLT_UQ)));
    }
    if (k < end) {                                   /* the lanes before end */
        const __m256d ok = eval_o4(L, k, ax, ay, az, n0, n1, n2);
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
        corners += corner[i] < end && !(dd_lift_row_o(L, corner[i], A, N, P) < -oerr);
    }
    return total == corners;
}
#endif
