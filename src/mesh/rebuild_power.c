/*
 * rebuild_power.c -- the regular triangulation rebuilt without a set of
 * its points (hidden_move.h), dd_delete_set's rebuild course on a
 * weighted triangulation (issue 44).
 *
 * The points left (vertices, and kept hidden points when hidden points
 * are kept) go in vertex id order, the construction's BRIO + Hilbert
 * order, into a scratch triangulation that borrows t's points and
 * weights and has cells and hidden points of its own, by CGAL's
 * insertion rule (regular.c): so the scratch ends as the regular
 * triangulation of those points, whatever their order (keep mode: the
 * unique state; discard mode: a point left was a vertex of t, and
 * removing points hides none, so none is forgotten).  On success the
 * cells and the hidden-point state are swapped into t.
 */
#include "mesh/hidden_move.h"
#include "dtdel/alloc.h"

#include <string.h>

/* The ids of the points left, in id order; returns how many. */
static uint32_t points_left(const dd_tri *t, const uint32_t *ids, size_t n, uint32_t *kept)
{
    uint32_t m = 0;
    size_t k = 0;
    for (uint32_t v = 0; v < t->nvid; v++) {
        while (k < n && ids[k] < v) k++;
        if (k < n && ids[k] == v) continue;
        if (t->vcell[v] != DD_NONE || dd_hidden_has(t, v)) kept[m++] = v;
    }
    return m;
}

/* Gives t the cells and hidden points of s (and s t's, to be freed). */
static void swap_state(dd_tri *t, dd_tri *s)
{
#define SWAP(f) do { __typeof__(t->f) x_ = t->f; t->f = s->f; s->f = x_; } while (0)
    SWAP(cell); SWAP(cell_block); SWAP(stamp); SWAP(ncell); SWAP(cap_c); SWAP(nlive); SWAP(nfinite);
    SWAP(free_head); SWAP(nfree); SWAP(epoch); SWAP(inf_cell); SWAP(hint); SWAP(hid);
#undef SWAP
}

/* The points kept[0..m) inserted into the empty scratch s (CGAL's rule). */
static dd_status build_scratch(dd_tri *s, uint32_t *kept, uint32_t m)
{
    dd_status st = dd_pick_simplex(s, s->xyz, kept, m);
    if (st == DD_OK) st = dd_reserve_cells(s, m < 8 ? 64 : 7 * m);
    if (st != DD_OK) return st;
    dd_make_first_cells(s, kept);
    dd_fate fate;
    uint32_t dup;
    for (uint32_t k = 4; k < m && st == DD_OK; k++) {
        st = dd_insert_power(s, kept[k], s->hint, 1, &fate, &dup);
        if (st == DD_OK && fate == DD_FATE_DUPLICATE) st = DD_ERR_DUPLICATE;
    }
    return st;
}

dd_status dd_rebuild_power_without(dd_tri *t, const uint32_t *ids, size_t n)
{
    dd_tri *s = NULL;
    uint32_t *kept = dd_malloc(((size_t)t->nvid + 1) * sizeof *kept), *vcell = dd_malloc((size_t)t->cap_v * sizeof *vcell);
    dd_status st = kept && vcell ? dd_tri_alloc_borrowed(&s) : DD_ERR_NOMEM;
    if (st == DD_OK) {
        s->xyz = t->xyz;
        s->v2in = t->v2in;
        s->vcell = vcell;
        s->wt = t->wt;
        s->nvid = t->nvid;
        s->cap_v = t->cap_v;
        st = dd_hidden_init(s, t->hid->keep);
    }
    if (st == DD_OK) {
        const uint32_t m = points_left(t, ids, n, kept);
        for (uint32_t v = 0; v < t->nvid; v++) vcell[v] = DD_NONE;
        st = build_scratch(s, kept, m);
    }
    if (st == DD_OK) {
        swap_state(t, s);
        memcpy(t->vcell, vcell, (size_t)t->nvid * sizeof *vcell);
        t->nvert = s->nvert;
        t->tets_created += s->tets_created;
        dd_shrink_cells(t);
    } else if (st == DD_ERR_NOMEM) {
        dd_fail(t, st, "out of memory");
    } else if (s && st != DD_ERR_DUPLICATE) {       /* a duplicate: no message, the caller goes on */
        dd_fail(t, st, "%s", s->err[0] ? s->err : "rebuilding failed");
    }
    dd_tri_destroy(s);
    dd_mfree(kept), dd_mfree(vcell);
    return st;
}
