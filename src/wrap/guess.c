/*
 * guess.c -- the guesses of the gift wrap.
 */
#include "wrap/wrap_int.h"

/* The scalar pass of the guesses: of the points ks[0..nk) (NULL: 0..nk),
 * the one beyond the facet of pencil N, T (rows from a) of least t/o, or
 * W_TIE when two such quotients are equal; *unsure: how many had unsure
 * orientation.                                                          */
static inline uint32_t w_least_ratio(const struct dd_wrap *w, uint32_t a, const double N[4], const double T[4],
                                     const uint32_t *ks, uint32_t nk, uint32_t *unsure)
{
    double *const *L = w->lift;
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]}, oerr = w->oerr;
    double br = 1.0 / 0.0;
    uint32_t best = W_NONE, uns = 0;
    int tie = 0;
    for (uint32_t i = 0; i < nk; i++) {
        const uint32_t k = ks ? ks[i] : i;
        double P[4], ok = w_row_o(L, k, A, N, P);
        int pos = ok > oerr;
        uns += !pos & (ok >= -oerr);
        double r = pos ? w_t(P, T) / ok : 1.0 / 0.0;
        tie |= pos & (r == br);
        best = r < br ? k : best;
        br = r < br ? r : br;
    }
    *unsure = uns;
    return tie ? W_TIE : best;
}

/* The wide guess; *unsure: 1 when points other than a, b, c had unsure
 * orientations, 0 when none had, W_UNCOUNTED (the lean guess, on points
 * not of exact orientation from W_LEAN_FROM neighbours on and not in the
 * narrow guesses' course, see w_guess_lean_avx2), W_SINGLE (not counted
 * either, the point chosen in single precision, w_guess_f32, not yet
 * known to be beyond the facet).                                       */
static uint32_t wrap_guess(struct dd_wrap *w, uint32_t a, const double N[4], const double T[4], int *unsure)
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
        return w_guess_lean_avx2(w->lift, w->n, a, N, T, w->oerr);
    }
    if (w->avx2) return w_guess_avx2(w->lift, w->n, a, N, T, w->oerr, unsure);
#endif
    uint32_t uns;
    const uint32_t best = w_least_ratio(w, a, N, T, NULL, w->n, &uns);
    *unsure = uns != 3;                              /* a, b, c always are */
    return best;
}


/* Known neighbours.  The fill cell on facet abc is a cell of DT(S \ q),
 * so its point is a neighbour of a, b and c there.  Edges of DT(S \ q)
 * known during the wrap: the link's (they bound cells outside the
 * cavity) and those of the fill cells made so far.  Each point keeps its
 * known neighbours in a short list, or none once it has more than
 * W_ADJ_CAP (a hub).                                                   */


/* Whether v is among k's known neighbours (k not a hub).                */
static inline int w_adj_has(const struct dd_wrap *w, uint32_t k, uint32_t v)
{
    const uint32_t *l = w->adj + (size_t)k * W_ADJ_CAP;
    for (uint32_t i = 0; i < w->nadj[k]; i++)
        if (l[i] == v) return 1;
    return 0;
}

/* Records edge (k, v) of a new fill cell, unless known (or between hubs). */
void w_adj_edge(struct dd_wrap *w, uint32_t k, uint32_t v)
{
    if (w->nadj[k] == W_ADJ_FULL && w->nadj[v] == W_ADJ_FULL) return;
    if (w->nadj[k] != W_ADJ_FULL ? w_adj_has(w, k, v) : w_adj_has(w, v, k)) return;
    w_adj_put(w, k, v);
    w_adj_put(w, v, k);
}

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

/* The narrow guess on finite facet (a, b, c), pencil m, N, T: the least
 * t/o, as wrap_guess's, over candidates taken from the known neighbours,
 * the points of unsure orientation among them decided as there
 * (w_scan_exact on the same points).
 *  - DD_GUESS_SHORT: the lists of the corners that are at most 4s + 8
 *    long, s the shortest (a hub's are not used).  On the curves the
 *    wrap's order has met the edge from the cell's point to a corner of
 *    short list before nearly every cell: moment n = 128-1024, every cell
 *    with 2 candidates a facet; helix n = 4000-64000, degree 64-768, all
 *    but one cell in ~5000, with 2.4-4.6 candidates.
 *  - DD_GUESS_TWO_STEP: those lists and the lists of their points (that
 *    one cell: its point was a neighbour of the two hubs of its facet
 *    only, and of a neighbour of the third corner).
 * W_NONE when every corner is a hub or no candidate is beyond abc: the
 * wide guess (wrap_guess) decides that facet.  A wrong point only makes
 * the proof refute the guess.                                           */
static uint32_t w_guess_narrow(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c,
                               const double m[6], const double N[4], const double T[4])
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
    uint32_t nc = 0, bound = w->narrower ? s : 4 * s + 8;
    for (int i = 0; i < 3; i++)
        if (w->nadj[v[i]] <= bound) nc = w_take_list(w, v[i], nc);
    for (uint32_t i = 0, n1 = nc; w->narrow == DD_GUESS_TWO_STEP && !w->narrower && i < n1; i++)
        if (w->nadj[w->cand[i]] != W_ADJ_FULL) nc = w_take_list(w, w->cand[i], nc);
    uint32_t uns, best = w_least_ratio(w, a, N, T, w->cand, nc, &uns);   /* a, b, c not among them */
    if (best != W_NONE && best != W_TIE && uns) best = w_scan_exact(w, pr, a, b, c, m, best, 1, w->cand, nc);
    return best;
}

/* The guessed apex of finite open facet (a, b, e), pencil m, N, T
 * (w_pencil): the narrow guess (w->narrow), else the wide one
 * (wrap_guess); *single when single precision chose it.                  */
uint32_t w_guess_apex(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t e, const double m[6],
                      const double N[4], const double T[4], int on_hull, int *single)
{
    int unsure;
    uint32_t p = w->narrow ? w_guess_narrow(w, pr, a, b, e, m, N, T) : W_NONE;
    if (p != W_NONE) return p;
    p = wrap_guess(w, a, N, T, &unsure);
    *single = unsure == W_SINGLE;
    /* points of unsure orientation: decided exactly, each
     * beyond compared with the guess's choice               */
    if (unsure > 0 && p != W_TIE) p = w_scan_exact(w, pr, a, b, e, m, p, 1, NULL, w->n);
    /* None beyond: the exact scan says so of the unsure
     * points; without any, the guess's pass has shown every
     * point but a, b, c surely behind (o < -oerr, as
     * w_all_behind has it: the same o, bit for bit), which
     * makes abc a hull facet.  Testing that again took 8% of
     * a deletion on the helix (n = 1000, degree 32-47: 79
     * passes a deletion) and 2.4% at uniform degree 48-63;
     * the lean guess, not counting, has it tested.          */
    if (p == W_NONE && on_hull && (unsure >= 0 || w_all_behind(w, b, a, e, N, w->n))) p = w->n;
    return p;
}
