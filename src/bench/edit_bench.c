/*
 * edit_bench.c -- `dtdel edit-bench`: the edits mesh generators and
 * smoothers run most, against CGAL, each result compared with CGAL's
 * simplex for simplex.  What make bench writes to results/edits.txt:
 *  - smoothing: every vertex of N uniform points moved by a random step
 *    of 5% of the mean spacing, P passes, the same moves in the same
 *    order for dd_move and CGAL's move_if_no_collision; run twice, on a
 *    fresh triangulation each time, with the same moves:
 *      first in input order, the generated points numbered and visited
 *      as they come, random in space (DESIGN §10: the headline row):
 *        smoothing: N uniform points, P passes of a random step of 5% of
 *        the mean spacing: dtdel A us, CGAL move_if_no_collision B us
 *        (Rx); kept by the filter K%; identical to CGAL: yes|NO
 *      then along a Morton curve, as a mesh may store its vertices,
 *      reported beside it, never instead: the same line with the prefix
 *        smoothing (Morton order): N uniform points, ...
 *    (one line each; A and B are the mean per move over all P N moves,
 *    K the share of moves dd_move's filter kept with no cell changed);
 *    then the same moves by dd_move_many, a call a pass, beside both
 *    CGAL loops' times:
 *        smoothing by dd_move_many: N uniform points, P passes ...: dtdel
 *        A us a move, CGAL move_if_no_collision B us in input order (Rx),
 *        C us in Morton order (R2x); identical to CGAL: yes|NO
 *  - set deletion: a random 10%, 50% and 90% of M uniform points deleted
 *    by dd_delete_set and by CGAL's remove(first, last).
 */
#include "bench/bench.h"
#include "cgal/cgal_query.h"
#include "dtdel/alloc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct eb_opts {
    uint64_t n, passes, m, seed;
} eb_opts;

static int parse_opts(int argc, char **argv, eb_opts *o)
{
    *o = (eb_opts){100000, 2, 200000, 1};
    const num_opt opts[] = {{NULL, &o->n}, {"--passes", &o->passes}, {"--set", &o->m}, {"--seed", &o->seed}};
    int rc = parse_num_opts("edit-bench", argc, argv, opts, (int)(sizeof opts / sizeof *opts));
    if (rc) return rc;
    if (o->n < 8 || o->m < 8) return usage_error("edit-bench", "N and --set must be at least %s", "8");
    return 0;
}

/* The Morton code of a point of the unit cube: the low 21 bits of x, y,
 * z interleaved.                                                       */
static uint64_t morton(const double *p)
{
    uint64_t k = 0;
    for (int b = 20; b >= 0; b--)
        for (int c = 0; c < 3; c++) k = k << 1 | ((uint64_t)(p[c] * 2097152.0) >> b & 1);
    return k;
}

typedef struct keyed {
    uint64_t key;
    uint32_t i;
} keyed;

static int by_key(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    return x->key != y->key ? (x->key > y->key) - (x->key < y->key) : (x->i > y->i) - (x->i < y->i);
}

/* order[0..np): the generated points along a Morton curve (ties by
 * index, so the order is the same on every machine).  0, or 1 out of
 * memory.                                                              */
static int sort_by_morton(const double *p, uint32_t np, uint32_t *order)
{
    keyed *ks = dd_malloc((size_t)np * sizeof *ks);
    if (!ks) return 1;
    for (uint32_t i = 0; i < np; i++) ks[i] = (keyed){morton(p + 3 * (size_t)i), i};
    qsort(ks, np, sizeof *ks, by_key);
    for (uint32_t i = 0; i < np; i++) order[i] = ks[i].i;
    dd_mfree(ks);
    return 0;
}

/* One smoothing run: vertex i is generated point order[i], and each
 * pass visits the vertices in index order, i = 0, 1, ...  Point j's
 * step in pass s is step[3 (s np + j)], whatever the order, so every
 * order makes the same moves (the same targets, bit for bit), only in
 * another sequence.  The moves are replayed with dd_move, all timed,
 * then with CGAL's move_if_no_collision; prints the line `label: ...`
 * (format in the file's comment).  0, or 1 if a call failed or the
 * result differs from CGAL's.                                          */
static int smooth_in_order(const eb_opts *o, const double *p, uint32_t np, const uint32_t *order,
                           const double *step, const char *label, double *cgal_per_move)
{
    const uint64_t k = o->passes * np;
    uint32_t *who = dd_malloc(k * sizeof *who);
    double *to = dd_malloc(3 * k * sizeof *to), *cur = dd_malloc(3 * (size_t)np * sizeof *cur);
    dd_tri *t = NULL;
    dd_cgalq *g = NULL;
    char msg[256];
    int rc = !who || !to || !cur;
    for (uint32_t i = 0; !rc && i < np; i++)
        for (int c = 0; c < 3; c++) cur[3 * (size_t)i + c] = p[3 * (size_t)order[i] + c];
    if (!rc) g = dd_cgalq_build(cur, np, 0);
    rc = rc || !g || dd_create(&t, cur, np, msg, sizeof msg) != DD_OK;
    for (uint64_t i = 0; !rc && i < k; i++) {
        const uint32_t v = (uint32_t)(i % np);
        const double *s = step + 3 * (i - v + order[v]);
        who[i] = v;
        for (int c = 0; c < 3; c++) to[3 * i + c] = cur[3 * v + c] += s[c];
    }
    long bad = 0;
    if (!rc) {
        dd_counters c0, c1;
        dd_reset_counters(t);
        dd_get_counters(t, &c0);
        double t0 = now_seconds();
        for (uint64_t i = 0; i < k; i++) bad += dd_move(t, who[i], to + 3 * i) != DD_OK;
        double t1 = now_seconds();
        for (uint64_t i = 0; i < k; i++) bad += dd_cgalq_move(g, who[i], to + 3 * i) != 0;
        double t2 = now_seconds();
        dd_get_counters(t, &c1);
        const double ours = (t1 - t0) / (double)k, theirs = (t2 - t1) / (double)k;
        *cgal_per_move = theirs;
        bad += !same_as_cgalq(t, g);
        printf("%s: %u uniform points, %llu passes of a random step of 5%% of the mean spacing: dtdel %.2f us, "
               "CGAL move_if_no_collision %.2f us (%.1fx); kept by the filter %.1f%%; identical to CGAL: %s\n",
               label, np, (unsigned long long)o->passes, 1e6 * ours, 1e6 * theirs, theirs / ours,
               100.0 * (double)(c1.moves_kept - c0.moves_kept) / (double)k, bad ? "NO" : "yes");
        fflush(stdout);
    }
    dd_free(t);
    dd_cgalq_free(g);
    dd_mfree(who), dd_mfree(to), dd_mfree(cur);
    return rc || bad;
}

/* The same moves (input order) by dd_move_many, one call a pass of every
 * vertex, against the two CGAL loops' times per move; the result against
 * CGAL's DT of the moved points.  0, or 1 on a failure or a difference. */
static int smooth_many(const eb_opts *o, const double *p, uint32_t np, const double *step, double cgal_input,
                       double cgal_morton)
{
    uint32_t *vs = dd_malloc((size_t)np * sizeof *vs);
    double *cur = dd_malloc(3 * (size_t)np * sizeof *cur);
    dd_tri *t = NULL;
    char msg[256];
    int rc = !vs || !cur || dd_create(&t, p, np, msg, sizeof msg) != DD_OK;
    double ours = 0;
    if (!rc) memcpy(cur, p, 3 * (size_t)np * sizeof *cur);
    for (uint32_t i = 0; !rc && i < np; i++) vs[i] = i;
    for (uint64_t s = 0; !rc && s < o->passes; s++) {
        for (size_t i = 0; i < 3 * (size_t)np; i++) cur[i] += step[3 * s * np + i];
        const double t0 = now_seconds();
        rc = dd_move_many(t, vs, cur, NULL, np) != DD_OK;
        ours += now_seconds() - t0;
    }
    dd_cgalq *g = rc ? NULL : dd_cgalq_build(cur, np, 0);
    rc = rc || !g;
    if (!rc) {
        const int same = same_as_cgalq(t, g);
        const double per = ours / (double)(o->passes * np);
        printf("smoothing by dd_move_many: %u uniform points, %llu passes of a random step of 5%% of the mean spacing: "
               "dtdel %.2f us a move, CGAL move_if_no_collision %.2f us in input order (%.1fx), %.2f us in Morton "
               "order (%.1fx); identical to CGAL: %s\n",
               np, (unsigned long long)o->passes, 1e6 * per, 1e6 * cgal_input, cgal_input / per, 1e6 * cgal_morton,
               cgal_morton / per, same ? "yes" : "NO");
        rc = !same;
    }
    dd_free(t);
    dd_cgalq_free(g);
    dd_mfree(vs), dd_mfree(cur);
    return rc;
}

/* The smoothing workload: the steps drawn first, one per point and
 * pass, then two runs of the same moves (DESIGN §10): the headline in
 * input order (the generated points as they come, random in space),
 * then along a Morton curve, as a mesh may store its vertices and a
 * smoother sweep them.                                                 */
static int smoothing(const eb_opts *o)
{
    double *p = NULL;
    uint32_t np;
    if (gen_points("edit-bench", "uniform", o->n, o->seed, &p, &np)) return 1;
    const uint64_t k = o->passes * np;
    double *step = dd_malloc(3 * k * sizeof *step);
    uint32_t *order = dd_malloc((size_t)np * sizeof *order);
    int rc = !step || !order;
    const double h = 0.05 * cbrt(1.0 / np);                    /* 5% of the mean spacing */
    uint64_t x = o->seed * 0x9E3779B97F4A7C15ull | 1;
    for (uint64_t i = 0; !rc && i < 3 * k; i++) step[i] = h * (2.0 * rand_below(&x, 1u << 30) / (1u << 30) - 1);
    for (uint32_t i = 0; !rc && i < np; i++) order[i] = i;
    double cgal_input = 0, cgal_morton = 0;
    if (!rc) {
        rc |= smooth_in_order(o, p, np, order, step, "smoothing", &cgal_input);
        rc |= sort_by_morton(p, np, order) ||
              smooth_in_order(o, p, np, order, step, "smoothing (Morton order)", &cgal_morton);
        fflush(stdout);
        rc |= smooth_many(o, p, np, step, cgal_input, cgal_morton);
    }
    dd_mfree(p), dd_mfree(step), dd_mfree(order);
    return rc;
}

/* A random `fraction` of m uniform points deleted as a set. */
static int set_deletion(const eb_opts *o, double fraction)
{
    double *p = NULL;
    uint32_t np;
    if (gen_points("edit-bench", "uniform", o->m, o->seed + 3, &p, &np)) return 1;
    uint32_t *vs = dd_malloc((size_t)np * sizeof *vs), k = 0;
    dd_tri *t = NULL;
    char msg[256];
    dd_cgalq *g = dd_cgalq_build(p, np, 0);
    int rc = !vs || !g || dd_create(&t, p, np, msg, sizeof msg) != DD_OK;
    uint64_t x = o->seed * 0xD1B54A32D192ED03ull | 1;
    for (uint32_t i = 0; !rc && i < np; i++)
        if (dd_is_vertex(t, i) && rand_below(&x, 1u << 30) < fraction * (1u << 30)) vs[k++] = i;
    for (uint32_t i = k; !rc && i > 1; i--) {   /* a random order: the caller's */
        uint32_t j = rand_below(&x, i), s = vs[i - 1];
        vs[i - 1] = vs[j], vs[j] = s;
    }
    if (!rc) {
        double t0 = now_seconds();
        rc |= dd_delete_set(t, vs, k) != DD_OK;
        double t1 = now_seconds();
        rc |= dd_cgalq_remove_set(g, vs, k) != 0;
        double t2 = now_seconds();
        const int same = !rc && same_as_cgalq(t, g);
        printf("delete-set %.0f%%: %u of %u uniform points: dtdel %.2f us a vertex, CGAL remove(first, last) %.2f "
               "us (%.1fx); identical to CGAL: %s\n",
               100 * fraction, k, np, 1e6 * (t1 - t0) / k, 1e6 * (t2 - t1) / k, (t2 - t1) / (t1 - t0),
               same ? "yes" : "NO");
        rc |= !same;
    }
    dd_free(t);
    dd_cgalq_free(g);
    dd_mfree(p), dd_mfree(vs);
    return rc;
}

int cmd_edit_bench(int argc, char **argv)
{
    eb_opts o;
    int rc = parse_opts(argc, argv, &o);
    if (rc) return rc;
    rc |= smoothing(&o);
    fflush(stdout);
    const double fractions[3] = {0.1, 0.5, 0.9};
    for (int i = 0; i < 3; i++) {
        rc |= set_deletion(&o, fractions[i]);
        fflush(stdout);
    }
    return rc ? EXIT_INPUT : 0;
}
