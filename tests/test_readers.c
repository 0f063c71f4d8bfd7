/*
 * test_readers.c -- the .ply and .obj readers (datasets/readers.c).
 *
 * Real models written in every format and read back: the bunny's points
 * as .xyz, ascii .ply, binary little- and big-endian .ply (with extra
 * properties, list properties and face elements before and after the
 * vertices, which must be skipped) and .obj (with normals, texture
 * coordinates, faces, groups and a w); each read gives the same doubles,
 * and DT of them equals CGAL's.  Coordinates of every PLY numeric type.
 * Then bad input: each gets its exact status and a message naming the
 * file and the line (text) or byte offset (binary).
 */
#include "testlib.h"
#include "dtdel.h"
#include "cgal/cgal_shim.h"
#include "../datasets/datasets.h"
#include "../datasets/readers.h"

#include <math.h>
#include <unistd.h>

static char dir[64];

static void path_of(char *out, size_t len, const char *file) { snprintf(out, len, "%s/%s", dir, file); }

static int write_file(const char *file, const void *data, size_t n)
{
    char p[256];
    path_of(p, sizeof p, file);
    FILE *f = fopen(p, "wb");
    if (!f) return -1;
    size_t w = fwrite(data, 1, n, f);
    return fclose(f) == 0 && w == n ? 0 : -1;
}

/* ---- a growing byte buffer, written little- or big-endian --------------- */

typedef struct buf { unsigned char *b; size_t n, cap; } buf;

static void put(buf *b, const void *p, size_t n)
{
    if (b->n + n > b->cap) {
        b->cap = 2 * (b->n + n) + 256;
        b->b = realloc(b->b, b->cap);
        if (!b->b) abort();
    }
    memcpy(b->b + b->n, p, n);
    b->n += n;
}

static void puts_(buf *b, const char *s) { put(b, s, strlen(s)); }

__attribute__((format(printf, 2, 3)))
static void putf(buf *b, const char *fmt, ...)
{
    char s[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(s, sizeof s, fmt, ap);
    va_end(ap);
    puts_(b, s);
}

/* n bytes of v, in the byte order `big` (the host is little-endian: x86). */
static void put_ord(buf *b, const void *v, size_t n, int big)
{
    unsigned char t[8];
    memcpy(t, v, n);
    if (big)
        for (size_t i = 0; i < n / 2; i++) {
            unsigned char x = t[i];
            t[i] = t[n - 1 - i];
            t[n - 1 - i] = x;
        }
    put(b, t, n);
}
static void put_f64(buf *b, double v, int big) { put_ord(b, &v, 8, big); }
static void put_f32(buf *b, float v, int big) { put_ord(b, &v, 4, big); }
static void put_i32(buf *b, int32_t v, int big) { put_ord(b, &v, 4, big); }
static void put_i16(buf *b, int16_t v, int big) { put_ord(b, &v, 2, big); }
static void put_u8(buf *b, uint8_t v) { put(b, &v, 1); }

/* ---- the model in every format -------------------------------------------- */

/* A PLY of the points: an element "material" (2 instances) before the
 * vertices, vertex properties nx (float), x (double), red (uchar),
 * y (double), a list "idx" (uchar count, int items), z (double), w (short);
 * then 'face' (list uchar int) and 'edge' (two ints) elements.           */
static void make_ply(buf *b, const double *xyz, uint32_t n, const char *format)
{
    int ascii = !strcmp(format, "ascii"), big = !strcmp(format, "binary_big_endian");
    putf(b, "ply\r\nformat %s 1.0\ncomment the bunny, for test_readers\nobj_info nothing\n", format);
    puts_(b, "element material 2\nproperty uchar kind\nproperty list uint short colours\n");
    putf(b, "element vertex %u\nproperty float nx\nproperty double x\nproperty uchar red\n", n);
    puts_(b, "property float64 y\nproperty list uchar int idx\nproperty double z\nproperty int16 w\n");
    putf(b, "element face %u\nproperty list uint8 int32 vertex_indices\n", n / 3);
    puts_(b, "element edge 2\nproperty int a\nproperty int b\nend_header\n");
    for (int m = 0; m < 2; m++) {
        if (ascii) putf(b, "%d 2 %d %d\n", m, m + 1, -m);
        else {
            put_u8(b, (uint8_t)m);
            uint32_t two = 2;
            put_ord(b, &two, 4, big);
            put_i16(b, (int16_t)(m + 1), big);
            put_i16(b, (int16_t)-m, big);
        }
    }
    for (uint32_t i = 0; i < n; i++) {
        const double *p = xyz + 3 * (size_t)i;
        uint8_t k = (uint8_t)(i % 4);
        if (ascii) {
            putf(b, "0.25 %.17g %u %.17g %u", p[0], (unsigned)(i % 256), p[1], (unsigned)k);
            for (uint8_t j = 0; j < k; j++) putf(b, " %u", (unsigned)(i + j));
            putf(b, " %.17g -3\n", p[2]);
        } else {
            put_f32(b, 0.25f, big);
            put_f64(b, p[0], big);
            put_u8(b, (uint8_t)(i % 256));
            put_f64(b, p[1], big);
            put_u8(b, k);
            for (uint8_t j = 0; j < k; j++) put_i32(b, (int32_t)(i + j), big);
            put_f64(b, p[2], big);
            put_i16(b, -3, big);
        }
    }
    for (uint32_t f = 0; f < n / 3; f++) {
        if (ascii) putf(b, "3 %u %u %u\n", 3 * f, 3 * f + 1, 3 * f + 2);
        else {
            put_u8(b, 3);
            for (uint32_t j = 0; j < 3; j++) put_i32(b, (int32_t)(3 * f + j), big);
        }
    }
    for (int e = 0; e < 2; e++) {
        if (ascii) putf(b, "%d %d\n", e, e + 1);
        else {
            put_i32(b, e, big);
            put_i32(b, e + 1, big);
        }
    }
}

static void make_obj(buf *b, const double *xyz, uint32_t n)
{
    puts_(b, "# the bunny, for test_readers\nmtllib bunny.mtl\no bunny\ng body\n");
    for (uint32_t i = 0; i < n; i++) {
        const double *p = xyz + 3 * (size_t)i;
        if (i % 3 == 0) putf(b, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
        else if (i % 3 == 1) putf(b, "  v\t%.17g %.17g %.17g 1.0   # with w\n", p[0], p[1], p[2]);
        else putf(b, "v %.17g %.17g %.17g 0.5 0.5 0.5\n", p[0], p[1], p[2]);   /* vertex colours */
        putf(b, "vn 0 0 1\nvt 0.5 0.5\n");
    }
    puts_(b, "usemtl skin\ns 1\n");
    for (uint32_t f = 0; f + 2 < n; f += 3) putf(b, "f %u/%u/1 %u//1 %u\n", f + 1, f + 1, f + 2, f + 3);
    puts_(b, "l 1 2\nvp 0.5\n");
}

/* Reads file, compares the points with xyz bit for bit, and DT of them
 * with CGAL's.                                                          */
static void check_model_file(tl_state *st, const char *file, const double *xyz, uint32_t n)
{
    char p[256], name[160], msg[512];
    path_of(p, sizeof p, file);
    double *got = NULL;
    uint32_t np = 0;
    dd_status s = dd_read_points(p, &got, &np, msg, sizeof msg);
    snprintf(name, sizeof name, "readers/%s/read", file);
    tl_check(st, s == DD_OK && np == n, name, "status %s, %u points of %u: %s", dd_status_name(s), np, n,
             s == DD_OK ? "" : msg);
    if (s != DD_OK || np != n) { free(got); return; }
    snprintf(name, sizeof name, "readers/%s/same-points", file);
    tl_check(st, !memcmp(got, xyz, 3 * (size_t)n * sizeof *xyz), name, "the points differ from the model's");

    dd_tri *t = NULL;
    dd_cgal *c = dd_cgal_build(got, np);
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    int ok = dd_create(&t, got, np, msg, sizeof msg) == DD_OK && c && dd_canonical(t, &a, &na) == DD_OK
             && !dd_cgal_canonical(c, &b, &nb);
    snprintf(name, sizeof name, "readers/%s/tets-equal-cgal", file);
    tl_check(st, ok && na == nb && !memcmp(a, b, 4 * na * sizeof *a), name, "%zu cells vs CGAL's %zu", na, nb);
    free(a);
    free(b);
    dd_free(t);
    dd_cgal_free(c);
    free(got);
}

static void test_models(tl_state *st, uint32_t n)
{
    char msg[512];
    double *xyz = NULL;
    uint32_t np = 0;
    dd_status s = dd_gen("bunny", n, 1, &xyz, &np, msg, sizeof msg);
    tl_check(st, s == DD_OK && np >= 100, "readers/bunny-loaded", "%s", msg);
    if (s != DD_OK) return;
    static const char *const plys[][2] = {
        {"bunny-ascii.ply", "ascii"},
        {"bunny-le.ply", "binary_little_endian"},
        {"bunny-be.ply", "binary_big_endian"},
    };
    buf b = {0};
    for (size_t k = 0; k < 3; k++) {
        b.n = 0;
        make_ply(&b, xyz, np, plys[k][1]);
        write_file(plys[k][0], b.b, b.n);
        check_model_file(st, plys[k][0], xyz, np);
    }
    b.n = 0;
    make_obj(&b, xyz, np);
    write_file("bunny.obj", b.b, b.n);
    check_model_file(st, "bunny.obj", xyz, np);
    b.n = 0;
    for (uint32_t i = 0; i < np; i++) putf(&b, "%.17g %.17g %.17g\n", xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    write_file("bunny.xyz", b.b, b.n);
    check_model_file(st, "bunny.xyz", xyz, np);
    /* the extension is case-insensitive, and a stream reads the same */
    b.n = 0;
    make_ply(&b, xyz, np, "binary_little_endian");
    write_file("BUNNY.PLY", b.b, b.n);
    check_model_file(st, "BUNNY.PLY", xyz, np);
    FILE *f = fmemopen(b.b, b.n, "r");
    double *got = NULL;
    uint32_t ng = 0;
    s = f ? dd_read_points_stream(f, "memory.ply", &got, &ng, msg, sizeof msg) : DD_ERR_IO;
    if (f) fclose(f);
    tl_check(st, s == DD_OK && ng == np && !memcmp(got, xyz, 3 * (size_t)np * sizeof *xyz), "readers/stream",
             "%s, %u points", dd_status_name(s), ng);
    free(got);
    free(b.b);
    free(xyz);
}

/* Coordinates of each numeric type: the 27 points of a 3x3x3 grid plus
 * one (-1 for signed types), written with x, y, z of type `type`.       */
static void test_types(tl_state *st)
{
    static const char *const types[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                        "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32",
                                        "float64"};
    static const unsigned size[] = {1, 1, 2, 2, 4, 4, 4, 8, 1, 1, 2, 2, 4, 4, 4, 8};
    for (size_t t = 0; t < sizeof types / sizeof *types; t++) {
        for (int big = 0; big < 2; big++) {
            buf b = {0};
            double want[3 * 27];
            int flt = !strcmp(types[t], "float") || !strcmp(types[t], "float32");
            int dbl = !strcmp(types[t], "double") || !strcmp(types[t], "float64");
            putf(&b, "ply\nformat binary_%s_endian 1.0\nelement vertex 27\n", big ? "big" : "little");
            putf(&b, "property %s x\nproperty %s y\nproperty %s z\nend_header\n", types[t], types[t], types[t]);
            for (int i = 0; i < 27; i++) {
                int c[3] = {i % 3, i / 3 % 3, i / 9};
                for (int k = 0; k < 3; k++) {
                    /* 200 + c fits the unsigned bytes, -c the signed ones */
                    double v = types[t][0] == 'u' ? 200 + c[k] : flt || dbl ? c[k] * 0.5 - 0.25 : -c[k];
                    want[3 * i + k] = v;
                    if (flt) put_f32(&b, (float)v, big);
                    else if (dbl) put_f64(&b, v, big);
                    else {
                        int64_t iv = (int64_t)v;
                        put_ord(&b, &iv, size[t], big);   /* little-endian host: low bytes first */
                    }
                }
            }
            char file[64], name[96], msg[512], p[256];
            snprintf(file, sizeof file, "type-%s-%s.ply", types[t], big ? "be" : "le");
            write_file(file, b.b, b.n);
            path_of(p, sizeof p, file);
            double *got = NULL;
            uint32_t np = 0;
            dd_status s = dd_read_points(p, &got, &np, msg, sizeof msg);
            snprintf(name, sizeof name, "readers/type/%s-%s", types[t], big ? "be" : "le");
            tl_check(st, s == DD_OK && np == 27 && !memcmp(got, want, sizeof want), name, "%s: %s",
                     dd_status_name(s), s == DD_OK ? "values differ" : msg);
            free(got);
            free(b.b);
        }
    }
}

/* ---- bad input ------------------------------------------------------------------ */

/* Reads data as `file`; the status must be `want` and the message must
 * contain `where` (the file name with its line or byte offset) and
 * `what`.                                                                */
static void expect_bad(tl_state *st, const char *file, const void *data, size_t n, dd_status want,
                       const char *where, const char *what)
{
    char p[256], name[128], msg[512] = "", full[300];
    write_file(file, data, n);
    path_of(p, sizeof p, file);
    snprintf(full, sizeof full, "%s/%s", dir, where);
    double *xyz = (double *)1;
    uint32_t np = 7;
    dd_status s = dd_read_points(p, &xyz, &np, msg, sizeof msg);
    snprintf(name, sizeof name, "readers/bad/%s", file);
    tl_check(st, s == want && xyz == NULL && np == 0 && strstr(msg, full) && strstr(msg, what), name,
             "status %s (want %s), message '%s' (want '%s' and '%s')", dd_status_name(s), dd_status_name(want), msg,
             full, what);
    if (s == DD_OK) free(xyz);
}

static void expect_bad_s(tl_state *st, const char *file, const char *text, dd_status want, const char *where,
                         const char *what)
{
    expect_bad(st, file, text, strlen(text), want, where, what);
}

/* A binary PLY of 5 float points (header of `hlen` bytes); the body has
 * 12 bytes a point.                                                      */
static size_t ply5(buf *b, int big, const char *fmt_extra, uint32_t count, float bad, int bad_at)
{
    putf(b, "ply\nformat binary_%s_endian 1.0\nelement vertex %u\nproperty float x\nproperty float y\n"
         "property float z\n%send_header\n", big ? "big" : "little", count, fmt_extra);
    size_t hlen = b->n;
    static const float pts[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    for (int i = 0; i < 5; i++)
        for (int k = 0; k < 3; k++) put_f32(b, 3 * i + k == bad_at ? bad : pts[i][k], big);
    return hlen;
}

static void test_bad(tl_state *st)
{
    char where[96];
    buf b = {0};
    size_t h;

    /* binary bodies: truncated, counts that lie, NaN and infinity */
    h = ply5(&b, 0, "", 5, 0, -1);
    expect_bad(st, "truncated.ply", b.b, b.n - 5, DD_ERR_PARSE, "truncated.ply:3:", "truncated, or the counts lie");
    b.n = 0;
    h = ply5(&b, 0, "", 4000000000u, 0, -1);
    expect_bad(st, "count-too-large.ply", b.b, b.n, DD_ERR_PARSE, "count-too-large.ply:3:",
               "need at least 48000000000 bytes");
    b.n = 0;
    h = ply5(&b, 0, "", 4, 0, -1);
    snprintf(where, sizeof where, "count-too-small.ply: byte %zu:", h + 48);
    expect_bad(st, "count-too-small.ply", b.b, b.n, DD_ERR_PARSE, where, "12 bytes after the last element");
    b.n = 0;
    h = ply5(&b, 0, "", 5, NAN, 7);
    snprintf(where, sizeof where, "nan.ply: byte %zu:", h + 28);
    expect_bad(st, "nan.ply", b.b, b.n, DD_ERR_NAN, where, "vertex 2: coordinate y is NaN");
    b.n = 0;
    h = ply5(&b, 1, "", 5, INFINITY, 11);
    snprintf(where, sizeof where, "inf-be.ply: byte %zu:", h + 44);
    expect_bad(st, "inf-be.ply", b.b, b.n, DD_ERR_INFINITE, where, "vertex 3: coordinate z is infinite");
    b.n = 0;
    h = ply5(&b, 0, "", 5, -INFINITY, 0);
    snprintf(where, sizeof where, "minus-inf.ply: byte %zu:", h);
    expect_bad(st, "minus-inf.ply", b.b, b.n, DD_ERR_INFINITE, where, "vertex 0: coordinate x is infinite");
    /* a face element whose list runs past the end */
    b.n = 0;
    h = ply5(&b, 0, "element face 1\nproperty list uchar int vertex_indices\n", 5, 0, -1);
    put_u8(&b, 3);
    put_i32(&b, 0, 0);
    put_i32(&b, 1, 0);
    snprintf(where, sizeof where, "face-truncated.ply: byte %zu:", b.n);
    expect_bad(st, "face-truncated.ply", b.b, b.n, DD_ERR_PARSE, where, "ends in element 'face' 0 of 1");
    /* a negative list count (char) */
    b.n = 0;
    h = ply5(&b, 0, "element face 1\nproperty list char int vertex_indices\n", 5, 0, -1);
    put_u8(&b, 0xff);
    snprintf(where, sizeof where, "negative-list.ply: byte %zu:", h + 60);
    expect_bad(st, "negative-list.ply", b.b, b.n, DD_ERR_PARSE, where, "negative count");
    /* faces counted beyond the data: the header check catches them */
    b.n = 0;
    h = ply5(&b, 0, "element face 1000000\nproperty list uchar int vertex_indices\n", 5, 0, -1);
    expect_bad(st, "faces-lie.ply", b.b, b.n, DD_ERR_PARSE, "faces-lie.ply:3:", "and other elements");
    free(b.b);
    (void)h;

    /* ascii bodies */
    static const char hdr[] = "ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\n"
                              "property double z\nend_header\n";
    char t[512];
    snprintf(t, sizeof t, "%s0 0 0\n1 0 0\n0 1 x\n0 0 1\n1 1 1\n", hdr);
    expect_bad_s(st, "ascii-bad-number.ply", t, DD_ERR_PARSE, "ascii-bad-number.ply:10:", "property 'z'");
    snprintf(t, sizeof t, "%s0 0 0\n1.000 0 0\n0 1\n0 0 1.000\n1 1 1\n", hdr);
    expect_bad_s(st, "ascii-short-line.ply", t, DD_ERR_PARSE, "ascii-short-line.ply:10:", "expected 3 values");
    snprintf(t, sizeof t, "%s0 0 0\n1 0 0 7\n0 1 0\n0 0 1\n1 1 1\n", hdr);
    expect_bad_s(st, "ascii-long-line.ply", t, DD_ERR_PARSE, "ascii-long-line.ply:9:", "more values");
    snprintf(t, sizeof t, "%s0 0 0\n1 0 0\n0 1 0\nnan 0 1\n1 1 1\n", hdr);
    expect_bad_s(st, "ascii-nan.ply", t, DD_ERR_NAN, "ascii-nan.ply:11:", "coordinate x is NaN");
    snprintf(t, sizeof t, "%s0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 -inf 1\n", hdr);
    expect_bad_s(st, "ascii-inf.ply", t, DD_ERR_INFINITE, "ascii-inf.ply:12:", "coordinate y is infinite");
    snprintf(t, sizeof t, "%s0 0 0\n1 0 0\n0 1 0\n0 0 1\n", hdr);
    expect_bad_s(st, "ascii-count-lies.ply", t, DD_ERR_PARSE, "ascii-count-lies.ply:3:", "need at least");
    snprintf(t, sizeof t, "%s0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n2 2 2\n", hdr);
    expect_bad_s(st, "ascii-extra.ply", t, DD_ERR_PARSE, "ascii-extra.ply:13:", "data after the last element");
    {   /* a face list count that is no integer: a vertex line read as a face */
        char t2[600];
        snprintf(t2, sizeof t2, "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                 "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                 "0 0 0\n1 0 0\n0 1 0\n0 0 1\n0.5 0.5 0.5\n");
        expect_bad_s(st, "ascii-face-count.ply", t2, DD_ERR_PARSE, "ascii-face-count.ply:14:",
                     "count of list 'vertex_indices'");
    }

    /* headers */
    expect_bad_s(st, "not-ply.ply", "plx\nformat ascii 1.0\n", DD_ERR_PARSE, "not-ply.ply:1:", "expected 'ply'");
    expect_bad_s(st, "no-end.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", DD_ERR_PARSE,
                 "no-end.ply:4:", "no 'end_header'");
    expect_bad_s(st, "bad-format.ply", "ply\nformat binary_middle_endian 1.0\n", DD_ERR_PARSE, "bad-format.ply:2:",
                 "unknown format");
    expect_bad_s(st, "bad-version.ply", "ply\nformat ascii 2.0\n", DD_ERR_PARSE, "bad-version.ply:2:", "version");
    expect_bad_s(st, "bad-type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\n",
                 DD_ERR_PARSE, "bad-type.ply:4:", "unknown property type 'float128'");
    expect_bad_s(st, "float-count.ply", "ply\nformat ascii 1.0\nelement face 1\nproperty list float int v\n",
                 DD_ERR_PARSE, "float-count.ply:4:", "integer type");
    expect_bad_s(st, "prop-first.ply", "ply\nformat ascii 1.0\nproperty float x\n", DD_ERR_PARSE,
                 "prop-first.ply:3:", "before any 'element'");
    expect_bad_s(st, "no-vertex.ply", "ply\nformat ascii 1.0\nelement face 0\nend_header\n", DD_ERR_PARSE,
                 "no-vertex.ply:4:", "no 'vertex' element");
    expect_bad_s(st, "no-z.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                 "end_header\n", DD_ERR_PARSE, "no-z.ply:3:", "no property 'z'");
    expect_bad_s(st, "list-x.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty list uchar float x\n"
                 "property float y\nproperty float z\nend_header\n", DD_ERR_PARSE, "list-x.ply:3:",
                 "no scalar property 'x'");
    expect_bad_s(st, "two-vertex.ply", "ply\nformat ascii 1.0\nelement vertex 0\nelement vertex 0\n", DD_ERR_PARSE,
                 "two-vertex.ply:4:", "second 'vertex'");
    expect_bad_s(st, "bad-count.ply", "ply\nformat ascii 1.0\nelement vertex -3\n", DD_ERR_PARSE,
                 "bad-count.ply:3:", "element NAME COUNT");
    expect_bad_s(st, "keyword.ply", "ply\nformat ascii 1.0\nelephant vertex 3\n", DD_ERR_PARSE, "keyword.ply:3:",
                 "unknown header keyword");
    expect_bad_s(st, "too-many.ply", "ply\nformat ascii 1.0\nelement vertex 5000000000\nproperty float x\n"
                 "property float y\nproperty float z\nend_header\n", DD_ERR_PARSE, "too-many.ply:3:", "more than");
    expect_bad(st, "nul-header.ply", "ply\nform\0at ascii 1.0\n", 22, DD_ERR_PARSE, "nul-header.ply:2:", "NUL byte");
    expect_bad_s(st, "empty.ply", "", DD_ERR_PARSE, "empty.ply:1:", "expected 'ply'");

    /* obj */
    expect_bad_s(st, "two-coords.obj", "# x\nv 0 0 0\nvn 1 2\nv 1 0\n", DD_ERR_PARSE, "two-coords.obj:4:",
                 "expected a vertex");
    expect_bad_s(st, "word.obj", "v 0 0 0\nv 1 0 0 w\n", DD_ERR_PARSE, "word.obj:2:", "non-number");
    expect_bad_s(st, "nan.obj", "v 0 0 0\n\n\nv 1 NaN 0\n", DD_ERR_NAN, "nan.obj:4:", "vertex 1: coordinate y is NaN");
    expect_bad_s(st, "inf.obj", "v 0 0 0\nv 1 0 1e999\n", DD_ERR_INFINITE, "inf.obj:2:",
                 "vertex 1: coordinate z is infinite");
    expect_bad(st, "nul.obj", "v 0 0 0\nv 1\0 0 0\n", 17, DD_ERR_PARSE, "nul.obj:2:", "NUL byte");

    /* a missing file */
    char p[256], msg[512];
    double *xyz;
    uint32_t np;
    path_of(p, sizeof p, "missing.ply");
    dd_status s = dd_read_points(p, &xyz, &np, msg, sizeof msg);
    tl_check(st, s == DD_ERR_IO && strstr(msg, "missing.ply"), "readers/bad/missing-file", "%s: %s",
             dd_status_name(s), msg);
}

/* A sparse file whose header count the file's size allows but the
 * machine's memory does not: refused before allocating (not the OOM
 * killer).  Skipped where the file system has no sparse files or the
 * machine has more than 96 GB.                                           */
static void test_larger_than_memory(tl_state *st)
{
    static const char hdr[] = "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                              "property float x\nproperty float y\nproperty float z\nend_header\n";
    char p[256], msg[512] = "";
    path_of(p, sizeof p, "huge.ply");
    FILE *f = fopen(p, "wb");
    int made = f && fwrite(hdr, 1, sizeof hdr - 1, f) == sizeof hdr - 1 && fclose(f) == 0;
    if (made) made = truncate(p, (off_t)(sizeof hdr - 1) + (off_t)48000000000) == 0;
    long pages = sysconf(_SC_PHYS_PAGES), psize = sysconf(_SC_PAGESIZE);
    if (!made || (double)pages * (double)psize > 96e9) {
        printf("ok readers/bad/larger-than-memory (skipped: %s)\n", made ? "a machine of more than 96 GB"
                                                                          : "no sparse file");
        st->passed++;
        unlink(p);
        return;
    }
    double *xyz;
    uint32_t np;
    dd_status s = dd_read_points(p, &xyz, &np, msg, sizeof msg);
    tl_check(st, s == DD_ERR_NOMEM && strstr(msg, "huge.ply:3:") && strstr(msg, "memory"),
             "readers/bad/larger-than-memory", "%s: %s", dd_status_name(s), msg);
    unlink(p);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    int small = argc > 1 && !strcmp(argv[1], "small");
    snprintf(dir, sizeof dir, "/tmp/dd-readers-XXXXXX");
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    test_models(&st, small ? 3000 : 0);
    test_types(&st);
    test_bad(&st);
    test_larger_than_memory(&st);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "cannot remove %s\n", dir);
    return tl_finish(&st);
}
