/*
 * summarize -- turns the bench driver's per-dataset CSVs into the
 * Markdown summary and the gnuplot data files (DESIGN 10).  Standalone:
 * libc and libm only, no state outside the context passed first.
 *
 *   summarize OUTDIR CSV... [--weighted CSV...]
 *
 * The CSVs after --weighted are those of dtdel wbench (weighted points,
 * issue 44): their datasets get their sections like any other, but are
 * pooled apart ("All weighted datasets", not in "All unweighted
 * datasets" nor in its plot), and the weighted rows (write_weighted) go into summary.md
 * and readme-table.md with the lines of OUTDIR/wedits.txt.
 *
 * Input.  Each CSV starts with exactly this header line:
 *   dataset,n,vertex,degree,on_hull,variant,us,tets_created,link_us,
 *   locate_us,conflict_us,sew_us,match
 * then one row per (deletion, variant).  Fields are separated by commas,
 * no quoting.  tets_created and the four phase times may be empty
 * (unknown); every other field is required.  Rows are grouped by the
 * dataset column (not the file name) and, inside a dataset, over all its
 * sizes n.  A dataset name is made of letters, digits, '.', '_', '-' (it
 * names files); a variant name is any printable ASCII without spaces or
 * | " ' ` \ (it goes into Markdown tables and gnuplot strings).  Blank
 * lines are skipped; anything else malformed stops the run with
 * "FILE:LINE: what" on stderr and exit status 1 (2 for bad usage), before
 * any output is written.
 *
 * The variant "insert" is not a deletion: the bench driver's row timing our
 * engine's re-insertion of the deleted vertex (see src/bench/bench.c), the
 * cost deletions are measured against.  It is the last column of the time
 * table, gets no ratio to cgal there nor in the plot data (so the ratio
 * plot leaves it out; it has no tets or phases either), and its match 0
 * means the re-insertion did not restore the triangulation.  "Engine
 * deletion variants" below are all variants but cgal, cgal-rnd and insert.
 *
 * Degree buckets: src/bench/buckets.h ([4,8), [8,12), [12,16), [16,24), ...,
 * nearly even steps on the log axis).  Empty buckets are skipped.  A bucket's
 * plotted x is the middle of its integer degrees, (lo + hi - 1) / 2.
 * "deletions" in a bucket is the row count of the variant with the most
 * rows there (every variant deletes the same vertices); a variant with
 * fewer rows has its count shown in its cell, "[k rows]".
 *
 * Statistics.  Quantiles by linear interpolation between order statistics
 * (Hyndman-Fan type 7, R's and numpy's default): for sorted x[0..m-1] the
 * p-quantile is x[h] interpolated at h = (m-1)p.  Median p = .5, IQR from
 * q1 = .25 to q3 = .75.  ratio = cgal median / variant median in the same
 * bucket of the same dataset (> 1: the variant is faster than CGAL), only
 * when that bucket has cgal rows.  vs insert = variant median / insert
 * median in the same bucket of the same dataset, for engine deletion
 * variants only (2.00: deleting costs twice re-inserting; the target is at
 * most 2).  Phase and tets medians ignore empty fields.  "All unweighted
 * datasets" pools the rows of every unweighted dataset per bucket and
 * variant and applies the same definitions to the pool, except that a
 * variant's cgal and insert references are pooled only over the datasets
 * in which the variant has rows in that bucket ("All weighted datasets"
 * likewise for the weighted ones).
 *
 * Output, all under OUTDIR:
 *   summary.md              meta.txt's lines, then per dataset: time table
 *                           (buckets x variants), mismatches, "Deletion vs
 *                           re-insertion" (per bucket with insert rows:
 *                           insert's median µs and each engine deletion
 *                           variant's vs insert, "×2.31"), phase split,
 *                           tets created; then the unweighted datasets
 *                           pooled, then the weighted ones.
 *   plotdata/datasets.txt   the datasets of this run, one per line.
 *   plotdata/D.dat          per dataset D: one gnuplot index block per
 *                           variant, in column order; each line
 *                             1 bucket_center 2 median_us 3 q1_us 4 q3_us
 *                             5 ratio_to_cgal 6 median_tets 7 median_link_us
 *                             8 median_locate_us 9 median_conflict_us
 *                             10 median_sew_us 11 bucket_lo 12 bucket_hi
 *                             13 rows 14 mismatches
 *                           NaN where a value is unknown (ratio always
 *                           for insert).  A "# title: " line opens the
 *                           file.
 *   plotdata/D.variants     the variant of each block, one per line.
 *   plotdata/D.phases       per variant with phase times: variant, median
 *                           link, locate, conflict, sew, us (all rows).
 *   plotdata/all-datasets.* the same three files for the unweighted pool
 *                           (the paper's time-vs-degree figure); "all-datasets"
 *                           is therefore reserved as a dataset name.
 *   readme-table.md         README.md's results table (scripts/bench.sh
 *                           puts it between the README's bench-table
 *                           markers): the rows of readme_rows, each with
 *                           cgal's median µs and, per variant, cgal median
 *                           / variant median over the same rows; then the
 *                           mismatch count of all rows, the run from
 *                           meta.txt and the construction ratios from
 *                           OUTDIR/build.txt (dtdel build-bench), if there;
 *                           then the rows of queries.txt, edits.txt,
 *                           refine.txt and regular.txt, if there.
 *
 * Mismatches (match == 0) are counted per variant and bucket, printed
 * loudly in summary.md and on stderr; they do not change the exit status
 * (the summary itself is valid), the bench driver decides about failing.
 *
 * Files: this one (usage, main), load.c, table.c, summary.c, readme.c,
 * weighted.c; summarize.h lists what each owns.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "summarize.h"

int main(int argc, char **argv)
{
    if (argc < 3 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        FILE *o = argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) ? stdout : stderr;
        fprintf(o, "usage: summarize OUTDIR CSV...\n"
                   "Aggregates bench CSVs by degree bucket and variant into OUTDIR/summary.md\n"
                   "and OUTDIR/plotdata/ (gnuplot input for scripts/plots.sh).\n");
        return o == stdout ? 0 : EXIT_USAGE;
    }
    ctx c;
    memset(&c, 0, sizeof c);
    c.outdir = argv[1];
    char **files = malloc((size_t)argc * sizeof *files);
    size_t nfiles = 0;
    c.first_weighted = (size_t)argc;
    for (int i = 2; files && i < argc; i++) {
        if (!strcmp(argv[i], "--weighted")) c.first_weighted = nfiles;
        else files[nfiles++] = argv[i];
    }
    c.files = files;
    int st = files ? 0 : fail(&c, "out of memory");
    for (size_t i = 0; i < nfiles && !st; i++) st = load_csv(&c, i);
    if (!st && c.nrows == 0) st = fail(&c, "no data rows in the CSV files given");
    if (!st) {
        c.scratch = malloc(c.nrows * sizeof *c.scratch);
        st = c.scratch ? compute_var_rank(&c) : fail(&c, "out of memory");
    }
    if (!st) st = write_all(&c);
    if (st) fprintf(stderr, "summarize: %s\n", c.err);

    for (size_t i = 0; i < c.datasets.n; i++) free(c.datasets.s[i]);
    for (size_t i = 0; i < c.variants.n; i++) free(c.variants.s[i]);
    free(c.datasets.s);
    free(c.variants.s);
    free(c.rows);
    free(c.var_rank);
    free(c.scratch);
    free(files);
    return st ? EXIT_INPUT : 0;
}
