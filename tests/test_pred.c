/*
 * test_pred.c -- our predicates return CGAL's signs (DESIGN 3).
 *
 * Compares every predicate of pred.h with CGAL's (through the shim) on
 * random tuples built to be degenerate -- integer points on spheres and
 * circles, small grids, coplanar and cocircular sets in the three axis
 * planes, hull facets with coplanar query points -- and on random
 * non-degenerate ones, each also translated and scaled by 1e16 and by a
 * tiny factor (1e-200, or 2^-660 where coplanarity must survive).  At least
 * 10^5 degenerate tuples.
 *
 * Then lift.h, the lifted filter, on the same sets and on random nearly
 * degenerate tuples: its certified signs against the exact ones, its
 * errors against the bounds it derives, its integer modes at and just
 * inside their limits (and their classification just beyond), and the
 * rank form of the 3D perturbation on every cospherical tuple above.
 * "small" (the sanitizer run) takes a quarter of the lift tuples.
 */
#include "testlib.h"
#include "mesh/mesh.h"
#include "geom/lift.h"
#include "cgal/cgal_shim.h"

#include <limits.h>
#include <math.h>
#include <stdarg.h>

typedef struct tally { long tuples, mismatches; char first[256]; } tally;

static void note(tally *t, int ours, int cgal, const char *what)
{
    t->tuples++;
    if (ours != cgal && t->mismatches++ == 0)
        snprintf(t->first, sizeof t->first, "%s: ours %d, CGAL %d", what, ours, cgal);
}

/* Point sources ----------------------------------------------------------- */



static void transform(double pts[][3], int k, double scale, const double off[3])
{
    for (int i = 0; i < k; i++)
        for (int c = 0; c < 3; c++) pts[i][c] = (pts[i][c] + off[c]) * scale;
}

/* ---- the lifted filter (lift.h) ------------------------------------------
 *
 * Every tuple is a cell v[0..3], a query p and a frame centre q.  The
 * exact values of the lifted determinants come from GMP integers (the
 * points scaled by a common power of two), so the tests check both the
 * signs the filter certifies and the errors lift.h derives its bounds
 * from: below 1.8e-12 m^5 (in-sphere), 6e-14 m^3 (orientation),
 * 9e-13 m^3 M (shifted), and 0 in an integer mode that holds.            */
#define LIFT_ERR_I 1.8e-12
#define LIFT_ERR_O 6e-14
#define LIFT_ERR_S 9e-13

typedef struct lift_tally {
    long tuples, answered, mismatches;
    double worst_i, worst_o;      /* largest error / m^5, / m^3 */
    char first[256];
} lift_tally;

static void lift_miss(lift_tally *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void lift_miss(lift_tally *t, const char *fmt, ...)
{
    if (t->mismatches++ > 0) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(t->first, sizeof t->first, fmt, ap);
    va_end(ap);
}

/* GMP scratch of the exact values. */
typedef struct lift_z { mpz_t c[6][3], r[4][4], s[16], D, O, a, b; } lift_z;

static void lift_z_init(lift_z *z)
{
    for (int i = 0; i < 6; i++)
        for (int c = 0; c < 3; c++) mpz_init(z->c[i][c]);
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 4; c++) mpz_init(z->r[i][c]);
    for (int i = 0; i < 16; i++) mpz_init(z->s[i]);
    mpz_inits(z->D, z->O, z->a, z->b, NULL);
}

static void lift_z_clear(lift_z *z)
{
    for (int i = 0; i < 6; i++)
        for (int c = 0; c < 3; c++) mpz_clear(z->c[i][c]);
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 4; c++) mpz_clear(z->r[i][c]);
    for (int i = 0; i < 16; i++) mpz_clear(z->s[i]);
    mpz_clears(z->D, z->O, z->a, z->b, NULL);
}

/* out = x / 2^emin, an integer (emin at most x's lowest bit). */
static void lift_z_set(mpz_t out, double x, long emin)
{
    if (x == 0) { mpz_set_ui(out, 0); return; }
    int e;
    double f = frexp(x, &e);
    mpz_set_d(out, ldexp(f, 53));
    long sh = (long)e - 53 - emin;
    if (sh >= 0) mpz_mul_2exp(out, out, (mp_bitcnt_t)sh);
    else mpz_tdiv_q_2exp(out, out, (mp_bitcnt_t)-sh);   /* exact: emin is x's lowest bit at most */
}

/* The smallest exponent e with every coordinate of pts[0..n) a multiple
 * of 2^e. */
static long lift_emin(const double *const *pts, int n)
{
    long emin = LONG_MAX;
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            double x = pts[i][c];
            if (x == 0) continue;
            int e;
            double f = frexp(x, &e);
            int64_t m = (int64_t)ldexp(f, 53);
            long lo = (long)e - 53 + __builtin_ctzll((uint64_t)(m < 0 ? -m : m));
            emin = lo < emin ? lo : emin;
        }
    return emin == LONG_MAX ? 0 : emin;
}

static void lift_det3(mpz_t out, mpz_ptr a[3], mpz_ptr b[3], mpz_ptr c[3], mpz_ptr *s)
{
    mpz_mul(s[0], b[1], c[2]); mpz_submul(s[0], b[2], c[1]); mpz_mul(out, a[0], s[0]);
    mpz_mul(s[0], b[0], c[2]); mpz_submul(s[0], b[2], c[0]); mpz_submul(out, a[1], s[0]);
    mpz_mul(s[0], b[0], c[1]); mpz_submul(s[0], b[1], c[0]); mpz_addmul(out, a[2], s[0]);
}

/* The exact lifted values of cell v, query p, centre q, with *e the
 * scale: z->D * 2^(5e) = det4(L[vi] - L[p]) and z->O * 2^(3e) =
 * orient3d(v0, v1, v2, p).                                               */
static void lift_exact(lift_z *z, const double *const v[4], const double *p, const double *q, long *e)
{
    const double *pts[6] = {v[0], v[1], v[2], v[3], p, q};
    *e = lift_emin(pts, 6);
    for (int i = 0; i < 6; i++)
        for (int c = 0; c < 3; c++) lift_z_set(z->c[i][c], pts[i][c], *e);
    mpz_ptr s[16];
    for (int i = 0; i < 16; i++) s[i] = z->s[i];
    /* |p - q|^2 into s[10], then rows v_i - p and |v_i - q|^2 - |p - q|^2 */
    mpz_set_ui(s[10], 0);
    for (int c = 0; c < 3; c++) {
        mpz_sub(s[11], z->c[4][c], z->c[5][c]);
        mpz_addmul(s[10], s[11], s[11]);
    }
    for (int i = 0; i < 4; i++) {
        mpz_neg(z->r[i][3], s[10]);
        for (int c = 0; c < 3; c++) {
            mpz_sub(z->r[i][c], z->c[i][c], z->c[4][c]);
            mpz_sub(s[11], z->c[i][c], z->c[5][c]);
            mpz_addmul(z->r[i][3], s[11], s[11]);
        }
    }
    mpz_set_ui(z->D, 0);                 /* Laplace along the last column */
    for (int i = 0; i < 4; i++) {
        mpz_ptr m[3][3];
        for (int j = 0, k = 0; j < 4; j++) {
            if (j == i) continue;
            for (int c = 0; c < 3; c++) m[k][c] = z->r[j][c];
            k++;
        }
        lift_det3(s[12], m[0], m[1], m[2], s);
        if (i & 1) mpz_addmul(z->D, z->r[i][3], s[12]);
        else mpz_submul(z->D, z->r[i][3], s[12]);
    }
    mpz_ptr b[3] = {s[1], s[2], s[3]}, c3[3] = {s[4], s[5], s[6]}, d[3] = {s[7], s[8], s[9]};
    for (int c = 0; c < 3; c++) {
        mpz_sub(b[c], z->c[1][c], z->c[0][c]);
        mpz_sub(c3[c], z->c[2][c], z->c[0][c]);
        mpz_sub(d[c], z->c[4][c], z->c[0][c]);
    }
    lift_det3(z->O, b, c3, d, s);
}

/* |x - X 2^e| for a double x and an exact X, rounded to a double. */
static double lift_gap(lift_z *z, double x, const mpz_t X, long e)
{
    long lo = e;
    if (x != 0) {
        int xe;
        double f = frexp(x, &xe);
        long xl = (long)xe - 53;
        lo = xl < e ? xl : e;
        mpz_set_d(z->a, ldexp(f, 53));
        mpz_mul_2exp(z->a, z->a, (mp_bitcnt_t)(xl - lo));
    } else {
        mpz_set_ui(z->a, 0);
    }
    mpz_mul_2exp(z->b, X, (mp_bitcnt_t)(e - lo));
    mpz_sub(z->a, z->a, z->b);
    long ex;
    double g = mpz_get_d_2exp(&ex, z->a);
    return fabs(ldexp(g, (int)(ex + lo)));
}

static int sgn(double x) { return (x > 0) - (x < 0); }

/* One evaluation against the exact sign S: answered beyond err, or always
 * in an exact mode. */
static void lift_sign(lift_tally *t, double x, double err, int exact, int S, const char *what, const char *src)
{
    if (!exact && !(x > err || x < -err)) return;
    t->answered++;
    if (sgn(x) != S) lift_miss(t, "%s: %s gives %d (value %g, bound %g), exact %d", src, what, sgn(x), x, err, S);
}

/* lift.h's evaluations for cell v, query p and centre q (the frame is
 * the six points) against the exact values and pred.h's predicates.    */
static void lift_tuple(dd_pred *pr, lift_z *z, lift_tally *t, const double *const v[4], const double *p,
                       const double *q, const char *src)
{
    const double *pts[5] = {v[0], v[1], v[2], v[3], p};
    dd_lift_frame f = dd_lift_frame_of(q, pts, 5);
    double L[5][4];
    for (int i = 0; i < 5; i++) dd_lift_row(L[i], pts[i], q);
    const double *rows[4] = {L[0], L[1], L[2], L[3]};
    double d1 = dd_lift_det4(rows, L[4]), B[4], C[4], X[4], P[4], mn[6], K[4];
    for (int c = 0; c < 4; c++) {
        B[c] = L[1][c] - L[0][c]; C[c] = L[2][c] - L[0][c];
        X[c] = L[3][c] - L[0][c]; P[c] = L[4][c] - L[0][c];
    }
    dd_lift_minors(mn, B, C);
    dd_lift_cofactors(K, X, mn);
    double d2 = dd_lift_dot4(K, P), o = dd_lift_orient(mn, P);
    long e;
    lift_exact(z, v, p, q, &e);
    int S = mpz_sgn(z->D), So = mpz_sgn(z->O);
    t->tuples++;
    if (S != -dd_insphere(pr, v[0], v[1], v[2], v[3], p))
        lift_miss(t, "%s: det4 of the lifts %d, -insphere %d", src, S, -dd_insphere(pr, v[0], v[1], v[2], v[3], p));
    if (So != dd_orient3d(pr, v[0], v[1], v[2], p))
        lift_miss(t, "%s: lifted orientation %d, orient3d %d", src, So, dd_orient3d(pr, v[0], v[1], v[2], p));
    const int ex = (f.modes & DD_LIFT_EXACT) != 0, oex = (f.modes & DD_LIFT_OEXACT) != 0;
    lift_sign(t, d1, f.ierr, ex, S, "dd_lift_det4", src);
    lift_sign(t, d2, f.ierr, ex, S, "K . P", src);
    lift_sign(t, o, f.oerr, oex, So, "dd_lift_orient", src);
    if (f.modes & DD_LIFT_KEXACT) {
        if (dd_lift_sign_kp(K, P) != S) lift_miss(t, "%s: dd_lift_sign_kp %d, exact %d", src, dd_lift_sign_kp(K, P), S);
        mpz_set_ui(z->s[13], 0);           /* K exact: K . P summed exactly is the determinant */
        for (int c = 0; c < 4; c++) {
            mpz_set_d(z->s[14], K[c]);
            mpz_set_d(z->s[15], P[c]);
            mpz_addmul(z->s[13], z->s[14], z->s[15]);
        }
        if (e >= 0) mpz_mul_2exp(z->s[14], z->D, (mp_bitcnt_t)(5 * e));
        if (e < 0 || mpz_cmp(z->s[13], z->s[14]) != 0 || K[0] != floor(K[0]) || K[3] != floor(K[3]))
            lift_miss(t, "%s: integer cofactors not exact (m = %g)", src, f.m);
    }
    if (f.m >= DD_LIFT_M_MIN && f.m <= DD_LIFT_M_MAX) {
        double m3 = f.m * f.m * f.m, m5 = m3 * f.m * f.m;
        double g1 = lift_gap(z, d1, z->D, 5 * e), g2 = lift_gap(z, d2, z->D, 5 * e), go = lift_gap(z, o, z->O, 3 * e);
        double gi = (g1 > g2 ? g1 : g2) / m5;
        t->worst_i = gi > t->worst_i ? gi : t->worst_i;
        t->worst_o = go / m3 > t->worst_o ? go / m3 : t->worst_o;
        if (gi > LIFT_ERR_I || go / m3 > LIFT_ERR_O)
            lift_miss(t, "%s: errors %g m^5, %g m^3 beyond lift.h's derivation (m = %g)", src, gi, go / m3, f.m);
        if ((ex && (g1 != 0 || g2 != 0)) || (oex && go != 0))
            lift_miss(t, "%s: an integer mode is not exact (m = %g: %g, %g, %g)", src, f.m, g1, g2, go);
    }
}

/* Tuples of pool pl, transformed as run_3d's (scales sc), each with a
 * frame centre drawn from the pool too (sometimes a cell vertex: the
 * dummy vertex's row in qsmall.c).                                      */
static void lift_pool(dd_pred *pr, lift_z *z, lift_tally *t, tl_rng *r, const char *src, const pool *pl, int rounds,
                      const double *sc)
{
    for (int it = 0; it < rounds; it++) {
        double x[6][3];
        tl_pick(r, pl, pl->n >= 6 ? 6 : 5, x);
        if (pl->n < 6 || tl_int(r, 0, 3) == 0) memcpy(x[5], x[tl_int(r, 0, 3)], sizeof x[5]);
        double off[3] = {(double)tl_int(r, -3, 3), (double)tl_int(r, -3, 3), (double)tl_int(r, -3, 3)};
        transform(x, 6, sc[it % 3], off);
        const double *v[4] = {x[0], x[1], x[2], x[3]};
        lift_tuple(pr, z, t, v, x[4], x[5], src);
    }
}

static void lift_report(tl_state *st, const lift_tally *t, const char *name, long min_tuples)
{
    tl_check(st, t->mismatches == 0 && t->tuples >= min_tuples && t->answered > 0, name,
             "%ld of %ld tuples wrong (%ld answers); first: %s", t->mismatches, t->tuples, t->answered, t->first);
    printf("# %s: %ld tuples, %ld answers, worst errors %.3g m^5, %.3g m^3\n", name, t->tuples, t->answered,
           t->worst_i, t->worst_o);
}

/* A point of the sphere of centre c and radius rad, rounded. */
static void on_sphere(tl_rng *r, const double c[3], double rad, double out[3])
{
    double u[3], n2;
    do {
        for (int i = 0; i < 3; i++) u[i] = 2 * tl_unif(r) - 1;
        n2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    } while (n2 < 0.01 || n2 > 1);
    double s = rad / sqrt(n2);
    for (int i = 0; i < 3; i++) out[i] = c[i] + s * u[i];
}

/* Random near-degenerate tuples: rounded points of a sphere (q on it
 * too), of a plane, and of a grid, moved by noise of 2^-60 .. 2^-20
 * (relative), at three magnitudes.                                      */
static void lift_near(dd_pred *pr, lift_z *z, lift_tally *t, tl_rng *r, int rounds)
{
    static const double size[3] = {1.0, 1e-3, 1e9}, shift[3] = {0.0, 1.0, 1e12};
    for (int it = 0; it < rounds; it++) {
        const int kind = it % 3, mag = (it / 3) % 3;
        const double noise = ldexp(size[mag], -(int)tl_int(r, 20, 60)) * (tl_int(r, 0, 3) == 0 ? 0.0 : 1.0);
        double x[6][3], c[3], nrm[3];
        for (int i = 0; i < 3; i++) {
            c[i] = shift[mag] + size[mag] * (2 * tl_unif(r) - 1);
            nrm[i] = 2 * tl_unif(r) - 1;
        }
        for (int k = 0; k < 6; k++) {
            if (kind == 0) {
                on_sphere(r, c, size[mag], x[k]);
            } else if (kind == 1) {       /* c + a u + b w, u and w spanning the plane normal to nrm */
                double u[3] = {nrm[1], -nrm[0], 0}, w[3] = {nrm[0] * nrm[2], nrm[1] * nrm[2], -(nrm[0] * nrm[0] + nrm[1] * nrm[1])};
                double a = 2 * tl_unif(r) - 1, b = 2 * tl_unif(r) - 1;
                for (int i = 0; i < 3; i++) x[k][i] = c[i] + size[mag] * (a * u[i] + b * w[i]);
            } else {
                for (int i = 0; i < 3; i++) x[k][i] = c[i] + size[mag] * (double)tl_int(r, -2, 2) / 4;
            }
            for (int i = 0; i < 3; i++) x[k][i] += noise * (2 * tl_unif(r) - 1);
        }
        const double *v[4] = {x[0], x[1], x[2], x[3]};
        lift_tuple(pr, z, t, v, x[4], x[5], kind == 0 ? "near-cosphere" : kind == 1 ? "near-plane" : "near-grid");
    }
}

/* The shifted lifts on frames of n rounded points of a sphere through q:
 * every answer beyond dd_shift_lifts' bound is the exact sign, every
 * error below 9e-13 m^3 M, and the shift answers more than the plain
 * filter.                                                                */
static void lift_shifted(tl_state *st, lift_z *z, tl_rng *r, int frames)
{
    lift_tally t = {0, 0, 0, 0, 0, ""};
    long plain = 0, shifted_frames = 0;
    enum { N = 12 };
    for (int it = 0; it < frames; it++) {
        double x[N + 1][3], c[3], rad = it % 2 ? 1.0 : 1e-2, L[N + 1][4], w[N];
        for (int i = 0; i < 3; i++) c[i] = (it % 4 < 2 ? 0.0 : 100.0) + 2 * tl_unif(r) - 1;
        for (int k = 0; k <= N; k++) on_sphere(r, c, rad, x[k]);
        const double *q = x[N], *pts[N];
        for (int k = 0; k < N; k++) pts[k] = x[k];
        dd_lift_frame f = dd_lift_frame_of(q, pts, N);
        for (int k = 0; k <= N; k++) dd_lift_row(L[k], x[k], q);
        double es = dd_shift_lifts(pts, N, q, L[0], L[1], L[2], f.m, f.ierr, w), M = 0;
        if (es == 0) continue;
        shifted_frames++;
        for (int k = 0; k < N; k++) M = fabs(w[k]) > M ? fabs(w[k]) : M;
        double S4[N + 1][4];
        for (int k = 0; k <= N; k++) {
            memcpy(S4[k], L[k], sizeof S4[k]);
            S4[k][3] = k < N ? w[k] : 0.0;  /* q: w' = 0 */
        }
        for (int j = 0; j < 40; j++) {
            int id[5];
            for (int i = 0; i < 5; i++) {
                int again;
                do {
                    id[i] = (int)tl_int(r, 0, N);
                    again = 0;
                    for (int h = 0; h < i; h++) again |= id[h] == id[i];
                } while (again);
            }
            const double *v[4] = {x[id[0]], x[id[1]], x[id[2]], x[id[3]]};
            const double *rows[4] = {S4[id[0]], S4[id[1]], S4[id[2]], S4[id[3]]};
            const double *prow[4] = {L[id[0]], L[id[1]], L[id[2]], L[id[3]]};
            double d = dd_lift_det4(rows, S4[id[4]]), dp = dd_lift_det4(prow, L[id[4]]);
            long e;
            lift_exact(z, v, x[id[4]], q, &e);
            int S = mpz_sgn(z->D);
            t.tuples++;
            plain += dp > f.ierr || dp < -f.ierr;
            lift_sign(&t, d, es, 0, S, "shifted dd_lift_det4", "near-cosphere");
            double g = lift_gap(z, d, z->D, 5 * e) / (f.m * f.m * f.m * M);
            t.worst_i = g > t.worst_i ? g : t.worst_i;
            if (g > LIFT_ERR_S) lift_miss(&t, "shifted error %g m^3 M beyond lift.h's derivation", g);
        }
    }
    tl_check(st, t.mismatches == 0 && shifted_frames > frames / 2 && t.answered > 2 * plain, "lift/shifted-near-cospherical",
             "%ld of %ld wrong; %ld of %d frames shifted; %ld answers shifted, %ld plain; first: %s", t.mismatches,
             t.tuples, shifted_frames, frames, t.answered, plain, t.first);
    printf("# lift/shifted-near-cospherical: %ld tuples, %ld answers (plain filter: %ld), worst error %.3g m^3 M\n",
           t.tuples, t.answered, plain, t.worst_i);
}

/* Integer points x = q + d of the sphere |x - c|^2 = r2 with q on it:
 * up to max offsets d (from q), found by sampling. */
static int int_sphere_offsets(tl_rng *r, int64_t r2, int64_t (*d)[3], int max)
{
    int64_t rad = (int64_t)sqrt((double)r2), s[3], q0[3] = {0, 0, 0};
    int n = 0, have_q = 0;
    for (long tries = 0; tries < 4000000 && n < max; tries++) {
        s[0] = tl_int(r, -rad, rad);
        s[1] = tl_int(r, -rad, rad);
        int64_t z2 = r2 - s[0] * s[0] - s[1] * s[1];
        if (z2 < 0) continue;
        int64_t z = (int64_t)llround(sqrt((double)z2));
        if (z * z != z2) continue;
        s[2] = tl_int(r, 0, 1) ? z : -z;
        if (!have_q) { memcpy(q0, s, sizeof q0); have_q = 1; continue; }   /* q's point of the sphere */
        for (int i = 0; i < 3; i++) d[n][i] = s[i] - q0[i];
        n++;
    }
    return n;
}

/* Integer frames at exactly m = lim: q a random integer point (up to
 * 2^40), the others q + d with |d_i| <= lim, one of them at lim; half of
 * the offsets at the extremes +-lim, +-(lim - 1), a fifth on an integer
 * sphere through q (diameter below lim), a fifth on a plane through q.
 * Checks that the frame has `mode` and that every tuple's evaluations are
 * exact there (lift_tuple's exact-mode checks).                          */
static void lift_int_limit(tl_state *st, dd_pred *pr, lift_z *z, tl_rng *r, const char *name, int64_t lim,
                           unsigned mode, int frames)
{
    lift_tally t = {0, 0, 0, 0, 0, ""};
    enum { N = 24 };
    int64_t sph[N][3];
    int64_t r2 = (lim / 2) * (lim / 2) - 1;
    while (r2 % 8 == 7 || r2 % 4 == 0) r2--;
    int ns = int_sphere_offsets(r, r2, sph, N);
    long modes_ok = 0;
    for (int it = 0; it < frames; it++) {
        double q[3], x[N][3];
        for (int i = 0; i < 3; i++) q[i] = (double)tl_int(r, -((int64_t)1 << 40), (int64_t)1 << 40);
        for (int k = 0; k < N; k++) {
            int64_t d[3];
            int kind = k == 0 ? 0 : (int)tl_int(r, 0, 9);
            if (kind < 5) {
                for (int i = 0; i < 3; i++) {
                    int64_t a = tl_int(r, 0, 1) ? lim : lim - 1;
                    d[i] = tl_int(r, 0, 2) ? (tl_int(r, 0, 1) ? a : -a) : tl_int(r, -lim, lim);
                }
                if (k == 0) d[0] = -lim;            /* m is lim exactly */
            } else if (kind < 7 && ns > 0) {
                memcpy(d, sph[tl_int(r, 0, ns - 1)], sizeof d);
            } else {                                /* the plane d0 + 2 d1 = 3 d2 */
                do {
                    d[0] = tl_int(r, -lim, lim);
                    d[1] = tl_int(r, -lim / 2, lim / 2);
                } while ((d[0] + 2 * d[1]) % 3 != 0);
                d[2] = (d[0] + 2 * d[1]) / 3;
            }
            for (int i = 0; i < 3; i++) x[k][i] = q[i] + (double)d[i];
        }
        const double *pts[N];
        for (int k = 0; k < N; k++) pts[k] = x[k];
        dd_lift_frame f = dd_lift_frame_of(q, pts, N);
        modes_ok += (f.modes & mode) && f.m == (double)lim;
        for (int j = 0; j < 30; j++) {
            int id[5];
            for (int i = 0; i < 5; i++) {
                int again;
                do {
                    id[i] = (int)tl_int(r, 0, N);       /* N: q itself */
                    again = 0;
                    for (int h = 0; h < i; h++) again |= id[h] == id[i];
                } while (again);
            }
            const double *v[4], *p = id[4] == N ? q : x[id[4]];
            for (int i = 0; i < 4; i++) v[i] = id[i] == N ? q : x[id[i]];
            /* lift_tuple's frame is the tuple's: its m is at most lim, so
             * the mode holds there too */
            lift_tuple(pr, z, &t, v, p, q, name);
        }
    }
    tl_check(st, t.mismatches == 0 && modes_ok == frames && ns >= N / 2, name,
             "%ld of %ld tuples wrong; mode held in %ld of %d frames at m = %lld; %d sphere points; first: %s",
             t.mismatches, t.tuples, modes_ok, frames, (long long)lim, ns, t.first);
}

/* The classification just beyond each limit, off the integers, and
 * outside the bounds' range. */
static void lift_classify_limits(tl_state *st)
{
    char why[256] = "";
    int bad = 0;
    const double q[3] = {7, -3, 1e6};
    /* the limits lift.h derives, not its constants: a constant moved
     * without its derivation fails here */
    const struct { double lim; unsigned mode; } lims[3] = {
        {400, DD_LIFT_EXACT}, {2048, DD_LIFT_KEXACT}, {32768, DD_LIFT_OEXACT}};
    for (int i = 0; i < 3; i++) {
        if (lims[i].mode == DD_LIFT_KEXACT && DD_LIFT_INT_K == 0) continue;   /* no 128-bit integers */
        for (int beyond = 0; beyond <= 1; beyond++) {
            double x[3] = {q[0] - lims[i].lim - beyond, q[1] + 1, q[2]};
            const double *pts[1] = {x};
            dd_lift_frame f = dd_lift_frame_of(q, pts, 1);
            if (((f.modes & lims[i].mode) != 0) == beyond && !bad++)
                snprintf(why, sizeof why, "m = %g: modes %u", f.m, f.modes);
            if (beyond && (lims[i].mode == DD_LIFT_EXACT ? f.ierr == 0 : lims[i].mode == DD_LIFT_OEXACT ? f.oerr == 0 : 0) &&
                !bad++)
                snprintf(why, sizeof why, "m = %g: bound 0 beyond the limit", f.m);
        }
    }
    /* a half-integer, then (centred at 0) m below and beyond the range,
     * a NaN and an infinite coordinate */
    const double half[3] = {1, 2.5, 3}, tiny[3] = {1e-60, 0, 0}, nan_[3] = {1, NAN, 3},
                 huge[3] = {1e56, 0, 0}, inf_[3] = {1.0 / 0.0, 0, 0}, zero[3] = {0, 0, 0};
    const double *cases[5] = {half, tiny, nan_, huge, inf_};
    for (int i = 0; i < 5; i++) {
        const double *pts[1] = {cases[i]};
        const double *qq = i == 0 ? q : zero;
        dd_lift_frame f = dd_lift_frame_of(qq, pts, 1);
        int want_inf = i > 0;                  /* the half-integer frame keeps its filters */
        if ((i != 3 && f.modes != 0) || (want_inf && (f.ierr != 1.0 / 0.0 || f.oerr != 1.0 / 0.0)) ||
            (!want_inf && !(f.ierr > 0 && f.ierr < 1.0 / 0.0))) {
            if (!bad++) snprintf(why, sizeof why, "case %d: modes %u, bounds %g %g", i, f.modes, f.ierr, f.oerr);
        }
    }
    tl_check(st, bad == 0, "lift/classify-limits", "%d wrong; first: %s", bad, why);
}

/* ---- the perturbation on ranks ---- */

typedef struct rank_cell {
    dd_pred *pr;
    const double *v[5];           /* the cell, then the query */
    double L[5][4];
    dd_lift_frame f;
} rank_cell;

/* orient3d of the cell with vertex k replaced by the query, as the wrap
 * evaluates it: the lifted orientation, certified by the frame's bound
 * or its integer mode, else dd_orient3d.                                 */
static int rank_orient(void *ctx, int k)
{
    const rank_cell *c = ctx;
    int ix[4] = {0, 1, 2, 3};
    ix[k] = 4;
    double B[4], C[4], P[4], mn[6];
    for (int i = 0; i < 4; i++) {
        B[i] = c->L[ix[1]][i] - c->L[ix[0]][i];
        C[i] = c->L[ix[2]][i] - c->L[ix[0]][i];
        P[i] = c->L[ix[3]][i] - c->L[ix[0]][i];
    }
    dd_lift_minors(mn, B, C);
    double o = dd_lift_orient(mn, P);
    if (o > c->f.oerr) return 1;
    if (o < -c->f.oerr) return -1;
    if (c->f.modes & DD_LIFT_OEXACT) return 0;
    return dd_orient3d(c->pr, c->v[ix[0]], c->v[ix[1]], c->v[ix[2]], c->v[ix[3]]);
}

typedef struct rank_tally { long tuples, from1, mismatches; char first[256]; tl_rng r; } rank_tally;

/* For a positively oriented cell q[0..3] and query q[4] with exact
 * in-sphere 0: dd_lift_symbolic on ranks that only keep the lexicographic
 * order (random gaps, as a frame's ranks have), with lifted orientations
 * in a frame centred at one of the five, against dd_insphere_perturbed and
 * CGAL; and from the second step when the first orientation is 0.       */
static void rank_check(dd_pred *pr, rank_tally *t, double q[5][3], int cgal)
{
    rank_cell c;
    c.pr = pr;
    for (int i = 0; i < 5; i++) c.v[i] = q[i];
    const double *centre = q[tl_int(&t->r, 0, 4)];
    c.f = dd_lift_frame_of(centre, c.v, 5);
    for (int i = 0; i < 5; i++) dd_lift_row(c.L[i], q[i], centre);
    int order[5] = {0, 1, 2, 3, 4};
    for (int i = 1; i < 5; i++)
        for (int j = i; j > 0 && dd_lex_cmp(q[order[j - 1]], q[order[j]]) > 0; j--) {
            int s = order[j]; order[j] = order[j - 1]; order[j - 1] = s;
        }
    uint32_t rk[5], at = (uint32_t)tl_int(&t->r, 0, 1000);
    for (int i = 0; i < 5; i++) rk[order[i]] = at += 1 + (uint32_t)tl_int(&t->r, 0, 1000);
    int want = dd_insphere_perturbed(pr, q[0], q[1], q[2], q[3], q[4]);
    int got = dd_lift_symbolic(rk, 0, rank_orient, &c);
    t->tuples++;
    if ((got != want || got != cgal) && t->mismatches++ == 0)
        snprintf(t->first, sizeof t->first, "ranks %d, dd_insphere_perturbed %d, CGAL %d", got, want, cgal);
    int top[2];
    dd_lift_top2(rk, top);
    if (top[0] != 4 && rank_orient(&c, top[0]) == 0) {
        t->from1++;
        got = dd_lift_symbolic(rk, 1, rank_orient, &c);
        if (got != want && t->mismatches++ == 0)
            snprintf(t->first, sizeof t->first, "from the second step %d, dd_insphere_perturbed %d", got, want);
    }
}

/* 3D tests on 5 points: orientation, insphere (perturbed and not); the
 * rank form of the perturbation where the in-sphere sign is 0.          */
static void test_3d(dd_pred *pr, tally *t, rank_tally *rt, double q[5][3])
{
    note(t, dd_orient3d(pr, q[0], q[1], q[2], q[3]),
         dd_cgal_orientation(q[0], q[1], q[2], q[3]), "orientation");
    int o = dd_orient3d(pr, q[0], q[1], q[2], q[3]);
    if (o == 0) return;
    if (o < 0) { double s[3]; memcpy(s, q[0], sizeof s); memcpy(q[0], q[1], sizeof s); memcpy(q[1], s, sizeof s); }
    note(t, dd_insphere(pr, q[0], q[1], q[2], q[3], q[4]),
         dd_cgal_side_of_oriented_sphere(q[0], q[1], q[2], q[3], q[4], 0), "insphere");
    int cgal = dd_cgal_side_of_oriented_sphere(q[0], q[1], q[2], q[3], q[4], 1);
    note(t, dd_insphere_perturbed(pr, q[0], q[1], q[2], q[3], q[4]), cgal, "insphere perturbed");
    if (dd_insphere(pr, q[0], q[1], q[2], q[3], q[4]) == 0) rank_check(pr, rt, q, cgal);
    /* The same tetrahedron as an infinite cell: q[k] plays the infinite
     * vertex, q[4] the query.                                              */
    for (int k = 0; k < 4; k++) {
        const double *v[4] = {q[0], q[1], q[2], q[3]};
        if (dd_orient_coplanar(pr, v[dd_facet[k][0]], v[dd_facet[k][1]], v[dd_facet[k][2]]) == 0) continue;
        note(t, dd_inf_conflict(pr, v, k, q[4]),
             dd_cgal_side_of_sphere_cell(q[0], q[1], q[2], q[3], k, q[4], 1), "infinite cell");
    }
}

/* 2D tests on 4 coplanar points: coplanar orientation, in-circle. */
static void test_2d(dd_pred *pr, tally *t, double q[4][3])
{
    note(t, dd_orient_coplanar(pr, q[0], q[1], q[2]),
         dd_cgal_coplanar_orientation(q[0], q[1], q[2]), "coplanar orientation");
    if (dd_orient_coplanar(pr, q[0], q[1], q[2]) == 0) return;
    note(t, dd_incircle_coplanar(pr, q[0], q[1], q[2], q[3]),
         dd_cgal_coplanar_side_of_bounded_circle(q[0], q[1], q[2], q[3], 0), "in-circle");
    note(t, dd_incircle_coplanar_perturbed(pr, q[0], q[1], q[2], q[3]),
         dd_cgal_coplanar_side_of_bounded_circle(q[0], q[1], q[2], q[3], 1), "in-circle perturbed");
}

/* 3D tuples are also scaled by 1e-200 (rounded: nearly degenerate); 2D ones
 * by 2^-660 only, an exact scaling, so coplanar sets stay coplanar (CGAL's
 * coplanar predicates require it).                                       */
static const double scales[3] = {1.0, 1e16, 1e-200};
static const double scales2d[3] = {1.0, 1e16, 0x1p-660};

static void run_3d(tl_state *st, dd_pred *pr, tl_rng *r, rank_tally *rt, const char *name, const pool *pl, int rounds,
                   long *degenerate)
{
    tally t = {0, 0, ""};
    for (int it = 0; it < rounds; it++) {
        double q[5][3];
        tl_pick(r, pl, 5, q);
        double off[3] = {(double)tl_int(r, -3, 3), (double)tl_int(r, -3, 3), (double)tl_int(r, -3, 3)};
        transform(q, 5, scales[it % 3], off);
        test_3d(pr, &t, rt, q);
    }
    if (degenerate) *degenerate += t.tuples;
    tl_check(st, t.mismatches == 0 && t.tuples > rounds, name, "%ld of %ld differ from CGAL; first: %s",
             t.mismatches, t.tuples, t.first);
}

static void run_2d(tl_state *st, dd_pred *pr, tl_rng *r, const char *name, const pool *pl, int rounds, long *degenerate)
{
    tally t = {0, 0, ""};
    for (int it = 0; it < rounds; it++) {
        double q[4][3];
        tl_pick(r, pl, 4, q);
        double off[3] = {(double)tl_int(r, -3, 3), (double)tl_int(r, -3, 3), (double)tl_int(r, -3, 3)};
        transform(q, 4, scales2d[it % 3], off);
        test_2d(pr, &t, q);
    }
    if (degenerate) *degenerate += t.tuples;
    tl_check(st, t.mismatches == 0 && t.tuples > rounds, name, "%ld of %ld differ from CGAL; first: %s",
             t.mismatches, t.tuples, t.first);
}

/* Integer points of a circle of radius^2 r2 in the plane axis = level. */
static pool circle_pool(int64_t r2, int axis, double level)
{
    pool pl = {malloc(3 * 4096 * sizeof(double)), 0};
    for (int64_t a = -2000; a <= 2000 && pl.n < 4096; a++) {
        int64_t b2 = r2 - a * a;
        if (b2 < 0) continue;
        int64_t b = (int64_t)llround(sqrt((double)b2));
        if (b * b != b2) continue;
        for (int s = -1; s <= 1; s += 2) {
            if (b == 0 && s > 0) continue;
            double *p = pl.p + 3 * pl.n++;
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            p[axis] = level; p[u] = (double)a; p[v] = (double)(s * b);
        }
    }
    return pl;
}

static pool grid_pool(int k, int flat_axis)
{
    pool pl = {malloc(3 * (size_t)(k * k * k) * sizeof(double)), 0};
    for (int x = 0; x < k; x++)
        for (int y = 0; y < k; y++)
            for (int z = 0; z < k; z++) {
                int c[3] = {x, y, z};
                if (flat_axis >= 0 && c[flat_axis] != 0) continue;
                double *p = pl.p + 3 * pl.n++;
                p[0] = x; p[1] = y; p[2] = z;
            }
    return pl;
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    dd_pred pr;
    dd_pred_init(&pr);
    tl_rng r = {12345};
    long degenerate = 0;
    /* the lift tests draw from their own generators: the tuples above stay as they were */
    const int lq = argc > 1 && strcmp(argv[1], "small") == 0 ? 4 : 1;
    tl_rng lr = {777};
    lift_z z;
    lift_z_init(&z);
    lift_tally deg = {0, 0, 0, 0, 0, ""};
    rank_tally rt = {0, 0, 0, "", {4242}};

    /* Cospherical: integer points on spheres of several radii. */
    static const int64_t radii2[] = {3, 9, 25, 50, 75, 81, 121, 169, 338, 3000};
    for (size_t i = 0; i < sizeof radii2 / sizeof *radii2; i++) {
        pool pl = {malloc(3 * 20000 * sizeof(double)), 0};
        pl.n = tl_sphere_points(radii2[i], pl.p, 20000);
        char name[64];
        snprintf(name, sizeof name, "pred/cosphere-r2=%lld", (long long)radii2[i]);
        if (pl.n >= 8) run_3d(&st, &pr, &r, &rt, name, &pl, 4000, &degenerate);
        if (pl.n >= 8) lift_pool(&pr, &z, &deg, &lr, name, &pl, 600 / lq, scales);
        free(pl.p);
    }
    /* Small grids: coplanar, cospherical and collinear tuples everywhere. */
    for (int k = 2; k <= 5; k++) {
        pool pl = grid_pool(k, -1);
        char name[64];
        snprintf(name, sizeof name, "pred/grid-%d", k);
        run_3d(&st, &pr, &r, &rt, name, &pl, 8000, &degenerate);
        lift_pool(&pr, &z, &deg, &lr, name, &pl, 1000 / lq, scales);
        free(pl.p);
    }
    /* Coplanar grids in each axis plane (exercises the xy, yz, xz cases). */
    for (int axis = 0; axis < 3; axis++) {
        pool pl = grid_pool(5, axis);
        char name[64];
        snprintf(name, sizeof name, "pred/coplanar-grid-axis%d", axis);
        run_2d(&st, &pr, &r, name, &pl, 8000, &degenerate);
        lift_pool(&pr, &z, &deg, &lr, name, &pl, 600 / lq, scales2d);
        free(pl.p);
    }
    /* Cocircular: integer points on circles in each axis plane. */
    static const int64_t cr2[] = {25, 65, 325, 1105};
    for (int axis = 0; axis < 3; axis++)
        for (size_t i = 0; i < sizeof cr2 / sizeof *cr2; i++) {
            pool pl = circle_pool(cr2[i], axis, (double)(axis + 1));
            char name[64];
            snprintf(name, sizeof name, "pred/cocircle-r2=%lld-axis%d", (long long)cr2[i], axis);
            run_2d(&st, &pr, &r, name, &pl, 3000, &degenerate);
            lift_pool(&pr, &z, &deg, &lr, name, &pl, 300 / lq, scales2d);
            free(pl.p);
        }
    /* Non-degenerate: uniform random doubles. */
    {
        pool pl = {malloc(3 * 5000 * sizeof(double)), 5000};
        for (int i = 0; i < 3 * 5000; i++) pl.p[i] = tl_unif(&r);
        run_3d(&st, &pr, &r, &rt, "pred/uniform", &pl, 20000, NULL);
        free(pl.p);
        /* random points of one axis plane: coplanar, in general position */
        for (int axis = 0; axis < 3; axis++) {
            pool pl2 = {malloc(3 * 2000 * sizeof(double)), 2000};
            for (int i = 0; i < 2000; i++)
                for (int c = 0; c < 3; c++) pl2.p[3 * i + c] = c == axis ? 0.5 : tl_unif(&r);
            char name[64];
            snprintf(name, sizeof name, "pred/uniform-plane-axis%d", axis);
            run_2d(&st, &pr, &r, name, &pl2, 3000, NULL);
            free(pl2.p);
        }
    }
    tl_check(&st, degenerate >= 100000, "pred/at-least-1e5-degenerate-tuples",
             "only %ld degenerate tuples compared", degenerate);
    printf("# %ld degenerate tuples compared with CGAL\n", degenerate);

    lift_report(&st, &deg, "lift/filter-degenerate-sets", 15000 / lq);
    lift_tally near = {0, 0, 0, 0, 0, ""};
    lift_near(&pr, &z, &near, &lr, 20000 / lq);
    lift_report(&st, &near, "lift/filter-near-degenerate", 20000 / lq);
    lift_shifted(&st, &z, &lr, 300 / lq);
    lift_int_limit(&st, &pr, &z, &lr, "lift/int-lifts-m=400", 400, DD_LIFT_EXACT, 40 / lq);
    lift_int_limit(&st, &pr, &z, &lr, "lift/int-lifts-m=399", 399, DD_LIFT_EXACT, 40 / lq);
    if (DD_LIFT_INT_K > 0) {
        lift_int_limit(&st, &pr, &z, &lr, "lift/int-cofactors-m=2048", 2048, DD_LIFT_KEXACT, 40 / lq);
        lift_int_limit(&st, &pr, &z, &lr, "lift/int-cofactors-m=2047", 2047, DD_LIFT_KEXACT, 40 / lq);
    }
    lift_int_limit(&st, &pr, &z, &lr, "lift/int-orient-m=32768", 32768, DD_LIFT_OEXACT, 40 / lq);
    lift_int_limit(&st, &pr, &z, &lr, "lift/int-orient-m=32767", 32767, DD_LIFT_OEXACT, 40 / lq);
    lift_classify_limits(&st);
    tl_check(&st, rt.mismatches == 0 && rt.tuples >= 20000 && rt.from1 > 0, "lift/rank-perturbation-cospherical",
             "%ld of %ld cospherical tuples wrong (%ld from the second step); first: %s", rt.mismatches, rt.tuples,
             rt.from1, rt.first);
    printf("# lift/rank-perturbation-cospherical: %ld cospherical tuples, %ld from the second step\n", rt.tuples,
           rt.from1);
    lift_z_clear(&z);
    dd_pred_clear(&pr);
    return tl_finish(&st);
}
