/*
 * check.c -- the validator (DESIGN 8b): run after every operation in test
 * builds, never in timed runs.
 *
 * Checks, in order: neighbour symmetry tn[tn[f]] == f and that the two
 * cells really share the facet's three vertices; one infinite vertex at
 * most per cell; positive orientation of finite cells; vertex -> cell links;
 * the perturbed empty-sphere test across every facet (the opposite vertex
 * of the neighbour is not in conflict with the cell).  For a valid
 * triangulation the last test certifies the perturbed Delaunay
 * triangulation, hence CGAL's.  A weighted triangulation is checked the
 * same way with the power test (every facet regular), and its kept
 * hidden points by hidden.c (each hidden in its cell).
 *
 * Read-only (dtdel.h, threads): its predicates are a context of its own,
 * and its message goes to the caller's buffer, not to t.
 */
#include "mesh/mesh.h"
#include "mesh/hidden.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

/* Whether facet i of cell c and facet j of cell d have the same three
 * vertices (in any order).                                              */
static int same_facet(const dd_tri *t, uint32_t c, uint32_t i, uint32_t d, uint32_t j)
{
    uint32_t a[3], b[3];
    for (int k = 0; k < 3; k++) {
        a[k] = dd_tv(t, c)[(uint32_t)dd_facet[i][k]];
        b[k] = dd_tv(t, d)[(uint32_t)dd_facet[j][k]];
    }
    for (int k = 0; k < 3; k++)
        if (a[k] != b[0] && a[k] != b[1] && a[k] != b[2]) return 0;
    return 1;
}

/* The validator's failure: its message in msg (if not NULL), and s. */
static dd_status refute(char *msg, size_t msglen, dd_status s, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static dd_status refute(char *msg, size_t msglen, dd_status s, const char *fmt, ...)
{
    if (msg && msglen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, msglen, fmt, ap);
        va_end(ap);
    }
    return s;
}

/* The checks on combinatorics, orientation and links (all but the
 * empty-sphere test).                                                   */
static dd_status check_cells(const dd_tri *t, dd_pred *pr, char *msg, size_t msglen)
{
    size_t live = 0, finite = 0;
    for (uint32_t c = 0; c < t->ncell; c++) {
        const uint32_t *v = dd_tv(t, c);
        if (v[0] == DD_DEAD) continue;
        live++;
        int ninf = 0;
        for (uint32_t i = 0; i < 4; i++) {
            if (v[i] == DD_INF) { ninf++; continue; }
            if (v[i] >= t->nvid || t->vcell[v[i]] == DD_NONE)
                return refute(msg, msglen, DD_ERR_INTERNAL, "cell %u: vertex id %u is not a live vertex", c, v[i]);
            for (uint32_t k = i + 1; k < 4; k++)
                if (v[k] == v[i]) return refute(msg, msglen, DD_ERR_INTERNAL, "cell %u repeats vertex %u", c, v[i]);
        }
        if (ninf > 1) return refute(msg, msglen, DD_ERR_INTERNAL, "cell %u has %d infinite vertices", c, ninf);
        if (ninf == 0) finite++;
        for (uint32_t i = 0; i < 4; i++) {
            uint32_t f = dd_tn(t, c)[i];
            if (f == DD_NONE || (f >> 2) >= t->ncell || dd_tv(t, f >> 2)[0] == DD_DEAD)
                return refute(msg, msglen, DD_ERR_INTERNAL, "cell %u facet %u: no live neighbour", c, i);
            if (*dd_fn(t, f) != 4 * c + i)
                return refute(msg, msglen, DD_ERR_INTERNAL, "cell %u facet %u: neighbour link not symmetric", c, i);
            if (!same_facet(t, c, i, f >> 2, f & 3))
                return refute(msg, msglen, DD_ERR_INTERNAL, "cell %u facet %u: neighbour %u does not share the facet", c, i, f >> 2);
        }
        if (ninf == 0 && dd_orient3d(pr, dd_pt(t, v[0]), dd_pt(t, v[1]),
                                     dd_pt(t, v[2]), dd_pt(t, v[3])) <= 0)
            return refute(msg, msglen, DD_ERR_INTERNAL, "cell %u (points %d %d %d %d) is not positively oriented",
                          c, dd_input_index(t, v[0]), dd_input_index(t, v[1]),
                          dd_input_index(t, v[2]), dd_input_index(t, v[3]));
    }
    if (live != t->nlive || finite != t->nfinite)
        return refute(msg, msglen, DD_ERR_INTERNAL, "cell counts wrong: %zu live (recorded %u), %zu finite (recorded %u)",
                      live, t->nlive, finite, t->nfinite);
    /* every other cell is free, once, on the free list: none lost (the
     * cells a strategy gives back, wrap/run.c's w_drop_fill)                 */
    size_t nfree = 0;
    for (uint32_t c = t->free_head; c != DD_NONE; c = dd_tn(t, c)[0])
        if (c >= t->ncell || dd_tv(t, c)[0] != DD_DEAD || ++nfree > t->nfree)
            return refute(msg, msglen, DD_ERR_INTERNAL, "the free list is broken at cell %u", c);
    if (nfree != t->nfree || live + nfree != t->ncell)
        return refute(msg, msglen, DD_ERR_INTERNAL, "cells lost: %zu live and %zu free (recorded %u) of %u", live, nfree,
                      t->nfree, t->ncell);
    uint32_t nv = 0;
    for (uint32_t v = 0; v < t->nvid; v++) {
        uint32_t c = t->vcell[v];
        if (c == DD_NONE) continue;
        nv++;
        if (c >= t->ncell || dd_tv(t, c)[0] == DD_DEAD || dd_index_of(t, c, v) < 0)
            return refute(msg, msglen, DD_ERR_INTERNAL, "point %d: its cell link %u does not contain it", dd_input_index(t, v), c);
    }
    if (nv != t->nvert)
        return refute(msg, msglen, DD_ERR_INTERNAL, "vertex count wrong: %u found, %u recorded", nv, t->nvert);
    if (t->inf_cell == DD_NONE || dd_tv(t, t->inf_cell)[0] == DD_DEAD ||
        !dd_is_infinite_cell(t, t->inf_cell))
        return refute(msg, msglen, DD_ERR_INTERNAL, "the infinite vertex has no live cell link");
    return DD_OK;
}

/* The perturbed empty-sphere test across every facet: the vertex
 * across it is not in conflict with the cell.                          */
static dd_status check_delaunay(const dd_tri *t, dd_pred *pr, char *msg, size_t msglen)
{
    for (uint32_t c = 0; c < t->ncell; c++) {
        if (dd_tv(t, c)[0] == DD_DEAD) continue;
        for (uint32_t i = 0; i < 4; i++) {
            uint32_t w = *dd_fv(t, dd_tn(t, c)[i]);
            if (w == DD_INF) continue;
            if (dd_cell_conflict_on(t, pr, c, dd_pt(t, w)))
                return refute(msg, msglen, DD_ERR_INTERNAL,
                              "facet %u of cell %u is not locally Delaunay: point %d is in conflict",
                              i, c, dd_input_index(t, w));
        }
    }
    return DD_OK;
}

/* The same with the power test (a weighted t): every facet regular.    */
static dd_status check_regular(const dd_tri *t, dd_pred *pr, char *msg, size_t msglen)
{
    for (uint32_t c = 0; c < t->ncell; c++) {
        if (dd_tv(t, c)[0] == DD_DEAD) continue;
        for (uint32_t i = 0; i < 4; i++) {
            uint32_t w = *dd_fv(t, dd_tn(t, c)[i]);
            if (w == DD_INF) continue;
            if (dd_cell_power_conflict_on(t, pr, c, dd_pt(t, w), t->wt[w]))
                return refute(msg, msglen, DD_ERR_INTERNAL,
                              "facet %u of cell %u is not regular: point %d is in conflict with the power sphere",
                              i, c, dd_input_index(t, w));
        }
    }
    return DD_OK;
}

dd_status dd_mesh_check(const dd_tri *t, char *msg, size_t msglen)
{
    if (msg && msglen) msg[0] = 0;
    dd_pred pr;
    dd_pred_init(&pr);
    dd_status s = check_cells(t, &pr, msg, msglen);
    if (s == DD_OK) s = t->wt ? check_regular(t, &pr, msg, msglen) : check_delaunay(t, &pr, msg, msglen);
    if (s == DD_OK) s = dd_hidden_check(t, &pr, msg, msglen);
    dd_pred_clear(&pr);
    return s;
}
