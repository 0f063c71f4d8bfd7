/*
 * datasets.c -- point-set generators and point-file readers (DESIGN 9).
 *
 * Owns: the dataset table behind dd_gen, a seeded PRNG (splitmix64 seeding
 * xoshiro256**), and one line-based parser for .xyz and .off text shared by
 * dd_read_points and the real models (read from tar through popen).
 *
 * Invariants:
 *  - A generator is a pure function of (name, n, seed): no global mutable
 *    state, the PRNG lives on the stack of each call and is seeded from
 *    `seed` alone.  Only moment/grid/layers/cosphere are exact integers or
 *    dyadic rationals; uniform/sphere/grid-perturbed use only IEEE +,-,*,/
 *    and sqrt, so they are bit-identical on every IEEE machine; helix uses
 *    libm cos/sin, which may differ in the last bit between libms.
 *  - On success *xyz is a malloc'd array (never NULL, even for 0 points)
 *    holding 3 * *np doubles, all finite.  On failure *xyz is NULL, *np is
 *    0, and msg (if not NULL) names the problem: file:line for input files.
 *  - Input index = order of the point in the file or in the generator.
 */
#define _POSIX_C_SOURCE 200809L /* getline, popen, pclose */

#include "datasets.h"
#include "msg.h"
#include "readers.h"
#include "rng.h"
#include "tokens.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* Vertex indices are uint32 and UINT32_MAX is the "no vertex" sentinel.  */
#define MAX_POINTS ((uint64_t)UINT32_MAX - 1)



/* ---- synthetic generators ------------------------------------------------ */
/* Each fills xyz[0 .. 3n-1] (allocated by the caller) and returns a status.
 * Only cosphere can fail (it allocates and has a size limit).              */

typedef dd_status (*gen_fn)(uint32_t n, uint64_t seed, double *xyz,
                            char *msg, size_t msglen);

/* moment curve p_i = (t, t^2, t^3), t = i/M, M = smallest power of 2 >= n.
 * t has at most 17 significant bits for n <= 2^17, so t^2, t^3 are exact. */
static dd_status gen_moment(uint32_t n, uint64_t seed, double *xyz,
                            char *msg, size_t msglen)
{
    (void)seed; (void)msg; (void)msglen;
    uint64_t m = 1;
    while (m < n) m <<= 1;
    double inv = 1.0 / (double)m;      /* a power of two: exact */
    for (uint32_t i = 0; i < n; i++) {
        double t = (double)i * inv;
        xyz[3 * (size_t)i] = t;
        xyz[3 * (size_t)i + 1] = t * t;
        xyz[3 * (size_t)i + 2] = t * t * t;
    }
    return DD_OK;
}

/* Erickson's helix: m = sqrt(n) + (sqrt(5)-1)/2 points per turn,
 * a = 2 pi / m, p_i = (cos(ia), sin(ia), ia/m).                           */
static dd_status gen_helix(uint32_t n, uint64_t seed, double *xyz,
                           char *msg, size_t msglen)
{
    (void)seed; (void)msg; (void)msglen;
    const double two_pi = 6.283185307179586476925286766559;
    double m = sqrt((double)n) + (sqrt(5.0) - 1.0) / 2.0;
    double a = two_pi / m;
    for (uint32_t i = 0; i < n; i++) {
        double ia = (double)i * a;
        xyz[3 * (size_t)i] = cos(ia);
        xyz[3 * (size_t)i + 1] = sin(ia);
        xyz[3 * (size_t)i + 2] = ia / m;
    }
    return DD_OK;
}

/* Uniform in the unit cube [0,1)^3; x, y, z drawn in that order. */
static dd_status gen_uniform(uint32_t n, uint64_t seed, double *xyz,
                             char *msg, size_t msglen)
{
    (void)msg; (void)msglen;
    rng g;
    seed_rng(&g, seed);
    for (size_t i = 0; i < 3 * (size_t)n; i++) xyz[i] = next_unit(&g);
    return DD_OK;
}

/* Uniform on the unit sphere, Marsaglia (1972): (u, v) uniform in the unit
 * disk, s = u^2 + v^2, p = (2u sqrt(1-s), 2v sqrt(1-s), 1 - 2s).  Norms are
 * 1 up to rounding.                                                        */
static dd_status gen_sphere(uint32_t n, uint64_t seed, double *xyz,
                            char *msg, size_t msglen)
{
    (void)msg; (void)msglen;
    rng g;
    seed_rng(&g, seed);
    for (uint32_t i = 0; i < n; i++) {
        double u, v, s;
        do {
            u = 2.0 * next_unit(&g) - 1.0;
            v = 2.0 * next_unit(&g) - 1.0;
            s = u * u + v * v;
        } while (s >= 1.0 || s == 0.0);
        double f = 2.0 * sqrt(1.0 - s);
        xyz[3 * (size_t)i] = u * f;
        xyz[3 * (size_t)i + 1] = v * f;
        xyz[3 * (size_t)i + 2] = 1.0 - 2.0 * s;
    }
    return DD_OK;
}

/* Smallest k with k^3 >= n. */
static uint64_t cube_side(uint32_t n)
{
    uint64_t k = (uint64_t)cbrt((double)n);
    while (k * k * k < n) k++;
    while (k > 0 && (k - 1) * (k - 1) * (k - 1) >= n) k--;
    return k;
}

/* First n points of the k x k x k integer grid, x fastest, in grid order. */
static void fill_grid(uint32_t n, double *xyz)
{
    uint64_t k = cube_side(n);
    for (uint32_t i = 0; i < n; i++) {
        xyz[3 * (size_t)i] = (double)(i % k);
        xyz[3 * (size_t)i + 1] = (double)(i / k % k);
        xyz[3 * (size_t)i + 2] = (double)(i / k / k);
    }
}

static dd_status gen_grid(uint32_t n, uint64_t seed, double *xyz,
                          char *msg, size_t msglen)
{
    (void)seed; (void)msg; (void)msglen;
    fill_grid(n, xyz);
    return DD_OK;
}

/* The grid plus a uniform perturbation in [-1e-13, 1e-13) per coordinate
 * (x, y, z of each point in order).  Near k = 512 and beyond the
 * perturbation is below half an ulp of the coordinate and may vanish.     */
static dd_status gen_grid_perturbed(uint32_t n, uint64_t seed, double *xyz,
                                    char *msg, size_t msglen)
{
    (void)msg; (void)msglen;
    rng g;
    seed_rng(&g, seed);
    fill_grid(n, xyz);
    for (size_t i = 0; i < 3 * (size_t)n; i++)
        xyz[i] += (2.0 * next_unit(&g) - 1.0) * 1e-13;
    return DD_OK;
}

/* Two stacked k x k integer grids at z = 0 and z = 1, k the smallest with
 * 2k^2 >= n; the first n points, layer z = 0 first, x fastest.             */
static dd_status gen_layers(uint32_t n, uint64_t seed, double *xyz,
                            char *msg, size_t msglen)
{
    (void)seed; (void)msg; (void)msglen;
    uint64_t k = (uint64_t)sqrt((double)n / 2.0);
    while (2 * k * k < n) k++;
    while (k > 0 && 2 * (k - 1) * (k - 1) >= n) k--;
    for (uint32_t i = 0; i < n; i++) {
        xyz[3 * (size_t)i] = (double)(i % k);
        xyz[3 * (size_t)i + 1] = (double)(i / k % k);
        xyz[3 * (size_t)i + 2] = (double)(i / k / k);
    }
    return DD_OK;
}

/* ---- cosphere: integer points on x^2 + y^2 + z^2 = r^2 ------------------- */

/* Largest radius allowed.  Exactness only needs r^2 < 2^53; the limit keeps
 * the enumeration, about 0.2 r^2 steps, to seconds (`time dtdel gen
 * cosphere N`).  n up to about 4.5 million fits.                         */
#define COSPHERE_MAX_R ((uint64_t)1 << 18)

/* r3(r^2), the number of integer points on the sphere of radius r >= 1
 * (Hurwitz): 6 * prod over odd p^a || r of sigma(p^a) - (-1|p) sigma(p^(a-1)),
 * with (-1|p) = +1 for p = 1 mod 4, -1 for p = 3 mod 4.  Cost O(sqrt r).  */
static uint64_t sphere_count(uint64_t r)
{
    uint64_t count = 6;
    while (r % 2 == 0) r /= 2;
    for (uint64_t p = 3; p * p <= r; p += 2) {
        if (r % p != 0) continue;
        uint64_t pa = 1, sig = 1, sig_prev = 0;  /* sigma(p^a), sigma(p^(a-1)) */
        while (r % p == 0) {
            r /= p;
            pa *= p;
            sig_prev = sig;
            sig += pa;
        }
        count *= p % 4 == 1 ? sig - sig_prev : sig + sig_prev;
    }
    if (r > 1) count *= r % 4 == 1 ? r : r + 2;   /* a prime to the power 1 */
    return count;
}

static int cmp_triple(const void *pa, const void *pb)
{
    const int32_t *a = pa, *b = pb;
    for (int c = 0; c < 3; c++)
        if (a[c] != b[c]) return a[c] < b[c] ? -1 : 1;
    return 0;
}

/* floor(sqrt(m)) for m < 2^53. */
static int64_t isqrt(int64_t m)
{
    int64_t s = (int64_t)sqrt((double)m);
    while (s * s > m) s--;
    while ((s + 1) * (s + 1) <= m) s++;
    return s;
}

/* Appends to pts (count triples, capacity cap) all sign and coordinate
 * permutations of (a, b, c); duplicates are removed later by sorting.     */
static int push_variants(int32_t **pts, size_t *count, size_t *cap,
                         int32_t a, int32_t b, int32_t c)
{
    static const int perm[6][3] = {
        {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    const int32_t v[3] = {a, b, c};
    if (*count + 48 > *cap) {
        size_t ncap = *cap ? 2 * *cap : 1024;
        int32_t *np = realloc(*pts, 3 * ncap * sizeof **pts);
        if (np == NULL) return 0;
        *pts = np;
        *cap = ncap;
    }
    for (int p = 0; p < 6; p++)
        for (int s = 0; s < 8; s++) {
            int32_t w[3];
            int skip = 0;
            for (int i = 0; i < 3; i++) {
                w[i] = v[perm[p][i]];
                if (s >> i & 1) {
                    if (w[i] == 0) skip = 1;   /* -0 is 0: same point */
                    w[i] = -w[i];
                }
            }
            if (skip) continue;
            memcpy(*pts + 3 * *count, w, sizeof w);
            (*count)++;
        }
    return 1;
}

/* n distinct integer points on the smallest sphere x^2+y^2+z^2 = r^2 that
 * has at least n of them: all of them enumerated in lexicographic order,
 * then a seeded Fisher-Yates shuffle; the first n of the shuffled order
 * are returned (in that order).                                           */
static dd_status gen_cosphere(uint32_t n, uint64_t seed, double *xyz,
                              char *msg, size_t msglen)
{
    if (n == 0) return DD_OK;
    uint64_t r = 1;
    while (sphere_count(r) < n) {
        if (++r > COSPHERE_MAX_R) {
            set_msg(msg, msglen, "cosphere: n = %lu is too large (the sphere "
                    "radius would exceed %lu)", (unsigned long)n,
                    (unsigned long)COSPHERE_MAX_R);
            return DD_ERR_PARSE;
        }
    }
    uint64_t expected = sphere_count(r);

    /* Representatives a >= b >= c >= 0 by two pointers on b^2 + c^2. */
    int32_t *pts = NULL;
    size_t count = 0, cap = 0;
    const int64_t ri = (int64_t)r, r2 = ri * ri;
    for (int64_t a = ri; 3 * a * a >= r2; a--) {
        int64_t m = r2 - a * a;
        int64_t b = isqrt(m), c = 0;
        if (b > a) b = a;
        while (c <= b) {
            int64_t s = b * b + c * c;
            if (s < m) { c++; continue; }
            if (s > m) { b--; continue; }
            if (!push_variants(&pts, &count, &cap, (int32_t)a, (int32_t)b,
                               (int32_t)c)) {
                free(pts);
                set_msg(msg, msglen, "cosphere: out of memory");
                return DD_ERR_NOMEM;
            }
            c++;
            b--;
        }
    }
    qsort(pts, count, 3 * sizeof *pts, cmp_triple);
    size_t uniq = 0;
    for (size_t i = 0; i < count; i++)
        if (uniq == 0 || cmp_triple(pts + 3 * (uniq - 1), pts + 3 * i) != 0)
            memmove(pts + 3 * uniq++, pts + 3 * i, 3 * sizeof *pts);
    if (uniq != expected || uniq < n) {
        free(pts);
        set_msg(msg, msglen, "cosphere: found %lu points on radius %lu, "
                "expected %lu", (unsigned long)uniq, (unsigned long)r,
                (unsigned long)expected);
        return DD_ERR_INTERNAL;
    }

    rng g;
    seed_rng(&g, seed);
    for (size_t i = 0; i < n; i++) {
        size_t j = i + (size_t)next_below(&g, uniq - i);
        int32_t t[3];
        memcpy(t, pts + 3 * i, sizeof t);
        memmove(pts + 3 * i, pts + 3 * j, sizeof t);
        memcpy(pts + 3 * j, t, sizeof t);
        for (int k = 0; k < 3; k++) xyz[3 * i + k] = (double)pts[3 * i + k];
    }
    free(pts);
    return DD_OK;
}

/* ---- line-based text parsing --------------------------------------------- */
/* Tokens are separated by white space (isspace, so CR of CRLF files too);
 * a token starting with '#' begins a comment to the end of the line.
 * Numbers use strtod syntax in the C locale ("1", "-2.5e-3", "0x1p-3",
 * "nan", "inf"); a number must fill its whole token.                       */

typedef struct reader {
    FILE *f;
    const char *name;       /* for messages */
    char *line;             /* getline buffer, grows as needed */
    size_t cap;
    size_t len;
    unsigned long lineno;
} reader;

typedef struct points {
    double *xyz;
    double *w;               /* weights, when wmode != W_NONE */
    size_t n, cap;           /* in points */
    int wmode;
} points;

/* The fourth column of a text line: none (.xyz, .off), a weight (.xyzw)
 * or a radius whose square is the weight (.xyzr).                       */
enum { W_NONE, W_WEIGHT, W_RADIUS };

/* 1 if nothing but blanks or a comment remains at p. */
static int at_end(const char *p)
{
    p = skip_blank(p);
    return *p == '\0' || *p == '#';
}

/* A printable copy of the current line for messages: at most 40 chars,
 * trailing white space dropped, control chars as '?', "..." if cut.      */
static void quote_line(const reader *rd, char *out, size_t outlen)
{
    const size_t max = 40;
    size_t len = rd->len;
    while (len > 0 && isspace((unsigned char)rd->line[len - 1])) len--;
    size_t k = 0;
    for (size_t i = 0; i < len && i < max && k + 1 < outlen; i++) {
        unsigned char c = (unsigned char)rd->line[i];
        out[k++] = (char)(c < 32 || c == 127 ? '?' : c);
    }
    if (len > max && k + 4 < outlen) {
        memcpy(out + k, "...", 3);
        k += 3;
    }
    out[k] = '\0';
}

/* Reads the next line that has content (skipping blank and comment lines).
 * Returns DD_OK with *got = 1, DD_OK with *got = 0 at end of file, or an
 * error (read error, NUL byte in the line).                               */
static dd_status next_line(reader *rd, int *got, char *msg, size_t msglen)
{
    *got = 0;
    for (;;) {
        errno = 0;
        ssize_t r = getline(&rd->line, &rd->cap, rd->f);
        if (r < 0) {
            if (ferror(rd->f)) {
                set_msg(msg, msglen, "error reading '%s': %s", rd->name,
                        strerror(errno ? errno : EIO));
                return errno == ENOMEM ? DD_ERR_NOMEM : DD_ERR_IO;
            }
            return DD_OK;
        }
        rd->lineno++;
        rd->len = (size_t)r;
        if (strlen(rd->line) != rd->len) {
            set_msg(msg, msglen, "%s:%lu: line contains a NUL byte (binary "
                    "file?)", rd->name, rd->lineno);
            return DD_ERR_PARSE;
        }
        if (!at_end(rd->line)) {
            *got = 1;
            return DD_OK;
        }
    }
}

/* Parses "x y z ..." from the current line into v.  Trailing tokens must
 * all be numbers when `strict_tail` (xyz: normals etc.), anything when
 * not (off: colours, normals, texture coordinates).  Reports a parse
 * error with `what`, or NaN / infinity, naming file and line.             */
static dd_status parse_point(const reader *rd, int strict_tail,
                             const char *what, double v[3],
                             char *msg, size_t msglen)
{
    const char *p = rd->line;
    int ok = parse_number(&p, &v[0]) && parse_number(&p, &v[1])
             && parse_number(&p, &v[2]);
    if (ok && strict_tail) {
        double extra;
        while (ok && !at_end(p)) ok = parse_number(&p, &extra);
    }
    if (!ok) {
        char q[64];
        quote_line(rd, q, sizeof q);
        set_msg(msg, msglen, "%s:%lu: expected %s, got '%s'", rd->name,
                rd->lineno, what, q);
        return DD_ERR_PARSE;
    }
    for (int c = 0; c < 3; c++) {
        if (isnan(v[c])) {
            set_msg(msg, msglen, "%s:%lu: coordinate is NaN", rd->name,
                    rd->lineno);
            return DD_ERR_NAN;
        }
        if (isinf(v[c])) {
            set_msg(msg, msglen, "%s:%lu: coordinate is infinite", rd->name,
                    rd->lineno);
            return DD_ERR_INFINITE;
        }
    }
    return DD_OK;
}

/* Appends a point (and its weight v[3] when pts has weights), growing
 * the arrays geometrically.                                              */
static dd_status push_point(points *pts, const double v[4], const reader *rd,
                            char *msg, size_t msglen)
{
    if (pts->n >= MAX_POINTS) {
        set_msg(msg, msglen, "%s:%lu: more than %lu points", rd->name,
                rd->lineno, (unsigned long)MAX_POINTS);
        return DD_ERR_PARSE;
    }
    if (pts->n == pts->cap) {
        size_t ncap = pts->cap ? 2 * pts->cap : 1024;
        double *nx = realloc(pts->xyz, 3 * ncap * sizeof *nx);
        if (nx != NULL) pts->xyz = nx;
        double *nw = nx == NULL || pts->wmode == W_NONE ? NULL : realloc(pts->w, ncap * sizeof *nw);
        if (nw != NULL) pts->w = nw;
        if (nx == NULL || (pts->wmode != W_NONE && nw == NULL)) {
            set_msg(msg, msglen, "out of memory reading '%s'", rd->name);
            return DD_ERR_NOMEM;
        }
        pts->cap = ncap;
    }
    memcpy(pts->xyz + 3 * pts->n, v, 3 * sizeof *v);
    if (pts->wmode != W_NONE) pts->w[pts->n] = v[3];
    pts->n++;
    return DD_OK;
}

/* The fourth number of the current line (after "x y z") as a weight:
 * missing or not a number, NaN, infinite, a negative radius or one whose
 * square overflows are errors naming file and line.                     */
static dd_status parse_weight(const reader *rd, int wmode, double *w,
                              char *msg, size_t msglen)
{
    const char *what = wmode == W_RADIUS ? "radius" : "weight";
    const char *p = rd->line;
    double x[3], v;
    parse_number(&p, &x[0]);
    parse_number(&p, &x[1]);
    parse_number(&p, &x[2]);
    if (!parse_number(&p, &v)) {
        char q[64];
        quote_line(rd, q, sizeof q);
        set_msg(msg, msglen, "%s:%lu: missing %s: expected 'x y z %s', got "
                "'%s'", rd->name, rd->lineno, what,
                wmode == W_RADIUS ? "r" : "w", q);
        return DD_ERR_PARSE;
    }
    if (isnan(v)) {
        set_msg(msg, msglen, "%s:%lu: %s is NaN", rd->name, rd->lineno, what);
        return DD_ERR_NAN;
    }
    if (isinf(v) || (wmode == W_RADIUS && isinf(v * v))) {
        set_msg(msg, msglen, "%s:%lu: %s is infinite%s", rd->name, rd->lineno,
                what, isinf(v) ? "" : " (its square overflows)");
        return DD_ERR_INFINITE;
    }
    if (wmode == W_RADIUS && v < 0) {
        set_msg(msg, msglen, "%s:%lu: negative radius %.17g", rd->name,
                rd->lineno, v);
        return DD_ERR_PARSE;
    }
    double extra;
    while (!at_end(p))
        if (!parse_number(&p, &extra)) {
            char q[64];
            quote_line(rd, q, sizeof q);
            set_msg(msg, msglen, "%s:%lu: expected numbers after 'x y z %s', "
                    "got '%s'", rd->name, rd->lineno,
                    wmode == W_RADIUS ? "r" : "w", q);
            return DD_ERR_PARSE;
        }
    *w = wmode == W_RADIUS ? v * v : v;
    return DD_OK;
}

/* .xyz: every content line is "x y z" optionally followed by more numbers
 * (normals "nx ny nz", weights, ...) and a '#' comment; they are ignored. */
static dd_status parse_xyz(reader *rd, points *pts, char *msg, size_t msglen)
{
    for (;;) {
        int got;
        dd_status st = next_line(rd, &got, msg, msglen);
        if (st != DD_OK || !got) return st;
        double v[4] = {0, 0, 0, 0};
        st = parse_point(rd, pts->wmode == W_NONE, "three numbers 'x y z'", v,
                         msg, msglen);
        if (st == DD_OK && pts->wmode != W_NONE)
            st = parse_weight(rd, pts->wmode, &v[3], msg, msglen);
        if (st == DD_OK) st = push_point(pts, v, rd, msg, msglen);
        if (st != DD_OK) return st;
    }
}

/* 1 if tok (length len) is an OFF keyword without binary or dimension
 * prefixes: [ST][C][N]OFF.                                               */
static int is_off_keyword(const char *tok, size_t len)
{
    if (len < 3 || memcmp(tok + len - 3, "OFF", 3) != 0) return 0;
    size_t i = 0, end = len - 3;
    if (i + 2 <= end && memcmp(tok + i, "ST", 2) == 0) i += 2;
    if (i < end && tok[i] == 'C') i++;
    if (i < end && tok[i] == 'N') i++;
    return i == end;
}

/* .off (vertices only): a header "OFF" (or [ST][C][N]OFF), the counts
 * "nv nf [ne]" on the same or a later line, then nv vertex lines
 * "x y z ..." (extra tokens ignored).  Faces are not read.  A file with no
 * content at all gives 0 points.                                          */
static dd_status parse_off(reader *rd, points *pts, char *msg, size_t msglen)
{
    int got;
    char q[64];
    dd_status st = next_line(rd, &got, msg, msglen);
    if (st != DD_OK || !got) return st;

    const char *p = skip_blank(rd->line);
    size_t len = 0;
    while (!ends_token(p[len])) len++;
    if (!is_off_keyword(p, len)) {
        quote_line(rd, q, sizeof q);
        set_msg(msg, msglen, "%s:%lu: expected an 'OFF' header (ASCII, 3D), "
                "got '%s'", rd->name, rd->lineno, q);
        return DD_ERR_PARSE;
    }
    p += len;
    const char *b = skip_blank(p);
    if (strncmp(b, "BINARY", 6) == 0 && ends_token(b[6])) {
        set_msg(msg, msglen, "%s:%lu: binary OFF is not supported",
                rd->name, rd->lineno);
        return DD_ERR_PARSE;
    }
    if (at_end(p)) {                    /* counts on the next content line */
        st = next_line(rd, &got, msg, msglen);
        if (st != DD_OK) return st;
        if (!got) {
            set_msg(msg, msglen, "%s:%lu: file ends before the counts "
                    "'nv nf ne'", rd->name, rd->lineno);
            return DD_ERR_PARSE;
        }
        p = rd->line;
    }
    uint64_t nv, nf, ne;
    if (!parse_count_tok(&p, &nv, 0) || !parse_count_tok(&p, &nf, 0)
        || (!at_end(p) && !parse_count_tok(&p, &ne, 0)) || !at_end(p)) {
        quote_line(rd, q, sizeof q);
        set_msg(msg, msglen, "%s:%lu: expected counts 'nv nf ne', got '%s'",
                rd->name, rd->lineno, q);
        return DD_ERR_PARSE;
    }
    if (nv > MAX_POINTS) {
        set_msg(msg, msglen, "%s:%lu: vertex count %llu exceeds %lu",
                rd->name, rd->lineno, (unsigned long long)nv,
                (unsigned long)MAX_POINTS);
        return DD_ERR_PARSE;
    }
    for (uint64_t i = 0; i < nv; i++) {
        st = next_line(rd, &got, msg, msglen);
        if (st != DD_OK) return st;
        if (!got) {
            set_msg(msg, msglen, "%s:%lu: file ends after %llu of %llu "
                    "vertices", rd->name, rd->lineno, (unsigned long long)i,
                    (unsigned long long)nv);
            return DD_ERR_PARSE;
        }
        double v[4] = {0, 0, 0, 0};
        st = parse_point(rd, 0, "vertex 'x y z'", v, msg, msglen);
        if (st == DD_OK) st = push_point(pts, v, rd, msg, msglen);
        if (st != DD_OK) return st;
    }
    return DD_OK;
}

/* Parses f as OFF (is_off) or xyz (with a fourth column by wmode); on
 * success hands the array to *xyz (never NULL), the weights to *w (when
 * wmode is not W_NONE; never NULL then) and the count to *np.            */
static dd_status parse_file(FILE *f, const char *name, int is_off, int wmode,
                            double **xyz, double **w, uint32_t *np,
                            char *msg, size_t msglen)
{
    reader rd = {f, name, NULL, 0, 0, 0};
    points pts = {NULL, NULL, 0, 0, is_off ? W_NONE : wmode};
    dd_status st = is_off ? parse_off(&rd, &pts, msg, msglen)
                          : parse_xyz(&rd, &pts, msg, msglen);
    free(rd.line);
    if (st == DD_OK && pts.xyz == NULL) pts.xyz = malloc(3 * sizeof *pts.xyz);
    if (st == DD_OK && pts.wmode != W_NONE && pts.w == NULL)
        pts.w = malloc(sizeof *pts.w);
    if (st == DD_OK && (pts.xyz == NULL || (pts.wmode != W_NONE && pts.w == NULL))) {
        set_msg(msg, msglen, "out of memory reading '%s'", name);
        st = DD_ERR_NOMEM;
    }
    if (st != DD_OK) {
        free(pts.xyz);
        free(pts.w);
        return st;
    }
    *xyz = pts.xyz;
    if (w != NULL) *w = pts.w;
    else free(pts.w);
    *np = (uint32_t)pts.n;
    return DD_OK;
}

static int has_off_extension(const char *path)
{
    size_t len = strlen(path);
    if (len < 4) return 0;
    const char *e = path + len - 4;
    return e[0] == '.' && tolower((unsigned char)e[1]) == 'o'
           && tolower((unsigned char)e[2]) == 'f'
           && tolower((unsigned char)e[3]) == 'f';
}

dd_status dd_read_points(const char *path, double **xyz, uint32_t *np,
                         char *msg, size_t msglen)
{
    *xyz = NULL;
    *np = 0;
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        set_msg(msg, msglen, "cannot open '%s': %s", path, strerror(errno));
        return DD_ERR_IO;
    }
    dd_status st = dd_read_points_stream(f, path, xyz, np, msg, msglen);
    fclose(f);
    return st;
}

dd_status dd_read_points_stream(FILE *f, const char *name, double **xyz,
                                uint32_t *np, char *msg, size_t msglen)
{
    *xyz = NULL;
    *np = 0;
    switch (dd_format_of(name)) {      /* .ply, .obj: readers.c */
    case DD_FORMAT_PLY: return dd_read_ply(f, name, xyz, np, msg, msglen);
    case DD_FORMAT_OBJ: return dd_read_obj(f, name, xyz, np, msg, msglen);
    default:
        return parse_file(f, name, has_off_extension(name), W_NONE, xyz, NULL,
                          np, msg, msglen);
    }
}

dd_status dd_read_weighted(const char *path, double **xyz, double **w,
                           uint32_t *np, char *msg, size_t msglen)
{
    *xyz = NULL;
    *w = NULL;
    *np = 0;
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        set_msg(msg, msglen, "cannot open '%s': %s", path, strerror(errno));
        return DD_ERR_IO;
    }
    dd_status st = dd_read_weighted_stream(f, path, xyz, w, np, msg, msglen);
    fclose(f);
    return st;
}

dd_status dd_read_weighted_stream(FILE *f, const char *name, double **xyz,
                                  double **w, uint32_t *np, char *msg,
                                  size_t msglen)
{
    *xyz = NULL;
    *w = NULL;
    *np = 0;
    switch (dd_format_of(name)) {
    case DD_FORMAT_PLY:
        return dd_read_ply_weighted(f, name, xyz, w, np, msg, msglen);
    case DD_FORMAT_XYZW:
        return parse_file(f, name, 0, W_WEIGHT, xyz, w, np, msg, msglen);
    case DD_FORMAT_XYZR:
        return parse_file(f, name, 0, W_RADIUS, xyz, w, np, msg, msglen);
    default:
        return dd_read_points_stream(f, name, xyz, np, msg, msglen);
    }
}

/* ---- real models --------------------------------------------------------- */

static const char *const data_archives[] = {
    "/usr/share/doc/libcgal-dev/data.tar.gz",
    "/usr/share/doc/libcgal-demo/data.tar.gz",
};

/* Reads the vertices of data/meshes/<file> from the CGAL data archive
 * through `tar -xzOf`; keeps the first n (all if n == 0).                 */
static dd_status load_model(const char *file, uint32_t n, double **xyz,
                            uint32_t *np, char *msg, size_t msglen)
{
    const char *archive = NULL;
    for (size_t i = 0; i < sizeof data_archives / sizeof *data_archives; i++)
        if (access(data_archives[i], R_OK) == 0) {
            archive = data_archives[i];
            break;
        }
    if (archive == NULL) {
        set_msg(msg, msglen, "model data not found (%s): install libcgal-dev "
                "(or run `make deps`)", data_archives[0]);
        return DD_ERR_IO;
    }

    /* Names come from the const tables here: nothing to quote.  GNU tar's
     * --occurrence=1 stops at the member instead of reading the whole
     * 18 MB archive; a tar without it fails before writing anything, and
     * the plain command runs instead.                                     */
    char cmd[1024], name[512];
    snprintf(cmd, sizeof cmd,
             "tar -xzOf '%s' --occurrence=1 'data/meshes/%s' 2>/dev/null"
             " || tar -xzOf '%s' 'data/meshes/%s' 2>/dev/null",
             archive, file, archive, file);
    snprintf(name, sizeof name, "%s:data/meshes/%s", archive, file);
    FILE *f = popen(cmd, "r");
    if (f == NULL) {
        set_msg(msg, msglen, "cannot run tar on '%s': %s", archive,
                strerror(errno));
        return DD_ERR_IO;
    }
    dd_status st = parse_file(f, name, 1, W_NONE, xyz, NULL, np, msg, msglen);
    char drain[1 << 14];               /* let tar finish: no SIGPIPE */
    while (fread(drain, 1, sizeof drain, f) > 0) {}
    int ws = pclose(f);
    if (ws == -1 || !WIFEXITED(ws) || WEXITSTATUS(ws) != 0) {
        if (st == DD_OK) free(*xyz);
        *xyz = NULL;
        *np = 0;
        int code = ws != -1 && WIFEXITED(ws) ? WEXITSTATUS(ws) : -1;
        set_msg(msg, msglen, "cannot extract 'data/meshes/%s' from '%s' "
                "(tar exit status %d%s)", file, archive, code,
                code == 127 ? ": is tar installed?" : "");
        return DD_ERR_IO;
    }
    if (st != DD_OK) return st;
    if (n != 0 && n < *np) *np = n;    /* keep the first n; no shrink needed */
    return DD_OK;
}

/* ---- the table ------------------------------------------------------------ */

typedef struct dataset {
    const char *name;
    gen_fn gen;              /* synthetic: fills n points; else NULL */
    const char *model;       /* real model: file in data/meshes/     */
} dataset;

static const dataset datasets[] = {
    {"moment", gen_moment, NULL},
    {"helix", gen_helix, NULL},
    {"uniform", gen_uniform, NULL},
    {"sphere", gen_sphere, NULL},
    {"grid", gen_grid, NULL},
    {"cosphere", gen_cosphere, NULL},
    {"layers", gen_layers, NULL},
    {"grid-perturbed", gen_grid_perturbed, NULL},
    {"bunny", NULL, "bunny00.off"},
    {"elephant", NULL, "elephant.off"},
    {"armadillo", NULL, "armadillo.off"},
    {"camel", NULL, "camel.off"},
    {"cow", NULL, "cow.off"},
    {"dragon", NULL, "ChineseDragon-10kv.off"},
    {"eight", NULL, "eight.off"},
    {"fandisk", NULL, "fandisk.off"},
};
#define NUM_DATASETS (sizeof datasets / sizeof *datasets)

const char *dd_dataset_name(size_t i)
{
    return i < NUM_DATASETS ? datasets[i].name : dd_weighted_dataset_name(i - NUM_DATASETS);
}

dd_status dd_gen(const char *name, uint32_t n, uint64_t seed,
                 double **xyz, uint32_t *np, char *msg, size_t msglen)
{
    *xyz = NULL;
    *np = 0;
    const dataset *d = NULL;
    for (size_t i = 0; name != NULL && i < NUM_DATASETS; i++)
        if (strcmp(name, datasets[i].name) == 0) d = &datasets[i];
    if (d == NULL && dd_dataset_is_weighted(name)) {  /* weights dropped */
        double *w;
        dd_status st = dd_gen_weighted(name, n, seed, xyz, &w, np, msg, msglen);
        free(w);
        return st;
    }
    if (d == NULL) {
        char known[768];
        size_t k = 0;
        known[0] = '\0';
        for (size_t i = 0; dd_dataset_name(i) && k < sizeof known; i++) {
            int w = snprintf(known + k, sizeof known - k, "%s%s",
                             i ? ", " : "", dd_dataset_name(i));
            if (w < 0) break;
            k += (size_t)w;
        }
        set_msg(msg, msglen, "unknown dataset '%s' (known: %s)",
                name ? name : "(null)", known);
        return DD_ERR_PARSE;
    }
    if (d->gen == NULL) return load_model(d->model, n, xyz, np, msg, msglen);

    double *out = malloc((n ? 3 * (size_t)n : 3) * sizeof *out);
    if (out == NULL) {
        set_msg(msg, msglen, "out of memory for %lu points of '%s'",
                (unsigned long)n, d->name);
        return DD_ERR_NOMEM;
    }
    dd_status st = d->gen(n, seed, out, msg, msglen);
    if (st != DD_OK) {
        free(out);
        return st;
    }
    *xyz = out;
    *np = n;
    return DD_OK;
}
