/*
 * soak_weighted.c -- the weighted half of `make soak` (issue 44): regular
 * triangulations edited and compared with CGAL's Regular_triangulation_3
 * (src/cgal/cgal_regular.h) after every operation, in both hidden modes.
 *
 * A weighted case is a dataset (every weighted one of datasets/weighted.c,
 * and "wgrid-dups", the degenerate integer grid of tests/testweighted.h
 * with exact duplicates and power ties), a transform of the coordinates
 * (soak.h; weights scale as squared lengths), a hidden mode (keep, or
 * DD_DISCARD_HIDDEN) and a mode:
 *  - "wseq": deletions one after another, each with the next strategy of
 *    the registry (dd_delete_with), sets (dd_delete_set_with, 2 to 8
 *    vertices), reinsertions of deleted vertices (dd_reinsert) and
 *    insertions (dd_insert_weighted: points held back, exact copies of a
 *    vertex's weighted point, which both sides must refuse, deleted
 *    points with new weights, vertices' positions with other weights);
 *  - "wmove": moves keeping the weight (dd_move: steps of up to the mean
 *    spacing, onto held-back, deleted, hidden points or other vertices'
 *    positions, onto v's own), moves with a weight (dd_move_weighted:
 *    re-weightings by +-10% in place, steps with new weights, heavy
 *    weights that hide neighbours, exact copies of other vertices' or
 *    hidden points' weighted points), with deletions and insertions.
 * The reference of every operation is CGAL's remove() and insert()
 * (DESIGN 12: a move is a removal and then an insertion; a reinsertion
 * an insertion).  CGAL's input indices only grow, so the comparison
 * renames them to the engine's (canon.h): after each operation the
 * cells and the hidden set equal CGAL's and dd_check passes; the one
 * difference accepted is exact copies of a hidden point kept here that
 * CGAL's remove() dropped (wp_copies_dropped), counted and reported.
 *
 * Every strategy deletes weighted points, so a deletion (alone or in a
 * set) that answers DD_ERR_UNSUPPORTED is a mismatch.  Another edit that
 * answers it (one not yet there for weighted points) is skipped and
 * counted per operation, not failed: the triangulation must be
 * unchanged, which the next comparison proves (CGAL's side was not
 * touched).
 */
#include "dtdel.h"
#include "cgal/cgal_regular.h"
#include "datasets/datasets.h"
#include "soak.h"
#include "testweighted.h"
#include "fuzz/canon.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WSOAK_BASE_QUOTA 540.0   /* deletions and moves of one case at scale 1 */

const char *const soak_wop_names[NUM_WOPS] = {"deletions", "in sets", "reinsertions", "insertions",
                                              "moves", "weighted moves"};

enum { WMODE_SEQ, WMODE_MOVE, NUM_WMODES };
static const char *const wmode_names[NUM_WMODES][2] = {{"wseq/keep", "wseq/discard"},
                                                       {"wmove/keep", "wmove/discard"}};

/* ---- the cases ------------------------------------------------------------ */

static size_t num_wdatasets(void)
{
    size_t n = 0;
    while (dd_weighted_dataset_name(n)) n++;
    return n + 1;                                   /* and wgrid-dups */
}

static const char *wdataset(size_t i)
{
    return i + 1 < num_wdatasets() ? dd_weighted_dataset_name(i) : "wgrid-dups";
}

/* Points of a round: CGAL's remove() and the whole comparison after each
 * operation cost O(n), so the triangulations stay moderate; the moment
 * curve's degrees (about n) keep it smaller.                            */
static uint32_t round_size(const char *name)
{
    if (!strcmp(name, "wmoment")) return 80;
    if (!strcmp(name, "whelix")) return 240;
    return 320;
}

size_t soak_num_weighted(void) { return num_wdatasets() * NUM_WMODES * 2 * NUM_TF; }

/* The dataset varies fastest, then the mode, the hidden mode, the
 * transform: a worker taking every J-th case still meets all of them.  */
soak_case soak_weighted_case(size_t j, int index, double scale, uint64_t seed)
{
    const size_t nd = num_wdatasets();
    soak_case c;
    memset(&c, 0, sizeof c);
    c.index = index;
    c.weighted = 1;
    c.dataset = wdataset(j % nd);
    c.mode = (int)(j / nd % NUM_WMODES);
    c.discard = (int)(j / nd / NUM_WMODES % 2);
    c.tf = (soak_tf)(j / nd / NUM_WMODES / 2 % NUM_TF);
    c.mode_name = wmode_names[c.mode][c.discard];
    c.seed = seed * 1000003u + (uint64_t)index;
    const double q = WSOAK_BASE_QUOTA * scale;
    c.quota = q < 6 ? 6 : (uint64_t)q;
    return c;
}

double soak_weighted_cost(const soak_case *c)
{
    double cost = (double)c->quota * 0.4 * round_size(c->dataset);
    if (c->tf == TF_E150 || c->tf == TF_EM150) cost *= 3;
    return cost;
}

/* The points and weights of a round (the caller frees both). */
static int wdataset_points(soak *s, const char *name, uint32_t n, uint64_t seed, double **xyz, double **w,
                           uint32_t *np)
{
    char msg[256];
    if (!strcmp(name, "wgrid-dups")) {
        const uint32_t side = (uint32_t)cbrt((double)n * 0.8);
        wset g = gen_grid(side < 3 ? 3 : side, n / 5, 1, seed);
        *xyz = g.p, *w = g.w, *np = g.n;
        return 0;
    }
    if (dd_gen_weighted(name, n, seed, xyz, w, np, msg, sizeof msg) != DD_OK || !*w) {
        printf("[w%d] cannot generate %s: %s\n", s->worker, name, msg);
        free(*xyz);
        return -1;
    }
    return 0;
}

/* ---- one regular triangulation on both sides -------------------------------- */

typedef struct wpair {
    dd_tri *t;
    dd_cgal_rt *c;
    uint32_t *cg2e;          /* CGAL input index -> the engine's */
    size_t ncg, cgcap;
    double *xyz, *w;         /* the weighted point of each engine index */
    uint32_t *e2cg;          /* engine index -> CGAL's now */
    size_t ne, ecap;
    uint32_t *gone;          /* indices deleted here, for dd_reinsert */
    size_t ngone, gonecap;
    double h, h2;            /* the mean spacing, and its square (finite) */
} wpair;

static void wp_free(wpair *p)
{
    dd_free(p->t);
    dd_cgal_rt_free(p->c);
    free(p->cg2e), free(p->xyz), free(p->w), free(p->e2cg), free(p->gone);
    memset(p, 0, sizeof *p);
}

/* Room for engine index e and for one more CGAL index. */
static int wp_room(wpair *p, size_t e)
{
    if (e >= p->ecap) {
        size_t cap = p->ecap ? p->ecap : 64;
        while (cap <= e) cap *= 2;
        double *x = realloc(p->xyz, 3 * cap * sizeof *x), *w = x ? realloc(p->w, cap * sizeof *w) : NULL;
        if (x) p->xyz = x;
        if (w) p->w = w;
        uint32_t *m = w ? realloc(p->e2cg, cap * sizeof *m) : NULL;
        if (!m) return -1;
        p->e2cg = m;
        p->ecap = cap;
    }
    if (p->ncg + 1 > p->cgcap || p->ngone + 1 > p->gonecap) {
        size_t cap = 2 * (p->cgcap > p->gonecap ? p->cgcap : p->gonecap) + 64;
        uint32_t *a = realloc(p->cg2e, cap * sizeof *a), *b = a ? realloc(p->gone, cap * sizeof *b) : NULL;
        if (a) p->cg2e = a;
        if (!b) return -1;
        p->gone = b;
        p->cgcap = p->gonecap = cap;
    }
    return 0;
}

/* Engine index e is now (q, w), CGAL's next index. */
static void wp_name(wpair *p, uint32_t e, const double q[3], double w)
{
    memcpy(p->xyz + 3 * (size_t)e, q, 3 * sizeof *q);
    p->w[e] = w;
    if (e >= p->ne) p->ne = e + 1;
    p->e2cg[e] = (uint32_t)p->ncg;
    p->cg2e[p->ncg++] = e;
}

static void wp_ungone(wpair *p, uint32_t e)
{
    for (size_t i = 0; i < p->ngone; i++)
        if (p->gone[i] == e) p->gone[i--] = p->gone[--p->ngone];
}

/* Builds both sides.  0 built, -1 mismatch or failure (reported). */
static int wp_build(soak *s, wpair *p, const double *xyz, const double *w, uint32_t n, int discard)
{
    char msg[256];
    memset(p, 0, sizeof *p);
    const dd_status st = dd_create_ex(&p->t, xyz, w, n, discard ? DD_DISCARD_HIDDEN : 0, msg, sizeof msg);
    p->c = dd_cgal_rt_build(xyz, w, n, discard);
    if (st != DD_OK || !p->c) {
        soak_mismatch(s, "building RT of %u points: engine %s (%s), CGAL %s", n, dd_status_name(st),
                      st == DD_OK ? "" : msg, p->c ? "built it" : "refused");
        wp_free(p);
        return -1;
    }
    for (uint32_t i = 0; i < n; i++) {
        if (wp_room(p, i)) return -1;
        wp_name(p, i, xyz + 3 * (size_t)i, w[i]);
    }
    p->h = soak_mean_spacing(xyz, n);
    p->h2 = isfinite(p->h * p->h) ? p->h * p->h : DBL_MAX;
    return 0;
}

/* The first point hidden on one side only, for the message: its weighted
 * point, and another point with exactly the same one if there is.      */
static void hidden_difference(const wpair *p, const uint32_t *ha, size_t nha, const uint32_t *hb, size_t nhb,
                              char *why, size_t len)
{
    size_t i = 0, j = 0;
    while (i < nha && j < nhb && ha[i] == hb[j]) i++, j++;
    const int here = j == nhb || (i < nha && ha[i] < hb[j]);
    const uint32_t e = here ? ha[i] : hb[j];
    const double *x = p->xyz + 3 * (size_t)e;
    uint32_t twin = UINT32_MAX;
    for (uint32_t k = 0; k < p->ne && twin == UINT32_MAX; k++)
        if (k != e && !memcmp(p->xyz + 3 * (size_t)k, x, 3 * sizeof *x) && p->w[k] == p->w[e]) twin = k;
    snprintf(why, len, "hidden sets differ: %zu points, CGAL %zu; point %u (%.17g, %.17g, %.17g; %.17g) hidden %s "
             "only; its exact copy %d is %s", nha, nhb, e, x[0], x[1], x[2], p->w[e], here ? "here" : "in CGAL",
             twin == UINT32_MAX ? -1 : (int)twin, twin == UINT32_MAX ? "none" : dd_is_vertex(p->t, twin) ? "a vertex" :
             dd_is_hidden(p->t, twin) ? "hidden here" : "neither");
}

/* Whether engine indices a and b carry the same weighted point now. */
static int wp_twins(const wpair *p, uint32_t a, uint32_t b)
{
    return !memcmp(p->xyz + 3 * (size_t)a, p->xyz + 3 * (size_t)b, 3 * sizeof *p->xyz) && p->w[a] == p->w[b];
}

/* Exact copies are one weighted point under several indices: when a
 * deletion brings one back, each side keeps the lowest index of the
 * copies in its own numbering, and the two numberings need not agree in
 * order (an engine index re-used by an insertion takes a new CGAL index).
 * So a copy present here whose CGAL name is gone there, while a twin gone
 * here is present there under its CGAL name, swaps names with that twin;
 * the comparison then holds both sides to the same points.  0, or -1
 * when CGAL's lists cannot be read.                                     */
static int wp_rename_copies(wpair *p)
{
    uint32_t *v = NULL, *h = NULL;
    size_t nv = 0, nh = 0;
    unsigned char *there = calloc(p->ncg + 1, 1);
    int rc = !there || dd_cgal_rt_vertices(p->c, &v, &nv) || dd_cgal_rt_hidden(p->c, &h, &nh) ? -1 : 0;
    for (size_t i = 0; rc == 0 && i < nv + nh; i++) {
        const uint32_t k = i < nv ? v[i] : h[i - nv];
        if (k < p->ncg) there[k] = 1;
    }
    for (uint32_t e = 0; rc == 0 && e < p->ne; e++) {
        if (p->e2cg[e] >= p->ncg || there[p->e2cg[e]] || !(dd_is_vertex(p->t, e) || dd_is_hidden(p->t, e))) continue;
        for (uint32_t f = 0; f < p->ne; f++)
            if (f != e && p->e2cg[f] < p->ncg && there[p->e2cg[f]] && !dd_is_vertex(p->t, f) && !dd_is_hidden(p->t, f) && wp_twins(p, e, f)) {
                const uint32_t ce = p->e2cg[e], cf = p->e2cg[f];
                p->e2cg[e] = cf, p->e2cg[f] = ce;
                p->cg2e[cf] = e, p->cg2e[ce] = f;
                break;
            }
    }
    free(there), free(v), free(h);
    return rc;
}

/* CGAL's remove() re-inserts its star's hidden points one at a time, in
 * its own order: a copy may come back as a vertex for a while, its twins
 * then dropped as copies of a vertex, until a later re-insertion hides it
 * again.  The engine builds the result at once and keeps every copy
 * (dtdel.h: dd_delete), so where the hidden sets differ only by copies
 * kept here of a weighted point CGAL still hides, the copies CGAL dropped
 * are forgotten here too (dd_delete of a hidden point) and counted, and
 * the two sides go on from the same points.  hb is CGAL's list renamed;
 * both sorted.  1 when that was the only difference, else 0.           */
static int wp_copies_dropped(soak *s, wpair *p, const uint32_t *ha, size_t nha, const uint32_t *hb, size_t nhb)
{
    size_t j = 0, extra = 0;
    for (size_t i = 0; i < nha; i++) {
        if (j < nhb && hb[j] == ha[i]) {
            j++;
            continue;
        }
        int twin = 0;
        for (size_t k = 0; k < nhb && !twin; k++) twin = wp_twins(p, ha[i], hb[k]);
        if (!twin) return 0;
        extra++;
    }
    if (j != nhb || !extra) return 0;
    for (size_t i = 0, k = 0; i < nha; i++) {
        while (k < nhb && hb[k] < ha[i]) k++;
        if (k < nhb && hb[k] == ha[i]) continue;
        if (dd_delete(p->t, ha[i]) != DD_OK) return 0;
        s->st.wcopies++;
    }
    return 1;
}

/* The cells and hidden sets of both sides, CGAL's renamed (exact copies
 * renamed alike first: wp_rename_copies; copies CGAL dropped forgotten
 * here: wp_copies_dropped); dd_check.                                   */
static int wp_check(soak *s, wpair *p, const char *after)
{
    int32_t *a = NULL, *b = NULL;
    uint32_t *ha = NULL, *hb = NULL;
    size_t na = 0, nb = 0, nha = 0, nhb = 0;
    char why[256] = "";
    s->st.wchecks++;
#ifdef SOAK_TRACE             /* -DSOAK_TRACE: every operation checked */
    printf("[w%d] %s\n", s->worker, after);
#endif
    if (wp_rename_copies(p))
        snprintf(why, sizeof why, "no vertex or hidden list from CGAL");
    else if (dd_canonical(p->t, &a, &na) != DD_OK || dd_cgal_rt_canonical(p->c, &b, &nb))
        snprintf(why, sizeof why, "no canonical form");
    else if (dd_hidden(p->t, &ha, &nha) != DD_OK || dd_cgal_rt_hidden(p->c, &hb, &nhb))
        snprintf(why, sizeof why, "no hidden list");
    if (!why[0]) {
        canon_remap(b, nb, p->cg2e);
        canon_remap_list(hb, nhb, p->cg2e);
        size_t i = 0;
        while (i < na && i < nb && !memcmp(a + 4 * i, b + 4 * i, 4 * sizeof *a)) i++;
        if (na != nb || i < na)
            snprintf(why, sizeof why, "%zu cells, CGAL %zu; first difference at %zu: %d %d %d %d, CGAL %d %d %d %d",
                     na, nb, i, i < na ? a[4 * i] : 0, i < na ? a[4 * i + 1] : 0, i < na ? a[4 * i + 2] : 0,
                     i < na ? a[4 * i + 3] : 0, i < nb ? b[4 * i] : 0, i < nb ? b[4 * i + 1] : 0,
                     i < nb ? b[4 * i + 2] : 0, i < nb ? b[4 * i + 3] : 0);
        else if ((nha != nhb || (nha && memcmp(ha, hb, nha * sizeof *ha))) &&
                 !wp_copies_dropped(s, p, ha, nha, hb, nhb))
            hidden_difference(p, ha, nha, hb, nhb, why, sizeof why);
    }
    free(a), free(b), free(ha), free(hb);
    if (!why[0]) {
        char msg[200];
        if (dd_check_msg(p->t, msg, sizeof msg) != DD_OK) snprintf(why, sizeof why, "dd_check: %s", msg);
    }
    if (why[0]) soak_mismatch(s, "after %s: %s", after, why);
    return why[0] ? -1 : 0;
}

/* A vertex at random (UINT32_MAX if none). */
static uint32_t wp_vertex(const wpair *p, rng *r)
{
    const uint32_t ne = (uint32_t)p->ne;
    for (int tries = 0; tries < 64; tries++) {
        const uint32_t v = below(r, ne);
        if (dd_is_vertex(p->t, v)) return v;
    }
    for (uint32_t i = 0, k = below(r, ne); i < ne; i++)
        if (dd_is_vertex(p->t, (k + i) % ne)) return (k + i) % ne;
    return UINT32_MAX;
}

/* A hidden point at random (UINT32_MAX if none). */
static uint32_t wp_hidden(const wpair *p, rng *r)
{
    uint32_t *h = NULL, v = UINT32_MAX;
    size_t nh = 0;
    if (dd_hidden(p->t, &h, &nh) == DD_OK && nh > 0) v = h[below(r, (uint32_t)nh)];
    free(h);
    return v;
}

/* The vertex whose weighted point is exactly (q, w), or UINT32_MAX. */
static uint32_t wp_same(const wpair *p, const double q[3], double w)
{
    for (uint32_t i = 0; i < p->ne; i++) {
        const double *x = p->xyz + 3 * (size_t)i;
        if (x[0] == q[0] && x[1] == q[1] && x[2] == q[2] && p->w[i] == w && dd_is_vertex(p->t, i)) return i;
    }
    return UINT32_MAX;
}

static double finite_or_max(double x) { return isfinite(x) ? x : copysign(DBL_MAX, x); }

/* ---- the operations ---------------------------------------------------------- */

static int is_skip(soak *s, dd_status st, soak_wop op)
{
    if (st != DD_ERR_UNSUPPORTED) return 0;
    s->st.wskipped[op]++;
    return 1;
}

/* Deletes vertex v with the next strategy (every one deletes weighted
 * points: a refusal is a mismatch).  0 done, -1 mismatch.               */
static int wp_delete(soak *s, wpair *p, uint32_t v)
{
    char what[128];
    const uint32_t nv = dd_num_vertices(p->t);
    const size_t vi = s->turn++ % s->nvariants;
    const char *var = s->variants[vi];
    const dd_status st = dd_delete_with(p->t, v, var);
    snprintf(what, sizeof what, "deleting vertex %u with %s", v, var);
    const int rc = dd_cgal_rt_remove(p->c, p->e2cg[v]);
    if (st != DD_OK || rc) {
        soak_mismatch(s, "%s: engine %s (%s), CGAL %d", what, dd_status_name(st), dd_errmsg(p->t), rc);
        return -1;
    }
    s->st.wdone[WOP_DELETE]++;
    s->st.wvariant[vi]++;
    if (dd_num_vertices(p->t) + 1 > nv) s->st.wreleased += dd_num_vertices(p->t) + 1 - nv;
    p->gone[p->ngone++] = v;
    return wp_check(s, p, what);
}

/* Deletes 2 to 8 vertices as a set with the next strategy. */
static int wp_delete_set(soak *s, wpair *p, rng *r)
{
    uint32_t vs[8], m = 2 + below(r, 7), k = 0, kv = 0;
    unsigned char hidden[8];
    for (uint32_t i = 0; i < 4 * m && k < m; i++) {
        const uint32_t v = i == 0 && below(r, 3) == 0 ? wp_hidden(p, r) : wp_vertex(p, r);
        int again = v == UINT32_MAX;
        for (uint32_t j = 0; j < k; j++) again |= vs[j] == v;
        if (again) continue;
        hidden[k] = !dd_is_vertex(p->t, v);
        kv += !hidden[k];
        vs[k++] = v;
    }
    const uint32_t nv = dd_num_vertices(p->t);
    const size_t vi = s->turn++ % s->nvariants;
    const char *var = s->variants[vi];
    const dd_status st = dd_delete_set_with(p->t, vs, k, var);
    char what[160];
    snprintf(what, sizeof what, "deleting the set of %u points %u%s, %u, ... with %s", k, vs[0],
             hidden[0] ? " (hidden)" : "", vs[1], var);
    if (st != DD_OK) {
        soak_mismatch(s, "%s: engine %s (%s)", what, dd_status_name(st), dd_errmsg(p->t));
        return -1;
    }
    /* CGAL: the hidden points forgotten first, then the vertices removed */
    for (int pass = 1; pass >= 0; pass--)
        for (uint32_t i = 0; i < k; i++)
            if (hidden[i] == pass && (pass ? dd_cgal_rt_forget(p->c, p->e2cg[vs[i]])
                                           : dd_cgal_rt_remove(p->c, p->e2cg[vs[i]]))) {
                soak_mismatch(s, "%s: CGAL refused point %u", what, vs[i]);
                return -1;
            }
    s->st.wdone[WOP_SET] += k;
    s->st.wvariant[vi] += k;
    s->st.whidden_ops += k - kv;
    if (dd_num_vertices(p->t) + kv > nv) s->st.wreleased += dd_num_vertices(p->t) + kv - nv;
    for (uint32_t i = 0; i < k; i++) p->gone[p->ngone++] = vs[i];
    return wp_check(s, p, what);
}

/* CGAL's insertion of (q, w) under engine index e: 0 inserted (hidden or
 * forgotten included), 2 equal to a vertex's weighted point (nothing
 * changed), 1 failure.                                                   */
static int cgal_insert_as(wpair *p, uint32_t e, const double q[3], double w)
{
    const int rc = dd_cgal_rt_insert(p->c, q, w, dd_cgal_rt_num_input(p->c));
    if (rc == 0) wp_name(p, e, q, w);
    return rc;
}

/* Inserts (q, w): 0 inserted or refused by both alike, -1 mismatch. */
static int wp_insert(soak *s, wpair *p, const double q[3], double w)
{
    char what[200];
    snprintf(what, sizeof what, "inserting (%.17g, %.17g, %.17g; %.17g)", q[0], q[1], q[2], w);
    uint32_t idx = UINT32_MAX;
    const uint32_t same = wp_same(p, q, w);
    const dd_status st = dd_insert_weighted(p->t, q, w, &idx);
    if (is_skip(s, st, WOP_INSERT)) return 0;
    if (wp_room(p, idx == UINT32_MAX ? p->ne : idx)) return -1;
    const int rc = cgal_insert_as(p, st == DD_OK && same == UINT32_MAX ? idx : (uint32_t)p->ne, q, w);
    /* a vertex's exact weighted point: that vertex, nothing changed (CGAL's insert returns it) */
    if (rc == 2 && same != UINT32_MAX && ((st == DD_OK && idx == same) || st == DD_ERR_DUPLICATE)) {
        s->st.wrefused[WOP_INSERT]++;
        return wp_check(s, p, what);
    }
    if (st != DD_OK || rc != 0) {
        soak_mismatch(s, "%s: engine %s (%s) index %u, CGAL %d", what, dd_status_name(st), dd_errmsg(p->t), idx,
                      rc);
        return -1;
    }
    wp_ungone(p, idx);
    s->st.wdone[WOP_INSERT]++;
    return wp_check(s, p, what);
}

/* Puts back a vertex deleted here, with its weight. */
static int wp_reinsert(soak *s, wpair *p, rng *r)
{
    if (p->ngone == 0) return 0;
    const size_t k = below(r, (uint32_t)p->ngone);
    const uint32_t v = p->gone[k];
    char what[96];
    snprintf(what, sizeof what, "reinserting %u", v);
    const uint32_t same = wp_same(p, p->xyz + 3 * (size_t)v, p->w[v]);
    const dd_status st = dd_reinsert(p->t, v);
    if (is_skip(s, st, WOP_REINSERT)) return 0;
    if (wp_room(p, v)) return -1;
    double q[3];
    memcpy(q, p->xyz + 3 * (size_t)v, sizeof q);
    const int rc = cgal_insert_as(p, v, q, p->w[v]);
    /* another vertex has v's weighted point: refused, or nothing changed */
    if (rc == 2 && same != UINT32_MAX && (st == DD_ERR_DUPLICATE || st == DD_OK)) {
        s->st.wrefused[WOP_REINSERT]++;
        return wp_check(s, p, what);
    }
    if (st != DD_OK || rc != 0) {
        soak_mismatch(s, "%s: engine %s (%s), CGAL %d", what, dd_status_name(st), dd_errmsg(p->t), rc);
        return -1;
    }
    p->gone[k] = p->gone[--p->ngone];
    s->st.wdone[WOP_REINSERT]++;
    return wp_check(s, p, what);
}

/* Moves point v (a vertex, or a kept hidden point) to (q, w):
 * dd_move_weighted, or dd_move when w is v's weight and `plain`.  The
 * reference: dd_cgal_rt_move_any_dim (CGAL's remove() or the hidden point
 * forgotten, then insert() under the same index).  Onto another point's
 * exact weighted point that is or becomes a vertex both refuse.        */
static int wp_move(soak *s, wpair *p, uint32_t v, const double q[3], double w, int plain)
{
    const soak_wop op = plain ? WOP_MOVE : WOP_MOVE_WEIGHTED;
    char what[320];
    snprintf(what, sizeof what, "%s %s %u from (%.17g, %.17g, %.17g; %.17g) to (%.17g, %.17g, %.17g; %.17g)",
             plain ? "moving" : "moving with its weight", dd_is_vertex(p->t, v) ? "vertex" : "hidden point", v,
             p->xyz[3 * (size_t)v], p->xyz[3 * (size_t)v + 1], p->xyz[3 * (size_t)v + 2], p->w[v], q[0], q[1], q[2],
             w);
    const dd_status st = plain ? dd_move(p->t, v, q) : dd_move_weighted(p->t, v, q, w);
    if (is_skip(s, st, op)) return 0;
    const int rc = dd_cgal_rt_move_any_dim(p->c, p->e2cg[v], q, w);
    if (st == DD_ERR_DUPLICATE && rc == 2) {
        s->st.wrefused[op]++;
        return wp_check(s, p, what);
    }
    if (st != DD_OK || rc != 0) {
        soak_mismatch(s, "%s: engine %s (%s), CGAL %d", what, dd_status_name(st), dd_errmsg(p->t), rc);
        return -1;
    }
    memcpy(p->xyz + 3 * (size_t)v, q, 3 * sizeof *q);
    p->w[v] = w;
    s->st.wdone[op]++;
    return wp_check(s, p, what);
}

/* Deletes a kept hidden point: forgotten, no cell changes (CGAL's side:
 * dd_cgal_rt_forget).                                                   */
static int wp_forget(soak *s, wpair *p, uint32_t v)
{
    char what[96];
    snprintf(what, sizeof what, "deleting hidden point %u", v);
    const dd_status st = dd_delete(p->t, v);
    if (is_skip(s, st, WOP_DELETE)) return 0;
    const int rc = dd_cgal_rt_forget(p->c, p->e2cg[v]);
    if (st != DD_OK || rc) {
        soak_mismatch(s, "%s: engine %s (%s), CGAL %d", what, dd_status_name(st), dd_errmsg(p->t), rc);
        return -1;
    }
    s->st.wdone[WOP_DELETE]++;
    s->st.whidden_ops++;
    p->gone[p->ngone++] = v;
    return wp_check(s, p, what);
}

/* ---- the targets --------------------------------------------------------------- */

/* A weighted point to insert: held back (spare), an exact copy of a
 * vertex's (refused), a deleted one with a new weight, or a vertex's
 * position with another weight.                                          */
static void insert_target(rng *r, wpair *p, const double *spare, const double *wspare, uint32_t *nspare,
                          double q[3], double *w)
{
    const uint32_t coin = below(r, 100);
    const uint32_t v = wp_vertex(p, r);
    if ((coin < 60 || v == UINT32_MAX) && *nspare > 0) {
        --*nspare;
        memcpy(q, spare + 3 * (size_t)*nspare, 3 * sizeof *q);
        *w = wspare[*nspare];
        return;
    }
    if (coin < 80 && p->ngone > 0) {
        const uint32_t g = p->gone[below(r, (uint32_t)p->ngone)];
        memcpy(q, p->xyz + 3 * (size_t)g, 3 * sizeof *q);
        *w = finite_or_max(p->w[g] + p->h2 * ((double)below(r, 1001) / 1000.0 - 0.5));
        return;
    }
    const uint32_t u = v == UINT32_MAX ? 0 : v;
    memcpy(q, p->xyz + 3 * (size_t)u, 3 * sizeof *q);
    *w = coin < 90 ? p->w[u] : finite_or_max(p->w[u] + p->h2 * (double)(1 + below(r, 3)) * 0.25);
}

/* Where v moves: a step of up to h/k per coordinate, onto a deleted or
 * hidden point's position, onto another vertex's, or onto its own.      */
static void move_point(rng *r, wpair *p, uint32_t v, double q[3])
{
    const uint32_t coin = below(r, 100);
    const double *x = p->xyz + 3 * (size_t)v;
    uint32_t u = UINT32_MAX;
    if (coin < 70) {
        const double h = p->h / (1 + below(r, 20));
        for (int c = 0; c < 3; c++) {
            q[c] = x[c] + h * ((double)below(r, 2001) / 1000.0 - 1.0);
            if (!isfinite(q[c])) q[c] = x[c];
        }
        return;
    }
    if (coin < 78 && p->ngone > 0) u = p->gone[below(r, (uint32_t)p->ngone)];
    else if (coin < 86) u = wp_hidden(p, r);
    else if (coin < 95) u = wp_vertex(p, r);
    memcpy(q, p->xyz + 3 * (size_t)(u == UINT32_MAX ? v : u), 3 * sizeof *q);
}

/* A move with a weight: a re-weighting by +-10% in place, a step with a
 * new weight, a heavy weight (hides neighbours), or an exact copy of
 * another vertex's or a hidden point's weighted point.                   */
static void move_weighted_target(rng *r, wpair *p, uint32_t v, double q[3], double *w)
{
    const uint32_t coin = below(r, 100);
    const double wv = p->w[v], u = (double)below(r, 2001) / 1000.0 - 1.0;
    memcpy(q, p->xyz + 3 * (size_t)v, 3 * sizeof *q);
    if (coin < 40) {
        *w = finite_or_max(wv + 0.1 * u * (wv != 0 ? fabs(wv) : p->h2));
    } else if (coin < 70) {
        move_point(r, p, v, q);
        *w = finite_or_max(wv + 0.5 * u * p->h2);
    } else if (coin < 80) {
        *w = finite_or_max(wv + p->h2 * (double)(1 + below(r, 4)));
    } else {
        const uint32_t o = coin < 90 ? wp_vertex(p, r) : wp_hidden(p, r);
        const uint32_t src = o == UINT32_MAX ? v : o;
        memcpy(q, p->xyz + 3 * (size_t)src, 3 * sizeof *q);
        *w = p->w[src];
    }
}

/* ---- the modes ------------------------------------------------------------------- */

/* One operation of the case's mode on p; 0, or -1 after a mismatch. */
static int one_op(soak *s, const soak_case *c, wpair *p, rng *r, const double *spare, const double *wspare,
                  uint32_t *nspare)
{
    const uint32_t coin = below(r, 100), v = wp_vertex(p, r);
    double q[3], w;
    if (v == UINT32_MAX) return 0;
    const uint32_t hp = coin % 10 == 0 && !c->discard ? wp_hidden(p, r) : UINT32_MAX;
    if (c->mode == WMODE_SEQ) {
        if (coin < 55 && hp != UINT32_MAX) return wp_forget(s, p, hp);
        if (coin < 55) return wp_delete(s, p, v);
        if (coin < 65) return wp_delete_set(s, p, r);
        if (coin < 80) return wp_reinsert(s, p, r);
    } else {
        const uint32_t u = hp != UINT32_MAX ? hp : v;     /* a hidden point now and then */
        if (coin < 35) {
            move_point(r, p, u, q);
            if (u != v) s->st.whidden_ops++;
            return wp_move(s, p, u, q, p->w[u], 1);
        }
        if (coin < 75) {
            move_weighted_target(r, p, u, q, &w);
            if (u != v) s->st.whidden_ops++;
            return wp_move(s, p, u, q, w, 0);
        }
        if (coin < 88) return wp_delete(s, p, v);
        if (coin < 94) return wp_reinsert(s, p, r);
    }
    insert_target(r, p, spare, wspare, nspare, q, &w);
    return wp_insert(s, p, q, w);
}

/* What the quota counts: deletions and moves, done or refused alike. */
static uint64_t ops_done(const soak *s)
{
    uint64_t n = 0;
    for (int k = 0; k < NUM_WOPS; k++)
        if (k != WOP_INSERT && k != WOP_REINSERT) n += s->st.wdone[k] + s->st.wrefused[k];
    return n;
}

/* Rounds of RT(S) (three quarters of the points; the rest held back for
 * insertions), edited until a third of the vertices is gone or the
 * round's share of the quota is done.                                   */
int soak_weighted_run(soak *s, const soak_case *c, rng *r)
{
    const uint64_t start = ops_done(s);
    uint64_t attempts = 0;
    while (ops_done(s) - start < c->quota && attempts < 20 * c->quota + 100) {
        double *xyz, *w;
        uint32_t np;
        if (wdataset_points(s, c->dataset, round_size(c->dataset), c->seed + s->round, &xyz, &w, &np)) return -1;
        soak_shuffle(r, xyz, w, np);
        soak_transform(c->tf, xyz, w, np);
        const uint32_t n0 = np - np / 4;
        uint32_t nspare = np - n0;
        wpair p;
        if (wp_build(s, &p, xyz, w, n0, c->discard)) {
            free(xyz), free(w);
            return -1;
        }
        int rc = wp_check(s, &p, "the build");
        const uint32_t keep = dd_num_vertices(p.t) * 2 / 3 > 12 ? dd_num_vertices(p.t) * 2 / 3 : 12;
        const uint64_t round_start = ops_done(s);
        for (s->step = 0; !rc && ops_done(s) - start < c->quota && ops_done(s) - round_start < n0 / 2 &&
                          dd_num_vertices(p.t) > keep && attempts < 20 * c->quota + 100;
             s->step++, attempts++)
            rc = one_op(s, c, &p, r, xyz + 3 * (size_t)n0, w + n0, &nspare);
        wp_free(&p);
        free(xyz), free(w);
        if (rc) return -1;
        s->round++;
    }
    return 0;
}

/* ---- the totals ------------------------------------------------------------------- */

void soak_weighted_report(const soak *proto, const stats *tot)
{
    uint64_t done = 0, skipped = 0, refused = 0;
    for (int k = 0; k < NUM_WOPS; k++) done += tot->wdone[k], skipped += tot->wskipped[k], refused += tot->wrefused[k];
    printf("soak: weighted, done:");
    for (int k = 0; k < NUM_WOPS; k++)
        printf(" %llu %s%s", (unsigned long long)tot->wdone[k], soak_wop_names[k], k + 1 < NUM_WOPS ? "," : "\n");
    printf("soak: weighted, refused by both alike:");
    for (int k = 0; k < NUM_WOPS; k++)
        printf(" %llu %s%s", (unsigned long long)tot->wrefused[k], soak_wop_names[k], k + 1 < NUM_WOPS ? "," : "\n");
    printf("soak: weighted, skipped (DD_ERR_UNSUPPORTED):");
    for (int k = 0; k < NUM_WOPS; k++)
        printf(" %llu %s%s", (unsigned long long)tot->wskipped[k], soak_wop_names[k], k + 1 < NUM_WOPS ? "," : "\n");
    printf("soak: weighted, deleted by strategy:");
    for (size_t v = 0; v < proto->nvariants; v++)
        printf(" %s %llu%s", proto->variants[v], (unsigned long long)tot->wvariant[v],
               v + 1 < proto->nvariants ? "," : "\n");
    printf("soak: weighted, %llu deletions and moves, %llu operations in all, %llu refused alike, %llu skipped, "
           "%llu hidden points came back, %llu deletions and moves of hidden points, %llu whole comparisons with CGAL, "
           "%llu exact copies CGAL's remove() dropped\n",
           (unsigned long long)(tot->wdone[WOP_DELETE] + tot->wdone[WOP_SET] + tot->wdone[WOP_MOVE] +
                                tot->wdone[WOP_MOVE_WEIGHTED]),
           (unsigned long long)done, (unsigned long long)refused, (unsigned long long)skipped,
           (unsigned long long)tot->wreleased, (unsigned long long)tot->whidden_ops, (unsigned long long)tot->wchecks,
           (unsigned long long)tot->wcopies);
}
