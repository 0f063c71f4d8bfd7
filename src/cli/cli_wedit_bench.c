/*
 * cli_wedit_bench.c -- `dtdel wedit-bench`: the edits of a regular
 * triangulation (issue 44) against CGAL's Regular_triangulation_3 in the
 * same run, hidden points kept, each result compared with CGAL's (cells
 * and hidden set):
 *  - set deletion: a random 10% and 90% of M weighted points (default
 *    2*10^5) deleted by dd_delete_set, against CGAL's remove() of each,
 *    one at a time (its handles found untimed);
 *  - moves: every vertex of N weighted points (default 10^5) moved by a
 *    random step of 5% of the mean spacing, its weight kept, P passes
 *    (default 2), in input order, dd_move against CGAL's remove and
 *    insert (the move reference, DESIGN 12; CGAL's move() refuses a
 *    point that ends hidden);
 *  - re-weighting: every vertex of the N points re-weighted in place by
 *    a random factor in [0.9, 1.1], dd_move_weighted against the same.
 * --dataset: a weighted dataset (default wuniform).  A mismatch exits 1.
 */
#include "cli/cli.h"
#include "dtdel/alloc.h"
#include "cgal/cgal_regular.h"
#include "datasets/datasets.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct wb_opts {
    uint64_t n, m, passes, seed;
    const char *dataset;
} wb_opts;

static long compare(const dd_tri *t, const dd_cgal_rt *c)
{
    int32_t *a = NULL, *b = NULL;
    uint32_t *ha = NULL, *hb = NULL;
    size_t na = 0, nb = 0, nha = 0, nhb = 0;
    long bad = 0;
    if (dd_canonical(t, &a, &na) != DD_OK || dd_cgal_rt_canonical(c, &b, &nb) || !same_canonical(a, na, b, nb))
        bad++;
    if (dd_hidden(t, &ha, &nha) != DD_OK || dd_cgal_rt_hidden(c, &hb, &nhb) || nha != nhb ||
        (nha && memcmp(ha, hb, nha * sizeof *ha)))
        bad++;
    dd_mfree(a), dd_mfree(b), dd_mfree(ha), dd_mfree(hb);
    return bad;
}

/* Both triangulations of n points of the dataset. */
static int make_both(const wb_opts *o, uint64_t n, uint64_t seed, double **p, double **w, uint32_t *np, dd_tri **t,
                     dd_cgal_rt **c)
{
    char msg[256];
    if (dd_gen_weighted(o->dataset, (uint32_t)n, seed, p, w, np, msg, sizeof msg) != DD_OK || !*w) {
        fprintf(stderr, "dtdel wedit-bench: %s\n", *msg ? msg : "not a weighted dataset");
        return 1;
    }
    *c = dd_cgal_rt_build(*p, *w, *np, 0);
    if (!*c || dd_create_ex(t, *p, *w, *np, 0, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel wedit-bench: cannot build: %s\n", msg);
        return 1;
    }
    return 0;
}

static int set_deletion(const wb_opts *o, double fraction)
{
    double *p = NULL, *w = NULL;
    uint32_t np = 0;
    dd_tri *t = NULL;
    dd_cgal_rt *c = NULL;
    int rc = make_both(o, o->m, o->seed + 3, &p, &w, &np, &t, &c);
    uint32_t *vs = dd_malloc((size_t)np * sizeof *vs), k = 0;
    uint64_t x = o->seed * 0xD1B54A32D192ED03ull | 1;
    rc |= !vs;
    for (uint32_t i = 0; !rc && i < np; i++)
        if (dd_is_vertex(t, i) && rand_below(&x, 1u << 30) < fraction * (1u << 30)) vs[k++] = i;
    for (uint32_t i = k; !rc && i > 1; i--) {
        uint32_t j = rand_below(&x, i), s = vs[i - 1];
        vs[i - 1] = vs[j], vs[j] = s;
    }
    if (!rc) {
        const size_t h0 = dd_num_input(t) - dd_num_vertices(t);
        double t0 = now_seconds();
        rc |= dd_delete_set(t, vs, k) != DD_OK;
        double ours = now_seconds() - t0;
        double theirs = dd_cgal_rt_time_remove_set(c, vs, k);
        const long bad = rc || theirs < 0 ? 1 : compare(t, c);
        printf("weighted delete-set %.0f%%: %u of %u %s points (%zu not vertices): dtdel %.3f s, CGAL remove() one "
               "at a time %.3f s (%.1fx); identical to CGAL: %s\n",
               100 * fraction, k, np, o->dataset, h0, ours, theirs, theirs / ours, bad ? "NO" : "yes");
        rc |= bad != 0;
    }
    dd_free(t);
    dd_cgal_rt_free(c);
    dd_mfree(p), dd_mfree(w), dd_mfree(vs);
    return rc;
}

/* A pass of moves (reweight 0) or re-weightings (reweight 1). */
static int moves(const wb_opts *o, int reweight)
{
    double *p = NULL, *w = NULL;
    uint32_t np = 0;
    dd_tri *t = NULL;
    dd_cgal_rt *c = NULL;
    int rc = make_both(o, o->n, o->seed, &p, &w, &np, &t, &c);
    const uint64_t passes = reweight ? 1 : o->passes;
    size_t k = 0, cap = (size_t)passes * np;
    uint32_t *who = dd_malloc(cap * sizeof *who);
    double *to = dd_malloc(3 * cap * sizeof *to), *tw = dd_malloc(cap * sizeof *tw);
    rc |= !who || !to || !tw;
    const double h = 0.05 * cbrt(1.0 / np);
    uint64_t x = o->seed * 0x9E3779B97F4A7C15ull | 1;
    for (uint64_t pass = 0; !rc && pass < passes; pass++)
        for (uint32_t v = 0; v < np; v++) {
            if (!dd_is_vertex(t, v)) continue;     /* hidden at the start: left alone */
            who[k] = v;
            for (int d = 0; d < 3; d++) {
                if (!reweight) p[3 * (size_t)v + d] += h * (2.0 * rand_below(&x, 1u << 30) / (1u << 30) - 1);
                to[3 * k + (size_t)d] = p[3 * (size_t)v + d];
            }
            if (reweight) w[v] *= 0.9 + 0.2 * rand_below(&x, 1u << 30) / (1u << 30);
            tw[k++] = w[v];
        }
    if (!rc) {
        dd_counters c0, c1;
        dd_reset_counters(t);
        dd_get_counters(t, &c0);
        long bad = 0;
        double t0 = now_seconds();
        for (size_t i = 0; i < k; i++) bad += dd_move_weighted(t, who[i], to + 3 * i, tw[i]) != DD_OK;
        double ours = now_seconds() - t0;
        dd_get_counters(t, &c1);
        double theirs = dd_cgal_rt_time_moves(c, who, to, tw, k);
        if (theirs >= 0) bad += compare(t, c);
        char cg[64] = "CGAL failed";
        if (theirs >= 0) snprintf(cg, sizeof cg, "CGAL remove+insert %.2f us (%.1fx)", 1e6 * theirs / (double)k,
                                  theirs / ours);
        printf("weighted %s: %zu %s of %u %s points: dtdel %.2f us, %s; kept by the filter %.1f%%; identical to "
               "CGAL: %s\n",
               reweight ? "re-weighting +-10%" : "moves of 5% of the spacing", k, reweight ? "re-weightings" : "moves",
               np, o->dataset, 1e6 * ours / (double)k, cg, 100.0 * (double)(c1.moves_kept - c0.moves_kept) / (double)k,
               theirs < 0 ? "n/a" : bad ? "NO" : "yes");
        rc |= bad != 0;
    }
    dd_free(t);
    dd_cgal_rt_free(c);
    dd_mfree(p), dd_mfree(w), dd_mfree(who), dd_mfree(to), dd_mfree(tw);
    return rc;
}

int cmd_wedit_bench(int argc, char **argv)
{
    if (wants_help(argc, argv)) return print_help("wedit-bench");
    wb_opts o = {100000, 200000, 2, 1, "wuniform"};
    char *args[32];
    int na = 0;
    for (int i = 0; i < argc && na < 32; i++) {
        if (!strcmp(argv[i], "--dataset") && i + 1 < argc) o.dataset = argv[++i];
        else args[na++] = argv[i];
    }
    const num_opt opts[] = {{NULL, &o.n}, {"--set", &o.m}, {"--passes", &o.passes}, {"--seed", &o.seed}};
    int rc = parse_num_opts("wedit-bench", na, args, opts, (int)(sizeof opts / sizeof *opts));
    if (rc) return rc;
    if (o.n < 8 || o.m < 8) return usage_error("wedit-bench", "N and --set must be at least %s", "8");
    rc |= set_deletion(&o, 0.1);
    rc |= set_deletion(&o, 0.9);
    rc |= moves(&o, 0);
    rc |= moves(&o, 1);
    return rc;
}
