/*
 * test_parallel.c -- construction on several threads (dtdel.h, DD_THREADS)
 * gives the one-thread triangulation: the canonical form, the counts, the
 * duplicates' aliases and the hidden points are those of one thread, at
 * 1, 2, 3 and 8 threads, and dd_check passes.
 *
 * Datasets: uniform, grid (integer points: every cell cospherical with
 * its neighbours), sphere (all on the hull), cosphere, helix, bunny, and
 * uniform with every fifth point repeated; weighted: wuniform, molecule
 * and wgrid, hidden points kept and discarded.  Also the thread count's
 * sources: DD_THREADS(n), DD_THREADS_ALL, the DTDEL_THREADS variable,
 * dd_set_threads (0: every core, 64 on any machine, past 1024 clamped),
 * and the refusals that do not depend on it (unknown flag bits,
 * coplanar input).  And the read-only batches, dd_locate_many and
 * dd_nearest_many, answer the same on every count.
 *
 * In the ThreadSanitizer build (make test) a data race between the
 * construction's threads fails the run.  Argument "small": smaller sets
 * (the sanitizer builds, whose rounds go parallel from a few points).
 */
#include "testlib.h"
#include <unistd.h>
#include "dtdel.h"
#include "../datasets/datasets.h"

static tl_state st = {0, 0};
static const unsigned counts[] = {1, 2, 3, 8};
#define NCOUNTS (sizeof counts / sizeof counts[0])

/* What must not depend on the thread count. */
typedef struct outcome {
    dd_status status;
    uint64_t hash;
    size_t ntets, nfinite;
    uint32_t nvert, ndup;
    uint64_t alias_hash, hidden_hash;
    int valid;
} outcome;

static uint64_t mix(uint64_t h, uint64_t x)
{
    h ^= x + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    return h * 0x100000001b3ull;
}

static outcome build(const double *p, const double *w, uint32_t n, unsigned flags, unsigned *threads)
{
    outcome o;
    memset(&o, 0, sizeof o);
    dd_tri *t = NULL;
    char msg[256];
    o.status = dd_create_ex(&t, p, w, n, flags, msg, sizeof msg);
    if (o.status != DD_OK) return o;
    int32_t *tets = NULL;
    size_t nt = 0;
    if (dd_canonical(t, &tets, &nt) == DD_OK) o.hash = dd_canonical_hash(tets, nt);
    free(tets);
    o.ntets = dd_num_tets(t);
    o.nfinite = dd_num_finite_tets(t);
    o.nvert = dd_num_vertices(t);
    o.ndup = dd_num_duplicates(t);
    for (uint32_t i = 0; i < n; i++) o.alias_hash = mix(o.alias_hash, dd_alias(t, i));
    uint32_t *hid = NULL;
    size_t nh = 0;
    if (w && dd_hidden(t, &hid, &nh) == DD_OK)
        for (size_t k = 0; k < nh; k++) o.hidden_hash = mix(o.hidden_hash, hid[k]);
    free(hid);
    o.valid = dd_check(t) == DD_OK;
    if (threads) *threads = dd_threads(t);
    dd_free(t);
    return o;
}

static int same(const outcome *a, const outcome *b)
{
    return a->status == b->status && a->hash == b->hash && a->ntets == b->ntets && a->nfinite == b->nfinite &&
           a->nvert == b->nvert && a->ndup == b->ndup && a->alias_hash == b->alias_hash &&
           a->hidden_hash == b->hidden_hash;
}

/* The dataset on each thread count against one thread. */
static void across_counts(const char *name, const double *p, const double *w, uint32_t n, unsigned flags)
{
    char tn[160];
    outcome one = build(p, w, n, flags | DD_THREADS(1), NULL);
    snprintf(tn, sizeof tn, "parallel/%s/one-thread", name);
    tl_check(&st, one.status == DD_OK && one.valid, tn, "status %s, valid %d", dd_status_name(one.status), one.valid);
    for (size_t k = 1; k < NCOUNTS; k++) {
        unsigned got = 0;
        outcome o = build(p, w, n, flags | DD_THREADS(counts[k]), &got);
        snprintf(tn, sizeof tn, "parallel/%s/threads-%u", name, counts[k]);
        tl_check(&st, same(&o, &one) && o.valid && got == counts[k], tn,
                 "status %s, hash %016llx vs %016llx, %zu vs %zu cells, %u vs %u vertices, valid %d, threads %u",
                 dd_status_name(o.status), (unsigned long long)o.hash, (unsigned long long)one.hash, o.ntets,
                 one.ntets, o.nvert, one.nvert, o.valid, got);
    }
}

static void datasets(int small)
{
    static const char *const plain[] = {"uniform", "grid", "sphere", "cosphere", "helix", "bunny"};
    for (size_t d = 0; d < sizeof plain / sizeof *plain; d++) {
        uint32_t n = 0;
        double *p = NULL;
        char msg[256];
        uint32_t want = !strcmp(plain[d], "helix") ? (small ? 400 : 4000) : small ? 3000 : 40000;
        if (dd_gen(plain[d], want, 5, &p, &n, msg, sizeof msg) != DD_OK) {
            tl_check(&st, 0, plain[d], "dd_gen: %s", msg);
            continue;
        }
        across_counts(plain[d], p, NULL, n, 0);
        if (d == 0) {                        /* every fifth point repeated */
            for (uint32_t i = 4; i < n; i += 5)
                memcpy(p + 3 * (size_t)i, p + 3 * (size_t)(i / 7), 3 * sizeof *p);
            across_counts("uniform-duplicates", p, NULL, n, 0);
        }
        free(p);
    }
    static const char *const weighted[] = {"wuniform", "molecule", "wgrid"};
    for (size_t d = 0; d < sizeof weighted / sizeof *weighted; d++) {
        uint32_t n = 0;
        double *p = NULL, *w = NULL;
        char msg[256], name[64];
        if (dd_gen_weighted(weighted[d], small ? 2000 : 10000, 3, &p, &w, &n, msg, sizeof msg) != DD_OK) {
            tl_check(&st, 0, weighted[d], "dd_gen_weighted: %s", msg);
            continue;
        }
        snprintf(name, sizeof name, "%s/keep-hidden", weighted[d]);
        across_counts(name, p, w, n, 0);
        snprintf(name, sizeof name, "%s/discard-hidden", weighted[d]);
        across_counts(name, p, w, n, DD_DISCARD_HIDDEN);
        free(p);
        free(w);
    }
}

/* dd_locate_many and dd_nearest_many give the same answers on 1, 2, 3
 * and 8 threads (the queries: random points, the grid's own points and
 * the midpoints of grid edges, where a point lies on several cells).  */
static void batch_reads(const char *name, int small)
{
    uint32_t n = 0;
    double *p = NULL;
    if (dd_gen(name, small ? 3000 : 40000, 5, &p, &n, NULL, 0) != DD_OK) exit(1);
    dd_tri *t = NULL;
    if (dd_create(&t, p, n, NULL, 0) != DD_OK) exit(1);
    const size_t m = small ? 10000 : 60000;
    double *q = malloc(3 * m * sizeof *q);
    tl_rng r = {11};
    for (size_t i = 0; i < m; i++)
        for (int c = 0; c < 3; c++) {
            const double *a = p + 3 * (size_t)(i % n), *b = p + 3 * (size_t)((i * 7 + 1) % n);
            q[3 * i + c] = i % 3 == 0 ? a[c] : i % 3 == 1 ? 0.5 * (a[c] + b[c]) : tl_unif(&r) * 30;
        }
    dd_cell_id *c1 = malloc(m * sizeof *c1), *ck = malloc(m * sizeof *ck);
    uint32_t *n1 = malloc(m * sizeof *n1), *nk = malloc(m * sizeof *nk);
    dd_set_threads(t, 1);
    dd_status a1 = dd_locate_many(t, q, m, c1), b1 = dd_nearest_many(t, q, m, n1);
    for (size_t k = 1; k < NCOUNTS; k++) {
        dd_set_threads(t, counts[k]);
        dd_status ak = dd_locate_many(t, q, m, ck), bk = dd_nearest_many(t, q, m, nk);
        char tn[96];
        snprintf(tn, sizeof tn, "parallel/reads/%s/threads-%u", name, counts[k]);
        tl_check(&st, a1 == DD_OK && b1 == DD_OK && ak == DD_OK && bk == DD_OK && !memcmp(c1, ck, m * sizeof *c1) &&
                          !memcmp(n1, nk, m * sizeof *n1),
                 tn, "statuses %s %s, answers differ", dd_status_name(ak), dd_status_name(bk));
    }
    free(c1), free(ck), free(n1), free(nk), free(q), free(p);
    dd_free(t);
}

/* Where the count comes from: flags, DTDEL_THREADS, dd_set_threads. */
static void thread_counts(void)
{
    uint32_t n = 0;
    double *p = NULL;
    if (dd_gen("uniform", 500, 2, &p, &n, NULL, 0) != DD_OK) exit(1);
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    unsigned all = cores > 1024 ? 1024 : cores > 0 ? (unsigned)cores : 1, got = 0;
    outcome one = build(p, NULL, n, 0, &got);
    tl_check(&st, got == 1, "parallel/count/default-one", "dd_threads %u", got);
    outcome o = build(p, NULL, n, DD_THREADS_ALL, &got);
    tl_check(&st, got == all && same(&o, &one), "parallel/count/all", "dd_threads %u, cores %u", got, all);
    o = build(p, NULL, n, DD_THREADS(2000), &got);
    tl_check(&st, got == 1024 && same(&o, &one), "parallel/count/clamped", "dd_threads %u", got);

    static const struct { const char *value; unsigned want; } env[] = {
        {"3", 3}, {"all", 0}, {"0", 0}, {"1", 1}, {"abc", 1}, {"-2", 1}, {"", 1}, {"99999", 1024}};
    for (size_t k = 0; k < sizeof env / sizeof *env; k++) {
        setenv("DTDEL_THREADS", env[k].value, 1);
        char tn[96];
        unsigned want = env[k].want ? env[k].want : all;
        o = build(p, NULL, n, 0, &got);
        snprintf(tn, sizeof tn, "parallel/count/env-'%s'", env[k].value);
        tl_check(&st, got == want && same(&o, &one), tn, "dd_threads %u, want %u", got, want);
        o = build(p, NULL, n, DD_THREADS(2), &got);    /* the flag wins */
        snprintf(tn, sizeof tn, "parallel/count/env-'%s'/flag-wins", env[k].value);
        tl_check(&st, got == 2 && same(&o, &one), tn, "dd_threads %u", got);
    }
    unsetenv("DTDEL_THREADS");

    dd_tri *t = NULL;
    if (dd_create(&t, p, n, NULL, 0) == DD_OK) {
        static const unsigned set[] = {0, 1, 64, 5000, 2};
        static const unsigned want[] = {0, 1, 64, 1024, 2};
        int ok = 1;
        for (size_t k = 0; k < sizeof set / sizeof *set; k++) {
            dd_set_threads(t, set[k]);
            ok &= dd_threads(t) == (want[k] ? want[k] : all);
        }
        tl_check(&st, ok, "parallel/count/dd_set_threads", "dd_threads %u after the last", dd_threads(t));
    }
    dd_free(t);

    char msg[256];
    t = NULL;
    dd_status s = dd_create_ex(&t, p, NULL, n, DD_THREADS(4) | 1u << 30, msg, sizeof msg);
    tl_check(&st, s == DD_ERR_ARG && !t, "parallel/refused/unknown-flag", "status %s", dd_status_name(s));
    for (uint32_t i = 0; i < n; i++) p[3 * (size_t)i + 2] = 0.25;    /* all coplanar */
    dd_status s1 = dd_create_ex(&t, p, NULL, n, DD_THREADS(1), msg, sizeof msg);
    dd_status s8 = dd_create_ex(&t, p, NULL, n, DD_THREADS(8), msg, sizeof msg);
    tl_check(&st, s1 != DD_OK && s8 == s1 && !t, "parallel/refused/coplanar", "status %s on 1 thread, %s on 8",
             dd_status_name(s1), dd_status_name(s8));
    free(p);
}

int main(int argc, char **argv)
{
    int small = argc > 1 && !strcmp(argv[1], "small");
    unsetenv("DTDEL_THREADS");
    datasets(small);
    batch_reads("uniform", small);
    batch_reads("grid", small);
    thread_counts();
    return tl_finish(&st);
}
