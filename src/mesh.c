/*
 * mesh.c -- cell storage, point location and Bowyer-Watson insertion
 * (DESIGN 4 and 5).
 *
 * Owns: growth of the flat arrays, the free list of dead cells, the
 * visibility walk, the conflict search and the star re-filling of the
 * cavity.  Insertion is all-or-nothing: every allocation happens before
 * the first write to the mesh, so a failed insertion leaves it unchanged.
 */
#include "mesh.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

dd_status dd_vec_reserve(dd_vec *v, size_t cap)
{
    if (cap <= v->cap) return DD_OK;
    uint32_t *a = realloc(v->a, cap * sizeof *a);
    if (!a) return DD_ERR_NOMEM;
    v->a = a;
    v->cap = cap;
    return DD_OK;
}

void dd_vec_free(dd_vec *v)
{
    free(v->a);
    v->a = NULL;
    v->n = v->cap = 0;
}

dd_status dd_fail(dd_tri *t, dd_status s, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(t->err, sizeof t->err, fmt, ap);
    va_end(ap);
    return s;
}

dd_status dd_tri_alloc(dd_tri **out, uint32_t np)
{
    *out = NULL;
    dd_tri *t = calloc(1, sizeof *t);
    if (!t) return DD_ERR_NOMEM;
    uint32_t cap = np < 16 ? 16 : np;
    t->xyz = malloc(3 * (size_t)cap * sizeof *t->xyz);
    t->vcell = malloc((size_t)cap * sizeof *t->vcell);
    t->alias = malloc((size_t)cap * sizeof *t->alias);
    if (!t->xyz || !t->vcell || !t->alias) {
        free(t->xyz); free(t->vcell); free(t->alias); free(t);
        return DD_ERR_NOMEM;
    }
    t->cap_p = cap;
    t->free_head = DD_NONE;
    t->inf_cell = DD_NONE;
    t->hint = DD_NONE;
    t->rng = 0x9E3779B97F4A7C15ull;
    dd_pred_init(&t->pred);
    *out = t;
    return DD_OK;
}

void dd_free(dd_tri *t)
{
    if (!t) return;
    free(t->xyz); free(t->vcell); free(t->alias);
    free(t->tv); free(t->tn); free(t->stamp);
    dd_vec_free(&t->stack); dd_vec_free(&t->conflict); dd_vec_free(&t->boundary);
    dd_pred_clear(&t->pred);
    free(t);
}

/* ---- cell storage -------------------------------------------------------- */

dd_status dd_reserve_cells(dd_tri *t, uint32_t k)
{
    /* Cells on the free list count as room. */
    uint32_t onfree = 0;
    for (uint32_t c = t->free_head; c != DD_NONE && onfree < k; c = t->tn[4 * (size_t)c])
        onfree++;
    if (onfree >= k) return DD_OK;
    uint64_t need = (uint64_t)t->ncell + (k - onfree);
    if (need <= t->cap_c) return DD_OK;
    if (need > (UINT32_MAX - 8) / 4) return DD_ERR_NOMEM;
    uint64_t cap = t->cap_c ? t->cap_c : 64;
    while (cap < need) cap += cap / 2 + 1;
    if (cap > (UINT32_MAX - 8) / 4) cap = (UINT32_MAX - 8) / 4;
    uint32_t *tv = realloc(t->tv, 4 * cap * sizeof *tv);
    if (!tv) return DD_ERR_NOMEM;
    t->tv = tv;
    uint32_t *tn = realloc(t->tn, 4 * cap * sizeof *tn);
    if (!tn) return DD_ERR_NOMEM;
    t->tn = tn;
    uint32_t *st = realloc(t->stamp, cap * sizeof *st);
    if (!st) return DD_ERR_NOMEM;
    memset(st + t->cap_c, 0, (cap - t->cap_c) * sizeof *st);
    t->stamp = st;
    t->cap_c = (uint32_t)cap;
    return DD_OK;
}

uint32_t dd_new_cell(dd_tri *t)
{
    uint32_t c;
    if (t->free_head != DD_NONE) {
        c = t->free_head;
        t->free_head = t->tn[4 * (size_t)c];
    } else {
        c = t->ncell++;
    }
    t->stamp[c] = 0;
    t->nlive++;
    t->tets_created++;
    return c;
}

void dd_kill_cell(dd_tri *t, uint32_t c)
{
    t->tv[4 * (size_t)c] = DD_DEAD;
    t->tn[4 * (size_t)c] = t->free_head;
    t->free_head = c;
    t->nlive--;
}

/* ---- predicates on cells ------------------------------------------------- */

int dd_cell_conflict(dd_tri *t, uint32_t c, const double *p)
{
    const uint32_t *v = t->tv + 4 * (size_t)c;
    const double *q[4];
    int k = -1;
    for (int i = 0; i < 4; i++) {
        if (v[i] == DD_INF) { k = i; q[i] = NULL; }
        else q[i] = dd_pt(t, v[i]);
    }
    if (k < 0) return dd_insphere_perturbed(&t->pred, q[0], q[1], q[2], q[3], p) > 0;
    return dd_inf_conflict(&t->pred, q, k, p) > 0;
}

/* orient3d of cell c with its vertex i replaced by p (c finite). */
static int orient_replaced(dd_tri *t, uint32_t c, int i, const double *p)
{
    const uint32_t *v = t->tv + 4 * (size_t)c;
    const double *q[4];
    for (int k = 0; k < 4; k++) q[k] = (k == i) ? p : dd_pt(t, v[k]);
    return dd_orient3d(&t->pred, q[0], q[1], q[2], q[3]);
}

/* ---- point location ------------------------------------------------------ */

/* Visibility walk from `start` to a cell in conflict with p: a finite cell
 * whose closure contains p, or an infinite cell whose hull facet p sees
 * strictly.  Each step crosses a facet whose plane strictly separates the
 * cell from p; the facet tried first is random, so the walk cannot cycle.  */
static dd_status locate(dd_tri *t, const double *p, uint32_t start, uint32_t *out)
{
    uint32_t c = start;
    uint32_t from = DD_NONE;            /* facet index we entered through */
    uint64_t steps = 0, limit = 16 + 4 * (uint64_t)t->ncell;
    if (dd_is_infinite_cell(t, c)) {    /* start from its finite neighbour */
        int k = dd_index_of(t, c, DD_INF);
        uint32_t f = t->tn[4 * (size_t)c + (uint32_t)k];
        c = f >> 2;             /* nothing known about p yet: from stays */
    }
    for (;;) {
        if (++steps > limit)
            return dd_fail(t, DD_ERR_INTERNAL, "point location did not terminate");
        if (dd_is_infinite_cell(t, c)) { *out = c; break; }
        uint32_t r = dd_rand(t) & 3, next = DD_NONE;
        for (uint32_t k = 0; k < 4; k++) {
            uint32_t i = (r + k) & 3;
            if (i == from) continue;
            if (orient_replaced(t, c, (int)i, p) < 0) { next = t->tn[4 * (size_t)c + i]; break; }
        }
        if (next == DD_NONE) { *out = c; break; }
        c = next >> 2;
        from = next & 3;
    }
    t->walk_steps += steps;
    return DD_OK;
}

/* ---- Bowyer-Watson insertion --------------------------------------------- */

/* Marks the conflict region of p reachable from c0 (stamp == ep) and lists
 * its boundary facets (4c+i, c in conflict, its neighbour not).  Cells found
 * not in conflict get stamp ep+1 so they are tested once.                  */
static dd_status find_conflicts(dd_tri *t, const double *p, uint32_t c0, uint32_t ep)
{
    t->stack.n = t->conflict.n = t->boundary.n = 0;
    t->stamp[c0] = ep;
    dd_status s = dd_vec_push(&t->stack, c0);
    while (s == DD_OK && t->stack.n > 0) {
        uint32_t c = t->stack.a[--t->stack.n];
        s = dd_vec_push(&t->conflict, c);
        for (uint32_t i = 0; i < 4 && s == DD_OK; i++) {
            uint32_t nb = t->tn[4 * (size_t)c + i] >> 2;
            if (t->stamp[nb] == ep) continue;
            if (t->stamp[nb] != ep + 1 && dd_cell_conflict(t, nb, p)) {
                t->stamp[nb] = ep;
                s = dd_vec_push(&t->stack, nb);
            } else {
                t->stamp[nb] = ep + 1;
                s = dd_vec_push(&t->boundary, 4 * c + i);
            }
        }
    }
    return s;
}

/* Replaces the marked conflict cells (stamp == ep) by the star of vertex v
 * over the boundary facets.  Rooms for the new cells must be reserved.     */
static void fill_star(dd_tri *t, uint32_t v, uint32_t ep)
{
    /* 1. One new cell per boundary facet: the conflict cell's vertices with
     *    the one opposite the facet replaced by v.  Glue it to the outside
     *    cell, then point the old facet at the new cell so the rotation in
     *    step 2 can find it.                                               */
    for (size_t b = 0; b < t->boundary.n; b++) {
        uint32_t f = t->boundary.a[b], c = f >> 2, i = f & 3;
        uint32_t n = dd_new_cell(t);
        for (uint32_t k = 0; k < 4; k++) {
            t->tv[4 * (size_t)n + k] = k == i ? v : t->tv[4 * (size_t)c + k];
            t->tn[4 * (size_t)n + k] = DD_NONE;
        }
        dd_glue(t, 4 * n + i, t->tn[f]);
        t->tn[f] = 4 * n + i;
    }
    /* 2. Glue the new cells to each other: the neighbour of new cell n
     *    (from conflict facet c,i) across its facet j != i holds v and the
     *    edge e = tv(c) minus {tv[c,i], tv[c,j]}.  Turn around e through
     *    conflict cells until a boundary facet: its new cell is the one.   */
    for (size_t b = 0; b < t->boundary.n; b++) {
        uint32_t f = t->boundary.a[b], c = f >> 2, i = f & 3;
        uint32_t n = t->tn[f] >> 2;
        for (uint32_t j = 0; j < 4; j++) {
            if (j == i || t->tn[4 * (size_t)n + j] != DD_NONE) continue;
            uint32_t cur = c, fin = i, fout = j;
            for (;;) {
                uint32_t x = t->tn[4 * (size_t)cur + fout], nb = x >> 2;
                if (t->stamp[nb] != ep) {            /* nb is a new cell */
                    dd_glue(t, 4 * n + j, 4 * nb + fin);
                    break;
                }
                uint32_t e0 = 0;
                while (e0 == fin || e0 == fout) e0++;
                uint32_t e1 = 6 - fin - fout - e0;
                int p0 = dd_index_of(t, nb, t->tv[4 * (size_t)cur + e0]);
                int p1 = dd_index_of(t, nb, t->tv[4 * (size_t)cur + e1]);
                fin = x & 3;
                fout = 6 - fin - (uint32_t)p0 - (uint32_t)p1;
                cur = nb;
            }
        }
    }
    /* 3. Vertex links, then recycle the conflict cells. */
    for (size_t b = 0; b < t->boundary.n; b++) {
        uint32_t n = t->tn[t->boundary.a[b]] >> 2;
        int inf = 0;
        for (uint32_t k = 0; k < 4; k++) {
            uint32_t w = t->tv[4 * (size_t)n + k];
            if (w == DD_INF) { t->inf_cell = n; inf = 1; }
            else t->vcell[w] = n;
        }
        if (!inf) t->nfinite++;
        t->hint = n;
    }
    for (size_t k = 0; k < t->conflict.n; k++) {
        uint32_t c = t->conflict.a[k];
        if (!dd_is_infinite_cell(t, c)) t->nfinite--;
        dd_kill_cell(t, c);
    }
}

dd_status dd_insert_vertex(dd_tri *t, uint32_t v)
{
    const double *p = dd_pt(t, v);
    uint32_t start = t->hint;
    if (start == DD_NONE || t->tv[4 * (size_t)start] == DD_DEAD) start = t->inf_cell;
    uint32_t c0 = DD_NONE;
    dd_status s = locate(t, p, start, &c0);
    if (s != DD_OK) return s;
    uint32_t ep = dd_new_epoch(t, 2);
    s = find_conflicts(t, p, c0, ep);
    if (s == DD_OK) s = dd_reserve_cells(t, (uint32_t)t->boundary.n);
    if (s != DD_OK) return dd_fail(t, s, "out of memory inserting vertex %u", v);
    fill_star(t, v, ep);
    t->nvert++;
    return DD_OK;
}
