/*
 * build.c -- construction of DT(S) (DESIGN 5).
 *
 * Owns: input validation (NaN, infinities, duplicates, too few points,
 * collinear and coplanar sets), the BRIO + Hilbert insertion order, the
 * first tetrahedron, and the incremental loop (mesh.c inserts).
 *
 * Order: the kept points are shuffled with a fixed seed, then split into
 * rounds growing by a factor of 8 (the smallest about 64 points) and each
 * round is sorted along a 3D Hilbert curve (Skilling's transform on 16 bits
 * per axis), as CGAL's spatial_sort and geogram do.  The result depends only
 * on the point set (the perturbed DT is unique), not on this order.
 */
#include "mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- Hilbert order ------------------------------------------------------- */

/* Skilling's transform: axes -> transposed Hilbert index, b bits per axis. */
static uint64_t hilbert_key(uint32_t x[3], int b)
{
    uint32_t m = 1u << (b - 1);
    for (uint32_t q = m; q > 1; q >>= 1) {
        uint32_t p = q - 1;
        for (int i = 0; i < 3; i++) {
            if (x[i] & q) x[0] ^= p;
            else { uint32_t s = (x[0] ^ x[i]) & p; x[0] ^= s; x[i] ^= s; }
        }
    }
    x[1] ^= x[0];
    x[2] ^= x[1];
    uint32_t s = 0;
    for (uint32_t q = m; q > 1; q >>= 1)
        if (x[2] & q) s ^= q - 1;
    for (int i = 0; i < 3; i++) x[i] ^= s;
    uint64_t key = 0;
    for (int bit = b - 1; bit >= 0; bit--)
        for (int i = 0; i < 3; i++) key = (key << 1) | ((x[i] >> bit) & 1u);
    return key;
}

typedef struct keyed { uint64_t key; uint32_t id; } keyed;

/* Sorts ids[0..n) along the Hilbert curve of their bounding box (LSD radix
 * sort on the 48-bit key, 16 bits a pass).                                */
static dd_status hilbert_sort(const double *pts, uint32_t *ids, uint32_t n)
{
    if (n < 2) return DD_OK;
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
    double scale = ext > 0 && isfinite(65535.0 / ext) ? 65535.0 / ext : 0.0;
    keyed *a = malloc(2 * (size_t)n * sizeof *a);
    uint32_t *count = malloc(65536 * sizeof *count);
    if (!a || !count) { free(a); free(count); return DD_ERR_NOMEM; }
    keyed *b = a + n;
    for (uint32_t k = 0; k < n; k++) {
        const double *p = pts + 3 * (size_t)ids[k];
        uint32_t x[3];
        for (int c = 0; c < 3; c++) {
            double q = (p[c] - lo[c]) * scale;
            x[c] = q <= 0 ? 0 : q >= 65535.0 ? 65535u : (uint32_t)q;
        }
        a[k].key = hilbert_key(x, 16);
        a[k].id = ids[k];
    }
    for (int shift = 0; shift < 48; shift += 16) {
        memset(count, 0, 65536 * sizeof *count);
        for (uint32_t k = 0; k < n; k++) count[(a[k].key >> shift) & 0xFFFF]++;
        uint32_t sum = 0;
        for (uint32_t d = 0; d < 65536; d++) { uint32_t c = count[d]; count[d] = sum; sum += c; }
        for (uint32_t k = 0; k < n; k++) b[count[(a[k].key >> shift) & 0xFFFF]++] = a[k];
        keyed *tmp = a; a = b; b = tmp;
    }
    /* after 3 passes the sorted data is in the buffer that started as b */
    for (uint32_t k = 0; k < n; k++) ids[k] = a[k].id;
    free(a < b ? a : b);
    free(count);
    return DD_OK;
}

/* BRIO: shuffle, then Hilbert-sort rounds [n/8, n), [n/64, n/8), ... */
static dd_status brio_order(const double *pts, uint32_t *ids, uint32_t n)
{
    uint64_t r = 0x243F6A8885A308D3ull;
    for (uint32_t k = n; k > 1; k--) {
        r ^= r << 13; r ^= r >> 7; r ^= r << 17;
        uint32_t j = (uint32_t)((r >> 33) % k);
        uint32_t tmp = ids[k - 1]; ids[k - 1] = ids[j]; ids[j] = tmp;
    }
    uint32_t hi = n;
    while (hi > 64) {
        uint32_t lo = hi / 8;
        dd_status s = hilbert_sort(pts, ids + lo, hi - lo);
        if (s != DD_OK) return s;
        hi = lo;
    }
    return hilbert_sort(pts, ids, hi);
}

/* ---- validation and duplicates ------------------------------------------- */

typedef struct lexpt { double x[3]; uint32_t id; } lexpt;

static int cmp_lexpt(const void *a, const void *b)
{
    const lexpt *p = a, *q = b;
    int c = dd_lex_cmp(p->x, q->x);
    return c ? c : (p->id < q->id ? -1 : p->id > q->id);
}

/* first[i] = the smallest input index holding the same point as input i;
 * writes the kept inputs (first[i] == i, ascending) to ids[0..*nkept).    */
static dd_status dedup(dd_tri *t, const double *pts, uint32_t n, uint32_t *first,
                       uint32_t *ids, uint32_t *nkept)
{
    lexpt *a = malloc((size_t)(n ? n : 1) * sizeof *a);
    if (!a) return dd_fail(t, DD_ERR_NOMEM, "out of memory");
    for (uint32_t i = 0; i < n; i++) {
        memcpy(a[i].x, pts + 3 * (size_t)i, sizeof a[i].x);
        a[i].id = i;
    }
    qsort(a, n, sizeof *a, cmp_lexpt);
    for (uint32_t k = 0; k < n; k++) {
        if (k > 0 && dd_lex_cmp(a[k].x, a[k - 1].x) == 0)
            first[a[k].id] = first[a[k - 1].id];
        else
            first[a[k].id] = a[k].id;
    }
    free(a);
    uint32_t m = 0;
    for (uint32_t i = 0; i < n; i++)
        if (first[i] == i) ids[m++] = i;
    *nkept = m;
    return DD_OK;
}

/* ---- the first tetrahedron ----------------------------------------------- */

/* Moves four affinely independent points to ids[0..3] (scanning in order). */
static dd_status pick_simplex(dd_tri *t, const double *pts, uint32_t *ids, uint32_t n)
{
    if (n < 4)
        return dd_fail(t, DD_ERR_TOO_FEW, "need at least 4 distinct points, got %u", n);
    dd_pred *pr = &t->pred;
#define PT(i) (pts + 3 * (size_t)(i))
    const double *a = PT(ids[0]), *b = PT(ids[1]);
    uint32_t k = 2;
    while (k < n && dd_orient_coplanar(pr, a, b, PT(ids[k])) == 0) k++;
    if (k == n)
        return dd_fail(t, DD_ERR_COLLINEAR, "all %u points are collinear", n);
    uint32_t tmp = ids[2]; ids[2] = ids[k]; ids[k] = tmp;
    const double *c = PT(ids[2]);
    k = 3;
    while (k < n && dd_orient3d(pr, a, b, c, PT(ids[k])) == 0) k++;
#undef PT
    if (k == n)
        return dd_fail(t, DD_ERR_COPLANAR, "all %u points are coplanar", n);
    tmp = ids[3]; ids[3] = ids[k]; ids[k] = tmp;
    return DD_OK;
}

/* ---- dd_create ------------------------------------------------------------ */

static dd_status report(dd_tri *t, dd_status s, char *msg, size_t msglen)
{
    if (msg && msglen) snprintf(msg, msglen, "%s", t->err[0] ? t->err : dd_status_name(s));
    dd_free(t);
    return s;
}

dd_status dd_create(dd_tri **out, const double *xyz, uint32_t n, char *msg, size_t msglen)
{
    *out = NULL;
    if (msg && msglen) msg[0] = 0;
    dd_tri *t;
    dd_status s = dd_tri_alloc(&t, n);
    if (s != DD_OK) {
        if (msg && msglen) snprintf(msg, msglen, "out of memory");
        return s;
    }
    for (uint32_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            double x = xyz[3 * (size_t)i + (size_t)c];
            if (isnan(x))
                return report(t, dd_fail(t, DD_ERR_NAN, "point %u: coordinate %c is NaN", i, "xyz"[c]), msg, msglen);
            if (isinf(x))
                return report(t, dd_fail(t, DD_ERR_INFINITE, "point %u: coordinate %c is infinite", i, "xyz"[c]), msg, msglen);
        }
    uint32_t *ids = malloc(2 * (size_t)(n ? n : 1) * sizeof *ids);
    if (!ids) return report(t, dd_fail(t, DD_ERR_NOMEM, "out of memory"), msg, msglen);
    uint32_t *first = ids + n;
    /* Input order -> insertion order: drop duplicates, BRIO + Hilbert, the
     * first tetrahedron in front.  Vertex id k is then input ids[k].      */
    uint32_t m = 0;
    s = dedup(t, xyz, n, first, ids, &m);
    if (s == DD_OK) s = brio_order(xyz, ids, m);
    if (s == DD_OK) s = pick_simplex(t, xyz, ids, m);
    if (s == DD_OK) s = dd_reserve_cells(t, m < 8 ? 64 : 7 * m);
    if (s != DD_OK) { free(ids); return report(t, s, msg, msglen); }
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
    free(ids);
    uint32_t first4[4] = {0, 1, 2, 3};
    dd_make_first_cells(t, first4);
    for (uint32_t k = 4; k < m && s == DD_OK; k++) s = dd_insert_vertex(t, k);
    if (s != DD_OK) return report(t, s, msg, msglen);
    *out = t;
    return DD_OK;
}
