/*
 * summary.c -- OUTDIR/summary.md and OUTDIR/plotdata/: per dataset the
 * time table, mismatches, deletion vs re-insertion, phase split and tets
 * created, then the unweighted datasets pooled ("All unweighted
 * datasets"), then the weighted pool (weighted.c); the gnuplot data of
 * each dataset and of the unweighted pool; write_all drives every
 * output, readme-table.md too.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "bench/buckets.h"
#include "summarize.h"

#define MAX_LISTED_MISMATCHES 20

/* ---- degree buckets --------------------------------------------------------- */

static double bucket_center(int b)
{
    long long lo, hi;
    dd_bucket_bounds(b, &lo, &hi);
    return (double)(lo + hi - 1) / 2.0;
}
/* ---- formatting ------------------------------------------------------------- */

/* A time in µs with 3-4 significant digits: 1234, 123.4 -> "123", 12.3, 1.23. */
static const char *fmt_us(double v, char buf[32])
{
    if (isnan(v)) snprintf(buf, 32, "—");
    else if (v >= 100) snprintf(buf, 32, "%.0f", v);
    else if (v >= 10) snprintf(buf, 32, "%.1f", v);
    else snprintf(buf, 32, "%.2f", v);
    return buf;
}

/* A median count: integral, or .5 for an even number of values. */
static const char *fmt_count(double v, char buf[32])
{
    if (isnan(v)) snprintf(buf, 32, "—");
    else if (v == floor(v)) snprintf(buf, 32, "%.0f", v);
    else snprintf(buf, 32, "%.1f", v);
    return buf;
}

static const char *fmt_bucket(int b, char buf[48])
{
    long long lo, hi;
    dd_bucket_bounds(b, &lo, &hi);
    snprintf(buf, 48, "[%lld,%lld)", lo, hi);
    return buf;
}

/* Writes "NaN" for unknown values so gnuplot skips them. */
static void put_num(FILE *f, double v)
{
    if (isnan(v)) fputs(" NaN", f);
    else fprintf(f, " %.6g", v);
}

/* ---- summary.md ----------------------------------------------------------------- */

static void write_meta(const ctx *c, FILE *out)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/meta.txt", c->outdir);
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(out, "_No meta.txt in %s: machine, compiler, flags, CGAL version and date unknown._\n\n",
                c->outdir);
        return;
    }
    char *buf = NULL;
    size_t cap = 0;
    while (read_line(f, &buf, &cap) == 1) {
        if (!buf[strspn(buf, " \t")]) continue;
        char *colon = strchr(buf, ':');
        if (colon) {
            *colon = '\0';
            const char *val = colon + 1 + strspn(colon + 1, " \t");
            fprintf(out, "- **%s**: %s\n", buf, val);
        } else {
            fprintf(out, "- %s\n", buf);
        }
    }
    free(buf);
    fclose(f);
    fputc('\n', out);
}

void write_time_table(const ctx *c, const table *t, FILE *out)
{
    char b1[32], b2[32], b3[32], bb[48];
    fprintf(out, "Time per deletion in µs: median (IQR q1–q3) ×ratio, ratio = cgal median / "
                 "variant median in the same bucket (> 1: faster than CGAL).");
    if (column_of(c, t, INSERT_NAME) >= 0)
        fprintf(out, " The insert column is not a deletion: our engine re-inserting the same "
                     "vertex (compared with the deletions below).");
    fprintf(out, "\n\n");
    fprintf(out, "| degree | deletions |");
    for (size_t j = 0; j < t->nvar; j++) fprintf(out, " %s |", c->variants.s[t->var[j]]);
    fprintf(out, "\n|---|---:|");
    for (size_t j = 0; j < t->nvar; j++) fprintf(out, "---:|");
    fputc('\n', out);
    for (int b = 0; b < t->nbucket; b++) {
        if (!t->deletions[b]) continue;
        fprintf(out, "| %s | %zu |", fmt_bucket(b, bb), t->deletions[b]);
        for (size_t j = 0; j < t->nvar; j++) {
            const cell *ce = &t->cells[(size_t)b * t->nvar + j];
            if (!ce->rows) { fprintf(out, " — |"); continue; }
            fprintf(out, " %s (%s–%s)", fmt_us(ce->med, b1), fmt_us(ce->q1, b2), fmt_us(ce->q3, b3));
            if (!isnan(ce->ratio) && strcmp(c->variants.s[t->var[j]], "cgal"))
                fprintf(out, " ×%.2f", ce->ratio);
            if (ce->rows != t->deletions[b]) fprintf(out, " [%zu rows]", ce->rows);
            fprintf(out, " |");
        }
        fputc('\n', out);
    }
    fprintf(out, "| **mismatches** | %zu |", t->mismatches);
    for (size_t j = 0; j < t->nvar; j++) {
        size_t m = 0;
        for (int b = 0; b < t->nbucket; b++) m += t->cells[(size_t)b * t->nvar + j].mismatches;
        fprintf(out, m ? " **%zu** |" : " %zu |", m);
    }
    fprintf(out, "\n\n");
}

/* Deletion vs re-insertion: per bucket with insert rows, insert's median
 * and each deletion variant's median / insert's median. */
static void write_insert_table(const ctx *c, const table *t, FILE *out)
{
    char b1[32], bb[48];
    int in = column_of(c, t, INSERT_NAME);
    if (in < 0) {
        fprintf(out, "Deletion vs re-insertion: no %s rows in this dataset.\n\n", INSERT_NAME);
        return;
    }
    fprintf(out, "Deletion vs re-insertion: median µs of our engine re-inserting the deleted "
                 "vertex (%s), and per deletion variant its median deletion time divided by "
                 "that (×2.00: deleting costs twice re-inserting; lower is better, target ≤ 2).\n\n"
                 "| degree | %s µs |", INSERT_NAME, INSERT_NAME);
    for (size_t j = 0; j < t->nvar; j++)
        if (is_deletion_variant(c->variants.s[t->var[j]])) fprintf(out, " %s |", c->variants.s[t->var[j]]);
    fprintf(out, "\n|---|---:|");
    for (size_t j = 0; j < t->nvar; j++)
        if (is_deletion_variant(c->variants.s[t->var[j]])) fprintf(out, "---:|");
    fputc('\n', out);
    for (int b = 0; b < t->nbucket; b++) {
        const cell *ic = &t->cells[(size_t)b * t->nvar + (size_t)in];
        if (!ic->rows) continue;
        fprintf(out, "| %s | %s |", fmt_bucket(b, bb), fmt_us(ic->med, b1));
        for (size_t j = 0; j < t->nvar; j++) {
            if (!is_deletion_variant(c->variants.s[t->var[j]])) continue;
            double r = t->cells[(size_t)b * t->nvar + j].vs_insert;
            if (isnan(r)) fprintf(out, " — |");
            else fprintf(out, " ×%.2f |", r);
        }
        fputc('\n', out);
    }
    fputc('\n', out);
}

/* The mismatch line: "mismatches: 0", or loud, with the rows listed. */
void write_mismatches(const ctx *c, const table *t, size_t ds, FILE *out)
{
    if (!t->mismatches) {
        fprintf(out, "mismatches: 0\n\n");
        return;
    }
    fprintf(out, "**MISMATCHES: %zu** deletions differ from CGAL's canonical form (a bug):",
            t->mismatches);
    for (size_t j = 0; j < t->nvar; j++) {
        size_t m = 0;
        for (int b = 0; b < t->nbucket; b++) m += t->cells[(size_t)b * t->nvar + j].mismatches;
        if (m) fprintf(out, " %s %zu;", c->variants.s[t->var[j]], m);
    }
    int in = column_of(c, t, INSERT_NAME);
    for (int b = 0; in >= 0 && b < t->nbucket; b++)
        if (t->cells[(size_t)b * t->nvar + (size_t)in].mismatches) {
            fprintf(out, " (the %s rows count re-insertions that did not restore the triangulation)",
                    INSERT_NAME);
            break;
        }
    fprintf(out, "\n\n");
    size_t listed = 0;
    for (size_t i = 0; i < c->nrows && listed < MAX_LISTED_MISMATCHES; i++) {
        const row *r = &c->rows[i];
        if (r->match || !in_group(c, r, ds)) continue;
        fprintf(out, "- MISMATCH %s n=%lld vertex=%lld degree=%lld variant=%s (%s:%ld)\n",
                c->datasets.s[r->ds], r->n, r->vertex, r->degree, c->variants.s[r->var],
                c->files[r->file], r->line);
        listed++;
    }
    if (t->mismatches > listed) fprintf(out, "- ... and %zu more\n", t->mismatches - listed);
    fputc('\n', out);
}

/* Medians over all rows of column j of t (dataset ds, or all): the four
 * phases into med[0..3], us into med[4]; returns whether any phase time is
 * known.  idx is scratch for nrows indices. */
static int phase_medians(const ctx *c, const table *t, size_t ds, size_t j, size_t *idx,
                         double med[NPHASES + 1], size_t *rows)
{
    size_t k = 0;
    for (size_t i = 0; i < c->nrows; i++)
        if (c->rows[i].var == t->var[j] && in_group(c, &c->rows[i], ds))
            idx[k++] = i;
    int any = 0;
    for (int p = 0; p < NPHASES; p++) {
        med[p] = median_of(c, idx, k, (enum field)(F_LINK + p));
        any |= !isnan(med[p]);
    }
    med[NPHASES] = median_of(c, idx, k, F_US);
    *rows = k;
    return any;
}

/* The phase split in Markdown (out) or, when out is NULL, as plot data
 * (dat). */
static int write_phases(ctx *c, const table *t, size_t ds, FILE *out, FILE *dat)
{
    size_t *idx = malloc((c->nrows ? c->nrows : 1) * sizeof *idx);
    if (!idx) return fail(c, "out of memory");
    int header = 0;
    char b[32];
    for (size_t j = 0; j < t->nvar; j++) {
        double med[NPHASES + 1];
        size_t k;
        if (!phase_medians(c, t, ds, j, idx, med, &k)) continue;
        if (!out) {
            fprintf(dat, "%s", c->variants.s[t->var[j]]);
            for (int p = 0; p <= NPHASES; p++) put_num(dat, med[p]);
            fputc('\n', dat);
            continue;
        }
        if (!header) {
            fprintf(out, "Phase split: median µs of each phase over all deletions of the variant "
                         "(medians do not add up to the median total).\n\n"
                         "| variant | rows | link | locate | conflict | sew | total |\n"
                         "|---|---:|---:|---:|---:|---:|---:|\n");
            header = 1;
        }
        fprintf(out, "| %s | %zu |", c->variants.s[t->var[j]], k);
        for (int p = 0; p <= NPHASES; p++) fprintf(out, " %s |", fmt_us(med[p], b));
        fputc('\n', out);
    }
    if (out && !header) fprintf(out, "Phase split: no phase times recorded.\n");
    if (out) fputc('\n', out);
    free(idx);
    return 0;
}

static void write_tets_table(const ctx *c, const table *t, FILE *out)
{
    char b1[32], bb[48];
    int *has = calloc(t->nvar ? t->nvar : 1, sizeof *has);
    int any = 0;
    if (!has) return;
    for (size_t j = 0; j < t->nvar; j++)
        for (int b = 0; b < t->nbucket; b++)
            if (!isnan(t->cells[(size_t)b * t->nvar + j].tets)) has[j] = any = 1;
    if (!any) {
        fprintf(out, "Tetrahedra created: not recorded in this dataset.\n\n");
        free(has);
        return;
    }
    fprintf(out, "Tetrahedra created per deletion (median):\n\n| degree |");
    for (size_t j = 0; j < t->nvar; j++)
        if (has[j]) fprintf(out, " %s |", c->variants.s[t->var[j]]);
    fprintf(out, "\n|---|");
    for (size_t j = 0; j < t->nvar; j++)
        if (has[j]) fprintf(out, "---:|");
    fputc('\n', out);
    for (int b = 0; b < t->nbucket; b++) {
        if (!t->deletions[b]) continue;
        fprintf(out, "| %s |", fmt_bucket(b, bb));
        for (size_t j = 0; j < t->nvar; j++)
            if (has[j]) fprintf(out, " %s |", fmt_count(t->cells[(size_t)b * t->nvar + j].tets, b1));
        fputc('\n', out);
    }
    fputc('\n', out);
    free(has);
}

/* ---- plot data ------------------------------------------------------------------ */

static FILE *open_out(ctx *c, const char *name, const char *suffix)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/plotdata/%s%s", c->outdir, name, suffix);
    FILE *f = fopen(path, "w");
    if (!f) fail(c, "cannot write %s: %s", path, strerror(errno));
    return f;
}

static int close_out(ctx *c, FILE *f, const char *name, const char *suffix)
{
    int bad = ferror(f);
    if (fclose(f) || bad)
        return fail(c, "cannot write %s/plotdata/%s%s", c->outdir, name, suffix);
    return 0;
}

/* How many datasets have rows in the pool (or dataset) ds. */
static size_t count_datasets(const ctx *c, size_t ds)
{
    size_t n = 0;
    for (size_t d = 0; d < c->datasets.n; d++)
        for (size_t i = 0; i < c->nrows; i++)
            if (c->rows[i].ds == d && in_group(c, &c->rows[i], ds)) { n++; break; }
    return n;
}

/* "# title: NAME (n = sizes), K deletions"; the unweighted pool says how
 * many datasets it holds instead of sizes. */
static void write_title(const ctx *c, const table *t, size_t ds, const char *name, FILE *f)
{
    fprintf(f, "# title: %s", name);
    if (ds == POOL_PLAIN) {
        size_t n = count_datasets(c, ds);
        fprintf(f, ", %zu unweighted dataset%s", n, n == 1 ? "" : "s");
    } else if (t->nsizes) {
        fprintf(f, " (n = ");
        for (size_t i = 0; i < t->nsizes; i++) fprintf(f, "%s%lld", i ? ", " : "", t->sizes[i]);
        fprintf(f, ")");
    }
    fprintf(f, ", %zu deletion%s\n", t->total_deletions, t->total_deletions == 1 ? "" : "s");
}

/* name.dat, name.variants, name.phases for one table. */
static int write_plotdata(ctx *c, const table *t, size_t ds, const char *name)
{
    FILE *dat = open_out(c, name, ".dat");
    if (!dat) return -1;
    write_title(c, t, ds, name, dat);
    fprintf(dat, "# columns: 1 bucket_center 2 median_us 3 q1_us 4 q3_us 5 ratio_to_cgal "
                 "6 median_tets 7 median_link_us 8 median_locate_us 9 median_conflict_us "
                 "10 median_sew_us 11 bucket_lo 12 bucket_hi 13 rows 14 mismatches\n"
                 "# one index block per variant (see %s.variants); NaN = unknown\n", name);
    for (size_t j = 0; j < t->nvar; j++) {
        if (j) fputs("\n\n", dat);
        fprintf(dat, "# variant %s\n", c->variants.s[t->var[j]]);
        for (int b = 0; b < t->nbucket; b++) {
            const cell *ce = &t->cells[(size_t)b * t->nvar + j];
            if (!ce->rows) continue;
            long long lo, hi;
            dd_bucket_bounds(b, &lo, &hi);
            fprintf(dat, "%.6g", bucket_center(b));
            put_num(dat, ce->med);
            put_num(dat, ce->q1);
            put_num(dat, ce->q3);
            put_num(dat, ce->ratio);
            put_num(dat, ce->tets);
            for (int p = 0; p < NPHASES; p++) put_num(dat, ce->phase[p]);
            fprintf(dat, " %lld %lld %zu %zu\n", lo, hi, ce->rows, ce->mismatches);
        }
    }
    if (close_out(c, dat, name, ".dat")) return -1;

    FILE *vf = open_out(c, name, ".variants");
    if (!vf) return -1;
    for (size_t j = 0; j < t->nvar; j++) fprintf(vf, "%s\n", c->variants.s[t->var[j]]);
    if (close_out(c, vf, name, ".variants")) return -1;

    FILE *ph = open_out(c, name, ".phases");
    if (!ph) return -1;
    fprintf(ph, "# variant median_link_us median_locate_us median_conflict_us median_sew_us median_us\n");
    int st = write_phases(c, t, ds, NULL, ph);
    if (close_out(c, ph, name, ".phases") || st) return -1;
    return 0;
}
/* ---- driver ------------------------------------------------------------------------ */

static int make_dir(ctx *c, const char *path)
{
    if (mkdir(path, 0777) && errno != EEXIST)
        return fail(c, "cannot create directory %s: %s", path, strerror(errno));
    return 0;
}


int write_all(ctx *c)
{
    char path[4096];
    if (make_dir(c, c->outdir)) return -1;
    snprintf(path, sizeof path, "%s/plotdata", c->outdir);
    if (make_dir(c, path)) return -1;

    snprintf(path, sizeof path, "%s/summary.md", c->outdir);
    FILE *md = fopen(path, "w");
    if (!md) return fail(c, "cannot write %s: %s", path, strerror(errno));
    FILE *list = open_out(c, "datasets", ".txt");
    if (!list) { fclose(md); return -1; }

    fprintf(md, "# Vertex deletion benchmark: dtdel variants against CGAL\n\n");
    write_meta(c, md);
    table all;
    if (build_table(c, POOL_PLAIN, &all)) { fclose(md); fclose(list); return -1; }
    size_t mism = 0;
    for (size_t i = 0; i < c->nrows; i++) mism += !c->rows[i].match;
    if (mism)
        fprintf(md, "**MISMATCHES: %zu in total** -- see the datasets below.\n\n", mism);
    else
        fprintf(md, "mismatches: 0 (every deletion of every variant equals CGAL's result)\n\n");
    fprintf(md, "Degree buckets [lo,hi): [4,8), then [2^k, 1.5·2^k) and [1.5·2^k, 2^(k+1)); "
                "empty buckets omitted. Median and quartiles by linear interpolation "
                "(type 7). \"deletions\": rows of the variant with the most rows in the "
                "bucket (all variants delete the same vertices); a cell marked [k rows] "
                "has fewer.\n\n");

    int st = 0;
    for (size_t d = 0; d < c->datasets.n && !st; d++) {
        table t;
        if ((st = build_table(c, d, &t))) break;
        const char *name = c->datasets.s[d];
        fprintf(md, "## %s\n\nn = ", name);
        for (size_t i = 0; i < t.nsizes; i++) fprintf(md, "%s%lld", i ? ", " : "", t.sizes[i]);
        fprintf(md, "; %zu deletions (%zu on the hull), %zu rows.\n\n", t.total_deletions,
                t.on_hull, t.rows);
        write_time_table(c, &t, md);
        write_refused(c, &t, d, md);
        write_mismatches(c, &t, d, md);
        write_insert_table(c, &t, md);
        st = write_phases(c, &t, d, md, NULL);
        if (!st) write_tets_table(c, &t, md);
        if (!st) st = write_plotdata(c, &t, d, name);
        fprintf(list, "%s\n", name);
        if (t.mismatches)
            fprintf(stderr, "summarize: MISMATCHES in %s: %zu deletions differ from CGAL\n", name,
                    t.mismatches);
        free_table(&t);
    }
    if (!st) {
        fprintf(md, "## All unweighted datasets\n\nRows of every unweighted dataset (dtdel bench: "
                    "Delaunay triangulations; the weighted ones are pooled apart below) pooled "
                    "per bucket and variant (a variant's ratio uses only the cgal rows, and its "
                    "cost relative to "
                    "insert only the insert rows, of the datasets in which it has rows in that "
                    "bucket); %zu deletions, %zu rows.\n\n",
                all.total_deletions, all.rows);
        write_time_table(c, &all, md);
        write_mismatches(c, &all, POOL_PLAIN, md);
        write_insert_table(c, &all, md);
        st = write_phases(c, &all, POOL_PLAIN, md, NULL);
        if (!st) write_tets_table(c, &all, md);
        if (!st) st = write_plotdata(c, &all, POOL_PLAIN, ALL_NAME);
    }
    free_table(&all);
    if (!st) st = write_weighted_pool(c, md);
    if (!st) st = write_readme_table(c);
    int bad = ferror(md);
    if (fclose(md) || bad) st = st ? st : fail(c, "cannot write %s", path);
    if (close_out(c, list, "datasets", ".txt")) st = -1;
    return st;
}
