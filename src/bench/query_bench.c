/*
 * query_bench.c -- `dtdel query-bench`: insertion of new points, point
 * location and nearest-vertex queries against CGAL, with and without
 * CGAL's Fast_location (its Delaunay hierarchy), and the memory of a
 * triangulation under churn.  What make bench writes to results/queries.txt.
 *
 * Each timing is one pass over the same points in the same order for
 * every row; the insertions' result is compared with CGAL's simplex for
 * simplex, each nearest vertex with CGAL's (the same, or as near), and
 * the first located cells with CGAL's.  The tests check location exactly
 * (tests/test_access.c).
 */
#include "bench/bench.h"
#include "cgal/cgal_query.h"
#include "dtdel/alloc.h"

#include <stdlib.h>
#include <string.h>

/* Resident set size in bytes (/proc/self/statm), 0 if unknown. */
static size_t rss_bytes(void)
{
    FILE *f = fopen("/proc/self/statm", "r");
    unsigned long size = 0, res = 0;
    if (!f) return 0;
    if (fscanf(f, "%lu %lu", &size, &res) != 2) res = 0;
    fclose(f);
    return (size_t)res * 4096;
}

typedef struct qb_opts {
    uint64_t n, inserts, queries, seed, live, rounds;
} qb_opts;

static int parse_opts(int argc, char **argv, qb_opts *o)
{
    *o = (qb_opts){200000, 50000, 50000, 1, 100000, 12};
    const num_opt opts[] = {{NULL, &o->n},          {"--inserts", &o->inserts}, {"--queries", &o->queries},
                            {"--seed", &o->seed},   {"--live", &o->live},       {"--rounds", &o->rounds}};
    int rc = parse_num_opts("query-bench", argc, argv, opts, (int)(sizeof opts / sizeof *opts));
    if (rc) return rc;
    if (o->n < 4 || o->live < 8) return usage_error("query-bench", "N and --live must be at least %s", "8");
    return 0;
}

/* Seconds per operation for ours and for CGAL's two rows, and whether
 * each answer was right.                                                */
typedef struct qb_row { double ours, cgal, fast; long bad; } qb_row;

static void print_row(const char *what, uint64_t k, const qb_row *r, const char *check)
{
    printf("%s: %llu: dtdel %.2f us, CGAL %.2f us (%.1fx), CGAL Fast_location %.2f us (%.1fx); %s: %s\n", what,
           (unsigned long long)k, 1e6 * r->ours, 1e6 * r->cgal, r->cgal / r->ours, 1e6 * r->fast, r->fast / r->ours,
           check, r->bad ? "NO" : "yes");
}

int same_as_cgalq(dd_tri *t, const dd_cgalq *g)
{
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    int same = dd_canonical(t, &a, &na) == DD_OK && !dd_cgalq_canonical(g, &b, &nb) && na == nb &&
               !memcmp(a, b, 4 * na * sizeof *a);
    dd_mfree(a);
    dd_mfree(b);
    return same;
}

/* Insertion of the k new points p[3i..] one at a time, ours then CGAL's
 * plain and fast rows; indices n, n + 1, ... on both sides.             */
static qb_row bench_insert(dd_tri *t, dd_cgalq *g, dd_cgalq *gf, const double *p, uint64_t k, uint32_t n)
{
    qb_row r = {0, 0, 0, 0};
    double t0 = now_seconds();
    for (uint64_t i = 0; i < k; i++) {
        uint32_t idx;
        r.bad += dd_insert(t, p + 3 * i, &idx) != DD_OK || idx != n + i;
    }
    double t1 = now_seconds();
    for (uint64_t i = 0; i < k; i++) r.bad += dd_cgalq_insert(g, p + 3 * i, n + (uint32_t)i) != 0;
    double t2 = now_seconds();
    for (uint64_t i = 0; i < k; i++) r.bad += dd_cgalq_insert(gf, p + 3 * i, n + (uint32_t)i) != 0;
    double t3 = now_seconds();
    r.ours = (t1 - t0) / (double)k, r.cgal = (t2 - t1) / (double)k, r.fast = (t3 - t2) / (double)k;
    r.bad += !same_as_cgalq(t, g);
    return r;
}

/* dd_locate of each query point, then CGAL's two locates.              */
static qb_row bench_locate(dd_tri *t, dd_cgalq *g, dd_cgalq *gf, const double *q, uint64_t k)
{
    qb_row r = {0, 0, 0, 0};
    int32_t c[4], d[4];
    int32_t *ours = dd_malloc(4 * k * sizeof *ours);
    if (!ours) { r.bad = 1; return r; }
    double t0 = now_seconds();
    for (uint64_t i = 0; i < k; i++) r.bad += dd_locate(t, q + 3 * i, ours + 4 * i) != DD_OK;
    double t1 = now_seconds();
    for (uint64_t i = 0; i < k; i++) r.bad += dd_cgalq_locate(g, q + 3 * i, c) != 0;
    double t2 = now_seconds();
    for (uint64_t i = 0; i < k; i++) r.bad += dd_cgalq_locate(gf, q + 3 * i, d) != 0;
    double t3 = now_seconds();
    r.ours = (t1 - t0) / (double)k, r.cgal = (t2 - t1) / (double)k, r.fast = (t3 - t2) / (double)k;
    /* the same cell as CGAL's for a point inside the hull (a random point
     * lies in one cell); outside, any infinite cell whose facet it sees  */
    long differ = 0;
    for (uint64_t i = 0; i < k && i < 2000; i++) {
        dd_cgalq_locate(g, q + 3 * i, c);
        const int32_t *o = ours + 4 * i;
        int same = 1, outside = 0;
        for (int a = 0; a < 4; a++) {
            int found = 0;
            for (int b = 0; b < 4; b++) found |= o[a] == c[b];
            same &= found;
            outside += (o[a] < 0) + (c[a] < 0);
        }
        differ += !same && outside != 2;
    }
    r.bad += differ > 0;
    dd_mfree(ours);
    return r;
}

static qb_row bench_nearest(dd_tri *t, dd_cgalq *g, dd_cgalq *gf, const double *q, uint64_t k)
{
    qb_row r = {0, 0, 0, 0};
    uint32_t *ours = dd_malloc(k * sizeof *ours);
    int64_t *theirs = dd_malloc(k * sizeof *theirs);
    if (!ours || !theirs) { dd_mfree(ours); dd_mfree(theirs); r.bad = 1; return r; }
    double t0 = now_seconds();
    for (uint64_t i = 0; i < k; i++)
        if (dd_nearest_vertex(t, q + 3 * i, &ours[i]) != DD_OK) ours[i] = UINT32_MAX;
    double t1 = now_seconds();
    for (uint64_t i = 0; i < k; i++) theirs[i] = dd_cgalq_nearest(g, q + 3 * i);
    double t2 = now_seconds();
    for (uint64_t i = 0; i < k; i++) r.bad += dd_cgalq_nearest(gf, q + 3 * i) != theirs[i];
    double t3 = now_seconds();
    r.ours = (t1 - t0) / (double)k, r.cgal = (t2 - t1) / (double)k, r.fast = (t3 - t2) / (double)k;
    for (uint64_t i = 0; i < k; i++) {   /* a tie may pick another vertex: compare distances */
        if ((int64_t)ours[i] == theirs[i]) continue;
        double a[3], b[3];
        if (theirs[i] < 0 || dd_point(t, ours[i], a) != DD_OK || dd_point(t, (uint32_t)theirs[i], b) != DD_OK) {
            r.bad++;
            continue;
        }
        double da = 0, db = 0;
        for (int c = 0; c < 3; c++) {
            da += (a[c] - q[3 * i + c]) * (a[c] - q[3 * i + c]);
            db += (b[c] - q[3 * i + c]) * (b[c] - q[3 * i + c]);
        }
        r.bad += da != db;
    }
    dd_mfree(ours);
    dd_mfree(theirs);
    return r;
}

/* Churn: `rounds` rounds of deleting a random half of the vertices
 * (dd_delete_set) and inserting as many new points; prints the RSS and
 * dd_memory_bytes after rounds 2 and the last, and returns 1 when the
 * last is over 1.3 times round 2's.                                      */
static int churn(const qb_opts *o)
{
    double *p = NULL;
    uint32_t np;
    if (gen_points("query-bench", "uniform", o->live, o->seed + 7, &p, &np)) return 1;
    dd_tri *t;
    char msg[256];
    if (dd_create(&t, p, np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel query-bench: %s\n", msg);
        dd_mfree(p);
        return 1;
    }
    dd_mfree(p);
    uint64_t x = o->seed * 0x9E3779B97F4A7C15ull | 1;
    uint32_t *live = dd_malloc((size_t)np * sizeof *live), nlive = np, half = np / 2;
    size_t rss2 = 0, mem2 = 0, rss = 0, mem = 0;
    int rc = !live;
    for (uint32_t i = 0; live && i < np; i++) live[i] = i;
    for (uint64_t round = 1; !rc && round <= o->rounds; round++) {
        for (uint32_t i = 0; i < half; i++) {   /* a random half to the front */
            uint32_t j = i + rand_below(&x, nlive - i), s = live[i];
            live[i] = live[j];
            live[j] = s;
        }
        rc |= dd_delete_set(t, live, half) != DD_OK;
        for (uint32_t i = 0; !rc && i < half; i++) {
            double q[3] = {(rand_below(&x, 1u << 30) + 0.5) / (1u << 30), (rand_below(&x, 1u << 30) + 0.5) / (1u << 30),
                           (rand_below(&x, 1u << 30) + 0.5) / (1u << 30)};
            uint32_t idx;
            dd_status s = dd_insert(t, q, &idx);
            if (s == DD_OK) live[i] = idx;
            else if (s == DD_ERR_DUPLICATE) i--;
            else rc = 1;
        }
        rss = rss_bytes(), mem = dd_memory_bytes(t);
        if (round == 2) rss2 = rss, mem2 = mem;
    }
    rc |= dd_check(t) != DD_OK;
    printf("churn: %u live vertices, %llu rounds of deleting half and inserting as many: RSS %.1f MiB after "
           "round 2, %.1f MiB after round %llu (%.2fx); arrays %.1f MiB, %.1f MiB (%.2fx); valid: %s\n",
           np, (unsigned long long)o->rounds, (double)rss2 / 1048576.0, (double)rss / 1048576.0,
           (unsigned long long)o->rounds, rss2 ? (double)rss / (double)rss2 : 0, (double)mem2 / 1048576.0,
           (double)mem / 1048576.0,
           mem2 ? (double)mem / (double)mem2 : 0, rc ? "NO" : "yes");
    dd_mfree(live);
    dd_free(t);
    return rc || (o->rounds >= 2 && (double)rss > 1.3 * (double)rss2);
}

int cmd_query_bench(int argc, char **argv)
{
    qb_opts o;
    int rc = parse_opts(argc, argv, &o);
    if (rc) return rc;
    double *p = NULL, *ins = NULL, *q = NULL;
    uint32_t np, nins, nq;
    if (gen_points("query-bench", "uniform", o.n, o.seed, &p, &np) ||
        gen_points("query-bench", "uniform", o.inserts, o.seed + 1, &ins, &nins) ||
        gen_points("query-bench", "uniform", o.queries, o.seed + 2, &q, &nq)) {
        dd_mfree(p), dd_mfree(ins), dd_mfree(q);
        return EXIT_INPUT;
    }
    dd_tri *t = NULL;
    char msg[256];
    dd_cgalq *g = dd_cgalq_build(p, np, 0), *gf = dd_cgalq_build(p, np, 1);
    if (dd_create(&t, p, np, msg, sizeof msg) != DD_OK || !g || !gf) {
        fprintf(stderr, "dtdel query-bench: cannot build the triangulations\n");
        rc = EXIT_INPUT;
    } else {
        printf("dataset uniform, n = %u; new points and queries uniform in the same cube (seed %llu)\n", np,
               (unsigned long long)o.seed);
        qb_row r = bench_insert(t, g, gf, ins, nins, np);
        print_row("insert", nins, &r, "identical to CGAL");
        rc |= r.bad != 0;
        r = bench_locate(t, g, gf, q, nq);
        print_row("locate", nq, &r, "same cells as CGAL");
        rc |= r.bad != 0;
        r = bench_nearest(t, g, gf, q, nq);
        print_row("nearest", nq, &r, "nearest as CGAL's");
        rc |= r.bad != 0;
    }
    dd_cgalq_free(g);
    dd_cgalq_free(gf);
    dd_free(t);
    dd_mfree(p), dd_mfree(ins), dd_mfree(q);
    fflush(stdout);
    if (!rc && o.rounds) rc |= churn(&o);
    return rc ? EXIT_INPUT : 0;
}
