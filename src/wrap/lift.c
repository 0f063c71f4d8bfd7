/*
 * lift.c -- the gift wrap's frame (docs/gift-wrap.md §2, §8): the rows
 * of the neighbours lifted at q and the modes that follow, kept in the
 * wrap's state; the switch to the shifted lifts.
 *
 * Owns: w->lift (the rows, in columns, padded with NaN to a multiple of
 * four), the bounds ierr and oerr and the integer modes (w->exact,
 * oexact, kexact) of this deletion.  The rows, the bounds and their
 * derivation are geom/lift.h's and lift_pass.h's (dd_lift_rows,
 * dd_shift_lifts); the float rows are made at their first use
 * (w_flift, dd_lift_f32_rows).
 *
 * Invariant: a bound of 0 means that the evaluation is exact, +inf that
 * there is no filter (every sign goes to the exact predicates, and
 * nothing is guessed).
 */
#include "wrap/wrap_int.h"

/* Lifts the sites relative to q (dd_lift_rows; weighted,
 * dd_lift_rows_power at (q, qw)) and sets the filters' bounds and exact
 * modes from the frame.  The weighted mode (docs §13) holds when a
 * weight differs from q's or hidden points are among the sites: then the
 * in-sphere bound is dd_lift_power_err, only the orientations may be
 * exact in integers, and there are no shifted lifts (they drop the
 * weights).  Otherwise the lifts are the unweighted ones, bit for bit,
 * and so is everything that follows.  O(n).                              */
void w_lift(struct dd_wrap *w, const double *q, double qw, int weighted)
{
    double W = 0;
    dd_lift_frame f = weighted ? dd_lift_rows_power(w->lift, w->pt, w->wgt, w->n, q, qw, &W)
                               : dd_lift_rows(w->lift, w->pt, w->n, q);
    w->wmode = weighted && (W != 0 || w->nlink < w->n);
    if (w->wmode) {
        f.modes &= DD_LIFT_OEXACT;
        f.ierr = dd_lift_power_err(f.m, W);
    }
    w->wbig = w->wmode && !(W <= 1e3 * f.m * f.m);
    w->exact = (f.modes & DD_LIFT_EXACT) != 0;
    w->oexact = (f.modes & DD_LIFT_OEXACT) != 0;
    w->kexact = (f.modes & DD_LIFT_KEXACT) != 0;
    w->ierr = f.ierr;
    w->oerr = f.oerr;
    const int ok = f.ierr != 1.0 / 0.0;
    w->m = f.m;
    w->q = q;
    /* nothing to shift for: the filters are off, exact tests cheap, or weights */
    w->shifted = !ok || w->kexact || w->wmode;
    w->nexact = 0;
    w->lex_ok = 0;
}

/* Switches to the shifted lifts (docs §8; geom/lift.h's dd_shift_lifts,
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
