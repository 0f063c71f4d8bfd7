/*
 * test_delete.c -- every deletion strategy equals CGAL after every deletion
 * (DESIGN 6 and 8): single deletions from DT(S) on every dataset, hull and
 * degenerate cases included, long sequences, delete-then-reinsert, refused
 * deletions that must leave the triangulation unchanged, and cgal-rnd
 * against CGAL's own remove().  The validator runs after each deletion.
 */
#include "testlib.h"
#include <math.h>
#include "dtdel.h"
#include "wrap/wrap.h"
#include "cgal/cgal_shim.h"
#include "../datasets/datasets.h"

typedef struct canon { int32_t *a; size_t n; } canon;

static canon ours(const dd_tri *t)
{
    canon c = {NULL, 0};
    if (dd_canonical(t, &c.a, &c.n) != DD_OK) c.n = (size_t)-1;
    return c;
}

static canon theirs(const dd_cgal *g)
{
    canon c = {NULL, 0};
    if (dd_cgal_canonical(g, &c.a, &c.n)) c.n = (size_t)-1;
    return c;
}

static int same(canon x, canon y)
{
    return x.n == y.n && x.n != (size_t)-1 && !memcmp(x.a, y.a, 4 * x.n * sizeof *x.a);
}

/* Per-variant tallies over many deletions, reported once per dataset. */
typedef struct tally { long total, bad; char why[200]; } tally;

static void fail_once(tally *t, const char *fmt, uint32_t v, const char *extra)
{
    if (t->bad++ == 0) snprintf(t->why, sizeof t->why, fmt, v, extra);
}

#define MAXVAR 16

/* Deletes k sampled vertices (`first` unless UINT32_MAX, then hull ones,
 * then random), each from DT(S), with every variant, comparing with CGAL;
 * reinserting restores.  Each variant takes every course in turn
 * (testlib.h): all of them once k is at least TL_NCOURSES.              */
static void single_deletions(tl_state *st, const char *name, const double *pts, uint32_t n,
                             uint32_t k, uint64_t seed, int check_every, uint32_t first)
{
    char msg[256];
    dd_tri *t;
    if (dd_create(&t, pts, n, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, name, "dd_create: %s", msg);
        return;
    }
    dd_cgal *g = dd_cgal_build(pts, n);
    canon orig = ours(t);
    tally tv[MAXVAR + 1];
    memset(tv, 0, sizeof tv);
    tl_courses cs[MAXVAR + 1];
    for (size_t vi = 0; vi <= MAXVAR; vi++) cs[vi] = tl_courses_all();
    tally rnd = {0, 0, ""}, reins = {0, 0, ""};
    tl_rng r = {seed};
    uint32_t hull_seen = 0;
    for (uint32_t it = 0; it < k; it++) {
        uint32_t v = (uint32_t)tl_int(&r, 0, n - 1);
        if (it == 0 && first != UINT32_MAX) v = first;
        else if (!dd_is_vertex(t, v)) continue;
        else if (it < k / 4) {   /* prefer hull vertices for a quarter of the sample */
            for (int tries = 0; tries < 50 && !dd_on_hull(t, v); tries++) {
                v = (uint32_t)tl_int(&r, 0, n - 1);
                while (!dd_is_vertex(t, v)) v = (v + 1) % n;
            }
        }
        hull_seen += (uint32_t)dd_on_hull(t, v);
        int cg = dd_cgal_remove(g, v);
        canon ref = theirs(g);
        int refused = cg != 0;
        if (!refused) dd_cgal_reinsert(g, v);
        if (!refused) {
            dd_cgal_remove_rnd(g, v, seed + it);
            canon c2 = theirs(g);
            rnd.total++;
            if (!same(ref, c2)) fail_once(&rnd, "cgal-rnd differs from cgal deleting %u%s", v, "");
            free(c2.a);
            dd_cgal_reinsert(g, v);
        }
        for (size_t vi = 0; dd_variant_name(vi) && vi < MAXVAR; vi++) {
            const char *var = dd_variant_name(vi);
            tally *ta = &tv[vi];
            ta->total++;
            tl_course_next(&cs[vi], t);
            dd_status s = dd_delete_with(t, v, var);
            if (refused) {
                canon now = ours(t);
                if (s != DD_ERR_DIMENSION || !same(now, orig))
                    fail_once(ta, "CGAL refuses deleting %u but we did not (or changed the DT): %s", v, dd_errmsg(t));
                free(now.a);
                continue;
            }
            if (s != DD_OK) {
                fail_once(ta, "deleting %u failed: %s", v, dd_errmsg(t));
                continue;
            }
            canon now = ours(t);
            if (!same(now, ref)) fail_once(ta, "deleting %u: result differs from CGAL's%s", v, "");
            /* GRR variants delete every finite neighbour but the 4 base
             * points from the link: the counters must say so.             */
            dd_delete_stats dst;
            dd_last_delete_stats(t, &dst);
            if (!strncmp(var, "grr-", 4) || !strcmp(var, "guide-only")) {
                uint32_t sum = 0, finite = dst.degree - (uint32_t)dst.on_hull;
                for (int b = 0; b < DD_LINKDEG_BUCKETS; b++) sum += dst.link_deletions[b];
                if (!dst.forced_fill && finite > 4 && sum != finite - 4)
                    fail_once(ta, "deleting %u: %s link deletions counted", v, "wrong number of");
            }
            free(now.a);
            char why[150];
            if (check_every && dd_check_msg(t, why, sizeof why) != DD_OK)
                fail_once(ta, "deleting %u: validator: %s", v, why);
            reins.total++;
            if (dd_reinsert(t, v) != DD_OK) {
                fail_once(&reins, "reinserting %u failed: %s", v, dd_errmsg(t));
                continue;
            }
            canon back = ours(t);
            if (!same(back, orig)) fail_once(&reins, "delete + reinsert of %u does not restore DT(S)%s", v, "");
            free(back.a);
        }
        free(ref.a);
    }
    char tn[160];
    for (size_t vi = 0; dd_variant_name(vi) && vi < MAXVAR; vi++) {
        snprintf(tn, sizeof tn, "delete/%s/%s", name, dd_variant_name(vi));
        char unrun[96] = "";
        int covered = tv[vi].total < TL_NCOURSES || tl_courses_covered(&cs[vi], unrun, sizeof unrun);
        tl_check(st, tv[vi].bad == 0 && tv[vi].total > 0 && covered, tn, "%ld of %ld deletions wrong; first: %s%s",
                 tv[vi].bad, tv[vi].total, tv[vi].why, unrun);
    }
    snprintf(tn, sizeof tn, "delete/%s/cgal-rnd-equals-cgal", name);
    tl_check(st, rnd.bad == 0, tn, "%ld of %ld differ; first: %s", rnd.bad, rnd.total, rnd.why);
    snprintf(tn, sizeof tn, "delete/%s/reinsert-restores", name);
    tl_check(st, reins.bad == 0 && reins.total > 0, tn, "%ld of %ld; first: %s", reins.bad, reins.total, reins.why);
    printf("# %s: %u hull vertices among the sampled\n", name, hull_seen);
    free(orig.a);
    dd_cgal_free(g);
    dd_free(t);
}

/* Deletes `count` vertices one after another (no reinsertion) with one
 * variant, comparing with CGAL every `every` deletions and at the end;
 * every course in turn.                                                 */
static void sequence(tl_state *st, const char *name, const double *pts, uint32_t n, uint32_t count,
                     uint32_t every, const char *var, uint64_t seed)
{
    char msg[256], tn[160];
    dd_tri *t;
    if (dd_create(&t, pts, n, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, name, "dd_create: %s", msg);
        return;
    }
    dd_cgal *g = dd_cgal_build(pts, n);
    uint32_t *perm = malloc(n * sizeof *perm);
    for (uint32_t i = 0; i < n; i++) perm[i] = i;
    tl_rng r = {seed};
    for (uint32_t i = n; i > 1; i--) {
        uint32_t j = (uint32_t)tl_int(&r, 0, i - 1), s = perm[i - 1];
        perm[i - 1] = perm[j]; perm[j] = s;
    }
    uint32_t done = 0, compared = 0;
    char why[200] = "";
    int ok = 1;
    tl_courses cs = tl_courses_all();
    for (uint32_t pass = 0; pass < 3 * n && done < count && ok; pass++) {
        uint32_t v = perm[pass % n];  /* several passes: refused ones get retried */
        if (!dd_is_vertex(t, v)) continue;
        int cg = dd_cgal_remove(g, v);
        tl_course_next(&cs, t);
        dd_status s = dd_delete_with(t, v, var);
        if (cg != 0) {   /* CGAL refuses: we must refuse too, and change nothing */
            if (s != DD_ERR_DIMENSION) { ok = 0; snprintf(why, sizeof why, "vertex %u: CGAL refuses, we say %s", v, dd_status_name(s)); }
            continue;
        }
        if (s != DD_OK) { ok = 0; snprintf(why, sizeof why, "vertex %u: %s", v, dd_errmsg(t)); break; }
        done++;
        if (done % every == 0 || done == count) {
            canon a = ours(t), b = theirs(g);
            compared++;
            if (!same(a, b)) { ok = 0; snprintf(why, sizeof why, "after %u deletions (last %u): differs from CGAL", done, v); }
            char bad[160];
            if (ok && dd_check_msg(t, bad, sizeof bad) != DD_OK) { ok = 0; snprintf(why, sizeof why, "after %u deletions: %s", done, bad); }
            free(a.a); free(b.a);
        }
    }
    snprintf(tn, sizeof tn, "sequence/%s/%s", name, var);
    ok = ok && tl_courses_covered(&cs, why, sizeof why);
    tl_check(st, ok && done == count && compared > 0, tn, "%s (%u of %u deleted, %u comparisons)", why, done, count, compared);
    free(perm);
    dd_cgal_free(g);
    dd_free(t);
}

/* dd_delete_set of a random `frac` of the vertices, with one variant:
 * the result equals CGAL after removing the same points one by one, and
 * passes the validator.                                                  */
static void delete_set(tl_state *st, const char *name, const double *pts, uint32_t n, double frac,
                       const char *var, uint64_t seed)
{
    char msg[256], tn[160], why[200] = "";
    dd_tri *t;
    if (dd_create(&t, pts, n, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, name, "dd_create: %s", msg);
        return;
    }
    dd_cgal *g = dd_cgal_build(pts, n);
    uint32_t *vs = malloc(n * sizeof *vs), m = 0;
    tl_rng r = {seed};
    for (uint32_t i = 0; i < n; i++)
        if (dd_is_vertex(t, i) && tl_unif(&r) < frac) vs[m++] = i;
    int ok = 1;
    for (uint32_t i = 0; i < m && ok; i++)
        if (dd_cgal_remove(g, vs[i])) { ok = 0; snprintf(why, sizeof why, "CGAL refuses vertex %u", vs[i]); }
    dd_status s = dd_delete_set_with(t, vs, m, var);
    if (ok && s != DD_OK) { ok = 0; snprintf(why, sizeof why, "%s", dd_errmsg(t)); }
    if (ok) {
        canon a = ours(t), b = theirs(g);
        if (!same(a, b)) { ok = 0; snprintf(why, sizeof why, "differs from CGAL"); }
        free(a.a); free(b.a);
    }
    if (ok && dd_check_msg(t, why, sizeof why) != DD_OK) ok = 0;
    snprintf(tn, sizeof tn, "delete-set/%s/%s", name, var);
    tl_check(st, ok && m > 0, tn, "%s (%u points in the set)", why, m);
    free(vs);
    dd_cgal_free(g);
    dd_free(t);
}

/* dd_delete_set refusing a set, with the status it must say and the
 * triangulation left as it was.                                         */
static void set_refused(tl_state *st, const char *name, dd_tri *t, const uint32_t *vs, size_t n, const char *var,
                        dd_status want)
{
    canon before = ours(t);
    dd_status s = dd_delete_set_with(t, vs, n, var);
    canon after = ours(t);
    char tn[160];
    snprintf(tn, sizeof tn, "delete-set-refused/%s", name);
    tl_check(st, s == want && same(before, after) && dd_check(t) == DD_OK, tn, "status %s (want %s): %s%s",
             dd_status_name(s), dd_status_name(want), dd_errmsg(t), same(before, after) ? "" : "; DT changed");
    free(before.a);
    free(after.a);
}

static double *gen(const char *ds, uint32_t n, uint32_t *np)
{
    double *p = NULL;
    char msg[256];
    if (dd_gen(ds, n, 5, &p, np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dd_gen %s: %s\n", ds, msg);
        exit(1);
    }
    return p;
}

/* n points of the unit sphere (gen) and its centre, last: *np of them.  */
static double *sphere_and_centre(uint32_t n, uint32_t *np)
{
    double *p = gen("sphere", n, np);
    p = realloc(p, 3 * sizeof *p * (*np + 1));
    p[3 * *np] = p[3 * *np + 1] = p[3 * *np + 2] = 0;
    ++*np;
    return p;
}

/* Deletes v from t with vars[0] and vars[1] in turn, in course c,
 * re-inserting it after each: their canonical results in got[k], their
 * stats in ds[k].
 * 1; 0, the reason in why, when a deletion or the re-insertion fails or
 * a result fails dd_check (the perturbed empty-sphere test of every
 * facet).  The caller frees got[k].a.                                   */
static int delete_each(dd_tri *t, uint32_t v, tl_course c, const char *const vars[2], canon got[2],
                       dd_delete_stats ds[2], char *why, size_t nwhy)
{
    for (int k = 0; k < 2; k++) {
        tl_set_course(t, c);
        dd_status s = dd_delete_with(t, v, vars[k]);
        dd_last_delete_stats(t, &ds[k]);
        got[k] = ours(t);
        dd_status chk = s == DD_OK ? dd_check(t) : DD_OK;
        if (s != DD_OK || chk != DD_OK || dd_reinsert(t, v) != DD_OK) {
            snprintf(why, nwhy, "%s: status %s, check %s", vars[k], dd_status_name(s), dd_status_name(chk));
            return 0;
        }
    }
    return 1;
}

/* auto's conflict DT from degree 40 (variants/auto.c), where the wrap
 * declines, deletes the link vertices in order of least link degree;
 * grr-neighbor in random order of degree <= 7.  Both must give CGAL's
 * result; the order of least degree must build fewer cells.  The vertex:
 * the centre of n points of a sphere, whose link has no hub, so that from
 * degree 600 auto does not try the wide guess and the conflict DT runs
 * (dtdel delete --stats shows the cells each order builds).            */
static void auto_least_degree(tl_state *st, uint32_t n)
{
    uint32_t np;
    double *p = sphere_and_centre(n, &np);
    const uint32_t v = np - 1;
    char msg[256], name[96];
    snprintf(name, sizeof name, "auto-least-degree/sphere-%u-centre", np - 1);
    dd_tri *t;
    if (dd_create(&t, p, np, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, name, "dd_create: %s", msg);
        free(p);
        return;
    }
    dd_cgal *g = dd_cgal_build(p, np);
    int cg = dd_cgal_remove(g, v);
    canon ref = theirs(g), got[2] = {{NULL, 0}, {NULL, 0}};
    const char *const vars[2] = {"auto", "grr-neighbor"};
    dd_delete_stats ds[2];
    memset(ds, 0, sizeof ds);
    char why[160] = "";
    int ok = cg == 0 && dd_degree(t, v) >= 600 && delete_each(t, v, TL_COURSE_DEFAULT, vars, got, ds, why, sizeof why);
    for (int k = 0; k < 2 && ok; k++)
        if (!same(got[k], ref) || ds[k].fallbacks != 0) {
            snprintf(why, sizeof why, "%s: %s CGAL's, %llu fallbacks", vars[k],
                     same(got[k], ref) ? "equals" : "differs from", (unsigned long long)ds[k].fallbacks);
            ok = 0;
        }
    tl_check(st, ok && ds[0].strategy[DD_WS_COURSE] == DD_WRAP_DECLINED && ds[0].tets_created < ds[1].tets_created, name,
             "%s; auto's wrap: course %d (declined: %d); cells built: least degree %llu, random %llu", why,
             ds[0].strategy[DD_WS_COURSE], DD_WRAP_DECLINED, (unsigned long long)ds[0].tets_created,
             (unsigned long long)ds[1].tets_created);
    free(got[0].a);
    free(got[1].a);
    free(ref.a);
    dd_cgal_free(g);
    dd_free(t);
    free(p);
}

/* The exact-test budget of gift wrapping (wrap_int.h, W_EXACT_FROM) weighs
 * the tests it leaves to the predicates by their cost (w_spent): on the
 * moment curve, n = 2048, a deletion's proof leaves thousands of tests
 * to the predicates, most of them settled by the predicates' filters,
 * and auto must wrap with a proved guess there, not decline to the
 * slower conflict DT.  CGAL's remove() takes seconds at this degree, so
 * the result is checked by the perturbed empty-sphere test of every
 * facet (dd_check) and against grr-neighbor's, which never wraps.      */
static void auto_wraps_dense_moment(tl_state *st, uint32_t v)
{
    uint32_t np;
    double *p = gen("moment", 2048, &np);
    char msg[256], name[64], why[160] = "";
    snprintf(name, sizeof name, "wrap-budget/moment-%u/vertex-%u", np, v);
    dd_tri *t;
    if (dd_create(&t, p, np, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, name, "dd_create: %s", msg);
        free(p);
        return;
    }
    const char *const vars[2] = {"grr-neighbor", "auto"};
    canon got[2] = {{NULL, 0}, {NULL, 0}};
    dd_delete_stats ds[2];
    memset(ds, 0, sizeof ds);
    int ok = dd_degree(t, v) >= 2000 && delete_each(t, v, TL_COURSE_DEFAULT, vars, got, ds, why, sizeof why);
    tl_check(st, ok && same(got[0], got[1]) && ds[1].strategy[DD_WS_COURSE] == DD_WRAP_PROVED, name,
             "%s; results %s; auto's wrap: course %d (proved: %d)", why, same(got[0], got[1]) ? "equal" : "differ",
             ds[1].strategy[DD_WS_COURSE], DD_WRAP_PROVED);
    free(got[0].a);
    free(got[1].a);
    dd_free(t);
    free(p);
}

/* Gift wrapping (src/wrap) builds the fill's cells and no others: the
 * cells it reports built equal the cells the deletion added, counted from
 * the mesh (a link of degree d, the infinite vertex included, is a
 * triangulated sphere: 2d - 4 star cells go).  On generic points, interior
 * and hull vertices alike, and for auto, which wraps there.
 * The result itself is CGAL's: checked by the tests above.              */
static void wrap_builds_only_fill(tl_state *st, const char *ds, uint32_t n, const char *variant)
{
    uint32_t np;
    double *p = gen(ds, n, &np);
    dd_tri *t = NULL;
    char msg[256], name[96];
    snprintf(name, sizeof name, "wrap-only-fill/%s-%u/%s", ds, np, variant);
    if (!p || dd_create(&t, p, np, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, name, "setup failed");
        free(p);
        return;
    }
    int ok = 1, tested = 0;
    char why[160] = "";
    tl_courses cs = tl_courses_all();
    for (uint32_t v = 0; v < np && tested < 40; v += 7) {
        if (!dd_is_vertex(t, v) || dd_degree(t, v) >= 256) continue;
        size_t before = dd_num_tets(t), star = 2 * (size_t)dd_degree(t, v) - 4;
        tl_course_next(&cs, t);
        if (dd_delete_with(t, v, variant) != DD_OK) {
            snprintf(why, sizeof why, "deleting %u: %s", v, dd_errmsg(t));
            ok = 0;
            break;
        }
        dd_delete_stats ds_;
        dd_last_delete_stats(t, &ds_);
        size_t fill = dd_num_tets(t) + star - before;
        /* a refuted guess (wrap_guess_course, wrap_narrow_course below,
         * the one made again on shifted lifts, and one with answers in
         * single precision, made again in doubles: the sanitizer build
         * spoils some of those, wrap_single_course) built cells it
         * dropped                                                        */
        if (ds_.strategy[DD_WS_COURSE] != DD_WRAP_REFUTED && ds_.strategy[DD_WS_NARROW_REFUTED] == 0 && !ds_.strategy[DD_WS_SHIFT_GUESS] &&
            !ds_.strategy[DD_WS_SINGLE_REFUTED] && ds_.tets_created != fill) {
            snprintf(why, sizeof why, "vertex %u (degree %u, hull %d): %llu cells built, fill %zu", v,
                     ds_.degree, ds_.on_hull, (unsigned long long)ds_.tets_created, fill);
            ok = 0;
            break;
        }
        if (dd_reinsert(t, v) != DD_OK) {
            snprintf(why, sizeof why, "re-inserting %u: %s", v, dd_errmsg(t));
            ok = 0;
            break;
        }
        tested++;
    }
    ok = ok && tl_courses_covered(&cs, why, sizeof why);
    tl_check(st, ok && tested > 0, name, "%s", ok ? "no vertex tested" : why);
    dd_free(t);
    free(p);
}

/* Two concentric shells of n sphere points each, radii 1 and 2 (the outer
 * one turned by a fixed rotation), every radius times 1 + 10^-e * [-1,1):
 * each inner point is an interior vertex whose neighbours are nearly
 * cospherical, so gift wrapping's guesses (wrap/guess.c) are close calls.
 * Even indices are the inner shell.                                     */
static double *shells(uint32_t n, int e, uint32_t *np)
{
    uint32_t ns;
    double *s = gen("sphere", n, &ns), *p = malloc(6 * ns * sizeof *p);
    tl_rng r = {0x5E11500u + (uint64_t)e};
    for (uint32_t i = 0; i < ns; i++)
        for (int k = 0; k < 2; k++) {
            double f = (k ? 2 : 1) * (1 + pow(10, -e) * (2 * tl_unif(&r) - 1));
            double x = s[3 * i], y = s[3 * i + 1], *o = p + 3 * (2 * i + (uint32_t)k);
            if (k) { double x0 = x; x = 0.6 * x - 0.8 * y; y = 0.8 * x0 + 0.6 * y; }
            o[0] = x * f; o[1] = y * f; o[2] = s[3 * i + 2] * f;
        }
    free(s);
    *np = 2 * ns;
    return p;
}

/* Deletes v with `variant`, in the next course of cs, and re-inserts it,
 * against CGAL's deletion of
 * v in g: counts the wrap's course, and a wrong result, a failed dd_check
 * or a failed step in *bad (the first one said in why); the deletion's
 * statistics in *out.  0 when CGAL refuses to delete v
 * (nothing done), else 1.                                               */
static int wrap_one(dd_tri *t, dd_cgal *g, uint32_t v, const char *variant, tl_courses *cs, long course[5],
                    long *bad, char *why, size_t nwhy, dd_delete_stats *out)
{
    if (dd_cgal_remove(g, v)) return 0;
    canon ref = theirs(g);
    dd_cgal_reinsert(g, v);
    tl_course_next(cs, t);
    dd_status s = dd_delete_with(t, v, variant);
    canon now = ours(t);
    dd_last_delete_stats(t, out);
    course[out->strategy[DD_WS_COURSE]]++;
    if ((s != DD_OK || !same(now, ref) || dd_check(t) != DD_OK) && (*bad)++ == 0)
        snprintf(why, nwhy, "deleting %u (course %d): %s", v, out->strategy[DD_WS_COURSE],
                 s != DD_OK ? dd_errmsg(t) : "differs from CGAL");
    free(now.a);
    free(ref.a);
    if (s == DD_OK && dd_reinsert(t, v) != DD_OK && (*bad)++ == 0)
        snprintf(why, nwhy, "re-inserting %u: %s", v, dd_errmsg(t));
    return 1;
}

/* Wrap courses (wrap/wrap.c, dd_wrap_fill), checked against CGAL with
 * wrap_one: deletes up to k vertices with `variant`, in the courses cs
 * names (in turn), any vertex or, when hull_below > 0, hull vertices of lower degree only,
 * or, when deg_from > 0, vertices of at least that degree only, and
 * counts the courses.  `want`: bit 0, some guess proved; bit 1, some
 * refuted; bit 2, none declined; bit 3, some guess over every neighbour
 * refuted, then proved on shifted lifts (wrap-shift-guess/).
 *  - The guess proved and refuted (wrap-guess/): whatever the proof
 *    decides, kept or refuted and wrapped again by the scans, the result
 *    is CGAL's; both sides of the proof must be exercised.
 *  - Flat faces of the hull (wrap-flat-hull/; wrap/scan.c: w_flat_hull,
 *    wrap_scan_inf): on a grid, a cosphere or stacked layers the hull's
 *    faces hold many coplanar points, which the coplanar in-circle rules
 *    of the perturbation triangulate.  Every hull vertex of degree below
 *    W_EXACT_FROM (40) is deleted, and the wrap must finish the fill
 *    itself, with no decline to the conflict DT.
 *  - Nearly cospherical neighbours (wrap-shift-guess/, points of a
 *    sphere, degree 24 and more): a guess on the plain lifts is refuted
 *    there (the quotients t/o differ by less than their rounding); the
 *    wrap must guess again on the shifted lifts, prove that guess on some
 *    vertices, and decline none (not leave cavities of 40 neighbours and
 *    more to the slower conflict DT).
 *  - Integer lifts (wrap-integer/, see wrap_integer): `lifts` >= 0 asks
 *    every wrap to have taken integer lifts (1) or rounded ones (0), or
 *    (2) none rounded and some with integer cofactors only, and none with
 *    integer lifts or cofactors to leave a test to the exact predicates. */
static void wrap_course(tl_state *st, const char *tn, const double *pts, uint32_t n, const char *variant,
                        tl_courses cs, uint32_t hull_below, uint32_t deg_from, uint32_t k, int want, int lifts)
{
    char msg[256], why[200] = "";
    dd_tri *t;
    if (dd_create(&t, pts, n, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, tn, "dd_create: %s", msg);
        return;
    }
    dd_cgal *g = dd_cgal_build(pts, n);
    long course[5] = {0}, bad = 0, done = 0, wrong_lifts = 0, expansions = 0, shifted = 0, cofactors = 0;
    for (uint32_t v = 0; v < n && done < k; v++) {
        if (!dd_is_vertex(t, v)) continue;
        if (hull_below && (!dd_on_hull(t, v) || dd_degree(t, v) >= hull_below)) continue;
        if (deg_from && dd_degree(t, v) < deg_from) continue;
        dd_delete_stats ds_;
        memset(&ds_, 0, sizeof ds_);
        if (!wrap_one(t, g, v, variant, &cs, course, &bad, why, sizeof why, &ds_)) continue;
        done++;
        shifted += ds_.strategy[DD_WS_COURSE] == DD_WRAP_PROVED && ds_.strategy[DD_WS_SHIFT_GUESS];
        if (lifts < 0 || ds_.strategy[DD_WS_COURSE] == DD_WRAP_NONE) continue;   /* forced fill: no wrap */
        wrong_lifts += lifts == 2 ? ds_.strategy[DD_WS_INTEGER] == 0 : ds_.strategy[DD_WS_INTEGER] != (uint32_t)lifts;
        cofactors += ds_.strategy[DD_WS_INTEGER] == 2;
        if (ds_.strategy[DD_WS_INTEGER]) expansions += ds_.strategy[DD_WS_EXPANSIONS];
    }
    int seen = (course[DD_WRAP_PROVED] > 0) | (course[DD_WRAP_REFUTED] > 0) << 1 |
               (course[DD_WRAP_DECLINED] == 0) << 2 | (shifted > 0) << 3;
    if (lifts == 2 && cofactors == 0) wrong_lifts++;
    int covered = done < cs.n || tl_courses_covered(&cs, why, sizeof why);
    tl_check(st, bad == 0 && done > 0 && covered && (seen & want) == want && wrong_lifts == 0 && expansions == 0, tn,
             "%ld of %ld wrong (%s); proved %ld (%ld on shifted lifts), refuted %ld, scanned %ld, declined %ld; "
             "%ld wraps without %s lifts, %ld tests left to the exact predicates with integer lifts", bad, done,
             why, course[DD_WRAP_PROVED], shifted, course[DD_WRAP_REFUTED], course[DD_WRAP_SCANNED],
             course[DD_WRAP_DECLINED], wrong_lifts,
             lifts == 1 ? "integer" : lifts == 2 ? "integer or integer-cofactor" : "rounded", expansions);
    printf("# %s: proved %ld (%ld on shifted lifts), refuted %ld, scanned %ld, declined %ld\n", tn,
           course[DD_WRAP_PROVED], shifted, course[DD_WRAP_REFUTED], course[DD_WRAP_SCANNED],
           course[DD_WRAP_DECLINED]);
    dd_cgal_free(g);
    dd_free(t);
}

static void wrap_guess_course(tl_state *st, const char *name, const double *pts, uint32_t n, tl_courses cs,
                              uint32_t k, int want)
{
    char tn[128];
    snprintf(tn, sizeof tn, "wrap-guess/%s", name);
    wrap_course(st, tn, pts, n, "gift-wrap", cs, 0, 0, k, want, -1);
}

/* Test name kind/name/variant in tn, our DT of pts in *t and CGAL's
 * (returned); NULL, the failure said, when ours cannot be built.       */
static dd_cgal *wrap_setup(tl_state *st, char *tn, size_t ntn, const char *kind, const char *name,
                           const char *variant, const double *pts, uint32_t n, dd_tri **t)
{
    char msg[256];
    snprintf(tn, ntn, "%s/%s/%s", kind, name, variant);
    if (dd_create(t, pts, n, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, tn, "dd_create: %s", msg);
        return NULL;
    }
    dd_cgal *g = dd_cgal_build(pts, n);
    if (!g) {
        tl_check(st, 0, tn, "CGAL's triangulation could not be built");
        dd_free(*t);
    }
    return g;
}

/* The narrow guesses (wrap/guess.c, w_guess_narrow), on a point set whose
 * links have hubs: deletes vertices lo..hi-1 with `variant`, each result
 * CGAL's (wrap_one), none declined, and counts the kept guesses by where
 * their candidates came from.  want: bit 0, some short-list guess kept
 * at once; bit 1, some two-step guess kept after a refuted short one;
 * bit 2, some wide guess kept after two refuted narrow ones (the
 * narrower course's lists, wrap/wrap.c, in test builds).            */
static void wrap_narrow_course(tl_state *st, const char *name, const double *pts, uint32_t n, const char *variant,
                               uint32_t lo, uint32_t hi, int want)
{
    char tn[128], why[200] = "";
    dd_tri *t;
    dd_cgal *g = wrap_setup(st, tn, sizeof tn, "wrap-narrow", name, variant, pts, n, &t);
    if (!g) return;
    long course[5] = {0}, bad = 0, done = 0, kept[3] = {0, 0, 0}, after[3] = {0, 0, 0};
    tl_courses cs = tl_courses_all();
    for (uint32_t v = lo; v < hi && v < n; v++) {
        dd_delete_stats ds_;
        if (!dd_is_vertex(t, v) || !wrap_one(t, g, v, variant, &cs, course, &bad, why, sizeof why, &ds_)) continue;
        done++;
        if (ds_.strategy[DD_WS_COURSE] != DD_WRAP_PROVED) continue;
        kept[ds_.strategy[DD_WS_GUESS]]++;
        after[ds_.strategy[DD_WS_GUESS]] += ds_.strategy[DD_WS_NARROW_REFUTED] > 0;
    }
    int seen = (kept[DD_GUESS_SHORT] > 0) | (after[DD_GUESS_TWO_STEP] > 0) << 1 | (after[DD_GUESS_WIDE] > 0) << 2;
    int covered = done < cs.n || tl_courses_covered(&cs, why, sizeof why);
    tl_check(st, bad == 0 && done > 0 && covered && course[DD_WRAP_DECLINED] == 0 && (seen & want) == want, tn,
             "%ld of %ld wrong (%s); declined %ld; kept: short %ld, two-step %ld (%ld after a refuted guess), "
             "wide %ld (%ld after refuted ones)", bad, done, why, course[DD_WRAP_DECLINED], kept[DD_GUESS_SHORT],
             kept[DD_GUESS_TWO_STEP], after[DD_GUESS_TWO_STEP], kept[DD_GUESS_WIDE], after[DD_GUESS_WIDE]);
    printf("# %s: %ld deletions; kept: short %ld, two-step %ld, wide %ld (%ld after refuted narrow ones)\n", tn,
           done, kept[DD_GUESS_SHORT], kept[DD_GUESS_TWO_STEP], kept[DD_GUESS_WIDE], after[DD_GUESS_WIDE]);
    dd_cgal_free(g);
    dd_free(t);
}

/* The single-precision guess (wrap/simd.c, w_guess_f32_avx2) and hull step
 * (w_inf_f32), in two courses taken in turn: the default one, and the
 * spoiled one (TL_COURSE_SPOIL_SINGLE: the sanitizer build answers a
 * wrong point on one guess in 16 and on each hull step).  Every vertex
 * of index 0 mod 4 (a sample) and degree 24 or more is deleted with
 * `variant` against CGAL (wrap_one); some in the default course must
 * have kept single-precision answers in a proved guess, and hull steps,
 * with at most one in ten of those refuted (the floats' rounding rarely
 * misleads them; more refutations mean a pass read stale scales, such
 * as those of the deletion before); and (sanitizer build) some in the
 * spoiled course must have had such a guess refuted, and hull steps
 * made in doubles instead, and still end as CGAL's.                    */
static void wrap_single_course(tl_state *st, const char *name, const double *pts, uint32_t n, const char *variant)
{
    char tn[128], why[200] = "";
    dd_tri *t;
    dd_cgal *g = wrap_setup(st, tn, sizeof tn, "wrap-single", name, variant, pts, n, &t);
    if (!g) return;
    long course[5] = {0}, bad = 0, done = 0, kept = 0, answered = 0, spoiled = 0, recovered = 0;
    long hull_kept = 0, hull_back = 0, unspoiled_refuted = 0;
    tl_courses cs = TL_COURSES(TL_COURSE_DEFAULT, TL_COURSE_SPOIL_SINGLE);
    for (uint32_t v = 0; v < n; v += 4) {
        if (!dd_is_vertex(t, v) || dd_degree(t, v) < 24) continue;
        dd_delete_stats ds_;
        memset(&ds_, 0, sizeof ds_);
        if (!wrap_one(t, g, v, variant, &cs, course, &bad, why, sizeof why, &ds_)) continue;
        done++;
        answered += ds_.strategy[DD_WS_SINGLE];
        if (cs.last == TL_COURSE_DEFAULT) {
            kept += ds_.strategy[DD_WS_COURSE] == DD_WRAP_PROVED && ds_.strategy[DD_WS_SINGLE] > 0 && !ds_.strategy[DD_WS_SINGLE_REFUTED];
            unspoiled_refuted += ds_.strategy[DD_WS_SINGLE_REFUTED];
            hull_kept += ds_.strategy[DD_WS_HULL_SINGLE];
        } else {
            spoiled += ds_.strategy[DD_WS_SINGLE_REFUTED], recovered += ds_.strategy[DD_WS_SINGLE_REFUTED] && ds_.strategy[DD_WS_COURSE] == DD_WRAP_PROVED;
            hull_back += ds_.strategy[DD_WS_HULL_BACK];
        }
    }
#ifdef DD_TEST_BUILD
    const int want_recovered = 1;
#else
    const int want_recovered = 0;                  /* nothing spoiled there */
#endif
    int covered = tl_courses_covered(&cs, why, sizeof why);
    tl_check(st, bad == 0 && done > 0 && covered && kept > 0 && 10 * unspoiled_refuted <= kept && recovered >= want_recovered &&
                     hull_kept > 0 && hull_back >= want_recovered, tn,
             "%ld of %ld wrong (%s); %ld proved with single-precision answers (%ld in all; %ld refuted unspoiled), "
             "%ld refuted with a wrong one (%ld proved again); hull steps %ld in single precision, %ld in doubles "
             "after a wrong one", bad, done, why, kept, answered, unspoiled_refuted, spoiled, recovered, hull_kept,
             hull_back);
    printf("# %s: %ld deletions, %ld proved with single-precision answers (%ld), %ld refuted with a wrong one "
           "(%ld proved again); hull steps %ld, %ld in doubles after a wrong one\n", tn, done, kept, answered,
           spoiled, recovered, hull_kept, hull_back);
    dd_cgal_free(g);
    dd_free(t);
}

static void wrap_flat_hull(tl_state *st, const char *name, const double *pts, uint32_t n, const char *variant)
{
    char tn[128];
    snprintf(tn, sizeof tn, "wrap-flat-hull/%s/%s", name, variant);
    wrap_course(st, tn, pts, n, variant, tl_courses_all(), 40, 0, UINT32_MAX, 4, -1);
}

/* Integer lifts (wrap/lift.c, w_lift): when q and its neighbours have integer
 * coordinates and lie within W_INT_M = 400 of each other per coordinate,
 * every test of the wrap is exact in doubles: none may be left to the
 * exact predicates, and a zero is decided by the perturbation alone.  A
 * k x k x k grid scaled by s has each vertex's neighbours exactly s away
 * in some coordinate and no further, so s = 400 is wrapped with integer
 * lifts, s = 401 and 2048 with integer cofactors (W_INT_K: orientations
 * exact in doubles, the in-sphere tests the filter leaves summed exactly
 * in 128 bits, none left to the exact predicates either) and s = 2049
 * with rounded ones (the cosphere scaled by 20, radius 540: integer
 * lifts where a vertex's neighbours are within 400, integer cofactors
 * elsewhere); an offset of 2^50 keeps the lifts
 * integers.  Integer points of a sphere halved and moved by 1/4 stay
 * exactly cospherical with no integer coordinate: their wrap asks the
 * perturbation with rounded lifts (w_symbolic's filtered orientations).
 * Every vertex is deleted (wrap_one: against CGAL, dd_check), and each
 * wrap must have taken the lifts `want` says (1: integer).              */
static void wrap_integer(tl_state *st, const char *name, const double *pts, uint32_t n, const char *variant,
                         int want)
{
    char tn[128];
    snprintf(tn, sizeof tn, "wrap-integer/%s/%s", name, variant);
    wrap_course(st, tn, pts, n, variant, tl_courses_all(), 0, 0, UINT32_MAX, 0, want);
}

static void refusals(tl_state *st)
{
    /* a square pyramid: deleting the apex leaves coplanar points */
    double pyr[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 1, 1, 0, 0};
    char msg[256];
    dd_tri *t;
    dd_create(&t, pyr, 6, msg, sizeof msg);   /* point 5 duplicates point 1 */
    canon before = ours(t);
    dd_status s = dd_delete(t, 4);
    canon after = ours(t);
    tl_check(st, s == DD_ERR_DIMENSION && same(before, after), "refuse/apex-leaves-coplanar",
             "status %s, unchanged %d", dd_status_name(s), same(before, after));
    free(after.a);
    s = dd_delete(t, 5);
    after = ours(t);
    tl_check(st, s == DD_ERR_UNKNOWN_VERTEX && same(before, after) && strstr(dd_errmsg(t), "duplicate"),
             "refuse/duplicate-index", "status %s: %s", dd_status_name(s), dd_errmsg(t));
    free(after.a);
    s = dd_delete(t, 77);
    tl_check(st, s == DD_ERR_UNKNOWN_VERTEX && strstr(dd_errmsg(t), "77"), "refuse/unknown-index",
             "status %s: %s", dd_status_name(s), dd_errmsg(t));
    s = dd_delete_with(t, 0, "no-such-variant");
    after = ours(t);
    tl_check(st, s == DD_ERR_UNKNOWN_VARIANT && same(before, after), "refuse/unknown-variant",
             "status %s", dd_status_name(s));
    free(after.a);
    free(before.a);
    dd_free(t);

    /* a tetrahedron: no deletion possible */
    double tet[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    dd_create(&t, tet, 4, msg, sizeof msg);
    s = dd_delete(t, 2);
    tl_check(st, s == DD_ERR_DIMENSION, "refuse/four-points", "status %s", dd_status_name(s));
    dd_free(t);

    /* deleted twice; reinserting a vertex that exists; inserting a duplicate */
    uint32_t np;
    double *p = gen("uniform", 200, &np);
    dd_create(&t, p, np, msg, sizeof msg);
    dd_delete(t, 10);
    canon b2 = ours(t);
    s = dd_delete(t, 10);
    canon a2 = ours(t);
    tl_check(st, s == DD_ERR_UNKNOWN_VERTEX && same(a2, b2), "refuse/deleted-twice", "status %s", dd_status_name(s));
    free(a2.a);
    s = dd_reinsert(t, 11);
    a2 = ours(t);
    tl_check(st, s == DD_ERR_DUPLICATE && same(a2, b2), "refuse/reinsert-existing", "status %s", dd_status_name(s));
    free(a2.a);
    uint32_t idx;
    s = dd_insert(t, p + 3 * 20, &idx);
    a2 = ours(t);
    tl_check(st, s == DD_ERR_DUPLICATE && same(a2, b2) && dd_num_input(t) == np, "refuse/insert-duplicate",
             "status %s", dd_status_name(s));
    free(a2.a);
    double nanp[3] = {0.5, NAN, 0.5};
    s = dd_insert(t, nanp, &idx);
    tl_check(st, s == DD_ERR_NAN, "refuse/insert-nan", "status %s", dd_status_name(s));
    /* a fresh point: it takes the index of the deleted vertex 10 */
    double fresh[3] = {0.123, 0.456, 0.789};
    s = dd_insert(t, fresh, &idx);
    tl_check(st, s == DD_OK && idx == 10 && dd_is_vertex(t, idx) && dd_check(t) == DD_OK,
             "insert/new-point", "status %s, index %u", dd_status_name(s), idx);
    free(b2.a);
    dd_free(t);
    free(p);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    int small = argc > 1 && !strcmp(argv[1], "small");
    uint32_t k = small ? 15 : 60;
    /* heavy: every vertex of moment-200 has degree about 200 and its DT
     * about 200^2 / 2 cells, so each deletion of each strategy and the
     * validator after it are the suite's slowest: a quarter of the
     * sample, and one deletion per course in the sanitizer build.        */
    struct { const char *ds; uint32_t n; int heavy; } sets[] = {
        {"uniform", 2000, 0}, {"sphere", 1000, 0}, {"moment", 64, 0}, {"moment", 200, 1}, {"helix", 1500, 0},
        {"grid", 216, 0}, {"grid", 1000, 0}, {"cosphere", 300, 0}, {"layers", 128, 0}, {"grid-perturbed", 512, 0},
        {"bunny", 2000, 0}, {"cow", 0, 0}};
    for (size_t i = 0; i < sizeof sets / sizeof *sets; i++) {
        uint32_t np;
        double *p = gen(sets[i].ds, sets[i].n, &np);
        char name[64];
        snprintf(name, sizeof name, "%s-%u", sets[i].ds, np);
        const uint32_t ki = !sets[i].heavy ? k : small ? TL_NCOURSES : k / 4;
        single_deletions(&st, name, p, np, ki, 1000 + i, 1, UINT32_MAX);
        free(p);
    }
    /* scaled inputs */
    {
        uint32_t np;
        double *p = gen("grid", 343, &np);
        for (uint32_t i = 0; i < 3 * np; i++) p[i] *= 1e-200;
        single_deletions(&st, "grid-343-x1e-200", p, np, k, 77, 1, UINT32_MAX);
        for (uint32_t i = 0; i < 3 * np; i++) p[i] *= 1e216;
        single_deletions(&st, "grid-343-x1e16", p, np, k, 78, 1, UINT32_MAX);
        free(p);
    }
    /* Near-cospherical points at graded distances from the unit sphere
     * (radius times 1 + 10^-e * [-1,1)), and uniform points scaled to the
     * edges of the range where the compact conflict DT's filter answers
     * (qsmall.c: 1e-55 <= m <= 1e55): the filter must abstain whenever
     * its error bound says so.                                           */
    for (int e = 8; e <= 15; e++) {
        uint32_t np;
        double *p = gen("sphere", small ? 300 : 800, &np);
        tl_rng r = {0x51ED2700u + (uint64_t)e};
        for (uint32_t i = 0; i < np; i++) {
            double f = 1 + pow(10, -e) * (2 * tl_unif(&r) - 1);
            for (int c = 0; c < 3; c++) p[3 * i + c] *= f;
        }
        char name[64];
        snprintf(name, sizeof name, "sphere-%u-radial-1e-%d", np, e);
        single_deletions(&st, name, p, np, k / 2, 90 + (uint64_t)e, 1, UINT32_MAX);
        free(p);
    }
    {
        const double scale[] = {1e-56, 1e-54, 1e54, 1e56};
        for (int i = 0; i < 4; i++) {
            uint32_t np;
            double *p = gen("uniform", 500, &np);
            for (uint32_t j = 0; j < 3 * np; j++) p[j] *= scale[i];
            char name[64];
            snprintf(name, sizeof name, "uniform-%u-x%g", np, scale[i]);
            single_deletions(&st, name, p, np, k / 2, 95 + (uint64_t)i, 1, UINT32_MAX);
            free(p);
        }
    }
    /* hull vertex with coplanar finite neighbours: a 5x5 grid, one point
     * above its centre, one below a corner                                 */
    {
        double p[3 * 27];
        uint32_t n = 0;
        for (int x = 0; x < 5; x++)
            for (int y = 0; y < 5; y++) { p[3 * n] = x; p[3 * n + 1] = y; p[3 * n + 2] = 0; n++; }
        p[3 * n] = 2; p[3 * n + 1] = 2; p[3 * n + 2] = 3; n++;
        p[3 * n] = 0.5; p[3 * n + 1] = 0.5; p[3 * n + 2] = -1; n++;
        single_deletions(&st, "apex-over-grid", p, n, 40, 5, 1, UINT32_MAX);
    }
    /* A nearly flat hull: a 7x7 grid lifted by 10^-e * [-1,1) (e = 13..16)
     * under two apexes, so that deleting a grid vertex opens hull facets with
     * points a hair's breadth beyond or behind them, within the
     * orientation filter's bound: gift wrapping's guess may not take such
     * a facet for a hull facet (w_all_behind).                          */
    for (int e = 13; e <= 16; e++) {
        double p[3 * 51];
        uint32_t n = 0;
        tl_rng r = {0xF1A7u + (uint64_t)e};
        for (int x = 0; x < 7; x++)
            for (int y = 0; y < 7; y++) {
                p[3 * n] = x; p[3 * n + 1] = y; p[3 * n + 2] = pow(10, -e) * (2 * tl_unif(&r) - 1);
                n++;
            }
        p[3 * n] = 3.2; p[3 * n + 1] = 2.9; p[3 * n + 2] = 4; n++;
        p[3 * n] = 1.1; p[3 * n + 1] = 0.7; p[3 * n + 2] = 9; n++;
        char name[64];
        snprintf(name, sizeof name, "near-flat-grid-1e-%d", e);
        single_deletions(&st, name, p, n, 40, 30 + (uint64_t)e, 1, UINT32_MAX);
        wrap_guess_course(&st, name, p, n, tl_courses_all(), 49, 0);
    }
    /* The centre of 300 points on a sphere: its star is the whole ball, so
     * deleting it fills a cavity with 300 boundary vertices and
     * re-inserting it refills one; both are beyond the direct edge table
     * of mesh.c (DD_STAR_MAXV vertices) and glue through the edge hash.   */
    {
        uint32_t np;
        double *p = sphere_and_centre(300, &np);
        single_deletions(&st, "sphere-300-centre", p, np, small ? 4 : 10, 6, 1, np - 1);
        free(p);
        /* 2200 points: the centre's star has 4396 cells, more than one
         * pass's marks (DD_EPOCH_STEP_MAX), so the link finds star slots
         * through the link-triangle hash (link.c).                        */
        p = sphere_and_centre(2200, &np);
        single_deletions(&st, "sphere-2200-centre", p, np, 1, 6, 1, np - 1);
        free(p);
    }
    /* The vertex of highest degree among 3000 integer points of a sphere:
     * its cavity (degree 50 or more) is wholly degenerate, every in-sphere
     * test a tie.  Gift wrapping sees that its neighbours are cospherical
     * and asks the perturbation alone (wrap/scan.c, w_cospherical), so it wraps
     * the cavity itself instead of declining at its budget of exact tests
     * (W_EXACT_FROM); every variant must give CGAL's result.             */
    {
        uint32_t np, best = 0, bd = 0;
        double *p = gen("cosphere", 3000, &np);
        char msg[256];
        dd_tri *t;
        if (dd_create(&t, p, np, msg, sizeof msg) == DD_OK) {
            for (uint32_t v = 0; v < np; v++)
                if (dd_is_vertex(t, v) && dd_degree(t, v) > bd) { bd = dd_degree(t, v); best = v; }
            dd_free(t);
        }
        tl_check(&st, bd >= 50, "cosphere-3000/max-degree", "highest degree %u, expected at least 50", bd);
        single_deletions(&st, "cosphere-3000-max-degree", p, np, 1, 15, 1, best);
        if (dd_create(&t, p, np, msg, sizeof msg) == DD_OK) {
            dd_delete_stats ds_ = {0};
            dd_status s = DD_OK;
            int c = 0;
            for (; c < TL_NCOURSES && s == DD_OK && ds_.strategy[DD_WS_COURSE] != DD_WRAP_DECLINED; c++) {
                tl_set_course(t, tl_all_courses[c]);
                s = dd_delete_with(t, best, "gift-wrap");
                dd_last_delete_stats(t, &ds_);
                if (s == DD_OK) s = dd_reinsert(t, best);
            }
            tl_check(&st, s == DD_OK && ds_.strategy[DD_WS_COURSE] != DD_WRAP_DECLINED, "cosphere-3000-max-degree/wrapped",
                     "course %s: status %s, wrap's course %d (declined: %d)", tl_course_name[tl_all_courses[c - 1]],
                     dd_status_name(s), ds_.strategy[DD_WS_COURSE], DD_WRAP_DECLINED);
            dd_free(t);
        }
        free(p);
    }
    /* Integer points of a sphere, every 7th moved off it (radius times
     * 1 + 2^-40): most cavities are cospherical but for a point or two,
     * which gift wrapping's test of cospherical neighbours must see.    */
    {
        uint32_t np;
        double *p = gen("cosphere", 300, &np);
        for (uint32_t i = 0; i < np; i += 7)
            for (int c = 0; c < 3; c++) p[3 * i + c] *= 1 + ldexp(1, -40);
        single_deletions(&st, "cosphere-300-every-7th-off", p, np, k, 16, 1, UINT32_MAX);
        free(p);
    }
    for (size_t vi = 0; dd_variant_name(vi); vi++) {
        const char *var = dd_variant_name(vi);
        uint32_t np;
        double *p = gen("uniform", small ? 600 : 5000, &np);
        sequence(&st, small ? "uniform-600-half" : "uniform-5000-half", p, np, np / 2, small ? 50 : 250, var, 11);
        free(p);
        p = gen("grid", 216, &np);
        sequence(&st, "grid-216-all-but-4", p, np, np - 4, 20, var, 12);
        free(p);
        p = gen("cosphere", 200, &np);
        sequence(&st, "cosphere-200-all-but-4", p, np, np - 4, 10, var, 13);
        free(p);
        p = gen("moment", 100, &np);
        sequence(&st, "moment-100-all-but-4", p, np, np - 4, 8, var, 14);
        free(p);
    }
    auto_least_degree(&st, 700);
    if (!small) auto_wraps_dense_moment(&st, 1000);   /* its DT has 2M cells: release only */
    const char *wrap_sets[][2] = {{"uniform", "2000"}, {"sphere", "1000"}, {"bunny", "2000"}};
    for (size_t i = 0; i < 3; i++) {
        wrap_builds_only_fill(&st, wrap_sets[i][0], (uint32_t)atoi(wrap_sets[i][1]), "gift-wrap");
        wrap_builds_only_fill(&st, wrap_sets[i][0], (uint32_t)atoi(wrap_sets[i][1]), "auto");
    }
    /* The guess of gift wrapping, proved and refuted (see above).       */
    {
        uint32_t np;
        double *p = gen("uniform", 2000, &np);
        wrap_guess_course(&st, "uniform-2000", p, np, tl_courses_all(), small ? 40 : 150, 1);
        free(p);
        /* proved; since the guess decides points of unsure orientation
         * (wrap/guess.h, wrap_guess) it is refuted on 2 of 300 vertices only, so
         * the refuted side is asked of the sphere and the shells below  */
        p = gen("grid-perturbed", 512, &np);
        wrap_guess_course(&st, "grid-perturbed-512", p, np, tl_courses_all(), small ? 100 : 300, 1);
        free(p);
        /* hull vertices: every point of a sphere (nearly cospherical, so
         * some guesses are refuted), and the moment curve                */
        p = gen("sphere", 1000, &np);
        wrap_guess_course(&st, "sphere-1000", p, np, tl_courses_all(), small ? 100 : 300, 3);
        free(p);
        /* its vertices of degree 24 and more (wrap_course)             */
        p = gen("sphere", 3000, &np);
        wrap_course(&st, "wrap-shift-guess/sphere-3000/auto", p, np, "auto", tl_courses_all(), 0, 24, small ? 40 : 120, 13, -1);
        wrap_course(&st, "wrap-shift-guess/sphere-3000/gift-wrap", p, np, "gift-wrap", tl_courses_all(), 0, 24, small ? 40 : 120,
                    13, -1);
        free(p);
        /* the single-precision guess (wrap_single_course)              */
        p = gen("uniform", 2000, &np);
        wrap_single_course(&st, "uniform-2000", p, np, "auto");
        free(p);
        p = gen("bunny", 2000, &np);
        wrap_single_course(&st, "bunny-2000", p, np, "gift-wrap");
        free(p);
        p = gen("moment", 128, &np);
        wrap_guess_course(&st, "moment-128", p, np, tl_courses_all(), small ? 20 : 128, 1);
        free(p);
        /* The moment curve at t = i/512, n = 300: each cavity has facets
         * with a point nearly in their plane, of unsure orientation, that
         * is the apex; the guess must take such points (wrap/guess.h,
         * wrap_guess's *unsure), so that every guess is proved.          */
        p = gen("moment", 300, &np);
        wrap_guess_course(&st, "moment-300", p, np, tl_courses_all(), small ? 1 : 6, 5);
        free(p);
        /* The narrow guesses: on the helix, n = 4000 (degree ~140, every
         * link with hubs), the short lists hold for most vertices; for
         * 69, 70, 87, 89 and 105 the two-step guess holds after them.  (The
         * helix's DT has many cells a point, and each comparison with
         * CGAL's whole triangulation is slow: few vertices.)            */
        p = gen("helix", 4000, &np);
#ifdef DD_TEST_BUILD
        const int narrow_want = 7;
#else
        const int narrow_want = 3;
#endif
        wrap_narrow_course(&st, "helix-4000", p, np, "gift-wrap", 66, 106, narrow_want);
        free(p);
        /* from degree 600 auto wraps only with a narrow guess           */
        p = gen("moment", 640, &np);
        wrap_narrow_course(&st, "moment-640", p, np, "auto", 0, small ? 2 : 4, 1);
        free(p);
        for (int e = 12; e <= 16; e += 2) {
            char name[64];
            p = shells(small ? 150 : 300, e, &np);
            snprintf(name, sizeof name, "shells-%u-radial-1e-%d", np, e);
            wrap_guess_course(&st, name, p, np, tl_courses_all(), small ? 60 : 150, e == 16 ? 3 : 1);
            single_deletions(&st, name, p, np, k / 2, 120 + (uint64_t)e, 1, UINT32_MAX);
            free(p);
        }
    }
    /* A flat hull face without ties: uniform points in the unit cube and
     * as many more on its face z = 0 (x, y of the others, z exactly 0).
     * Deleting a vertex of that face, the guess meets finite facets in
     * the plane z = 0 with points in it and none beyond, which are hull
     * facets only if the coplanar in-circle rules allow: the scan's step
     * decides them (src/wrap: the guess's w_scan_exact, w_flat_hull). */
    {
        uint32_t np;
        double *p = gen("uniform", small ? 300 : 600, &np);
        p = realloc(p, 2 * 3 * sizeof *p * np);
        for (uint32_t i = 0; i < np; i++) {
            p[3 * (np + i)] = p[3 * i];
            p[3 * (np + i) + 1] = p[3 * i + 1];
            p[3 * (np + i) + 2] = 0;
        }
        wrap_flat_hull(&st, small ? "cube-face-z0-600" : "cube-face-z0-1200", p, 2 * np, "gift-wrap");
        wrap_flat_hull(&st, small ? "cube-face-z0-600" : "cube-face-z0-1200", p, 2 * np, "auto");
        free(p);
    }
    {
        const struct { const char *ds; uint32_t n; double scale; } flat[] = {
            {"grid", 216, 1}, {"grid", 512, 1}, {"grid", 343, 1e-200}, {"cosphere", 300, 1},
            {"cosphere", 600, 1}, {"layers", 128, 1}};
        for (size_t i = 0; i < sizeof flat / sizeof *flat; i++) {
            if (small && flat[i].n > 512) continue;  /* the sanitizer build: cosphere-300 stands for it */
            uint32_t np;
            double *p = gen(flat[i].ds, flat[i].n, &np);
            for (uint32_t j = 0; j < 3 * np; j++) p[j] *= flat[i].scale;
            char name[64];
            snprintf(name, sizeof name, "%s-%u%s", flat[i].ds, np, flat[i].scale != 1 ? "-x1e-200" : "");
            wrap_flat_hull(&st, name, p, np, "gift-wrap");
            wrap_flat_hull(&st, name, p, np, "auto");
            free(p);
        }
    }
    {
        const struct { const char *ds; uint32_t n; double scale, offset; int want; } ints[] = {
            {"grid", 216, 1, 0, 1}, {"grid", 216, 400, 0, 1}, {"grid", 216, 401, 0, 2},
            {"grid", 216, 2048, 0, 2}, {"grid", 216, 2049, 0, 0},
            {"grid", 216, 3, 1125899906842624.0 /* 2^50 */, 1}, {"cosphere", 300, 1, 0, 1},
            {"cosphere", 300, 20, 0, 2}, {"layers", 128, 1, 0, 1}, {"cosphere", 300, 0.5, 0.25, 0}};
        for (size_t i = 0; i < sizeof ints / sizeof *ints; i++) {
            uint32_t np;
            double *p = gen(ints[i].ds, ints[i].n, &np);
            for (uint32_t j = 0; j < 3 * np; j++) p[j] = p[j] * ints[i].scale + ints[i].offset;
            char name[64];
            snprintf(name, sizeof name, "%s-%u-x%g+%g", ints[i].ds, np, ints[i].scale, ints[i].offset);
            wrap_integer(&st, name, p, np, "gift-wrap", ints[i].want);
            wrap_integer(&st, name, p, np, "auto", ints[i].want);
            free(p);
        }
    }
    /* Sets of deletions (dd_delete_set, the engine's own order). */
    for (size_t vi = 0; dd_variant_name(vi); vi++) {
        const char *var = dd_variant_name(vi);
        const struct { const char *ds; uint32_t n; double frac; } dsets[] = {
            {"uniform", small ? 800 : 3000, 0.5}, {"grid", 343, 0.7}, {"cosphere", 300, 0.6},
            {"moment", 64, 0.5}, {"sphere", 1000, 0.3}, {"layers", 128, 0.4}};
        for (size_t i = 0; i < sizeof dsets / sizeof *dsets; i++) {
            uint32_t np;
            double *p = gen(dsets[i].ds, dsets[i].n, &np);
            char name[64];
            snprintf(name, sizeof name, "%s-%u-%g", dsets[i].ds, np, dsets[i].frac);
            delete_set(&st, name, p, np, dsets[i].frac, var, 40 + i);
            free(p);
        }
    }
    {
        uint32_t np;
        double *p = gen("layers", 128, &np);     /* two planes of 64 points */
        char msg[256];
        dd_tri *t;
        if (dd_create(&t, p, np, msg, sizeof msg) == DD_OK) {
            uint32_t *vs = malloc(np * sizeof *vs), m = 0;
            for (uint32_t i = 0; i < np; i++)    /* one whole layer: the other is left, flat */
                if (p[3 * i + 2] == p[2]) vs[m++] = i;
            set_refused(&st, "layers-one-plane-left", t, vs, m, NULL, DD_ERR_DIMENSION);
            for (uint32_t i = 0; i < np - 3; i++) vs[i] = i;
            set_refused(&st, "three-left", t, vs, np - 3, NULL, DD_ERR_DIMENSION);
            uint32_t twice[] = {5, 9, 5}, unknown[] = {5, np}, bad_last[] = {1, 2, 3, np + 7};
            set_refused(&st, "listed-twice", t, twice, 3, NULL, DD_ERR_ARG);
            set_refused(&st, "unknown-vertex", t, unknown, 2, NULL, DD_ERR_UNKNOWN_VERTEX);
            set_refused(&st, "unknown-last", t, bad_last, 4, "grr-edge", DD_ERR_UNKNOWN_VERTEX);
            set_refused(&st, "unknown-variant", t, twice, 2, "nope", DD_ERR_UNKNOWN_VARIANT);
            dd_status s = dd_delete(t, 9);
            uint32_t deleted[] = {4, 9};
            if (s == DD_OK) set_refused(&st, "deleted-before", t, deleted, 2, NULL, DD_ERR_UNKNOWN_VERTEX);
            else tl_check(&st, 0, "delete-set-refused/deleted-before", "dd_delete: %s", dd_errmsg(t));
#ifdef DD_TEST_BUILD
            /* a failure at the 7th deletion: the six before are undone */
            for (uint32_t i = 0; i < 40; i++) vs[i] = 10 + 2 * i;
            dd_test_control(t, DD_TEST_SET_FAIL_AT, 7);
            set_refused(&st, "rolled-back", t, vs, 40, "auto", DD_ERR_NOMEM);
            dd_test_control(t, DD_TEST_SET_FAIL_AT, 0);
#endif
            tl_check(&st, m == 64 && dd_delete_set(t, vs, 0) == DD_OK, "delete-set/empty",
                     "layer of %u points; %s", m, dd_errmsg(t));
            free(vs);
            dd_free(t);
        }
        free(p);
    }
    /* 3000 points of a plane and an apex on each side.  The first
     * tetrahedron holds one apex among the first vertex ids; deleting
     * that apex, whether the points left span space is decided by the
     * other, past the first 64 vertices that are checked first (then all
     * those left are).  Each apex is deleted with 10 plane points, and
     * both apexes together are refused.                                 */
    {
        uint32_t np = 3002;
        double *p = malloc(3 * sizeof *p * np);
        tl_rng r = {77};
        for (uint32_t i = 0; i < 3000; i++) {
            p[3 * i] = tl_unif(&r);
            p[3 * i + 1] = tl_unif(&r);
            p[3 * i + 2] = 0;
        }
        p[9000] = p[9001] = p[9003] = p[9004] = 0.5;
        p[9002] = 1;
        p[9005] = -1;
        for (uint32_t apex = 3000; apex < 3002; apex++) {
            char msg[256], name[64];
            snprintf(name, sizeof name, "delete-set/plane-and-apex-%u", apex);
            dd_tri *t;
            dd_cgal *g = dd_cgal_build(p, np);
            if (g && dd_create(&t, p, np, msg, sizeof msg) == DD_OK) {
                uint32_t both[] = {3, 3000, 3001}, set[11];
                if (apex == 3000) set_refused(&st, "plane-and-both-apexes", t, both, 3, NULL, DD_ERR_DIMENSION);
                int cg = 0;
                for (uint32_t i = 0; i < 11; i++) cg |= dd_cgal_remove(g, set[i] = i < 10 ? 290 * i + 1 : apex);
                dd_status s = dd_delete_set(t, set, 11);
                canon a = ours(t), b = theirs(g);
                tl_check(&st, !cg && s == DD_OK && same(a, b) && dd_check(t) == DD_OK, name, "CGAL %d, status %s: %s",
                         cg, dd_status_name(s), dd_errmsg(t));
                free(a.a); free(b.a);
                dd_free(t);
            } else {
                tl_check(&st, 0, name, "dd_create: %s", msg);
            }
            dd_cgal_free(g);
        }
        free(p);
    }
    refusals(&st);
    return tl_finish(&st);
}
