/*
 * weighted.c -- the datasets of dtdel wbench (the CSVs after --weighted:
 * regular triangulations, hidden points kept; issue 44): the strategies
 * that refused them, their pool ("All weighted datasets"), and the rows
 * of issue 44 with their targets (deletion per dataset, then the edits of
 * OUTDIR/wedits.txt) for summary.md and readme-table.md.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench/buckets.h"
#include "summarize.h"

/* On a weighted dataset: the engine deletion variants of the run with no
 * rows there, which refused weighted points (dtdel wbench says n/a).   */
void write_refused(const ctx *c, const table *t, size_t ds, FILE *out)
{
    size_t i = 0;
    while (i < c->nrows && c->rows[i].ds != ds) i++;
    if (i == c->nrows || !in_group(c, &c->rows[i], POOL_WEIGHTED)) return;
    int any = 0;
    for (size_t v = 0; v < c->variants.n; v++) {
        const char *name = c->variants.s[v];
        if (!is_deletion_variant(name) || strstr(name, "-paired") || column_of(c, t, name) >= 0) continue;
        fprintf(out, "%s%s", any++ ? ", " : "n/a (the strategy refuses weighted points in this build): ", name);
    }
    if (any) fprintf(out, ".\n\n");
}

/* ---- weighted points (dtdel wbench, wedits-bench; issue 44) ------------------ */

/* The weighted deletion rows and their targets (issue 44): the ratio of
 * CGAL's regular remove() to the default strategy's, over the rows.     */
static const struct { readme_spec s; const char *target; } weighted_rows[] = {
    {{"wuniform", 0, 4, 32}, "≥ 15×"}, {{"wuniform-most", 0, 4, 32}, ""}, {{"molecule", 0, 4, 32}, ""},
    {{"wgrid", 0, 4, 32}, ""},         {{"wmoment", 256, 0, ALL_DEGREES}, "≥ 300×"},
    {{"whelix", 16000, 0, ALL_DEGREES}, "≥ 200×"}};
#define NWEIGHTED (sizeof weighted_rows / sizeof weighted_rows[0])

/* The edits' lines of wedits.txt: their prefix, name and target. */
static const struct { const char *prefix, *name, *target; } wedit_rows[] = {
    {"wreweight:", "re-weight every vertex by ±10% (exudation-like)", "≥ 8×"},
    {"wmove:", "move every vertex by 5% of the spacing (Mesh_3-like)", "≥ 8×"},
    {"wdelete-set 10%:", "delete a set, 10%", "≥ 8×"},
    {"wdelete-set 90%:", "delete a set, 90%", "≥ 50×"}};
#define NWEDITS (sizeof wedit_rows / sizeof wedit_rows[0])

/* The number n in the first "; n WORDS" of line, or -1. */
static long long after_semicolon(const char *line, const char *words)
{
    long long v;
    int at;
    for (const char *m = strstr(line, "; "); m; m = strstr(m + 1, "; "))
        if (sscanf(m, "; %lld%n", &v, &at) == 1 && !strncmp(m + at, words, strlen(words))) return v;
    return -1;
}

/* One row of the edits' table from a line of wedits.txt (dtdel
 * wedits-bench), if it is one: our µs and CGAL's, their ratio (n/a while
 * the engine refuses the call), the target.                            */
static void weighted_edit_row(const char *line, FILE *out)
{
    for (size_t i = 0; i < NWEDITS; i++) {
        size_t len = strlen(wedit_rows[i].prefix);
        if (strncmp(line, wedit_rows[i].prefix, len)) continue;
        long long n = 0, k = 0;
        double ours = NAN, cgal = NAN, ratio = NAN;
        if (sscanf(line + len, " %lld of %lld", &k, &n) != 2) sscanf(line + len, " %lld", &n);
        const char *d = strstr(line, "): dtdel "), *g = strstr(line, ", CGAL ");
        if (d) sscanf(d + 9, "%lf", &ours);
        for (const char *v = g ? g + 7 : NULL; v && *v; v++)
            if (*v >= '0' && *v <= '9' && v[-1] == ' ') { sscanf(v, "%lf", &cgal); break; }
        const char *x = g ? strstr(g, "x); ") : NULL;
        while (x && x > g && x[-1] != '(') x--;
        if (x && !isnan(ours)) sscanf(x, "%lf", &ratio);
        const long long mism = after_semicolon(line, " mismatches"), edits = after_semicolon(line, " edits, ");
        const char *e = strstr(line, " edits, ");
        long long fb = -1;
        if (e) sscanf(e, " edits, %lld by", &fb);
        char b[40], b1[40], b2[40], b3[40], extra[96] = "";
        if (!strcmp(wedit_rows[i].prefix, "wmove:") && edits > 0 && fb >= 0)
            snprintf(extra, sizeof extra, " (CGAL: move() %.0f%%, remove+insert %.0f%%)",
                     100.0 * (double)(edits - fb) / (double)edits, 100.0 * (double)fb / (double)edits);
        fprintf(out, "| %s, %s points%s%s | %s | %s | %s | %s |\n", wedit_rows[i].name, fmt_int(n, b), extra,
                mism > 0 ? " (**differs from CGAL**)" : "", isnan(ours) ? "n/a" : fmt_sig(ours, b1),
                fmt_sig(cgal, b2), isnan(ratio) ? "n/a" : (fmt_sig(ratio, b3), strcat(b3, "×")), wedit_rows[i].target);
        return;
    }
}

/* The weighted rows (summary.md and readme-table.md): the deletion rows
 * (default strategy and every other, n/a where a strategy refuses
 * weighted points) and the edits of OUTDIR/wedits.txt, with targets.    */
void write_weighted(const ctx *c, FILE *out)
{
    size_t nw = 0;
    for (size_t i = 0; i < c->nrows; i++) nw += in_group(c, &c->rows[i], POOL_WEIGHTED);
    if (!nw) return;
    size_t *col = malloc((c->variants.n ? c->variants.n : 1) * sizeof *col);
    size_t *idx = malloc((c->nrows ? c->nrows : 1) * sizeof *idx);
    long long *sizes = malloc((c->nrows ? c->nrows : 1) * sizeof *sizes);
    if (!col || !idx || !sizes) { free(col), free(idx), free(sizes); return; }
    size_t ncol = readme_columns(c, col);
    if (ncol && !strcmp(c->variants.s[col[ncol - 1]], "cgal-rnd")) ncol--;    /* none for weights */
    fprintf(out, "\n| weighted points, hidden points kept | degree | deletions | CGAL regular remove µs |");
    for (size_t j = 0; j < ncol; j++) fprintf(out, " %s |", c->variants.s[col[j]]);
    fprintf(out, " target |\n|---|---:|---:|---:|");
    for (size_t j = 0; j < ncol; j++) fprintf(out, "---:|");
    fprintf(out, "---|\n");
    for (size_t i = 0; i < NWEIGHTED; i++) {
        char line[4096];
        FILE *mem = fmemopen(line, sizeof line, "w");
        if (!mem) continue;
        int got = readme_row(c, &weighted_rows[i].s, col, ncol, idx, sizes, "n/a", mem);
        fclose(mem);
        size_t len = strlen(line);
        if (!got || !len) continue;
        line[len - 1] = '\0';                           /* the newline */
        fprintf(out, "%s %s |\n", line, weighted_rows[i].target);
    }
    fprintf(out, "\nn/a: the strategy refuses weighted points in this build (DD_ERR_UNSUPPORTED). Target: on "
                 "the default strategy (%s).\n", c->variants.n ? "auto" : "");
    char path[4096];
    snprintf(path, sizeof path, "%s/wedits.txt", c->outdir);
    FILE *f = fopen(path, "r");
    if (f) {
        fputs("\n| weighted edits (wuniform) | dtdel µs | CGAL µs | ratio | target |\n|---|---:|---:|---:|---|\n", out);
        char *line = NULL;
        size_t cap = 0;
        while (read_line(f, &line, &cap) == 1) weighted_edit_row(line, out);
        free(line);
        fclose(f);
    }
    free(col), free(idx), free(sizes);
}

/* ---- what weights cost, degree by degree ---------------------------------- */

/* Each weighted dataset beside the unweighted one of its kind, at size n
 * (0: every size, pooled as in the per-degree tables; a helix's cost
 * follows its degree, and the sizes of the two sets reach different
 * degrees).                                                             */
static const struct { const char *w, *u; long long n; } parity_pairs[] = {
    {"wuniform", "uniform", 100000}, {"whelix", "helix", 0}};

/* The rows of dataset ds at size n of variant var in bucket b into idx;
 * how many.                                                             */
static size_t rows_of(const ctx *c, size_t ds, long long n, size_t var, int b, size_t *idx)
{
    size_t k = 0;
    for (size_t i = 0; i < c->nrows; i++) {
        const row *r = &c->rows[i];
        if (r->ds == ds && (!n || r->n == n) && r->var == var && r->bucket == b) idx[k++] = i;
    }
    return k;
}

/* One bucket of a pair: the medians of cgal and auto on the weighted
 * dataset (m[0], m[1]) and the unweighted one (m[2], m[3]); the most
 * rows of one of them on each side in *nw, *nu.  0 if one is missing. */
static int parity_medians(const ctx *c, const size_t ds[2], long long n, const size_t var[2], int b, size_t *idx,
                          double m[4], size_t *nw, size_t *nu)
{
    *nw = *nu = 0;
    for (int side = 0; side < 2; side++)
        for (int v = 0; v < 2; v++) {
            const size_t k = rows_of(c, ds[side], n, var[v], b, idx);
            if (!k) return 0;
            m[2 * side + v] = median_of(c, idx, k, F_US);
            size_t *most = side ? nu : nw;
            if (k > *most) *most = k;
        }
    return 1;
}

/* Per degree bucket, what weights cost CGAL and the default strategy:
 * each weighted dataset's medians beside those of the unweighted
 * dataset of the same kind and size (summary.md).  Where both engines
 * pay the same share for weights, the ratio to CGAL on weighted points
 * is the unweighted one; it can only be higher where CGAL pays more. */
void write_weight_cost(const ctx *c, FILE *md)
{
    const size_t cg = find_name(&c->variants, "cgal"), au = find_name(&c->variants, "auto");
    size_t *idx = malloc((c->nrows ? c->nrows : 1) * sizeof *idx);
    if (!idx || cg == (size_t)-1 || au == (size_t)-1) { free(idx); return; }
    int top = 0;
    for (size_t i = 0; i < c->nrows; i++) top = c->rows[i].bucket > top ? c->rows[i].bucket : top;
    int any = 0;
    for (size_t p = 0; p < sizeof parity_pairs / sizeof *parity_pairs; p++) {
        const size_t ds[2] = {find_name(&c->datasets, parity_pairs[p].w), find_name(&c->datasets, parity_pairs[p].u)};
        const size_t var[2] = {cg, au};
        if (ds[0] == (size_t)-1 || ds[1] == (size_t)-1) continue;
        for (int b = 0; b <= top; b++) {
            double m[4];
            size_t nw, nu;
            if (!parity_medians(c, ds, parity_pairs[p].n, var, b, idx, m, &nw, &nu)) continue;
            if (!any++)
                fprintf(md, "## What weights cost, degree by degree\n\nMedian µs per deletion in the same degree bucket: "
                            "CGAL's regular `remove()` on the weighted dataset against its Delaunay `remove()` on the "
                            "unweighted one of the same kind and size, and the same for `auto`. The ratio to CGAL on "
                            "weighted points exceeds the unweighted one only as far as weights cost CGAL a larger "
                            "share than they cost `auto` (the last two columns).\n\n"
                            "| weighted / unweighted, size | degree | deletions | CGAL regular | CGAL Delaunay | CGAL "
                            "w/u | auto weighted | auto unweighted | auto w/u | ratio weighted | ratio unweighted |\n"
                            "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
            long long lo, hi;
            dd_bucket_bounds(b, &lo, &hi);
            char b0[40], b1[40], b2[40], b3[40], b4[40], b5[40], b6[40], b7[40], b8[40];
            fprintf(md, "| %s / %s, %s | [%lld,%lld) | %zu / %zu | %s | %s | %s | %s | %s | %s | %s× | %s× |\n",
                    parity_pairs[p].w, parity_pairs[p].u,
                    parity_pairs[p].n ? fmt_int(parity_pairs[p].n, b0) : "every n", lo, hi, nw, nu,
                    fmt_sig(m[0], b1), fmt_sig(m[2], b2), fmt_sig(m[0] / m[2], b3), fmt_sig(m[1], b4),
                    fmt_sig(m[3], b5), fmt_sig(m[1] / m[3], b6), fmt_sig(m[0] / m[1], b7), fmt_sig(m[2] / m[3], b8));
        }
    }
    if (any) fputc('\n', md);
    free(idx);
}

/* The weighted datasets pooled, then the weighted rows of issue 44. */
int write_weighted_pool(ctx *c, FILE *md)
{
    table w;
    if (build_table(c, POOL_WEIGHTED, &w)) return -1;
    if (w.rows) {
        fprintf(md, "## All weighted datasets\n\nRows of every weighted dataset (dtdel wbench: regular "
                    "triangulations, hidden points kept, against CGAL's Regular_triangulation_3::remove()) "
                    "pooled per bucket and variant; %zu deletions, %zu rows.\n\n", w.total_deletions, w.rows);
        write_time_table(c, &w, md);
        write_mismatches(c, &w, POOL_WEIGHTED, md);
        fprintf(md, "## Weighted points: the rows of issue 44\n");
        write_weighted(c, md);
        fputc('\n', md);
        write_weight_cost(c, md);
    }
    free_table(&w);
    return 0;
}
