/*
 * fuzz_entry.h -- the entry points of the fuzz targets, shared by the
 * libFuzzer drivers (tests/fuzz/fuzz_*.c, `make fuzz`) and the replay
 * test (tests/test_fuzz_replay.c, `make test`), so that every input the
 * fuzzer kept or crashed on runs the same code in the normal and the
 * sanitizer builds.
 *
 *   dd_fuzz_readers(data, n): data[0] % 4 picks .xyz, .off, .ply or .obj;
 *     the rest is the file, read from memory (dd_read_points_stream).
 *     On success the points must be finite and *xyz not NULL; on failure
 *     *xyz NULL, no points, a known status and a message naming the input.
 *   dd_fuzz_ops(data, n): an interpreter of operations on points of the
 *     integer grid {0..4}^3, degenerate on purpose, of that grid scaled
 *     to the ends of the double range, and of any finite doubles (whole
 *     bit patterns; see fz_coord): create, delete, insert (reusing
 *     deleted indices), move, delete_set, reinsert, test controls and
 *     the grid's scale.  After each operation
 *     dd_check must pass and the canonical form must equal that of a
 *     dd_create from scratch of the vertices left (indices mapped back);
 *     a refused operation must leave the canonical form unchanged, and
 *     only the refusals the API documents are allowed.
 *     An input whose first byte is FZ_WEIGHTED runs the same operations on
 *     weighted points (issue 44): create makes a regular triangulation
 *     (dd_create_ex, hidden points kept or DD_DISCARD_HIDDEN), insert is
 *     dd_insert_weighted, move is dd_move or dd_move_weighted, each point
 *     with a weight from fz_weight (any finite double among them); with
 *     hidden points kept, deletions, sets and moves may name hidden
 *     points too (fz_target).  The
 *     reference is a dd_create_ex from scratch of the points left: with
 *     hidden points kept, the vertices and the hidden points (the same
 *     cells, the same hidden set but for exact copies of a point still
 *     there); when discarding, the vertices (the same cells, nothing
 *     hidden).  DD_ERR_UNSUPPORTED (an edit or a strategy not there yet
 *     for weighted points) is an allowed refusal: nothing may change.
 *
 * Both return 0, or 1 after printing what broke to stderr (the drivers
 * abort then, so libFuzzer saves the input).  Header-only, all static:
 * each program includes it once.
 */
#ifndef DD_FUZZ_ENTRY_H
#define DD_FUZZ_ENTRY_H

#include "dtdel.h"
#include "dtdel_stats.h"
#include "datasets/datasets.h"

#include "canon.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- readers ------------------------------------------------------------- */

static int dd_fuzz_readers(const uint8_t *data, size_t n)
{
    static const char *const names[4] = {"fuzz.xyz", "fuzz.off", "fuzz.ply", "fuzz.obj"};
    if (n == 0) return 0;
    const char *name = names[data[0] % 4];
    /* fmemopen wants a non-empty writable-looking buffer: copy */
    size_t len = n - 1;
    char *copy = malloc(len ? len : 1);
    if (!copy) return 0;
    if (len) memcpy(copy, data + 1, len);
    else copy[0] = '\n';
    FILE *f = fmemopen(copy, len ? len : 1, "r");
    if (!f) {
        free(copy);
        return 0;
    }
    double *xyz = (double *)&name;      /* must be overwritten */
    uint32_t np = 12345;
    char msg[512] = "";
    dd_status st = dd_read_points_stream(f, name, &xyz, &np, msg, sizeof msg);
    fclose(f);
    free(copy);
    int bad = 0;
    if (st == DD_OK) {
        if (xyz == NULL) {
            fprintf(stderr, "fuzz readers %s: DD_OK with no array\n", name);
            bad = 1;
        }
        for (size_t i = 0; !bad && i < 3 * (size_t)np; i++)
            if (!isfinite(xyz[i])) {
                fprintf(stderr, "fuzz readers %s: DD_OK with a coordinate %g\n", name, xyz[i]);
                bad = 1;
            }
        if (!bad) free(xyz);
    } else {
        int known = st == DD_ERR_PARSE || st == DD_ERR_NAN || st == DD_ERR_INFINITE || st == DD_ERR_IO
                    || st == DD_ERR_NOMEM;
        if (xyz != NULL || np != 0 || !known || strncmp(msg, name, strlen(name)) != 0) {
            fprintf(stderr, "fuzz readers %s: failure %s with array %p, %u points, message '%s'\n", name,
                    dd_status_name(st), (void *)xyz, np, msg);
            bad = 1;
        }
    }
    return bad;
}

/* ---- the operation interpreter ---------------------------------------------- */

#define FZ_GRID 5          /* coordinates 0..4 */
#define FZ_MAX_OPS 48
#define FZ_MAX_POINTS 256
#define FZ_WEIGHTED 0x57   /* first byte of a weighted session ('W') */

typedef struct fz_in {
    const uint8_t *p;
    size_t n, at;
} fz_in;

static int fz_more(const fz_in *in) { return in->at < in->n; }
static unsigned fz_byte(fz_in *in) { return in->at < in->n ? in->p[in->at++] : 0; }

/* The scales 2^e of the scaled grid (the controls op picks one): the
 * ends of the range (2^1022: differences overflow; 2^-1074: subnormal),
 * where squares or products of the filters overflow or underflow, and
 * ordinary ones.                                                         */
static const int fz_scales[16] = {0, 1022, -1074, 1000, -1000, 511, -537, 300, -300, 150, -150, 52, -52, 1021, -1060, 7};

/* One coordinate.  A byte b < 224 is the grid coordinate b % 5; b < 240
 * the grid coordinate b % 5 - 2 times 2^e (e the scale set last, 0 at
 * first); b >= 240 takes the next 8 bytes as the bit pattern of a double
 * (little-endian), made finite (an exponent of all ones becomes the
 * largest finite one): any double, subnormals and magnitudes near
 * DBL_MAX included, in one set with the grid's.                          */
static double fz_coord(fz_in *in, int e)
{
    unsigned b = fz_byte(in);
    if (b < 224) return (double)(b % FZ_GRID);
    if (b < 240) return ldexp((double)((int)(b % FZ_GRID) - 2), e);
    uint64_t bits = 0;
    for (int i = 0; i < 8; i++) bits |= (uint64_t)fz_byte(in) << (8 * i);
    if ((bits >> 52 & 0x7ff) == 0x7ff) bits ^= (uint64_t)1 << 52;
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}

static void fz_point(fz_in *in, int e, double q[3])
{
    for (int k = 0; k < 3; k++) q[k] = fz_coord(in, e);
}

/* A weight, scaled as a squared length of the grid: a byte b < 200 is
 * b % 5 times 4^e (power ties among the grid's integer weights); b <
 * 240 that minus 2 (negative weights too); b >= 240 any finite double,
 * as fz_coord.  4^e saturates at DBL_MAX and rounds to 0 below the
 * subnormals.                                                            */
static double fz_weight(fz_in *in, int e)
{
    unsigned b = fz_byte(in);
    if (b >= 240) {
        in->at--;
        return fz_coord(in, e);
    }
    const double k = b < 200 ? (double)(b % 5) : (double)(b % 5) - 2.0;
    const double w = ldexp(k, 2 * e);
    return isfinite(w) ? w : copysign(DBL_MAX, w);
}

/* The same point (-0.0 is 0.0, as for the engine). */
static int fz_same(const double *a, const double *b)
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

typedef struct fz_state {
    dd_tri *t;
    double xyz[3 * FZ_MAX_POINTS];   /* the point of each input index */
    uint32_t np;                     /* input indices so far */
    int scale;                       /* the scaled grid's exponent */
    /* a weighted session */
    int weighted, discard;
    double w[FZ_MAX_POINTS];         /* the weight of each input index */
    unsigned char gone[FZ_MAX_POINTS];   /* deleted (not hidden nor forgotten) */
} fz_state;

/* The points a build from scratch takes: the vertices, and with hidden
 * points kept the hidden ones too.                                      */
static int fz_alive(const fz_state *s, uint32_t i)
{
    return dd_is_vertex(s->t, i) || (s->weighted && !s->discard && dd_is_hidden(s->t, i));
}

/* The canonical form of a build from scratch of the points of s->t
 * (fz_alive), its indices mapped back to s->t's; *out malloc'd; with
 * hid not NULL (weighted), the hidden points' indices too, *hid malloc'd.
 * 0, or 1 on a bug.                                                      */
static int fz_scratch(const fz_state *s, int32_t **out, size_t *nout, uint32_t **hid, size_t *nhid)
{
    uint32_t map[FZ_MAX_POINTS], m = 0;
    double pts[3 * FZ_MAX_POINTS], w[FZ_MAX_POINTS];
    for (uint32_t i = 0; i < s->np; i++)
        if (fz_alive(s, i)) {
            map[m] = i;
            memcpy(pts + 3 * m, s->xyz + 3 * i, 3 * sizeof *pts);
            w[m] = s->w[i];
            m++;
        }
    dd_tri *r = NULL;
    char msg[256];
    dd_status st = dd_create_ex(&r, pts, s->weighted ? w : NULL, m, s->discard ? DD_DISCARD_HIDDEN : 0, msg, sizeof msg);
    if (st != DD_OK) {
        fprintf(stderr, "fuzz ops: the %u points left do not build from scratch: %s\n", m, msg);
        return 1;
    }
    int32_t *c = NULL;
    size_t nc = 0;
    if (dd_canonical(r, &c, &nc) != DD_OK || (hid && dd_hidden(r, hid, nhid) != DD_OK)) {
        free(c);
        dd_free(r);
        return 1;
    }
    dd_free(r);
    canon_remap(c, nc, map);
    if (hid) canon_remap_list(*hid, *nhid, map);
    *out = c;
    *nout = nc;
    return 0;
}

/* 1 if input i is an exact copy (point and weight) of another point
 * left in s->t (fz_alive): which of equal copies stays hidden is not
 * the build from scratch's to say.                                       */
static int fz_has_twin(const fz_state *s, uint32_t i)
{
    for (uint32_t k = 0; k < s->np; k++)
        if (k != i && fz_alive(s, k) && !memcmp(s->xyz + 3 * k, s->xyz + 3 * i, 3 * sizeof *s->xyz) && s->w[k] == s->w[i])
            return 1;
    return 0;
}

/* Weighted: the hidden sets of s->t and of the build from scratch are
 * equal but for exact copies; discarding, both are empty.  0, or 1.    */
static int fz_same_hidden(const fz_state *s, const uint32_t *hs, size_t nhs, const char *after)
{
    uint32_t *h = NULL;
    size_t nh = 0;
    if (dd_hidden(s->t, &h, &nh) != DD_OK) return 1;
    int bad = s->discard && (nh || nhs);
    for (size_t i = 0, j = 0; !bad && (i < nh || j < nhs);) {
        if (i < nh && j < nhs && h[i] == hs[j]) i++, j++;
        else if (j == nhs || (i < nh && h[i] < hs[j])) bad = !fz_has_twin(s, h[i++]);
        else bad = !fz_has_twin(s, hs[j++]);
    }
    if (bad) fprintf(stderr, "fuzz ops: after %s: %zu hidden points, from scratch %zu or others\n", after, nh, nhs);
    free(h);
    return bad;
}

/* dd_check, then the canonical form against the one from scratch. */
static int fz_verify(const fz_state *s, const char *after)
{
    char why[256];
    dd_status st = dd_check_msg(s->t, why, sizeof why);
    if (st != DD_OK) {
        fprintf(stderr, "fuzz ops: dd_check after %s: %s: %s\n", after, dd_status_name(st), why);
        return 1;
    }
    int32_t *a = NULL, *b = NULL;
    uint32_t *hs = NULL;
    size_t na = 0, nb = 0, nhs = 0;
    if (dd_canonical(s->t, &a, &na) != DD_OK || fz_scratch(s, &b, &nb, s->weighted ? &hs : NULL, &nhs)) {
        free(a);
        free(b);
        return 1;
    }
    int same = na == nb && !memcmp(a, b, 4 * na * sizeof *a);
    free(a);
    free(b);
    if (!same) fprintf(stderr, "fuzz ops: after %s: %zu cells, from scratch %zu or different cells\n", after, na, nb);
    if (same && s->weighted) same = !fz_same_hidden(s, hs, nhs, after);
    free(hs);
    return !same;
}

/* The canonical form's hash, with the hidden set and the index range. */
static uint64_t fz_hash(dd_tri *t)
{
    int32_t *a = NULL;
    uint32_t *hid = NULL;
    size_t na = 0, nh = 0;
    if (dd_canonical(t, &a, &na) != DD_OK) return 0;
    uint64_t h = dd_canonical_hash(a, na);
    free(a);
    if (dd_hidden(t, &hid, &nh) != DD_OK) return 0;
    for (size_t i = 0; i < nh; i++) h = (h ^ hid[i]) * 0x100000001b3ull;
    free(hid);
    return (h ^ dd_num_input(t)) * 0x100000001b3ull;
}

/* A refused operation leaves the triangulation as it was. */
static int fz_unchanged(const fz_state *s, uint64_t before, const char *what, dd_status st)
{
    if (fz_hash(s->t) == before) return 0;
    fprintf(stderr, "fuzz ops: %s was refused (%s) but changed the triangulation\n", what, dd_status_name(st));
    return 1;
}

/* 1 if q equals the point of a vertex of t. */
static int fz_is_vertex_point(const fz_state *s, const double q[3])
{
    for (uint32_t i = 0; i < s->np; i++)
        if (dd_is_vertex(s->t, i) && fz_same(s->xyz + 3 * i, q)) return 1;
    return 0;
}

/* The k-th vertex (mod their number) of t, or UINT32_MAX if none. */
static uint32_t fz_vertex(const fz_state *s, unsigned k)
{
    uint32_t nv = dd_num_vertices(s->t);
    if (nv == 0) return UINT32_MAX;
    k %= nv;
    for (uint32_t i = 0; i < s->np; i++)
        if (dd_is_vertex(s->t, i) && k-- == 0) return i;
    return UINT32_MAX;
}

/* What a byte names in a weighted session: with hidden points kept and
 * the top bit set, the k-th kept hidden point (k the low bits), if any;
 * else the vertex fz_vertex names.                                      */
static uint32_t fz_target(const fz_state *s, unsigned b)
{
    if (s->weighted && !s->discard && (b & 0x80)) {
        uint32_t nh = 0, k = b & 0x7f;
        for (uint32_t i = 0; i < s->np; i++) nh += (uint32_t)dd_is_hidden(s->t, i);
        for (uint32_t i = 0; i < s->np && nh > 0; i++)
            if (dd_is_hidden(s->t, i) && k-- % nh == 0) return i;
    }
    return fz_vertex(s, b);
}

static const char *fz_variant(unsigned b)
{
    size_t nv = 0;
    while (dd_variant_name(nv)) nv++;
    return dd_variant_name(b % nv);
}

/* ---- weighted sessions ---------------------------------------------------- */

/* The vertex whose weighted point is exactly (q, w), or UINT32_MAX. */
static uint32_t fz_weighted_twin(const fz_state *s, const double q[3], double w)
{
    for (uint32_t i = 0; i < s->np; i++)
        if (dd_is_vertex(s->t, i) && fz_same(s->xyz + 3 * i, q) && s->w[i] == w) return i;
    return UINT32_MAX;
}

/* create: a mode byte (bit 0: DD_DISCARD_HIDDEN), then 4 to 32 weighted
 * points.  Refusals: fewer than 4 vertices, or all in a plane.          */
static int fz_wcreate(fz_state *s, fz_in *in)
{
    const int discard = fz_byte(in) & 1;
    uint32_t m = 4 + fz_byte(in) % 29;
    double pts[3 * 32], w[32];
    for (uint32_t i = 0; i < m; i++) {
        fz_point(in, s->scale, pts + 3 * i);
        w[i] = fz_weight(in, s->scale);
    }
    dd_tri *t = NULL;
    char msg[256], what[96];
    dd_status st = dd_create_ex(&t, pts, w, m, discard ? DD_DISCARD_HIDDEN : 0, msg, sizeof msg);
    if (st != DD_OK) {
        if (st == DD_ERR_TOO_FEW || st == DD_ERR_COLLINEAR || st == DD_ERR_COPLANAR || st == DD_ERR_DIMENSION) return 0;
        fprintf(stderr, "fuzz ops: weighted create of %u points: %s: %s\n", m, dd_status_name(st), msg);
        return 1;
    }
    dd_free(s->t);
    s->t = t;
    s->discard = discard;
    memcpy(s->xyz, pts, 3 * m * sizeof *pts);
    memcpy(s->w, w, m * sizeof *w);
    memset(s->gone, 0, sizeof s->gone);
    s->np = m;
    snprintf(what, sizeof what, "weighted create of %u points (%s)", m, discard ? "discard" : "keep");
    return fz_verify(s, what);
}

/* insert (dd_insert_weighted): a new index, or a deleted one reused;
 * a vertex's exact weighted point names that vertex and changes nothing. */
static int fz_winsert(fz_state *s, fz_in *in, uint64_t before)
{
    double q[3];
    char what[128];
    fz_point(in, s->scale, q);
    const double w = fz_weight(in, s->scale);
    if (s->np == FZ_MAX_POINTS) return 0;
    const uint32_t twin = fz_weighted_twin(s, q, w);
    uint32_t idx = UINT32_MAX;
    snprintf(what, sizeof what, "weighted insert of (%g, %g, %g; %g)", q[0], q[1], q[2], w);
    const dd_status st = dd_insert_weighted(s->t, q, w, &idx);
    if (st == DD_OK && twin != UINT32_MAX && idx == twin) return fz_unchanged(s, before, what, st);
    const int fresh = idx == s->np || (idx < s->np && s->gone[idx] && dd_alias(s->t, idx) == idx);
    if (st == DD_OK && twin == UINT32_MAX && fresh) {
        memcpy(s->xyz + 3 * idx, q, sizeof q);
        s->w[idx] = w;
        s->gone[idx] = 0;
        if (idx == s->np) s->np++;
        return fz_verify(s, what);
    }
    if (st == DD_ERR_DUPLICATE && twin != UINT32_MAX) return fz_unchanged(s, before, what, st);
    fprintf(stderr, "fuzz ops: %s: %s (a vertex's weighted point: %d), index %u of %u: %s\n", what,
            dd_status_name(st), twin != UINT32_MAX, idx, s->np, dd_errmsg(s->t));
    return 1;
}

/* move of a vertex or a kept hidden point (fz_target): a byte picks
 * dd_move (even) or dd_move_weighted (odd), then the point and the
 * weight.  Onto another point's exact weighted point that is, or becomes
 * with v gone, a vertex: DD_ERR_DUPLICATE, so only that may refuse.    */
static int fz_wmove(fz_state *s, fz_in *in, uint64_t before)
{
    const uint32_t v = fz_target(s, fz_byte(in));
    const int weighted = fz_byte(in) & 1;
    double q[3];
    char what[128];
    fz_point(in, s->scale, q);
    double w = fz_weight(in, s->scale);
    if (v == UINT32_MAX) return 0;
    if (!weighted) w = s->w[v];
    int vtwin = 0, htwin = 0;                       /* another vertex's or point's exact copy */
    for (uint32_t i = 0; i < s->np; i++)
        if (i != v && fz_alive(s, i) && fz_same(s->xyz + 3 * i, q) && s->w[i] == w) {
            if (dd_is_vertex(s->t, i)) vtwin = 1;
            else htwin = 1;
        }
    const int dup = vtwin || htwin;
    snprintf(what, sizeof what, "%s of %u to (%g, %g, %g; %g)", weighted ? "move_weighted" : "move", v, q[0], q[1],
             q[2], w);
    const dd_status st = weighted ? dd_move_weighted(s->t, v, q, w) : dd_move(s->t, v, q);
    if (st == DD_OK && !vtwin) {
        memcpy(s->xyz + 3 * v, q, sizeof q);
        s->w[v] = w;
        return fz_verify(s, what);
    }
    if ((st == DD_ERR_DUPLICATE && dup) || st == DD_ERR_DIMENSION || st == DD_ERR_UNSUPPORTED)
        return fz_unchanged(s, before, what, st);
    fprintf(stderr, "fuzz ops: %s: %s (another point's weighted point: %d): %s\n", what, dd_status_name(st), dup,
            dd_errmsg(s->t));
    return 1;
}

/* reinsert: a deleted point (not a hidden or forgotten one), its weight. */
static int fz_wreinsert(fz_state *s, fz_in *in, uint64_t before)
{
    uint32_t k = fz_byte(in), v = UINT32_MAX;
    char what[96];
    for (uint32_t i = 0; i < s->np && v == UINT32_MAX; i++)
        if (s->gone[(k + i) % s->np]) v = (k + i) % s->np;
    if (v == UINT32_MAX) return 0;
    const int dup = fz_weighted_twin(s, s->xyz + 3 * v, s->w[v]) != UINT32_MAX;
    snprintf(what, sizeof what, "weighted reinsert of %u", v);
    const dd_status st = dd_reinsert(s->t, v);
    if (st == DD_OK && !dup) {
        s->gone[v] = 0;
        return fz_verify(s, what);
    }
    if ((st == DD_ERR_DUPLICATE && dup) || st == DD_ERR_UNSUPPORTED) return fz_unchanged(s, before, what, st);
    fprintf(stderr, "fuzz ops: %s: %s (a vertex's weighted point: %d): %s\n", what, dd_status_name(st), dup,
            dd_errmsg(s->t));
    return 1;
}

static int dd_fuzz_ops(const uint8_t *data, size_t n)
{
    fz_in in = {data, n, 0};
    fz_state *s = calloc(1, sizeof *s);
    if (!s) return 0;
    int bad = 0;
    char what[96];
    if (n > 0 && data[0] == FZ_WEIGHTED) s->weighted = 1, in.at = 1;
    for (int op = 0; op < FZ_MAX_OPS && fz_more(&in) && !bad; op++) {
        unsigned code = fz_byte(&in) % 8;
        if (s->t == NULL) code = 0;                         /* nothing to work on yet */
        uint64_t before = s->t ? fz_hash(s->t) : 0;
        dd_status st;
        if (s->weighted && (code == 0 || code == 3 || code == 4 || code == 6)) {   /* their weighted forms */
            bad = code == 0 ? fz_wcreate(s, &in) : code == 3 ? fz_winsert(s, &in, before)
                : code == 4 ? fz_wmove(s, &in, before) : fz_wreinsert(s, &in, before);
            continue;
        }
        switch (code) {
        case 0: {                                           /* create */
            uint32_t m = 4 + fz_byte(&in) % 29;
            double pts[3 * 32];
            for (uint32_t i = 0; i < m; i++) fz_point(&in, s->scale, pts + 3 * i);
            dd_tri *t = NULL;
            char msg[256];
            st = dd_create(&t, pts, m, msg, sizeof msg);
            if (st == DD_OK) {
                dd_free(s->t);
                s->t = t;
                memcpy(s->xyz, pts, 3 * m * sizeof *pts);
                s->np = m;
                snprintf(what, sizeof what, "create of %u points", m);
                bad = fz_verify(s, what);
            } else if (st != DD_ERR_TOO_FEW && st != DD_ERR_COLLINEAR && st != DD_ERR_COPLANAR) {
                fprintf(stderr, "fuzz ops: create of %u points: %s: %s\n", m, dd_status_name(st), msg);
                bad = 1;
            }
            break;
        }
        case 1: case 2: {                                   /* delete */
            uint32_t v = fz_target(s, fz_byte(&in));
            const char *var = fz_variant(fz_byte(&in));
            snprintf(what, sizeof what, "delete of %u with %s", v, var);
            st = dd_delete_with(s->t, v, var);
            if (st == DD_OK) s->gone[v] = 1, bad = fz_verify(s, what);
            else if (st == DD_ERR_DIMENSION || (s->weighted && st == DD_ERR_UNSUPPORTED))
                bad = fz_unchanged(s, before, what, st);
            else {
                fprintf(stderr, "fuzz ops: %s: %s: %s\n", what, dd_status_name(st), dd_errmsg(s->t));
                bad = 1;
            }
            break;
        }
        case 3: {                                           /* insert */
            double q[3];
            uint32_t idx = UINT32_MAX;
            fz_point(&in, s->scale, q);
            if (s->np == FZ_MAX_POINTS) break;
            int dup = fz_is_vertex_point(s, q);
            snprintf(what, sizeof what, "insert of (%g, %g, %g)", q[0], q[1], q[2]);
            st = dd_insert(s->t, q, &idx);
            /* a new index, or the index of a deleted vertex, reused */
            const int fresh = idx == s->np || (idx < s->np && dd_alias(s->t, idx) == idx);
            if (st == DD_OK && !dup && fresh) {
                memcpy(s->xyz + 3 * idx, q, sizeof q);
                if (idx == s->np) s->np++;
                bad = fz_verify(s, what);
            } else if (st == DD_ERR_DUPLICATE && dup) {
                bad = fz_unchanged(s, before, what, st) || dd_num_input(s->t) != s->np;
            } else {
                fprintf(stderr, "fuzz ops: %s: %s (a vertex's point: %d), index %u of %u\n", what,
                        dd_status_name(st), dup, idx, s->np);
                bad = 1;
            }
            break;
        }
        case 4: {                                           /* move a vertex */
            uint32_t v = fz_vertex(s, fz_byte(&in));
            double q[3];
            fz_point(&in, s->scale, q);
            if (v == UINT32_MAX) break;
            int dup = fz_is_vertex_point(s, q) && !fz_same(s->xyz + 3 * v, q);
            snprintf(what, sizeof what, "move of %u to (%g, %g, %g)", v, q[0], q[1], q[2]);
            st = dd_move(s->t, v, q);
            if (st == DD_OK && !dup) {
                memcpy(s->xyz + 3 * v, q, sizeof q);
                bad = fz_verify(s, what);
            } else if ((st == DD_ERR_DUPLICATE && dup) || st == DD_ERR_DIMENSION) {
                bad = fz_unchanged(s, before, what, st);
            } else {
                fprintf(stderr, "fuzz ops: %s: %s (a vertex's point: %d): %s\n", what, dd_status_name(st), dup,
                        dd_errmsg(s->t));
                bad = 1;
            }
            break;
        }
        case 5: {                                           /* delete_set */
            uint32_t m = 1 + fz_byte(&in) % 6, vs[6], k = 0;
            for (uint32_t i = 0; i < m; i++) {
                uint32_t v = fz_target(s, fz_byte(&in)), again = 0;
                for (uint32_t j = 0; j < k; j++) again |= vs[j] == v;
                if (!again && v != UINT32_MAX) vs[k++] = v;
            }
            const char *var = fz_variant(fz_byte(&in));
            snprintf(what, sizeof what, "delete_set of %u vertices with %s", k, var);
            st = dd_delete_set_with(s->t, vs, k, var);
            if (st == DD_OK) {
                for (uint32_t i = 0; i < k; i++) s->gone[vs[i]] = 1;
                bad = fz_verify(s, what);
            } else if (st == DD_ERR_DIMENSION || (s->weighted && st == DD_ERR_UNSUPPORTED))
                bad = fz_unchanged(s, before, what, st);
            else {
                fprintf(stderr, "fuzz ops: %s: %s: %s\n", what, dd_status_name(st), dd_errmsg(s->t));
                bad = 1;
            }
            break;
        }
        case 6: {                                           /* reinsert a deleted point */
            uint32_t k = fz_byte(&in), v = UINT32_MAX;
            for (uint32_t i = 0; i < s->np; i++) {
                uint32_t j = (k + i) % s->np;
                if (!dd_is_vertex(s->t, j) && dd_alias(s->t, j) == j) { v = j; break; }
            }
            if (v == UINT32_MAX) break;
            int dup = fz_is_vertex_point(s, s->xyz + 3 * v);
            snprintf(what, sizeof what, "reinsert of %u", v);
            st = dd_reinsert(s->t, v);
            if (st == DD_OK && !dup) bad = fz_verify(s, what);
            else if (st == DD_ERR_DUPLICATE && dup) bad = fz_unchanged(s, before, what, st);
            else {
                fprintf(stderr, "fuzz ops: %s: %s (a vertex's point: %d): %s\n", what, dd_status_name(st), dup,
                        dd_errmsg(s->t));
                bad = 1;
            }
            break;
        }
        default: {                                          /* test controls, the grid's scale */
            unsigned b = fz_byte(&in);
            s->scale = fz_scales[fz_byte(&in) % 16];
#ifdef DD_TEST_BUILD
            dd_test_control(s->t, DD_TEST_SCALAR, b & 1);
            dd_test_control(s->t, DD_TEST_NO_SINGLE, b >> 1 & 1);
            dd_test_control(s->t, DD_TEST_SPOIL_SINGLE, b >> 2 & 1);
            dd_test_control(s->t, DD_TEST_NARROWER, b >> 3 & 1);
#else
            (void)b;
#endif
            break;
        }
        }
    }
    dd_free(s->t);
    free(s);
    return bad;
}

#endif
