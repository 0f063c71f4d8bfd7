/*
 * table.c -- aggregates rows into a table: the cells of (degree bucket,
 * variant) with median, quartiles, ratio to cgal and cost relative to
 * insert, for one dataset or a pool of them (POOL_PLAIN, POOL_WEIGHTED);
 * the order of the variant columns; the quantile definition (type 7).
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "summarize.h"

/* Column order of the variants known to the paper; others follow, sorted,
 * and "insert" comes last. */
static const char *const variant_order[] = {
    "cgal", "cgal-rnd", "sew-full", "dtq-only", "guide-only",
    "grr-edge", "grr-neighbor", "grr-hashing", "grr-brio"};
#define NKNOWN (sizeof variant_order / sizeof variant_order[0])

/* Whether row r belongs to dataset ds or to the pool ds names. */
int in_group(const ctx *c, const struct row *r, size_t ds)
{
    if (ds == POOL_PLAIN) return r->file < c->first_weighted;
    if (ds == POOL_WEIGHTED) return r->file >= c->first_weighted;
    return r->ds == ds;
}

/* ---- statistics ------------------------------------------------------------- */

int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* p-quantile of sorted x[0..m-1], m > 0, linear interpolation (type 7). */
double quantile(const double *x, size_t m, double p)
{
    double h = (double)(m - 1) * p;
    size_t lo = (size_t)floor(h);
    if (lo + 1 >= m) return x[m - 1];
    return x[lo] + (h - (double)lo) * (x[lo + 1] - x[lo]);
}

int cmp_llong(const void *a, const void *b)
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

double median_of(const ctx *c, const size_t *idx, size_t k, enum field f)
{
    size_t m = gather(c, idx, k, f);
    return m ? quantile(c->scratch, m, 0.5) : NAN;
}

/* Column rank of a variant: known ones in the paper's order, then the
 * others alphabetically, then insert (not a deletion) last. */
int compute_var_rank(ctx *c)
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
int column_of(const ctx *c, const table *t, const char *name)
{
    for (size_t j = 0; j < t->nvar; j++)
        if (!strcmp(c->variants.s[t->var[j]], name)) return (int)j;
    return -1;
}

/* An engine deletion variant: neither a CGAL row nor the insert row. */
int is_deletion_variant(const char *name)
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

void free_table(table *t)
{
    free(t->var);
    free(t->deletions);
    free(t->cells);
    free(t->sizes);
    memset(t, 0, sizeof *t);
}

/* Aggregates the rows of dataset ds (or of a pool: POOL_PLAIN, POOL_WEIGHTED)
 * into t: cells by (bucket, variant), deletions per bucket. */
int build_table(ctx *c, size_t ds, table *t)
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
