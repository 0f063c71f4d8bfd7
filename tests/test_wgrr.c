/*
 * test_wgrr.c -- the paper's strategies on weighted points (issue 44):
 * grr-edge, grr-neighbor, grr-hashing, grr-brio, guide-only and dtq-only
 * build the conflict regular triangulation (delete/qdt.h), and auto's
 * weighted-capable entries dd_grr_fill_mindeg and dd_qs_fill_nearest
 * (delete/grr.h, qsmall.h) run through a test-local strategy:
 *  - deletion sequences on uniform weighted points (few to most hidden),
 *    the degenerate integer grid (power ties; with and without exact
 *    duplicates), a molecule, the weighted moment curve and helix: after
 *    every step the cells and hidden set equal CGAL's
 *    Regular_triangulation_3 after remove() and dd_check passes, in both
 *    hidden modes;
 *  - with every weight zero each strategy's result equals its own
 *    unweighted result, step by step;
 *  - every allocation of a deletion that releases hidden points refused
 *    in turn (test builds): DD_ERR_NOMEM, nothing changed, then the
 *    deletion succeeds with CGAL's result.
 * Argument "small": smaller sizes (the sanitizer build).
 */
#include "testlib.h"
#include <math.h>
#include "dtdel.h"
#include "cgal/cgal_regular.h"
#include "testweighted.h"
#include "delete/delete.h"
#include "delete/grr.h"
#include "delete/qsmall.h"

static int small;

static const char *const strategies[] = {"grr-edge", "grr-neighbor", "grr-hashing", "grr-brio",
                                         "guide-only", "dtq-only", "mindeg", "qs-nearest"};
#define NSTRAT (sizeof strategies / sizeof *strategies)

/* auto's entries as strategies of their own: GRR with the least-degree
 * policy; the compact conflict RT nearest first where it fits.          */
static dd_status fill_mindeg(dd_del *d) { return dd_grr_fill_mindeg(d); }
static dd_status fill_nearest(dd_del *d)
{
    return d->order.n <= DD_QS_MAXV ? dd_qs_fill_nearest(d) : dd_grr_fill_mindeg(d);
}
static const dd_variant var_mindeg = {"mindeg", "test: dd_grr_fill_mindeg", fill_mindeg, fill_mindeg};
static const dd_variant var_nearest = {"qs-nearest", "test: dd_qs_fill_nearest", fill_nearest, fill_nearest};

/* Deletes input vertex v with strategy `name` (one of strategies[]). */
static dd_status delete_by(dd_tri *t, uint32_t v, const char *name)
{
    const dd_variant *var = !strcmp(name, "mindeg") ? &var_mindeg : !strcmp(name, "qs-nearest") ? &var_nearest : NULL;
    if (!var) return dd_delete_with(t, v, name);
    uint32_t id;
    dd_status s = dd_del_resolve(t, v, &id);
    return s == DD_OK ? dd_del_vertex(t, id, var) : s;
}

/* Builds s in one hidden mode here and in CGAL, then deletes `ndel`
 * random vertices with strategy `variant`, comparing with CGAL's
 * remove() and checking after every step.                              */
static void delete_case(tl_state *st, const char *name, const wset *s, uint32_t ndel, const char *variant, int keep)
{
    char tn[200], why[256] = "";
    snprintf(tn, sizeof tn, "wgrr/%s/%s/%s", name, variant, keep ? "keep" : "discard");
    dd_tri *t;
    dd_cgal_rt *c;
    int ok = ws_build(s, keep, &t, &c, why, sizeof why);
    tl_rng r = {0x5eed + s->n + (uint64_t)keep};
    uint32_t done = 0, back = 0;
    for (uint32_t k = 0; k < ndel && ok && dd_num_vertices(t) > 8; k++) {
        const uint32_t v = ws_random_vertex(t, &r);
        const uint32_t nv = dd_num_vertices(t);
        const dd_status ds = delete_by(t, v, variant);
        const int cr = dd_cgal_rt_remove(c, v);
        if (ds != DD_OK || cr != 0) {
            ok = 0, snprintf(why, sizeof why, "deleting %u (step %u): %s (%s); CGAL %d", v, k, dd_status_name(ds),
                             dd_errmsg(t), cr);
            break;
        }
        back += dd_num_vertices(t) + 1 - nv;
        done++;
        ok = ws_deleted_ok(t, c, v, k, why, sizeof why);
    }
    if (ok && done == 0) ok = 0, snprintf(why, sizeof why, "nothing deleted");
    tl_check(st, ok, tn, "%s", why);
    if (ok && !small)
        fprintf(stderr, "  %s: %u deletions, %u hidden points came back\n", tn, done, back);
    dd_free(t);
    dd_cgal_rt_free(c);
}

static void delete_all(tl_state *st, const char *name, const wset *s, uint32_t ndel)
{
    for (int keep = 1; keep >= 0; keep--)
        for (size_t k = 0; k < NSTRAT; k++) delete_case(st, name, s, ndel, strategies[k], keep);
}

/* ---- zero weights ----------------------------------------------------------------- */

/* Every weight zero: each strategy's weighted deletions give, step by
 * step, the cells of its unweighted deletions of the same points.      */
static void zero_case(tl_state *st, const char *name, const wset *s0, uint32_t ndel)
{
    wset s = *s0;
    double *w = calloc(s.n, sizeof *w);
    s.w = w;
    for (size_t k = 0; k < NSTRAT; k++) {
        char tn[200], why[256] = "", msg[256];
        snprintf(tn, sizeof tn, "wgrr/zero-weights/%s/%s", name, strategies[k]);
        dd_tri *a = NULL, *b = NULL;
        int ok = dd_create_ex(&a, s.p, s.w, s.n, 0, msg, sizeof msg) == DD_OK &&
                 dd_create_ex(&b, s.p, NULL, s.n, 0, msg, sizeof msg) == DD_OK;
        if (!ok) snprintf(why, sizeof why, "build: %.200s", msg);
        tl_rng r = {0x2e60 + s.n};
        for (uint32_t j = 0; j < ndel && ok && dd_num_vertices(a) > 8; j++) {
            const uint32_t v = ws_random_vertex(a, &r);
            const dd_status da = delete_by(a, v, strategies[k]), db = delete_by(b, v, strategies[k]);
            if (da != DD_OK || db != DD_OK) {
                ok = 0, snprintf(why, sizeof why, "deleting %u: weighted %s, unweighted %s", v, dd_status_name(da),
                                 dd_status_name(db));
                break;
            }
            shot x = take_shot(a);
            ok = unchanged(b, &x) && checked(a, why, sizeof why);
            if (!ok && !why[0]) snprintf(why, sizeof why, "step %u (deleting %u): the cells differ", j, v);
            shot_free(&x);
        }
        tl_check(st, ok, tn, "%s", why);
        dd_free(a);
        dd_free(b);
    }
    free(w);
}

/* ---- allocation failures ---------------------------------------------------------- */

#ifdef DD_TEST_BUILD
static void fault_case(tl_state *st)
{
    wset s = gen_uniform(small ? 80 : 150, 3, 21);
    dd_cgal_rt *c;
    const uint32_t v = ws_releasing_vertex(&s, &c);
    if (v == UINT32_MAX) {
        tl_check(st, 0, "wgrr/fault", "no vertex releases a hidden point");
        ws_free(&s);
        return;
    }
    for (size_t k = 0; k < NSTRAT; k++) {
        char tn[160];
        snprintf(tn, sizeof tn, "wgrr/fault/%s", strategies[k]);
        ws_fault_delete(st, tn, &s, v, c, delete_by, &strategies[k], 1);
    }
    dd_cgal_rt_free(c);
    ws_free(&s);
}
#endif

int main(int argc, char **argv)
{
    small = argc > 1 && !strcmp(argv[1], "small");
    tl_state st = {0, 0};
    const uint32_t n = small ? 150 : 600, nd = small ? 20 : 100;
    const double scales[] = {0.01, 1, 3, 10};
    for (size_t k = 0; k < sizeof scales / sizeof *scales; k++) {
        char name[64];
        snprintf(name, sizeof name, "uniform-w%g", scales[k]);
        wset s = gen_uniform(n, scales[k], 100 + k);
        delete_all(&st, name, &s, nd);
        if (k == 2) zero_case(&st, "uniform", &s, nd);
        ws_free(&s);
    }
    wset s = gen_grid(small ? 4 : 5, small ? 30 : 80, 0, 5);
    delete_all(&st, "grid", &s, s.n);
    zero_case(&st, "grid", &s, s.n);
    ws_free(&s);
    s = gen_grid(small ? 4 : 5, small ? 30 : 80, 1, 6);
    delete_all(&st, "grid-dups", &s, s.n);
    ws_free(&s);
    s = gen_molecule(small ? 4 : 7, 1);
    delete_all(&st, "molecule", &s, nd);
    ws_free(&s);
    s = gen_curve(small ? 80 : 200, 0, 3);     /* degree about n: half the sample in release */
    delete_all(&st, "moment-curve", &s, small ? nd : nd / 2);
    zero_case(&st, "moment-curve", &s, small ? nd : nd / 2);
    ws_free(&s);
    s = gen_curve(small ? 150 : 500, 1, 4);
    delete_all(&st, "helix", &s, nd);
    ws_free(&s);
#ifdef DD_TEST_BUILD
    fault_case(&st);
#endif
    return tl_finish(&st);
}
