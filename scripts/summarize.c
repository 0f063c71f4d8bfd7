/*
 * summarize.c -- turns the bench driver's per-dataset CSVs into the
 * Markdown summary and the gnuplot data files (DESIGN 10).  Standalone:
 * libc and libm only, no state outside the context passed first.
 *
 *   summarize OUTDIR CSV... [--weighted CSV...]
 *
 * The CSVs after --weighted are those of dtdel wbench (weighted points,
 * issue 44): their datasets get their sections like any other, but are
 * pooled apart ("All weighted datasets", not in "All datasets" nor in
 * its plot), and the weighted rows (write_weighted) go into summary.md
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
 * engine's re-insertion of the deleted vertex (see src/cli_bench.c), the
 * cost deletions are measured against.  It is the last column of the time
 * table, gets no ratio to cgal there nor in the plot data (so the ratio
 * plot leaves it out; it has no tets or phases either), and its match 0
 * means the re-insertion did not restore the triangulation.  "Engine
 * deletion variants" below are all variants but cgal, cgal-rnd and insert.
 *
 * Degree buckets: src/buckets.h ([4,8), [8,12), [12,16), [16,24), ...,
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
 * most 2).  Phase and tets medians ignore empty fields.  "All datasets"
 * pools the rows of every dataset per bucket and variant and applies the
 * same definitions to the pool, except that a variant's cgal and insert
 * references are pooled only over the datasets in which the variant has
 * rows in that bucket.
 *
 * Output, all under OUTDIR:
 *   summary.md              meta.txt's lines, then per dataset: time table
 *                           (buckets x variants), mismatches, "Deletion vs
 *                           re-insertion" (per bucket with insert rows:
 *                           insert's median µs and each engine deletion
 *                           variant's vs insert, "×2.31"), phase split,
 *                           tets created; then all datasets pooled.
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
 *   plotdata/all-datasets.* the same three files for the pooled rows (the
 *                           paper's time-vs-degree figure); "all-datasets"
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
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "cli/buckets.h"

#define EXIT_INPUT 1
#define EXIT_USAGE 2

#define NFIELDS 13
#define NPHASES 4
#define ALL_NAME "all-datasets"
#define INSERT_NAME "insert"       /* the re-insertion row, not a deletion */
#define MAX_LISTED_MISMATCHES 20

static const char *const csv_header =
    "dataset,n,vertex,degree,on_hull,variant,us,tets_created,link_us,"
    "locate_us,conflict_us,sew_us,match";

/* Column order of the variants known to the paper; others follow, sorted,
 * and "insert" comes last. */
static const char *const variant_order[] = {
    "cgal", "cgal-rnd", "sew-full", "dtq-only", "guide-only",
    "grr-edge", "grr-neighbor", "grr-hashing", "grr-brio"};
#define NKNOWN (sizeof variant_order / sizeof variant_order[0])

static const char *const phase_name[NPHASES] = {"link", "locate", "conflict", "sew"};

/* Which numeric field of a row a statistic is taken over. */
enum field { F_US, F_TETS, F_LINK, F_LOCATE, F_CONFLICT, F_SEW };

typedef struct row {
    size_t ds, var;            /* indices into ctx.datasets / ctx.variants */
    size_t file;               /* index into argv's CSV list              */
    long line;                 /* line number in that file                */
    long long n, vertex;
    long long degree;
    int on_hull, match;
    int bucket;
    double us, tets;           /* tets NaN when unknown                   */
    double phase[NPHASES];     /* NaN when unknown                        */
} row;

typedef struct strtab {
    char **s;
    size_t n, cap;
} strtab;

/* Statistics of one (bucket, variant) cell. */
typedef struct cell {
    size_t first, rows;        /* rows idx[first..first+rows-1] of
                                  build_table's sorted index array        */
    size_t mismatches, on_hull;
    double med, q1, q3;        /* of us                                   */
    double ratio;              /* cgal med / med, NaN without cgal        */
    double vs_insert;          /* med / insert med, deletion variants only */
    double tets;               /* median tets_created, NaN if unknown     */
    double phase[NPHASES];     /* median phase times, NaN if unknown      */
} cell;

/* One group of rows (a dataset, or all of them) aggregated. */
typedef struct table {
    size_t nvar;               /* columns: variants present, in order     */
    size_t *var;               /* their ctx.variants indices              */
    int nbucket;               /* buckets 0..nbucket-1 (some empty)       */
    size_t *deletions;         /* per bucket: most rows of one variant    */
    cell *cells;               /* nbucket x nvar                          */
    size_t rows, total_deletions, on_hull, mismatches;
    long long *sizes;          /* distinct n, ascending                   */
    size_t nsizes;
} table;

typedef struct ctx {
    const char *outdir;
    char *const *files;
    size_t first_weighted;     /* files from this index on: --weighted    */
    strtab datasets, variants;
    row *rows;
    size_t nrows, caprows;
    size_t *var_rank;          /* column position of each variant         */
    double *scratch;           /* nrows doubles                           */
    char err[1024];
} ctx;

/* ---- errors and memory ---------------------------------------------------- */

static int fail(ctx *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int fail(ctx *c, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->err, sizeof c->err, fmt, ap);
    va_end(ap);
    return -1;
}

/* Grows *p (elements of size sz) to hold at least need; 0 or -1. */
static int grow(void **p, size_t *cap, size_t need, size_t sz)
{
    if (need <= *cap) return 0;
    size_t ncap = *cap ? *cap : 16;
    while (ncap < need) ncap *= 2;
    void *q = realloc(*p, ncap * sz);
    if (!q) return -1;
    *p = q;
    *cap = ncap;
    return 0;
}

/* Index of s in t, adding it if new; (size_t)-1 when out of memory. */
static size_t intern(strtab *t, const char *s)
{
    for (size_t i = 0; i < t->n; i++)
        if (!strcmp(t->s[i], s)) return i;
    void *p = t->s;
    if (grow(&p, &t->cap, t->n + 1, sizeof *t->s)) return (size_t)-1;
    t->s = p;
    size_t len = strlen(s);
    char *copy = malloc(len + 1);
    if (!copy) return (size_t)-1;
    memcpy(copy, s, len + 1);
    t->s[t->n] = copy;
    return t->n++;
}

/* The pools: every unweighted dataset, every weighted one. */
#define POOL_PLAIN ((size_t)-1)
#define POOL_WEIGHTED ((size_t)-2)

/* Whether row r belongs to dataset ds or to the pool ds names. */
static int in_group(const ctx *c, const struct row *r, size_t ds)
{
    if (ds == POOL_PLAIN) return r->file < c->first_weighted;
    if (ds == POOL_WEIGHTED) return r->file >= c->first_weighted;
    return r->ds == ds;
}

/* ---- degree buckets --------------------------------------------------------- */

static double bucket_center(int b)
{
    long long lo, hi;
    dd_bucket_bounds(b, &lo, &hi);
    return (double)(lo + hi - 1) / 2.0;
}

/* ---- CSV parsing -------------------------------------------------------------- */

/* Reads one line into *buf (without the newline or a trailing CR).
 * Returns 1 on a line, 0 at end of file, -1 on a read error. */
static int read_line(FILE *f, char **buf, size_t *cap)
{
    ssize_t len = getline(buf, cap, f);
    if (len < 0) return ferror(f) ? -1 : 0;
    while (len > 0 && ((*buf)[len - 1] == '\n' || (*buf)[len - 1] == '\r'))
        (*buf)[--len] = '\0';
    return 1;
}

static int parse_int(const char *s, long long lo, long long hi, long long *out)
{
    if (!*s) return -1;
    char *end;
    errno = 0;
    long long v = strtoll(s, &end, 10);
    if (errno || *end || v < lo || v > hi) return -1;
    *out = v;
    return 0;
}

/* A finite non-negative number; empty gives NaN when allow_empty. */
static int parse_time(const char *s, int allow_empty, double *out)
{
    if (!*s) {
        if (!allow_empty) return -1;
        *out = NAN;
        return 0;
    }
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || *end || !isfinite(v) || v < 0) return -1;
    *out = v;
    return 0;
}

static int valid_dataset_name(const char *s)
{
    if (!*s || !strcmp(s, ALL_NAME) || s[0] == '.') return 0;
    for (; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') ||
              (*s >= '0' && *s <= '9') || *s == '.' || *s == '_' || *s == '-'))
            return 0;
    return 1;
}

/* Printable ASCII without space or the characters that break Markdown
 * tables, gnuplot strings or the shell: | " ' ` \ */
static int valid_variant_name(const char *s)
{
    if (!*s) return 0;
    for (; *s; s++)
        if (*s <= ' ' || *s > '~' || strchr("|\"'`\\", *s)) return 0;
    return 1;
}

/* Parses one data line (modified in place) into a new row. */
static int parse_row(ctx *c, char *line, size_t file, long lineno)
{
    const char *where = c->files[file];
    char *f[NFIELDS];
    int nf = 0;
    for (char *p = line;;) {
        if (nf < NFIELDS) f[nf] = p;
        nf++;
        char *comma = strchr(p, ',');
        if (!comma) break;
        *comma = '\0';
        p = comma + 1;
    }
    if (nf != NFIELDS)
        return fail(c, "%s:%ld: expected %d comma-separated fields, got %d",
                    where, lineno, NFIELDS, nf);

    void *p = c->rows;
    if (grow(&p, &c->caprows, c->nrows + 1, sizeof *c->rows))
        return fail(c, "out of memory reading %s", where);
    c->rows = p;
    row *r = &c->rows[c->nrows];
    r->file = file;
    r->line = lineno;

#define BAD(what, val) fail(c, "%s:%ld: %s must be %s, got \"%s\"", where, lineno, \
                            what, val, f[col])
    int col = 0;
    if (!valid_dataset_name(f[col]))
        return BAD("dataset", "letters, digits, '.', '_' or '-' (not \"" ALL_NAME "\")");
    r->ds = intern(&c->datasets, f[col]);
    col = 1;
    if (parse_int(f[col], 1, (long long)1 << 53, &r->n)) return BAD("n", "a positive integer");
    col = 2;
    if (parse_int(f[col], 0, (long long)1 << 53, &r->vertex))
        return BAD("vertex", "a non-negative integer");
    col = 3;
    if (parse_int(f[col], 0, (long long)1 << 53, &r->degree))
        return BAD("degree", "a non-negative integer");
    long long v;
    col = 4;
    if (parse_int(f[col], 0, 1, &v)) return BAD("on_hull", "0 or 1");
    r->on_hull = (int)v;
    col = 5;
    if (!valid_variant_name(f[col]))
        return BAD("variant", "printable, without spaces or | \" ' ` \\");
    r->var = intern(&c->variants, f[col]);
    col = 6;
    if (parse_time(f[col], 0, &r->us)) return BAD("us", "a finite number >= 0");
    col = 7;
    if (!*f[col]) r->tets = NAN;
    else if (parse_int(f[col], 0, (long long)1 << 53, &v))
        return BAD("tets_created", "empty or a non-negative integer");
    else r->tets = (double)v;
    for (int i = 0; i < NPHASES; i++) {
        col = 8 + i;
        if (parse_time(f[col], 1, &r->phase[i]))
            return fail(c, "%s:%ld: %s_us must be empty or a finite number >= 0, got \"%s\"",
                        where, lineno, phase_name[i], f[col]);
    }
    col = 12;
    if (parse_int(f[col], 0, 1, &v)) return BAD("match", "0 or 1");
    r->match = (int)v;
#undef BAD
    if (r->ds == (size_t)-1 || r->var == (size_t)-1)
        return fail(c, "out of memory reading %s", where);
    r->bucket = dd_degree_bucket(r->degree);
    c->nrows++;
    return 0;
}

static int load_csv(ctx *c, size_t file)
{
    const char *path = c->files[file];
    FILE *f = fopen(path, "r");
    if (!f) return fail(c, "cannot open %s: %s", path, strerror(errno));
    char *buf = NULL;
    size_t cap = 0;
    long lineno = 0;
    int st = 0, got;
    while ((got = read_line(f, &buf, &cap)) == 1) {
        lineno++;
        if (lineno == 1) {
            if (strcmp(buf, csv_header)) {
                st = fail(c, "%s:1: header must be exactly \"%s\", got \"%.200s\"",
                          path, csv_header, buf);
                break;
            }
            continue;
        }
        if (!buf[strspn(buf, " \t")]) continue;          /* blank line */
        if ((st = parse_row(c, buf, file, lineno))) break;
    }
    if (!st && got < 0) st = fail(c, "cannot read %s: %s", path, strerror(errno));
    if (!st && lineno == 0) st = fail(c, "%s:1: empty file, expected the header \"%s\"", path, csv_header);
    free(buf);
    fclose(f);
    return st;
}

/* ---- statistics ------------------------------------------------------------- */

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* p-quantile of sorted x[0..m-1], m > 0, linear interpolation (type 7). */
static double quantile(const double *x, size_t m, double p)
{
    double h = (double)(m - 1) * p;
    size_t lo = (size_t)floor(h);
    if (lo + 1 >= m) return x[m - 1];
    return x[lo] + (h - (double)lo) * (x[lo + 1] - x[lo]);
}

static int cmp_llong(const void *a, const void *b)
{
    long long x = *(const long long *)a, y = *(const long long *)b;
    return (x > y) - (x < y);
}

static double field_of(const row *r, enum field f)
{
    switch (f) {
    case F_US: return r->us;
    case F_TETS: return r->tets;
    default: return r->phase[f - F_LINK];
    }
}

/* Sorts the known values of field f over rows idx[0..k-1] into scratch and
 * returns how many there are. */
static size_t gather(const ctx *c, const size_t *idx, size_t k, enum field f)
{
    size_t m = 0;
    for (size_t i = 0; i < k; i++) {
        double v = field_of(&c->rows[idx[i]], f);
        if (!isnan(v)) c->scratch[m++] = v;
    }
    qsort(c->scratch, m, sizeof *c->scratch, cmp_double);
    return m;
}

static double median_of(const ctx *c, const size_t *idx, size_t k, enum field f)
{
    size_t m = gather(c, idx, k, f);
    return m ? quantile(c->scratch, m, 0.5) : NAN;
}

/* Column rank of a variant: known ones in the paper's order, then the
 * others alphabetically, then insert (not a deletion) last. */
static int compute_var_rank(ctx *c)
{
    size_t nv = c->variants.n;
    size_t *order = malloc((nv ? nv : 1) * sizeof *order);
    c->var_rank = malloc((nv ? nv : 1) * sizeof *c->var_rank);
    if (!order || !c->var_rank) { free(order); return fail(c, "out of memory"); }
    size_t m = 0;
    for (size_t k = 0; k < NKNOWN; k++)
        for (size_t v = 0; v < nv; v++)
            if (!strcmp(c->variants.s[v], variant_order[k])) order[m++] = v;
    size_t first_other = m;
    for (size_t v = 0; v < nv; v++) {
        int known = 0;
        for (size_t k = 0; k < NKNOWN; k++)
            if (!strcmp(c->variants.s[v], variant_order[k])) known = 1;
        if (known || !strcmp(c->variants.s[v], INSERT_NAME)) continue;
        size_t at = m++;                       /* insertion sort by name */
        while (at > first_other && strcmp(c->variants.s[order[at - 1]], c->variants.s[v]) > 0) {
            order[at] = order[at - 1];
            at--;
        }
        order[at] = v;
    }
    for (size_t v = 0; v < nv; v++)
        if (!strcmp(c->variants.s[v], INSERT_NAME)) order[m++] = v;
    for (size_t i = 0; i < nv; i++) c->var_rank[order[i]] = i;
    free(order);
    return 0;
}

/* Column of the variant called name in t, or -1. */
static int column_of(const ctx *c, const table *t, const char *name)
{
    for (size_t j = 0; j < t->nvar; j++)
        if (!strcmp(c->variants.s[t->var[j]], name)) return (int)j;
    return -1;
}

/* An engine deletion variant: neither a CGAL row nor the insert row. */
static int is_deletion_variant(const char *name)
{
    return strcmp(name, "cgal") && strcmp(name, "cgal-rnd") && strcmp(name, INSERT_NAME);
}

/* Median us of the rows of cell ref (same bucket as ce) from the datasets
 * in which ce has rows; NaN if none.  idx: build_table's sorted indices;
 * present: scratch for one flag per dataset. */
static double ref_median(const ctx *c, const size_t *idx, const cell *ce, const cell *ref, char *present)
{
    if (!ref->rows) return NAN;
    for (size_t i = 0; i < c->datasets.n; i++) present[i] = 0;
    for (size_t i = ce->first; i < ce->first + ce->rows; i++) present[c->rows[idx[i]].ds] = 1;
    size_t m = 0;
    for (size_t i = ref->first; i < ref->first + ref->rows; i++)
        if (present[c->rows[idx[i]].ds]) c->scratch[m++] = c->rows[idx[i]].us;
    if (!m) return NAN;
    qsort(c->scratch, m, sizeof *c->scratch, cmp_double);
    return quantile(c->scratch, m, 0.5);
}

/* qsort has no context argument: sort (key, row) pairs instead. */
typedef struct keyed { unsigned long long k[4]; size_t row; } keyed;

static int cmp_keyed(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    for (int i = 0; i < 4; i++)
        if (x->k[i] != y->k[i]) return x->k[i] < y->k[i] ? -1 : 1;
    return (x->row > y->row) - (x->row < y->row);
}

static void free_table(table *t)
{
    free(t->var);
    free(t->deletions);
    free(t->cells);
    free(t->sizes);
    memset(t, 0, sizeof *t);
}

/* Aggregates the rows of dataset ds (or of a pool: POOL_PLAIN, POOL_WEIGHTED)
 * into t: cells by (bucket, variant), deletions per bucket. */
static int build_table(ctx *c, size_t ds, table *t)
{
    memset(t, 0, sizeof *t);
    size_t nv = c->variants.n, k = 0;
    keyed *key = malloc((c->nrows ? c->nrows : 1) * sizeof *key);
    size_t *idx = malloc((c->nrows ? c->nrows : 1) * sizeof *idx);
    int *col = malloc((nv ? nv : 1) * sizeof *col);
    char *present = NULL;      /* per dataset, for the ratios */
    if (!key || !idx || !col) goto oom;

    int maxb = 0;
    for (size_t i = 0; i < c->nrows; i++) {
        const row *r = &c->rows[i];
        if (!in_group(c, r, ds)) continue;
        if (r->bucket > maxb) maxb = r->bucket;
        idx[k++] = i;
    }
    t->rows = k;
    t->nbucket = maxb + 1;

    /* columns: the variants present, in rank order */
    for (size_t v = 0; v < nv; v++) col[v] = -1;
    for (size_t i = 0; i < k; i++) col[c->rows[idx[i]].var] = 0;
    t->var = malloc((nv ? nv : 1) * sizeof *t->var);
    if (!t->var) goto oom;
    for (size_t r = 0; r < nv; r++)
        for (size_t v = 0; v < nv; v++)
            if (c->var_rank[v] == r && col[v] == 0) t->var[t->nvar++] = v;
    for (size_t j = 0; j < t->nvar; j++) col[t->var[j]] = (int)j;

    size_t ncell = (size_t)t->nbucket * t->nvar;
    t->cells = malloc((ncell ? ncell : 1) * sizeof *t->cells);
    t->deletions = calloc((size_t)t->nbucket, sizeof *t->deletions);
    t->sizes = malloc((k ? k : 1) * sizeof *t->sizes);
    present = malloc((c->datasets.n ? c->datasets.n : 1) * sizeof *present);
    if (!t->cells || !t->deletions || !t->sizes || !present) goto oom;
    for (size_t i = 0; i < ncell; i++)
        t->cells[i] = (cell){.med = NAN, .q1 = NAN, .q3 = NAN, .ratio = NAN, .vs_insert = NAN,
                             .tets = NAN, .phase = {NAN, NAN, NAN, NAN}};

    /* distinct sizes */
    for (size_t i = 0; i < k; i++) t->sizes[i] = c->rows[idx[i]].n;
    qsort(t->sizes, k, sizeof *t->sizes, cmp_llong);
    for (size_t i = 0; i < k; i++)
        if (i == 0 || t->sizes[i] != t->sizes[t->nsizes - 1]) t->sizes[t->nsizes++] = t->sizes[i];

    /* cells: group by (bucket, column) */
    for (size_t i = 0; i < k; i++) {
        const row *r = &c->rows[idx[i]];
        key[i] = (keyed){{(unsigned long long)r->bucket, (unsigned long long)col[r->var], 0, 0},
                         idx[i]};
    }
    qsort(key, k, sizeof *key, cmp_keyed);
    for (size_t i = 0; i < k; i++) idx[i] = key[i].row;
    for (size_t lo = 0, hi; lo < k; lo = hi) {
        for (hi = lo; hi < k && key[hi].k[0] == key[lo].k[0] && key[hi].k[1] == key[lo].k[1]; hi++) {}
        cell *ce = &t->cells[key[lo].k[0] * t->nvar + key[lo].k[1]];
        ce->first = lo;
        ce->rows = hi - lo;
        for (size_t i = lo; i < hi; i++) {
            ce->mismatches += !c->rows[idx[i]].match;
            ce->on_hull += (size_t)c->rows[idx[i]].on_hull;
        }
        t->mismatches += ce->mismatches;
        size_t m = gather(c, idx + lo, hi - lo, F_US);
        ce->med = quantile(c->scratch, m, 0.5);
        ce->q1 = quantile(c->scratch, m, 0.25);
        ce->q3 = quantile(c->scratch, m, 0.75);
        ce->tets = median_of(c, idx + lo, hi - lo, F_TETS);
        for (int p = 0; p < NPHASES; p++)
            ce->phase[p] = median_of(c, idx + lo, hi - lo, (enum field)(F_LINK + p));
    }

    /* deletions: every variant deletes the same vertices, so count the
     * rows of the variant with the most, per bucket and in total */
    for (size_t j = 0; j < t->nvar; j++) {
        size_t rows = 0, hull = 0;
        for (int b = 0; b < t->nbucket; b++) {
            const cell *ce = &t->cells[(size_t)b * t->nvar + j];
            if (ce->rows > t->deletions[b]) t->deletions[b] = ce->rows;
            rows += ce->rows;
            hull += ce->on_hull;
        }
        if (rows > t->total_deletions) t->total_deletions = rows;
        if (hull > t->on_hull) t->on_hull = hull;
    }

    /* ratios to cgal in the same bucket, over the cgal rows of the datasets
     * in which the variant has rows in that bucket (when pooling datasets,
     * a variant run on only some of them is compared on those only); the
     * deletion variants' cost relative to insert the same way */
    int cg = column_of(c, t, "cgal"), in = column_of(c, t, INSERT_NAME);
    for (int b = 0; b < t->nbucket; b++)
        for (size_t j = 0; j < t->nvar; j++) {
            cell *ce = &t->cells[(size_t)b * t->nvar + j];
            if (!ce->rows || !(ce->med > 0)) continue;
            double ref = NAN;
            if (cg >= 0 && (int)j != in)
                ref = ref_median(c, idx, ce, &t->cells[(size_t)b * t->nvar + (size_t)cg], present);
            if (!isnan(ref)) ce->ratio = ref / ce->med;
            if (in >= 0 && is_deletion_variant(c->variants.s[t->var[j]])) {
                ref = ref_median(c, idx, ce, &t->cells[(size_t)b * t->nvar + (size_t)in], present);
                if (ref > 0) ce->vs_insert = ce->med / ref;
            }
        }
    free(key);
    free(idx);
    free(col);
    free(present);
    return 0;
oom:
    free(key);
    free(idx);
    free(col);
    free(present);
    free_table(t);
    return fail(c, "out of memory");
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

static void write_time_table(const ctx *c, const table *t, FILE *out)
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

/* On a weighted dataset: the engine deletion variants of the run with no
 * rows there, which refused weighted points (dtdel wbench says n/a).   */
static void write_refused(const ctx *c, const table *t, size_t ds, FILE *out)
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
static void write_mismatches(const ctx *c, const table *t, size_t ds, FILE *out)
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

static void write_title(const ctx *c, const table *t, const char *name, FILE *f)
{
    fprintf(f, "# title: %s", name);
    if (!strcmp(name, ALL_NAME)) {
        fprintf(f, ", %zu dataset%s", c->datasets.n, c->datasets.n == 1 ? "" : "s");
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
    write_title(c, t, name, dat);
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

/* ---- readme-table.md -------------------------------------------------------------- */

/* The rows of README.md's results table: the paper's experiment at a
 * glance.  n = 0: every size of the dataset; lo = hi = 0: the degree
 * bucket of the highest degree at size n (on the curves each size has
 * one degree, or nearly: the moment curve n - 1, the helix about 2√n).  */
typedef struct readme_spec { const char *dataset; long long n, lo, hi; } readme_spec;
/* hi of a row over every degree (its cells say the degrees seen). */
#define ALL_DEGREES (1LL << 40)
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

static size_t find_name(const strtab *t, const char *s)
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
static size_t readme_columns(const ctx *c, size_t *col)
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
static const char *fmt_int(long long v, char buf[40])
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
static const char *fmt_sig(double v, char buf[40])
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
static int readme_row(const ctx *c, const readme_spec *s, const size_t *col, size_t ncol,
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
    double ratio;
    int any = 0;
    while (read_line(f, &line, &cap) == 1) {
        if (sscanf(line, "dataset %63[^,], n = %lld", ds, &n) == 2) continue;
        if (sscanf(line, "speed ratio dtdel/cgal: %lf", &ratio) == 1 && ds[0]) {
            fprintf(out, "%s%.2f×%s on %s, n = %s",
                    any ? "; " : " Construction of DT(S) (`dtdel build-bench`): ", ratio,
                    any ? "" : " CGAL's speed", ds, fmt_int(n, b));
            any = 1;
        } else if (!strcmp(line, "identical to CGAL: NO") && any) {
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

/* One README row of a line of queries.txt, edits.txt, refine.txt or
 * regular.txt (dtdel query-bench, edit-bench, refine-bench,
 * regular-bench), or none; *header says whether the table's head was
 * written.                                                              */
static void readme_extra_row(const char *line, long long nq, FILE *out, int *header)
{
    char what[64], ok[8], b[40];
    long long k, n, mism;
    double ours, cgal, rc, fast, rf, share, frac;
    if (!*header) {
        fputs("\n| beyond deletion (uniform points) | dtdel µs | CGAL µs | ratio | CGAL Fast_location µs | ratio |\n"
              "|---|---:|---:|---:|---:|---:|\n", out);
        *header = 1;
    }
    if (sscanf(line, "%63[^:]: %lld: dtdel %lf us, CGAL %lf us (%lfx), CGAL Fast_location %lf us (%lfx); %*[^:]: %7s",
               what, &k, &ours, &cgal, &rc, &fast, &rf, ok) == 8)
        fprintf(out, "| %s, %s points%s | %.2f | %.2f | %.1f× | %.2f | %.1f× |\n",
                !strcmp(what, "insert") ? "insert a new point" : !strcmp(what, "locate") ? "locate" : "nearest vertex",
                fmt_int(nq, b), strcmp(ok, "yes") ? " (**differs from CGAL**)" : "", ours, cgal, rc, fast, rf);
    else if (sscanf(line, "smoothing: %lld uniform points, %lld passes of a random step of 5%% of the mean spacing: "
                          "dtdel %lf us, CGAL move_if_no_collision %lf us (%lfx); kept by the filter %lf%%; "
                          "identical to CGAL: %7s", &n, &k, &ours, &cgal, &rc, &share, ok) == 7)
        fprintf(out, "| move (smoothing %s points, %lld passes)%s | %.2f | %.2f | %.1f× | | |\n", fmt_int(n, b), k,
                strcmp(ok, "yes") ? " (**differs from CGAL**)" : "", ours, cgal, rc);
    else if (sscanf(line, "delete-set %lf%%: %lld of %lld uniform points: dtdel %lf us a vertex, CGAL remove(first, "
                          "last) %lf us (%lfx); identical to CGAL: %7s", &frac, &k, &n, &ours, &cgal, &rc, ok) == 7)
        fprintf(out, "| delete a set, %.0f%% of %s%s | %.2f | %.2f | %.1f× | | |\n", frac, fmt_int(n, b),
                strcmp(ok, "yes") ? " (**differs from CGAL**)" : "", ours, cgal, rc);
    else if (sscanf(line, "refine: %lld uniform points, %lld circumcentres of the largest cell inserted (CGAL %*d); "
                          "dtdel %lf us an insertion (queue fed by dd_created_cells), CGAL find_conflicts + "
                          "insert_in_hole %lf us (%lfx); hashes %*x / %*x; %lld mismatches",
                    &n, &k, &ours, &cgal, &rc, &mism) == 6) {
        char b2[40];
        fprintf(out, "| refine (%s circumcentres of the largest cell into %s points)%s | %.2f | %.2f | %.1f× | | |\n",
                fmt_int(k, b), fmt_int(n, b2), mism ? " (**differs from CGAL**)" : "", ours, cgal, rc);
    } else if (!strncmp(line, "regular-", 8)) {
        readme_regular_row(line, out);
    }
}

/* The rows of OUTDIR/queries.txt, edits.txt, refine.txt and regular.txt
 * as a second table: insertion of new points, locate and nearest vertex
 * against CGAL with and without Fast_location, moves, set deletion,
 * refinement and the regular triangulation's construction and insertion
 * (weighted points), then the churn line; nothing without the files.   */
static void readme_queries(const ctx *c, FILE *out)
{
    static const char *const files[4] = {"queries.txt", "edits.txt", "refine.txt", "regular.txt"};
    char path[4096], churn[512] = "", b[40];
    int header = 0;
    for (int i = 0; i < 4; i++) {
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
                         "\nUnder churn (`dtdel query-bench`: %lld rounds of deleting half of %s vertices and "
                         "inserting as many), resident memory after the last round is %.2f× that after round 2.\n",
                         k, fmt_int(n, b), rss);
            else if (strchr(line, ':'))
                readme_extra_row(line, nq, out, &header);
        }
        free(line);
        fclose(f);
    }
    fputs(churn, out);
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
static void write_weighted(const ctx *c, FILE *out)
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

static int write_readme_table(ctx *c)
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
    free(col);
    free(idx);
    free(sizes);
    int bad = ferror(out);
    if (fclose(out) || bad) return fail(c, "cannot write %s", path);
    return 0;
}

/* ---- driver ------------------------------------------------------------------------ */

static int make_dir(ctx *c, const char *path)
{
    if (mkdir(path, 0777) && errno != EEXIST)
        return fail(c, "cannot create directory %s: %s", path, strerror(errno));
    return 0;
}

/* The weighted datasets pooled, then the weighted rows of issue 44. */
static int write_weighted_pool(ctx *c, FILE *md)
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
    }
    free_table(&w);
    return 0;
}

static int write_all(ctx *c)
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
    if (build_table(c, (size_t)-1, &all)) { fclose(md); fclose(list); return -1; }
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
        fprintf(md, "## All datasets\n\nRows of every dataset pooled per bucket and variant "
                    "(a variant's ratio uses only the cgal rows, and its cost relative to "
                    "insert only the insert rows, of the datasets in which it has rows in that "
                    "bucket); %zu deletions, %zu rows.\n\n",
                all.total_deletions, all.rows);
        write_time_table(c, &all, md);
        write_mismatches(c, &all, (size_t)-1, md);
        write_insert_table(c, &all, md);
        st = write_phases(c, &all, (size_t)-1, md, NULL);
        if (!st) write_tets_table(c, &all, md);
        if (!st) st = write_plotdata(c, &all, (size_t)-1, ALL_NAME);
    }
    free_table(&all);
    if (!st) st = write_weighted_pool(c, md);
    if (!st) st = write_readme_table(c);
    int bad = ferror(md);
    if (fclose(md) || bad) st = st ? st : fail(c, "cannot write %s", path);
    if (close_out(c, list, "datasets", ".txt")) st = -1;
    return st;
}

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
