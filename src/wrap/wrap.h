/*
 * wrap.h -- a cavity filled by gift wrapping: the low-degree fast path of
 * auto.c, not an algorithm of the paper.
 *
 * The fill of q's cavity is exactly the set of cells of DT(P) (P = q's
 * neighbours, perturbed as CGAL does) in conflict with q, and these cells
 * tile the star of q.  So every link triangle abc, seen from q's side, is
 * a facet of exactly one fill cell abcp, where p is the point of P on
 * that side of abc whose sphere through a, b, c holds no other such point
 * (or the infinite vertex, when q is on the hull and no point is on that
 * side); the same holds for every facet between two fill cells.  Gift
 * wrapping finds the fill cell by cell from the link, with no conflict
 * test against q and no cell built that is not kept, where DT(x)_q builds
 * every cell of DT(x)_q(P_i) for every i: about five times the fill at
 * degree 15.
 *
 * The wrap first guesses, with no check, and keeps the guess when it
 * proves to be a triangulation of the cavity whose facets are all
 * locally Delaunay: then it is DT(S \ q)'s fill.  Otherwise the certified
 * scans wrap: each comparison filtered (wrap.c) and else decided by the
 * exact perturbed predicates of pred.c.  Either way the fill is exactly
 * the one the other strategies build.
 *
 * Cost: the wide guess scans P for each fill cell, O(d) lifted dot
 * products (four points at a time with AVX2), so O(d * |fill|), about
 * d^2: cheaper than the conflict DT, and than GRR below degree ~600.
 * Where the link has a hub (a vertex of more than 32 link neighbours: the
 * curves), narrow guesses come first, each cell's point taken among the
 * known neighbours of its facet's corners in DT(P): a few points a cell,
 * O(|fill|) in all, about 1.6-1.8 times a re-insertion on the curves at
 * every degree (wrap.c, w_guess_narrow).
 */
#ifndef DD_WRAP_H
#define DD_WRAP_H

#include "delete/delete.h"

/* Makes the fill of the cavity of d->q in the mesh (d->fill), over the
 * star's cells and past them in new ones, glued to each other, and the
 * sew's matching (d->sew_out; d->fill_in_mesh); d->order holds d->nbr
 * (its order is the wrap's local numbering).  It declines (*declined = 1, DD_OK; the
 * star written back and the new cells given back, the mesh as it was,
 * d->fill empty) for a cavity of 40 neighbours or more, not all on one
 * sphere, whose guess is refuted or whose exact tests pass the budget
 * (wrap.c, W_EXACT_FROM), for the flat hull cases that its checks do
 * not settle (every neighbour in one plane; wrap.c, W_BAIL), and from
 * DD_WRAP_CODE_LEN - 1 neighbours on (no keys for its facet table).  From
 * wide_below neighbours on it does not try the wide guess, so it
 * declines there too unless a narrow guess holds (or the neighbours are
 * cospherical: the scans, whose in-sphere tests are the perturbation's
 * alone).  Flat hull
 * faces are otherwise triangulated by the perturbation's coplanar rules
 * (wrap_scan_inf, w_flat_hull).
 * DD_ERR_INTERNAL (with a message) if the fill does not close, which only
 * a broken triangulation can cause (the mesh as it was as well).       */
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

/* The facet table's keys from 64 neighbours on (wrap.c, w_fkey): the
 * exclusive or of three words, one per local number k, k < 2^21 - 1.
 * Two distinct sets of three numbers have distinct keys: were they
 * equal, the set E of the numbers in one set and not the other (2, 4 or
 * 6 of them) would have sum over k in E of x_k^j = 0 for j = 1, 3, 5,
 * where word k is (x_k, x_k^3, x_k^5), x_k = alpha^k in GF(2^21), and
 * so for j = 2, 4, 6 too (squaring is additive in characteristic 2): a
 * Vandermonde system in at most six distinct nonzero x_k (alpha is
 * primitive: tests, wrap-code) with a nonzero solution, which has none.
 * (The words are the columns of the parity checks of a binary BCH code
 * of designed distance 7.)  So a wrap declines from DD_WRAP_CODE_LEN - 1
 * neighbours on, where the words run out.
 * Writes words from .. count - 1 into code; gf: the state, {1, 1, 1}
 * for from = 0, left for count.                                         */
#define DD_WRAP_CODE_LEN ((1u << 21) - 1)
void dd_wrap_code_words(uint64_t *code, uint32_t from, uint32_t count, uint32_t gf[3]);

#endif
