/*
 * pred.c -- exact, perturbed predicates (DESIGN 3; see pred.h for signs).
 *
 * Each predicate runs in two stages.
 *  1. A semi-static filter (inline, pred.h): the determinant in doubles,
 *     evaluated in the same order as CGAL's determinant(), accepted when
 *     its magnitude exceeds CGAL's certified error bound for that order
 *     (orientation 5.1107127829973299e-15 * maxx*maxy*maxz, in-sphere
 *     1.2466136531027298e-13 * maxx*maxy*maxz * max^2, max the largest of
 *     the three), with CGAL's underflow and overflow guards.
 *  2. An exact evaluation: adaptive floating-point expansions
 *     (expansion.c) when the coordinates are in their safe range or can
 *     be scaled into it exactly by a power of two (below), else GMP
 *     integers: every double is m * 2^e with an integer m of at most 53
 *     bits, so after shifting all coordinates of one call by the smallest
 *     exponent they are integers and every sum and product is exact.  GMP
 *     works for all finite doubles (1e-300 and 1e300 included).
 * The perturbation (Devillers & Teillaud 2011, as CGAL implements it) is
 * applied on top, only when the exact sign is zero; its 3D rule is
 * lift.h's dd_lift_symbolic_top, on the lexicographic order of the five.
 */
#include "geom/pred.h"
#include "geom/expansion.h"
#include "geom/lift.h"

#include "dtdel/alloc.h"

#include <math.h>
#include <stdlib.h>

void dd_pred_init(dd_pred *ctx)
{
    ctx->z_ready = 0;
    ctx->limbs = NULL;
    ctx->orient_exact = ctx->insphere_exact = 0;
#ifdef DD_COUNTERS
    ctx->orient_calls = ctx->insphere_calls = 0;
    ctx->perturbed = 0;
#endif
}

/* Makes z[0..DD_PRED_SCRATCH) zeros over limbs, DD_PRED_LIMBS each.
 * The fields are GMP's documented representation (its manual, "Integer
 * Internals"); GMP reallocates a number only when a result needs more
 * than its _mp_alloc limbs, which DD_PRED_LIMBS rules out (pred.h), and
 * these are never given to mpz_clear.                                  */
static void bind_scratch(mpz_t z[DD_PRED_SCRATCH], mp_limb_t *limbs)
{
    for (int i = 0; i < DD_PRED_SCRATCH; i++) {
        z[i]->_mp_alloc = DD_PRED_LIMBS;
        z[i]->_mp_size = 0;
        z[i]->_mp_d = limbs + (size_t)i * DD_PRED_LIMBS;
    }
}

dd_status dd_pred_reserve(dd_pred *ctx)
{
    if (ctx->limbs) return DD_OK;
    mp_limb_t *limbs = dd_malloc((size_t)DD_PRED_SCRATCH * DD_PRED_LIMBS * sizeof *limbs);
    if (!limbs) return DD_ERR_NOMEM;
    dd_pred_clear(ctx);
    ctx->limbs = limbs;
    bind_scratch(ctx->z, limbs);
    ctx->z_ready = 1;
    return DD_OK;
}

void dd_pred_clear(dd_pred *ctx)
{
    if (ctx->limbs) dd_mfree(ctx->limbs);
    else if (ctx->z_ready)   /* made by mpz_init (a caller's lazy scratch) */
        for (int i = 0; i < DD_PRED_SCRATCH; i++) mpz_clear(ctx->z[i]);
    ctx->limbs = NULL;
    ctx->z_ready = 0;
}

/* ---- exact stage --------------------------------------------------------- */

/* Smallest binary exponent e such that every nonzero x[i] is an integer
 * multiple of 2^e.                                                          */
static int min_exponent(const double *const *pts, int npts)
{
    int emin = INT32_MAX;
    for (int i = 0; i < npts; i++)
        for (int c = 0; c < 3; c++) {
            double x = pts[i][c];
            if (x == 0.0) continue;
            int e;
            double f = frexp(x, &e);           /* x = f 2^e, |f| in [.5,1) */
            int64_t m = (int64_t)ldexp(f, 53); /* exact 53-bit integer      */
            int tz = __builtin_ctzll((uint64_t)(m < 0 ? -m : m));
            int lo = e - 53 + tz;
            if (lo < emin) emin = lo;
        }
    return emin == INT32_MAX ? 0 : emin;
}

/* out = x / 2^emin, exactly (an integer by choice of emin). */
static void set_scaled(mpz_t out, double x, int emin)
{
    if (x == 0.0) { mpz_set_ui(out, 0); return; }
    int e;
    double f = frexp(x, &e);
    int64_t m = (int64_t)ldexp(f, 53);
    mpz_set_si(out, (long)m);
    int sh = e - 53 - emin;
    if (sh > 0) mpz_mul_2exp(out, out, (mp_bitcnt_t)sh);
    else if (sh < 0) mpz_tdiv_q_2exp(out, out, (mp_bitcnt_t)(-sh)); /* exact */
}

/* f on z, the points loaded first (dd_pred_exact). */
static int exact_on(mpz_t zs[DD_PRED_SCRATCH], const double *const *pts, int npts, dd_exact_fn f,
                    const void *arg, int *emin_out)
{
    mpz_ptr z[DD_PRED_SCRATCH];
    for (int i = 0; i < DD_PRED_SCRATCH; i++) z[i] = zs[i];
    int emin = min_exponent(pts, npts);
    for (int i = 0; i < npts; i++)
        for (int c = 0; c < 3; c++) set_scaled(z[3 * i + c], pts[i][c], emin);
    if (emin_out) *emin_out = emin;
    return f(z, arg);
}

/* The same on a scratch of this frame's: a context with none of its
 * own (a read-only call's) allocates nothing either.  Not inlined, so
 * that its frame exists only while a GMP stage runs.                     */
static __attribute__((noinline)) int exact_on_stack(const double *const *pts, int npts, dd_exact_fn f,
                                                    const void *arg, int *emin_out)
{
    mp_limb_t limbs[DD_PRED_SCRATCH * DD_PRED_LIMBS];
    mpz_t zs[DD_PRED_SCRATCH];
    bind_scratch(zs, limbs);
    return exact_on(zs, pts, npts, f, arg, emin_out);
}

int dd_pred_exact(dd_pred *ctx, const double *const *pts, int npts, dd_exact_fn f, const void *arg,
                  int *emin_out)
{
    if (ctx->limbs) return exact_on(ctx->z, pts, npts, f, arg, emin_out);
    return exact_on_stack(pts, npts, f, arg, emin_out);
}

/* r = a*d - b*c */
void dd_mpz_det2(mpz_t r, const mpz_t a, const mpz_t b, const mpz_t c, const mpz_t d, mpz_t tmp)
{
    mpz_mul(r, a, d);
    mpz_mul(tmp, b, c);
    mpz_sub(r, r, tmp);
}

int dd_mpz_sign_det3(mpz_ptr *a, mpz_ptr *b, mpz_ptr *c, mpz_ptr *s)
{
    dd_mpz_det2(s[0], b[1], b[2], c[1], c[2], s[3]);
    mpz_mul(s[1], a[0], s[0]);
    dd_mpz_det2(s[0], b[0], b[2], c[0], c[2], s[3]);
    mpz_submul(s[1], a[1], s[0]);
    dd_mpz_det2(s[0], b[0], b[1], c[0], c[1], s[3]);
    mpz_addmul(s[1], a[2], s[0]);
    return mpz_sgn(s[1]);
}

/* orient3d of the points in z[0..12) (dd_exact_fn). */
static int orient3d_z(mpz_ptr *z, const void *arg)
{
    (void)arg;
    /* rows q-p, r-p, s-p into z[12..20] */
    for (int row = 0; row < 3; row++)
        for (int c = 0; c < 3; c++)
            mpz_sub(z[12 + 3 * row + c], z[3 * (row + 1) + c], z[c]);
    return dd_mpz_sign_det3(&z[12], &z[15], &z[18], &z[21]);
}

static int orient3d_exact(dd_pred *ctx, const double *p, const double *q,
                          const double *r, const double *s)
{
    const double *pts[4] = {p, q, r, s};
    return dd_pred_exact(ctx, pts, 4, orient3d_z, NULL, NULL);
}

int dd_mpz_sign_det4(mpz_ptr *const r[4], mpz_ptr *s)
{
    mpz_set_ui(s[9], 0);
    for (int i = 0; i < 4; i++) {   /* Laplace along the last column */
        mpz_ptr m[3][3];
        for (int j = 0, k = 0; j < 4; j++) {
            if (j == i) continue;
            for (int c = 0; c < 3; c++) m[k][c] = r[j][c];
            k++;
        }
        dd_mpz_sign_det3(m[0], m[1], m[2], s);   /* value left in s[1] */
        if ((i & 1) == 1) mpz_addmul(s[9], r[i][3], s[1]);   /* (-1)^(i+3) */
        else mpz_submul(s[9], r[i][3], s[1]);
    }
    return mpz_sgn(s[9]);
}

/* CGAL: sign det(rows p-t, r-t, q-t, s-t, each lifted with its squared
 * norm), the points p, r, q, s, t in z[0..15) (dd_exact_fn).             */
static int insphere_z(mpz_ptr *z, const void *arg)
{
    (void)arg;
    mpz_ptr rows[4][4];
    for (int i = 0; i < 4; i++) {
        for (int c = 0; c < 3; c++) {
            rows[i][c] = z[15 + 4 * i + c];
            mpz_sub(rows[i][c], z[3 * i + c], z[12 + c]);
        }
        rows[i][3] = z[15 + 4 * i + 3];
        mpz_mul(rows[i][3], rows[i][0], rows[i][0]);
        mpz_addmul(rows[i][3], rows[i][1], rows[i][1]);
        mpz_addmul(rows[i][3], rows[i][2], rows[i][2]);
    }
    return dd_mpz_sign_det4((mpz_ptr *const[4]){rows[0], rows[1], rows[2], rows[3]}, &z[31]);
}

static int insphere_exact(dd_pred *ctx, const double *p, const double *q,
                          const double *r, const double *s, const double *t)
{
    const double *pts[5] = {p, r, q, s, t};   /* note r, q swapped */
    return dd_pred_exact(ctx, pts, 5, insphere_z, NULL, NULL);
}

/* 2D orientation of (a,b,c) projected on coordinates i, j (exact ints). */
static int orient2d_exact_z(mpz_ptr *z, int i, int j, mpz_ptr *s)
{
    /* (b_i - a_i)(c_j - a_j) - (c_i - a_i)(b_j - a_j) */
    mpz_sub(s[0], z[3 + i], z[i]);
    mpz_sub(s[1], z[6 + j], z[j]);
    mpz_sub(s[2], z[6 + i], z[i]);
    mpz_sub(s[3], z[3 + j], z[j]);
    mpz_mul(s[4], s[0], s[1]);
    mpz_submul(s[4], s[2], s[3]);
    return mpz_sgn(s[4]);
}

/* The first nonzero 2D orientation of z[0..9) (dd_exact_fn). */
static int orient_coplanar_z(mpz_ptr *z, const void *arg)
{
    (void)arg;
    int o = orient2d_exact_z(z, 0, 1, &z[9]);
    if (o != 0) return o;
    o = orient2d_exact_z(z, 1, 2, &z[9]);
    if (o != 0) return o;
    return orient2d_exact_z(z, 0, 2, &z[9]);
}

static int orient_coplanar_exact(dd_pred *ctx, const double *p,
                                 const double *q, const double *r)
{
    const double *pts[3] = {p, q, r};
    return dd_pred_exact(ctx, pts, 3, orient_coplanar_z, NULL, NULL);
}

/* CGAL: side_of_bounded_sphere(p, q, r, t+v, t) with v = pq x pr, i.e. the
 * sign of det(rows p-t, r-t, q-t, v), each lifted; the points p, r, q, t
 * in z[0..12) (dd_exact_fn).                                              */
static int incircle_coplanar_z(mpz_ptr *z, const void *arg)
{
    (void)arg;
    mpz_ptr rows[4][4];
    for (int i = 0; i < 3; i++) {
        for (int c = 0; c < 3; c++) {
            rows[i][c] = z[12 + 4 * i + c];
            mpz_sub(rows[i][c], z[3 * i + c], z[9 + c]);
        }
        rows[i][3] = z[12 + 4 * i + 3];
        mpz_mul(rows[i][3], rows[i][0], rows[i][0]);
        mpz_addmul(rows[i][3], rows[i][1], rows[i][1]);
        mpz_addmul(rows[i][3], rows[i][2], rows[i][2]);
    }
    /* pq = q - p = z[6..8] - z[0..2]; pr = r - p = z[3..5] - z[0..2] */
    mpz_ptr pq[3] = {z[24], z[25], z[26]}, pr[3] = {z[27], z[28], z[29]};
    for (int c = 0; c < 3; c++) {
        mpz_sub(pq[c], z[6 + c], z[c]);
        mpz_sub(pr[c], z[3 + c], z[c]);
    }
    mpz_ptr *v = &z[30];   /* v[0..3] = vx, vy, vz, v2 */
    dd_mpz_det2(v[0], pq[1], pq[2], pr[1], pr[2], z[34]);
    dd_mpz_det2(v[1], pq[2], pq[0], pr[2], pr[0], z[34]);
    dd_mpz_det2(v[2], pq[0], pq[1], pr[0], pr[1], z[34]);
    mpz_mul(v[3], v[0], v[0]);
    mpz_addmul(v[3], v[1], v[1]);
    mpz_addmul(v[3], v[2], v[2]);
    for (int c = 0; c < 4; c++) rows[3][c] = v[c];
    return dd_mpz_sign_det4((mpz_ptr *const[4]){rows[0], rows[1], rows[2], rows[3]}, &z[35]);
}

static int incircle_coplanar_exact(dd_pred *ctx, const double *p,
                                   const double *q, const double *r,
                                   const double *t)
{
    const double *pts[4] = {p, r, q, t};   /* rows in CGAL's order */
    return dd_pred_exact(ctx, pts, 4, incircle_coplanar_z, NULL, NULL);
}

/* ---- exact rescaling ------------------------------------------------------
 *
 * orient3d and insphere are homogeneous in the points taken together (of
 * degree 3 and 5, no translation involved): multiplying every coordinate
 * of every point by one 2^k > 0 keeps their signs, and is exact while no
 * nonzero coordinate leaves the normal doubles.  So points outside the
 * expansions' safe range whose nonzero coordinates span no more than its
 * width (sets near 1e300 or 1e-300, subnormal ones, any set scaled as a
 * whole) are scaled into it and decided there; only mixed magnitudes go
 * to GMP.  The computation is on the original doubles, scaled exactly.  */

/* out = pts * 2^k with every nonzero |out| in [2^-lim, 2^lim]: 1, or 0
 * when their exponents span more than that range.                        */
static int rescale_into(const double *const *pts, int n, int lim, double out[][3])
{
    int emin = INT32_MAX, emax = INT32_MIN;
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++)
            if (pts[i][c] != 0) {
                const int e = ilogb(pts[i][c]);   /* |x| in [2^e, 2^(e+1)) */
                emin = e < emin ? e : emin;
                emax = e > emax ? e : emax;
            }
    if (emax == INT32_MIN) return 0;
    const int k = -(emax + 1 + emin) / 2;
    if (emin + k < -lim || emax + 1 + k > lim) return 0;
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) out[i][c] = ldexp(pts[i][c], k);
    return 1;
}

/* ---- filtered predicates ------------------------------------------------- */

int dd_orient3d(dd_pred *ctx, const double *p, const double *q,
                const double *r, const double *s)
{
    int f = dd_orient3d_filter(ctx, p, q, r, s);
    return f != DD_FILTER_UNSURE ? f : dd_orient3d_unfiltered(ctx, p, q, r, s);
}

int dd_orient3d_unfiltered(dd_pred *ctx, const double *p, const double *q,
                           const double *r, const double *s)
{
    ctx->orient_exact++;
    int e = dd_orient3d_exp(p, q, r, s);
    if (e != DD_EXP_UNSAFE) return e;
    const double *pts[4] = {p, q, r, s};
    double x[4][3];
    if (rescale_into(pts, 4, DD_EXP_O3_LIM, x) && (e = dd_orient3d_exp(x[0], x[1], x[2], x[3])) != DD_EXP_UNSAFE)
        return e;
    return orient3d_exact(ctx, p, q, r, s);
}

int dd_insphere(dd_pred *ctx, const double *p, const double *q,
                const double *r, const double *s, const double *t)
{
    int f = dd_insphere_filter(ctx, p, q, r, s, t);
    return f != DD_FILTER_UNSURE ? f : dd_insphere_unfiltered(ctx, p, q, r, s, t);
}

int dd_insphere_unfiltered(dd_pred *ctx, const double *p, const double *q,
                           const double *r, const double *s, const double *t)
{
    ctx->insphere_exact++;
    int e = dd_insphere_exp(p, q, r, s, t);
    if (e != DD_EXP_UNSAFE) return e;
    const double *pts[5] = {p, q, r, s, t};
    double x[5][3];
    if (rescale_into(pts, 5, DD_EXP_INS_LIM, x) &&
        (e = dd_insphere_exp(x[0], x[1], x[2], x[3], x[4])) != DD_EXP_UNSAFE)
        return e;
    return insphere_exact(ctx, p, q, r, s, t);
}

/* Shewchuk's orient2d bound: |det| > 3.3307e-16 * (|l| + |r|) is certain
 * (differences of doubles are rounded too; the bound covers that).        */
static int orient2d_filtered(dd_pred *ctx, const double *p, const double *q,
                             const double *r, int i, int j)
{
    double l = (q[i] - p[i]) * (r[j] - p[j]);
    double rr = (r[i] - p[i]) * (q[j] - p[j]);
    double det = l - rr;
    double bound = 3.3306690738754716e-16 * (fabs(l) + fabs(rr));
    if (det > bound && bound > 1e-250) return 1;
    if (-det > bound && bound > 1e-250) return -1;
    (void)ctx;
    return 2;   /* undecided */
}

/* ---- small integers: exact in 128-bit integer arithmetic ---------------- */

/* 1 if every coordinate of the n points is an integer of magnitude below
 * 2^11: then all differences are below 2^12 and the degree-7 coplanar
 * in-circle determinant below 2^100, so __int128 evaluates it exactly.
 * (Integer grids and integer spheres: where exact zeros are common.)      */
static int small_ints(const double *const *pts, int n)
{
    for (int i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            double x = pts[i][c];
            if (!(x > -2048.0 && x < 2048.0) || x != (double)(int32_t)x) return 0;
        }
    return 1;
}

typedef __int128 i128;

static int sign128(i128 x) { return (x > 0) - (x < 0); }

static int orient_coplanar_small(const double *p, const double *q, const double *r)
{
    static const int ax[3][2] = {{0, 1}, {1, 2}, {0, 2}};   /* xy, yz, xz */
    for (int k = 0; k < 3; k++) {
        int i = ax[k][0], j = ax[k][1];
        int64_t d = ((int64_t)q[i] - (int64_t)p[i]) * ((int64_t)r[j] - (int64_t)p[j]) -
                    ((int64_t)r[i] - (int64_t)p[i]) * ((int64_t)q[j] - (int64_t)p[j]);
        if (d) return d > 0 ? 1 : -1;
    }
    return 0;
}

/* CGAL's determinant of rows p-t, r-t, q-t (lifted) and v = pq x pr. */
static int incircle_coplanar_small(const double *p, const double *q, const double *r, const double *t)
{
    const double *row[3] = {p, r, q};
    i128 m[4][4];
    for (int i = 0; i < 3; i++) {
        int64_t a = (int64_t)row[i][0] - (int64_t)t[0], b = (int64_t)row[i][1] - (int64_t)t[1],
                c = (int64_t)row[i][2] - (int64_t)t[2];
        m[i][0] = a; m[i][1] = b; m[i][2] = c; m[i][3] = a * a + b * b + c * c;
    }
    int64_t pq[3], pr[3];
    for (int c = 0; c < 3; c++) {
        pq[c] = (int64_t)q[c] - (int64_t)p[c];
        pr[c] = (int64_t)r[c] - (int64_t)p[c];
    }
    i128 vx = (i128)(pq[1] * pr[2] - pq[2] * pr[1]), vy = (i128)(pq[2] * pr[0] - pq[0] * pr[2]),
         vz = (i128)(pq[0] * pr[1] - pq[1] * pr[0]);
    m[3][0] = vx; m[3][1] = vy; m[3][2] = vz; m[3][3] = vx * vx + vy * vy + vz * vz;
    /* Laplace expansion along the last column */
    i128 det = 0;
    for (int i = 0; i < 4; i++) {
        int rr[3], k = 0;
        for (int j = 0; j < 4; j++)
            if (j != i) rr[k++] = j;
        i128 minor = m[rr[0]][0] * (m[rr[1]][1] * m[rr[2]][2] - m[rr[1]][2] * m[rr[2]][1]) -
                     m[rr[0]][1] * (m[rr[1]][0] * m[rr[2]][2] - m[rr[1]][2] * m[rr[2]][0]) +
                     m[rr[0]][2] * (m[rr[1]][0] * m[rr[2]][1] - m[rr[1]][1] * m[rr[2]][0]);
        det += ((i + 3) & 1 ? -1 : 1) * m[i][3] * minor;
    }
    return sign128(det);
}

int dd_orient_coplanar(dd_pred *ctx, const double *p, const double *q,
                       const double *r)
{
    int o = orient2d_filtered(ctx, p, q, r, 0, 1);
    if (o != 2) return o;
    const double *pts[3] = {p, q, r};
    if (small_ints(pts, 3)) return orient_coplanar_small(p, q, r);
    return orient_coplanar_exact(ctx, p, q, r);
}

int dd_incircle_coplanar(dd_pred *ctx, const double *p, const double *q,
                         const double *r, const double *t)
{
    const double *pts[4] = {p, q, r, t};
    if (small_ints(pts, 4)) return incircle_coplanar_small(p, q, r, t);
    return incircle_coplanar_exact(ctx, p, q, r, t);
}

/* ---- perturbation -------------------------------------------------------- */

/* Sorts the n point pointers lexicographically (insertion sort, n <= 5). */
static void lex_sort(const double **pts, int n)
{
    for (int i = 1; i < n; i++) {
        const double *x = pts[i];
        int j = i - 1;
        while (j >= 0 && dd_lex_cmp(pts[j], x) > 0) { pts[j + 1] = pts[j]; j--; }
        pts[j + 1] = x;
    }
}

int dd_insphere_perturbed(dd_pred *ctx, const double *p0, const double *p1,
                          const double *p2, const double *p3,
                          const double *p)
{
    int s = dd_insphere(ctx, p0, p1, p2, p3, p);
    return s != 0 ? s : dd_insphere_symbolic(ctx, p0, p1, p2, p3, p);
}

/* The cell and query of dd_insphere_symbolic, for lift.h's rule. */
typedef struct symbolic_cell {
    dd_pred *pr;
    const double *v[4], *p;
} symbolic_cell;

/* orient3d of the cell with its vertex k replaced by the query: the
 * rule's orientations (dd_lift_orient_fn, inlined where it is used).    */
static int orient_replaced(void *ctx, int k)
{
    const symbolic_cell *c = ctx;
    const double *v[4] = {c->v[0], c->v[1], c->v[2], c->v[3]};
    v[k] = c->p;
    return dd_orient3d(c->pr, v[0], v[1], v[2], v[3]);
}

int dd_insphere_symbolic(dd_pred *ctx, const double *p0, const double *p1,
                         const double *p2, const double *p3,
                         const double *p)
{
    DD_COUNT(ctx, perturbed);
    symbolic_cell c = {ctx, {p0, p1, p2, p3}, p};
    const double *pts[5] = {p0, p1, p2, p3, p};
    int t0 = 0, t1;                       /* the two largest by dd_lex_cmp */
    for (int i = 1; i < 5; i++) t0 = dd_lex_cmp(pts[i], pts[t0]) > 0 ? i : t0;
    t1 = t0 == 0;
    for (int i = t1 + 1; i < 5; i++) t1 = i != t0 && dd_lex_cmp(pts[i], pts[t1]) > 0 ? i : t1;
    return dd_lift_symbolic_top(t0, t1, 0, orient_replaced, &c);
}

int dd_incircle_coplanar_perturbed(dd_pred *ctx, const double *p0,
                                   const double *p1, const double *p2,
                                   const double *p)
{
    int s = dd_incircle_coplanar(ctx, p0, p1, p2, p);
    if (s != 0) return s;
    DD_COUNT(ctx, perturbed);
    const double *pts[4] = {p0, p1, p2, p};
    lex_sort(pts, 4);
    int local = dd_orient_coplanar(ctx, p0, p1, p2);
    for (int i = 3; i > 0; --i) {
        int o;
        if (pts[i] == p) return -1;
        if (pts[i] == p2 && (o = dd_orient_coplanar(ctx, p0, p1, p)) != 0) return o * local;
        if (pts[i] == p1 && (o = dd_orient_coplanar(ctx, p0, p, p2)) != 0) return o * local;
        if (pts[i] == p0 && (o = dd_orient_coplanar(ctx, p, p1, p2)) != 0) return o * local;
    }
    return -local;
}

int dd_inf_conflict(dd_pred *ctx, const double *const v[4], int k,
                    const double *p)
{
    /* Same argument order as CGAL's side_of_sphere(v0, v1, v2, v3, p). */
    static const int facet[4][3] = {{2, 1, 3}, {2, 3, 0}, {1, 0, 3}, {0, 1, 2}};
    const double *a = v[facet[k][0]], *b = v[facet[k][1]], *c = v[facet[k][2]];
    int o = dd_orient3d(ctx, a, b, c, p);
    if (o != 0) return o;
    return dd_incircle_coplanar_perturbed(ctx, a, b, c, p);
}

/* ---- distances ------------------------------------------------------------ */

/* Filter: each |p - x|^2 is a sum of three squares of rounded differences,
 * within 6u of its value (u = 2^-53: the difference, the square and two
 * additions each add at most u relative to positive terms); their
 * difference adds u |d|.  So |d - exact| <= 8u (A + B) with A, B the
 * computed sums, while A + B lies in [1e-290, 1e300]: no overflow, and
 * an underflowed term is far below the bound.                           */
static int distance_filter(const double *p, const double *a, const double *b)
{
    double A = 0, B = 0;
    for (int c = 0; c < 3; c++) {
        double x = p[c] - a[c], y = p[c] - b[c];
        A += x * x;
        B += y * y;
    }
    double d = A - B, err = 8.8817841970012523e-16 * (A + B);
    if (A + B >= 1e-290 && A + B <= 1e300) {
        if (d > err) return 1;
        if (d < -err) return -1;
    }
    return DD_FILTER_UNSURE;
}

static int compare_distance_z(mpz_ptr *z, const void *arg);

/* The filter, then (the sign is homogeneous of degree 2 in the three
 * points) the filter on the points scaled exactly into [2^-400, 2^400]
 * when it failed for their magnitude, then GMP.                         */
int dd_compare_distance(dd_pred *ctx, const double *p, const double *a, const double *b)
{
    int f = distance_filter(p, a, b);
    if (f != DD_FILTER_UNSURE) return f;
    const double *pts[3] = {p, a, b};
    double x[3][3];
    if (rescale_into(pts, 3, 400, x) && (f = distance_filter(x[0], x[1], x[2])) != DD_FILTER_UNSURE) return f;
    return dd_pred_exact(ctx, pts, 3, compare_distance_z, NULL, NULL);
}

/* sign(|p - a|^2 - |p - b|^2) of p, a, b in z[0..9) (dd_exact_fn). */
static int compare_distance_z(mpz_ptr *z, const void *arg)
{
    (void)arg;
    mpz_set_ui(z[9], 0);                       /* A - B, summed exactly */
    for (int c = 0; c < 3; c++) {
        mpz_sub(z[10], z[c], z[3 + c]);
        mpz_addmul(z[9], z[10], z[10]);
        mpz_sub(z[10], z[c], z[6 + c]);
        mpz_submul(z[9], z[10], z[10]);
    }
    return mpz_sgn(z[9]);
}
