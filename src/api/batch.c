/*
 * batch.c -- dd_insert_many: m new points in one call (dtdel.h).
 *
 * One pass that equals m single insertions: the batch is checked whole
 * first (every coordinate and weight), merged within itself (the first
 * of equal points is kept, as dd_create does), then inserted in an order
 * of its own -- along a Hilbert curve, in BRIO rounds when it is large
 * against the triangulation -- each walk starting from the last star,
 * so that consecutive insertions touch nearby cells in space and memory.
 *
 * The indices are those of the given order.  The insertions take the
 * same supply of input indices one-at-a-time insertion would (deleted
 * ones to reuse, then new ones), but in the call's order: the j-th
 * insertion that succeeds takes supply item j.  Afterwards the r-th new
 * point of the given order is given item r (a permutation of the slots'
 * indices, O(m)).  A point equal to a vertex takes none.
 *
 * All or nothing: a failure part way (out of memory) deletes the points
 * inserted, last first, which restores the unique triangulation of the
 * points before; the free list, counts and reused slots' points are put
 * back as they were; under DD_DISCARD_HIDDEN the vertices the batch's
 * points forgot are inserted again.
 */
#include "dtdel.h"
#include "delete/delete.h"
#include "mesh/hidden_move.h"
#include "dtdel/alloc.h"
#include "api/api_int.h"

#include <math.h>
#include <string.h>

/* The registry (variants/registry.c): the first entry is the default. */
extern const dd_variant *const dd_variant_table[];

dd_status dd_check_batch(dd_tri *t, const double *xyz, const double *w, size_t m)
{
    for (size_t i = 0; i < m; i++)
        for (int c = 0; c < 3; c++) {
            const double x = xyz[3 * i + (size_t)c];
            if (isnan(x)) return dd_fail(t, DD_ERR_NAN, "point %zu of the batch: coordinate %c is NaN", i, "xyz"[c]);
            if (isinf(x))
                return dd_fail(t, DD_ERR_INFINITE, "point %zu of the batch: coordinate %c is infinite", i, "xyz"[c]);
        }
    for (size_t i = 0; w && i < m; i++) {
        if (isnan(w[i])) return dd_fail(t, DD_ERR_NAN, "point %zu of the batch: the weight is NaN", i);
        if (isinf(w[i])) return dd_fail(t, DD_ERR_INFINITE, "point %zu of the batch: the weight is infinite", i);
    }
    if (m >= UINT32_MAX - 8) return dd_fail(t, DD_ERR_NOMEM, "a batch of %zu points is too large", m);
    return DD_OK;
}

/* A batch's state: kept[0..nkept) the batch positions left once merged
 * (ascending), order[] the same in insertion order; for position i,
 * first[i] its first equal, slot[i] its vertex id once inserted (DD_NONE
 * for one equal to a vertex: then dupin[i] is its index); taken[j] the
 * input index the j-th insertion that succeeded took; old[3i..] a
 * reused slot's former point.  done[0..ndone) the positions inserted, in
 * order, for the undo.                                                 */
typedef struct ins_batch {
    const double *xyz, *w;
    uint32_t *kept, *order, *first, *slot, *taken, *done, *dupin;
    double *old;
    uint32_t nkept, ndone;
    /* t as it was: counts, free list, present vertices (discard mode) */
    uint32_t np, nvid;
    size_t nfree;
    unsigned char *was;
} ins_batch;

static void batch_free(ins_batch *b)
{
    dd_mfree(b->kept);
    dd_mfree(b->old);
    dd_mfree(b->was);
}

static dd_status batch_alloc(dd_tri *t, ins_batch *b, size_t m)
{
    b->kept = dd_malloc(7 * m * sizeof *b->kept);
    b->old = dd_malloc(3 * m * sizeof *b->old);
    const int discard = t->wt && (t->flags & DD_DISCARD_HIDDEN_FLAG);
    b->was = discard ? dd_calloc((size_t)t->nvid / 8 + 1, 1) : NULL;
    if (!b->kept || !b->old || (discard && !b->was)) return dd_fail(t, DD_ERR_NOMEM, "out of memory");
    b->order = b->kept + m;
    b->first = b->order + m;
    b->slot = b->first + m;
    b->taken = b->slot + m;
    b->done = b->taken + m;
    b->dupin = b->done + m;
    b->np = t->np;
    b->nvid = t->nvid;
    b->nfree = t->vfree.n;
    for (uint32_t v = 0; discard && v < t->nvid; v++)
        if (t->vcell[v] != DD_NONE) b->was[v / 8] |= (unsigned char)(1u << (v % 8));
    return DD_OK;
}

/* Inserts batch point i (unweighted t): a vertex id from the supply, its
 * point written, inserted from t's last cells.  A point equal to vertex
 * *dup: DD_ERR_DUPLICATE, nothing taken.                               */
static dd_status insert_plain(dd_tri *t, ins_batch *b, uint32_t i, uint32_t *dup)
{
    uint32_t v;
    int reused;
    dd_status s = dd_new_vertex_id(t, &v, &reused);
    if (s != DD_OK) return s;
    double *x = t->xyz + 3 * (size_t)v;
    memcpy(b->old + 3 * (size_t)i, x, 3 * sizeof *x);
    memcpy(x, b->xyz + 3 * (size_t)i, 3 * sizeof *x);
    s = dd_insert_vertex_dup(t, v, dd_start_near(t, x), dup);
    if (s != DD_OK) {
        memcpy(x, b->old + 3 * (size_t)i, 3 * sizeof *x);
        if (reused) t->vfree.a[t->vfree.n++] = v;    /* its place: no growth */
        return s;
    }
    if (!reused) {
        t->nvid++;
        t->np++;
    }
    b->slot[i] = v;
    dd_grid_note(t, v);
    return DD_OK;
}

/* Inserts batch point i of a weighted t by CGAL's rule: it takes the next
 * id and index whether it ends a vertex or hidden (or forgotten); its
 * exact weighted point equal to vertex *dup's is DD_ERR_DUPLICATE.     */
static dd_status insert_power(dd_tri *t, ins_batch *b, uint32_t i, uint32_t *dup)
{
    dd_status s = dd_reserve_vertex(t);
    if (s != DD_OK) return dd_fail(t, s, "out of memory or too many points");
    const uint32_t v = t->nvid;
    memcpy(t->xyz + 3 * (size_t)v, b->xyz + 3 * (size_t)i, 3 * sizeof *t->xyz);
    t->wt[v] = b->w ? b->w[i] : 0.0;
    t->vcell[v] = DD_NONE;
    t->v2in[v] = t->np;
    dd_fate fate;
    if ((s = dd_insert_power(t, v, t->hint, 1, &fate, dup)) != DD_OK) return s;
    if (fate == DD_FATE_DUPLICATE) return DD_ERR_DUPLICATE;
    t->in2v[t->np++] = v;
    t->nvid++;
    b->slot[i] = v;
    if (fate == DD_FATE_VERTEX) dd_grid_note(t, v);
    return DD_OK;
}

/* Takes out what the batch inserted, last first, and restores t's counts,
 * free list and reused slots' points; in discard mode puts back the
 * vertices the batch forgot.  0 if some step of it failed.            */
static int undo_batch(dd_tri *t, ins_batch *b)
{
    const dd_variant *var = dd_variant_table[0];
    int ok = 1;
    while (b->ndone > 0 && ok) {
        const uint32_t i = b->done[--b->ndone], v = b->slot[i];
        uint32_t cell;
        if (dd_hidden_has(t, v)) dd_hidden_forget(t, v, &cell);
        else if (t->vcell[v] != DD_NONE) ok = dd_del_vertex(t, v, var) == DD_OK;
        if (ok && !t->wt) memcpy(t->xyz + 3 * (size_t)v, b->old + 3 * (size_t)i, 3 * sizeof *t->xyz);
    }
    if (!ok) return 0;
    t->np = b->np;
    t->nvid = b->nvid;
    t->vfree.n = b->nfree;
    for (uint32_t v = 0; b->was && v < b->nvid && ok; v++)
        if (b->was[v / 8] >> (v % 8) & 1 && t->vcell[v] == DD_NONE) ok = dd_put_back(t, v) == DD_OK;
    return ok;
}

/* The inserted points' input indices in the given order (the header's
 * permutation), then indices[] for every position.                     */
static void number_batch(dd_tri *t, ins_batch *b, uint32_t *indices)
{
    uint32_t r = 0;
    for (uint32_t k = 0; k < b->nkept; k++) {
        const uint32_t i = b->kept[k], v = b->slot[i];
        if (v == DD_NONE) continue;
        const uint32_t in = b->taken[r++];
        t->v2in[v] = in;
        t->in2v[in] = v;
    }
    for (uint32_t k = 0; k < b->nkept; k++) {
        const uint32_t i = b->kept[k];
        indices[i] = b->slot[i] != DD_NONE ? t->v2in[b->slot[i]] : b->dupin[i];
    }
}

static dd_status insert_batch(dd_tri *t, ins_batch *b, uint32_t *indices, size_t *merged)
{
    size_t nmerged = 0;
    dd_status s = DD_OK;
    for (uint32_t k = 0; k < b->nkept && s == DD_OK; k++) {
        const uint32_t i = b->order[k];
        uint32_t dup = DD_NONE;
        b->slot[i] = DD_NONE;
        s = t->wt ? insert_power(t, b, i, &dup) : insert_plain(t, b, i, &dup);
        if (s == DD_ERR_DUPLICATE) {         /* a vertex's point: its index */
            b->dupin[i] = t->v2in[dup];
            nmerged++;
            s = DD_OK;
        } else if (s == DD_OK) {
            b->taken[b->ndone] = t->v2in[b->slot[i]];
            b->done[b->ndone++] = i;
        }
    }
    if (s != DD_OK) {
        char why[sizeof t->err];
        memcpy(why, t->err, sizeof why);
        const int undone = undo_batch(t, b);
        memcpy(t->err, why, sizeof why);
        if (!undone) return dd_fail(t, DD_ERR_INTERNAL, "inserting the batch failed (%s) and could not be undone", why);
        return s;
    }
    number_batch(t, b, indices);
    if (merged) *merged = nmerged;
    return DD_OK;
}

static dd_status insert_many(dd_tri *t, const double *xyz, const double *w, size_t m, uint32_t *indices,
                             size_t *merged)
{
    if (merged) *merged = 0;
    if (w && !t->wt) return dd_fail(t, DD_ERR_UNSUPPORTED, "weights given for an unweighted triangulation");
    dd_status s = dd_check_batch(t, xyz, w, m);
    if (s != DD_OK || m == 0) return s;
    if ((s = dd_grid_ready(t)) != DD_OK) return dd_fail(t, s, "out of memory");
    ins_batch b;
    memset(&b, 0, sizeof b);
    b.xyz = xyz;
    b.w = w;
    double *w0 = NULL;                 /* weight 0 for each, to merge by */
    if ((s = batch_alloc(t, &b, m)) == DD_OK && t->wt && !w) {
        w0 = dd_calloc(m, sizeof *w0);
        if (!w0) s = dd_fail(t, DD_ERR_NOMEM, "out of memory");
    }
    const uint32_t n = (uint32_t)m;
    if (s == DD_OK) s = dd_dedup_points(t, xyz, t->wt ? (w ? w : w0) : NULL, n, b.first, b.kept, &b.nkept);
    dd_mfree(w0);
    if (s == DD_OK) {
        memcpy(b.order, b.kept, b.nkept * sizeof *b.order);
        const int given = t->wt && (t->flags & DD_DISCARD_HIDDEN_FLAG);   /* discard mode: the given order */
        if (!given && dd_spatial_order(xyz, b.order, b.nkept, b.nkept > t->nvert) != DD_OK)
            s = dd_fail(t, DD_ERR_NOMEM, "out of memory");
    }
    size_t dups = m - b.nkept;
    if (s == DD_OK) s = insert_batch(t, &b, indices, merged);
    if (s == DD_OK) {
        for (uint32_t i = 0; i < n; i++)         /* merged within the batch */
            if (b.first[i] != i) indices[i] = indices[b.first[i]];
        if (merged) *merged += dups;
        (void)dd_grid_ready(t);
    }
    batch_free(&b);
    return s;
}

dd_status dd_insert_many(dd_tri *t, const double *xyz, const double *w, size_t m, uint32_t *indices,
                         size_t *merged)
{
    dd_edit_begin(t);
    return dd_edit_end(t, insert_many(t, xyz, w, m, indices, merged));
}
