/*
 * hull.c -- the hull step of the gift wrap (docs/gift-wrap.md §5): the
 * fill cell on an open facet through the infinite vertex, by a Jarvis
 * step around its hull edge, and w_all_behind, the test that makes a
 * finite facet a facet of the hull of the neighbours.
 *
 * Invariant: a hull step's answer is certified (every other point surely
 * behind the new hull facet in doubles or exactly, and the points of its
 * plane checked by the perturbed in-circle rules), so the proof of a
 * guessed fill takes it as it is (§7, property 5).  A step that its
 * checks do not settle bails (W_BAIL): the wrap declines.
 */
#include "wrap/wrap_int.h"

/* Whether every point k < end but x, y, z is surely behind the plane of
 * normal N through y (o < -oerr, rows from y, o as dd_lift_row_o: the scans'
 * test).  With end = n and facet (x, y, z): the facet is a facet of the
 * hull of the neighbours.  O(end), four points a vector with AVX2.      */
int w_all_behind(const struct dd_wrap *w, uint32_t x, uint32_t y, uint32_t z, const double N[4], uint32_t end)
{
#ifdef W_AVX2
    if (w->avx2) return dd_lift_all_behind_avx2(w->lift, end, x, y, z, N, w->oerr);
#endif
    for (uint32_t k = 0; (k = w_next_to(w, y, N, k, end, 0)) < end; k++)
        if (k != x && k != y && k != z) return 0;
    return 1;
}

/* The apex p of open facet (a, b, INF) (docs §5 HULLSTEP), the infinite
 * vertex last: the cell (a, b, INF, p) whose hull facet (b, a, p) has no
 * point beyond it and, among the points of its plane, none in the
 * perturbed circle of b, a, p (the conflict test of the infinite cell: a
 * flat face of the hull is triangulated by the coplanar in-circle rules).
 * Orientations are filtered as in the scans (w_orient), else exact.
 *  1. Seen along the hull edge ab, the points lie in a wedge of at most a
 *     half-turn, and "x beyond the plane of b, a, p" orders them by
 *     angle: one pass keeping the point furthest round (Jarvis) finds the
 *     plane of the facet.  When the wedge is a half-turn (ab a diagonal
 *     of a flat face), no point of one edge of the wedge is beyond one of
 *     the other: the pass may skip a point of the far edge while its best
 *     is on the near one.
 *  2. The check (first that every point is surely behind, w_all_behind):
 *     no point beyond; those in the plane (flat) are marked in
 *     w->o, and z is a point behind it.  Only a point so skipped can be
 *     beyond the pass's best: it becomes the best and the check starts
 *     again, once.
 *  3. For a flat face, the points of the plane on p's side of line ab
 *     (the side of p as seen from the plane of a, b, z) are ordered by
 *     the perturbed circles through a and b: one pass keeping the point
 *     in conflict with the best so far, then a check that none is.
 * W_BAIL, left to the conflict DT, when every point is in one plane or a
 * check fails; W_NONE when every point is on line ab.  With the float
 * lifts, step 1 is first guessed in floats (w_inf_f32) and taken when
 * its check passes in doubles.  O(n) a pass: one or two passes and the
 * check; on flat faces a few more, with exact tests.                    */
uint32_t w_scan_inf(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b)
{
    const double *const *pt = w->pt;
    uint32_t best = W_NONE, z = W_NONE;
    double N[4];
#ifdef W_AVX2
    if (w->flift_ok) {                               /* step 1 guessed (dd_lift_inf_f32) */
        uint32_t p = dd_lift_inf_f32(w_flift(w), w->n, a, b);
        if (p < w->n && W_F32_SPOIL(w)) p = (p + 1) % w->n;   /* tests: refused */
        if (p < w->n && p != a && p != b) {
            w_normal(w, b, a, p, N);
            if (w_all_behind(w, a, b, p, N, w->n)) { w->inf_kept++; return p; }
        }
        w->inf_back++;
    }
#endif
    uint32_t i = 0;
    for (; i < w->n && best == W_NONE; i++)
        if (i != a && i != b && dd_orient_coplanar(pr, pt[a], pt[b], pt[i]) != 0) w_normal(w, b, a, best = i, N);
    /* from `last` on, each point was met with the plane as it is now:
     * surely behind it (w_next passed it), or not (`met`)                */
    uint32_t last = i;
    int met = 0;
    for (; (i = w_next(w, b, N, i, 0)) < w->n; i++) {   /* the others are behind: not further round */
        if (i == a || i == b || i == best) continue;
        if (w_orient(w, pr, b, a, best, N, i) > 0) {
            w_normal(w, b, a, best = i, N);
            last = i + 1;
            met = 0;
        } else {
            met = 1;
        }
    }
    if (best == W_NONE) return W_NONE;
    /* The check (w_all_behind: every point but a, b, best surely behind),
     * on the points before `last` only when the pass met every one after
     * it surely behind the final plane already.                         */
    if (w_all_behind(w, a, b, best, N, met ? w->n : last)) return best;
    int flat = 0;
    double *mark = w->o;
    for (uint32_t k = 0, again = 1; k < w->n; k++) {
        mark[k] = 0;
        if (k == a || k == b || k == best) continue;
        int o = w_orient(w, pr, b, a, best, N, k);
        if (o > 0) {
            if (!again--) return W_BAIL;
            w_normal(w, b, a, best = k, N);     /* the pass again, from inside the wedge */
            flat = 0;
            z = W_NONE;
            k = UINT32_MAX;
            continue;
        }
        if (o < 0 && z == W_NONE) z = k;
        flat |= o == 0;
        mark[k] = o == 0;
    }
    if (!flat) return best;
    if (z == W_NONE || w->wmode) return W_BAIL;     /* weighted: power circles, left to the regular fill */
    const int side = dd_orient3d(pr, pt[a], pt[b], pt[z], pt[best]);
    for (uint32_t k = 0; k < w->n; k++)
        mark[k] = mark[k] != 0 && dd_orient3d(pr, pt[a], pt[b], pt[z], pt[k]) == side;
    const double *cell[4] = {pt[a], pt[b], NULL, pt[best]};
    for (uint32_t k = 0; k < w->n; k++)
        if (mark[k] != 0 && k != best && dd_points_conflict(pr, cell, 2, -1, pt[k])) {
            mark[best] = 1;
            best = k;
            cell[3] = pt[k];
        }
    for (uint32_t k = 0; k < w->n; k++)
        if (mark[k] != 0 && k != best && dd_points_conflict(pr, cell, 2, -1, pt[k])) return W_BAIL;
    return best;
}
