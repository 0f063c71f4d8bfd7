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
 * Order: BRIO rounds along a Hilbert curve (order.c).  The result
 * depends only on the point set (the perturbed DT is unique), not on
 * this order.  On more than one thread the loop is pbuild.c's.
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

/* Points a thread of the copy into vertex id order at least. */
#define STORE_SHARE 262144u

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
    if (!t->wt && t->nthreads > 1) {
        uint32_t rounds[18], nround;
        dd_brio_rounds(t->v2in, m, rounds, &nround);
        return dd_build_parallel(t, 4, m, rounds, nround);
    }
    if (!t->wt) {
        for (uint32_t k = 4; k < m && s == DD_OK; k++) s = dd_build_insert(t, k);
        return s;
    }
    dd_fate fate;
    uint32_t dup;
    for (uint32_t k = 4; k < m && s == DD_OK; k++) s = dd_insert_power(t, k, t->hint, 1, &fate, &dup);
    return s;
}

/* The points in vertex id order, and the maps between ids and inputs:
 * chunks of ids, then chunks of inputs, one a thread.                  */
typedef struct store_job {
    dd_tri *t;
    const double *xyz;
    const uint32_t *ids, *first;
    unsigned nth;
} store_job;

static void store_ids(void *arg, unsigned j)
{
    const store_job *s = arg;
    dd_tri *t = s->t;
    uint32_t k0 = (uint32_t)((uint64_t)t->nvid * j / s->nth), k1 = (uint32_t)((uint64_t)t->nvid * (j + 1) / s->nth);
    for (uint32_t k = k0; k < k1; k++) {
        memcpy(t->xyz + 3 * (size_t)k, s->xyz + 3 * (size_t)s->ids[k], 3 * sizeof *s->xyz);
        t->v2in[k] = s->ids[k];
        t->vcell[k] = DD_NONE;
        t->in2v[s->ids[k]] = k;
    }
}

static void store_duplicates(void *arg, unsigned j)
{
    const store_job *s = arg;
    dd_tri *t = s->t;
    uint32_t i0 = (uint32_t)((uint64_t)t->np * j / s->nth), i1 = (uint32_t)((uint64_t)t->np * (j + 1) / s->nth);
    for (uint32_t i = i0; i < i1; i++)
        if (s->first[i] != i) t->in2v[i] = t->in2v[s->first[i]];
}

static void store_points(dd_tri *t, const double *xyz, const uint32_t *ids, const uint32_t *first)
{
    store_job s = {t, xyz, ids, first, t->np / STORE_SHARE + 1};
    if (s.nth > t->nthreads) s.nth = t->nthreads;
    dd_run_threads(s.nth, store_ids, &s);
    dd_run_threads(s.nth, store_duplicates, &s);
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
    t->nthreads = flags & DD_THREADS_ALL_FLAG ? dd_cores()
                  : flags >> DD_THREADS_SHIFT & DD_THREADS_MASK ? flags >> DD_THREADS_SHIFT & DD_THREADS_MASK
                  : dd_threads_default();
    if (t->nthreads > DD_THREADS_MAX) t->nthreads = DD_THREADS_MAX;
    if ((s = check_input(t, xyz, weights, n)) != DD_OK) return report(t, s, msg, msglen);
    uint32_t *ids = dd_malloc(2 * (size_t)(n ? n : 1) * sizeof *ids);
    if (!ids) return report(t, dd_fail(t, DD_ERR_NOMEM, "out of memory"), msg, msglen);
    uint32_t *first = ids + n;
    /* Input order -> insertion order: drop duplicates, BRIO + Hilbert, the
     * first tetrahedron in front.  Vertex id k is then input ids[k].      */
    uint32_t m = 0;
    s = dd_dedup_points(t, xyz, weights, n, first, ids, &m);
    if (s == DD_OK) s = dd_spatial_order_threads(xyz, ids, m, 1, t->nthreads);
    if (s == DD_OK) s = dd_pick_simplex(t, xyz, ids, m);
    if (s == DD_OK) s = dd_reserve_cells(t, m < 8 ? 64 : 7 * m);
    if (s == DD_OK && weights && make_weighted(t, weights, ids, m) != DD_OK)
        s = dd_fail(t, DD_ERR_NOMEM, "out of memory");
    if (s != DD_OK) { dd_mfree(ids); return report(t, s, msg, msglen); }
    t->np = n;
    t->nvid = m;
    t->ndup = n - m;
    store_points(t, xyz, ids, first);
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
