/*
 * regular_bench.c -- `dtdel regular-bench`: regular triangulations
 * (weighted points, DESIGN 12) against CGAL's Regular_triangulation_3 in
 * the same run (bench protocol, DESIGN 10), hidden points kept:
 *
 *   construction: N weighted points of dataset wuniform (default 10^6),
 *     dd_create_ex against CGAL's range insert, R times each, in turns;
 *     the medians compared, as build-bench compares them;
 *   insertion: M new weighted points (default 5*10^4) inserted one at a
 *     time into the regular triangulation of N0 (default 2*10^5), in the
 *     order they come (random in space), dd_insert_weighted against
 *     CGAL's insert hinted by the last vertex (cgal/cgal_regular.h).
 *
 * Results are compared after every construction and at five checkpoints
 * of the insertions (untimed): the canonical cells and the hidden set,
 * each a check; a check that differs is a mismatch, counted and printed.
 * While the engine refuses weights (DD_ERR_UNSUPPORTED) the rows print
 * "dtdel n/a" and CGAL's figures, and the command succeeds; a mismatch
 * exits 1.  What make bench writes to results/regular.txt.
 */
#include "bench/bench.h"
#include "dtdel/alloc.h"
#include "cgal/cgal_regular.h"

#include <stdlib.h>
#include <string.h>

#define RB_MAX_REPS 9
#define RB_CHECKPOINTS 5

typedef struct rb_opts {
    uint64_t n, n0, m, reps, seed;
} rb_opts;

/* The number of differing checks (cells, hidden set) between t and c. */
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

static size_t cgal_hidden_count(const dd_cgal_rt *c)
{
    uint32_t *h = NULL;
    size_t n = 0;
    if (dd_cgal_rt_hidden(c, &h, &n)) n = 0;
    dd_mfree(h);
    return n;
}

/* Construction of o->n weighted points, R times each in turns. */
static int construction(const rb_opts *o)
{
    double *p, *w;
    uint32_t np;
    char msg[512];
    if (dd_gen_weighted("wuniform", (uint32_t)o->n, o->seed, &p, &w, &np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel regular-bench: %s\n", msg);
        return EXIT_INPUT;
    }
    double ours[RB_MAX_REPS], theirs[RB_MAX_REPS];
    dd_tri *t = NULL;
    dd_cgal_rt *c = NULL;
    dd_status s = DD_OK;
    for (uint64_t r = 0; r < o->reps; r++) {
        dd_free(t);                          /* the last pair is compared */
        dd_cgal_rt_free(c);
        t = NULL;
        double t0 = now_seconds();
        s = dd_create_ex(&t, p, w, np, 0, msg, sizeof msg);
        double t1 = now_seconds();
        c = dd_cgal_rt_build(p, w, np, 0);
        double t2 = now_seconds();
        ours[r] = t1 - t0;
        theirs[r] = t2 - t1;
        if (s != DD_OK) t = NULL;
        if (!c) break;
    }
    int rc = 0;
    if (!c) {
        fprintf(stderr, "dtdel regular-bench: CGAL cannot build the regular triangulation\n");
        rc = EXIT_INPUT;
    } else {
        double tc = median_of(theirs, o->reps);
        printf("regular-build: %u wuniform weighted points, %zu hidden (CGAL), %llu runs each: ", np,
               cgal_hidden_count(c), (unsigned long long)o->reps);
        if (s == DD_OK) {
            long bad = compare(t, c);
            double to = median_of(ours, o->reps);
            printf("dtdel %.3f s, CGAL %.3f s (%.2fx); %ld mismatches\n", to, tc, tc / to, bad);
            rc = bad ? EXIT_INPUT : 0;
        } else {
            printf("dtdel n/a (%s), CGAL %.3f s; mismatches n/a\n", dd_status_name(s), tc);
            if (s != DD_ERR_UNSUPPORTED) rc = EXIT_INPUT;
        }
    }
    dd_free(t);
    dd_cgal_rt_free(c);
    dd_mfree(p), dd_mfree(w);
    return rc;
}

/* o->m weighted points inserted into the regular triangulation of o->n0. */
static int insertion(const rb_opts *o)
{
    double *p, *w;
    uint32_t np;
    char msg[512];
    const uint32_t n0 = (uint32_t)o->n0, m = (uint32_t)o->m;
    if (dd_gen_weighted("wuniform", n0 + m, o->seed + 1, &p, &w, &np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel regular-bench: %s\n", msg);
        return EXIT_INPUT;
    }
    dd_tri *t = NULL;
    dd_status s = dd_create_ex(&t, p, w, n0, 0, msg, sizeof msg);
    dd_cgal_rt *c = dd_cgal_rt_build(p, w, n0, 0);
    if (!c) {
        fprintf(stderr, "dtdel regular-bench: CGAL cannot build the regular triangulation\n");
        dd_free(t);
        dd_mfree(p), dd_mfree(w);
        return EXIT_INPUT;
    }
    double ours = 0, theirs = 0;
    long bad = 0, failed = 0;
    for (uint32_t k = 0; k < RB_CHECKPOINTS; k++) {
        const uint32_t lo = n0 + (uint32_t)((uint64_t)m * k / RB_CHECKPOINTS);
        const uint32_t hi = n0 + (uint32_t)((uint64_t)m * (k + 1) / RB_CHECKPOINTS);
        double t0 = now_seconds();
        for (uint32_t i = lo; s == DD_OK && i < hi; i++) {
            uint32_t idx;
            dd_status si = dd_insert_weighted(t, p + 3 * (size_t)i, w[i], &idx);
            if (si != DD_OK) s = si;
            else failed += idx != i;
        }
        double t1 = now_seconds();
        for (uint32_t i = lo; i < hi; i++) failed += dd_cgal_rt_insert(c, p + 3 * (size_t)i, w[i], i) != 0;
        double t2 = now_seconds();
        ours += t1 - t0;
        theirs += t2 - t1;
        if (s == DD_OK) bad += compare(t, c);
    }
    printf("regular-insert: %u wuniform weighted points into %u, %zu hidden at the end (CGAL): ", m, n0,
           cgal_hidden_count(c));
    int rc = 0;
    if (s == DD_OK) {
        printf("dtdel %.2f us an insertion, CGAL hinted insert %.2f us (%.2fx); %ld mismatches in %d checkpoints\n",
               1e6 * ours / m, 1e6 * theirs / m, theirs / ours, bad + failed, RB_CHECKPOINTS);
        rc = bad || failed ? EXIT_INPUT : 0;
    } else {
        printf("dtdel n/a (%s), CGAL hinted insert %.2f us; mismatches n/a\n", dd_status_name(s), 1e6 * theirs / m);
        if (s != DD_ERR_UNSUPPORTED) rc = EXIT_INPUT;
    }
    dd_free(t);
    dd_cgal_rt_free(c);
    dd_mfree(p), dd_mfree(w);
    return rc;
}

int cmd_regular_bench(int argc, char **argv)
{
    rb_opts o = {1000000, 200000, 50000, 3, 1};
    const num_opt opts[] = {{NULL, &o.n}, {"--base", &o.n0}, {"--inserts", &o.m}, {"--reps", &o.reps},
                            {"--seed", &o.seed}};
    int rc = parse_num_opts("regular-bench", argc, argv, opts, 5);
    if (rc) return rc;
    if (o.n < 4 || o.n0 < 4 || o.m < RB_CHECKPOINTS || o.reps < 1 || o.reps > RB_MAX_REPS)
        return usage_error("regular-bench", "N and --base need at least 4 points, --inserts 5, --reps 1 to 9%s",
                           "");
    rc = construction(&o);
    fflush(stdout);
    rc |= insertion(&o);
    return rc ? EXIT_INPUT : 0;
}
