/*
 * build.c -- construction of DT(S) (DESIGN 5).
 *
 * Owns: input validation (NaN, infinities, duplicates, too few points,
 * collinear and coplanar sets), the BRIO + Hilbert insertion order, the
 * first tetrahedron, and the incremental loop (mesh.c inserts).
 *
 * Duplicates: an open-addressing hash on the exact coordinates (-0.0 as
 * +0.0) maps each input to the first input holding the same point; with
 * weights, the same weighted point (a point at another's position with
 * another weight is an input of its own, for regular.c's rule).
 *
 * Weights (DESIGN 12): checked, stored per vertex id, and each point
 * inserted by regular.c's rule (dd_insert_power) instead of mesh.c's;
 * the choice is made once, for the whole loop.
 *
 * Order: each kept point draws its BRIO round from a hash of its input
 * index with a fixed seed: rounds grow by a factor of 8 (the last holds
 * about 7/8 of the points, the one before 7/64, ..., the first about 64
 * points or fewer).  Insertion goes round by round, smallest first, each
 * round along a 3D Hilbert curve (Skilling's transform on 16 bits per axis)
 * of the kept points' bounding box, as CGAL's spatial_sort and geogram do.
 * Round and Hilbert index form one 52-bit key, so a single sequential pass
 * over the coordinates and one LSD radix sort give the whole order; it is
 * a deterministic function of the input.  The result depends only on the
 * point set (the perturbed DT is unique), not on this order.
 */
#include "mesh/mesh.h"
#include "mesh/hidden.h"
#include "dtdel/alloc.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- hashing ------------------------------------------------------------- */

/* Hash of the exact coordinates; -0.0 hashes as +0.0, since dd_lex_cmp
 * holds them equal.  Each coordinate goes through dd_mix64: coordinates that
 * differ only in their high bits (grids) must not collide early.          */
static uint64_t hash_point(const double *p)
{
    uint64_t h = 0;
    for (int c = 0; c < 3; c++) {
        double x = p[c] == 0 ? 0.0 : p[c];
        uint64_t bits;
        memcpy(&bits, &x, sizeof bits);
        h = dd_mix64(h ^ bits);
    }
    return h;
}

/* The weighted point's hash: the point's, and its weight's likewise. */
static uint64_t hash_weighted(const double *p, double w)
{
    double x = w == 0 ? 0.0 : w;
    uint64_t bits;
    memcpy(&bits, &x, sizeof bits);
    return dd_mix64(hash_point(p) ^ bits);
}

/* The hash dedup keys input i by: of its point, or of its weighted point
 * (w not NULL), where a point at another's position with another weight
 * is another point.                                                     */
static inline uint64_t hash_input(const double *pts, const double *w, uint32_t i)
{
    return w ? hash_weighted(pts + 3 * (size_t)i, w[i]) : hash_point(pts + 3 * (size_t)i);
}

/* ---- Hilbert order ------------------------------------------------------- */

/* Spreads the low 16 bits of v to bits 0, 3, 6, ..., 45. */
static uint64_t spread3(uint64_t v)
{
    v &= 0xFFFF;
    v = (v | v << 16) & 0x0000FF0000FFull;
    v = (v | v << 8) & 0x00F00F00F00Full;
    v = (v | v << 4) & 0x0C30C30C30C3ull;
    v = (v | v << 2) & 0x249249249249ull;
    return v;
}

/* Skilling's transform: axes -> Hilbert index, b <= 16 bits per axis, the
 * bits of x[0] most significant in each triple.  Branch-free on scalars
 * (the axes' bits are unpredictable, and an array would keep the chain of
 * updates of x0 in memory).                                               */
static uint64_t hilbert_key(const uint32_t x[3], int b)
{
    uint32_t x0 = x[0], x1 = x[1], x2 = x[2];
    for (uint32_t q = 1u << (b - 1); q > 1; q >>= 1) {
        /* axis i: bit q set -> invert the low bits of x0, else swap them
         * between x0 and xi                                              */
        uint32_t p = q - 1, hit, s;
        x0 ^= p & (0u - ((x0 & q) != 0));
        hit = 0u - ((x1 & q) != 0);
        s = (x0 ^ x1) & p & ~hit;
        x0 ^= (p & hit) | s;
        x1 ^= s;
        hit = 0u - ((x2 & q) != 0);
        s = (x0 ^ x2) & p & ~hit;
        x0 ^= (p & hit) | s;
        x2 ^= s;
    }
    /* Gray decode */
    x1 ^= x0;
    x2 ^= x1;
    uint32_t t = 0;
    for (uint32_t q = 1u << (b - 1); q > 1; q >>= 1)
        t ^= (q - 1) & (0u - ((x2 & q) != 0));
    x0 ^= t;
    x1 ^= t;
    x2 ^= t;
    return spread3(x0) << 2 | spread3(x1) << 1 | spread3(x2);
}

typedef struct keyed { uint64_t key; uint32_t id; } keyed;

/* Composite key: BRIO round in bits 48..51 (at most 10 rounds for 32-bit
 * n), Hilbert index in bits 0..47; radix-sorted 13 bits a pass.           */
#define KEY_BITS 52
#define DIGIT_BITS 13
#define NDIGIT (1u << DIGIT_BITS)
#define NPASS (KEY_BITS / DIGIT_BITS)
#define BRIO_SEED 0x243F6A8885A308D3ull

/* BRIO round of input i among rounds 0..depth: depth with probability 7/8,
 * depth - 1 with 7/64, ..., 0 with 8^-depth (a leading zero octal digit
 * of a hash of i moves the point one round earlier).                      */
static uint64_t brio_round(uint32_t i, uint32_t depth)
{
    uint64_t r = dd_mix64(BRIO_SEED + ((uint64_t)i + 1) * 0x9E3779B97F4A7C15ull);
    uint32_t level = 0;
    while (level < depth && ((r >> (61 - 3 * level)) & 7u) == 0) level++;
    return depth - level;
}

static int cmp_keyed(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    return x->key < y->key ? -1 : x->key > y->key ? 1 : (x->id > y->id) - (x->id < y->id);
}

/* Below this many points a comparison sort of the keys beats the radix
 * sort's 128 KiB of counters.                                            */
#define RADIX_MIN 2048

dd_status dd_spatial_order(const double *pts, uint32_t *ids, uint32_t n, int brio)
{
    if (n < 2) return DD_OK;
    /* as many factor-8 rounds as take n down to 64 points or fewer */
    uint32_t depth = 0;
    for (uint32_t hi = n; brio && hi > 64; hi /= 8) depth++;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t k = 0; k < n; k++) {
        const double *p = pts + 3 * (size_t)ids[k];
        for (int c = 0; c < 3; c++) {
            if (p[c] < lo[c]) lo[c] = p[c];
            if (p[c] > hi[c]) hi[c] = p[c];
        }
    }
    double ext = 0;
    for (int c = 0; c < 3; c++) if (hi[c] - lo[c] > ext) ext = hi[c] - lo[c];
    /* bits per axis: 16 in a construction's rounds; else about 4 boxes a
     * point along each axis, as fine an order with fewer steps of the key
     * and fewer radix passes                                             */
    int bits = 16;
    while (!brio && bits > 4 && (1ull << (3 * (bits - 3))) > n) bits--;
    const double top = (double)((1u << bits) - 1);
    /* The grid coordinates (x - lo) * scale in doubles, unless the extent
     * overflows (coordinates of both signs beyond DBL_MAX / 2) or its
     * reciprocal does (subnormal extents): then in halves and scaled by
     * powers of two, which nothing can overflow.                        */
    const int plain = ext > 0 && ext <= DBL_MAX && top / ext <= DBL_MAX;
    double scale = plain ? top / ext : 0.0, half = 0;
    int eh = 0;
    if (!plain) {
        for (int c = 0; c < 3; c++) half = fmax(half, 0.5 * hi[c] - 0.5 * lo[c]);
        eh = half > 0 ? ilogb(half) : 0;
        scale = half > 0 ? top / ldexp(half, -eh) : 0.0;
    }
    const int radix = n >= RADIX_MIN;
    keyed *a = dd_malloc(2 * (size_t)n * sizeof *a);
    uint32_t *count = radix ? dd_calloc((size_t)NPASS * NDIGIT, sizeof *count) : NULL;
    if (!a || (radix && !count)) { dd_mfree(a); dd_mfree(count); return DD_ERR_NOMEM; }
    keyed *const buf = a;
    keyed *b = a + n;
    for (uint32_t k = 0; k < n; k++) {
        const double *p = pts + 3 * (size_t)ids[k];
        uint32_t x[3];
        for (int c = 0; c < 3; c++) {
            double q = plain ? (p[c] - lo[c]) * scale : ldexp(0.5 * p[c] - 0.5 * lo[c], -eh) * scale;
            x[c] = !(q > 0) ? 0 : q >= top ? (uint32_t)top : (uint32_t)q;
        }
        uint64_t key = brio_round(ids[k], depth) << 48 | hilbert_key(x, bits);
        a[k].key = key;
        a[k].id = ids[k];
        for (uint32_t d = 0; radix && d < NPASS; d++)
            count[d * NDIGIT + ((key >> (d * DIGIT_BITS)) & (NDIGIT - 1))]++;
    }
    if (!radix) qsort(a, n, sizeof *a, cmp_keyed);
    for (uint32_t d = 0; radix && d < NPASS; d++) {
        uint32_t shift = d * DIGIT_BITS, *cnt = count + d * NDIGIT;
        if (cnt[(a[0].key >> shift) & (NDIGIT - 1)] == n) continue; /* one digit */
        uint32_t sum = 0;
        for (uint32_t v = 0; v < NDIGIT; v++) { uint32_t c = cnt[v]; cnt[v] = sum; sum += c; }
        for (uint32_t k = 0; k < n; k++) b[cnt[(a[k].key >> shift) & (NDIGIT - 1)]++] = a[k];
        keyed *tmp = a; a = b; b = tmp;
    }
    for (uint32_t k = 0; k < n; k++) ids[k] = a[k].id;
    dd_mfree(buf);
    dd_mfree(count);
    return DD_OK;
}

/* ---- validation and duplicates ------------------------------------------- */

/* dd_dedup_points (mesh.h): open addressing with linear probing on a table of kept ids, at most
 * half full; the inputs are scanned in order, so the id found for a point
 * is its first occurrence.  A slot keeps the high half of the point's hash
 * beside the id: a probe compares coordinates (a read at a random place
 * of the input) only when those agree.  The slot of input i + 16 is
 * fetched ahead (the table, 16 bytes a point, is out of cache for large
 * n).  Cost O(n) expected.                                               */
#define DEDUP_AHEAD 16
dd_status dd_dedup_points(dd_tri *t, const double *pts, const double *w, uint32_t n, uint32_t *first,
                       uint32_t *ids, uint32_t *nkept)
{
    size_t cap = 16;
    while (cap < 2 * (size_t)n) cap <<= 1;
    uint64_t *slot = dd_malloc(cap * sizeof *slot);
    if (!slot) return dd_fail(t, DD_ERR_NOMEM, "out of memory");
    memset(slot, 0xFF, cap * sizeof *slot); /* empty: id UINT32_MAX > any id */
    size_t mask = cap - 1;
    uint32_t m = 0;
    uint64_t ahead[DEDUP_AHEAD];             /* the hashes of i .. i + 15 */
    for (uint32_t i = 0; i < DEDUP_AHEAD && i < n; i++) ahead[i] = hash_input(pts, w, i);
    for (uint32_t i = 0; i < n; i++) {
        const double *p = pts + 3 * (size_t)i;
        uint64_t hp = ahead[i % DEDUP_AHEAD], tag = hp >> 32 << 32;
        if (i + DEDUP_AHEAD < n) {
            uint64_t hn = hash_input(pts, w, i + DEDUP_AHEAD);
            ahead[i % DEDUP_AHEAD] = hn;
            __builtin_prefetch(&slot[hn & mask]);
        }
        size_t h = (size_t)hp & mask;
        for (;; h = (h + 1) & mask) {
            uint64_t e = slot[h];
            if (e == UINT64_MAX) {
                slot[h] = tag | i;
                first[i] = i;
                ids[m++] = i;
                break;
            }
            uint32_t id = (uint32_t)e;
            if ((e ^ tag) >> 32 == 0 && dd_lex_cmp(pts + 3 * (size_t)id, p) == 0 && (!w || w[id] == w[i])) {
                first[i] = id;
                break;
            }
        }
    }
    dd_mfree(slot);
    *nkept = m;
    return DD_OK;
}

/* ---- the first tetrahedron ----------------------------------------------- */

dd_status dd_find_simplex(dd_pred *pr, const double *pts, uint32_t *ids, uint32_t n)
{
    if (n < 2) return DD_ERR_TOO_FEW;
#define PT(i) (pts + 3 * (size_t)(i))
    const double *a = PT(ids[0]);
    uint32_t k = 1;             /* weighted points may share a position */
    while (k < n && dd_lex_cmp(a, PT(ids[k])) == 0) k++;
    if (k == n) return DD_ERR_COLLINEAR;
    uint32_t tmp = ids[1]; ids[1] = ids[k]; ids[k] = tmp;
    const double *b = PT(ids[1]);
    k = 2;
    while (k < n && dd_orient_coplanar(pr, a, b, PT(ids[k])) == 0) k++;
    if (k == n) return DD_ERR_COLLINEAR;
    tmp = ids[2]; ids[2] = ids[k]; ids[k] = tmp;
    const double *c = PT(ids[2]);
    k = 3;
    while (k < n && dd_orient3d(pr, a, b, c, PT(ids[k])) == 0) k++;
#undef PT
    if (k == n) return DD_ERR_COPLANAR;
    tmp = ids[3]; ids[3] = ids[k]; ids[k] = tmp;
    return DD_OK;
}

dd_status dd_pick_simplex(dd_tri *t, const double *pts, uint32_t *ids, uint32_t n)
{
    if (n < 4)
        return dd_fail(t, DD_ERR_TOO_FEW, "need at least 4 distinct points, got %u", n);
    dd_status s = dd_find_simplex(&t->pred, pts, ids, n);
    if (s == DD_ERR_COLLINEAR) return dd_fail(t, s, "all %u points are collinear", n);
    if (s == DD_ERR_COPLANAR) return dd_fail(t, s, "all %u points are coplanar", n);
    return s;
}

/* ---- dd_create ------------------------------------------------------------ */

static dd_status report(dd_tri *t, dd_status s, char *msg, size_t msglen)
{
    if (msg && msglen) snprintf(msg, msglen, "%s", t->err);
    dd_tri_destroy(t);
    return s;
}

/* NaN and infinities, in the coordinates, then in the weights (if any). */
static dd_status check_input(dd_tri *t, const double *xyz, const double *w, uint32_t n)
{
    for (uint32_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            double x = xyz[3 * (size_t)i + (size_t)c];
            if (isnan(x)) return dd_fail(t, DD_ERR_NAN, "point %u: coordinate %c is NaN", i, "xyz"[c]);
            if (isinf(x)) return dd_fail(t, DD_ERR_INFINITE, "point %u: coordinate %c is infinite", i, "xyz"[c]);
        }
    for (uint32_t i = 0; w && i < n; i++) {
        if (isnan(w[i])) return dd_fail(t, DD_ERR_NAN, "point %u: the weight is NaN", i);
        if (isinf(w[i])) return dd_fail(t, DD_ERR_INFINITE, "point %u: the weight is infinite", i);
    }
    return DD_OK;
}

/* A weighted t's weights (by vertex id: input ids[k] for id k) and its
 * hidden points' state.                                                */
static dd_status make_weighted(dd_tri *t, const double *w, const uint32_t *ids, uint32_t m)
{
    t->wt = dd_malloc((size_t)t->cap_v * sizeof *t->wt);
    if (!t->wt) return DD_ERR_NOMEM;
    for (uint32_t k = 0; k < m; k++) t->wt[k] = w[ids[k]];
    return dd_hidden_init(t, !(t->flags & DD_DISCARD_HIDDEN_FLAG));
}

/* Vertex ids 4 .. m - 1 inserted in order: by mesh.c's rule, or, in a
 * weighted t, by regular.c's (a duplicate cannot occur: dedup merged
 * equal weighted points).                                              */
static dd_status insert_all(dd_tri *t, uint32_t m)
{
    dd_status s = DD_OK;
    if (!t->wt) {
        for (uint32_t k = 4; k < m && s == DD_OK; k++) s = dd_build_insert(t, k);
        return s;
    }
    dd_fate fate;
    uint32_t dup;
    for (uint32_t k = 4; k < m && s == DD_OK; k++) s = dd_insert_power(t, k, t->hint, 1, &fate, &dup);
    return s;
}

dd_status dd_mesh_create(dd_tri **out, const double *xyz, const double *weights, uint32_t n, unsigned flags,
                         char *msg, size_t msglen)
{
    *out = NULL;
    if (msg && msglen) msg[0] = 0;
    dd_tri *t;
    dd_status s = dd_tri_alloc(&t, n);
    if (s != DD_OK) {
        if (msg && msglen) snprintf(msg, msglen, "out of memory");
        return s;
    }
    t->flags = flags;
    if ((s = check_input(t, xyz, weights, n)) != DD_OK) return report(t, s, msg, msglen);
    uint32_t *ids = dd_malloc(2 * (size_t)(n ? n : 1) * sizeof *ids);
    if (!ids) return report(t, dd_fail(t, DD_ERR_NOMEM, "out of memory"), msg, msglen);
    uint32_t *first = ids + n;
    /* Input order -> insertion order: drop duplicates, BRIO + Hilbert, the
     * first tetrahedron in front.  Vertex id k is then input ids[k].      */
    uint32_t m = 0;
    s = dd_dedup_points(t, xyz, weights, n, first, ids, &m);
    if (s == DD_OK) s = dd_spatial_order(xyz, ids, m, 1);
    if (s == DD_OK) s = dd_pick_simplex(t, xyz, ids, m);
    if (s == DD_OK) s = dd_reserve_cells(t, m < 8 ? 64 : 7 * m);
    if (s == DD_OK && weights && make_weighted(t, weights, ids, m) != DD_OK)
        s = dd_fail(t, DD_ERR_NOMEM, "out of memory");
    if (s != DD_OK) { dd_mfree(ids); return report(t, s, msg, msglen); }
    t->np = n;
    t->nvid = m;
    t->ndup = n - m;
    for (uint32_t k = 0; k < m; k++) {
        memcpy(t->xyz + 3 * (size_t)k, xyz + 3 * (size_t)ids[k], 3 * sizeof *xyz);
        t->v2in[k] = ids[k];
        t->vcell[k] = DD_NONE;
        t->in2v[ids[k]] = k;
    }
    for (uint32_t i = 0; i < n; i++) t->in2v[i] = t->in2v[first[i]];
    dd_mfree(ids);
    uint32_t first4[4] = {0, 1, 2, 3};
    dd_make_first_cells(t, first4);
    if ((s = insert_all(t, m)) != DD_OK) return report(t, s, msg, msglen);
    dd_shrink_cells(t);     /* the reserve above was a guess */
    if (dd_publish_all_cells(t) != DD_OK) return report(t, dd_fail(t, DD_ERR_NOMEM, "out of memory"), msg, msglen);
    (void)dd_grid_ready(t); /* where queries start (locate.c); none: longer walks */
    *out = t;
    return DD_OK;
}

/* ---- rebuilding without a set of vertices ----------------------------- */

/* The vertex ids now in t but not in the sorted ids[0..n), in id order:
 * the construction's BRIO + Hilbert order, a good insertion order still. */
static uint32_t kept_vertices(const dd_tri *t, const uint32_t *ids, size_t n, uint32_t *kept)
{
    uint32_t m = 0;
    size_t k = 0;
    for (uint32_t v = 0; v < t->nvid; v++) {
        while (k < n && ids[k] < v) k++;
        if (t->vcell[v] != DD_NONE && !(k < n && ids[k] == v)) kept[m++] = v;
    }
    return m;
}

/* Gives t the cells of s (and s t's old ones, for dd_tri_destroy). */
static void swap_cells(dd_tri *t, dd_tri *s)
{
#define SWAP(f) do { __typeof__(t->f) x_ = t->f; t->f = s->f; s->f = x_; } while (0)
    SWAP(cell); SWAP(cell_block); SWAP(stamp); SWAP(ncell); SWAP(cap_c); SWAP(nlive); SWAP(nfinite);
    SWAP(free_head); SWAP(nfree); SWAP(epoch); SWAP(inf_cell); SWAP(hint);
#undef SWAP
}

dd_status dd_rebuild_without(dd_tri *t, const uint32_t *ids, size_t n)
{
    dd_tri *s;
    uint32_t *kept = dd_malloc(((size_t)t->nvid + 1) * sizeof *kept), *vcell = dd_malloc((size_t)t->cap_v * sizeof *vcell);
    dd_status st = kept && vcell ? dd_tri_alloc_borrowed(&s) : DD_ERR_NOMEM;
    if (st != DD_OK) {
        dd_mfree(kept), dd_mfree(vcell);
        return dd_fail(t, st, "out of memory");
    }
    s->xyz = t->xyz;
    s->v2in = t->v2in;
    s->vcell = vcell;
    s->nvid = t->nvid;
    const uint32_t m = kept_vertices(t, ids, n, kept);
    for (uint32_t v = 0; v < t->nvid; v++) vcell[v] = DD_NONE;
    st = dd_pick_simplex(s, t->xyz, kept, m);
    if (st == DD_OK) st = dd_reserve_cells(s, m < 8 ? 64 : 7 * m);
    if (st == DD_OK) {
        dd_make_first_cells(s, kept);
        for (uint32_t k = 4; k < m && st == DD_OK; k++) st = dd_build_insert(s, kept[k]);
    }
    if (st == DD_OK) {
        swap_cells(t, s);
        memcpy(t->vcell, vcell, (size_t)t->nvid * sizeof *vcell);
        t->nvert = m;
        t->tets_created += s->tets_created;
        dd_shrink_cells(t);
    } else {
        dd_fail(t, st, "%s", st == DD_ERR_NOMEM ? "out of memory" : s->err);
    }
    dd_tri_destroy(s);
    dd_mfree(kept), dd_mfree(vcell);
    return st;
}
