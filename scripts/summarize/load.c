/*
 * load.c -- reads the bench CSVs into ctx.rows: the header checked, each
 * data line split into its 13 fields and validated (main.c says what each
 * may hold), datasets and variants interned; errors as "FILE:LINE: what"
 * into ctx.err.  Also the error and memory helpers every file uses.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench/buckets.h"
#include "summarize.h"

#define NFIELDS 13

static const char *const csv_header =
    "dataset,n,vertex,degree,on_hull,variant,us,tets_created,link_us,"
    "locate_us,conflict_us,sew_us,match";

static const char *const phase_name[NPHASES] = {"link", "locate", "conflict", "sew"};

/* ---- errors and memory ---------------------------------------------------- */

int fail(ctx *c, const char *fmt, ...)
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
/* ---- CSV parsing -------------------------------------------------------------- */

/* Reads one line into *buf (without the newline or a trailing CR).
 * Returns 1 on a line, 0 at end of file, -1 on a read error. */
int read_line(FILE *f, char **buf, size_t *cap)
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

int load_csv(ctx *c, size_t file)
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
