/*
 * test_filters.c -- every evaluation path of the lifted filter
 * (geom/lift.h, lift_pass.h) against the exact signs (pred.h): the
 * scalar evaluations (dd_lift_det4, dd_lift_minors, dd_lift_cofactors,
 * the scalar passes), SSE2 (dd_lift_minors_sse2, dd_lift_cofactors_sse2,
 * dd_lift_pencil), AVX2 (lift_simd.c) and single precision (lift_f32.c),
 * the last two only where the CPU has them (the output says which ran).
 *
 * For every answer a path certifies, the exact sign agrees; a path may
 * decline.  What each path certifies:
 *  - scalar and SSE2: a value beyond its bound (dd_lift_sure) has the
 *    sign of orient3d, resp. -insphere; in an integer mode the values
 *    are exact (dd_lift_sign_kp too); the SSE2 minors, cofactors and
 *    pencil are the scalar ones, bit for bit;
 *  - AVX2: each point a pass skips is surely behind (or surely not in
 *    the plane), a point it answers is surely beyond, "none unsure" means
 *    no point but the corners is in the plane, "all behind" that every
 *    other point is behind; the passes that find points near a plane
 *    answer what the scalar ones answer (the least quotient may not: t
 *    is summed in another order, and it only ranks);
 *  - single precision: a point it answers is beyond the facet, and
 *    DD_LIFT_BEHIND means every other point is behind (outside its band).
 * Inputs: random frames, exactly cospherical ones (integer points on a
 * sphere through q), the same moved by one ulp, extreme magnitudes
 * (where the bounds are +inf and nothing may be certified), and frames
 * just inside and just outside each path's range: the lifted bounds'
 * [DD_LIFT_M_MIN, DD_LIFT_M_MAX], the integer modes' limits and the float
 * rows' [DD_LIFT_F32_MIN, DD_LIFT_F32_MAX].
 */
#include "testlib.h"
#include "geom/lift_pass.h"
#include "geom/pred.h"

#include <math.h>

#define NMAX 64   /* points of a frame; the rows have room for the padding */

/* One frame: q, the points, their rows in columns and float rows. */
typedef struct frame {
    double q[3], p[NMAX][3];
    const double *pt[NMAX];
    uint32_t n;
    double col[4][NMAX + 8];
    float fcol[4][NMAX + 8];
    double *L[4];
    float *F[4];
    dd_lift_frame f;
} frame;

/* What the paths did, for the summary lines. */
typedef struct tally {
    long certified, declined, wrong;
    char first[200];
} tally;

static dd_pred pr;
static int has_avx2, has_fma;

static void count(tally *t, int certified, int agrees, const char *what, const frame *fr)
{
    if (!certified) {
        t->declined++;
        return;
    }
    t->certified++;
    if (!agrees && t->wrong++ == 0)
        snprintf(t->first, sizeof t->first, "%s (m = %.17g)", what, fr->f.m);
}

static void make_rows(frame *fr)
{
    for (int i = 0; i < 4; i++) fr->L[i] = fr->col[i], fr->F[i] = fr->fcol[i];
    for (uint32_t k = 0; k < fr->n; k++) fr->pt[k] = fr->p[k];
    fr->f = dd_lift_rows(fr->L, fr->pt, fr->n, fr->q);
}

static int sgn(double x) { return (x > 0) - (x < 0); }

/* Equal values; any two NaNs are the same (which NaN an operation makes
 * depends on its operands' order, and no path certifies a NaN).         */
static int same(const double *x, const double *y, int n)
{
    int eq = 1;
    for (int i = 0; i < n; i++) eq &= x[i] == y[i] || (isnan(x[i]) && isnan(y[i]));
    return eq;
}

/* The scalar and SSE2 paths on facet (a, b, c) and apex x of the frame. */
static void check_scalar(frame *fr, uint32_t a, uint32_t b, uint32_t c, uint32_t x, tally *to, tally *ti,
                         tally *bits)
{
    double *const *L = fr->L;
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
    double B[4], C[4], X[4], m[6], N[4], K[4];
    for (int i = 0; i < 4; i++) B[i] = L[i][b] - A[i], C[i] = L[i][c] - A[i], X[i] = L[i][x] - A[i];
    dd_lift_minors(m, B, C);
    dd_lift_normal_of(m, N);
    dd_lift_cofactors(K, X, m);
    /* SSE2 (or the same scalar code without it): bit for bit */
    double mv[6], Nv[4], Tv[4], Kv[4], T[4];
    dd_lift_vminors(mv, B, C);
    dd_lift_vcofactors(Kv, X, m);
    dd_lift_pencil(L, a, b, c, mv, Nv, Tv);
    dd_lift_cofactors(T, N, m);
    const int eq = same(m, mv, 6) && same(K, Kv, 4) && same(T, Tv, 4) && same(N, Nv, 4);
    count(bits, 1, eq, "SSE2 minors / cofactors / pencil differ from the scalar ones", fr);
    const double *P0 = fr->pt[a], *P1 = fr->pt[b], *P2 = fr->pt[c], *PX = fr->pt[x];
    const int ox = dd_orient3d(&pr, P0, P1, P2, PX);
    for (uint32_t k = 0; k < fr->n; k++) {
        double P[4];
        const double o = dd_lift_row_o(L, k, A, N, P);
        const int exact_o = dd_orient3d(&pr, P0, P1, P2, fr->pt[k]);
        const int so = dd_lift_sure(o, fr->f.oerr);
        count(to, so != 0, so == exact_o, "orientation certified with the wrong sign", fr);
        if (fr->f.modes & DD_LIFT_OEXACT) count(to, 1, sgn(o) == exact_o, "an exact orientation is wrong", fr);
        const double o2 = dd_lift_orient(m, P);
        count(to, 1, same(&o, &o2, 1), "dd_lift_row_o differs from dd_lift_orient", fr);
        if (ox == 0 || k == x) continue;
        /* K . P = det4(B, C, X, P): -insphere(a, b, c, x, k) */
        const int exact_i = -dd_insphere(&pr, P0, P1, P2, PX, fr->pt[k]);
        const double t = dd_lift_dot4(K, P);
        const int si = dd_lift_sure(t, fr->f.ierr);
        count(ti, si != 0, si == exact_i, "K . P certified with the wrong sign", fr);
        if (fr->f.modes & DD_LIFT_EXACT) count(ti, 1, sgn(t) == exact_i, "an exact K . P is wrong", fr);
        if (fr->f.modes & DD_LIFT_KEXACT)
            count(ti, 1, dd_lift_sign_kp(K, P) == exact_i, "dd_lift_sign_kp is wrong", fr);
        /* qsmall's 4x4 evaluation of the same determinant */
        const double *r[4] = {fr->p[0], fr->p[0], fr->p[0], fr->p[0]};
        double rows[5][4];
        const uint32_t v[5] = {a, b, c, x, k};
        for (int j = 0; j < 5; j++)
            for (int i = 0; i < 4; i++) rows[j][i] = L[i][v[j]];
        for (int j = 0; j < 4; j++) r[j] = rows[j];
        const double d4 = dd_lift_det4(r, rows[4]);
        const int s4 = dd_lift_sure(d4, fr->f.ierr);
        count(ti, s4 != 0, s4 == exact_i, "dd_lift_det4 certified with the wrong sign", fr);
    }
}

/* The scalar passes, and the AVX2 ones against them, on facet (a, b, c). */
static void check_passes(frame *fr, uint32_t a, uint32_t b, uint32_t c, tally *tp, tally *tv)
{
    double *const *L = fr->L;
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
    const double oerr = fr->f.oerr;
    double m[6], N[4], T[4];
    dd_lift_pencil(L, a, b, c, m, N, T);
    const double *P0 = fr->pt[a], *P1 = fr->pt[b], *P2 = fr->pt[c];
    int ex[NMAX];
    for (uint32_t k = 0; k < fr->n; k++) ex[k] = dd_orient3d(&pr, P0, P1, P2, fr->pt[k]);
    /* dd_lift_next: every point skipped is surely behind, or sure */
    for (int unsure = 0; unsure < 2; unsure++)
        for (uint32_t k = 0, from = 0; from < fr->n; from = k + 1) {
            k = dd_lift_next(L, A, N, oerr, from, fr->n, unsure);
            for (uint32_t j = from; j < k; j++) {
                double P[4];
                const double o = dd_lift_row_o(L, j, A, N, P);
                count(tp, 1, unsure ? sgn(o) == ex[j] && ex[j] != 0 : ex[j] < 0,
                      "dd_lift_next skipped a point it could not place", fr);
            }
#ifdef DD_LIFT_AVX2
            if (has_avx2) {
                const uint32_t kv = dd_lift_next_avx2(L, fr->n, a, N, oerr, from, unsure);
                count(tv, 1, kv == k, "dd_lift_next_avx2 differs from dd_lift_next", fr);
            }
#endif
        }
    /* the least ratio: its answer is beyond; "none unsure" means none
     * but a, b, c is in the plane                                        */
    uint32_t uns;
    const uint32_t best = dd_lift_least_ratio(L, a, N, T, oerr, NULL, fr->n, &uns);
    if (best < fr->n) count(tp, 1, ex[best] > 0, "dd_lift_least_ratio answered a point not beyond", fr);
    int others_flat = 0;
    for (uint32_t k = 0; k < fr->n; k++) others_flat |= k != a && k != b && k != c && ex[k] == 0;
    if (uns == 3) count(tp, 1, !others_flat, "dd_lift_least_ratio: a point in the plane not unsure", fr);
    double o[NMAX];
    int uns2;
    const uint32_t best2 = dd_lift_least_beyond(L, fr->n, a, N, T, oerr, o, &uns2);
    count(tp, 1, best2 == best || best == DD_LIFT_TIE, "dd_lift_least_beyond differs from dd_lift_least_ratio", fr);
    if (best2 < fr->n && uns2 == 3) {
        double X[4], K[4];
        dd_lift_row_o(L, best2, A, N, X);
        dd_lift_cofactors(K, X, m);
        o[best2] = -1.0;
        if (dd_lift_all_outside(L, fr->n, a, N, K, o, oerr, fr->f.ierr)) {
            int ok = 1;
            for (uint32_t k = 0; k < fr->n; k++)
                if (ex[k] > 0 && k != best2) ok &= dd_insphere(&pr, P0, P1, P2, fr->pt[best2], fr->pt[k]) < 0;
            count(tp, 1, ok, "dd_lift_all_outside certified a point inside", fr);
        }
    }
#ifdef DD_LIFT_AVX2
    if (has_avx2) {
        int u;
        const uint32_t g = dd_lift_guess_avx2(L, fr->n, a, N, T, oerr, &u);
        /* t is summed in another order than the scalar pass's: the least
         * quotient may differ in a near tie (a guess; only ranks)        */
        (void)best;
        if (g < fr->n) count(tv, 1, ex[g] > 0, "dd_lift_guess_avx2 answered a point not beyond", fr);
        if (!u) count(tv, 1, !others_flat, "dd_lift_guess_avx2: a point in the plane not unsure", fr);
        const uint32_t gl = dd_lift_guess_lean_avx2(L, fr->n, a, N, T, oerr);
        if (gl < fr->n) count(tv, 1, ex[gl] > 0, "dd_lift_guess_lean_avx2 answered a point not beyond", fr);
        /* all behind the plane (b, a, c): rows from b */
        double Nb[4];
        dd_lift_normal(L, b, a, c, Nb);
        if (dd_lift_all_behind_avx2(L, fr->n, a, b, c, Nb, oerr)) {
            int ok = 1;
            for (uint32_t k = 0; k < fr->n; k++)
                if (k != a && k != b && k != c) ok &= dd_orient3d(&pr, P1, P0, P2, fr->pt[k]) < 0;
            count(tv, 1, ok, "dd_lift_all_behind_avx2 certified a point not behind", fr);
        }
    }
#else
    (void)tv;
#endif
}

/* The single-precision passes on facet (a, b, c): their answers. */
static void check_f32(frame *fr, uint32_t a, uint32_t b, uint32_t c, tally *tf)
{
#ifdef DD_LIFT_AVX2
    if (!has_avx2 || !has_fma || !dd_lift_f32_ok(fr->f.m)) {
        tf->declined++;
        return;
    }
    const dd_lift_f32_scale sc = dd_lift_f32_rows(fr->L, fr->n, fr->f.m, fr->F);
    double m[6], N[4], T[4];
    dd_lift_pencil(fr->L, a, b, c, m, N, T);
    const double *P0 = fr->pt[a], *P1 = fr->pt[b], *P2 = fr->pt[c];
    const uint32_t g = dd_lift_guess_f32(fr->F, fr->n, a, N, T, sc);
    if (g < fr->n) count(tf, 1, dd_orient3d(&pr, P0, P1, P2, fr->pt[g]) > 0, "f32: a point not beyond", fr);
    else if (g == DD_LIFT_BEHIND) {
        int ok = 1;
        for (uint32_t k = 0; k < fr->n; k++)
            if (k != a && k != b && k != c) ok &= dd_orient3d(&pr, P0, P1, P2, fr->pt[k]) < 0;
        count(tf, 1, ok, "f32: all behind, but a point is not", fr);
    } else
        count(tf, 0, 1, "", fr);
    const uint32_t h = dd_lift_inf_f32(fr->F, fr->n, a, b);   /* ranks only: a point or none */
    count(tf, 1, h < fr->n || h == DD_LIFT_NONE, "f32 hull step: not a point", fr);
#else
    (void)fr, (void)a, (void)b, (void)c;
    tf->declined++;
#endif
}

/* Every path on `facets` random facets of the frame. */
static void check_frame(frame *fr, tl_rng *r, int facets, tally t[6])
{
    make_rows(fr);
    for (int i = 0; i < facets; i++) {
        uint32_t v[4];
        for (int j = 0; j < 4; j++) {
            int again;
            do {
                v[j] = (uint32_t)tl_int(r, 0, fr->n - 1);
                again = 0;
                for (int l = 0; l < j; l++) again |= v[l] == v[j];
            } while (again);
        }
        check_scalar(fr, v[0], v[1], v[2], v[3], &t[0], &t[1], &t[2]);
        check_passes(fr, v[0], v[1], v[2], &t[3], &t[4]);
        check_f32(fr, v[0], v[1], v[2], &t[5]);
    }
}

/* ---- the inputs ----------------------------------------------------------- */

/* n random points in q + s [-1, 1]^3, q random in [-1, 1]^3 * off. */
static void random_frame(frame *fr, tl_rng *r, uint32_t n, double s, double off)
{
    fr->n = n;
    for (int i = 0; i < 3; i++) fr->q[i] = (2 * tl_unif(r) - 1) * off;
    for (uint32_t k = 0; k < n; k++)
        for (int i = 0; i < 3; i++) fr->p[k][i] = fr->q[i] + (2 * tl_unif(r) - 1) * s;
}

/* Integer points of a sphere, q one of them, scaled by s (a power of
 * two: still exactly cospherical) and moved by off; with `ulp`, one
 * coordinate of each point is moved by one ulp.                         */
static void sphere_frame(frame *fr, tl_rng *r, int64_t r2, uint32_t n, double s, double off, int ulp)
{
    static double sp[3 * 4096];
    const int ns = tl_sphere_points(r2, sp, 4096);
    uint32_t take = n + 1 <= (uint32_t)ns ? n + 1 : (uint32_t)ns;
    /* a random subset, q first */
    int idx[NMAX + 1];
    for (uint32_t j = 0; j < take; j++) {
        int again;
        do {
            idx[j] = (int)tl_int(r, 0, ns - 1);
            again = 0;
            for (uint32_t l = 0; l < j; l++) again |= idx[l] == idx[j];
        } while (again);
    }
    fr->n = take - 1;
    for (int i = 0; i < 3; i++) fr->q[i] = sp[3 * idx[0] + i] * s + off;
    for (uint32_t k = 0; k < fr->n; k++) {
        for (int i = 0; i < 3; i++) fr->p[k][i] = sp[3 * idx[k + 1] + i] * s + off;
        if (ulp) {
            const int i = (int)tl_int(r, 0, 2);
            fr->p[k][i] = nextafter(fr->p[k][i], tl_next(r) & 1 ? INFINITY : -INFINITY);
        }
    }
}

/* Scales a frame about q so that its size m becomes about `to`. */
static void rescale(frame *fr, double to)
{
    make_rows(fr);
    const double f = to / fr->f.m;
    for (uint32_t k = 0; k < fr->n; k++)
        for (int i = 0; i < 3; i++) fr->p[k][i] = fr->q[i] + (fr->p[k][i] - fr->q[i]) * f;
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    const int small = argc > 1 && !strcmp(argv[1], "small");
    const int reps = small ? 1 : 3;
    dd_pred_init(&pr);
    has_avx2 = __builtin_cpu_supports("avx2");
    has_fma = __builtin_cpu_supports("fma");
#ifndef DD_LIFT_AVX2
    has_avx2 = has_fma = 0;
#endif
    printf("# paths: scalar, SSE2 %s, AVX2 %s, single precision %s\n",
#ifdef __SSE2__
           "(compiled in)",
#else
           "(not compiled: the scalar code twice)",
#endif
           has_avx2 ? "(ran)" : "(not run: no AVX2)", has_avx2 && has_fma ? "(ran)" : "(not run: no AVX2 + FMA)");
    tl_check(&st, !dd_fp_fused(), "filters/no-contraction",
             "the library was built with fused multiply-adds (clang -ffp-contract=fast?): no bound holds");

    struct { const char *name; tally t[6]; } cls[6];
    memset(cls, 0, sizeof cls);
    cls[0].name = "random";
    cls[1].name = "cospherical";
    cls[2].name = "near-degenerate";
    cls[3].name = "extreme";
    cls[4].name = "range-boundaries";
    cls[5].name = "integer-boundaries";
    tl_rng r = {41};
    frame *fr = malloc(sizeof *fr);
    for (int rep = 0; rep < reps; rep++) {
        /* random: near the origin and far from it, small and large */
        const double scales[] = {1, 1e-3, 1e5, 0x1p-40, 1e30};
        for (int s = 0; s < 5; s++) {
            random_frame(fr, &r, 12 + (uint32_t)tl_int(&r, 0, 40), scales[s], s == 1 ? 1e3 : 0);
            check_frame(fr, &r, 6, cls[0].t);
        }
        /* cospherical: r^2 = 2925 has many integer points; exact scales */
        const double ss[] = {1, 0x1p-20, 0x1p30, 0x1p-150, 0x1p150};
        for (int s = 0; s < 5; s++) {
            sphere_frame(fr, &r, 2925, 20 + (uint32_t)tl_int(&r, 0, 40), ss[s], s == 1 ? 0.5 : 0, 0);
            check_frame(fr, &r, 6, cls[1].t);
            sphere_frame(fr, &r, 2925, 20 + (uint32_t)tl_int(&r, 0, 40), ss[s], s == 1 ? 0.5 : 0, 1);
            check_frame(fr, &r, 6, cls[2].t);
        }
        /* extreme: far outside the bounds' range, and mixed magnitudes */
        const double ex[] = {1e60, 1e-60, 1e200, 1e-200, 1e300, 1e-300};
        for (int s = 0; s < 6; s++) {
            random_frame(fr, &r, 16, ex[s], 0);
            check_frame(fr, &r, 4, cls[3].t);
        }
        random_frame(fr, &r, 16, 1e-200, 0);
        for (int k = 0; k < 4; k++) fr->p[k][k % 3] += 1e200;   /* mixed */
        check_frame(fr, &r, 4, cls[3].t);
        /* each range's edges, just inside and just outside */
        const double edges[] = {DD_LIFT_M_MIN, DD_LIFT_M_MAX, DD_LIFT_F32_MIN, DD_LIFT_F32_MAX};
        for (int e = 0; e < 4; e++)
            for (int side = -1; side <= 1; side += 2) {
                random_frame(fr, &r, 16, 1, 0);
                rescale(fr, edges[e] * (1 + side * 0x1p-20));
                check_frame(fr, &r, 4, cls[4].t);
                sphere_frame(fr, &r, 2925, 24, 1, 0, 1);
                rescale(fr, edges[e] * (1 + side * 0x1p-20));
                check_frame(fr, &r, 4, cls[4].t);
            }
        /* integer frames at the integer modes' limits, and one past */
        const double lim[] = {DD_LIFT_INT_M, DD_LIFT_INT_K, DD_LIFT_INT_O};
        for (int e = 0; e < 3; e++)
            for (int side = 0; side <= 1; side++) {
                const double M = lim[e] + side;
                if (M <= 1) continue;
                fr->n = 24;
                for (int i = 0; i < 3; i++) fr->q[i] = (double)tl_int(&r, -1000, 1000);
                for (uint32_t k = 0; k < fr->n; k++)
                    for (int i = 0; i < 3; i++) fr->p[k][i] = fr->q[i] + (double)tl_int(&r, -(int64_t)M, (int64_t)M);
                fr->p[0][0] = fr->q[0] + M;               /* m = M exactly */
                check_frame(fr, &r, 4, cls[5].t);
                /* and cospherical, near the limit: r^2 = 2925 (r < 55, so m
                 * <= 110) scaled by an integer                             */
                sphere_frame(fr, &r, 2925, 24, floor((M + 109) / 110), (double)tl_int(&r, -1000, 1000), 0);
                check_frame(fr, &r, 4, cls[5].t);
            }
    }
    static const char *path[6] = {"scalar-orient", "scalar-insphere", "sse2-bits", "scalar-passes", "avx2", "f32"};
    for (int c = 0; c < 6; c++)
        for (int p = 0; p < 6; p++) {
            const tally *t = &cls[c].t[p];
            char name[96];
            snprintf(name, sizeof name, "filters/%s/%s", cls[c].name, path[p]);
            tl_check(&st, t->wrong == 0, name, "%ld of %ld certified answers wrong, first: %s", t->wrong, t->certified,
                     t->first);
            printf("# %s: %ld certified, %ld declined\n", name, t->certified, t->declined);
        }
    /* where the bounds are +inf, nothing was certified */
    tl_check(&st, cls[3].t[0].certified > 0 && !isfinite(dd_lift_err(1e60)) && !isfinite(dd_lift_orient_err(1e-60)),
             "filters/extreme-declines", "the bounds are finite outside their range");
    free(fr);
    dd_pred_clear(&pr);
    return tl_finish(&st);
}
