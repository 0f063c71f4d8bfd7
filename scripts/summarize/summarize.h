/*
 * summarize.h -- what the files of build/summarize share: the rows read
 * from the bench CSVs, the aggregated tables, the context passed first,
 * and the functions one file calls in another.  main.c documents the
 * program (input, statistics, output).
 *
 *   load.c      errors, memory, CSV parsing
 *   table.c     statistics, variant order, build_table (rows -> cells)
 *   summary.c   summary.md per dataset and pooled, plotdata/, the driver
 *   readme.c    readme-table.md (README.md's results table)
 *   weighted.c  the weighted datasets' pool and rows (issue 44)
 *   python.c    the README's Python table (python.txt, scripts/pybench.py)
 */
#ifndef SUMMARIZE_H
#define SUMMARIZE_H

#include <stddef.h>
#include <stdio.h>

#define EXIT_INPUT 1
#define EXIT_USAGE 2

#define NPHASES 4
#define ALL_NAME "all-datasets"
#define INSERT_NAME "insert"       /* the re-insertion row, not a deletion */

/* The pools: every unweighted dataset, every weighted one (a dataset
 * index ds names one dataset; these name a pool instead). */
#define POOL_PLAIN ((size_t)-1)
#define POOL_WEIGHTED ((size_t)-2)

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

/* A row of a README table: dataset, size n (0: every size) and degree
 * bucket [lo,hi) (lo = hi = 0: the bucket of the highest degree at size
 * n).  ALL_DEGREES as hi: every degree (its cells say the degrees seen). */
typedef struct readme_spec { const char *dataset; long long n, lo, hi; } readme_spec;
#define ALL_DEGREES (1LL << 40)

/* ---- load.c ---- */
/* Formats the error into c->err; returns -1. */
int fail(ctx *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* One line into *buf without its newline or a trailing CR: 1, 0 at end
 * of file, -1 on a read error. */
int read_line(FILE *f, char **buf, size_t *cap);
/* Appends the rows of CSV c->files[file]; 0, or -1 with c->err set. */
int load_csv(ctx *c, size_t file);

/* ---- table.c ---- */
int in_group(const ctx *c, const struct row *r, size_t ds);
int cmp_double(const void *a, const void *b);
int cmp_llong(const void *a, const void *b);
double quantile(const double *x, size_t m, double p);
double median_of(const ctx *c, const size_t *idx, size_t k, enum field f);
int compute_var_rank(ctx *c);
int column_of(const ctx *c, const table *t, const char *name);
int is_deletion_variant(const char *name);
int build_table(ctx *c, size_t ds, table *t);
void free_table(table *t);

/* ---- summary.c ---- */
void write_time_table(const ctx *c, const table *t, FILE *out);
void write_mismatches(const ctx *c, const table *t, size_t ds, FILE *out);
/* Writes every output file under c->outdir; 0, or -1 with c->err set. */
int write_all(ctx *c);

/* ---- readme.c ---- */
size_t find_name(const strtab *t, const char *s);
size_t readme_columns(const ctx *c, size_t *col);
int readme_row(const ctx *c, const readme_spec *s, const size_t *col, size_t ncol,
               size_t *idx, long long *sizes, const char *none, FILE *out);
const char *fmt_int(long long v, char buf[40]);
const char *fmt_sig(double v, char buf[40]);
int write_readme_table(ctx *c);

/* ---- python.c ---- */
void readme_python(const ctx *c, FILE *out);

/* ---- weighted.c ---- */
void write_refused(const ctx *c, const table *t, size_t ds, FILE *out);
void write_weighted(const ctx *c, FILE *out);
void write_weight_cost(const ctx *c, FILE *md);
int write_weighted_pool(ctx *c, FILE *md);

#endif
