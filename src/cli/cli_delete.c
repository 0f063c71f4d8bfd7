/*
 * cli_delete.c -- the deletion subcommands.
 *
 *   dtdel delete FILE --vertex I[,J,...] [--variant NAME]
 *   dtdel time   FILE --vertex I --variant NAME [--repeat R]
 *   dtdel check  FILE [--variant NAME|all] [--deletions K] [--seed S] [--sequence]
 *
 * Their --variant names a row (tool.h: an engine strategy, cgal or
 * cgal-rnd); every row's result but cgal's, the reference, is compared
 * with CGAL's canonical form.
 */
#include "cli/cli.h"
#include "dtdel/alloc.h"

#include <stdlib.h>
#include <string.h>

/* `dtdel time --variant insert`: deletes input vertex v untimed (default
 * strategy), then times its re-insertion alone into *secs.  0; -1 when
 * the deletion failed, -2 when the re-insertion did (dd_errmsg says why). */
static int reinsert_timed(dd_tri *t, uint32_t v, double *secs)
{
    if (dd_delete(t, v) != DD_OK) return -1;
    double t0 = now_seconds();
    dd_status st = dd_reinsert(t, v);
    *secs = now_seconds() - t0;
    return st == DD_OK ? 0 : -2;
}

/* Parses "I,J,K" into a malloc'd list: 0, -1 when malformed, -2 when
 * out of memory.                                                        */
static int parse_list(const char *s, uint32_t **out, size_t *n)
{
    size_t cap = 8, k = 0;
    uint32_t *a = dd_malloc(cap * sizeof *a);
    if (!a) return -2;
    const char *p = s;
    for (;;) {
        char buf[32];
        size_t len = strcspn(p, ",");
        uint64_t x;
        if (len == 0 || len >= sizeof buf) { dd_mfree(a); return -1; }
        memcpy(buf, p, len);
        buf[len] = 0;
        if (parse_u64(buf, &x) || x >= UINT32_MAX) { dd_mfree(a); return -1; }
        if (k == cap) {
            uint32_t *b = dd_realloc(a, 2 * cap * sizeof *a);
            if (!b) { dd_mfree(a); return -2; }
            a = b;
            cap *= 2;
        }
        a[k++] = (uint32_t)x;
        if (!p[len]) break;
        p += len + 1;
    }
    *out = a;
    *n = k;
    return 0;
}

/* Loads FILE and builds the engine's DT (and CGAL's if want_cgal). */
static int load_both(const char *cmd, const char *path, int want_cgal, dd_tri **t, dd_cgal **g,
                     double **pts, uint32_t *np)
{
    int rc = load_file(cmd, path, pts, np);
    if (rc) return rc;
    char msg[512];
    if (dd_create(t, *pts, *np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel %s: %s: %s\n", cmd, path, msg);
        dd_mfree(*pts);
        return EXIT_INPUT;
    }
    *g = NULL;
    if (want_cgal && !(*g = dd_cgal_build(*pts, *np))) {
        fprintf(stderr, "dtdel %s: %s: CGAL cannot triangulate these points\n", cmd, path);
        dd_free(*t);
        dd_mfree(*pts);
        return EXIT_INPUT;
    }
    return 0;
}

/* ---- delete --------------------------------------------------------------- */

int cmd_delete(int argc, char **argv)
{
    const char *file = NULL, *vlist = NULL, *var = NULL;
    int stats = 0, set = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--stats")) {
            stats = 1;
        } else if (!strcmp(argv[i], "--set")) {
            set = 1;
        } else if (!strcmp(argv[i], "--vertex")) {
            if (++i >= argc) return usage_error("delete", "--vertex needs a list I[,J,...]%s", "");
            vlist = argv[i];
        } else if (!strcmp(argv[i], "--variant")) {
            if (++i >= argc) return usage_error("delete", "--variant needs a name%s", "");
            var = argv[i];
        } else if (!file) file = argv[i];
        else return usage_error("delete", "unexpected argument '%s'", argv[i]);
    }
    if (!file || !vlist) return usage_error("delete", "missing FILE or --vertex%s", "");
    uint32_t *vs;
    size_t nv;
    int bad = parse_list(vlist, &vs, &nv);
    if (bad == -2) { fprintf(stderr, "dtdel delete: out of memory\n"); return EXIT_INPUT; }
    if (bad)
        return usage_error("delete", "--vertex wants non-negative integers separated by commas, got '%s'", vlist);
    row r = {dd_variant_name(0), ROW_ENGINE};
    if (var && !find_row(var, &r)) {
        fprintf(stderr, "dtdel delete: unknown variant '%s' (see dtdel variants)\n", var);
        dd_mfree(vs);
        return EXIT_INPUT;
    }
    dd_tri *t;
    dd_cgal *g;
    double *pts;
    uint32_t np;
    if (set && (r.kind != ROW_ENGINE || stats)) {
        dd_mfree(vs);
        return usage_error("delete", "--set is for an engine strategy, without --stats%s", "");
    }
    int rc = load_both("delete", file, r.kind != ROW_ENGINE, &t, &g, &pts, &np);
    if (rc) { dd_mfree(vs); return rc; }
    if (set && dd_delete_set_with(t, vs, nv, r.name) != DD_OK) {
        fprintf(stderr, "dtdel delete: cannot delete the set: %s\n", dd_errmsg(t));
        rc = EXIT_INPUT;
    }
    for (size_t k = 0; k < nv && !rc && !set; k++) {
        if (r.kind == ROW_ENGINE) {
            dd_reset_counters(t);
            if (dd_delete_with(t, vs[k], r.name) != DD_OK) {
                fprintf(stderr, "dtdel delete: cannot delete vertex %u: %s\n", vs[k], dd_errmsg(t));
                rc = EXIT_INPUT;
            } else if (stats) {
                dd_delete_stats st;
                dd_counters cn;
                dd_last_delete_stats(t, &st);
                dd_get_counters(t, &cn);
                fprintf(stderr, "vertex %u: degree %u%s, %llu cells built, %llu fallbacks, %llu location tests,"
                                " link deletions by degree:", vs[k], st.degree, st.on_hull ? " (hull)" : "",
                        (unsigned long long)st.tets_created, (unsigned long long)st.fallbacks,
                        (unsigned long long)st.locate_steps);
                for (int b = 3; b < DD_LINKDEG_BUCKETS; b++)
                    if (st.link_deletions[b]) fprintf(stderr, " %d%s:%u", b, b == DD_LINKDEG_BUCKETS - 1 ? "+" : "", st.link_deletions[b]);
                for (uint32_t i = 0; i < st.nstrategy; i++)   /* the strategy's own, by name */
                    if (st.strategy[i]) fprintf(stderr, "\n  %s: %u", st.strategy_name[i], st.strategy[i]);
                fprintf(stderr, "\n  insphere %llu (exact %llu), orient %llu (exact %llu), perturbed %llu%s\n",
                        (unsigned long long)cn.insphere_calls, (unsigned long long)cn.insphere_exact,
                        (unsigned long long)cn.orient_calls, (unsigned long long)cn.orient_exact,
                        (unsigned long long)cn.perturbed, cn.insphere_calls ? "" : " (counting build: build/count/dtdel)");
            }
        } else if (row_delete(&r, t, g, vs[k], 1 + k)) {
            fprintf(stderr, "dtdel delete: CGAL cannot delete vertex %u (unknown, or it would leave "
                            "fewer than 4 or only coplanar points)\n", vs[k]);
            rc = EXIT_INPUT;
        }
    }
    if (!rc) {
        int32_t *a;
        size_t n;
        if (row_canonical(&r, t, g, &a, &n)) rc = EXIT_INPUT, fprintf(stderr, "dtdel delete: out of memory\n");
        else { write_tets(a, n); dd_mfree(a); }
    }
    dd_mfree(vs);
    dd_mfree(pts);
    dd_free(t);
    dd_cgal_free(g);
    return rc;
}

/* ---- time ------------------------------------------------------------------ */

int cmd_time(int argc, char **argv)
{
    const char *file = NULL, *var = NULL;
    uint64_t v = UINT64_MAX, repeat = 5;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--vertex")) {
            if (++i >= argc || parse_u64(argv[i], &v) || v >= UINT32_MAX)
                return usage_error("time", "--vertex needs a non-negative integer%s", "");
        } else if (!strcmp(argv[i], "--variant")) {
            if (++i >= argc) return usage_error("time", "--variant needs a name%s", "");
            var = argv[i];
        } else if (!strcmp(argv[i], "--repeat")) {
            if (++i >= argc || parse_u64(argv[i], &repeat) || repeat == 0 || repeat > 1000000)
                return usage_error("time", "--repeat needs a positive integer%s", "");
        } else if (!file) file = argv[i];
        else return usage_error("time", "unexpected argument '%s'", argv[i]);
    }
    if (!file || v == UINT64_MAX || !var) return usage_error("time", "missing FILE, --vertex or --variant%s", "");
    /* "insert": the bench's insert row, our re-insertion of the vertex
     * (deleted untimed by the default strategy before each repetition). */
    const int insert = !strcmp(var, "insert");
    row r = {dd_variant_name(0), ROW_ENGINE};
    if (!insert && !find_row(var, &r)) {
        fprintf(stderr, "dtdel time: unknown variant '%s' (see dtdel variants, or insert)\n", var);
        return EXIT_INPUT;
    }
    dd_tri *t;
    dd_cgal *g;
    double *pts;
    uint32_t np;
    int rc = load_both("time", file, r.kind != ROW_ENGINE, &t, &g, &pts, &np);
    if (rc) return rc;
    double *us = dd_malloc(repeat * sizeof *us);
    if (!us) {
        fprintf(stderr, "dtdel time: out of memory\n");
        rc = EXIT_INPUT;
    }
    for (uint64_t k = 0; k < repeat && insert && !rc; k++) {
        double secs = 0;
        int bad = reinsert_timed(t, (uint32_t)v, &secs);
        us[k] = 1e6 * secs;
        if (bad) {
            fprintf(stderr, "dtdel time: %s vertex %u: %s\n", bad == -1 ? "cannot delete" : "cannot re-insert",
                    (uint32_t)v, dd_errmsg(t));
            rc = EXIT_INPUT;
        }
    }
    for (uint64_t k = 0; k < repeat && !insert && !rc; k++) {
        double t0 = now_seconds();
        int bad = row_delete(&r, t, g, (uint32_t)v, k + 1);
        double t1 = now_seconds();
        if (bad) {
            fprintf(stderr, "dtdel time: cannot delete vertex %u%s%s\n", (uint32_t)v,
                    r.kind == ROW_ENGINE ? ": " : "", r.kind == ROW_ENGINE ? dd_errmsg(t) : "");
            rc = EXIT_INPUT;
            break;
        }
        us[k] = 1e6 * (t1 - t0);
        if (row_reinsert(&r, t, g, (uint32_t)v)) {
            fprintf(stderr, "dtdel time: reinserting vertex %u failed\n", (uint32_t)v);
            rc = EXIT_INPUT;
        }
    }
    if (!rc) printf("%.3f\n", median_of(us, repeat));
    dd_mfree(us);
    dd_mfree(pts);
    dd_free(t);
    dd_cgal_free(g);
    return rc;
}

/* ---- check ----------------------------------------------------------------- */

int cmd_check(int argc, char **argv)
{
    const char *file = NULL, *var = "all";
    uint64_t k = 20, seed = 1;
    int sequence = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--variant")) {
            if (++i >= argc) return usage_error("check", "--variant needs a name or 'all'%s", "");
            var = argv[i];
        } else if (!strcmp(argv[i], "--deletions")) {
            if (++i >= argc || parse_u64(argv[i], &k) || k > UINT32_MAX)
                return usage_error("check", "--deletions needs a non-negative integer%s", "");
        } else if (!strcmp(argv[i], "--seed")) {
            if (++i >= argc || parse_u64(argv[i], &seed))
                return usage_error("check", "--seed needs a non-negative integer%s", "");
        } else if (!strcmp(argv[i], "--sequence")) {
            sequence = 1;
        } else if (!file) file = argv[i];
        else return usage_error("check", "unexpected argument '%s'", argv[i]);
    }
    if (!file) return usage_error("check", "missing FILE%s", "");
    /* every row but cgal: CGAL's remove() is the reference, and compared
     * with itself it could not fail                                     */
    row rows[32];
    size_t nr = 0;
    if (!strcmp(var, "all")) {
        row all[32];
        size_t na = all_rows(all, 32);
        for (size_t i = 0; i < na; i++)
            if (all[i].kind != ROW_CGAL) rows[nr++] = all[i];
    } else if (find_row(var, &rows[0])) {
        if (rows[0].kind == ROW_CGAL)
            return usage_error("check", "%s is the reference the other rows are compared with", var);
        nr = 1;
    } else {
        fprintf(stderr, "dtdel check: unknown variant '%s' (see dtdel variants)\n", var);
        return EXIT_INPUT;
    }
    double *pts;
    uint32_t np;
    int rc = load_file("check", file, &pts, &np);
    if (rc) return rc;
    /* The sample: K distinct vertices drawn with a seeded generator. */
    uint32_t *sample = dd_malloc((k ? k : 1) * sizeof *sample);
    uint64_t x = seed * 0x9E3779B97F4A7C15ull + 1;
    dd_tri *probe;
    char msg[512];
    if (!sample || dd_create(&probe, pts, np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel check: %s: %s\n", file, sample ? msg : "out of memory");
        dd_mfree(sample);
        dd_mfree(pts);
        return EXIT_INPUT;
    }
    uint32_t nvert = dd_num_vertices(probe);
    if (k > nvert) k = nvert;
    unsigned char *chosen = dd_calloc(np ? np : 1, 1);
    for (uint64_t i = 0; i < k && chosen; i++) sample[i] = draw_vertex(probe, &x, np, chosen);
    dd_mfree(chosen);
    dd_free(probe);
    int any_bad = 0;
    for (size_t ri = 0; ri < nr; ri++) {
        dd_tri *t = NULL;
        dd_cgal *g = NULL, *ref = NULL;
        dd_create(&t, pts, np, msg, sizeof msg);
        if (rows[ri].kind != ROW_ENGINE) g = dd_cgal_build(pts, np);
        ref = dd_cgal_build(pts, np);
        uint64_t matched = 0, total = 0, refused = 0;
        for (uint64_t i = 0; i < k; i++) {
            uint32_t v = sample[i];
            int cref = dd_cgal_remove(ref, v);
            int bad = row_delete(&rows[ri], t, g, v, seed + i);
            total++;
            if (cref || bad) {   /* both must refuse */
                if (cref && bad) { matched++; refused++; }
                else if (!bad) row_reinsert(&rows[ri], t, g, v);
                if (!cref && !sequence) dd_cgal_reinsert(ref, v);
                continue;
            }
            int32_t *a = NULL, *b = NULL;
            size_t na = 0, nb = 0;
            if (!row_canonical(&rows[ri], t, g, &a, &na) && !dd_cgal_canonical(ref, &b, &nb) &&
                same_canonical(a, na, b, nb))
                matched++;
            dd_mfree(a);
            dd_mfree(b);
            if (!sequence) {
                row_reinsert(&rows[ri], t, g, v);
                dd_cgal_reinsert(ref, v);
            }
        }
        printf("%-14s %llu/%llu matched%s\n", rows[ri].name, (unsigned long long)matched,
               (unsigned long long)total, refused ? " (some refused by both)" : "");
        if (matched != total) any_bad = 1;
        dd_free(t);
        dd_cgal_free(g);
        dd_cgal_free(ref);
    }
    dd_mfree(sample);
    dd_mfree(pts);
    return any_bad ? EXIT_INPUT : 0;
}
