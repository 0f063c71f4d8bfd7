/*
 * pbuild_bench.c -- `dtdel build-bench --threads N`: the construction on
 * one thread and on N, and CGAL's Parallel_tag construction on N
 * (cgal/cgal_par.h), in turns, the medians compared, all results
 * checked against CGAL's; then the weighted construction (wuniform) on
 * one thread and on N.  What make bench appends to results/build.txt.
 */
#include "bench/bench.h"
#include "cgal/cgal_par.h"
#include "../datasets/datasets.h"
#include "dtdel/alloc.h"

#include <unistd.h>

#define PAR_MAX_REPS 9

/* dd_create_ex on `threads` threads, timed, then freed; its canonical
 * form kept in *tets when tets is not NULL.  0, or EXIT_INPUT after a
 * message.  Each build starts with no other triangulation alive, as a
 * one-build program's would.                                           */
static int timed_build(const double *xyz, const double *w, uint32_t n, unsigned threads, double *secs,
                       int32_t **tets, size_t *ntets)
{
    char msg[512];
    dd_tri *t = NULL;
    double t0 = now_seconds();
    dd_status s = dd_create_ex(&t, xyz, w, n, DD_THREADS(threads), msg, sizeof msg);
    *secs = now_seconds() - t0;
    if (s != DD_OK) {
        fprintf(stderr, "dtdel build-bench: %s\n", msg);
        return EXIT_INPUT;
    }
    s = tets ? dd_canonical(t, tets, ntets) : DD_OK;
    dd_free(t);
    return s == DD_OK ? 0 : EXIT_INPUT;
}

static void print_row(const char *what, double *secs, unsigned reps, uint32_t n)
{
    double m = median_of(secs, reps);
    printf("%-30s %.3f s, %.0f points/s (%.3f-%.3f s)\n", what, m, n / m, secs[0], secs[reps - 1]);
}

/* The canonical forms of the last runs. */
typedef struct forms {
    int32_t *t[3];
    size_t n[3];
} forms;

static void forms_free(forms *f)
{
    for (int k = 0; k < 3; k++) dd_mfree(f->t[k]), f->t[k] = NULL;
}

/* The unweighted rows: dtdel on 1 and on `threads`, CGAL Parallel_tag on
 * `threads`, in turns; 0, or EXIT_INPUT when a build fails or differs.  */
static int plain_rows(const char *dataset, const double *xyz, uint32_t np, unsigned threads, unsigned reps)
{
    double one[PAR_MAX_REPS], many[PAR_MAX_REPS], cg[PAR_MAX_REPS];
    forms f = {{NULL, NULL, NULL}, {0, 0, 0}};
    int rc = 0;
    for (unsigned r = 0; r < reps && !rc; r++) {
        const int last = r + 1 == reps;
        rc = timed_build(xyz, NULL, np, 1, &one[r], last ? &f.t[0] : NULL, &f.n[0]);
        if (!rc) rc = timed_build(xyz, NULL, np, threads, &many[r], last ? &f.t[1] : NULL, &f.n[1]);
        dd_cgalp *c = rc ? NULL : dd_cgalp_build(xyz, np, threads, &cg[r]);
        if (!rc && (!c || (last && dd_cgalp_canonical(c, &f.t[2], &f.n[2])))) rc = EXIT_INPUT;
        dd_cgalp_free(c);
    }
    if (rc) {
        forms_free(&f);
        return rc;
    }
    int same = same_canonical(f.t[0], f.n[0], f.t[2], f.n[2]) && same_canonical(f.t[1], f.n[1], f.t[2], f.n[2]);
    forms_free(&f);
    char label[64];
    printf("dataset %s, n = %u, threads %u (%ld cores online)\n", dataset, np, threads, sysconf(_SC_NPROCESSORS_ONLN));
    printf("runs: %u each, in turns; medians (fastest-slowest)\n", reps);
    print_row("dtdel, 1 thread:", one, reps, np);
    snprintf(label, sizeof label, "dtdel, %u threads:", threads);
    print_row(label, many, reps, np);
    snprintf(label, sizeof label, "cgal Parallel_tag, %u threads:", threads);
    print_row(label, cg, reps, np);
    double m1 = median_of(one, reps), mn = median_of(many, reps), mc = median_of(cg, reps);
    printf("parallel: %u threads, dtdel %.2fx its 1 thread, %.2fx CGAL Parallel_tag on %u threads\n", threads,
           m1 / mn, mc / mn, threads);
    printf("identical to CGAL: %s\n", same ? "yes" : "NO");
    return same ? 0 : EXIT_INPUT;
}

/* The weighted rows (wuniform, hidden points kept): dtdel on 1 and on
 * `threads`, in turns, the two results compared.                       */
static int weighted_rows(uint64_t n, uint64_t seed, unsigned threads, unsigned reps)
{
    double *xyz = NULL, *w = NULL, one[PAR_MAX_REPS], many[PAR_MAX_REPS];
    uint32_t np = 0;
    char msg[512];
    if (dd_gen_weighted("wuniform", (uint32_t)n, seed, &xyz, &w, &np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel build-bench: %s\n", msg);
        return EXIT_INPUT;
    }
    forms f = {{NULL, NULL, NULL}, {0, 0, 0}};
    int rc = 0;
    for (unsigned r = 0; r < reps && !rc; r++) {
        const int last = r + 1 == reps;
        rc = timed_build(xyz, w, np, 1, &one[r], last ? &f.t[0] : NULL, &f.n[0]);
        if (!rc) rc = timed_build(xyz, w, np, threads, &many[r], last ? &f.t[1] : NULL, &f.n[1]);
    }
    dd_mfree(xyz);
    dd_mfree(w);
    int same = !rc && same_canonical(f.t[0], f.n[0], f.t[1], f.n[1]);
    forms_free(&f);
    if (rc) return rc;
    char label[64];
    printf("dataset wuniform (weighted), n = %u, threads %u\n", np, threads);
    print_row("dtdel, 1 thread:", one, reps, np);
    snprintf(label, sizeof label, "dtdel, %u threads:", threads);
    print_row(label, many, reps, np);
    printf("weighted parallel: %u threads, dtdel %.2fx its 1 thread\n", threads,
           median_of(one, reps) / median_of(many, reps));
    printf("identical to 1 thread: %s\n", same ? "yes" : "NO");
    return same ? 0 : EXIT_INPUT;
}

int build_bench_threads(const char *dataset, uint64_t n, uint64_t seed, unsigned threads, unsigned reps)
{
    double *xyz;
    uint32_t np;
    if (reps > PAR_MAX_REPS) reps = PAR_MAX_REPS;
    int rc = gen_points("build-bench", dataset, n, seed, &xyz, &np);
    if (rc) return rc;
    rc = plain_rows(dataset, xyz, np, threads, reps);
    dd_mfree(xyz);
    printf("\n");
    int wrc = weighted_rows(n, seed, threads, reps);
    return rc ? rc : wrc;
}
