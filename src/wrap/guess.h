/*
 * guess.h -- the guesses of the gift wrap (docs/gift-wrap.md §6): the
 * parts that run once a cell inside w_run, static inline so that run.c
 * inlines them (as calls across files they cost a few per cent of a
 * deletion), and the narrow guess of guess.c.
 *
 * Owns: the dispatch of the wide guess (wrap_guess; its passes, scalar,
 * AVX2 and single precision, are geom/lift_pass.h's), and the known-neighbour lists that the narrow guesses take
 * their candidates from (w->adj, w->nadj: up to W_ADJ_CAP per local
 * number, none for a hub; the hubs listed in w->hubs): w_open_link starts them from the link
 * (w_adj_link), w_make_cell adds the edges of each new finite cell
 * (w_adj_edge).  The guess course of a facet is w_guess_apex, in run.c.
 *
 * Invariant: a guess is only a guess; each is proved or refuted (§7).
 * The lists hold the link's edges, which are edges of DT(S \ q), and the
 * edges of the fill cells made so far, which are if the guess is right;
 * a wrong candidate only makes a wrong guess.  Each list holds a
 * neighbour once.
 */
#ifndef DD_WRAP_GUESS_H
#define DD_WRAP_GUESS_H

#include "wrap/wrap_int.h"

/* The scalar pass of the guesses (dd_lift_least_ratio): of the points
 * ks[0..nk) (NULL: 0..nk), the one beyond the facet of pencil N, T (rows
 * from a) of least t/o, or W_TIE when two such quotients are equal;
 * *unsure: how many had unsure orientation.  O(nk).                     */
static inline uint32_t w_least_ratio(const struct dd_wrap *w, uint32_t a, const double N[4], const double T[4],
                                     const uint32_t *ks, uint32_t nk, uint32_t *unsure)
{
    return dd_lift_least_ratio(w->lift, a, N, T, w->oerr, ks, nk, unsure);
}

#ifdef W_AVX2
/* The lean guess in single precision (w->f32, dd_lift_guess_f32): a
 * point, W_BEHIND, or W_NONE (abstained: the guess is made in doubles).
 * Test builds answer a wrong point on one guess in 16 (W_F32_SPOIL),
 * which the proof must refute.                                          */
static inline uint32_t w_guess_f32(struct dd_wrap *w, uint32_t a, const double N[4], const double T[4])
{
    float *const *F = w_flift(w);                    /* and the scales */
    const uint32_t p = dd_lift_guess_f32(F, w->n, a, N, T, w->f32_sc);
    if (p < w->n && W_F32_SPOIL(w) && w->f32_kept % 16 == 15) return (p + 1 + w->f32_kept % 5) % w->n;
    return p;
}
#endif

/* The wide guess (docs §6 WIDE): the point beyond abc of least t/o, one
 * pass over the neighbours with no check, W_TIE on equal quotients;
 * W_NONE if none is beyond.  With AVX2 the lean pass where w->lean, in
 * single precision first where w->f32, else the full one; else scalar.
 * *unsure: 1 when points other than a, b, c had unsure orientations, 0
 * when none had, W_UNCOUNTED (the lean pass), W_SINGLE (chosen in single
 * precision, not yet known to be beyond).                               */
static inline uint32_t wrap_guess(struct dd_wrap *w, uint32_t a, const double N[4], const double T[4], int *unsure)
{
#ifdef W_AVX2
    if (w->lean && !w->narrow) {
        *unsure = W_UNCOUNTED;
        if (w->f32) {
            const uint32_t p = w_guess_f32(w, a, N, T);
            if (p == W_BEHIND) {                     /* w_run asks w_all_behind */
                w->f32_kept++;
                return W_NONE;
            }
            if (p != W_NONE) {
                w->f32_kept++;
                *unsure = W_SINGLE;
                return p;
            }
            w->f32_back++;
        }
        return dd_lift_guess_lean_avx2(w->lift, w->n, a, N, T, w->oerr);
    }
    if (w->avx2) return dd_lift_guess_avx2(w->lift, w->n, a, N, T, w->oerr, unsure);
#endif
    uint32_t uns;
    const uint32_t best = w_least_ratio(w, a, N, T, NULL, w->n, &uns);
    *unsure = uns != 3;                              /* a, b, c always are */
    return best;
}

/* ---- the known neighbours ---------------------------------------------- */

/* Appends v to k's known neighbours (a hub's list is left as it is); k
 * becomes a hub, listed in w->hubs once, when its list overflows.       */
static inline void w_adj_put(struct dd_wrap *w, uint32_t k, uint32_t v)
{
    uint8_t c = w->nadj[k];
    if (c < W_ADJ_CAP) w->adj[(size_t)k * W_ADJ_CAP + c] = v;
    else if (c == W_ADJ_CAP) w->hubs[w->nhubs++] = k;   /* at most n: once each */
    w->nadj[k] = c < W_ADJ_CAP ? (uint8_t)(c + 1) : W_ADJ_FULL;
}

/* The known neighbours that link triangle tr gives: each corner the next
 * one, between finite vertices (inf: the infinite vertex's number).     */
static inline void w_adj_link(struct dd_wrap *w, const uint32_t tr[3], uint32_t inf)
{
    for (int j = 0; j < 3; j++) {
        uint32_t u = tr[j == 2 ? 0 : j + 1];
        if (tr[j] != inf && u != inf) w_adj_put(w, tr[j], u);
    }
}

/* Whether v is among k's known neighbours (k not a hub).                */
static inline int w_adj_has(const struct dd_wrap *w, uint32_t k, uint32_t v)
{
    const uint32_t *l = w->adj + (size_t)k * W_ADJ_CAP;
    for (uint32_t i = 0; i < w->nadj[k]; i++)
        if (l[i] == v) return 1;
    return 0;
}

/* Records edge (k, v) of a new fill cell, unless known or between hubs.
 * O(W_ADJ_CAP).                                                         */
static inline void w_adj_edge(struct dd_wrap *w, uint32_t k, uint32_t v)
{
    if (w->nadj[k] == W_ADJ_FULL && w->nadj[v] == W_ADJ_FULL) return;
    if (w->nadj[k] != W_ADJ_FULL ? w_adj_has(w, k, v) : w_adj_has(w, v, k)) return;
    w_adj_put(w, k, v);
    w_adj_put(w, v, k);
}

/* guess.c: the narrow guess on finite facet (a, b, c), pencil m, N, T;
 * W_NONE: the wide guess decides.  Out of line: inlined, it made w_run's
 * common path, where it is not taken, dearer.                           */
uint32_t w_guess_narrow(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c, const double m[6],
                        const double N[4], const double T[4]);

#endif
