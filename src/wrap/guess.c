/*
 * guess.c -- the narrow guesses of the gift wrap (docs/gift-wrap.md §6):
 * the apex of a facet taken among the known neighbours of its corners
 * (guess.h), a few candidates a cell where the link has a hub.
 *
 * Owns: the candidates of a facet (w->cand, marked in w->seen by stamp).
 *
 * Invariant: the candidates are distinct and none is a corner of the
 * facet; a narrow guess is only a guess, proved or refuted with the rest
 * of the guessed fill (§7).
 */
#include "wrap/guess.h"

/* Adds candidates: the known neighbours of k not seen yet.              */
static inline uint32_t w_take_list(struct dd_wrap *w, uint32_t k, uint32_t nc)
{
    const uint32_t *l = w->adj + (size_t)k * W_ADJ_CAP, st = w->stamp;
    for (uint32_t j = 0; j < w->nadj[k]; j++)
        if (w->seen[l[j]] != st) {
            w->seen[l[j]] = st;
            w->cand[nc++] = l[j];
        }
    return nc;
}

/* The narrow guess on finite facet (a, b, c), pencil m, N, T (docs §6
 * NARROW): the least t/o, as wrap_guess's, over candidates taken from the
 * known neighbours, its points of unsure orientation decided exactly
 * among the same candidates (w_scan_exact).
 *  - DD_GUESS_SHORT: the lists of the corners at most 4s + 8 long, s the
 *    shortest (a hub has none).  On the curves the depth-first wrap has
 *    nearly always met the edge from the apex to a corner of short list.
 *  - DD_GUESS_TWO_STEP: those lists and the lists of their points, for an
 *    apex that is a neighbour of its facet's hubs only and of a neighbour
 *    of the third corner.
 * Either way the hubs (w->hubs) are candidates too: a hub keeps no list,
 * so an apex that is a hub is found only where a short list knows it,
 * and on the curves the next cell round a hub's edge often has one more
 * hub (q's neighbours along the curve) as its apex.
 * W_NONE when every corner is a hub or no candidate is beyond abc: the
 * wide guess decides that facet.  O(candidates).                         */
uint32_t w_guess_narrow(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c, const double m[6],
                        const double N[4], const double T[4])
{
    const uint32_t v[3] = {a, b, c};
    uint32_t s = W_ADJ_FULL;
    for (int i = 0; i < 3; i++)
        if (w->nadj[v[i]] < s) s = w->nadj[v[i]];
    if (s == W_ADJ_FULL) return W_NONE;
    if (++w->stamp == 0) {                           /* wrapped round: clear */
        memset(w->seen, 0, w->n * sizeof *w->seen);
        w->stamp = 1;
    }
    w->seen[a] = w->seen[b] = w->seen[c] = w->stamp;
    uint32_t nc = 0, bound = W_NARROWER(w) ? s : 4 * s + 8;
    for (int i = 0; i < 3; i++)
        if (w->nadj[v[i]] <= bound) nc = w_take_list(w, v[i], nc);
    for (uint32_t i = 0, n1 = nc; w->narrow == DD_GUESS_TWO_STEP && !W_NARROWER(w) && i < n1; i++)
        if (w->nadj[w->cand[i]] != W_ADJ_FULL) nc = w_take_list(w, w->cand[i], nc);
    for (uint32_t i = 0; i < w->nhubs && !W_NARROWER(w); i++)   /* the hubs, a few */
        if (w->seen[w->hubs[i]] != w->stamp) {
            w->seen[w->hubs[i]] = w->stamp;
            w->cand[nc++] = w->hubs[i];
        }
    for (uint32_t k = w->nlink; k < w->n; k++)      /* the hidden sites (docs §13), a few */
        if (w->seen[k] != w->stamp) w->cand[nc++] = k;
    uint32_t uns, best = w_least_ratio(w, a, N, T, w->cand, nc, &uns);   /* a, b, c not among them */
    if (best != W_NONE && best != W_TIE && uns) best = w_scan_exact(w, pr, a, b, c, m, best, 1, w->cand, nc);
    return best;
}
