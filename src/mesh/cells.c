/*
 * cells.c -- what cell handles need from the mesh: the record of the
 * cells an edit makes, and a walk that reads the mesh only.
 *
 * The record.  A cell id is a cell's slot (mesh.h).  An edit kills
 * cells and makes others in their slots or in new ones; a live cell it
 * does not touch keeps its slot.  The edit notes the cells it makes where
 * it commits them (mesh.c's star of an insertion, delete.c's sewn fill,
 * flip.c's kept flips), straight into the public list.  An edit of one
 * step (an insertion, a deletion) notes each of its cells once, all
 * alive at its end; an edit of several steps may note a cell that a
 * later step kills (a set's next deletion, a move's second half) or
 * whose slot it fills again, so the outermost dd_edit_end then keeps
 * the live ones, each once (a mark of a fresh epoch).  So the list is
 * exactly the live cells whose slot the edit (re)filled.  Cost: O(1) a
 * cell made.
 *
 * The walk.  dd_walk_locate (mesh.c) keeps its statistics and its random
 * state in t; dd_walk_const takes them from the caller, so a read-only
 * call can walk without writing to t.
 */
#include "mesh/mesh.h"
#include "dtdel/alloc.h"

#include <stdlib.h>
#include <string.h>

/* ---- the record of made cells ------------------------------------------ */

void dd_made_free(dd_made *m)
{
    dd_mfree(m->list);
    memset(m, 0, sizeof *m);
}

/* Room for `more` entries past m->n, doubling; a list left far larger
 * than needed (after dd_create, every cell) is cut down at an edit's
 * first note.  DD_ERR_NOMEM.                                           */
static dd_status list_room(dd_made *m, size_t more)
{
    if (m->n + more <= m->cap) return DD_OK;
    size_t cap = m->cap ? 2 * m->cap : 64;
    while (cap < m->n + more) cap *= 2;
    int64_t *l = dd_realloc(m->list, cap * sizeof *l);
    if (!l) return DD_ERR_NOMEM;
    m->list = l;
    m->cap = cap;
    return DD_OK;
}

#define LIST_KEEP 4096       /* entries kept across edits at least */

void dd_note_made(dd_tri *t, const uint32_t *cells, size_t n)
{
    dd_made *m = &t->made;
    if (!m->depth) return;
    if (m->notes++ == 0) {                        /* the edit's first: a new list */
        m->n = 0;
        m->lost = 0;
        if (m->cap > LIST_KEEP && m->cap > 8 * n) {
            int64_t *l = dd_realloc(m->list, LIST_KEEP * sizeof *l);
            if (l) m->list = l, m->cap = LIST_KEEP;
        }
    }
    if (m->lost) return;
    if (list_room(m, n) != DD_OK) {
        m->lost = 1;
        m->n = 0;
        return;
    }
    int64_t *l = m->list + m->n;
    for (size_t k = 0; k < n; k++) l[k] = cells[k];
    m->n += n;
}

void dd_note_all(dd_tri *t)
{
    if (t->made.depth) t->made.all = 1;
}

dd_status dd_publish_all_cells(dd_tri *t)
{
    dd_made *m = &t->made;
    m->n = 0;
    m->lost = 0;
    if (m->cap < t->nlive || m->cap > 2 * (size_t)t->nlive + LIST_KEEP) {
        int64_t *l = dd_realloc(m->list, ((size_t)t->nlive + 1) * sizeof *l);
        if (!l) {
            m->lost = 1;
            return DD_ERR_NOMEM;
        }
        m->list = l;
        m->cap = (size_t)t->nlive + 1;
    }
    for (uint32_t c = 0; c < t->ncell; c++)
        if (dd_tv(t, c)[0] != DD_DEAD) m->list[m->n++] = c;
    return DD_OK;
}

/* Keeps the live cells of the list, each once (a mark of a fresh epoch). */
static void filter_list(dd_tri *t)
{
    dd_made *m = &t->made;
    const dd_mark ep = dd_new_epoch(t, 1);
    size_t k = 0;
    for (size_t j = 0; j < m->n; j++) {
        const uint32_t c = (uint32_t)m->list[j];
        if (c >= t->ncell || dd_tv(t, c)[0] == DD_DEAD || t->stamp[c] == ep) continue;
        t->stamp[c] = ep;
        m->list[k++] = c;
    }
    m->n = k;
}

void dd_edit_settle(dd_tri *t, dd_status s)
{
    dd_made *m = &t->made;
    if (m->all) {
        (void)dd_publish_all_cells(t);
    } else if (m->notes == 0) {
        if (s == DD_OK) m->n = 0, m->lost = 0;     /* succeeded, made none */
    } else if (!m->lost) {
        filter_list(t);
    }
}

/* ---- the read-only walk --------------------------------------------------- */

/* orient3d of cell c with its vertex i replaced by p. */
static int orient_with(const dd_tri *t, dd_pred *pr, uint32_t c, uint32_t i, const double *p)
{
    const uint32_t *v = dd_tv(t, c);
    const double *q[4];
    for (uint32_t k = 0; k < 4; k++) q[k] = k == i ? p : dd_pt(t, v[k]);
    return dd_orient3d(pr, q[0], q[1], q[2], q[3]);
}

/* The visibility walk: each step crosses a facet whose plane strictly
 * separates the cell from p, the facet tried first chosen at random
 * (so the walk cannot cycle); it ends in a finite cell with p beyond
 * none of its facets, whose closure holds p, or on entering an infinite
 * cell, whose hull facet p is then strictly beyond.  An infinite start
 * is that answer already when p is strictly beyond its facet; else the
 * walk starts from the finite cell across that facet.                  */
dd_status dd_walk_const(const dd_tri *t, dd_pred *pr, uint64_t *rng, const double *p, uint32_t start,
                        uint32_t *out)
{
    uint32_t c = start, from = 4;
    const int k = dd_index_of(t, c, DD_INF);
    if (k >= 0) {
        if (orient_with(t, pr, c, (uint32_t)k, p) > 0) {
            *out = c;
            return DD_OK;
        }
        const uint32_t f = dd_tn(t, c)[k];
        c = f >> 2;
        from = f & 3;
    }
    const uint64_t limit = 16 + 4 * (uint64_t)t->ncell;
    for (uint64_t steps = 0; steps < limit; steps++) {
        const uint32_t r = dd_xorshift(rng) & 3;
        uint32_t next = DD_NONE;
        for (uint32_t j = 0; j < 4; j++) {
            const uint32_t i = (r + j) & 3;
            if (i == from) continue;
            if (orient_with(t, pr, c, i, p) < 0) {
                next = dd_tn(t, c)[i];
                break;
            }
        }
        if (next == DD_NONE) {
            *out = c;
            return DD_OK;
        }
        c = next >> 2;
        from = next & 3;
        if (dd_is_infinite_cell(t, c)) {
            *out = c;
            return DD_OK;
        }
    }
    return DD_ERR_INTERNAL;
}
