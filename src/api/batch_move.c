/*
 * batch_move.c -- dd_move_many: m vertices moved in one call (dtdel.h).
 *
 * The result, the (regular) triangulation of the moved point set, does
 * not depend on the order of the moves, so they go along a Hilbert curve
 * of the targets: consecutive moves touch nearby cells (under
 * DD_DISCARD_HIDDEN, where what is forgotten depends on the order, in
 * the given one).  Each is dd_move's (or dd_move_weighted's) own course.
 *
 * A vertex may move onto the old point of another of the batch: its move
 * is refused (DD_ERR_DUPLICATE) while that one has not moved, so it waits
 * for the next round.  A round in which no move is made is a cycle (two
 * vertices swapping places, say): its first vertex is parked (deleted,
 * keeping its id and index) and put at its target once the others are
 * done.  A move still refused then lands on a vertex that does not move.
 *
 * Checked first, before any change: the points and weights, each vertex
 * (known, listed once).  Two equal targets are found on the way, as a
 * move refused to the last (its place taken by a vertex of the batch
 * that moved there).  All or nothing after: every step is logged, and a failure undoes the log, last step
 * first (a move moved back, a parked vertex put back where it was),
 * which restores the unique triangulation of the old points; under
 * DD_DISCARD_HIDDEN the vertices the batch forgot are put back.
 */
#include "dtdel.h"
#include "delete/delete.h"
#include "mesh/hidden_move.h"
#include "dtdel/alloc.h"
#include "api/api_int.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

extern const dd_variant *const dd_variant_table[];

/* A step of the batch: vertex id v moved from (p, w) (MOVED), deleted to
 * be placed later (PARKED), or placed at its target (PLACED).           */
enum { MOVED, PARKED, PLACED };
typedef struct step {
    uint32_t v, kind;
    double p[3], w;
} step;

typedef struct mv_batch {
    const uint32_t *vs;
    const double *xyz, *w;
    size_t m;
    uint32_t *id, *order, *wait;   /* id[i]: vs[i]'s vertex id */
    step *log;
    uint32_t nlog;
    unsigned char *was;            /* discard mode: the vertices before */
    uint32_t nvid;
} mv_batch;

/* ---- the checks ------------------------------------------------------- */

/* The vertex id of input vs[i]: a vertex, or on a weighted t a kept
 * hidden point (DD_ERR_UNKNOWN_VERTEX, naming the position, else).      */
static dd_status resolve_moved(dd_tri *t, const mv_batch *b, size_t i, uint32_t *v)
{
    const uint32_t in = b->vs[i];
    if (in < t->np) {
        const uint32_t x = t->in2v[in];
        if (x != DD_NONE && t->v2in[x] == in && dd_present(t, x)) {
            *v = x;
            return DD_OK;
        }
    }
    return dd_fail(t, DD_ERR_UNKNOWN_VERTEX, "point %u (at %zu in the batch) is no vertex", in, i);
}

static int cmp_u64(const void *a, const void *b)
{
    const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* A vertex listed twice (DD_ERR_ARG, naming both positions): a bitmap of
 * the vertex ids when the batch is large against t, else a sort.       */
static dd_status check_listed_once(dd_tri *t, const mv_batch *b, size_t m)
{
    const int bitmap = m >= t->nvid / 64;
    unsigned char *seen = bitmap ? dd_calloc((size_t)t->nvid / 8 + 1, 1) : NULL;
    uint64_t *ids = bitmap ? NULL : dd_malloc(m * sizeof *ids);
    if (!seen && !ids) return dd_fail(t, DD_ERR_NOMEM, "out of memory");
    size_t a = 0, c = 0;
    int twice = 0;
    for (size_t i = 0; bitmap && i < m && !twice; i++) {
        const uint32_t v = b->id[i];
        twice = seen[v / 8] >> (v % 8) & 1;
        seen[v / 8] |= (unsigned char)(1u << (v % 8));
        if (twice) {               /* the first: the one earlier with that id */
            c = i;
            while (b->id[a] != v) a++;
        }
    }
    for (size_t i = 0; !bitmap && i < m; i++) ids[i] = (uint64_t)b->id[i] << 32 | i;
    if (!bitmap) qsort(ids, m, sizeof *ids, cmp_u64);
    for (size_t k = 1; !bitmap && k < m && !twice; k++)
        if (ids[k] >> 32 == ids[k - 1] >> 32) twice = 1, a = (uint32_t)ids[k - 1], c = (uint32_t)ids[k];
    dd_mfree(seen);
    dd_mfree(ids);
    if (twice) return dd_fail(t, DD_ERR_ARG, "point %u is listed twice in the batch, at %zu and %zu", b->vs[c], a, c);
    return DD_OK;
}

static dd_status check_moves(dd_tri *t, mv_batch *b, size_t m)
{
    dd_status s = dd_check_batch(t, b->xyz, b->w, m);
    for (size_t i = 0; i < m && s == DD_OK; i++) s = resolve_moved(t, b, i, &b->id[i]);
    return s == DD_OK ? check_listed_once(t, b, m) : s;
}

/* ---- the steps ---------------------------------------------------------- */

static void log_step(mv_batch *b, uint32_t v, uint32_t kind, const dd_tri *t)
{
    step *e = &b->log[b->nlog++];
    e->v = v;
    e->kind = kind;
    memcpy(e->p, dd_pt(t, v), sizeof e->p);
    e->w = t->wt ? t->wt[v] : 0.0;
}

/* Moves vertex id v to (p, w) as dd_move / dd_move_weighted would. */
static dd_status move_to(dd_tri *t, uint32_t v, const double *p, const double *w)
{
    const uint32_t in = t->v2in[v];
    return w ? dd_move_weighted(t, in, p, *w) : dd_move(t, in, p);
}

/* Parks v: deleted (forgotten if hidden), its id, index and point kept. */
static dd_status park(dd_tri *t, uint32_t v)
{
    uint32_t cell;
    if (dd_hidden_has(t, v)) {
        dd_hidden_forget(t, v, &cell);
        return DD_OK;
    }
    return dd_del_vertex(t, v, dd_variant_table[0]);
}

/* Places a parked v at (p, w) (w NULL: its own): DD_ERR_DUPLICATE when
 * that is a vertex's point (weighted point), naming the pair.          */
static dd_status place(dd_tri *t, mv_batch *b, size_t i)
{
    const uint32_t v = b->id[i];
    memcpy(t->xyz + 3 * (size_t)v, b->xyz + 3 * i, 3 * sizeof *t->xyz);
    if (b->w) t->wt[v] = b->w[i];
    uint32_t dup = DD_NONE;
    dd_status s;
    if (!t->wt) {
        s = dd_insert_vertex_dup(t, v, dd_start_near(t, dd_pt(t, v)), &dup);
    } else {
        dd_fate fate;
        s = dd_insert_power(t, v, dd_start_near(t, dd_pt(t, v)), 0, &fate, &dup);
        if (s == DD_OK && fate == DD_FATE_DUPLICATE) s = DD_ERR_DUPLICATE;
        if (s == DD_OK && fate == DD_FATE_VERTEX) dd_grid_note(t, v);
    }
    if (s == DD_ERR_DUPLICATE) {        /* onto another target, or a fixed vertex */
        size_t j = 0;
        while (j < b->m && b->id[j] != dup) j++;
        if (j < b->m)
            return dd_fail(t, s, "points %u and %u of the batch (at %zu and %zu) move to the same point", b->vs[j],
                           b->vs[i], j, i);
        return dd_fail(t, s, "point %u of the batch (at %zu) moves onto point %u, which does not move", b->vs[i], i,
                       t->v2in[dup]);
    }
    if (s == DD_OK && !t->wt) dd_grid_note(t, v);
    return s;
}

/* Undoes the log, last step first; then, in discard mode, puts back the
 * vertices the batch forgot.  0 if a step of it failed.                 */
static int undo_moves(dd_tri *t, mv_batch *b)
{
    int ok = 1;
    while (b->nlog > 0 && ok) {
        const step *e = &b->log[--b->nlog];
        const uint32_t v = e->v;
        if (e->kind == MOVED && dd_present(t, v)) {
            ok = move_to(t, v, e->p, t->wt ? &e->w : NULL) == DD_OK;
            continue;
        }
        if (e->kind == PLACED && dd_present(t, v)) ok = park(t, v) == DD_OK;
        memcpy(t->xyz + 3 * (size_t)v, e->p, sizeof e->p);    /* as it was */
        if (t->wt) t->wt[v] = e->w;
        if (ok && e->kind == PARKED) ok = dd_put_back(t, v) == DD_OK;
    }
    for (uint32_t v = 0; b->was && v < b->nvid && ok; v++)
        if (b->was[v / 8] >> (v % 8) & 1 && !dd_present(t, v)) ok = dd_put_back(t, v) == DD_OK;
    return ok;
}

/* One round over wait[0..*n): the moves that can be made now; the ones
 * refused for landing on a point still taken stay in wait (*n).         */
static dd_status move_round(dd_tri *t, mv_batch *b, uint32_t *n)
{
    uint32_t left = 0;
    for (uint32_t k = 0; k < *n; k++) {
        const uint32_t i = b->wait[k], v = b->id[i];
        if (!dd_present(t, v))
            return dd_fail(t, DD_ERR_UNKNOWN_VERTEX, "point %u of the batch (at %u) was forgotten by an earlier move",
                           b->vs[i], i);
        log_step(b, v, MOVED, t);
        dd_status s = move_to(t, v, b->xyz + 3 * (size_t)i, b->w ? b->w + i : NULL);
        if (s == DD_OK) continue;
        b->nlog--;
        if (s != DD_ERR_DUPLICATE) return s;
        b->wait[left++] = i;
    }
    *n = left;
    return DD_OK;
}

static dd_status move_all(dd_tri *t, mv_batch *b, size_t m)
{
    uint32_t n = (uint32_t)m, nparked = 0;
    uint32_t *parked = b->order;          /* order is spent once in wait */
    memcpy(b->wait, b->order, m * sizeof *b->wait);
    dd_status s = DD_OK;
    while (n > 0 && s == DD_OK) {
        const uint32_t before = n;
        s = move_round(t, b, &n);
        if (s != DD_OK || n == 0 || n < before) continue;
        const uint32_t i = b->wait[0];    /* a cycle: park its first */
        log_step(b, b->id[i], PARKED, t);
        if ((s = park(t, b->id[i])) != DD_OK) { b->nlog--; continue; }
        parked[nparked++] = i;
        memmove(b->wait, b->wait + 1, --n * sizeof *b->wait);
    }
    for (uint32_t k = 0; k < nparked && s == DD_OK; k++) {
        const uint32_t i = parked[k];
        log_step(b, b->id[i], PLACED, t);
        if ((s = place(t, b, i)) != DD_OK) b->nlog--;
    }
    return s;
}

static dd_status move_many(dd_tri *t, const uint32_t *vs, const double *xyz, const double *w, size_t m)
{
    if (w && !t->wt) return dd_fail(t, DD_ERR_UNSUPPORTED, "weights given for an unweighted triangulation");
    if (m == 0) return DD_OK;
    mv_batch b;
    memset(&b, 0, sizeof b);
    b.vs = vs, b.xyz = xyz, b.w = w, b.m = m, b.nvid = t->nvid;
    const int discard = t->wt && (t->flags & DD_DISCARD_HIDDEN_FLAG);
    dd_status s = dd_check_batch(t, xyz, w, m);
    if (s != DD_OK) return s;
    b.id = dd_malloc(3 * m * sizeof *b.id);
    b.log = dd_malloc(2 * m * sizeof *b.log);
    b.was = discard ? dd_calloc((size_t)t->nvid / 8 + 1, 1) : NULL;
    if (!b.id || !b.log || (discard && !b.was)) s = dd_fail(t, DD_ERR_NOMEM, "out of memory");
    if (s == DD_OK) {
        b.order = b.id + m;
        b.wait = b.order + m;
        s = check_moves(t, &b, m);
    }
    for (uint32_t v = 0; s == DD_OK && discard && v < t->nvid; v++)
        if (t->vcell[v] != DD_NONE) b.was[v / 8] |= (unsigned char)(1u << (v % 8));
    for (uint32_t i = 0; s == DD_OK && i < (uint32_t)m; i++) b.order[i] = i;
    if (s == DD_OK && !discard && dd_spatial_order(xyz, b.order, (uint32_t)m, 0) != DD_OK)
        s = dd_fail(t, DD_ERR_NOMEM, "out of memory");
    if (s == DD_OK && (s = move_all(t, &b, m)) != DD_OK) {
        char why[sizeof t->err];
        memcpy(why, t->err, sizeof why);
        const int undone = undo_moves(t, &b);
        memcpy(t->err, why, sizeof why);
        if (!undone) s = dd_fail(t, DD_ERR_INTERNAL, "moving the batch failed (%s) and could not be undone", why);
    }
    if (s == DD_OK) (void)dd_grid_ready(t);
    dd_mfree(b.id);
    dd_mfree(b.log);
    dd_mfree(b.was);
    return s;
}

dd_status dd_move_many(dd_tri *t, const uint32_t *vs, const double *xyz, const double *w, size_t m)
{
    dd_edit_begin(t);
    return dd_edit_end(t, move_many(t, vs, xyz, w, m));
}
