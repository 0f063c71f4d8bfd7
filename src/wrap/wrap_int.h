/*
 * wrap_int.h -- the gift wrap's internals, shared by the files of
 * src/wrap/ (docs/gift-wrap.md states the algorithm; §12 names the parts).
 *
 * Owns: struct dd_wrap, the wrap's state, kept in the deletion context
 * across deletions (no allocation once warm); the local numbering (q's
 * neighbours are 0 .. n-1 in d->order's order, the infinite vertex is n);
 * the sentinels and thresholds; and, static inline, what the hot loops of
 * several files share: the frame's pencil and tests on local numbers
 * (their arithmetic is geom/lift_pass.h's), the choice between the
 * scalar and AVX2 passes, the facet table's probes.
 *
 * Invariant: every sign the wrap acts on is certified, by a filter bound
 * of geom/lift.h (compared in geom/lift_pass.h), by exact integer
 * arithmetic, or by the exact predicates of src/geom/; what only ranks
 * candidates may round (§8).  The wrap evaluates nothing itself: o, t
 * and K . P come from geom/lift_pass.h, one sequence of operations on
 * every path, so that one bound covers every pass.
 *
 * The files: wrap.c the driver (dd_wrap_fill); run.c the wrap (w_run) and
 * the link; guess.h the guesses that w_run inlines, guess.c the narrow
 * guess; scan.c the certified scans and the perturbation on local
 * numbers; hull.c the hull step; lift.c the frame's rows and modes;
 * ftab.c the facet table and its keys.
 */
#ifndef DD_WRAP_INT_H
#define DD_WRAP_INT_H

#include "wrap/wrap.h"
#include "delete/delete.h"
#include "geom/lift_pass.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The AVX2 passes (geom/lift_simd.c, lift_f32.c), taken when the CPU
 * has AVX2 (w->avx2).                                                    */
#ifdef DD_LIFT_AVX2
#define W_AVX2 1
#endif

/* Answers of the scans and guesses that are not a local number.         */
#define W_NONE DD_LIFT_NONE       /* no point beyond the facet                */
#define W_BAIL (UINT32_MAX - 1)   /* a flat hull case the checks do not settle */
#define W_SHIFT (UINT32_MAX - 2)  /* try the shifted lifts, then scan again  */
#define W_TIE DD_LIFT_TIE         /* a guess between cospherical points      */
#define W_BEHIND DD_LIFT_BEHIND   /* single precision: every point behind     */

/* The exact-test budget (docs §10): from W_EXACT_FROM neighbours on, the
 * wrap declines once this deletion's exact tests (w_spent) pass 2n, and
 * after a refuted guess unless the neighbours are cospherical.  On
 * degenerate cavities the scans make about n^2/2 exact tests where the
 * conflict DT makes far fewer; below 40 neighbours the wrap stays ahead
 * even there (build/dtdel bench --dataset cosphere: the gift-wrap and
 * grr-neighbor rows by degree).                                          */
#define W_EXACT_FROM 40

/* The known neighbours of the narrow guesses (docs §6): up to W_ADJ_CAP
 * per local number, a list short enough to scan per edge (w_adj_has); a
 * vertex with more is a hub (W_ADJ_FULL) and keeps none.  A hub has more
 * than W_ADJ_CAP link neighbours, so there is none below W_NARROW_FROM
 * neighbours.  Narrow guesses are made only where the link has a hub (the
 * curves): elsewhere the fill has many new edges and a narrow guess is
 * refuted too often (build/dtdel bench --dataset bunny).                 */
#define W_ADJ_CAP 32
#define W_ADJ_FULL (W_ADJ_CAP + 1)
#define W_NARROW_FROM (W_ADJ_CAP + 2)

/* The lean wide guess from W_LEAN_FROM neighbours on (docs §6): the pass
 * skips the count of unsure orientations, which pays once passes are
 * long.  A point nearly in a facet's plane is hardly ever its apex on
 * generic points; where it is, the proof refutes the lean guess and the
 * full one follows (scripts/abbench.sh, uniform and bunny).              */
#define W_LEAN_FROM 24

/* wrap_guess's *unsure when its pass did not count: the lean guess, and
 * the single-precision one (whose point is not yet known to be beyond). */
enum { W_UNCOUNTED = -1, W_SINGLE = -2 };

/* A wrap's outcome (w_run, dd_wrap_fill): the fill made; the cavity left
 * to the conflict DT; the guessed cells are not the fill.                */
enum { W_DONE, W_DECLINED, W_WRONG_GUESS };

/* An entry of the facet table (ftab.c): a triangle's key (w_fkey) and its
 * facet record.                                                          */
struct w_fslot {
    uint64_t key;
    uint32_t rec, gen;            /* used iff gen == w->fs_gen            */
};

/* The wrap's state: arrays indexed by local number (grown, never shrunk),
 * the facet records and their table, the fill's cells, the known
 * neighbours, and the deletion's modes and counters.                    */
struct dd_wrap {
    uint32_t n, cap_n;            /* neighbours, capacity of the arrays  */
    const double **pt;            /* local -> point                       */
    double *lift[4];              /* lift[i][k]: coordinate i of
                                     (x_k - q, |x_k - q|^2), rounded      */
    double *o;                    /* scan scratch, per local number       */
    uint32_t *tmp;                /* w_lex_ranks' scratch                 */
    uint32_t *lexr;               /* lexicographic rank, per local number */
    int lex_ok;                   /* lexr made for this deletion          */
    double ierr, oerr;            /* the filters' error bounds (+inf: off) */
    double m;                     /* max |x_k - q_k| over the neighbours  */
    const double *q;
    /* weighted points (docs §13): the sites are q's neighbours, local
     * numbers below nlink, then the star's hidden points up to n        */
    uint32_t nlink;               /* n on an unweighted t                  */
    int wmode;                    /* the weighted lift holds: weights not
                                     all q's, or hidden points among the
                                     sites (w_lift); 0: the unweighted
                                     wrap, bit for bit                    */
    double *wgt;                  /* local -> weight (a weighted t)       */
    int wbig;                     /* weighted, and a weight difference
                                     beyond 1e3 m^2: no float lifts       */
    int shifted;                  /* the shifted lifts were tried         */
    int cosph;                    /* every neighbour on one sphere (the
                                     scans' in-sphere tests are all 0)   */
    int exact;                    /* integer lifts: every evaluation of
                                     the scans is exact (see w_lift)     */
    int oexact;                   /* every orientation o is exact         */
    int kexact;                   /* the cofactors K are exact integers
                                     (dd_lift_sign_kp)                          */
    int avx2, has_avx2;           /* wrap_guess uses AVX2; the CPU has it  */
    int has_fma;                  /* the CPU has FMA (dd_lift_guess_f32)    */
    int lean;                     /* the wide guess is the lean one       */
    int flift_ok;                 /* the float lifts may be used
                                     (w_flift): the lean guess and the hull
                                     step are made in single precision first */
    int f32;                      /* the lean guess is (w_guess_f32): off
                                     after a refuted guess                */
    float *flift[4];              /* the lifts in units of m (m^2 for the
                                     lift), rounded to floats             */
    dd_lift_f32_scale f32_sc;     /* the scales of N and T to those units */
    uint32_t f32_kept, f32_back;  /* single-precision guesses answered,
                                     and abstained (made in doubles)      */
    uint32_t inf_kept, inf_back;  /* hull steps of w_inf_f32 proved, and
                                     made in doubles (w_scan_inf)      */
    int f32_ready;                /* flift made for this deletion (w_flift) */
    uint32_t nexact;              /* tests the filters left to the exact
                                     predicates, this deletion            */
    uint64_t unf0;                /* the predicates' count of tests past
                                     their filters when the wrap began   */
    uint32_t *loc, cap_loc;       /* vertex id -> local number, valid for
                                     this deletion's neighbours only      */
    /* the facet table (w_fslot_of): triangle -> its facet record        */
    struct w_fslot *fs;
    uint32_t fs_alloc, fs_mask, fs_gen, fs_shift;
    uint64_t *code;               /* code[k]: local number k's word (w_fkey),
                                     made for k < ncode                   */
    uint32_t ncode;
    const uint64_t *kword;        /* the keys' words (w_fkey): w_bit_words,
                                     or code from 64 neighbours on        */
    uint32_t gf[3];               /* alpha^ncode, alpha^3ncode, alpha^5ncode */
    /* facet records */
    uint32_t (*tri)[3];           /* oriented triangle, local numbers     */
    uint32_t *own;                /* fill facet 4k+j (facet j of the k-th
                                     fill cell) on the other side, or
                                     W_NONE for a link triangle           */
    uint32_t *out;                /* a link triangle's mesh facet outside
                                     the cavity                           */
    uint8_t *closed;
    uint32_t *stack, nrec, cap_rec;
    uint32_t *lcell, cap_lcell;   /* the k-th fill cell's local numbers,
                                     4k..4k+3                             */
    uint32_t ncell0;              /* d->t->ncell when the wrap began      */
    uint32_t *keep;               /* the star's cells as they were, 8
                                     words each (w_keep_star)             */
    size_t cap_keep;
    /* the narrow guesses (w_guess_narrow) */
    int narrow;                   /* DD_GUESS_*: where this guess's
                                     candidates come from                 */
    uint32_t *adj;                /* adj[W_ADJ_CAP k ..]: known neighbours
                                     of k, in DT(S \ q)                   */
    uint8_t *nadj;                /* their number; W_ADJ_FULL: a hub      */
    uint32_t *seen, stamp;        /* seen[k] == stamp: k is a candidate   */
    uint32_t *cand;               /* the candidates of one facet          */
    uint32_t *hubs, nhubs;        /* the hubs, each once (w_adj_put), made
                                     with the lists (w_open_link)         */
    int hub_last;                 /* the last link asked had a hub        */
    uint32_t lead;                /* local number of the least vertex id  */
#ifdef DD_TEST_BUILD
    int narrower;                 /* DD_TEST_NARROWER: shortest lists only */
    int f32_spoil;                /* DD_TEST_SPOIL_SINGLE: answer wrong
                                     points in single precision          */
#endif
};

/* Test controls (dtdel_stats.h), in test builds only: W_TESTCTL(t, k)
 * is control k of triangulation t, W_NARROWER(w) and W_F32_SPOIL(w) the
 * wrap's copies of two of them; all 0 in release builds.               */
#ifdef DD_TEST_BUILD
#define W_TESTCTL(t, k) ((t)->testctl[k] != 0)
#define W_NARROWER(w) ((w)->narrower)
#define W_F32_SPOIL(w) ((w)->f32_spoil)
#else
#define W_TESTCTL(t, k) 0
#define W_NARROWER(w) 0
#define W_F32_SPOIL(w) 0
#endif

/* ---- called across files ------------------------------------------------ */

/* ftab.c: the facet table */
/* Makes the code words of local numbers below count (< DD_WRAP_CODE_LEN), once. */
dd_status w_code_reserve(struct dd_wrap *w, uint32_t count);
/* Empties the facet table, sized for about `expect` records; picks the keys' words. */
dd_status w_ftab_reset(struct dd_wrap *w, size_t expect);
/* Room for `more` more facet records, in the arrays and in the table. */
dd_status w_grow_recs(struct dd_wrap *w, size_t more);

/* lift.c: the frame */
/* Lifts the sites relative to (q, qw) (w->wgt on a weighted t) and sets the filters' bounds and modes. */
void w_lift(struct dd_wrap *w, const double *q, double qw, int weighted);
/* Switches to the shifted lifts when their bound is tighter (1), else keeps the lifts (0). */
int w_shift(struct dd_wrap *w);

/* scan.c: the certified scans */
/* The apex of finite open facet (a, b, c) by the certified scans; the infinite vertex on the hull. */
uint32_t w_scan_apex(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c, int on_hull);
/* The exact scan from `best` over ks[0..nk) (NULL: 0..nk); unsure_only: those of unsure orientation. */
uint32_t w_scan_exact(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c, const double m[6],
                      uint32_t best, int unsure_only, const uint32_t *ks, uint32_t nk);
/* w_conflicts where the filter abstains: exact, or the perturbation on local numbers. */
int w_conflicts_near(struct dd_wrap *w, dd_pred *pr, const uint32_t lv[4], const double K[4], const double P[4],
                     uint32_t y);
/* Whether every neighbour lies on one sphere, exactly (the first nlink records: the link). */
int w_cospherical(struct dd_wrap *w, dd_pred *pr, size_t nlink);

/* hull.c: the hull step */
/* The apex of open facet (a, b, INF) (certified), W_NONE, or W_BAIL. */
uint32_t w_scan_inf(struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b);
/* Whether every point before `end` but x, y, z is surely behind the plane of normal N through y. */
int w_all_behind(const struct dd_wrap *w, uint32_t x, uint32_t y, uint32_t z, const double N[4], uint32_t end);

/* run.c: the wrap */
/* Keeps the star's cells as they are, before w_run writes the fill over them. */
dd_status w_keep_star(dd_del *d, struct dd_wrap *w);
/* Drops the fill cells made so far: the mesh as it was. */
void w_drop_fill(dd_del *d, struct dd_wrap *w);
/* Opens the link triangles as the first records; *start: the record to wrap from. */
dd_status w_open_link(dd_del *d, struct dd_wrap *w, uint32_t *start, int *hub);
/* The wrap from record `start`, guessing or scanning; *outcome: W_DONE, W_DECLINED, W_WRONG_GUESS. */
dd_status w_run(dd_del *d, struct dd_wrap *w, int guess, uint32_t start, int *outcome);

/* ---- the pencil of a facet (docs §2) -------------------------------------
 * geom/lift_pass.h: with the rows B = L[b] - L[a], C = L[c] - L[a] and
 * P = L[p] - L[a] of the lifts, K(X) . P = det(B, C, X, P) is the
 * in-sphere determinant of a, b, c, x, p (negative: p inside the sphere
 * of the positively oriented a, b, c, x); N gives o(P) = N . P =
 * orient3d(a, b, c, p), T = K(N) gives t(P) = T . P, and w(X, P) |N|^2 =
 * o(X) t(P) - t(X) o(P): the apex of the fill cell beyond abc is the
 * point beyond it of least t/o.                                          */

/* Facet (a, b, c)'s pencil in the wrap's lifts (dd_lift_pencil). */
static inline void w_pencil(const struct dd_wrap *w, uint32_t a, uint32_t b, uint32_t c, double m[6],
                            double N[4], double T[4])
{
    dd_lift_pencil(w->lift, a, b, c, m, N, T);
}

/* The normal N of plane (a, b, c), rows from a (dd_lift_normal). */
static inline void w_normal(const struct dd_wrap *w, uint32_t a, uint32_t b, uint32_t c, double N[4])
{
    dd_lift_normal(w->lift, a, b, c, N);
}

/* ---- certified signs ---------------------------------------------------- */

/* The sign of orient3d(a, b, c, k) from its evaluation o = dd_lift_row_o:
 * the filter's answer, else 0 with integer orientations (o is exact),
 * else the exact predicate.                                              */
static inline int w_sign_o(const struct dd_wrap *w, dd_pred *pr, double o, uint32_t a, uint32_t b, uint32_t c,
                           uint32_t k)
{
    const int s = dd_lift_sure(o, w->oerr);
    if (s) return s;
    return w->oexact ? 0 : dd_orient3d(pr, w->pt[a], w->pt[b], w->pt[c], w->pt[k]);
}

/* orient3d(a, b, c, k), N being w_normal(a, b, c) (w_sign_o).           */
static inline int w_orient(const struct dd_wrap *w, dd_pred *pr, uint32_t a, uint32_t b, uint32_t c,
                           const double N[4], uint32_t k)
{
    double *const *L = w->lift;
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
    double P[4];
    return w_sign_o(w, pr, dd_lift_row_o(L, k, A, N, P), a, b, c, k);
}

/* Whether point y is in conflict with the positively oriented fill cell
 * lv = (a, b, c, p), K being the cofactors of L[p] - L[a] with abc's
 * minors: the filtered determinant (geom/lift.h's bound), else, out of
 * line, the exact perturbed test (w_conflicts_near).                    */
static inline int w_conflicts(struct dd_wrap *w, dd_pred *pr, const uint32_t lv[4], const double K[4], uint32_t y)
{
    double *const *L = w->lift;
    const uint32_t a = lv[0];
    const double P[4] = {L[0][y] - L[0][a], L[1][y] - L[1][a], L[2][y] - L[2][a], L[3][y] - L[3][a]};
    const double det = dd_lift_dot4(K, P);
    if (dd_lift_sure_pos(det, w->ierr)) return 0;
    if (dd_lift_sure_neg(det, w->ierr)) return 1;
    return w_conflicts_near(w, pr, lv, K, P, y);
}

/* The first k, from <= k < end, whose o to the plane of normal N through
 * a is unsure (|o| <= oerr) with `unsure`, else not surely behind (o >=
 * -oerr); end if none (dd_lift_next, dd_lift_next_avx2).  The passes
 * over points nearly all surely on one side look only at those:
 * w_all_behind, the Jarvis pass of w_scan_inf, the exact pass over a
 * guess's unsure points.  Cost O(end - from), four points a vector with
 * AVX2.                                                                  */
static inline uint32_t w_next_to(const struct dd_wrap *w, uint32_t a, const double N[4], uint32_t from,
                                 uint32_t end, int unsure)
{
#ifdef W_AVX2
    if (w->avx2) return dd_lift_next_avx2(w->lift, end, a, N, w->oerr, from, unsure);   /* lanes past end: end */
#endif
    double *const *L = w->lift;
    const double A[4] = {L[0][a], L[1][a], L[2][a], L[3][a]};
    return dd_lift_next(L, A, N, w->oerr, from, end, unsure);
}

/* w_next_to up to n.                                                    */
static inline uint32_t w_next(const struct dd_wrap *w, uint32_t a, const double N[4], uint32_t from, int unsure)
{
    return w_next_to(w, a, N, from, w->n, unsure);
}

/* ---- the facet table (ftab.c) ------------------------------------------- */

/* A triangle's key: the exclusive or of its corners' words (ftab.c).    */
static inline uint64_t w_fkey(const struct dd_wrap *w, uint32_t a, uint32_t b, uint32_t c)
{
    return w->kword[a] ^ w->kword[b] ^ w->kword[c];
}

/* The slot of key `key`, or the empty slot where it would go (linear
 * probing from the top bits of a multiplicative hash).                  */
static inline struct w_fslot *w_fprobe(const struct dd_wrap *w, uint64_t key)
{
    uint32_t i = (uint32_t)((key * 0x9E3779B97F4A7C15ull) >> w->fs_shift);   /* the top bits */
    while (w->fs[i].gen == w->fs_gen && w->fs[i].key != key) i = (i + 1) & w->fs_mask;
    return &w->fs[i];
}

/* The entry of the triangle of key `key` (w_fkey): *found = 1 and its
 * record, or a new entry (*found = 0) that w_open fills.  The table has
 * room (w_reserve_recs).                                                */
static inline uint32_t *w_fslot_of(struct dd_wrap *w, uint64_t key, int *found)
{
    struct w_fslot *e = w_fprobe(w, key);
    *found = e->gen == w->fs_gen;
    if (!*found) *e = (struct w_fslot){key, W_NONE, w->fs_gen};
    return &e->rec;
}

/* Room for `more` more facet records, in the arrays and in the table
 * (at most a quarter full, ftab.c); inline but for the growth, as w_run
 * asks once a cell.                                                      */
static inline dd_status w_reserve_recs(struct dd_wrap *w, size_t more)
{
    return w->nrec + more <= w->cap_rec && 4 * (w->nrec + more) <= w->fs_mask + 1 ? DD_OK : w_grow_recs(w, more);
}

/* Opens triangle (a, b, c), whose other side is fill facet `own` (W_NONE:
 * a link triangle), as a new record; *val is its entry (w_fslot_of).    */
static inline void w_open(struct dd_wrap *w, uint32_t *val, uint32_t a, uint32_t b, uint32_t c, uint32_t own)
{
    uint32_t r = w->nrec++;
    w->tri[r][0] = a; w->tri[r][1] = b; w->tri[r][2] = c;
    w->own[r] = own;
    w->closed[r] = 0;
    *val = r;
}

/* ---- the float lifts, the budget ---------------------------------------- */

/* The float lifts (dd_lift_f32_rows), made at their first use in a
 * deletion: links where the narrow guesses hold and no hull step is
 * taken never pay for them.                                              */
static inline float *const *w_flift(struct dd_wrap *w)
{
    if (!w->f32_ready) {
        w->f32_sc = dd_lift_f32_rows(w->lift, w->n, w->m, w->flift);
        w->f32_ready = 1;
    }
    return w->flift;
}

/* The predicates' tests past their filters so far (pred.h).             */
static inline uint64_t w_unfiltered(const dd_pred *pr)
{
    return pr->orient_exact + pr->insphere_exact;
}

/* This deletion's exact tests, for W_EXACT_FROM's budget: those past the
 * predicates' filters, and one in 16 of the others the wrap left to the
 * predicates, whose own filters settle most of them at about a sixteenth
 * of the cost.                                                          */
static inline uint64_t w_spent(const struct dd_wrap *w, const dd_pred *pr)
{
    return w_unfiltered(pr) - w->unf0 + w->nexact / 16;
}

#endif
