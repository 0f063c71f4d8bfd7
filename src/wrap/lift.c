/*
 * lift.c -- the lifts of the gift wrap and its filters' bounds
 * (docs/gift-wrap.md §2, §8).
 *
 * Owns: the rows L[k] = (x_k - q, |x_k - q|^2) of the neighbours, in
 * doubles (w->lift) and, for the single-precision passes, in floats in
 * units of m (w->flift); the shifted lifts; the error bounds ierr
 * (in-sphere) and oerr (orientation) and the integer modes (w->exact,
 * oexact, kexact).
 *
 * Invariant: every determinant the wrap certifies with is evaluated from
 * these rows with at most the roundings counted below, so a value beyond
 * its bound has the sign of the exact determinant; a bound of 0 means
 * that the evaluation is exact, +inf that there is no filter (every sign
 * goes to the exact predicates, and nothing is guessed).  The lifts are
 * padded with NaN to a multiple of four (doubles) and of eight (floats)
 * for the AVX2 passes.
 */
#include "wrap/wrap_int.h"

/* Lifts the neighbours relative to q, L[y] = (y - q, |y - q|^2), and sets
 * the filters' bounds and exact modes from the frame: the in-sphere and
 * orientation bounds and the integer modes (integer lifts, orientations,
 * 128-bit cofactors) are geom/lift.h's, derived there once.  The wrap's
 * evaluations (w_pencil, w_row_o, w_t: 2x2 minors, 3x3 cofactors, a dot
 * product) have at most the roundings that derivation counts.          */
void w_lift(struct dd_wrap *w, const double *q)
{
    double m = 0;
    double *L[4] = {w->lift[0], w->lift[1], w->lift[2], w->lift[3]};
    int integral = floor(q[0]) == q[0] && floor(q[1]) == q[1] && floor(q[2]) == q[2];
    for (uint32_t k = 0; k < w->n; k++) {
        const double *p = w->pt[k];
        for (int i = 0; i < 3; i++) {
            L[i][k] = p[i] - q[i];
            integral = integral && floor(p[i]) == p[i];
            m = dd_lift_max(m, fabs(L[i][k]));
        }
        L[3][k] = L[0][k] * L[0][k] + L[1][k] * L[1][k] + L[2][k] * L[2][k];
    }
    for (uint32_t k = w->n; k % 4; k++)            /* wrap_guess's padding */
        for (int i = 0; i < 4; i++) L[i][k] = NAN;
    const dd_lift_frame f = dd_lift_classify(integral, m);
    w->exact = (f.modes & DD_LIFT_EXACT) != 0;
    w->oexact = (f.modes & DD_LIFT_OEXACT) != 0;
    w->kexact = (f.modes & DD_LIFT_KEXACT) != 0;
    w->ierr = f.ierr;
    w->oerr = f.oerr;
    const int ok = f.ierr != 1.0 / 0.0;
    w->m = m;
    w->q = q;
    w->shifted = !ok || w->kexact;   /* nothing to shift for: the filters are off, or exact tests cheap */
    w->nexact = 0;
    w->lex_ok = 0;
}

/* The single-precision lifts (simd.c): x_k - q over m and |x_k - q|^2
 * over m^2 (at most 1 and 3), rounded to floats, padded with NaN to a
 * multiple of eight; and the scales that take N and T (w_pencil) to the
 * same units: N's entries are at most 8m^2, T's O(m^5) (xyz) and O(m^4)
 * (lift), so that o and t are O(1) or less there.  Only for 1e-50 <= m
 * <= 1e50 (w->flift_ok): the scales do not overflow.  Only ranks: every
 * answer of the float passes is checked in doubles.  O(n).             */
void w_lift_f32(struct dd_wrap *w)
{
    const double s = 1.0 / w->m, s2 = s * s;
    w->f32_sn = s2;                                  /* N: at most 8m^2    */
    w->f32_st = s2 * s2 * s;                         /* T, xyz: O(m^5)     */
    w->f32_st3 = s2 * s2;                            /* T, lift: O(m^4)    */
    for (int i = 0; i < 4; i++) {
        const double *L = w->lift[i], f = i < 3 ? s : s2;
        float *F = w->flift[i];
        uint32_t k = 0;
        for (; k < w->n; k++) F[k] = (float)(L[k] * f);
        for (; k % 8; k++) F[k] = NAN;
    }
}

/* Switches to the shifted lifts (docs §8; qsmall.c's dd_shift_lifts,
 * whose bound holds here: the same entries, at most as many roundings)
 * for nearly cospherical cavities, where the plain filter abstains: the
 * lift becomes about the distance from a sphere through q and three
 * neighbours.  Once per deletion (w->shifted), from DD_SHIFT_FROM
 * neighbours on (below, the shift's exact expansions cost more than the
 * tests they save): after a refuted wide guess, which is made again, or a
 * fast scan's failed check, which is scanned again.  1: the bound is
 * tighter and the lifts replaced; 0: the lifts kept.  O(n) expansions.  */
int w_shift(struct dd_wrap *w)
{
    w->shifted = 1;
    double *const *L = w->lift, l[3][4];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++) l[j][i] = L[i][j];
    double *o = w->o;                              /* scratch until the next scan */
    double err = dd_shift_lifts(w->pt, w->n, w->q, l[0], l[1], l[2], w->m, w->ierr, o);
    if (err == 0) return 0;
    memcpy(L[3], o, w->n * sizeof *o);
    w->ierr = err;
    return 1;
}
