/*
 * run.c -- the wrap (docs/gift-wrap.md §3 WRAP): the link triangles
 * opened as the first facet records, then the fill cells found one at a
 * time from the open facets, made in the mesh and glued to each other.
 *
 * Owns: the facet records (w->tri, own, out, closed, stack), the fill's
 * cells in local numbers (w->lcell), the star's cells kept aside
 * (w->keep), and the matching handed to the sew (d->sew_out).
 *
 * Invariant: the k-th fill cell (d->fill.a[k]) is written over the k-th
 * star cell and, past the star, into new cells, and nothing outside the
 * cavity points at a fill cell before the sew, so w_drop_fill restores
 * the mesh exactly as it was, whatever a wrap did.  An open record has
 * its unknown cell on its positive side; a triangle bounds at most two
 * cells; a link triangle is closed at most once.  The start facet
 * depends on vertex ids only, so a deletion repeated is the same
 * computation.
 */
#include "wrap/guess.h"

/* The error of a wrap that cannot close, which only a broken
 * triangulation makes (the caller restores the mesh).                   */
static dd_status w_broken(dd_del *d, const char *what)
{
    return dd_fail(d->t, DD_ERR_INTERNAL, "gift wrapping the cavity of point %u: %s", d->t->v2in[d->q], what);
}

/* Room for `room` fill cells in all, `made` of them made already (in the
 * star's cells, then in new ones): cells in the mesh, d->fill,
 * d->sew_out and w->lcell.                                              */
static dd_status w_reserve_fill(dd_del *d, struct dd_wrap *w, size_t made, size_t room)
{
    const size_t S = d->star.n, more = (room > S ? room - S : 0) - (made > S ? made - S : 0);
    dd_status s = dd_reserve_cells(d->t, (uint32_t)more);
    if (s == DD_OK) s = dd_vec_reserve(&d->fill, room);
    if (s == DD_OK) s = dd_vec_reserve(&d->sew_out, 4 * room);
    if (s == DD_OK && 4 * room > w->cap_lcell) {
        if (dd_grow(&w->lcell, 4 * room, sizeof *w->lcell)) return DD_ERR_NOMEM;
        w->cap_lcell = (uint32_t)(4 * room);
    }
    return s;
}

/* Keeps the star's cells as they are (w->keep), before w_run writes the
 * fill over them.                                                      */
dd_status w_keep_star(dd_del *d, struct dd_wrap *w)
{
    const size_t words = DD_CELL_WORDS * d->star.n;
    if (words > w->cap_keep) {
        if (dd_grow(&w->keep, words, sizeof *w->keep)) return DD_ERR_NOMEM;
        w->cap_keep = words;
    }
    for (size_t k = 0; k < d->star.n; k++)
        memcpy(w->keep + DD_CELL_WORDS * k, dd_tv(d->t, d->star.a[k]), DD_CELL_WORDS * sizeof *w->keep);
    return DD_OK;
}

/* Drops the fill cells made so far (w_run): the star's cells written
 * back, the cells made past them given back (dd_unmake_cells), the mesh
 * as it was.                                                           */
void w_drop_fill(dd_del *d, struct dd_wrap *w)
{
    const size_t S = d->star.n, F = d->fill.n;
    for (size_t k = 0; k < F && k < S; k++)
        memcpy(dd_tv(d->t, d->star.a[k]), w->keep + DD_CELL_WORDS * k, DD_CELL_WORDS * sizeof *w->keep);
    if (F > S) dd_unmake_cells(d->t, d->fill.a + S, F - S, w->ncell0);
    d->fill.n = 0;
}

/* Opens the link triangles, oriented towards q (their other side: the
 * mesh facet outside the cavity), as the first records, all in the
 * table, and returns the record to wrap from, *start: of the triangles
 * through `lead` (for a hull vertex the infinite vertex, so that the
 * first step is the hull step and a flat hull bails before any other
 * work; else the neighbour of least vertex id), the one whose other
 * corners have the least ids, rotated to begin with its least id.  The
 * choice goes by vertex ids, not local numbers, so the wrap does not
 * depend on how the star was stored.  With hub not NULL it also starts
 * the known-neighbour lists from the link's edges (each triangle gives
 * each finite corner its successor: the link is a closed oriented
 * surface, so each neighbour comes once) and sets *hub when the link has
 * a hub.  Drops the fill made so far first.  O(d).                        */
dd_status w_open_link(dd_del *d, struct dd_wrap *w, uint32_t *start, int *hub)
{
    dd_tri *t = d->t;
    const uint32_t n = w->n, inf = n;
    w_drop_fill(d, w);   /* d->qdt is not reset: the wrap uses only its predicates */
    w->nrec = 0;
    /* Sized for 6n records: a wrap opens about 3n to 5n, the link's
     * included (docs §11), so the table seldom grows in a wrap.          */
    dd_status s = w_ftab_reset(w, 6 * (size_t)n);
    if (s != DD_OK) return s;
    if ((s = w_reserve_recs(w, d->star.n)) != DD_OK) return s;
    if (hub) {
        memset(w->nadj, 0, n * sizeof *w->nadj);
        w->nhubs = 0;
    }
    const int puts = hub && w->hub_last;             /* else count them (see below) */
    uint64_t kmin = UINT64_MAX;
    uint32_t rmin = 0;
    const uint32_t *gid = d->order.a;                /* gid[inf] = DD_INF, above all */
    /* The start is a triangle through `lead`: for a hull vertex the
     * infinite vertex, else the neighbour of least id (each neighbour is
     * a corner of the link).                                             */
    const uint32_t lead = d->on_hull ? inf : w->lead;
    /* Every vertex of a star cell but q is a neighbour (collect_star), so
     * w->loc holds the local number of each finite link vertex.         */
    for (size_t k = 0; k < d->star.n; k++) {
        uint32_t c = d->star.a[k];
        const uint32_t *v = dd_tv(t, c);
        const uint32_t i = dd_slot_of(v, d->q);
        uint32_t lv[3];
        for (int j = 0; j < 3; j++) {
            uint32_t g = v[dd_facet[i][j]];
            lv[j] = g == DD_INF ? inf : w->loc[g];
        }
        if (puts)
            w_adj_link(w, lv, inf);
        else if (hub)
            for (int j = 0; j < 3; j++) {
                uint32_t u = lv[j == 2 ? 0 : j + 1];
                if (lv[j] != inf && u != inf) w->nadj[lv[j]] = (uint8_t)(w->nadj[lv[j]] + (w->nadj[lv[j]] < W_ADJ_FULL));
            }
        int found;
        uint32_t *val = w_fslot_of(w, w_fkey(w, lv[0], lv[1], lv[2]), &found);
        if (found) return w_broken(d, "a link triangle appears twice");
        if ((lv[0] == lead) | (lv[1] == lead) | (lv[2] == lead)) {
            /* the ids of the other two corners (the lead's own is the largest
             * of the three, DD_INF, or the least): least, then largest */
            uint32_t g0 = gid[lv[0]], g1 = gid[lv[1]], g2 = gid[lv[2]];
            dd_sort3u(&g0, &g1, &g2);
            uint64_t key = lead == inf ? (uint64_t)g0 << 32 | g1 : (uint64_t)g1 << 32 | g2;
            if (key < kmin) { kmin = key; rmin = w->nrec; }
        }
        w->out[w->nrec] = dd_tn(t, c)[(uint32_t)i];
        w_open(w, val, lv[0], lv[1], lv[2], W_NONE);
    }
    if (w->nrec == 0) return w_broken(d, "no link triangle");
    if (hub) {
        /* Unless the last link had a hub, the loop only counted the puts
         * (cheaper where links have none, as on uniform points); where a
         * count shows a hub, the lists are made here, from the records.  */
        *hub = 0;
        for (uint32_t k = 0; k < n && !*hub; k++) *hub = w->nadj[k] == W_ADJ_FULL;
        if (*hub && !puts) {                     /* the lists, from the records */
            memset(w->nadj, 0, n * sizeof *w->nadj);
            w->nhubs = 0;
            for (uint32_t r = 0; r < w->nrec; r++) w_adj_link(w, w->tri[r], inf);
        }
        w->hub_last = *hub;
    }
    uint32_t *st = w->tri[rmin];
    while (gid[st[0]] > gid[st[1]] || gid[st[0]] > gid[st[2]]) {   /* rotate: same orientation */
        uint32_t x0 = st[0];
        st[0] = st[1]; st[1] = st[2]; st[2] = x0;
    }
    *start = rmin;
    return DD_OK;
}

/* Whether (a, b, c) is a rotation of triangle r: the same orientation.  */
static inline int w_same_turn(const uint32_t r[3], uint32_t a, uint32_t b)
{
    return ((r[0] == a) & (r[1] == b)) | ((r[1] == a) & (r[2] == b)) | ((r[2] == a) & (r[0] == b));
}

/* The arrays of the cell being made, which the tests read in place.  Its
 * corners are in w_wrapping as scalars too: read from lv, they would be
 * loaded again after each store to the mesh or the records (which might
 * alias lv, whose address the tests take).                              */
struct w_cell {
    uint32_t lv[4];               /* (a, b, e, p), as in w_wrapping       */
    double mb[6], N[4], T[4];     /* abc's pencil (w_pencil), guessing    */
    double K[4];                  /* the cell's cofactors (w_conflicts)   */
};

/* One wrap in progress (w_run): its course, the open records on
 * w->stack, and the cell being made (its arrays in *c).                 */
struct w_wrapping {
    dd_del *d;
    struct dd_wrap *w;
    dd_pred *pr;                  /* the predicates and their counters    */
    struct w_cell *c;
    int guess;                    /* guessing, or scanning                */
    uint32_t ns;                  /* open records on w->stack             */
    uint32_t nlink;               /* link triangles closed                */
    size_t room, limit;           /* fill cells reserved; at most         */
    const char *why;              /* what was wrong (W_WRONG_GUESS)       */
    uint32_t a, b, e, p;          /* the cell being made: p, the apex of
                                     facet abe (local numbers)            */
    uint32_t m;                   /* the new cell in the mesh             */
    size_t fp;                    /* its index in d->fill                 */
    uint32_t *tn, *so;            /* its neighbours, its sew_out entries  */
    int finite;                   /* no corner is the infinite vertex     */
    int check;                    /* guessed and finite: CHECK it (§7)    */
    int single;                   /* p chosen in single precision         */
};

/* The outcome W_WRONG_GUESS, and why: the cells do not make the fill.
 * For a guess that refutes it; for the scans it is an internal error
 * (w_run).                                                               */
static int w_wrong(struct w_wrapping *x, const char *why)
{
    x->why = why;
    return W_WRONG_GUESS;
}

/* The guessed apex of finite open facet (a, b, e), whose pencil is in x
 * (docs/gift-wrap.md §6 GUESS): the narrow guess (w->narrow), else the
 * wide one, its points of unsure orientation decided exactly and
 * compared with its choice; the infinite vertex for a hull vertex's
 * facet with every other point behind it.  x->single: the wide guess
 * chose in single precision (checked in w_make_cell).                   */
static inline uint32_t w_guess_apex(struct w_wrapping *x, uint32_t a, uint32_t b, uint32_t e)
{
    struct dd_wrap *w = x->w;
    int unsure;
    uint32_t p = w->narrow ? w_guess_narrow(w, x->pr, a, b, e, x->c->mb, x->c->N, x->c->T) : W_NONE;
    if (p != W_NONE) return p;
    p = wrap_guess(w, a, x->c->N, x->c->T, &unsure);
    x->single = unsure == W_SINGLE;
    if (unsure > 0 && p != W_TIE) p = w_scan_exact(w, x->pr, a, b, e, x->c->mb, p, 1, NULL, w->n);
    /* None beyond: the exact scan says so of the unsure points; with
     * none, the pass itself showed every point but a, b, e surely behind
     * (its o is w_all_behind's, bit for bit); a pass that did not count
     * them (the lean and single-precision guesses) leaves that to
     * w_all_behind.                                                      */
    if (p == W_NONE && x->d->on_hull && (unsure >= 0 || w_all_behind(w, b, a, e, x->c->N, w->n))) p = w->n;
    return p;
}

/* Picks the apex p of the open facet of record r, and sets x's cell to
 * (a, b, e, p): through the infinite vertex, rotated to (a, b, INF), by
 * the hull step; else by the guesses or the certified scans.  W_DECLINED
 * when the exact-test budget is spent (W_EXACT_FROM) or the hull step
 * bails (W_BAIL); W_WRONG_GUESS when no apex was found.                  */
static int w_pick_apex(struct w_wrapping *x, uint32_t r)
{
    struct dd_wrap *w = x->w;
    const uint32_t n = w->n, inf = n;
    uint32_t a = w->tri[r][0], b = w->tri[r][1], e = w->tri[r][2], p;
    x->single = 0;
    if (n >= W_EXACT_FROM && w_spent(w, x->pr) > 2 * (uint64_t)n) return W_DECLINED;
    if (a == inf || b == inf || e == inf) {
        while (e != inf) {                          /* rotate: same orientation */
            const uint32_t a0 = a;
            a = b; b = e; e = a0;
        }
        p = w_scan_inf(w, x->pr, a, b);
    } else if (x->guess) {
        w_pencil(w, a, b, e, x->c->mb, x->c->N, x->c->T);
        p = w_guess_apex(x, a, b, e);
    } else {
        p = w_scan_apex(w, x->pr, a, b, e, x->d->on_hull);
    }
    if (p >= W_TIE)                                 /* W_TIE, W_BAIL, W_NONE */
        return p == W_BAIL ? W_DECLINED : w_wrong(x, "an open facet has no point beyond it");
    x->a = x->c->lv[0] = a;
    x->b = x->c->lv[1] = b;
    x->e = x->c->lv[2] = e;
    x->p = x->c->lv[3] = p;
    x->finite = a != inf && b != inf && e != inf && p != inf;
    x->check = x->guess && x->finite;
    return W_DONE;
}

/* Whether the guessed cell is locally Delaunay across fill facet `own`
 * (4k + j: facet j of the k-th fill cell, W_NONE: none), docs §3 CHECK:
 * the apex of a finite cell there is not in conflict with it.  Always
 * for the scans and infinite cells.                                     */
static inline int w_delaunay_across(struct w_wrapping *x, uint32_t own)
{
    struct dd_wrap *w = x->w;
    return !(x->check && own != W_NONE && w->lcell[own] != w->n &&
             w_conflicts(w, x->pr, x->c->lv, x->c->K, w->lcell[own]));
}

/* Glues facet j of the new cell to the other side of record r: a facet
 * of an earlier fill cell, or, for a link triangle, nothing yet (the
 * sew glues d->sew_out's outside facet).                                 */
static inline void w_glue(struct w_wrapping *x, uint32_t r, uint32_t j)
{
    struct dd_wrap *w = x->w;
    const uint32_t own = w->own[r];
    if (own != W_NONE) {
        const uint32_t f = 4 * x->d->fill.a[own >> 2] + (own & 3);
        x->tn[j] = f;
        *dd_fn(x->d->t, f) = 4 * x->m + j;
        x->so[j] = DD_NONE;
    } else {
        x->tn[j] = DD_NONE;
        x->so[j] = w->out[r];
        x->nlink++;
    }
}

/* Room for one more fill cell (d->fill, the mesh, d->sew_out, lcell) and
 * for its three new facet records.                                     */
static dd_status w_reserve_cell(struct w_wrapping *x)
{
    if (x->d->fill.n == x->room) {
        x->room *= 2;
        dd_status s = w_reserve_fill(x->d, x->w, x->d->fill.n, x->room);
        if (s != DD_OK) return s;
    }
    return w_reserve_recs(x->w, 3);
}

/* Whether no hidden site (local numbers nlink .. n-1, none on an
 * unweighted t) but the cell's corners is in conflict with x's guessed
 * finite cell, its cofactors made (docs §13): local regularity proves
 * the fill the regular triangulation of its vertices; this proves that
 * the sites left out stay hidden.  O(hidden sites), filtered.          */
static inline int w_empty_of_hidden(struct w_wrapping *x)
{
    struct dd_wrap *w = x->w;
    for (uint32_t k = w->nlink; k < w->n; k++)
        if (k != x->a && k != x->b && k != x->e && k != x->p && w_conflicts(w, x->pr, x->c->lv, x->c->K, k)) return 0;
    return 1;
}

/* Makes x's cell in the mesh, the next fill cell: over the next star
 * cell, past the star in a new one (the star is in w->keep), and closes
 * the facet of record r with it (facet 3, opposite the apex).  A guessed
 * finite cell gets its cofactors K, and must have a single-precision
 * apex surely beyond its facet and be locally Delaunay across r; else,
 * or when the fill outgrows O(n^2) cells, W_WRONG_GUESS.               */
static int w_make_cell(struct w_wrapping *x, uint32_t r)
{
    dd_del *d = x->d;
    struct dd_wrap *w = x->w;
    const uint32_t a = x->a, b = x->b, e = x->e, p = x->p, *gid = d->order.a;
    x->fp = d->fill.n;
    if (x->fp >= x->limit) return w_wrong(x, "the fill does not close");
    x->m = x->fp < d->star.n ? d->star.a[x->fp] : dd_new_cell(d->t);
    d->fill.a[d->fill.n++] = x->m;                  /* at once: w_drop_fill */
    uint32_t *tv = dd_tv(d->t, x->m), *lc = w->lcell + 4 * x->fp;
    x->tn = dd_tn(d->t, x->m);
    x->so = d->sew_out.a + 4 * x->fp;
    tv[0] = gid[a]; tv[1] = gid[b]; tv[2] = gid[e]; tv[3] = gid[p];   /* gid[n] = DD_INF */
    lc[0] = a; lc[1] = b; lc[2] = e; lc[3] = p;
    if (w->narrow && x->finite) {
        w_adj_edge(w, p, a);
        w_adj_edge(w, p, b);
        w_adj_edge(w, p, e);
    }
    if (x->check) {
        double *const *L = w->lift;
        const double X[4] = {L[0][p] - L[0][a], L[1][p] - L[1][a], L[2][p] - L[2][a], L[3][p] - L[3][a]};
        dd_lift_vcofactors(x->c->K, X, x->c->mb);
        /* o as dd_lift_row_o has it; the other guesses' apexes are beyond already */
        if (x->single && !dd_lift_sure_pos(dd_lift_o(X, x->c->N), w->oerr)) return w_wrong(x, "");
        if (!w_empty_of_hidden(x)) return w_wrong(x, "");
    }
    if (!w_delaunay_across(x, w->own[r])) return w_wrong(x, "");
    w_glue(x, r, 3);
    return W_DONE;
}

/* Closes or opens the other three facets of the new cell: a facet whose
 * triangle has a record closes it (the record open, on the cell's side,
 * and, guessing, locally Delaunay), else it is opened outwards and
 * pushed.  W_WRONG_GUESS when a triangle would bound three cells or is
 * met from the wrong side, or a guess is not locally Delaunay.          */
static int w_close_or_open(struct w_wrapping *x)
{
    struct dd_wrap *w = x->w;
    const uint32_t lv[4] = {x->a, x->b, x->e, x->p};
    uint64_t key[3];                                /* facet j's: the cell's less lv[j] */
    const uint64_t *kw = w->kword, set = kw[lv[0]] ^ kw[lv[1]] ^ kw[lv[2]] ^ kw[lv[3]];
    for (uint32_t j = 0; j < 3; j++) key[j] = set ^ kw[lv[j]];
    for (uint32_t j = 0; j < 3; j++) {
        const uint32_t f0 = lv[dd_facet[j][0]], f1 = lv[dd_facet[j][1]], f2 = lv[dd_facet[j][2]];
        int found;
        uint32_t *val = w_fslot_of(w, key[j], &found);
        if (!found) {
            x->tn[j] = DD_NONE;
            x->so[j] = DD_NONE;
            w->stack[x->ns++] = w->nrec;
            w_open(w, val, f1, f0, f2, 4 * (uint32_t)x->fp + j);   /* reversed: open outwards */
            continue;
        }
        const uint32_t o = *val;
        if (w->closed[o]) return w_wrong(x, "a triangle bounds three cells");
        if (!w_same_turn(w->tri[o], f0, f1)) return w_wrong(x, "a triangle is met from the wrong side");
        if (!w_delaunay_across(x, w->own[o])) return w_wrong(x, "");
        w->closed[o] = 1;
        w_glue(x, o, j);
    }
    return W_DONE;
}

/* Ends the wrap with outcome o: *outcome, but for cells that are not
 * the fill while scanning, which only a broken triangulation makes:
 * DD_ERR_INTERNAL, with x->why.                                         */
static dd_status w_end(const struct w_wrapping *x, int o, int *outcome)
{
    if (o == W_WRONG_GUESS && !x->guess) return w_broken(x->d, x->why);
    *outcome = o;
    return DD_OK;
}

/* The wrap from record `start` (docs/gift-wrap.md §3 WRAP): pop an open
 * facet, pick its apex, make the cell, close or open its other facets;
 * at the end, every link triangle must be closed.  The k-th fill cell
 * (d->fill.a[k]) is written over the k-th star cell (kept in w->keep),
 * past the star in new cells; a record's `own` is facet 4k + j of the
 * k-th.  Each facet of a cell goes to d->sew_out for the sew: a link
 * triangle's outside facet, or DD_NONE inside the fill.  Nothing outside
 * the cavity reaches these cells before the sew, so w_drop_fill undoes
 * them.  *outcome: W_DONE; W_DECLINED (the budget, or the hull step
 * bailed); W_WRONG_GUESS (guessing: the cells are not the fill).  While
 * scanning, cells that are not the fill mean a broken triangulation:
 * DD_ERR_INTERNAL.  Cost: docs §9.                                      */
dd_status w_run(dd_del *d, struct dd_wrap *w, int guess, uint32_t start, int *outcome)
{
    struct w_cell c;
    struct w_wrapping x = {.d = d, .w = w, .pr = &d->qdt->pred, .c = &c, .guess = guess,
                           .room = 4 * (size_t)w->n + 16,                  /* grown by w_reserve_cell */
                           .limit = 8 * (size_t)w->n * w->n + 64};         /* |fill| is O(n^2) */
    dd_status s = w_reserve_fill(d, w, 0, x.room);
    if (s != DD_OK) return s;
    w->stack[x.ns++] = start;
    while (x.ns > 0) {
        const uint32_t r = w->stack[--x.ns];
        if (w->closed[r]) continue;
        w->closed[r] = 1;
        if ((s = w_reserve_cell(&x)) != DD_OK) return s;
        int o = w_pick_apex(&x, r);
        if (o == W_DONE) o = w_make_cell(&x, r);
        if (o == W_DONE) o = w_close_or_open(&x);
        if (o != W_DONE) return w_end(&x, o, outcome);
    }
    /* Each link triangle closed at most once, so all of them exactly
     * once: the sew needs no matching of its own.                       */
    return w_end(&x, x.nlink == d->star.n ? W_DONE : w_wrong(&x, "the fill does not cover the link"), outcome);
}
