/*
 * readme.c -- OUTDIR/readme-table.md, README.md's results table
 * (scripts/bench.sh puts it between the README's bench-table markers):
 * the deletion rows of readme_rows against cgal, the mismatch count, the
 * run, the construction ratios (build.txt), the rows of queries.txt,
 * edits.txt, refine.txt and regular.txt, then the weighted rows
 * (weighted.c).  Lines of a file it does not recognise are skipped.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench/buckets.h"
#include "summarize.h"

/* ---- readme-table.md -------------------------------------------------------------- */

/* The rows of README.md's results table: the paper's experiment at a
 * glance.  n = 0: every size of the dataset; lo = hi = 0: the degree
 * bucket of the highest degree at size n (on the curves each size has
 * one degree, or nearly: the moment curve n - 1, the helix about 2√n);
 * summarize.h defines readme_spec. */
static const readme_spec readme_rows[] = {
    {"moment", 64, 0, 0},    {"moment", 256, 0, 0},   {"moment", 1024, 0, 0},
    {"helix", 16000, 0, 0},  {"helix", 64000, 0, 0},  {"uniform", 0, 12, 16},
    {"sphere", 0, 4, 8},     {"sphere", 0, 8, 12},    {"bunny", 0, 12, 16},
    {"grid", 0, 12, 16},     {"cosphere", 0, 16, 24}};
#define NREADME (sizeof readme_rows / sizeof readme_rows[0])

/* Its ratio columns: these engine variants in this order, then any other
 * engine deletion variant (by name), then cgal-rnd.  Not the "-paired"
 * rows (the default's deletion timed again, next to insert) nor insert:
 * measurements of the default, not variants.                            */
static const char *const readme_order[] = {
    "auto", "gift-wrap", "grr-edge", "grr-neighbor", "grr-hashing", "grr-brio",
    "dtq-only", "guide-only", "sew-full"};
#define NREADME_ORDER (sizeof readme_order / sizeof readme_order[0])

size_t find_name(const strtab *t, const char *s)
{
    for (size_t i = 0; i < t->n; i++)
        if (!strcmp(t->s[i], s)) return i;
    return (size_t)-1;
}

static int ends_with(const char *s, const char *tail)
{
    size_t a = strlen(s), b = strlen(tail);
    return a >= b && !strcmp(s + a - b, tail);
}

/* The ratio columns present in the data (ctx.variants indices, in order);
 * returns their number.  col holds room for every variant.              */
size_t readme_columns(const ctx *c, size_t *col)
{
    size_t m = 0;
    for (size_t k = 0; k < NREADME_ORDER; k++) {
        size_t v = find_name(&c->variants, readme_order[k]);
        if (v != (size_t)-1) col[m++] = v;
    }
    size_t first_other = m;
    for (size_t v = 0; v < c->variants.n; v++) {
        const char *name = c->variants.s[v];
        int known = 0;
        for (size_t k = 0; k < NREADME_ORDER; k++) known |= !strcmp(name, readme_order[k]);
        if (known || !is_deletion_variant(name) || ends_with(name, "-paired")) continue;
        size_t at = m++;                       /* insertion sort by name */
        while (at > first_other && strcmp(c->variants.s[col[at - 1]], name) > 0) {
            col[at] = col[at - 1];
            at--;
        }
        col[at] = v;
    }
    size_t rnd = find_name(&c->variants, "cgal-rnd");
    if (rnd != (size_t)-1) col[m++] = rnd;
    return m;
}

/* Median us of the rows idx[0..k) of variant var (NaN if none); *count
 * gets their number. */
static double variant_median(const ctx *c, const size_t *idx, size_t k, size_t var, size_t *count)
{
    size_t m = 0;
    for (size_t i = 0; i < k; i++)
        if (c->rows[idx[i]].var == var) c->scratch[m++] = c->rows[idx[i]].us;
    *count = m;
    if (!m) return NAN;
    qsort(c->scratch, m, sizeof *c->scratch, cmp_double);
    return quantile(c->scratch, m, 0.5);
}

/* A non-negative integer, its thousands set apart from 10 000 on:
 * 1178, 52 233, 2 042 014. */
const char *fmt_int(long long v, char buf[40])
{
    char d[32];
    snprintf(d, sizeof d, "%lld", v);
    size_t len = strlen(d), o = 0;
    for (size_t i = 0; i < len; i++) {
        if (len >= 5 && i && (len - i) % 3 == 0) buf[o++] = ' ';
        buf[o++] = d[i];
    }
    buf[o] = '\0';
    return buf;
}

/* Three significant digits or more: 6444, 121, 36.1, 6.17, 0.76. */
const char *fmt_sig(double v, char buf[40])
{
    if (isnan(v)) snprintf(buf, 40, "—");
    else if (v >= 100) fmt_int(llround(v), buf);
    else if (v >= 10) snprintf(buf, 40, "%.1f", v);
    else snprintf(buf, 40, "%.2f", v);
    return buf;
}

/* How a row is named when it is not in this run. */
static void readme_missing(const readme_spec *s, FILE *out, int first)
{
    char b[40];
    fprintf(out, "%s%s", first ? "" : "; ", s->dataset);
    if (s->n) fprintf(out, " n = %s", fmt_int(s->n, b));
    if (s->lo || s->hi) fprintf(out, ", degree %lld–%lld", s->lo, s->hi - 1);
}

/* One row of the table from the rows of spec s; 0 if the run has none.
 * idx, sizes: scratch for nrows entries each. */
int readme_row(const ctx *c, const readme_spec *s, const size_t *col, size_t ncol,
                      size_t *idx, long long *sizes, const char *none, FILE *out)
{
    size_t ds = find_name(&c->datasets, s->dataset), k = 0;
    if (ds == (size_t)-1) return 0;
    long long maxdeg = -1;
    for (size_t i = 0; i < c->nrows; i++) {
        const row *r = &c->rows[i];
        if (r->ds != ds || (s->n && r->n != s->n)) continue;
        idx[k++] = i;
        if (r->degree > maxdeg) maxdeg = r->degree;
    }
    if (!k) return 0;
    long long lo = s->lo, hi = s->hi;
    if (!lo && !hi) dd_bucket_bounds(dd_degree_bucket(maxdeg), &lo, &hi);
    size_t m = 0;
    long long dmin = 0, dmax = 0;
    for (size_t i = 0; i < k; i++) {
        const row *r = &c->rows[idx[i]];
        if (r->degree < lo || r->degree >= hi) continue;
        if (!m || r->degree < dmin) dmin = r->degree;
        if (!m || r->degree > dmax) dmax = r->degree;
        idx[m++] = idx[i];
    }
    if (!m) return 0;

    /* dataset, n = its sizes here */
    char b[40];
    size_t ns = 0;
    for (size_t i = 0; i < m; i++) sizes[i] = c->rows[idx[i]].n;
    qsort(sizes, m, sizeof *sizes, cmp_llong);
    fprintf(out, "| %s, n = ", s->dataset);
    for (size_t i = 0; i < m; i++)
        if (!i || sizes[i] != sizes[i - 1]) fprintf(out, "%s%s", ns++ ? ", " : "", fmt_int(sizes[i], b));

    /* degree (as the bench counts it: the infinite vertex too): the range
     * asked for, else the one degree, else about the median             */
    if ((s->lo || s->hi) && hi < ALL_DEGREES) {
        fprintf(out, " | %lld–%lld", lo, hi - 1);
    } else if (s->lo || s->hi) {
        fprintf(out, " | %lld–%lld", dmin, dmax);
    } else if (dmin == dmax) {
        fprintf(out, " | %lld", dmin);
    } else {
        for (size_t i = 0; i < m; i++) c->scratch[i] = (double)c->rows[idx[i]].degree;
        qsort(c->scratch, m, sizeof *c->scratch, cmp_double);
        fprintf(out, " | ~%lld", llround(quantile(c->scratch, m, 0.5)));
    }

    /* deletions: the most rows of one variant (all delete the same vertices) */
    size_t most = 0, cnt;
    for (size_t v = 0; v < c->variants.n; v++) {
        variant_median(c, idx, m, v, &cnt);
        if (cnt > most) most = cnt;
    }
    size_t cg = find_name(&c->variants, "cgal");
    double ref = cg == (size_t)-1 ? NAN : variant_median(c, idx, m, cg, &cnt);
    fprintf(out, " | %zu | %s |", most, fmt_sig(ref, b));
    for (size_t j = 0; j < ncol; j++) {
        double med = variant_median(c, idx, m, col[j], &cnt);
        if (isnan(ref) || !(med > 0)) fprintf(out, " %s |", none);
        else fprintf(out, " %s× |", fmt_sig(ref / med, b));
    }
    fputc('\n', out);
    return 1;
}

/* The value of "key: value" in OUTDIR/NAME into buf ("" if none). */
static void file_value(const ctx *c, const char *name, const char *key, char *buf, size_t len)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", c->outdir, name);
    buf[0] = '\0';
    FILE *f = fopen(path, "r");
    if (!f) return;
    char *line = NULL;
    size_t cap = 0, klen = strlen(key);
    while (read_line(f, &line, &cap) == 1)
        if (!strncmp(line, key, klen) && line[klen] == ':') {
            const char *v = line + klen + 1;
            snprintf(buf, len, "%s", v + strspn(v, " \t"));
            break;
        }
    free(line);
    fclose(f);
}

/* " Construction ...: 2.07× CGAL's speed on uniform, n = 1 000 000; ..."
 * from OUTDIR/build.txt (dtdel build-bench's output), nothing without it. */
static void readme_construction(const ctx *c, FILE *out)
{
    char path[4096], ds[64] = "", b[40];
    snprintf(path, sizeof path, "%s/build.txt", c->outdir);
    FILE *f = fopen(path, "r");
    if (!f) return;
    char *line = NULL;
    size_t cap = 0;
    long long n = 0;
    double ratio, r2;
    unsigned th;
    int any = 0;
    while (read_line(f, &line, &cap) == 1) {
        if (sscanf(line, "parallel: %u threads, dtdel %lfx its 1 thread, %lfx CGAL Parallel_tag", &th, &ratio, &r2) == 3 &&
            any) {
            fprintf(out, "; on %u threads %.2f× our one thread and %.2f× CGAL's Parallel_tag on as many", th, ratio, r2);
            continue;
        }
        if (sscanf(line, "weighted parallel: %u threads, dtdel %lfx its 1 thread", &th, &ratio) == 2 && any) {
            fprintf(out, ", weighted points %.2f× our one thread", ratio);
            continue;
        }
        if (sscanf(line, "dataset %63[^,], n = %lld", ds, &n) == 2) continue;
        if (sscanf(line, "speed ratio dtdel/cgal: %lf", &ratio) == 1 && ds[0]) {
            fprintf(out, "%s%.2f×%s on %s, n = %s",
                    any ? "; " : " Construction of DT(S) (`dtdel build-bench`): ", ratio,
                    any ? "" : " CGAL's speed", ds, fmt_int(n, b));
            any = 1;
        } else if ((!strcmp(line, "identical to CGAL: NO") || !strcmp(line, "identical to 1 thread: NO")) && any) {
            fprintf(out, " (**not identical to CGAL's triangulation**)");
        }
    }
    if (any) fputc('.', out);
    free(line);
    fclose(f);
}

/* The README row of a line of regular.txt (dtdel regular-bench), or
 * none: the engine's figure per point, or n/a while it refuses weights. */
static void readme_regular_row(const char *line, FILE *out)
{
    char b[40], b2[40];
    long long n, n0, h, reps, mism;
    double ours, cgal, rc;
    if (sscanf(line, "regular-build: %lld wuniform weighted points, %lld hidden (CGAL), %lld runs each: dtdel %lf s, "
                     "CGAL %lf s (%lfx); %lld mismatches", &n, &h, &reps, &ours, &cgal, &rc, &mism) == 7)
        fprintf(out, "| regular triangulation, build %s weighted points%s | %.2f | %.2f | %.1f× | | |\n",
                fmt_int(n, b), mism ? " (**differs from CGAL**)" : "", 1e6 * ours / (double)n,
                1e6 * cgal / (double)n, rc);
    else if (sscanf(line, "regular-build: %lld wuniform weighted points, %lld hidden (CGAL), %lld runs each: "
                          "dtdel n/a (%*[^)]), CGAL %lf s", &n, &h, &reps, &cgal) == 4)
        fprintf(out, "| regular triangulation, build %s weighted points | n/a | %.2f | n/a | | |\n", fmt_int(n, b),
                1e6 * cgal / (double)n);
    else if (sscanf(line, "regular-insert: %lld wuniform weighted points into %lld, %lld hidden at the end (CGAL): "
                          "dtdel %lf us an insertion, CGAL hinted insert %lf us (%lfx); %lld mismatches",
                    &n, &n0, &h, &ours, &cgal, &rc, &mism) == 7)
        fprintf(out, "| regular triangulation, insert %s weighted points into %s%s | %.2f | %.2f | %.1f× | | |\n",
                fmt_int(n, b), fmt_int(n0, b2), mism ? " (**differs from CGAL**)" : "", ours, cgal, rc);
    else if (sscanf(line, "regular-insert: %lld wuniform weighted points into %lld, %lld hidden at the end (CGAL): "
                          "dtdel n/a (%*[^)]), CGAL hinted insert %lf us", &n, &n0, &h, &cgal) == 4)
        fprintf(out, "| regular triangulation, insert %s weighted points into %s | n/a | %.2f | n/a | | |\n",
                fmt_int(n, b), fmt_int(n0, b2), cgal);
}

/* The README row of a smoothing line of edits.txt (dtdel edit-bench):
 * "smoothing: ..." in input order, the headline (DESIGN §10), or
 * "smoothing (Morton order): ...", the row beside it; 1 if the line is
 * one, else 0.                                                          */
static int readme_smoothing_row(const char *line, FILE *out)
{
    static const char input[] = "smoothing: ", morton[] = "smoothing (Morton order): ";
    const int in_input = !strncmp(line, input, sizeof input - 1);
    if (!in_input && strncmp(line, morton, sizeof morton - 1)) return 0;
    char ok[8], b[40];
    long long n, k;
    double ours, cgal, rc;
    if (sscanf(line + (in_input ? sizeof input : sizeof morton) - 1,
               "%lld uniform points, %lld passes of a random step of 5%% of the mean spacing: dtdel %lf us, CGAL "
               "move_if_no_collision %lf us (%lfx); kept by the filter %*f%%; identical to CGAL: %7s",
               &n, &k, &ours, &cgal, &rc, ok) != 6)
        return 0;
    fprintf(out, "| move (smoothing %s points, %lld passes, %s)%s | %.2f | %.2f | %.1f× | | |\n", fmt_int(n, b), k,
            in_input ? "input order" : "Morton order", strcmp(ok, "yes") ? " (**differs from CGAL**)" : "", ours,
            cgal, rc);
    return 1;
}

/* The README rows of the whole-array calls: edit-bench's "smoothing by
 * dd_move_many" line and batch.txt's lines (dtdel batch-bench); 1 if
 * line was one.                                                         */
static int readme_batch_row(const char *line, FILE *out)
{
    char ok[8], b[40], b2[40];
    long long n, k;
    double ours, cgal, rc, morton, rm;
    const char *differs = " (**differs from CGAL**)";
    if (sscanf(line, "smoothing by dd_move_many: %lld uniform points, %lld passes of a random step of 5%% of the mean "
                     "spacing: dtdel %lf us a move, CGAL move_if_no_collision %lf us in input order (%lfx), %lf us in "
                     "Morton order (%lfx); identical to CGAL: %7s", &n, &k, &ours, &cgal, &rc, &morton, &rm, ok) == 8) {
        fprintf(out, "| dd_move_many (smoothing %s points, %lld passes) against CGAL's loop in input order%s | %.2f | "
                     "%.2f | %.1f× | | |\n", fmt_int(n, b), k, strcmp(ok, "yes") ? differs : "", ours, cgal, rc);
        fprintf(out, "| dd_move_many (same) against CGAL's loop in Morton order | %.2f | %.2f | %.1f× | | |\n", ours,
                morton, rm);
        return 1;
    }
    if (sscanf(line, "insert-many: %lld new uniform points into %lld: dtdel %lf us a point, CGAL insert(first, last) "
                     "%lf us (%lfx); identical to CGAL: %7s", &k, &n, &ours, &cgal, &rc, ok) == 6 ||
        sscanf(line, "winsert-many: %lld new wuniform weighted points into %lld: dtdel %lf us a point, CGAL "
                     "Regular_triangulation_3 insert(first, last) %lf us (%lfx); identical to CGAL: %7s",
               &k, &n, &ours, &cgal, &rc, ok) == 6) {
        const int w = line[0] == 'w';
        fprintf(out, "| dd_insert_many of %s%s into %s, against %s insert(first, last)%s | %.2f | %.2f | %.1f× | | |\n",
                fmt_int(k, b), w ? " weighted points" : " points", fmt_int(n, b2),
                w ? "Regular_triangulation_3's" : "CGAL's", strcmp(ok, "yes") ? differs : "", ours, cgal, rc);
        return 1;
    }
    if (sscanf(line, "locate-many: %lld queries in %lld uniform points: dtdel %lf us a query, CGAL spatial_sort + "
                     "hinted locate %lf us (%lfx); identical to CGAL: %7s", &k, &n, &ours, &cgal, &rc, ok) == 6) {
        fprintf(out, "| dd_locate_many of %s queries in %s points, against spatial_sort + hinted locate%s | %.3f | "
                     "%.3f | %.1f× | | |\n", fmt_int(k, b), fmt_int(n, b2), strcmp(ok, "yes") ? differs : "", ours,
                cgal, rc);
        return 1;
    }
    if (sscanf(line, "wmove-many: %lld wuniform weighted points, %lld passes of a step of 5%% of the mean spacing: "
                     "dtdel %lf us a move, CGAL move %lf us (%lfx); identical to CGAL: %7s", &n, &k, &ours, &cgal, &rc,
               ok) == 6) {
        fprintf(out, "| dd_move_many (%s weighted points, %lld passes), against Regular_triangulation_3's move loop%s | "
                     "%.2f | %.2f | %.1f× | | |\n", fmt_int(n, b), k, strcmp(ok, "yes") ? differs : "", ours, cgal, rc);
        return 1;
    }
    return 0;
}

/* One README row of a line of queries.txt, edits.txt, refine.txt or
 * regular.txt (dtdel query-bench, edit-bench, refine-bench,
 * regular-bench), or none; *header says whether the table's head was
 * written.                                                              */
static void readme_extra_row(const char *line, long long nq, FILE *out, int *header)
{
    char what[64], ok[8], b[40];
    long long k, n, mism;
    double ours, cgal, rc, fast, rf, frac;
    if (!*header) {
        fputs("\n| beyond deletion (uniform points) | dtdel µs | CGAL µs | ratio | CGAL Fast_location µs | ratio |\n"
              "|---|---:|---:|---:|---:|---:|\n", out);
        *header = 1;
    }
    if (readme_smoothing_row(line, out) || readme_batch_row(line, out)) return;
    if (sscanf(line, "%63[^:]: %lld: dtdel %lf us, CGAL %lf us (%lfx), CGAL Fast_location %lf us (%lfx); %*[^:]: %7s",
               what, &k, &ours, &cgal, &rc, &fast, &rf, ok) == 8)
        fprintf(out, "| %s, %s points%s | %.2f | %.2f | %.1f× | %.2f | %.1f× |\n",
                !strcmp(what, "insert") ? "insert a new point" : !strcmp(what, "locate") ? "locate" : "nearest vertex",
                fmt_int(nq, b), strcmp(ok, "yes") ? " (**differs from CGAL**)" : "", ours, cgal, rc, fast, rf);
    else if (sscanf(line, "delete-set %lf%%: %lld of %lld uniform points: dtdel %lf us a vertex, CGAL remove(first, "
                          "last) %lf us (%lfx); identical to CGAL: %7s", &frac, &k, &n, &ours, &cgal, &rc, ok) == 7)
        fprintf(out, "| delete a set, %.0f%% of %s%s | %.2f | %.2f | %.1f× | | |\n", frac, fmt_int(n, b),
                strcmp(ok, "yes") ? " (**differs from CGAL**)" : "", ours, cgal, rc);
    else if (sscanf(line, "refine: %lld uniform points, %lld circumcentres of the largest cell inserted (CGAL %*d); "
                          "dtdel %lf us an insertion (dd_insert_from the queued cell, queue fed by dd_created_cells), "
                          "CGAL find_conflicts + insert_in_hole %lf us (%lfx); triangulation part (dd_insert_from + "
                          "dd_cells_vertices vs find_conflicts + insert_in_hole) %lf us vs %lf us (%lfx); "
                          "hashes %*x / %*x; %lld mismatches",
                    &n, &k, &ours, &cgal, &rc, &fast, &frac, &rf, &mism) == 9) {
        char b2[40];
        fprintf(out, "| refine (%s circumcentres of the largest cell into %s points, dd_insert_from)%s | %.2f | %.2f | "
                     "%.1f× | | |\n",
                fmt_int(k, b), fmt_int(n, b2), mism ? " (**differs from CGAL**)" : "", ours, cgal, rc);
        fprintf(out, "| refine, the triangulation's part alone (dd_insert_from + dd_cells_vertices; find_conflicts + "
                     "insert_in_hole) | %.2f | %.2f | %.1f× | | |\n", fast, frac, rf);
    } else if (!strncmp(line, "regular-", 8)) {
        readme_regular_row(line, out);
    }
}

/* "Written by dd_write ..., 169.7 MB in 0.24 s." into note (empty if
 * none): the mesh file of build.txt's first block (dtdel build-bench
 * --write, the 10^6-point triangulation in make bench).                 */
static void write_note(const ctx *c, char *note, size_t size)
{
    char path[4096], b[40], b2[40];
    snprintf(path, sizeof path, "%s/build.txt", c->outdir);
    *note = 0;
    FILE *f = fopen(path, "r");
    if (!f) return;
    char *line = NULL, file[1024];
    size_t cap = 0;
    long long n = 0, cells, bytes;
    double mb, secs;
    while (!*note && read_line(f, &line, &cap) == 1) {
        if (sscanf(line, "dataset %*[^,], n = %lld", &n) == 1) continue;
        if (sscanf(line, "write: %1023s (dd_write) of %lld finite cells: %lld bytes (%lf MB) in %lf s", file, &cells,
                   &bytes, &mb, &secs) == 5) {
            const char *dot = strrchr(file, '.');
            const int ascii = dot && dot - file >= 6 && !strncmp(dot - 6, ".ascii", 6);
            snprintf(note, size, "Written by `dd_write` as a%s .vtu, the triangulation of %s points (%s finite "
                                 "cells) is %.1f MB, in %.2f s.", ascii ? "n ASCII" : " binary", fmt_int(n, b),
                     fmt_int(cells, b2), mb, secs);
        }
    }
    free(line);
    fclose(f);
}

/* The rows of OUTDIR/queries.txt, edits.txt, refine.txt and regular.txt
 * as a second table: insertion of new points, locate and nearest vertex
 * against CGAL with and without Fast_location, moves, set deletion,
 * refinement and the regular triangulation's construction and insertion
 * (weighted points), then one paragraph of notes: the churn line and
 * the mesh file's size and write time (write_note); nothing without the
 * files.                                                                */
static void readme_queries(const ctx *c, FILE *out)
{
    static const char *const files[5] = {"queries.txt", "edits.txt", "refine.txt", "regular.txt", "batch.txt"};
    char path[4096], churn[512] = "", note[512], b[40];
    int header = 0;
    for (int i = 0; i < 5; i++) {
        snprintf(path, sizeof path, "%s/%s", c->outdir, files[i]);
        FILE *f = fopen(path, "r");
        if (!f) continue;
        char *line = NULL;
        size_t cap = 0;
        long long n, k, last, nq = 0;
        double r2, rl, rss;
        while (read_line(f, &line, &cap) == 1) {
            if (sscanf(line, "dataset uniform, n = %lld", &nq) == 1) continue;
            const char *x = strstr(line, "RSS ");
            if (sscanf(line, "churn: %lld live vertices, %lld rounds", &n, &k) == 2 && x &&
                sscanf(x, "RSS %lf MiB after round 2, %lf MiB after round %lld (%lfx)", &r2, &rl, &last, &rss) == 4)
                snprintf(churn, sizeof churn,
                         "Under churn (`dtdel query-bench`: %lld rounds of deleting half of %s vertices and "
                         "inserting as many), resident memory after the last round is %.2f× that after round 2.",
                         k, fmt_int(n, b), rss);
            else if (strchr(line, ':'))
                readme_extra_row(line, nq, out, &header);
        }
        free(line);
        fclose(f);
    }
    write_note(c, note, sizeof note);
    if (*churn || *note) fprintf(out, "\n%s%s%s\n", churn, *churn && *note ? " " : "", note);
}
int write_readme_table(ctx *c)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/readme-table.md", c->outdir);
    size_t *col = malloc((c->variants.n ? c->variants.n : 1) * sizeof *col);
    size_t *idx = malloc(c->nrows * sizeof *idx);
    long long *sizes = malloc(c->nrows * sizeof *sizes);
    FILE *out = col && idx && sizes ? fopen(path, "w") : NULL;
    if (!out) {
        free(col);
        free(idx);
        free(sizes);
        return col && idx && sizes ? fail(c, "cannot write %s: %s", path, strerror(errno))
                                   : fail(c, "out of memory");
    }
    size_t ncol = readme_columns(c, col);
    fprintf(out, "| dataset | degree | deletions | CGAL µs |");
    for (size_t j = 0; j < ncol; j++) fprintf(out, " %s |", c->variants.s[col[j]]);
    fprintf(out, "\n|---|---:|---:|---:|");
    for (size_t j = 0; j < ncol; j++) fprintf(out, "---:|");
    fputc('\n', out);
    int present[NREADME], missing = 0;
    for (size_t i = 0; i < NREADME; i++) {
        present[i] = readme_row(c, &readme_rows[i], col, ncol, idx, sizes, "—", out);
        missing += !present[i];
    }
    if (missing) {                  /* paragraphs: a blank line before each */
        fprintf(out, "\nNot in this run: ");
        for (size_t i = 0, k = 0; i < NREADME; i++)
            if (!present[i]) readme_missing(&readme_rows[i], out, !k++);
        fprintf(out, ".\n");
    }

    size_t mism = 0;
    for (size_t i = 0; i < c->nrows; i++) mism += !c->rows[i].match;
    if (mism)
        fprintf(out, "\n**mismatches: %zu** (results that differ from CGAL's triangulation: a bug; "
                     "summary.md lists them)\n", mism);
    else
        fprintf(out, "\nmismatches: 0 (every result of the run equals CGAL's triangulation)\n");

    char commit[128], date[128], mode[128], machine[256], cores[32], cgal[128];
    file_value(c, "meta.txt", "commit", commit, sizeof commit);
    file_value(c, "meta.txt", "date", date, sizeof date);
    file_value(c, "meta.txt", "mode", mode, sizeof mode);
    file_value(c, "meta.txt", "machine", machine, sizeof machine);
    file_value(c, "meta.txt", "cores", cores, sizeof cores);
    file_value(c, "meta.txt", "cgal", cgal, sizeof cgal);
    fprintf(out, "\nRun: commit %s, %s, mode %s; %s, %s cores; CGAL %s.",
            *commit ? commit : "?", *date ? date : "?", *mode ? mode : "?", *machine ? machine : "?",
            *cores ? cores : "?", *cgal ? cgal : "?");
    readme_construction(c, out);
    fputc('\n', out);
    readme_queries(c, out);
    write_weighted(c, out);
    readme_python(c, out);
    free(col);
    free(idx);
    free(sizes);
    int bad = ferror(out);
    if (fclose(out) || bad) return fail(c, "cannot write %s", path);
    return 0;
}

