/*
 * readers.c -- the .ply and .obj point readers (readers.h).
 *
 * Owns: a buffered byte source that counts lines and bytes (for the
 * messages), the PLY header model (elements, their properties, the
 * numeric types), the PLY body readers (ascii, binary little and big
 * endian) and the OBJ reader.
 *
 * Invariants:
 *  - Nothing is allocated from a count read in a header before that count
 *    has been checked against the bytes the stream has left (when it can
 *    tell: files and memory streams; a pipe cannot, and its points are then
 *    grown as they are read).
 *  - Every error message starts with the file's name and the line ("f:12:")
 *    of a text part or the byte offset ("f: byte 1234:") of a binary one.
 *  - Coordinates are checked for NaN and infinity; other properties are
 *    skipped unread except for the counts of lists, which give their size.
 *  - The weighted reader also reads the vertex property `weight` or
 *    `radius` (weight = radius^2): NaN, infinite, a negative radius or
 *    one whose square overflows are errors naming the vertex.  The
 *    unweighted reader leaves such a property unread, as any other.
 */
#define _POSIX_C_SOURCE 200809L

#include "readers.h"
#include "msg.h"
#include "tokens.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

/* Vertex indices are uint32 and UINT32_MAX is the "no vertex" sentinel.  */
#define MAX_POINTS ((uint64_t)UINT32_MAX - 1)
#define MAX_LINE ((size_t)1 << 20)     /* longer text lines are refused */
#define MAX_ELEMENTS 64
#define MAX_PROPS 256
#define MAX_NAME 64


dd_format dd_format_of(const char *path)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (dot == NULL || (slash != NULL && dot < slash)) return DD_FORMAT_XYZ;
    if (!strcasecmp(dot, ".off")) return DD_FORMAT_OFF;
    if (!strcasecmp(dot, ".ply")) return DD_FORMAT_PLY;
    if (!strcasecmp(dot, ".obj")) return DD_FORMAT_OBJ;
    if (!strcasecmp(dot, ".xyzw")) return DD_FORMAT_XYZW;
    if (!strcasecmp(dot, ".xyzr")) return DD_FORMAT_XYZR;
    return DD_FORMAT_XYZ;
}

/* ---- a buffered source that counts ------------------------------------ */

typedef struct src {
    FILE *f;
    const char *name;
    size_t pos, len;
    uint64_t off;              /* bytes consumed */
    unsigned long lineno;      /* lines consumed by read_line */
    int err;                   /* a read error (errno) happened */
    char *line;                /* read_line's buffer */
    size_t cap, llen;
    unsigned char buf[1 << 16];
} src;

/* Bytes the stream has left from here, or -1 when it cannot tell (a
 * pipe).  Called before anything is read.                               */
static int64_t bytes_left(FILE *f)
{
    long cur = ftell(f);
    if (cur < 0 || fseek(f, 0, SEEK_END) != 0) return -1;
    long end = ftell(f);
    if (fseek(f, cur, SEEK_SET) != 0 || end < cur) return -1;
    return (int64_t)(end - cur);
}

static int fill(src *s)
{
    if (s->pos < s->len) return 1;
    s->pos = 0;
    errno = 0;
    s->len = fread(s->buf, 1, sizeof s->buf, s->f);
    if (s->len == 0 && ferror(s->f)) s->err = errno ? errno : EIO;
    return s->len > 0;
}

/* Copies up to n bytes to out; returns how many there were. */
static size_t read_bytes(src *s, void *out, size_t n)
{
    size_t got = 0;
    while (got < n && fill(s)) {
        size_t k = s->len - s->pos;
        if (k > n - got) k = n - got;
        if (out) memcpy((unsigned char *)out + got, s->buf + s->pos, k);
        s->pos += k;
        got += k;
    }
    s->off += got;
    return got;
}

/* Reads the next line (without its '\n') into s->line.  1: a line; 0:
 * end of file; -1: too long; -2: a NUL byte in it.  A read error shows
 * in s->err.                                                             */
static int read_line(src *s)
{
    size_t k = 0;
    int any = 0, nul = 0;
    for (;;) {
        if (!fill(s)) break;
        any = 1;
        unsigned char *b = s->buf + s->pos, *e = memchr(b, '\n', s->len - s->pos);
        size_t n = e ? (size_t)(e - b) : s->len - s->pos;
        if (k + n >= MAX_LINE) return -1;
        if (k + n + 1 > s->cap) {
            size_t cap = s->cap ? s->cap : 256;
            while (cap < k + n + 1) cap *= 2;
            char *l = realloc(s->line, cap);
            if (l == NULL) return -1;
            s->line = l;
            s->cap = cap;
        }
        memcpy(s->line + k, b, n);
        if (memchr(b, '\0', n)) nul = 1;
        k += n;
        s->pos += n + (e != NULL);
        s->off += n + (e != NULL);
        if (e) break;
    }
    if (!any) return 0;
    s->lineno++;
    if (s->line == NULL) {                     /* an empty last line */
        s->line = malloc(1);
        if (s->line == NULL) return -1;
        s->cap = 1;
    }
    s->line[k] = '\0';
    s->llen = k;
    return nul ? -2 : 1;
}

static src *src_open(FILE *f, const char *name)
{
    src *s = calloc(1, sizeof *s);
    if (s) {
        s->f = f;
        s->name = name;
    }
    return s;
}

static void src_close(src *s)
{
    if (s) free(s->line);
    free(s);
}

/* The status and message of a failed read_line (or of a read error). */
static dd_status line_error(const src *s, int rc, char *msg, size_t msglen)
{
    if (s->err) {
        set_msg(msg, msglen, "error reading '%s': %s", s->name, strerror(s->err));
        return DD_ERR_IO;
    }
    if (rc == -2) {
        set_msg(msg, msglen, "%s:%lu: line contains a NUL byte (binary data in a text part?)", s->name,
                s->lineno);
        return DD_ERR_PARSE;
    }
    set_msg(msg, msglen, "%s:%lu: line longer than %zu bytes (or out of memory)", s->name, s->lineno + 1,
            MAX_LINE);
    return DD_ERR_PARSE;
}

/* ---- points ---------------------------------------------------------- */

typedef struct points {
    double *xyz;
    double *w;                 /* weights, when `weighted` */
    uint64_t n, cap;
    int weighted;
} points;

/* Bytes of physical memory, or UINT64_MAX when the system cannot tell. */
static uint64_t physical_memory(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || size <= 0) return UINT64_MAX;
    return (uint64_t)pages * (uint64_t)size;
}

/* Room for cap points.  Refused (DD_ERR_NOMEM) beyond the machine's
 * physical memory, where malloc may still succeed (overcommit) and the
 * reading would end in the OOM killer.                                   */
static dd_status reserve_points(points *p, uint64_t cap, const char *where, char *msg, size_t msglen)
{
    if (cap <= p->cap) return DD_OK;
    uint64_t mem = physical_memory();
    if (cap > mem / (3 * sizeof *p->xyz)) {
        set_msg(msg, msglen, "%s: %llu points need %.1f GB, more than this machine's memory (%.1f GB)", where,
                (unsigned long long)cap, 24e-9 * (double)cap, 1e-9 * (double)mem);
        return DD_ERR_NOMEM;
    }
    double *x = cap > SIZE_MAX / 24 ? NULL : realloc(p->xyz, 3 * (size_t)cap * sizeof *x);
    if (x != NULL) p->xyz = x;
    double *w = x == NULL || !p->weighted ? NULL : realloc(p->w, (size_t)cap * sizeof *w);
    if (w != NULL) p->w = w;
    if (x == NULL || (p->weighted && w == NULL)) {
        set_msg(msg, msglen, "%s: out of memory for %llu points", where, (unsigned long long)cap);
        return DD_ERR_NOMEM;
    }
    p->cap = cap;
    return DD_OK;
}

/* Hands the points over (never NULL; the weights when read, else
 * NULL) or frees them on failure.                                        */
static dd_status finish_points(points *p, dd_status st, const char *name, double **xyz, double **w,
                               uint32_t *np, char *msg, size_t msglen)
{
    if (st == DD_OK && (p->xyz == NULL || (p->weighted && p->w == NULL)))
        st = reserve_points(p, p->cap ? p->cap : 1, name, msg, msglen);
    if (st != DD_OK) {
        free(p->xyz);
        free(p->w);
        return st;
    }
    *xyz = p->xyz;
    if (w != NULL) *w = p->w;
    else free(p->w);
    *np = (uint32_t)p->n;
    return DD_OK;
}

/* A vertex's weight value v (the `radius` property when is_radius) made
 * a weight in *w: NaN, infinity, a negative radius and a radius whose
 * square overflows are refused.                                          */
static dd_status check_weight(double v, int is_radius, const char *where, uint64_t vertex, double *w, char *msg,
                              size_t msglen)
{
    const char *what = is_radius ? "radius" : "weight";
    if (isnan(v)) {
        set_msg(msg, msglen, "%s: vertex %llu: %s is NaN", where, (unsigned long long)vertex, what);
        return DD_ERR_NAN;
    }
    if (isinf(v) || (is_radius && isinf(v * v))) {
        set_msg(msg, msglen, "%s: vertex %llu: %s is infinite%s", where, (unsigned long long)vertex, what,
                isinf(v) ? "" : " (its square overflows)");
        return DD_ERR_INFINITE;
    }
    if (is_radius && v < 0) {
        set_msg(msg, msglen, "%s: vertex %llu: negative radius %.17g", where, (unsigned long long)vertex, v);
        return DD_ERR_PARSE;
    }
    *w = is_radius ? v * v : v;
    return DD_OK;
}

/* Appends the point v (v[3] its weight when p is weighted, already
 * checked), growing the arrays geometrically.                            */
static dd_status push_vertex(points *p, const double v[4], const char *where, char *msg, size_t msglen)
{
    if (p->n == p->cap) {
        dd_status st = reserve_points(p, p->cap ? 2 * p->cap : 1024, where, msg, msglen);
        if (st != DD_OK) return st;
    }
    memcpy(p->xyz + 3 * p->n, v, 3 * sizeof *v);
    if (p->weighted) p->w[p->n] = v[3];
    p->n++;
    return DD_OK;
}

/* NaN / infinity in coordinate c ("xyz"[c]); `where` is "f:12" or
 * "f: byte 40".                                                          */
static dd_status check_finite(double v, int c, const char *where, uint64_t vertex, char *msg, size_t msglen)
{
    if (isnan(v)) {
        set_msg(msg, msglen, "%s: vertex %llu: coordinate %c is NaN", where, (unsigned long long)vertex, "xyz"[c]);
        return DD_ERR_NAN;
    }
    if (isinf(v)) {
        set_msg(msg, msglen, "%s: vertex %llu: coordinate %c is infinite", where, (unsigned long long)vertex,
                "xyz"[c]);
        return DD_ERR_INFINITE;
    }
    return DD_OK;
}

/* ---- text tokens (and tokens.h) ----------------------------------------- */

/* The next token of p copied to out (at most len - 1 chars); advances. */
static size_t take_word(const char **pp, char *out, size_t len)
{
    const char *p = skip_blank(*pp);
    size_t n = 0;
    while (!ends_token(p[n])) n++;
    size_t k = n < len - 1 ? n : len - 1;
    memcpy(out, p, k);
    out[k] = '\0';
    *pp = p + n;
    return n;
}

/* ---- PLY: the header ----------------------------------------------------- */

typedef enum { T_I8, T_U8, T_I16, T_U16, T_I32, T_U32, T_F32, T_F64, T_NONE } ply_type;

static const struct { const char *name; ply_type type; } type_names[] = {
    {"char", T_I8},    {"int8", T_I8},     {"uchar", T_U8},    {"uint8", T_U8},
    {"short", T_I16},  {"int16", T_I16},   {"ushort", T_U16},  {"uint16", T_U16},
    {"int", T_I32},    {"int32", T_I32},   {"uint", T_U32},    {"uint32", T_U32},
    {"float", T_F32},  {"float32", T_F32}, {"double", T_F64},  {"float64", T_F64},
};
static const unsigned type_size[] = {1, 1, 2, 2, 4, 4, 4, 8};

static ply_type type_of(const char *name)
{
    for (size_t i = 0; i < sizeof type_names / sizeof *type_names; i++)
        if (!strcmp(type_names[i].name, name)) return type_names[i].type;
    return T_NONE;
}

typedef struct ply_prop {
    char name[MAX_NAME];
    ply_type type;             /* the value's, or the items' for a list */
    ply_type count_type;       /* T_NONE unless a list */
} ply_prop;

typedef struct ply_elem {
    char name[MAX_NAME];
    uint64_t count;
    unsigned long line;        /* of its header line */
    ply_prop props[MAX_PROPS];
    size_t nprops;
} ply_elem;

enum { PLY_ASCII, PLY_LE, PLY_BE };

typedef struct ply {
    src *s;
    int format;
    ply_elem *elems;           /* MAX_ELEMENTS of them */
    size_t nelems;
    long vertex;               /* index of the vertex element, or -1 */
    int coord[4];              /* its properties x, y, z, and weight or
                                  radius (-1: none, or not read)       */
    int want_weight;           /* read `weight` or `radius`            */
    int radius;                /* coord[3] is `radius`                 */
} ply;

/* Parses the header up to and including end_header. */
static dd_status ply_header(ply *p, char *msg, size_t msglen)
{
    src *s = p->s;
    const char *name = s->name;
    char word[MAX_NAME + 8];
    int rc = read_line(s);
    if (rc < 0 || (rc == 0 && s->err)) return line_error(s, rc, msg, msglen);
    const char *q = s->line;
    if (rc == 0 || take_word(&q, word, sizeof word) != 3 || strcmp(word, "ply") || *skip_blank(q)) {
        set_msg(msg, msglen, "%s:1: expected 'ply' on the first line (not a PLY file)", name);
        return DD_ERR_PARSE;
    }
    int have_format = 0;
    p->vertex = -1;
    for (;;) {
        rc = read_line(s);
        if (rc < 0 || s->err) return line_error(s, rc, msg, msglen);
        if (rc == 0) {
            set_msg(msg, msglen, "%s:%lu: the file ends inside the header (no 'end_header')", name, s->lineno);
            return DD_ERR_PARSE;
        }
        const char *l = s->line;
        unsigned long ln = s->lineno;
        size_t wl = take_word(&l, word, sizeof word);
        if (wl == 0) continue;                                 /* a blank line */
        if (!strcmp(word, "comment") || !strcmp(word, "obj_info")) continue;
        if (!strcmp(word, "end_header")) break;
        if (!strcmp(word, "format")) {
            char fmt[32], ver[32];
            take_word(&l, fmt, sizeof fmt);
            take_word(&l, ver, sizeof ver);
            if (have_format || p->nelems) {
                set_msg(msg, msglen, "%s:%lu: 'format' must come once, before the elements", name, ln);
                return DD_ERR_PARSE;
            }
            if (!strcmp(fmt, "ascii")) p->format = PLY_ASCII;
            else if (!strcmp(fmt, "binary_little_endian")) p->format = PLY_LE;
            else if (!strcmp(fmt, "binary_big_endian")) p->format = PLY_BE;
            else {
                set_msg(msg, msglen, "%s:%lu: unknown format '%s' (ascii, binary_little_endian, "
                        "binary_big_endian)", name, ln, fmt);
                return DD_ERR_PARSE;
            }
            if (strcmp(ver, "1.0") && strcmp(ver, "1")) {
                set_msg(msg, msglen, "%s:%lu: unsupported PLY version '%s' (1.0)", name, ln, ver);
                return DD_ERR_PARSE;
            }
            if (*skip_blank(l)) {
                set_msg(msg, msglen, "%s:%lu: extra words after 'format %s %s'", name, ln, fmt, ver);
                return DD_ERR_PARSE;
            }
            have_format = 1;
            continue;
        }
        if (!have_format) {
            set_msg(msg, msglen, "%s:%lu: expected 'format ...' before '%s'", name, ln, word);
            return DD_ERR_PARSE;
        }
        if (!strcmp(word, "element")) {
            if (p->nelems == MAX_ELEMENTS) {
                set_msg(msg, msglen, "%s:%lu: more than %d elements", name, ln, MAX_ELEMENTS);
                return DD_ERR_PARSE;
            }
            ply_elem *e = &p->elems[p->nelems];
            memset(e, 0, sizeof *e);
            e->line = ln;
            size_t n = take_word(&l, e->name, sizeof e->name);
            if (n == 0 || n >= MAX_NAME || !parse_count_tok(&l, &e->count, 1) || *skip_blank(l)) {
                set_msg(msg, msglen, "%s:%lu: expected 'element NAME COUNT' (a name of at most %d characters, "
                        "a non-negative integer count)", name, ln, MAX_NAME - 1);
                return DD_ERR_PARSE;
            }
            if (!strcmp(e->name, "vertex")) {
                if (p->vertex >= 0) {
                    set_msg(msg, msglen, "%s:%lu: a second 'vertex' element", name, ln);
                    return DD_ERR_PARSE;
                }
                p->vertex = (long)p->nelems;
            }
            p->nelems++;
            continue;
        }
        if (!strcmp(word, "property")) {
            if (p->nelems == 0) {
                set_msg(msg, msglen, "%s:%lu: 'property' before any 'element'", name, ln);
                return DD_ERR_PARSE;
            }
            ply_elem *e = &p->elems[p->nelems - 1];
            if (e->nprops == MAX_PROPS) {
                set_msg(msg, msglen, "%s:%lu: element '%s' has more than %d properties", name, ln, e->name,
                        MAX_PROPS);
                return DD_ERR_PARSE;
            }
            ply_prop *pr = &e->props[e->nprops];
            char t[32];
            take_word(&l, t, sizeof t);
            pr->count_type = T_NONE;
            if (!strcmp(t, "list")) {
                char ct[32];
                take_word(&l, ct, sizeof ct);
                pr->count_type = type_of(ct);
                if (pr->count_type == T_NONE || pr->count_type == T_F32 || pr->count_type == T_F64) {
                    set_msg(msg, msglen, "%s:%lu: a list's count type must be an integer type, got '%s'", name,
                            ln, ct);
                    return DD_ERR_PARSE;
                }
                take_word(&l, t, sizeof t);
            }
            pr->type = type_of(t);
            if (pr->type == T_NONE) {
                set_msg(msg, msglen, "%s:%lu: unknown property type '%s'", name, ln, t);
                return DD_ERR_PARSE;
            }
            size_t n = take_word(&l, pr->name, sizeof pr->name);
            if (n == 0 || n >= MAX_NAME || *skip_blank(l)) {
                set_msg(msg, msglen, "%s:%lu: expected 'property TYPE NAME' or 'property list COUNT_TYPE "
                        "TYPE NAME'", name, ln);
                return DD_ERR_PARSE;
            }
            for (size_t i = 0; i < e->nprops; i++)
                if (!strcmp(e->props[i].name, pr->name)) {
                    set_msg(msg, msglen, "%s:%lu: element '%s' has two properties '%s'", name, ln, e->name,
                            pr->name);
                    return DD_ERR_PARSE;
                }
            e->nprops++;
            continue;
        }
        set_msg(msg, msglen, "%s:%lu: unknown header keyword '%s'", name, ln, word);
        return DD_ERR_PARSE;
    }
    if (!have_format) {
        set_msg(msg, msglen, "%s:%lu: 'end_header' before 'format'", name, s->lineno);
        return DD_ERR_PARSE;
    }
    if (p->vertex < 0) {
        set_msg(msg, msglen, "%s:%lu: no 'vertex' element in the header", name, s->lineno);
        return DD_ERR_PARSE;
    }
    ply_elem *v = &p->elems[p->vertex];
    for (int c = 0; c < 3; c++) {
        const char cn[2] = {"xyz"[c], '\0'};
        p->coord[c] = -1;
        for (size_t i = 0; i < v->nprops; i++)
            if (!strcmp(v->props[i].name, cn)) p->coord[c] = (int)i;
        if (p->coord[c] < 0 || v->props[p->coord[c]].count_type != T_NONE) {
            set_msg(msg, msglen, "%s:%lu: element 'vertex' has no %sproperty '%s'", name, v->line,
                    p->coord[c] < 0 ? "" : "scalar ", cn);
            return DD_ERR_PARSE;
        }
    }
    p->coord[3] = -1;
    for (size_t i = 0; p->want_weight && i < v->nprops; i++) {
        const int r = !strcmp(v->props[i].name, "radius");
        if (!r && strcmp(v->props[i].name, "weight")) continue;
        if (p->coord[3] >= 0) {
            set_msg(msg, msglen, "%s:%lu: element 'vertex' has both 'weight' and 'radius'", name, v->line);
            return DD_ERR_PARSE;
        }
        if (v->props[i].count_type != T_NONE) {
            set_msg(msg, msglen, "%s:%lu: property '%s' of 'vertex' must be a scalar, not a list", name, v->line,
                    v->props[i].name);
            return DD_ERR_PARSE;
        }
        p->coord[3] = (int)i;
        p->radius = r;
    }
    if (v->count > MAX_POINTS) {
        set_msg(msg, msglen, "%s:%lu: %llu vertices: more than %llu", name, v->line,
                (unsigned long long)v->count, (unsigned long long)MAX_POINTS);
        return DD_ERR_PARSE;
    }
    return DD_OK;
}

/* The fewest body bytes the header's counts need: each value at least its
 * size (binary) or one character and a separator (ascii); an empty list
 * only its count.  UINT64_MAX on overflow.                               */
static uint64_t ply_min_body(const ply *p)
{
    uint64_t total = 0;
    for (size_t i = 0; i < p->nelems; i++) {
        const ply_elem *e = &p->elems[i];
        uint64_t per = 0;
        for (size_t k = 0; k < e->nprops; k++) {
            const ply_prop *pr = &e->props[k];
            per += p->format == PLY_ASCII ? 2 : type_size[pr->count_type != T_NONE ? pr->count_type : pr->type];
        }
        if (per != 0 && e->count > (UINT64_MAX - total) / per) return UINT64_MAX;
        total += per * e->count;
    }
    return total;
}

/* ---- PLY: binary bodies -------------------------------------------------- */

/* Decodes one value of type t from b (the file's byte order). */
static double decode(const unsigned char *b, ply_type t, int big)
{
    unsigned n = type_size[t];
    uint64_t u = 0;
    for (unsigned i = 0; i < n; i++) u |= (uint64_t)b[big ? n - 1 - i : i] << (8 * i);
    switch (t) {
    case T_I8: return (double)(int8_t)u;
    case T_U8: return (double)(uint8_t)u;
    case T_I16: return (double)(int16_t)u;
    case T_U16: return (double)(uint16_t)u;
    case T_I32: return (double)(int32_t)u;
    case T_U32: return (double)(uint32_t)u;
    case T_F32: { uint32_t w = (uint32_t)u; float f; memcpy(&f, &w, 4); return (double)f; }
    case T_F64: { double d; memcpy(&d, &u, 8); return d; }
    default: return 0;
    }
}

static dd_status truncated(const ply *p, const ply_elem *e, uint64_t i, char *msg, size_t msglen)
{
    if (p->s->err) {
        set_msg(msg, msglen, "error reading '%s': %s", p->s->name, strerror(p->s->err));
        return DD_ERR_IO;
    }
    set_msg(msg, msglen, "%s: byte %llu: the file ends in element '%s' %llu of %llu (a truncated body, or "
            "a header count larger than the data)", p->s->name, (unsigned long long)p->s->off, e->name,
            (unsigned long long)i, (unsigned long long)e->count);
    return DD_ERR_PARSE;
}

/* Reads (or skips) the instances of element e; the vertex element's
 * coordinates go to pts.                                                 */
static dd_status ply_binary_elem(ply *p, const ply_elem *e, int is_vertex, points *pts, char *msg, size_t msglen)
{
    src *s = p->s;
    int big = p->format == PLY_BE;
    unsigned char b[8];
    if (e->nprops == 0) return DD_OK;
    for (uint64_t i = 0; i < e->count; i++) {
        double v[4] = {0, 0, 0, 0};
        uint64_t at[4] = {0, 0, 0, 0};
        for (size_t k = 0; k < e->nprops; k++) {
            const ply_prop *pr = &e->props[k];
            if (pr->count_type != T_NONE) {
                uint64_t start = s->off;
                if (read_bytes(s, b, type_size[pr->count_type]) != type_size[pr->count_type])
                    return truncated(p, e, i, msg, msglen);
                double c = decode(b, pr->count_type, big);
                if (c < 0) {
                    set_msg(msg, msglen, "%s: byte %llu: element '%s' %llu: list '%s' has a negative count "
                            "%.0f", s->name, (unsigned long long)start, e->name, (unsigned long long)i,
                            pr->name, c);
                    return DD_ERR_PARSE;
                }
                uint64_t skip = (uint64_t)c * type_size[pr->type];
                if (read_bytes(s, NULL, skip) != skip) return truncated(p, e, i, msg, msglen);
                continue;
            }
            int c = -1;
            if (is_vertex)
                for (int j = 0; j < 4; j++)
                    if (p->coord[j] == (int)k) c = j;
            uint64_t start = s->off;
            if (read_bytes(s, c >= 0 ? b : NULL, type_size[pr->type]) != type_size[pr->type])
                return truncated(p, e, i, msg, msglen);
            if (c >= 0) {
                v[c] = decode(b, pr->type, big);
                at[c] = start;
            }
        }
        if (!is_vertex) continue;
        char where[600];
        for (int c = 0; c < 4; c++) {
            if (c == 3 && p->coord[3] < 0) break;
            snprintf(where, sizeof where, "%s: byte %llu", s->name, (unsigned long long)at[c]);
            dd_status st = c < 3 ? check_finite(v[c], c, where, i, msg, msglen)
                                 : check_weight(v[3], p->radius, where, i, &v[3], msg, msglen);
            if (st != DD_OK) return st;
        }
        snprintf(where, sizeof where, "%s: byte %llu", s->name, (unsigned long long)s->off);
        dd_status st = push_vertex(pts, v, where, msg, msglen);
        if (st != DD_OK) return st;
    }
    return DD_OK;
}

/* ---- PLY: ascii bodies --------------------------------------------------- */

/* The next line with content (blank lines skipped). */
static dd_status ascii_next(src *s, const ply_elem *e, uint64_t i, char *msg, size_t msglen)
{
    for (;;) {
        int rc = read_line(s);
        if (rc < 0 || s->err) return line_error(s, rc, msg, msglen);
        if (rc == 0) {
            set_msg(msg, msglen, "%s:%lu: the file ends before element '%s' %llu of %llu (a header count "
                    "larger than the data)", s->name, s->lineno, e->name, (unsigned long long)i,
                    (unsigned long long)e->count);
            return DD_ERR_PARSE;
        }
        if (*skip_blank(s->line)) return DD_OK;
    }
}

static dd_status ply_ascii_elem(ply *p, const ply_elem *e, int is_vertex, points *pts, char *msg, size_t msglen)
{
    src *s = p->s;
    if (e->nprops == 0) return DD_OK;
    for (uint64_t i = 0; i < e->count; i++) {
        dd_status st = ascii_next(s, e, i, msg, msglen);
        if (st != DD_OK) return st;
        const char *l = s->line;
        double v[4] = {0, 0, 0, 0};
        for (size_t k = 0; k < e->nprops; k++) {
            const ply_prop *pr = &e->props[k];
            double x;
            if (pr->count_type != T_NONE) {
                uint64_t n;
                if (!parse_count_tok(&l, &n, 1)) {
                    set_msg(msg, msglen, "%s:%lu: element '%s' %llu: expected the count of list '%s' (a "
                            "non-negative integer)", s->name, s->lineno, e->name, (unsigned long long)i,
                            pr->name);
                    return DD_ERR_PARSE;
                }
                for (uint64_t j = 0; j < n; j++)
                    if (!parse_number(&l, &x)) {
                        set_msg(msg, msglen, "%s:%lu: element '%s' %llu: list '%s' has %llu items, the line "
                                "ends or has a non-number after %llu", s->name, s->lineno, e->name,
                                (unsigned long long)i, pr->name, (unsigned long long)n, (unsigned long long)j);
                        return DD_ERR_PARSE;
                    }
                continue;
            }
            if (!parse_number(&l, &x)) {
                set_msg(msg, msglen, "%s:%lu: element '%s' %llu: expected %zu values (property '%s' missing or "
                        "not a number)", s->name, s->lineno, e->name, (unsigned long long)i, e->nprops,
                        pr->name);
                return DD_ERR_PARSE;
            }
            if (is_vertex)
                for (int c = 0; c < 4; c++)
                    if (p->coord[c] == (int)k) v[c] = x;
        }
        if (*skip_blank(l)) {
            set_msg(msg, msglen, "%s:%lu: element '%s' %llu: more values than its %zu properties", s->name,
                    s->lineno, e->name, (unsigned long long)i, e->nprops);
            return DD_ERR_PARSE;
        }
        if (!is_vertex) continue;
        char where[600];
        snprintf(where, sizeof where, "%s:%lu", s->name, s->lineno);
        for (int c = 0; c < 3; c++) {
            st = check_finite(v[c], c, where, i, msg, msglen);
            if (st != DD_OK) return st;
        }
        if (p->coord[3] >= 0) st = check_weight(v[3], p->radius, where, i, &v[3], msg, msglen);
        if (st == DD_OK) st = push_vertex(pts, v, where, msg, msglen);
        if (st != DD_OK) return st;
    }
    return DD_OK;
}

/* ---- PLY ------------------------------------------------------------------- */

dd_status dd_read_ply(FILE *f, const char *name, double **xyz, uint32_t *np, char *msg, size_t msglen)
{
    return dd_read_ply_weighted(f, name, xyz, NULL, np, msg, msglen);
}

dd_status dd_read_ply_weighted(FILE *f, const char *name, double **xyz, double **w, uint32_t *np, char *msg,
                               size_t msglen)
{
    *xyz = NULL;
    if (w != NULL) *w = NULL;
    *np = 0;
    int64_t size = bytes_left(f);
    src *s = src_open(f, name);
    ply p;
    memset(&p, 0, sizeof p);
    p.elems = malloc(MAX_ELEMENTS * sizeof *p.elems);
    p.want_weight = w != NULL;
    points pts = {NULL, NULL, 0, 0, 0};
    dd_status st = DD_OK;
    if (s == NULL || p.elems == NULL) {
        set_msg(msg, msglen, "out of memory reading '%s'", name);
        st = DD_ERR_NOMEM;
        goto done;
    }
    p.s = s;
    st = ply_header(&p, msg, msglen);
    if (st != DD_OK) goto done;
    pts.weighted = p.coord[3] >= 0;

    /* the counts against the bytes left, before allocating for them */
    const ply_elem *ve = &p.elems[p.vertex];
    uint64_t need = ply_min_body(&p);
    char where[600];
    snprintf(where, sizeof where, "%s:%lu", name, ve->line);
    if (size >= 0) {
        uint64_t body = (uint64_t)size - s->off;
        if (need > body) {
            set_msg(msg, msglen, "%s:%lu: the header's counts (%llu vertices%s) need at least %llu bytes of data, "
                    "the file has %llu after the header (byte %llu on): truncated, or the counts lie", name,
                    ve->line, (unsigned long long)ve->count, p.nelems > 1 ? " and other elements" : "",
                    (unsigned long long)need, (unsigned long long)body, (unsigned long long)s->off);
            st = DD_ERR_PARSE;
            goto done;
        }
        st = reserve_points(&pts, ve->count, where, msg, msglen);
    } else {
        st = reserve_points(&pts, ve->count < 65536 ? ve->count : 65536, where, msg, msglen);
    }
    if (st != DD_OK) goto done;

    for (size_t i = 0; i < p.nelems && st == DD_OK; i++)
        st = p.format == PLY_ASCII ? ply_ascii_elem(&p, &p.elems[i], (long)i == p.vertex, &pts, msg, msglen)
                                   : ply_binary_elem(&p, &p.elems[i], (long)i == p.vertex, &pts, msg, msglen);
    if (st != DD_OK) goto done;

    /* nothing may follow the last element: the counts would have lied */
    if (p.format == PLY_ASCII) {
        int rc;
        while ((rc = read_line(s)) == 1 && !*skip_blank(s->line)) {}
        if (rc < 0 || s->err) st = line_error(s, rc, msg, msglen);
        else if (rc == 1) {
            set_msg(msg, msglen, "%s:%lu: data after the last element (the header's counts are smaller than "
                    "the data)", name, s->lineno);
            st = DD_ERR_PARSE;
        }
    } else {
        uint64_t at = s->off;
        unsigned char b;
        if (read_bytes(s, &b, 1) == 1) {
            uint64_t extra = size >= 0 ? (uint64_t)size - at : 1;
            set_msg(msg, msglen, "%s: byte %llu: %llu byte%s after the last element (the header's counts are "
                    "smaller than the data)", name, (unsigned long long)at, (unsigned long long)extra,
                    extra == 1 ? "" : "s");
            st = DD_ERR_PARSE;
        } else if (s->err) {
            set_msg(msg, msglen, "error reading '%s': %s", name, strerror(s->err));
            st = DD_ERR_IO;
        }
    }
done:
    free(p.elems);
    src_close(s);
    return finish_points(&pts, st, name, xyz, w, np, msg, msglen);
}

/* ---- OBJ ---------------------------------------------------------------------- */

dd_status dd_read_obj(FILE *f, const char *name, double **xyz, uint32_t *np, char *msg, size_t msglen)
{
    *xyz = NULL;
    *np = 0;
    src *s = src_open(f, name);
    points pts = {NULL, NULL, 0, 0, 0};
    dd_status st = DD_OK;
    if (s == NULL) {
        set_msg(msg, msglen, "out of memory reading '%s'", name);
        return DD_ERR_NOMEM;
    }
    for (;;) {
        int rc = read_line(s);
        if (rc < 0 || s->err) {
            st = line_error(s, rc, msg, msglen);
            break;
        }
        if (rc == 0) break;
        const char *l = skip_blank(s->line);
        if (l[0] != 'v' || !ends_token(l[1])) continue;       /* not a vertex line */
        l++;
        double v[3], extra;
        if (!parse_number(&l, &v[0]) || !parse_number(&l, &v[1]) || !parse_number(&l, &v[2])) {
            set_msg(msg, msglen, "%s:%lu: expected a vertex 'v x y z [w]'", name, s->lineno);
            st = DD_ERR_PARSE;
            break;
        }
        while (parse_number(&l, &extra)) {}
        l = skip_blank(l);
        if (*l && *l != '#') {
            set_msg(msg, msglen, "%s:%lu: a vertex line with a non-number after 'v x y z'", name, s->lineno);
            st = DD_ERR_PARSE;
            break;
        }
        char where[600];
        snprintf(where, sizeof where, "%s:%lu", name, s->lineno);
        for (int c = 0; c < 3 && st == DD_OK; c++) st = check_finite(v[c], c, where, pts.n, msg, msglen);
        if (st != DD_OK) break;
        if (pts.n == MAX_POINTS) {
            set_msg(msg, msglen, "%s:%lu: more than %llu vertices", name, s->lineno,
                    (unsigned long long)MAX_POINTS);
            st = DD_ERR_PARSE;
            break;
        }
        if (pts.n == pts.cap) {
            st = reserve_points(&pts, pts.cap ? 2 * pts.cap : 1024, where, msg, msglen);
            if (st != DD_OK) break;
        }
        memcpy(pts.xyz + 3 * pts.n++, v, sizeof v);
    }
    src_close(s);
    return finish_points(&pts, st, name, xyz, NULL, np, msg, msglen);
}
