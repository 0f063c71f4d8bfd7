/*
 * scan.c -- the certified scans of the gift wrap (docs/gift-wrap.md §4)
 * and the perturbed tests on local numbers (§1, §8).
 *
 * Owns: the fast scan (wrap_scan: one pass without data-dependent
 * branches, then a check of its candidate), the exact scan (w_scan_exact:
 * each decision filtered, else exact), the scan of cospherical neighbours
 * (wrap_scan_cosph), the flat-hull check (w_flat_hull), the test that the
 * neighbours are cospherical (w_cospherical), and CGAL's symbolic
 * perturbation evaluated on local numbers, with lexicographic ranks made
 * once per deletion (w_symbolic, w_conflicts_near).
 *
 * Invariant: every answer is the apex that the exact perturbed predicates
 * define; a sign is acted on only when a filter of geom/lift.h certifies
 * it (the evaluations and passes of geom/lift_pass.h),
 * integer arithmetic makes it exact, or src/geom/ decides it.  The tests
 * that the wrap's filters leave to the predicates are counted in
 * w->nexact, for the budget (w_spent).
 */
#include "wrap/wrap_int.h"
#include "geom/power.h"

/* Lexicographic ranks of the neighbours (w->lexr, dd_lex_ranks), made the
 * first time the perturbation is asked this deletion.  O(n log n).     */
static void w_lex_ranks(struct dd_wrap *w)
{
    dd_lex_ranks(w->pt, w->n, w->tmp, w->lexr);
    w->lex_ok = 1;
}

/* dd_insphere_symbolic on local numbers: the perturbation's sign for y
 * and the positively oriented cell lv when their in-sphere determinant is
 * exactly 0 (+1 inside), by geom/lift.h's rule (dd_lift_symbolic) on the
 * lexicographic ranks of w_lex_ranks, the orientations w_orient's (exact
 * in doubles with integer lifts, else filtered, else exact).            */
typedef struct w_sym_ctx {
    struct dd_wrap *w;
    dd_pred *pr;
    const uint32_t *lv;
    uint32_t y;
} w_sym_ctx;

/* orient3d of the cell lv with its corner k replaced by y. */
static inline int w_sym_orient(void *ctx, int k)
{
    const w_sym_ctx *c = ctx;
    uint32_t v[4] = {c->lv[0], c->lv[1], c->lv[2], c->lv[3]};
    v[k] = c->y;
    double N[4];
    w_normal(c->w, v[0], v[1], v[2], N);
    return w_orient(c->w, c->pr, v[0], v[1], v[2], N, v[3]);
}

static int w_symbolic_from(struct dd_wrap *w, dd_pred *pr, const uint32_t lv[4], uint32_t y, int from)
{
    if (!w->lex_ok) w_lex_ranks(w);
    const uint32_t *r = w->lexr, rk[5] = {r[lv[0]], r[lv[1]], r[lv[2]], r[lv[3]], r[y]};
    w_sym_ctx c = {w, pr, lv, y};
    return dd_lift_symbolic(rk, from, w_sym_orient, &c);
}

/* The perturbation's sign for y and cell lv: w_symbolic_from its start. */
static inline int w_symbolic(struct dd_wrap *w, dd_pred *pr, const uint32_t lv[4], uint32_t y)
{
    return w_symbolic_from(w, pr, lv, y, 0);
}

/* w_conflicts where its filter abstains, out of line so that the rare
 * path stays out of the callers' loops: with integer cofactors the sign
 * of K . P in 128-bit integers (dd_lift_sign_kp; 0 with integer lifts,
 * whose bound is 0), a 0 going to w_symbolic; else the exact perturbed
 * in-sphere test, counted in w->nexact.  P = L[y] - L[lv[0]].           */
__attribute__((noinline)) int w_conflicts_near(struct dd_wrap *w, dd_pred *pr, const uint32_t lv[4], const double K[4],
                                               const double P[4], uint32_t y)
{
    const double *const *pt = w->pt;
    if (w->kexact) {
        const int sg = w->exact ? 0 : dd_lift_sign_kp(K, P);
        return sg ? sg < 0 : w_symbolic(w, pr, lv, y) > 0;
    }
    w->nexact++;
    if (w->wmode) {                                 /* the weighted lift: the power test */
        const double *wg = w->wgt, wt[5] = {wg[lv[0]], wg[lv[1]], wg[lv[2]], wg[lv[3]], wg[y]};
        return dd_power_perturbed(pr, pt[lv[0]], pt[lv[1]], pt[lv[2]], pt[lv[3]], pt[y], wt) > 0;
    }
    return dd_insphere_perturbed(pr, pt[lv[0]], pt[lv[1]], pt[lv[2]], pt[lv[3]], pt[y]) > 0;
}

/* Whether finite facet (a, b, c), with no point beyond it but some in its
 * plane, is a facet of the hull (docs §4 FLATHULL): W_NONE when no point
 * of its plane is in the perturbed circle of a, b, c (the conflict test
 * of the infinite cell (a, b, c, INF), as in the conflict DT), else
 * W_BAIL.  With no point beyond, the cell on the facet's positive side
 * can only be infinite; the check keeps the wrap from building on a hull
 * triangle that the perturbation's coplanar rules would split.  O(n)
 * exact tests.                                                          */
static uint32_t w_flat_hull(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c)
{
    if (w->wmode) return W_BAIL;                    /* power circles: left to the regular fill */
    const double *cell[4] = {w->pt[a], w->pt[b], w->pt[c], NULL};
    for (uint32_t k = 0; k < w->n; k++) {
        if (k == a || k == b || k == c) continue;
        if (dd_points_conflict(pr, cell, 3, -1, w->pt[k])) return W_BAIL;
    }
    return W_NONE;
}

/* The exact scan (docs §4 SCAN_EXACT) of facet (a, b, c), minors m: one
 * pass over ks[0..nk) (NULL: 0..nk) keeping the best point beyond abc so
 * far, each orientation and conflict filtered (geom/lift.h) and else decided
 * exactly.  It starts from `best` (W_NONE: none yet); with `unsure_only`
 * it takes the points surely beyond as compared already (best is the
 * guess's minimum among them) and decides only those of unsure
 * orientation, with AVX2 found four at a time (w_next).  No point beyond
 * but some in the plane: w_flat_hull's answer.  Its branches follow the
 * data, so wrap_scan runs it only when its own check fails.  O(nk)
 * tests.                                                                */
uint32_t w_scan_exact(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c, const double m[6],
                      uint32_t best, int unsure_only, const uint32_t *ks, uint32_t nk)
{
    double *const *L = w->lift;
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
    double N[4], K[4] = {0, 0, 0, 0}, P[4];
    dd_lift_normal_of(m, N);
    const double oerr = w->oerr;
    uint32_t cell[4] = {a, b, c, best};
    if (best != W_NONE) {
        dd_lift_row_o(L, best, A, N, P);
        dd_lift_vcofactors(K, P, m);
    }
    int zero = 0;
    const int skip = unsure_only && !ks;            /* to the unsure points, four at a time */
    for (uint32_t i = skip ? w_next(w, a, N, 0, 1) : 0; i < nk; i = skip ? w_next(w, a, N, i + 1, 1) : i + 1) {
        const uint32_t k = ks ? ks[i] : i;
        if (k == a || k == b || k == c) continue;
        double o = dd_lift_row_o(L, k, A, N, P);
        if (!dd_lift_sure_pos(o, oerr)) {
            if (dd_lift_sure_neg(o, oerr)) continue;
            w->nexact += !w->oexact;                /* integer orientations: o is exact */
            int or = w_sign_o(w, pr, o, a, b, c, k);
            zero |= or == 0;
            if (or <= 0) continue;
        } else if (unsure_only) {
            continue;
        }
        if (best != W_NONE && !w_conflicts(w, pr, cell, K, k)) continue;
        best = cell[3] = k;
        dd_lift_vcofactors(K, P, m);
    }
    /* No point beyond: for a hull vertex, abc becomes a hull facet, the
     * cell (a, b, c, infinite), if the points in its plane allow.        */
    return best == W_NONE && zero ? w_flat_hull(w, pr, a, b, c) : best;
}

/* orient3d(a, b, c, k) as w_orient has it, A being the lifts of a, and
 * an unsure o counted for W_EXACT_FROM's budget as w_scan_exact
 * counts it.                                                            */
static inline int w_orient_counted(struct dd_wrap *w, dd_pred *pr, const double A[4], const double N[4], uint32_t a,
                                   uint32_t b, uint32_t c, uint32_t k)
{
    double P[4], o = dd_lift_row_o(w->lift, k, A, N, P);
    w->nexact += !w->oexact && dd_lift_unsure(o, w->oerr);
    return w_sign_o(w, pr, o, a, b, c, k);
}

/* The scan for cospherical neighbours (w->cosph, docs §4): every
 * in-sphere determinant is 0, so the apex is the point beyond abc that
 * w_symbolic prefers to every other.  For x the best so far and y a
 * candidate, both beyond abc, w_symbolic's first step looks at the
 * largest of the five ranks: y's, y is outside; x's, y is inside; so
 * among points ranked above every corner the least ranked wins, and any
 * point ranked below the top corner beats them all.  The top corner's:
 * the sign of orient3d(u0, u1, x, y), u0, u1 the other corners in cyclic
 * order, one evaluation against the normal of plane (u0, u1, x), kept
 * until x changes; a 0 (five points on a circle) goes to w_symbolic's
 * second step.  So a first pass takes the points ranked below the top
 * corner, and only if none is beyond does a second take the least ranked
 * of the others.  Each answer is w_symbolic's, so the apex is
 * w_scan_exact's.  O(n) orientations.                                    */
static uint32_t wrap_scan_cosph(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c,
                                const double N[4])
{
    if (!w->lex_ok) w_lex_ranks(w);
    double *const *L = w->lift;
    const uint32_t *rk = w->lexr, n = w->n;
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
    uint32_t lv[4] = {a, b, c, W_NONE};
    int top = 0;
    for (int i = 1; i < 3; i++)
        if (rk[lv[i]] > rk[lv[top]]) top = i;
    const uint32_t rtop = rk[lv[top]], u0 = lv[(top + 2) % 3], u1 = lv[(top + 1) % 3];
    double Nx[4];
    int zero = 0;
    for (uint32_t k = 0; k < n; k++) {
        if (rk[k] >= rtop || k == u0 || k == u1) continue;
        int o = w_orient_counted(w, pr, A, N, a, b, c, k);
        zero |= o == 0;
        if (o <= 0) continue;
        if (lv[3] != W_NONE) {
            int s = w_orient(w, pr, u0, u1, lv[3], Nx, k);
            if (s == 0) s = w_symbolic_from(w, pr, lv, k, 1);   /* its first step: this 0 */
            if (s <= 0) continue;
        }
        lv[3] = k;
        w_normal(w, u0, u1, k, Nx);
    }
    if (lv[3] != W_NONE) return lv[3];
    uint32_t best = W_NONE;
    for (uint32_t k = 0; k < n; k++) {
        if (rk[k] <= rtop || (best != W_NONE && rk[k] > rk[best])) continue;
        int o = w_orient_counted(w, pr, A, N, a, b, c, k);
        zero |= o == 0;
        if (o > 0) best = k;
    }
    return best == W_NONE && zero ? w_flat_hull(w, pr, a, b, c) : best;
}

/* The fast scan (docs §4 SCAN), without data-dependent branches: o and t
 * for every point, the least t/o beyond abc, then a check of that
 * candidate x with the filtered determinant w(x, p) for every other point
 * p beyond.  The check proves the answer (every such p surely outside the
 * sphere of a, b, c, x; every orientation sure); rounding or overflow in
 * t/o can only make it fail.  Then W_SHIFT, once per deletion from
 * DD_SHIFT_FROM neighbours on, else w_scan_exact.  Cospherical
 * neighbours: wrap_scan_cosph.  Two passes, O(n).                        */
static uint32_t wrap_scan(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c)
{
    double *const *L = w->lift;
    double m[6], N[4], T[4], K[4];
    w_pencil(w, a, b, c, m, N, T);
    if (w->cosph) return wrap_scan_cosph(w, pr, a, b, c, N);   /* every t/o ties */
    const double oerr = w->oerr, ierr = w->ierr;
    const uint32_t n = w->n;
    /* a, b, c need no test of their own: o(a) is exactly 0 and o(b),
     * o(c) are 0 up to less than oerr (their exact value is 0), so each
     * counts once among the unsure orientations, never as a candidate. */
    double *o = w->o;                           /* > oerr: a candidate */
    int unsure;
    const uint32_t best = dd_lift_least_beyond(L, n, a, N, T, oerr, o, &unsure);
    if (unsure != 3 || best == W_NONE) return w_scan_exact(w, pr, a, b, c, m, W_NONE, 0, NULL, w->n);
    double X[4];
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
    dd_lift_row_o(L, best, A, N, X);
    dd_lift_vcofactors(K, X, m);
    o[best] = -1.0;                             /* not tested against itself */
    if (dd_lift_all_outside(L, n, a, N, K, o, oerr, ierr)) return best;
    return w->shifted || n < DD_SHIFT_FROM ? w_scan_exact(w, pr, a, b, c, m, W_NONE, 0, NULL, w->n) : W_SHIFT;
}

/* The fill cell's apex on finite open facet (a, b, c) by the certified
 * scans: wrap_scan, once more on shifted lifts when it asks for them
 * (W_SHIFT), and the infinite vertex (number n) for a facet of a hull
 * vertex's cavity with no point beyond it.                              */
uint32_t w_scan_apex(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c, int on_hull)
{
    uint32_t p = wrap_scan(w, pr, a, b, c);
    if (p == W_SHIFT) {
        w_shift(w);
        p = wrap_scan(w, pr, a, b, c);
    }
    return p == W_NONE && on_hull ? w->n : p;
}

/* Whether every neighbour lies on one sphere, exactly (docs §3
 * COSPHERICAL): for the first finite link triangle abc among the first
 * nlink records and the first point e off its plane, every other point's
 * in-sphere determinant with a, b, c, e is 0.  Then every in-sphere
 * determinant of the scans is 0, and they ask the perturbation alone
 * (wrap_scan_cosph).  The tests are the scans' (w_orient; the lifted
 * determinant filtered by ierr, else exact: in integers with w->kexact,
 * else dd_insphere), so generic neighbours stop at the first point.
 * O(n).                                                                  */
int w_cospherical(struct dd_wrap *w, dd_pred *pr, size_t nlink)
{
    if (w->wmode) return 0;                         /* the weighted scans ask the power tests */
    double *const *L = w->lift;
    const double *const *pt = w->pt;
    const uint32_t n = w->n;
    for (size_t r = 0; r < nlink; r++) {
        const uint32_t a = w->tri[r][0], b = w->tri[r][1], c = w->tri[r][2];
        if (a == n || b == n || c == n) continue;       /* through the infinite vertex */
        const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
        double m[6], N[4], T[4], K[4], P[4];
        w_pencil(w, a, b, c, m, N, T);
        uint32_t e = W_NONE;
        for (uint32_t k = 0; k < n && e == W_NONE; k++)
            if (k != a && k != b && k != c && w_orient(w, pr, a, b, c, N, k) != 0) e = k;
        if (e == W_NONE) return 0;
        dd_lift_row_o(L, e, A, N, P);
        dd_lift_vcofactors(K, P, m);
        for (uint32_t k = 0; k < n; k++) {
            if (k == a || k == b || k == c || k == e) continue;
            dd_lift_row_o(L, k, A, N, P);
            if (dd_lift_sure(dd_lift_dot4(K, P), w->ierr) != 0) return 0;
            if (w->kexact ? !w->exact && dd_lift_sign_kp(K, P) != 0 : dd_insphere(pr, pt[a], pt[b], pt[c], pt[e], pt[k]) != 0)
                return 0;
        }
        return 1;
    }
    return 0;
}
