/*
 * test_wedit.c -- the edits of a regular (weighted Delaunay)
 * triangulation beyond one deletion (issue 44), against CGAL's
 * Regular_triangulation_3 (src/cgal/cgal_regular.h): dd_delete_set,
 * dd_reinsert, dd_move and dd_move_weighted, and dd_delete of a kept
 * hidden point, in both hidden modes, on every weighted set of
 * testweighted.h (uniform weights hiding few to most points, the
 * degenerate integer grid with duplicates and power ties, a molecule,
 * protecting balls, the moment curve and a helix):
 *  - sequences of set deletions (small and large fractions; in test
 *    builds both courses forced), re-insertions of what was deleted, and
 *    moves: small steps (the relocation filter's path, whose use is
 *    checked), large ones, onto another vertex's position with another
 *    weight, re-weightings up and down (v hidden, or hiding others),
 *    moves of kept hidden points, moves just past the nearest facet of
 *    the link (a star cell inverts: flipped away first, or the removal
 *    and insertion); after every step the cells and the
 *    hidden set equal CGAL's (a move's reference: remove, then insert
 *    under the same index, DESIGN 12) and dd_check passes;
 *  - moves of an apex whose removal leaves only coplanar points (a grid
 *    plane with hidden points on it) or 3 vertices (a tetrahedron with
 *    hidden points): CGAL's remove() drops the dimension and the
 *    insertion raises it again; the same cells and hidden set, or both
 *    refuse (the moved set coplanar, or another vertex's weighted point);
 *  - the course the cost model picks: a quarter of the points deleted one
 *    at a time, most of them by the rebuild (dd_created_cells tells);
 *  - refusals (NaN or infinite weight or coordinate, unknown index,
 *    another vertex's exact weighted point, an unweighted t) with
 *    nothing changed;
 *  - in test builds, every allocation of each call refused in turn:
 *    DD_ERR_NOMEM with nothing changed, then the call equals CGAL.
 * Argument "small": smaller sizes (the sanitizer build).
 */
#include "testlib.h"
#include <math.h>
#include "dtdel.h"
#include "dtdel_stats.h"
#include "cgal/cgal_regular.h"
#include "testweighted.h"

static int small;

/* A triangulation and its reference, in one hidden mode. */
typedef struct pair {
    dd_tri *t;
    dd_cgal_rt *c;
    int keep;
    double h;               /* the mean spacing of the set */
    double *p, *w;          /* each input point as it is now (moves) */
} pair;

static int pair_make(pair *pr, const wset *s, int keep, char *why, size_t nwhy)
{
    pr->keep = keep;
    pr->h = pow((double)s->n, -1.0 / 3);
    pr->p = malloc(3 * (size_t)s->n * sizeof *pr->p);
    pr->w = malloc((size_t)s->n * sizeof *pr->w);
    memcpy(pr->p, s->p, 3 * (size_t)s->n * sizeof *pr->p);
    memcpy(pr->w, s->w, (size_t)s->n * sizeof *pr->w);
    return ws_build(s, keep, &pr->t, &pr->c, why, nwhy);
}

static void pair_free(pair *pr)
{
    dd_free(pr->t);
    dd_cgal_rt_free(pr->c);
    free(pr->p), free(pr->w);
    pr->t = NULL, pr->c = NULL, pr->p = pr->w = NULL;
}

static int present(const dd_tri *t, uint32_t i) { return dd_is_vertex(t, i) || dd_is_hidden(t, i); }

/* A random input index with `want` (1 vertex, 2 hidden, 3 either), or
 * UINT32_MAX.                                                          */
static uint32_t pick(const dd_tri *t, tl_rng *r, int want)
{
    const uint32_t np = dd_num_input(t);
    for (int tries = 0; tries < 20000; tries++) {
        const uint32_t v = (uint32_t)tl_int(r, 0, np - 1);
        if (((want & 1) && dd_is_vertex(t, v)) || ((want & 2) && dd_is_hidden(t, v))) return v;
    }
    return UINT32_MAX;
}

/* After a step: checked, and equal to CGAL; why prefixed by what. */
static int agree(const pair *pr, const char *what, char *why, size_t nwhy)
{
    char w2[256] = "";
    if (checked(pr->t, w2, sizeof w2) && same_as_cgal(pr->t, pr->c, w2, sizeof w2)) return 1;
    snprintf(why, nwhy, "%.60s: %.180s", what, w2);
    return 0;
}

/* ---- set deletions and re-insertions ------------------------------------------ */

/* CGAL's reference of deleting index i: remove() a vertex, else forget. */
static int cgal_delete(dd_cgal_rt *c, uint32_t i)
{
    const int r = dd_cgal_rt_remove(c, i);
    return r == 1 ? dd_cgal_rt_forget(c, i) : r;
}

/* Exact copies of a hidden point made by a move (issue 44): the cube's
 * corners, its centre with weight 0.1 (8) and 0 (9, hidden), 10 moved onto
 * 9's weighted point (hidden too).  Then 8 moved off the centre (a
 * removal that makes 9 a vertex and forgets 10, as CGAL's remove) and
 * back near it (9 hidden again, 10 still gone), or 8 deleted as a set
 * with corner 0, or 8 moved onto corner 0's weighted point: refused by
 * both with nothing changed (9 and 10 still hidden; the engine's move
 * must refuse before deleting 8, whose deletion would forget 10 for
 * good).  Or 8 re-weighted in place, heavier: no flip is needed, but
 * the reference's removal makes 9 a vertex and forgets 10 before its
 * insertion hides 9 again, so the engine must not keep 10 (flips decline
 * a star with exact copies).  Or, 10 left where it is (9 the one hidden
 * point of 8's star), 8 re-weighted in place to 0, onto 9's weighted
 * point: refused after the removal, as CGAL's insert returns 9 (8 put
 * back, 9 hidden again), which flips, keeping 9 hidden under a vertex
 * with its weighted point, must not reach; discarding, 9 is gone and
 * the move is done.  Both modes, each step equal to CGAL.               */
static void copies_case(tl_state *st)
{
    static const char *const how_name[5] = {"move", "set", "refused", "reweight", "onto-copy"};
    for (int keep = 0; keep < 2; keep++)
        for (int how = 0; how < 5; how++) {
            char tn[128], why[256] = "";
            snprintf(tn, sizeof tn, "copies/%s/%s", how_name[how], keep ? "keep" : "discard");
            wset s = {0};
            for (int k = 0; k < 8; k++) ws_add(&s, k & 1, (k >> 1) & 1, (k >> 2) & 1, 0);
            ws_add(&s, 0.5, 0.5, 0.5, 0.1);
            ws_add(&s, 0.5, 0.5, 0.5, 0);
            ws_add(&s, 0.2, 0.25, 0.3, 0);
            ws_add(&s, 0.75, 0.7, 0.65, 0);
            pair pr;
            int ok = pair_make(&pr, &s, keep, why, sizeof why);
            const double mid[3] = {0.5, 0.5, 0.5}, off[3] = {0.5, 0.5, 0.51};
            if (ok && how != 4) {
                const dd_status ds = dd_move_weighted(pr.t, 10, mid, 0);
                ok = ds == DD_OK && dd_cgal_rt_move(pr.c, 10, mid, 0) == 0;
                if (!ok) snprintf(why, sizeof why, "moving 10: %s", dd_errmsg(pr.t));
                if (ok) ok = agree(&pr, "10 onto 9", why, sizeof why);
            }
            if (ok && (how == 0 || how == 3)) {
                const double *to = how ? mid : off, w8 = how ? 0.12 : 0.1;
                const dd_status ds = dd_move_weighted(pr.t, 8, to, w8);
                ok = ds == DD_OK && dd_cgal_rt_move(pr.c, 8, to, w8) == 0;
                if (!ok) snprintf(why, sizeof why, "moving 8: %s", dd_errmsg(pr.t));
                if (ok) ok = agree(&pr, "8 moved", why, sizeof why);
                if (ok && keep) {
                    ok = dd_is_hidden(pr.t, 9) && !present(pr.t, 10);
                    if (!ok) snprintf(why, sizeof why, "9 should be hidden again, 10 forgotten (9: v%d h%d, 10: v%d h%d)", dd_is_vertex(pr.t, 9), dd_is_hidden(pr.t, 9), dd_is_vertex(pr.t, 10), dd_is_hidden(pr.t, 10));
                }
            } else if (ok && how == 4) {
                const double w8 = 0;
                const dd_status ds = dd_move_weighted(pr.t, 8, mid, w8);
                const int rc = dd_cgal_rt_move(pr.c, 8, mid, w8);
                ok = !keep ? ds == DD_OK && rc == 0 : ds == DD_ERR_DUPLICATE && rc == 2;
                if (!ok) snprintf(why, sizeof why, "re-weighting 8 to %g: engine %s, CGAL %d", w8, dd_status_name(ds), rc);
                if (ok) ok = agree(&pr, "8 re-weighted", why, sizeof why);
                if (ok && keep) {
                    ok = dd_is_vertex(pr.t, 8) && dd_is_hidden(pr.t, 9);
                    if (!ok) snprintf(why, sizeof why, "8 should be a vertex, 9 hidden");
                }
            } else if (ok && how == 2) {
                const double corner[3] = {0, 0, 0};
                const dd_status ds = dd_move_weighted(pr.t, 8, corner, 0);
                const int rc = dd_cgal_rt_move(pr.c, 8, corner, 0);
                ok = ds == DD_ERR_DUPLICATE && rc == 2;
                if (!ok) snprintf(why, sizeof why, "moving 8 onto 0: engine %s, CGAL %d", dd_status_name(ds), rc);
                if (ok) ok = agree(&pr, "8 onto 0 refused", why, sizeof why);
                if (ok && keep) {
                    ok = dd_is_vertex(pr.t, 8) && dd_is_hidden(pr.t, 9) && dd_is_hidden(pr.t, 10);
                    if (!ok) snprintf(why, sizeof why, "8 should be a vertex, 9 and 10 hidden");
                }
            } else if (ok) {
                const uint32_t vs[2] = {0, 8};
                const dd_status ds = dd_delete_set(pr.t, vs, 2);
                ok = ds == DD_OK && cgal_delete(pr.c, 0) == 0 && cgal_delete(pr.c, 8) == 0;
                if (!ok) snprintf(why, sizeof why, "deleting {0, 8}: %s", dd_errmsg(pr.t));
                if (ok) ok = agree(&pr, "{0, 8} deleted", why, sizeof why);
                if (ok && keep) {
                    ok = dd_is_vertex(pr.t, 9) && !present(pr.t, 10);
                    if (!ok) snprintf(why, sizeof why, "9 should be the vertex, 10 forgotten");
                }
            }
            tl_check(st, ok, tn, "%s", why);
            pair_free(&pr);
            ws_free(&s);
        }
}

/* Deletes a random fraction f of the points present as one set (course:
 * 0 the engine's choice, 1 one at a time, 2 rebuild; test builds), then
 * re-inserts half of them, comparing after each step.  Lists the
 * deleted indices in gone (appended).                                  */
static int set_step(pair *pr, tl_rng *r, double f, int course, char *why, size_t nwhy)
{
    dd_tri *t = pr->t;
    const uint32_t np = dd_num_input(t);
    uint32_t *vs = malloc(np * sizeof *vs), n = 0;
    for (uint32_t i = 0; i < np; i++)
        if (present(t, i) && tl_unif(r) < f) vs[n++] = i;
    for (uint32_t k = n; k > 1; k--) {                   /* any order */
        const uint32_t j = (uint32_t)tl_int(r, 0, k - 1), x = vs[k - 1];
        vs[k - 1] = vs[j], vs[j] = x;
    }
#ifdef DD_TEST_BUILD
    dd_test_control(t, DD_TEST_SET_COURSE, course);
#else
    (void)course;
#endif
    dd_status s = dd_delete_set(t, vs, n);
#ifdef DD_TEST_BUILD
    dd_test_control(t, DD_TEST_SET_COURSE, 0);
#endif
    int ok = 1;
    char what[96];
    snprintf(what, sizeof what, "set of %u (f %g, course %d)", n, f, course);
    if (s == DD_ERR_DIMENSION) {
        free(vs);
        return 1;                                        /* too few left: fine */
    }
    if (s != DD_OK) ok = 0, snprintf(why, nwhy, "%s: %s (%s)", what, dd_status_name(s), dd_errmsg(t));
    for (uint32_t k = 0; k < n && ok; k++)
        if (cgal_delete(pr->c, vs[k]) != 0) ok = 0, snprintf(why, nwhy, "%s: CGAL could not delete %u", what, vs[k]);
    for (uint32_t k = 0; k < n && ok; k++)
        if (present(t, vs[k])) ok = 0, snprintf(why, nwhy, "%s: %u still there", what, vs[k]);
    if (ok) ok = agree(pr, what, why, nwhy);
    /* half of them back, one at a time */
    for (uint32_t k = 0; k < n && ok; k += 2) {
        const double *p = pr->p + 3 * (size_t)vs[k], w = pr->w[vs[k]];
        s = dd_reinsert(t, vs[k]);
        const int cr = dd_cgal_rt_insert_as(pr->c, p, w, vs[k]);
        snprintf(what, sizeof what, "reinsert %u", vs[k]);
        if (s != DD_OK || cr != 0) {
            ok = 0, snprintf(why, nwhy, "%s: %s (%s), CGAL %d", what, dd_status_name(s), dd_errmsg(t), cr);
            break;
        }
        if (k % 8 == 0 || n < 40) ok = agree(pr, what, why, nwhy);
    }
    if (ok) ok = agree(pr, "after the re-insertions", why, nwhy);
    free(vs);
    return ok;
}

/* The course the cost model takes (release and test builds alike): a
 * set of a quarter of the points of a weighted t is deleted one at a
 * time (dd_created_cells lists only the cells the deletions made), one
 * of most of them by the rebuild (it lists every cell); listed in a
 * random order, kept hidden points among them.  Both results equal
 * CGAL's, in both hidden modes.                                         */
static void course_case(tl_state *st)
{
    for (int keep = 1; keep >= 0; keep--)
        for (int most = 0; most <= 1; most++) {
            char tn[64], why[320] = "";
            snprintf(tn, sizeof tn, "set-course/%s/%s", most ? "most" : "quarter", keep ? "keep" : "discard");
            wset s = gen_uniform(small ? 400 : 1500, 1, 90 + (uint64_t)most);
            pair pr;
            int ok = pair_make(&pr, &s, keep, why, sizeof why);
            tl_rng r = {0x5EEDull + (uint64_t)most};
            const uint32_t np = dd_num_input(pr.t);
            uint32_t *vs = malloc(np * sizeof *vs), n = 0, nh = 0;
            for (uint32_t i = 0; ok && i < np; i++)
                if (present(pr.t, i) && tl_unif(&r) < (most ? 0.7 : 0.25)) vs[n++] = i, nh += dd_is_hidden(pr.t, i);
            for (uint32_t k = n; k > 1; k--) {
                const uint32_t j = (uint32_t)tl_int(&r, 0, k - 1), x = vs[k - 1];
                vs[k - 1] = vs[j], vs[j] = x;
            }
            const dd_status ds = ok ? dd_delete_set(pr.t, vs, n) : DD_ERR_INTERNAL;
            if (ok && ds != DD_OK) ok = 0, snprintf(why, sizeof why, "deleting %u: %s (%s)", n, dd_status_name(ds), dd_errmsg(pr.t));
            for (uint32_t k = 0; ok && k < n; k++)
                if (cgal_delete(pr.c, vs[k]) != 0) ok = 0, snprintf(why, sizeof why, "CGAL could not delete %u", vs[k]);
            if (ok) ok = agree(&pr, "the set deleted", why, sizeof why);
            const dd_cell_id *cells;
            size_t nc = 0;
            if (ok && dd_created_cells(pr.t, &cells, &nc) != DD_OK) ok = 0, snprintf(why, sizeof why, "no list of made cells");
            if (ok && most != (nc == dd_num_tets(pr.t)))
                ok = 0, snprintf(why, sizeof why, "%u of %u deleted: %zu of %zu cells listed made, expected the %s course", n, np,
                                 nc, dd_num_tets(pr.t), most ? "rebuild" : "one-at-a-time");
            if (ok && keep && nh == 0) ok = 0, snprintf(why, sizeof why, "no hidden point listed");
            tl_check(st, ok, tn, "%s", why);
            free(vs);
            pair_free(&pr);
            ws_free(&s);
        }
}

/* ---- moves ---------------------------------------------------------------------- */

enum { MV_SMALL, MV_LARGE, MV_ONTO, MV_UP, MV_DOWN, MV_HIDDEN, MV_KINDS };
static const char *const mv_name[MV_KINDS] = {"small", "large", "onto", "weight-up", "weight-down", "hidden"};

/* A move of kind k for point v: the new point p and weight *w. */
static void make_move(const pair *pr, tl_rng *r, int k, uint32_t v, double p[3], double *w)
{
    dd_tri *t = pr->t;
    double x[3], wv;
    memcpy(x, pr->p + 3 * (size_t)v, sizeof x);
    wv = pr->w[v];
    *w = wv;
    const double h = pr->h, step = k == MV_SMALL ? 1e-3 * h : 0.7 * h;
    for (int c = 0; c < 3; c++) p[c] = x[c] + step * (2 * tl_unif(r) - 1);
    if (k == MV_ONTO) {                          /* another vertex's position */
        const uint32_t u = pick(t, r, 1);
        const double wu = pr->w[u];
        memcpy(p, pr->p + 3 * (size_t)u, 3 * sizeof *p);
        *w = wu + (tl_unif(r) < 0.5 ? -1 : 1) * (0.1 + tl_unif(r)) * h * h;
    } else if (k == MV_UP || k == MV_DOWN) {     /* re-weighting in place */
        memcpy(p, x, sizeof x);
        const double d = (0.2 + 2 * tl_unif(r)) * h * h;
        *w = k == MV_UP ? wv + d : wv - d;
    } else if (k == MV_HIDDEN) {
        *w = wv + (tl_unif(r) - 0.5) * h * h;
    }
}

/* `count` moves of each kind in turn, each compared with CGAL's remove
 * then insert.  *kept: moves the relocation filter kept.  1 when all
 * agree, 0 on a difference, -1 when the reference cannot go on.       */
static int move_steps(pair *pr, tl_rng *r, uint32_t count, uint64_t *kept, char *why, size_t nwhy)
{
    dd_tri *t = pr->t;
    dd_counters c0, c1;
    dd_get_counters(t, &c0);
    int ok = 1;
    for (uint32_t m = 0; m < count && ok; m++) {
        const int k = (int)(m % MV_KINDS);
        const uint32_t v = pick(t, r, k == MV_HIDDEN ? 2 : 1);
        if (v == UINT32_MAX) continue;                 /* no hidden point */
        double p[3], w;
        make_move(pr, r, k, v, p, &w);
        const dd_status s = m % 7 == 3 && k == MV_SMALL ? dd_move(t, v, p) : dd_move_weighted(t, v, p, w);
        const int cr = dd_cgal_rt_move_any_dim(pr->c, v, p, w);
        char what[128];
        snprintf(what, sizeof what, "move %u (%s) to (%g %g %g; %g)", v, mv_name[k], p[0], p[1], p[2], w);
        if (s == DD_ERR_DUPLICATE && cr == 2) continue;    /* both refuse */
        if (cr == 3 && s == DD_ERR_DIMENSION) return -1;  /* the moved set is coplanar: CGAL's
                                                   triangulation, in 2D, ends the reference here */
        if (s != DD_OK || cr != 0) {
            ok = 0, snprintf(why, nwhy, "%s: %s (%s), CGAL %d", what, dd_status_name(s), dd_errmsg(t), cr);
            break;
        }
        memcpy(pr->p + 3 * (size_t)v, p, sizeof p);
        pr->w[v] = w;
        ok = agree(pr, what, why, nwhy);
    }
    dd_get_counters(t, &c1);
    *kept += c1.moves_kept - c0.moves_kept;
    return ok;
}

/* ---- one set in both modes ------------------------------------------------------ */

static void edit_case(tl_state *st, const char *name, const wset *s, uint32_t nmoves)
{
    for (int keep = 1; keep >= 0; keep--) {
        char tn[160], why[256] = "";
        snprintf(tn, sizeof tn, "edit/%s/%s", name, keep ? "keep" : "discard");
        pair pr;
        int ok = pair_make(&pr, s, keep, why, sizeof why);
        tl_rng r = {0xed17 + s->n + (uint64_t)keep};
        uint64_t kept = 0;
        size_t h0 = 0;
        uint32_t *hl = NULL;
        if (ok && dd_hidden(pr.t, &hl, &h0) != DD_OK) h0 = 0;
        free(hl);
        int go = 1;
        if (ok && (ok = move_steps(&pr, &r, nmoves, &kept, why, sizeof why)) < 0) ok = 1, go = 0;
        static const double fr[] = {0.03, 0.3, 0.6};
        for (int round = 0; round < 3 && ok && go; round++) {
            for (int course = 0; course <= 2 && ok; course++) {
#ifndef DD_TEST_BUILD
                if (course) continue;
#endif
                ok = set_step(&pr, &r, fr[round] * (course == 2 ? 0.5 : 1), course, why, sizeof why);
            }
            if (ok && (ok = move_steps(&pr, &r, nmoves / 3, &kept, why, sizeof why)) < 0) ok = 1, go = 0;
        }
        tl_check(st, ok, tn, "%s", why);
        if (ok) fprintf(stderr, "  %s: %zu hidden at first, %llu moves kept by the filter\n", tn, h0,
                        (unsigned long long)kept);
        pair_free(&pr);
    }
}

/* The relocation filter runs: tiny moves on a set with few hidden
 * points are mostly kept in place.                                     */
static void filter_case(tl_state *st)
{
    wset s = gen_uniform(small ? 300 : 1000, 0.01, 77);
    char why[256] = "";
    for (int keep = 1; keep >= 0; keep--) {
        pair pr;
        int ok = pair_make(&pr, &s, keep, why, sizeof why);
        tl_rng r = {99};
        uint64_t kept = 0;
        uint32_t tried = 0;
        dd_counters c0, c1;
        if (ok) dd_get_counters(pr.t, &c0);
        for (uint32_t m = 0; m < 60 && ok; m++) {
            const uint32_t v = pick(pr.t, &r, 1);
            double p[3], w;
            make_move(&pr, &r, MV_SMALL, v, p, &w);
            w *= 1.0 + 1e-6 * (tl_unif(&r) - 0.5);
            const dd_status ds = dd_move_weighted(pr.t, v, p, w);
            const int cr = dd_cgal_rt_move(pr.c, v, p, w);
            tried++;
            if (ds != DD_OK || cr != 0) ok = 0, snprintf(why, sizeof why, "move %u: %s, CGAL %d", v, dd_status_name(ds), cr);
            else ok = agree(&pr, "small move", why, sizeof why);
            memcpy(pr.p + 3 * (size_t)v, p, sizeof p);
            pr.w[v] = w;
        }
        if (ok) dd_get_counters(pr.t, &c1), kept = c1.moves_kept - c0.moves_kept;
        if (ok && kept * 2 < tried) ok = 0, snprintf(why, sizeof why, "the filter kept %llu of %u tiny moves",
                                                   (unsigned long long)kept, tried);
        tl_check(st, ok, keep ? "filter/keep" : "filter/discard", "%s", why);
        pair_free(&pr);
    }
    ws_free(&s);
}

/* ---- moves whose removal would leave a plane ------------------------------------ */

/* Apex 13 over the 3x3 grid {0,2,4}^2 on z = 0 (weight 0) with four
 * hidden points on that plane (weight -3); or (tet) apex 3 over the
 * triangle (0,0,0), (4,0,0), (0,4,0) with a hidden point on its plane
 * and one above it: removing the apex first leaves only coplanar
 * points, or 3 vertices.                                               */
static wset apex_set(int tet)
{
    wset s = {0};
    if (tet) {
        ws_add(&s, 0, 0, 0, 0), ws_add(&s, 4, 0, 0, 0), ws_add(&s, 0, 4, 0, 0);
        ws_add(&s, 0.5, 0.5, 4, 0);
        ws_add(&s, 1, 1, 0, -10);
        ws_add(&s, 1, 1, 0.5, -10);
        return s;
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) ws_add(&s, 2 * i, 2 * j, 0, 0);
    ws_add(&s, 1, 0.5, 0, -3), ws_add(&s, 3.5, 1, 0, -3), ws_add(&s, 3, 3.5, 0, -3), ws_add(&s, 0.5, 3, 0, -3);
    ws_add(&s, 2, 2, 2, 0);
    return s;
}

/* Each move of the apex, from a fresh pair, against CGAL's remove()
 * (which drops the dimension) then insert (dd_cgal_rt_move_any_dim):
 * the same cells and hidden set, or, when the moved set is coplanar,
 * DD_ERR_DIMENSION with nothing changed as CGAL ends in 2D, or onto
 * another vertex's weighted point DD_ERR_DUPLICATE as CGAL; in both
 * hidden modes.                                                        */
static void apex_case(tl_state *st, int tet, int keep)
{
    static const double mv[][4] = {
        {2, 2, -2, 0},  {2, 2, 3, -1},  {1, 1, 1, 5},   {3.5, 1, -0.25, 0}, {2, 2, 0, 0},
        {1, 0.5, 0, 10}, {1, 0.5, 0, -3}, {0.5, 0.5, -4, 0}, {1, 1, -3, 2}, {2, 2, 2, 1},   {4, 0, 0, 0},
    };
    const uint32_t apex = tet ? 3 : 13;
    char tn[160], why[256] = "";
    snprintf(tn, sizeof tn, "apex/%s/%s", tet ? "tet" : "grid", keep ? "keep" : "discard");
    uint32_t done = 0, refused = 0;
    int ok = 1;
    for (size_t k = 0; k < sizeof mv / sizeof *mv && ok; k++) {
        wset s = apex_set(tet);
        pair pr;
        ok = pair_make(&pr, &s, keep, why, sizeof why);
        if (!ok) break;
        shot before = take_shot(pr.t);
        const dd_status ds = dd_move_weighted(pr.t, apex, mv[k], mv[k][3]);
        const int cr = dd_cgal_rt_move_any_dim(pr.c, apex, mv[k], mv[k][3]);
        char what[96];
        snprintf(what, sizeof what, "move to (%g %g %g; %g)", mv[k][0], mv[k][1], mv[k][2], mv[k][3]);
        if (cr == 2) {                               /* another vertex's weighted point */
            ok = ds == DD_ERR_DUPLICATE && unchanged(pr.t, &before) && checked(pr.t, why, sizeof why);
            if (!ok && !why[0]) snprintf(why, sizeof why, "%s: %s (%s), CGAL a duplicate", what, dd_status_name(ds),
                                         dd_errmsg(pr.t));
            refused++;
        } else if (cr == 3) {
            ok = ds == DD_ERR_DIMENSION && unchanged(pr.t, &before) && checked(pr.t, why, sizeof why);
            if (!ok && !why[0]) snprintf(why, sizeof why, "%s: %s (%s), CGAL ends in 2D", what, dd_status_name(ds),
                                         dd_errmsg(pr.t));
            refused++;
        } else if (ds != DD_OK || cr != 0) {
            ok = 0, snprintf(why, sizeof why, "%s: %s (%s), CGAL %d", what, dd_status_name(ds), dd_errmsg(pr.t), cr);
        } else {
            ok = agree(&pr, what, why, sizeof why);
            done++;
        }
        shot_free(&before);
        pair_free(&pr);
        ws_free(&s);
    }
    if (ok && (!done || !refused)) ok = 0, snprintf(why, sizeof why, "%u moves made, %u refused: want both", done, refused);
    tl_check(st, ok, tn, "%s", why);
    if (ok) fprintf(stderr, "  %s: %u moves as CGAL's, %u refused alike\n", tn, done, refused);
}

#ifdef DD_TEST_BUILD
/* Each allocation of an apex move through the rebuild refused in turn:
 * DD_ERR_NOMEM with nothing changed, then the move equals CGAL's.     */
static void apex_fault_case(tl_state *st, int tet, int keep)
{
    static const double to[2][4] = {{2, 2, -2, 0}, {1, 1, -3, 2}};
    const uint32_t apex = tet ? 3 : 13;
    char tn[160], why[256] = "", msg[256];
    snprintf(tn, sizeof tn, "fault/apex/%s/%s", tet ? "tet" : "grid", keep ? "keep" : "discard");
    wset s = apex_set(tet);
    dd_cgal_rt *c = dd_cgal_rt_build(s.p, s.w, s.n, !keep);
    const int cr = dd_cgal_rt_move_any_dim(c, apex, to[tet], to[tet][3]);
    long nomem = 0, bad = cr != 0;
    for (long k = 1; k < 100000 && !bad; k++) {
        dd_tri *t = NULL;
        dd_create_ex(&t, s.p, s.w, s.n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg);
        shot before = take_shot(t);
        dd_test_control(NULL, DD_TEST_ALLOC_FAIL, k);
        const dd_status ds = dd_move_weighted(t, apex, to[tet], to[tet][3]);
        const long left = dd_test_control(NULL, DD_TEST_ALLOC_FAIL, 0);
        int ok = 1;
        why[0] = 0;
        if (ds == DD_ERR_NOMEM) {
            nomem++;
            ok = unchanged(t, &before) && checked(t, why, sizeof why);
            if (!ok && !why[0]) snprintf(why, sizeof why, "allocation %ld: changed by the failure", k);
            if (ok && dd_move_weighted(t, apex, to[tet], to[tet][3]) != DD_OK)
                ok = 0, snprintf(why, sizeof why, "allocation %ld: retry failed", k);
        } else if (ds != DD_OK) {
            ok = 0, snprintf(why, sizeof why, "allocation %ld: %s (%s)", k, dd_status_name(ds), dd_errmsg(t));
        }
        if (ok) ok = checked(t, why, sizeof why) && same_as_cgal(t, c, why, sizeof why);
        if (!ok && !bad++) fprintf(stderr, "  %s: %s\n", tn, why);
        shot_free(&before);
        dd_free(t);
        if (left > 0) break;
    }
    tl_check(st, bad == 0 && nomem > 0, tn, "%ld bad of %ld refusals (CGAL %d)", bad, nomem, cr);
    dd_cgal_rt_free(c);
    ws_free(&s);
}
#endif

/* The flips course (flip.c with power tests): moves by 5% of the
 * spacing, weight kept (dd_move), and re-weightings in place by a
 * factor in [0.9, 1.1), as the wedits bench makes them, each compared
 * with CGAL's remove then insert; on uniform points some are repaired
 * by flips, kept hidden points re-homed in the cells flipped.          */
static void flips_case(tl_state *st, const char *name, const wset *s, int need_flips)
{
    for (int keep = 1; keep >= 0; keep--) {
        char tn[160], why[256] = "";
        snprintf(tn, sizeof tn, "flips/%s/%s", name, keep ? "keep" : "discard");
        pair pr;
        int ok = pair_make(&pr, s, keep, why, sizeof why);
        tl_rng r = {0xf11b + s->n + (uint64_t)keep};
        dd_counters c0, c1;
        if (ok) dd_get_counters(pr.t, &c0);
        const uint32_t steps = small ? 60 : 240;
        for (uint32_t m = 0; m < steps && ok; m++) {
            const uint32_t v = pick(pr.t, &r, 1);
            if (v == UINT32_MAX) break;
            double p[3], w = pr.w[v];
            memcpy(p, pr.p + 3 * (size_t)v, sizeof p);
            if (m % 2) {
                w *= 0.9 + 0.2 * tl_unif(&r);
            } else {
                for (int c = 0; c < 3; c++) p[c] += 0.05 * pr.h * (2 * tl_unif(&r) - 1);
            }
            const dd_status ds = m % 2 ? dd_move_weighted(pr.t, v, p, w) : dd_move(pr.t, v, p);
            const int cr = dd_cgal_rt_move(pr.c, v, p, w);
            if (ds == DD_ERR_DUPLICATE && cr == 2) continue;
            if (ds != DD_OK || cr != 0) {
                ok = 0, snprintf(why, sizeof why, "move %u: %s, CGAL %d", v, dd_status_name(ds), cr);
                break;
            }
            memcpy(pr.p + 3 * (size_t)v, p, sizeof p);
            pr.w[v] = w;
            ok = agree(&pr, m % 2 ? "re-weighting" : "5% move", why, sizeof why);
        }
        uint64_t flipped = 0, redone = 0;
        if (ok) {
            dd_get_counters(pr.t, &c1);
            flipped = c1.moves_flipped - c0.moves_flipped, redone = c1.moves_redone - c0.moves_redone;
        }
        if (ok && need_flips && flipped == 0) ok = 0, snprintf(why, sizeof why, "no move was repaired by flips");
        tl_check(st, ok, tn, "%s", why);
        if (ok) fprintf(stderr, "  %s: %llu moves by flips, %llu by removal and insertion\n", tn,
                        (unsigned long long)flipped, (unsigned long long)redone);
        pair_free(&pr);
    }
}

/* Where v's move to q inverts a cell of its star: q just past the plane
 * of the link facet nearest v (its cell's distance from v times 1.1
 * from v), or 0 when that facet is farther than 0.2 h (the move would
 * not be small).                                                      */
static int past_link(const pair *pr, uint32_t v, double q[3])
{
    int32_t *tets = NULL;
    size_t nt = 0;
    if (dd_local_canonical(pr->t, &v, 1, &tets, &nt) != DD_OK) return 0;
    const double *x = pr->p + 3 * (size_t)v;
    double best = INFINITY;
    for (size_t k = 0; k < nt; k++) {
        const int32_t *c = tets + 4 * k;
        const double *a[4];
        int na = 0;
        for (int j = 0; j < 4; j++)
            if (c[j] >= 0 && (uint32_t)c[j] != v) a[na++] = pr->p + 3 * (size_t)c[j];
        if (na != 3) continue;                 /* a hull cell */
        double e1[3], e2[3], n[3];
        for (int j = 0; j < 3; j++) e1[j] = a[1][j] - a[0][j], e2[j] = a[2][j] - a[0][j];
        n[0] = e1[1] * e2[2] - e1[2] * e2[1], n[1] = e1[2] * e2[0] - e1[0] * e2[2], n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        if (!(nn > 0)) continue;
        const double d = ((x[0] - a[0][0]) * n[0] + (x[1] - a[0][1]) * n[1] + (x[2] - a[0][2]) * n[2]) / sqrt(nn);
        if (fabs(d) >= best) continue;
        best = fabs(d);
        for (int j = 0; j < 3; j++) q[j] = x[j] - 1.1 * d * n[j] / sqrt(nn);
    }
    free(tets);
    return best <= 0.2 * pr->h;
}

/* Moves that invert a cell of the moved vertex's star (past_link): the
 * flip course takes them when flipping that cell away first (flip.c's
 * unturn) leaves a positive star, else the removal and insertion do.
 * Both modes, each step equal to CGAL; some of these moves must be done
 * by flips (the flip course took none of them before unturn).         */
static void turn_case(tl_state *st)
{
    wset s = gen_uniform(small ? 300 : 1000, 1, 81);
    for (int keep = 1; keep >= 0; keep--) {
        char tn[64], why[256] = "";
        snprintf(tn, sizeof tn, "turn/uniform-w1/%s", keep ? "keep" : "discard");
        pair pr;
        int ok = pair_make(&pr, &s, keep, why, sizeof why);
        tl_rng r = {0x7e11 + (uint64_t)keep};
        uint64_t moved = 0, flipped = 0;
        const uint32_t steps = small ? 80 : 300;
        for (uint32_t m = 0; m < steps && ok; m++) {
            const uint32_t v = pick(pr.t, &r, 1);
            double q[3];
            if (v == UINT32_MAX) break;
            if (!past_link(&pr, v, q)) continue;
            dd_counters c0, c1;
            dd_get_counters(pr.t, &c0);
            const dd_status ds = dd_move(pr.t, v, q);
            const int cr = dd_cgal_rt_move(pr.c, v, q, pr.w[v]);
            if (ds == DD_ERR_DUPLICATE && cr == 2) continue;
            if (ds != DD_OK || cr != 0) {
                ok = 0, snprintf(why, sizeof why, "move %u: %s, CGAL %d", v, dd_status_name(ds), cr);
                break;
            }
            dd_get_counters(pr.t, &c1);
            memcpy(pr.p + 3 * (size_t)v, q, sizeof q);
            moved++, flipped += c1.moves_flipped - c0.moves_flipped;
            ok = agree(&pr, "a move past a link facet", why, sizeof why);
        }
        if (ok && flipped == 0)
            ok = 0, snprintf(why, sizeof why, "none of %llu moves past a link facet was done by flips",
                             (unsigned long long)moved);
        tl_check(st, ok, tn, "%s", why);
        if (ok) fprintf(stderr, "  %s: %llu of %llu moves by flips\n", tn, (unsigned long long)flipped, (unsigned long long)moved);
        pair_free(&pr);
    }
    ws_free(&s);
}

/* Power ties in the relocation filter (flip.c's star_test_power): an
 * integer grid with one weight, so that the corners of every cube lie
 * on one power sphere.  Each step moves a vertex off its grid point and
 * back, or re-weights it and back: on the way back every power test of
 * its star against an apex of a cube it shares is exactly 0, which the
 * filter must leave to Lawson's exact, perturbed tests (a filter that
 * certified a 0 would keep a facet CGAL's perturbation flips).  Both
 * modes, each step compared with CGAL's remove then insert.            */
static void ties_case(tl_state *st)
{
    const int side = small ? 4 : 6;
    wset s = {0};
    for (int z = 0; z < side; z++)
        for (int y = 0; y < side; y++)
            for (int x = 0; x < side; x++) ws_add(&s, x, y, z, 0.25);
    for (int keep = 1; keep >= 0; keep--) {
        char tn[160], why[256] = "";
        snprintf(tn, sizeof tn, "flips/ties/%s", keep ? "keep" : "discard");
        pair pr;
        int ok = pair_make(&pr, &s, keep, why, sizeof why);
        tl_rng r = {0x7135 + (uint64_t)keep};
        const uint32_t steps = small ? 40 : 160;
        for (uint32_t m = 0; m < steps && ok; m++) {
            const uint32_t v = (uint32_t)tl_int(&r, 0, (int64_t)s.n - 1);
            const double *g = s.p + 3 * (size_t)v;
            double p[3] = {g[0], g[1], g[2]}, w = 0.25;
            if (m % 2) w *= 0.9 + 0.2 * tl_unif(&r);
            else
                for (int c = 0; c < 3; c++) p[c] += 0.05 * (2 * tl_unif(&r) - 1);
            for (int back = 0; back < 2 && ok; back++) {
                const double *q = back ? g : p, wq = back ? 0.25 : w;
                const dd_status ds = m % 2 ? dd_move_weighted(pr.t, v, q, wq) : dd_move(pr.t, v, q);
                const int cr = dd_cgal_rt_move(pr.c, v, q, wq);
                if (ds != DD_OK || cr != 0) {
                    ok = 0, snprintf(why, sizeof why, "step %u of %u: %s, CGAL %d", m, v, dd_status_name(ds), cr);
                    break;
                }
                ok = agree(&pr, back ? "back on the grid" : "off the grid", why, sizeof why);
            }
        }
        tl_check(st, ok, tn, "%s", why);
        pair_free(&pr);
    }
    ws_free(&s);
}

/* ---- refusals ---------------------------------------------------------------------- */

static void refusals_case(tl_state *st)
{
    wset s = gen_uniform(small ? 200 : 500, 3, 9);
    char why[256] = "";
    pair pr;
    if (!pair_make(&pr, &s, 1, why, sizeof why)) {
        tl_check(st, 0, "wrefuse/setup", "%s", why);
        ws_free(&s);
        return;
    }
    dd_tri *t = pr.t;
    tl_rng r = {5};
    const uint32_t v = pick(t, &r, 1), u = pick(t, &r, 1), hp = pick(t, &r, 2);
    double p[3], pu[3], wu, wv;
    dd_point(t, v, p);
    dd_weight(t, v, &wv);
    dd_point(t, u, pu);
    dd_weight(t, u, &wu);
    const double bad[3] = {NAN, 0, 0}, inf[3] = {0, INFINITY, 0};
    shot before = take_shot(t);
    struct { const char *name; dd_status got, want; } cases[] = {
        {"move-nan-weight", dd_move_weighted(t, v, p, NAN), DD_ERR_NAN},
        {"move-inf-weight", dd_move_weighted(t, v, p, -INFINITY), DD_ERR_INFINITE},
        {"move-nan-point", dd_move_weighted(t, v, bad, 0), DD_ERR_NAN},
        {"move-inf-point", dd_move(t, v, inf), DD_ERR_INFINITE},
        {"move-unknown", dd_move_weighted(t, s.n + 3, p, 0), DD_ERR_UNKNOWN_VERTEX},
        {"move-onto-vertex", dd_move_weighted(t, v, pu, wu), DD_ERR_DUPLICATE},
        {"move-own-point", dd_move_weighted(t, v, p, wv), DD_OK},
        {"reinsert-vertex", dd_reinsert(t, v), DD_ERR_DUPLICATE},
        {"reinsert-hidden", hp != UINT32_MAX ? dd_reinsert(t, hp) : DD_ERR_DUPLICATE, DD_ERR_DUPLICATE},
        {"set-twice", dd_delete_set(t, (uint32_t[]){v, u, v}, 3), DD_ERR_ARG},
        {"set-unknown", dd_delete_set(t, (uint32_t[]){v, s.n + 9}, 2), DD_ERR_UNKNOWN_VERTEX},
    };
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        char tn[160];
        snprintf(tn, sizeof tn, "wrefuse/%s", cases[k].name);
        tl_check(st, cases[k].got == cases[k].want && unchanged(t, &before) && (cases[k].want == DD_OK || dd_errmsg(t)[0]),
                 tn, "status %s (want %s), errmsg '%s'", dd_status_name(cases[k].got), dd_status_name(cases[k].want),
                 dd_errmsg(t));
    }
    tl_check(st, checked(t, why, sizeof why), "wrefuse/check-after", "%s", why);
    /* a kept hidden point deleted: forgotten, no cell changes */
    if (hp != UINT32_MAX) {
        int32_t *c0 = NULL, *c1 = NULL;
        size_t n0 = 0, n1 = 0;
        dd_canonical(t, &c0, &n0);
        const dd_status ds = dd_delete(t, hp);
        dd_canonical(t, &c1, &n1);
        const int ok = ds == DD_OK && !dd_is_hidden(t, hp) && dd_cgal_rt_forget(pr.c, hp) == 0 && n0 == n1 &&
                       !memcmp(c0, c1, 4 * n0 * sizeof *c0) && agree(&pr, "forget", why, sizeof why);
        tl_check(st, ok, "wdelete/hidden-point", "%s %s", dd_status_name(ds), why);
        free(c0), free(c1);
    }
    tl_check(st, hp != UINT32_MAX, "wrefuse/has-hidden", "no hidden point to try");
    /* an unweighted t refuses dd_move_weighted */
    dd_tri *u0 = NULL;
    if (dd_create(&u0, s.p, s.n, NULL, 0) == DD_OK) {
        shot b0 = take_shot(u0);
        const dd_status ds = dd_move_weighted(u0, 0, p, 1);
        tl_check(st, ds == DD_ERR_UNSUPPORTED && unchanged(u0, &b0), "wrefuse/unweighted", "%s", dd_status_name(ds));
        shot_free(&b0);
        dd_free(u0);
    }
    shot_free(&before);
    pair_free(&pr);
    ws_free(&s);
}

/* ---- allocation failures --------------------------------------------------------------- */

#ifdef DD_TEST_BUILD
enum { OP_SET_EACH, OP_SET_REBUILD, OP_REINSERT, OP_MOVE_SMALL, OP_MOVE_FAR, OP_MOVE_HIDDEN, OP_REWEIGHT, NOPS };
static const char *const op_name[NOPS] = {"set-each", "set-rebuild", "reinsert", "move-small", "move-far",
                                          "move-hidden", "reweight"};

typedef struct op_args {
    uint32_t set[64], nset, v;
    double p[3], w;
} op_args;

static dd_status run_op(dd_tri *t, int op, const op_args *a)
{
    switch (op) {
    case OP_SET_EACH:
    case OP_SET_REBUILD: {
        dd_test_control(t, DD_TEST_SET_COURSE, op == OP_SET_EACH ? 1 : 2);
        const dd_status s = dd_delete_set(t, a->set, a->nset);
        dd_test_control(t, DD_TEST_SET_COURSE, 0);
        return s;
    }
    case OP_REINSERT: return dd_reinsert(t, a->v);
    default: return dd_move_weighted(t, a->v, a->p, a->w);
    }
}

static void cgal_op(dd_cgal_rt *c, int op, const op_args *a)
{
    if (op == OP_SET_EACH || op == OP_SET_REBUILD)
        for (uint32_t k = 0; k < a->nset; k++) cgal_delete(c, a->set[k]);
    else if (op == OP_REINSERT)
        dd_cgal_rt_insert_as(c, a->p, a->w, a->v);
    else
        dd_cgal_rt_move(c, a->v, a->p, a->w);
}

/* The triangulation an op starts from: the set built, and for a
 * re-insertion its point deleted first (in CGAL too).                 */
static dd_tri *start_of(const wset *s, int keep, int op, const op_args *a)
{
    dd_tri *t = NULL;
    char msg[256];
    dd_create_ex(&t, s->p, s->w, s->n, keep ? 0 : DD_DISCARD_HIDDEN, msg, sizeof msg);
    if (op == OP_REINSERT) dd_delete(t, a->v);
    return t;
}

/* An op as a ws_fault_call (testweighted.h). */
typedef struct fault_arg {
    const wset *s;
    int keep, op;
    const op_args *a;
} fault_arg;

static dd_tri *fault_start(const void *arg)
{
    const fault_arg *f = arg;
    return start_of(f->s, f->keep, f->op, f->a);
}

static dd_status fault_run(dd_tri *t, const void *arg, long k)
{
    const fault_arg *f = arg;
    (void)k;
    return run_op(t, f->op, f->a);
}

static void fault_op(tl_state *st, const wset *s, int keep, int op)
{
    char tn[160];
    snprintf(tn, sizeof tn, "fault/%s/%s", op_name[op], keep ? "keep" : "discard");
    op_args a = {0};
    dd_tri *t = start_of(s, keep, -1, &a);
    tl_rng r = {0xfa17 + (uint64_t)op};
    pair tmp = {t, NULL, keep, pow((double)s->n, -1.0 / 3), s->p, s->w};
    if (op == OP_SET_EACH || op == OP_SET_REBUILD) {
        const uint32_t want = op == OP_SET_EACH ? 6 : 40;
        while (a.nset < want) {
            const uint32_t v = pick(t, &r, keep ? 3 : 1);
            int seen = 0;
            for (uint32_t k = 0; k < a.nset; k++) seen |= a.set[k] == v;
            if (!seen) a.set[a.nset++] = v;
        }
    } else {
        a.v = pick(t, &r, op == OP_MOVE_HIDDEN ? 2 : 1);
        const int kind = op == OP_MOVE_SMALL ? MV_SMALL : op == OP_MOVE_FAR ? MV_LARGE : op == OP_REWEIGHT ? MV_UP : MV_HIDDEN;
        if (a.v != UINT32_MAX) make_move(&tmp, &r, kind, a.v, a.p, &a.w);
        if (op == OP_REINSERT) dd_point(t, a.v, a.p), dd_weight(t, a.v, &a.w);
    }
    dd_free(t);
    if (op != OP_SET_EACH && op != OP_SET_REBUILD && a.v == UINT32_MAX) {
        tl_check(st, !keep || op != OP_MOVE_HIDDEN, tn, "no point to use");
        return;
    }
    dd_cgal_rt *c = dd_cgal_rt_build(s->p, s->w, s->n, !keep);
    if (op == OP_REINSERT) dd_cgal_rt_remove(c, a.v);
    cgal_op(c, op, &a);
    const fault_arg fa = {s, keep, op, &a};
    const ws_fault_call call = {fault_start, fault_run, &fa};
    long bad;
    const long nomem = ws_fault_each(tn, &call, c, &bad);
    tl_check(st, bad == 0, tn, "%ld bad of %ld refusals", bad, nomem);
    fprintf(stderr, "  %s: %ld allocations refused in turn\n", tn, nomem);
    dd_cgal_rt_free(c);
}

static void fault_case(tl_state *st)
{
    wset s = gen_uniform(small ? 80 : 150, 3, 21);
    for (int keep = 1; keep >= 0; keep--)
        for (int op = 0; op < NOPS; op++)
            if (keep || op != OP_MOVE_HIDDEN) fault_op(st, &s, keep, op);
    ws_free(&s);
}
#endif

int main(int argc, char **argv)
{
    small = argc > 1 && !strcmp(argv[1], "small");
    tl_state st = {0, 0};
    const uint32_t n = small ? 250 : 1200, nm = small ? 30 : 120;
    const double scales[] = {0.01, 1, 10};
    for (size_t k = 0; k < sizeof scales / sizeof *scales; k++) {
        char name[64];
        snprintf(name, sizeof name, "uniform-w%g", scales[k]);
        wset s = gen_uniform(n, scales[k], 300 + k);
        edit_case(&st, name, &s, nm);
        ws_free(&s);
    }
    wset s = gen_grid(small ? 4 : 6, small ? 30 : 100, 1, 8);
    edit_case(&st, "grid-dups", &s, nm);
    ws_free(&s);
    s = gen_molecule(small ? 5 : 8, 2);
    edit_case(&st, "molecule", &s, nm);
    ws_free(&s);
    s = gen_protecting(small ? 30 : 80, small ? 100 : 400, 3);
    edit_case(&st, "protecting", &s, nm);
    ws_free(&s);
    s = gen_curve(small ? 80 : 200, 0, 4);
    edit_case(&st, "moment-curve", &s, nm);
    ws_free(&s);
    s = gen_curve(small ? 200 : 800, 1, 5);
    edit_case(&st, "helix", &s, nm);
    ws_free(&s);
    filter_case(&st);
    for (int keep = 1; keep >= 0; keep--)
        for (int tet = 0; tet <= 1; tet++) {
            apex_case(&st, tet, keep);
#ifdef DD_TEST_BUILD
            apex_fault_case(&st, tet, keep);
#endif
        }
    s = gen_uniform(small ? 300 : 1000, 1, 78);
    flips_case(&st, "uniform-w1", &s, 1);
    ws_free(&s);
    s = gen_uniform(small ? 300 : 1000, 10, 79);
    flips_case(&st, "uniform-w10", &s, 1);
    ws_free(&s);
    s = gen_grid(small ? 4 : 6, small ? 30 : 100, 1, 8);
    flips_case(&st, "grid-dups", &s, 0);
    ws_free(&s);
    turn_case(&st);
    ties_case(&st);
    refusals_case(&st);
    copies_case(&st);
    course_case(&st);
#ifdef DD_TEST_BUILD
    fault_case(&st);
#endif
    return tl_finish(&st);
}
