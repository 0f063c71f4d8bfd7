/*
 * wrap.h -- the cavity of a deleted vertex filled by gift wrapping: the
 * default strategy's fast path (variants/auto.c, gift_wrap.c), not an
 * algorithm of the paper.  docs/gift-wrap.md states the algorithm, why it
 * is correct and what it costs; src/wrap/wrap_int.h lists the files.
 *
 * The fill is exactly the one the other strategies build (the perturbed
 * DT(S \ q) inside the cavity): the wrap guesses it and keeps the guess
 * when it proves to be a triangulation of the cavity with every facet
 * locally Delaunay, and else finds it by certified scans.  On a weighted
 * t it is the perturbed regular fill, found in the lifted frame with the
 * star's hidden points among the sites (docs/gift-wrap.md §13).
 */
#ifndef DD_WRAP_H
#define DD_WRAP_H

#include "delete/delete.h"

/* Makes the fill of the cavity of d->q in the mesh (d->fill: over the
 * star's cells, then in new ones, glued to each other) and the sew's
 * matching (d->sew_out; d->fill_in_mesh); d->order holds d->nbr, in the
 * order that is the wrap's local numbering (weighted: then d->hpts, the
 * order rewritten so when there are hidden points).  It declines
 * (*declined = 1,
 * DD_OK, the mesh as it was, d->fill empty) when:
 *  - from 40 neighbours on, its exact tests pass their budget, or every
 *    guess is refuted and the neighbours are not all on one sphere;
 *  - a flat hull case its checks do not settle;
 *  - from wide_below neighbours on, no narrow guess holds and the
 *    neighbours are not cospherical (the wide guess is not tried);
 *  - from DD_WRAP_CODE_LEN - 1 neighbours on (no facet keys);
 *  - weighted: a flat hull facet with sites in its plane (§13).
 * (docs/gift-wrap.md §10.)  DD_ERR_INTERNAL, with a message and the mesh
 * as it was, if the fill does not close, which only a broken
 * triangulation causes; DD_ERR_NOMEM likewise.                          */
dd_status dd_wrap_fill(dd_del *d, uint32_t wide_below, int *declined);

struct dd_wrap;
void dd_wrap_free(struct dd_wrap *w);

/* Gift wrapping's statistics of a deletion, d->sstat[DD_WS_*] (named in
 * dd_delete_stats.strategy_name by dd_wrap_stat_names).                */
enum {
    DD_WS_COURSE,          /* DD_WRAP_*                                    */
    DD_WS_GUESS,           /* the last guess's candidates: DD_GUESS_*      */
    DD_WS_NARROW_REFUTED,  /* narrow guesses refuted before it             */
    DD_WS_INTEGER,         /* 1: integer lifts, every test of the scans
                              exact in doubles; 2: integer orientations
                              and cofactors, the in-sphere tests the
                              filter leaves exact in 128-bit integers     */
    DD_WS_SHIFT_GUESS,     /* the wide guess refuted, then made again on
                              shifted lifts (nearly cospherical points)  */
    DD_WS_SINGLE,          /* guesses answered in single precision         */
    DD_WS_SINGLE_BACK,     /* ... and made in doubles instead              */
    DD_WS_SINGLE_REFUTED,  /* a guess with single-precision answers was
                              refuted, then made again in doubles         */
    DD_WS_HULL_SINGLE,     /* hull steps found in single precision, proved */
    DD_WS_HULL_BACK,       /* ... and found in doubles instead             */
    DD_WS_EXPANSIONS,      /* tests left to the exact predicates           */
    DD_WS_COUNT
};
extern const char *const dd_wrap_stat_names[DD_WS_COUNT];

/* DD_WS_COURSE: how the wrap went.                                       */
enum {
    DD_WRAP_NONE,       /* not tried                                       */
    DD_WRAP_PROVED,     /* guessed fill proved Delaunay and kept           */
    DD_WRAP_REFUTED,    /* guessed fill refuted; the scans wrapped again   */
    DD_WRAP_SCANNED,    /* scans only (filters off: coordinates out of range) */
    DD_WRAP_DECLINED    /* left to the conflict DT                         */
};

/* DD_WS_GUESS: where the last guess took its candidates.                 */
enum {
    DD_GUESS_WIDE,      /* every neighbour                                 */
    DD_GUESS_SHORT,     /* the short lists of known neighbours             */
    DD_GUESS_TWO_STEP   /* those and their own lists                       */
};

/* The facet table's keys from 64 neighbours on (docs/gift-wrap.md §11):
 * word k of local number k, k < DD_WRAP_CODE_LEN, is (x_k, x_k^3, x_k^5)
 * in three 21-bit fields, x_k = alpha^k in GF(2^21), alpha a root of the
 * primitive x^21 + x^2 + 1: the parity-check columns of a binary BCH code
 * of designed distance 7, so the exclusive ors of two distinct sets of
 * three words differ.  A wrap declines from DD_WRAP_CODE_LEN - 1
 * neighbours on (the infinite vertex takes a word too).
 * Writes words from .. count - 1 into code; gf: the state, {1, 1, 1}
 * for from = 0, left for count.                                         */
#define DD_WRAP_CODE_LEN ((1u << 21) - 1)
void dd_wrap_code_words(uint64_t *code, uint32_t from, uint32_t count, uint32_t gf[3]);

#endif
