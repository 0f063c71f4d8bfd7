/*
 * build_bench.c -- `dtdel build-bench`: construction against CGAL's range
 * insert, both engines alternated, the medians compared and the two
 * triangulations too; with --write, dd_write's file of the result timed.
 * What make bench writes to results/build.txt.
 */
#include "bench/bench.h"
#include "dtdel/alloc.h"

#include <string.h>
#include <sys/stat.h>

#define BUILD_MAX_REPS 9

/* `dtdel build-bench --write FILE`: the triangulation written to FILE by
 * dd_write, timed once; its size and time on one line.                  */
static int time_write(const dd_tri *t, const char *path)
{
    const double t0 = now_seconds();
    const dd_status s = dd_write(t, path);
    const double secs = now_seconds() - t0;
    struct stat st;
    if (s != DD_OK || stat(path, &st) != 0) {
        fprintf(stderr, "dtdel build-bench: %s: %s\n", path,
                s == DD_OK || s == DD_ERR_IO ? "cannot write the file" : dd_status_name(s));
        return EXIT_INPUT;
    }
    printf("write: %s (dd_write) of %zu finite cells: %lld bytes (%.1f MB) in %.3f s\n", path,
           dd_num_finite_tets(t), (long long)st.st_size, (double)st.st_size / 1e6, secs);
    return 0;
}

/* `dtdel build-bench`: each engine builds R times, in turns (dtdel,
 * CGAL, dtdel, ...), so that a slow spell of the machine hits both; the
 * medians are compared, as the deletion bench compares medians, and the
 * last pair of triangulations with each other; then, with --write, the
 * last triangulation is written (time_write).                           */
int cmd_build_bench(int argc, char **argv)
{
    const char *dataset = "uniform", *wpath = NULL;
    uint64_t n = 1000000, seed = 1, reps = 3, threads = 1;
    for (int i = 1, rc; i < argc; i++) {
        if (take_dataset_option("build-bench", argc, argv, &i, &dataset, &seed, &rc)) {
            if (rc) return rc;
        } else if (!strcmp(argv[i], "--write")) {
            if (++i >= argc) return usage_error("build-bench", "--write needs a file name%s", "");
            wpath = argv[i];
        } else if (!strcmp(argv[i], "--reps")) {
            if (++i >= argc || parse_u64(argv[i], &reps) || reps < 1 || reps > BUILD_MAX_REPS)
                return usage_error("build-bench", "--reps needs an integer from 1 to 9%s", "");
        } else if (!strcmp(argv[i], "--threads")) {
            if (++i >= argc || parse_u64(argv[i], &threads) || threads < 1 || threads > 1024)
                return usage_error("build-bench", "--threads needs an integer from 1 to 1024%s", "");
        } else if (parse_u64(argv[i], &n) || n > UINT32_MAX / 8) {
            return usage_error("build-bench", "N must be a non-negative integer, got '%s'", argv[i]);
        }
    }
    if (threads > 1) return build_bench_threads(dataset, n, seed, (unsigned)threads, (unsigned)reps);
    double *xyz;
    uint32_t np;
    char msg[512];
    int rc = gen_points("build-bench", dataset, n, seed, &xyz, &np);
    if (rc) return rc;
    double ours[BUILD_MAX_REPS], theirs[BUILD_MAX_REPS];
    dd_tri *t = NULL;
    dd_cgal *c = NULL;
    for (uint64_t r = 0; r < reps; r++) {
        dd_free(t);                          /* the last pair is compared */
        dd_cgal_free(c);
        t = NULL;
        c = NULL;
        double t0 = now_seconds();
        dd_status s = dd_create(&t, xyz, np, msg, sizeof msg);
        double t1 = now_seconds();
        if (s != DD_OK) {
            fprintf(stderr, "dtdel build-bench: %s\n", msg);
            dd_mfree(xyz);
            return EXIT_INPUT;
        }
        c = dd_cgal_build(xyz, np);
        double t2 = now_seconds();
        ours[r] = t1 - t0;
        theirs[r] = t2 - t1;
    }
    int same = 0;
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    if (c && dd_canonical(t, &a, &na) == DD_OK && !dd_cgal_canonical(c, &b, &nb))
        same = same_canonical(a, na, b, nb);
    dd_mfree(a);
    dd_mfree(b);
    double to = median_of(ours, reps), tc = median_of(theirs, reps);   /* sorted now */
    printf("dataset %s, n = %u, %zu cells (%zu finite)\n", dataset, np, dd_num_tets(t), dd_num_finite_tets(t));
    printf("runs: %u each, alternated; medians (fastest-slowest)\n", (unsigned)reps);
    printf("dtdel: %.3f s, %.0f points/s (%.3f-%.3f s)\n", to, np / to, ours[0], ours[reps - 1]);
    printf("cgal:  %.3f s, %.0f points/s (%.3f-%.3f s) (%s)\n", tc, np / tc, theirs[0], theirs[reps - 1],
           dd_cgal_version());
    printf("speed ratio dtdel/cgal: %.2f\n", tc / to);
    printf("bytes per cell: %.1f (all arrays, capacity included)\n",
           (double)dd_memory_bytes(t) / (double)dd_num_tets(t));
    printf("identical to CGAL: %s\n", same ? "yes" : "NO");
    dd_cgal_free(c);
    const int wrc = wpath ? time_write(t, wpath) : 0;
    dd_free(t);
    dd_mfree(xyz);
    return same ? wrc : EXIT_INPUT;
}
