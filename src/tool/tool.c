/*
 * tool.c -- the helpers the user's commands and the bench share
 * (tool.h), and the comparison rows.
 *
 * A row is one way to delete: an engine strategy (variants/), "cgal"
 * (CGAL's remove() through the shim) or "cgal-rnd" (the shim's
 * triangulate-and-sew in random order).  Every row's result but cgal's,
 * the reference, is compared with CGAL's canonical form.
 */
#include "tool/tool.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

int usage_error(const char *cmd, const char *fmt, const char *arg)
{
    fprintf(stderr, "dtdel %s: ", cmd);
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n");
    return EXIT_SHOW_USAGE;
}

int parse_u64(const char *s, uint64_t *out)
{
    if (!s || !*s || *s == '-') return -1;
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno || *end) return -1;
    *out = v;
    return 0;
}

double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int same_canonical(const int32_t *a, size_t na, const int32_t *b, size_t nb)
{
    return na == nb && !memcmp(a, b, 4 * na * sizeof *a);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

double median_of(double *a, size_t n)
{
    qsort(a, n, sizeof *a, cmp_double);
    return n % 2 ? a[n / 2] : 0.5 * (a[n / 2 - 1] + a[n / 2]);
}

uint32_t draw_vertex(const dd_tri *t, uint64_t *x, uint32_t np, unsigned char *used)
{
    uint32_t v;
    do v = rand_below(x, np);
    while (used[v] || !dd_is_vertex(t, v));
    used[v] = 1;
    return v;
}

/* ---- rows ----------------------------------------------------------------- */

size_t all_rows(row *rows, size_t max)
{
    size_t n = 0;
    for (size_t i = 0; dd_variant_name(i) && n < max; i++) {
        rows[n].name = dd_variant_name(i);
        rows[n].kind = ROW_ENGINE;
        n++;
    }
    if (n < max) { rows[n].name = "cgal"; rows[n].kind = ROW_CGAL; n++; }
    if (n < max) { rows[n].name = "cgal-rnd"; rows[n].kind = ROW_CGAL_RND; n++; }
    return n;
}

int find_row(const char *name, row *out)
{
    row rows[32];
    size_t n = all_rows(rows, 32);
    for (size_t i = 0; i < n; i++)
        if (!strcmp(rows[i].name, name)) { *out = rows[i]; return 1; }
    return 0;
}

int row_delete(const row *r, dd_tri *t, dd_cgal *g, uint32_t v, uint64_t seed)
{
    switch (r->kind) {
    case ROW_ENGINE: return dd_delete_with(t, v, r->name) != DD_OK;
    case ROW_CGAL: return dd_cgal_remove(g, v);
    default: return dd_cgal_remove_rnd(g, v, seed);
    }
}

int row_reinsert(const row *r, dd_tri *t, dd_cgal *g, uint32_t v)
{
    return r->kind == ROW_ENGINE ? dd_reinsert(t, v) != DD_OK : dd_cgal_reinsert(g, v);
}

int row_canonical(const row *r, dd_tri *t, dd_cgal *g, int32_t **a, size_t *n)
{
    return r->kind == ROW_ENGINE ? dd_canonical(t, a, n) != DD_OK : dd_cgal_canonical(g, a, n);
}
