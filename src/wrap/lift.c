/*
 * lift.c -- the lifts and the filters' bounds of the gift wrap.
 */
#include "wrap/wrap_int.h"

/* Lifts the neighbours relative to q and sets the filters' bounds.
 *
 * In-sphere.  For points a, b, c, x, p the in-sphere determinant equals
 * det4(L[b]-L[a], L[c]-L[a], L[x]-L[a], L[p]-L[a]) with L[y] = (y - q,
 * |y - q|^2) (translate, then add to the lift a combination of the first
 * three columns); negative when p is inside the sphere of the positively
 * oriented a, b, c, x.  These are the entries of qsmall.c's filter (rows
 * L[v] - L[p] there), with the same bounds: columns 0-2 at most 2m with
 * errors at most 4um, column 3 at most 3m^2 with errors at most 36um^2,
 * m = max |y_k - q_k|.  wrap_scan evaluates the determinant by 2x2
 * minors of the first two rows, 3x3 cofactors with the third, a dot
 * product with the fourth: at most 9 roundings on any product path, so
 * qsmall.c's bound (10 roundings) holds: |error| < 1.8e-12 m^5, and the
 * filter answers only beyond 1e-11 m^5.
 *
 * Orientation.  orient3d(a, b, c, p) = det3 of the first three columns of
 * the same rows: entries at most 2m with errors at most 4um; the 6 terms
 * move by at most 6 * 3 * (2m)^2 * 4um = 288u m^3 from the entry errors,
 * and the evaluation (2x2 minors, then a 3-term dot product: 5 roundings)
 * adds at most gamma_5 * 48 m^3 < 241u m^3: in all below 6e-14 m^3; the
 * filter answers beyond 1e-13 m^3.
 *
 * Both only for 1e-55 <= m <= 1e55 (no overflow; underflow errors far
 * below the bounds); otherwise the bounds are +inf and the exact
 * predicates decide every test.
 *
 * Integer points.  When q and every neighbour have integer coordinates
 * and m <= W_INT_M = 400, each x_k - q is exact and every lift is an
 * integer: columns 0-2 at most m, column 3 at most 3m^2, so the rows'
 * entries are at most 2m and 3m^2.  Every quantity the scans certify
 * with is then a sum of products of integers below 2^53, computed
 * exactly: the minors at most 8m^2 (xyz) and 12m^3 (with the lift), o at
 * most 48m^3, the cofactors K at most 72m^4, the in-sphere determinant
 * K . P at most 576m^5 <= 5.9e15 < 2^53 (9.0e15; up to m = 434).  The
 * bounds become 0 (w->exact): a test
 * is decided by its sign, and 0 is exactly 0, where orient3d is 0 and the
 * in-sphere test is the perturbation's alone (w_symbolic): no
 * exact expansion at all (grids, cospheres, stacked layers, where they
 * were a quarter of a deletion).  t, which only ranks candidates, may
 * round.  (The bound was m <= 256 before: the cosphere, n = 4000, radius
 * 297, has neighbours up to 2r = 594 apart; at degree 8-31, 400 against
 * 256 took 16% fewer instructions a deletion, at 32-63 4%, callgrind.)
 *
 * Integer orientations.  o alone (the minors of the xyz columns, at most
 * 8m^2, times entries at most 2m: at most 48m^3) is exact further, up to
 * m = W_INT_O = 2^15 (48m^3 <= 1.6e15): the orientation filter's bound
 * is 0 there (w->oexact), a zero is exactly 0, and no orientation goes to
 * the exact predicate, while in-sphere tests keep their filter.  The
 * cosphere at degree 64-95 has neighbours up to 594 apart, where the
 * exact orient3d took 16% of a deletion.
 *
 * Integer cofactors.  Up to m = W_INT_K = 2^11 the cofactors K (at most
 * 72m^4 <= 1.3e15) are exact too, and the in-sphere determinant K . P
 * the filter leaves (products below 2^75) is summed exactly in 128-bit
 * integers (w_sign_kp): 0 goes to the perturbation (w_symbolic), as with
 * integer lifts, and no in-sphere test to the exact expansions (the
 * cosphere at degree 64-95: 15% of a deletion, w_cospherical's).       */
#define W_INT_M 400.0
#define W_INT_O 32768.0
#if defined(__SIZEOF_INT128__)
#define W_INT_K 2048.0
#else
#define W_INT_K 0.0                               /* no 128-bit integers */
#endif
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
    w->exact = integral && m <= W_INT_M;
    w->oexact = integral && m <= W_INT_O;
    w->kexact = integral && (m <= W_INT_M || m <= W_INT_K);   /* integer lifts: too */
    w->ierr = w->exact ? 0 : dd_lift_err(m);
    int ok = w->ierr != 1.0 / 0.0;
    w->oerr = w->oexact ? 0 : ok ? 1e-13 * m * m * m : 1.0 / 0.0;
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
