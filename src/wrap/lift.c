/*
 * lift.c -- the lifts and the filters' bounds of the gift wrap.
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
            double a = L[i][k] < 0 ? -L[i][k] : L[i][k];
            if (a > m) m = a;
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

/* The single-precision lifts (w_guess_f32_avx2): x_k - q over m and
 * |x_k - q|^2 over m^2 (at most 1 and 3), rounded to floats, padded with
 * NaN to a multiple of eight; and the scales that take N and T (w_pencil)
 * to the same units: N's entries are at most 8m^2, T's are O(m^5) (xyz)
 * and O(m^4) (lift), so that o and t are O(1) or less there.  Only for
 * 1e-50 <= m <= 1e50 (dd_wrap_fill): no overflow of the scales.        */
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

/* Shifted lifts (qsmall.c's, whose bound they keep: the determinants of
 * wrap_scan have the same entries and at most as many roundings), for
 * nearly cospherical cavities where the plain filter abstains.  Tried
 * once per deletion, with at least DD_SHIFT_FROM neighbours (below that
 * the exact expansions of the shift cost more than the tests they save,
 * as in qsmall.c): when a guess over every neighbour is refuted, which
 * is then made again (dd_wrap_fill), or when a fast scan first fails its
 * check, which is then run again.  0 when the shift is no tighter (the
 * lifts are kept).                                                      */
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
