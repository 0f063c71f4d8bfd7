/*
 * flip.c -- a vertex moved in place, the triangulation repaired by flips
 * (Lawson's flips in 3D: 2-3 and 3-2), for dd_move.
 *
 * Moving v to p changes only the signs that involve v.  If every cell of
 * v's star stays positively oriented, the mesh with v at p is still a
 * triangulation, and only facets of the star can fail to be locally
 * Delaunay.  Each such facet is flipped when its two cells' union is
 * convex (2-3), or when the edge that makes it reflex has three cells
 * around it (3-2); a flip keeps a triangulation, and the facets of its
 * new cells are tested in turn.  When no facet tested fails, every facet
 * is locally Delaunay (the others kept their points and cells), so the
 * mesh is the perturbed DT of the moved set: the Delaunay lemma.
 *
 * In 3D a facet may stay unflippable (Lawson's flips can get stuck), and
 * the perturbed predicates are not used for flat configurations: then, or
 * when a star cell inverts, a hull facet fails (the hull would change),
 * or the flips pass DD_FLIP_MAX, the repair gives up and the mesh is put
 * back exactly: touched cells are logged before their first write, the
 * cells a flip replaces are only killed once the repair succeeds, and the
 * new cells are given back in reverse (dd_unmake_cells).
 *
 * The first pass over the star (star_test) is the relocation filter: the
 * orientations and in-sphere tests of the star's cells are evaluated in
 * one frame lifted at p (geom/lift.h), each cell's three other vertices
 * lifted once and its in-sphere tests reduced to one dot product per
 * facet; only the facets the filter cannot certify, or that fail, go to
 * Lawson's loop, which tests them exactly.
 *
 * Cost: O(star) tests, plus O(1) a flip.
 */
#include "mesh/mesh.h"
#include "mesh/hidden_move.h"
#include "geom/lift.h"

#include <stdlib.h>
#include <string.h>

/* Flips before the repair gives up (a move by a fraction of the spacing
 * takes a few; the reinsertion it falls back to costs about a dozen).   */
#define DD_FLIP_MAX 24

/* The repair's state: cells made, cells replaced (killed on success),
 * logged cells (id, then their 8 words as they were), the facet stack. */
typedef struct flip_state {
    dd_tri *t;
    dd_vec *made, *gone, *log, *stack, *later;   /* t's scratch, reused   */
    dd_mark touched;            /* stamp of a cell logged already          */
    dd_mark replaced;           /* stamp of a cell a flip replaced         */
    int flips;
    int power;                  /* power tests: weighted t (DESIGN 12)    */
} flip_state;

/* Logs cell c before its first write in this repair. */
static dd_status touch(flip_state *f, uint32_t c)
{
    dd_tri *t = f->t;
    if (t->stamp[c] == f->touched) return DD_OK;
    dd_status s = dd_vec_room(f->log, 1 + DD_CELL_WORDS);
    if (s != DD_OK) return s;
    f->log->a[f->log->n++] = c;
    memcpy(f->log->a + f->log->n, dd_tv(t, c), DD_CELL_WORDS * sizeof *f->log->a);
    f->log->n += DD_CELL_WORDS;
    t->stamp[c] = f->touched;
    return DD_OK;
}

/* Puts the mesh back as it was before the repair. */
static void undo(flip_state *f, uint32_t ncell0)
{
    dd_tri *t = f->t;
    for (size_t k = f->log->n; k > 0;) {     /* restore, last logged first */
        k -= 1 + DD_CELL_WORDS;
        memcpy(dd_tv(t, f->log->a[k]), f->log->a + k + 1, DD_CELL_WORDS * sizeof *f->log->a);
    }
    dd_unmake_cells(t, f->made->a, f->made->n, ncell0);
}

static int is_gone(const flip_state *f, uint32_t c)
{
    return f->t->stamp[c] == f->replaced;
}

/* The five vertices of a flip, loc[0..5), name its facets: a facet is the
 * mask of the local indices of its three vertices.                       */
static uint32_t cell_mask(const uint32_t loc[5], const uint32_t *w, uint32_t bit[4])
{
    uint32_t all = 0;
    for (int i = 0; i < 4; i++) {
        int k = 0;
        while (k < 4 && loc[k] != w[i]) k++;
        bit[i] = 1u << k;
        all |= bit[i];
    }
    return all;
}

/* Replaces the k old cells old[] by the m new cells of vertices nv[4m]
 * (positively oriented), all on the five vertices loc[]: a facet of a new
 * cell that was on the old cells' boundary is glued to the outside cell
 * there, the others to each other.  Pushes the boundary facets for
 * testing; the facets between new cells are locally Delaunay already (a
 * flip trades the two triangulations of five points, and the one it
 * leaves failed the same five-point in-sphere test).                     */
static dd_status replace(flip_state *f, const uint32_t loc[5], const uint32_t *old, int k, const uint32_t (*nv)[4],
                         int m)
{
    dd_tri *t = f->t;
    uint32_t outside[32], pending[32], has_out = 0, has_pend = 0, bit[4];
    dd_status s = dd_vec_room(f->stack, 4 * (size_t)m);
    /* room first: a cell made and not listed in made could not be undone */
    if (s == DD_OK) s = dd_vec_room(f->made, (size_t)m);
    if (s == DD_OK) s = dd_vec_room(f->gone, (size_t)k);
    for (int a = 0; a < k && s == DD_OK; a++) {
        const uint32_t all = cell_mask(loc, dd_tv(t, old[a]), bit);
        for (uint32_t i = 0; i < 4 && s == DD_OK; i++) {
            const uint32_t g = dd_tn(t, old[a])[i], n = g >> 2;
            if (n == old[0] || n == old[1] || (k == 3 && n == old[2])) continue;
            outside[all & ~bit[i]] = g;
            has_out |= 1u << (all & ~bit[i]);
            s = touch(f, n);                   /* its back pointer is rewritten */
        }
    }
    for (int b = 0; b < m && s == DD_OK; b++) {
        const uint32_t nc = dd_new_cell(t), all = cell_mask(loc, nv[b], bit);
        memcpy(dd_tv(t, nc), nv[b], 4 * sizeof **nv);
        s = dd_vec_push(f->made, nc);
        for (uint32_t i = 0; i < 4 && s == DD_OK; i++) {
            const uint32_t key = all & ~bit[i];
            if (has_out >> key & 1) {
                dd_glue(t, 4 * nc + i, outside[key]);
                f->stack->a[f->stack->n++] = 4 * nc + i;
            } else if (has_pend >> key & 1) {
                dd_glue(t, 4 * nc + i, pending[key]);
                has_pend &= ~(1u << key);
            } else {
                pending[key] = 4 * nc + i;
                has_pend |= 1u << key;
            }
        }
    }
    if (s == DD_OK && has_pend) return DD_ERR_INTERNAL;
    for (int a = 0; a < k && s == DD_OK; a++) {
        s = dd_vec_push(f->gone, old[a]);
        t->stamp[old[a]] = f->replaced;
    }
    f->flips++;
    return s;
}

static int has(const uint32_t *v, uint32_t x)
{
    return v[0] == x || v[1] == x || v[2] == x || v[3] == x;
}

/* orient3d of the four vertices (all finite). */
static int orient4(dd_tri *t, const uint32_t *v)
{
    return dd_orient3d(&t->pred, dd_pt(t, v[0]), dd_pt(t, v[1]), dd_pt(t, v[2]), dd_pt(t, v[3]));
}

/* Flips facet i of cell c (apex x) with neighbour n (apex o), both finite:
 * 2-3 when the union is convex, else 3-2 around its reflex edge when that
 * edge has three cells.  0 when done, 1 when not flippable now, -1 when
 * the configuration is flat (give up).                                  */
static int flip(flip_state *f, uint32_t c, uint32_t i, dd_status *err)
{
    dd_tri *t = f->t;
    const uint32_t g = dd_tn(t, c)[i], n = g >> 2, x = dd_tv(t, c)[i], o = dd_tv(t, n)[g & 3];
    const uint32_t tri[3] = {dd_tv(t, c)[dd_facet[i][0]], dd_tv(t, c)[dd_facet[i][1]], dd_tv(t, c)[dd_facet[i][2]]};
    const uint32_t loc[5] = {tri[0], tri[1], tri[2], o, x};
    uint32_t nv[3][4];
    int reflex = -1;
    for (int e = 0; e < 3; e++) {     /* cell (p, q, o, x) for edge pq of the facet */
        nv[e][0] = tri[e], nv[e][1] = tri[(e + 1) % 3], nv[e][2] = o, nv[e][3] = x;
        const int s = orient4(t, nv[e]);
        if (s == 0) return -1;
        if (s < 0) reflex = e;
    }
    if (reflex < 0) {
        const uint32_t old[2] = {c, n};
        *err = replace(f, loc, old, 2, (const uint32_t(*)[4])nv, 3);
        return 0;
    }
    /* 3-2: the third cell around edge pq must hold x and o */
    const uint32_t p = tri[reflex], q = tri[(reflex + 1) % 3], r = tri[(reflex + 2) % 3];
    const int ri = dd_index_of(t, c, r);
    const uint32_t m = dd_tn(t, c)[(uint32_t)ri] >> 2;
    if (dd_is_infinite_cell(t, m) || !has(dd_tv(t, m), o) || !has(dd_tv(t, m), p) || !has(dd_tv(t, m), q) ||
        is_gone(f, m))
        return 1;
    uint32_t two[2][4] = {{r, x, o, p}, {r, x, o, q}};
    int side[2];
    for (int b = 0; b < 2; b++) {
        side[b] = orient4(t, two[b]);
        if (side[b] == 0) return -1;
        if (side[b] < 0) { uint32_t s0 = two[b][0]; two[b][0] = two[b][1]; two[b][1] = s0; }
    }
    if (side[0] == side[1]) return 1;        /* pq does not cross rxo */
    const uint32_t old[3] = {c, n, m};
    *err = replace(f, loc, old, 3, (const uint32_t(*)[4])two, 2);
    return 0;
}

/* Facet i of cell c is not locally Delaunay (locally regular, with
 * power tests): the apex across it is in conflict with c, or across a
 * hull facet, c's own apex is in conflict with the infinite cell.      */
static int facet_bad(const flip_state *f, uint32_t c, uint32_t i)
{
    dd_tri *t = f->t;
    const uint32_t g = dd_tn(t, c)[i], n = g >> 2, o = dd_tv(t, n)[g & 3], x = dd_tv(t, c)[i];
    if (f->power) {
        if (o != DD_INF) return dd_cell_power_conflict_fast(t, c, dd_pt(t, o), t->wt[o]);
        return x != DD_INF && dd_cell_power_conflict_fast(t, n, dd_pt(t, x), t->wt[x]);
    }
    if (o != DD_INF) return dd_cell_conflict_fast(t, c, dd_pt(t, o));
    return x != DD_INF && dd_cell_conflict(t, n, dd_pt(t, x));
}

/* Lawson's loop over the stacked facets: 1 when every facet is locally
 * Delaunay, 0 to give up.  A facet not flippable now is kept aside and
 * tried again once the stack is empty.                                  */
static int lawson(flip_state *f, dd_status *err)
{
    dd_tri *t = f->t;
    dd_vec *later = f->later;
    int ok = 1;
    later->n = 0;
    for (int round = 0; ok && (f->stack->n > 0 || later->n > 0) && round < 4; round++) {
        if (f->stack->n == 0) {              /* the facets set aside, once more */
            dd_vec *s = f->stack;
            f->stack = later;
            later = s;
            later->n = 0;
        }
        while (ok && f->stack->n > 0) {
            const uint32_t fc = f->stack->a[--f->stack->n], c = fc >> 2, i = fc & 3;
            if (dd_tv(t, c)[0] == DD_DEAD || is_gone(f, c)) continue;
            const uint32_t g = dd_tn(t, c)[i], n = g >> 2;
            if (!facet_bad(f, c, i)) continue;
            if (dd_is_infinite_cell(t, c) || dd_is_infinite_cell(t, n) || f->flips >= DD_FLIP_MAX) { ok = 0; break; }
            const int r = flip(f, c, i, err);
            if (*err != DD_OK || r < 0) ok = 0;
            else if (r > 0 && (*err = dd_vec_push(later, fc)) != DD_OK) ok = 0;
        }
        if (ok && f->stack->n == 0 && later->n > 0 && round == 3) ok = 0;
    }
    return ok && *err == DD_OK;
}

/* Positions but i, in an order that makes (i, after[i][0..3)) an even
 * permutation of (0, 1, 2, 3): the orientation of a cell, with vertex i
 * first.                                                                 */
static const uint8_t after[4][3] = {{1, 2, 3}, {0, 3, 2}, {3, 0, 1}, {2, 1, 0}};

/* The relocation filter, v now at p: every finite cell of v's star
 * positively oriented, and each facet of the star (a facet through v
 * from the cell of lesser id, a link facet from the star) locally
 * Delaunay.  In the frame lifted at p, where v's row is 0, a cell's
 * orientation is det3 of its other three rows R (in `after` order) and
 * its in-sphere test against an apex o is the cofactors K of R dotted
 * with L[o]: K . L[o] < 0 iff o is inside the cell's sphere (lift.h).
 * Pushes the facets the filter cannot certify, or that fail, on
 * f->stack (room made by the caller) for Lawson's exact tests; hull
 * cells go there whole.  0 when a star cell is not positively oriented. */
static int star_test(flip_state *f, uint32_t v, const double *p)
{
    dd_tri *t = f->t;
    const dd_vec *star = &t->conflict;
    dd_vec *stack = f->stack;
    for (size_t k = 0; k < star->n; k++) {
        const uint32_t c = star->a[k], *w = dd_tv(t, c), *nb = dd_tn(t, c);
        const uint32_t i = dd_slot_of(w, v);
        if (has(w, DD_INF)) {
            for (uint32_t j = 0; j < 4; j++)
                if (j == i || c < nb[j] >> 2) stack->a[stack->n++] = 4 * c + j;
            continue;
        }
        double R[3][4], mi[6], K[4], m = 0;
        for (int a = 0; a < 3; a++) m = dd_lift_max(m, dd_lift_row(R[a], dd_pt(t, w[after[i][a]]), p));
        dd_lift_minors(mi, R[0], R[1]);
        if (dd_lift_orient(mi, R[2]) > dd_lift_orient_err(m)) {
#ifdef DD_TEST_BUILD
            if (orient4(t, w) <= 0) __builtin_trap();   /* the filter is never wrong */
#endif
        } else if (orient4(t, w) <= 0) {
            return 0;
        }
        dd_lift_cofactors(K, R[2], mi);
        for (uint32_t j = 0; j < 4; j++) {
            if (j != i && c > nb[j] >> 2) continue;
            const uint32_t apex = dd_tv(t, nb[j] >> 2)[nb[j] & 3];
            if (apex != DD_INF) {
                double L[4];
                const double ma = dd_lift_max(m, dd_lift_row(L, dd_pt(t, apex), p));
                if (dd_lift_dot4(K, L) > dd_lift_err(ma)) {
#ifdef DD_TEST_BUILD
                    if (dd_cell_conflict(t, c, dd_pt(t, apex))) __builtin_trap();
#endif
                    continue;
                }
            }
            stack->a[stack->n++] = 4 * c + j;
        }
    }
    return 1;
}

/* The repair succeeded: vertex links, the cells made and kept noted
 * (dd_note_made), the count of finite cells (every flipped cell is
 * finite: + the new ones, - the replaced ones; a cell made and replaced
 * counts in both), the replaced cells killed.                          */
static void commit(flip_state *f)
{
    dd_tri *t = f->t;
    for (size_t k = 0; k < f->made->n; k++) {
        const uint32_t c = f->made->a[k];
        if (is_gone(f, c)) continue;
        for (int i = 0; i < 4; i++) t->vcell[dd_tv(t, c)[i]] = c;
        dd_note_cell(t, c);
    }
    t->nfinite += (uint32_t)f->made->n;
    t->nfinite -= (uint32_t)f->gone->n;
    for (size_t k = 0; k < f->gone->n; k++) dd_kill_cell(t, f->gone->a[k]);
    for (size_t k = f->made->n; k > 0; k--)
        if (!is_gone(f, f->made->a[k - 1])) {
            t->hint = f->made->a[k - 1];
            break;
        }
}

int dd_move_by_flips(dd_tri *t, uint32_t v, const double p[3], int *flips, dd_status *err)
{
    *flips = 0;
    *err = dd_star_cells(t, v, &t->conflict);
    if (*err != DD_OK) return 0;
    dd_vec *sc = t->flip;
    for (int k = 0; k < 5; k++) sc[k].n = 0;
    if ((*err = dd_vec_room(&sc[3], 4 * t->conflict.n)) != DD_OK) return 0;
    const dd_mark mark = dd_new_epoch(t, 2);
    flip_state f = {t, &sc[0], &sc[1], &sc[2], &sc[3], &sc[4], mark, (dd_mark)(mark + 1), 0, 0};
    double *x = t->xyz + 3 * (size_t)v, old[3] = {x[0], x[1], x[2]};
    x[0] = p[0], x[1] = p[1], x[2] = p[2];
    if (!star_test(&f, v, p)) {
        x[0] = old[0], x[1] = old[1], x[2] = old[2];
        return 0;
    }
    const uint32_t ncell0 = t->ncell;
    *err = dd_reserve_cells(t, 3 * DD_FLIP_MAX);
    const int ok = *err == DD_OK && lawson(&f, err);
    if (!ok) {
        undo(&f, ncell0);
        x[0] = old[0], x[1] = old[1], x[2] = old[2];
    } else {
        commit(&f);
        *flips = f.flips;
    }
    return ok;
}

/* ---- weighted moves --------------------------------------------------- */

/* Star cells ahead of the one tested whose apex across the link is
 * prefetched: its cell, prefetched first, has arrived by then.        */
#define DD_STAR_AHEAD 4

/* Prefetches the point and weight of the apex across star cell c's link
 * facet (the vertex opposite v in the cell there).                      */
static void prefetch_apex(const dd_tri *t, uint32_t c, uint32_t v)
{
    const uint32_t g = dd_tn(t, c)[dd_slot_of(dd_tv(t, c), v)], o = dd_tv(t, g >> 2)[g & 3];
    if (o == DD_INF) return;
    __builtin_prefetch(t->xyz + 3 * (size_t)o);
    __builtin_prefetch(t->wt + o);
}

/* The weighted counterpart of star_test, v now at (p, w): every finite
 * star cell positively oriented (unchanged when only the weight changed:
 * !moved, no test) and each facet of the star locally regular.  In the
 * frame lifted at (p, w), a vertex x's row is (x - p, |x - p|^2 -
 * (w_x - w)) (lift.h's weighted lift), v's is 0, and a cell's power
 * test against an apex o is K . L[o] as in star_test, certified beyond
 * dd_lift_power_err of the frame's m and W = max |w_x - w| (the cell's
 * three rows and the apex's).  Pushes the facets the filter cannot
 * certify, or that fail, on f->stack (room made by the caller) for
 * Lawson's exact power tests; hull cells go there whole.  0 when a star
 * cell is not positively oriented.                                      */
static int star_test_power(flip_state *f, uint32_t v, const double *p, double wv, int moved)
{
    dd_tri *t = f->t;
    const dd_vec *star = &t->conflict;
    dd_vec *stack = f->stack;
    const uint32_t *head = t->hid && t->hid->keep ? t->hid->head : NULL, ncap = head ? t->hid->ncap : 0;
    for (size_t k = 0; k < star->n; k++) {     /* the cells across the link, and the lists read after */
        const uint32_t c = star->a[k];
        __builtin_prefetch(dd_tv(t, dd_tn(t, c)[dd_slot_of(dd_tv(t, c), v)] >> 2));
        if (c < ncap) __builtin_prefetch(head + c);
    }
    for (size_t k = 0; k < star->n; k++) {
        if (k + DD_STAR_AHEAD < star->n) prefetch_apex(t, star->a[k + DD_STAR_AHEAD], v);
        const uint32_t c = star->a[k], *w = dd_tv(t, c), *nb = dd_tn(t, c);
        const uint32_t i = dd_slot_of(w, v);
        if (has(w, DD_INF)) {
            for (uint32_t j = 0; j < 4; j++)
                if (j == i || c < nb[j] >> 2) stack->a[stack->n++] = 4 * c + j;
            continue;
        }
        double R[3][4], mi[6], K[4], m = 0, W = 0;
        for (int a = 0; a < 3; a++) {
            const uint32_t x = w[after[i][a]];
            const double dw = t->wt[x] - wv;
            W = dd_lift_max(W, fabs(dw));
            m = dd_lift_max(m, dd_lift_row_power(R[a], dd_pt(t, x), p, dw));
        }
        dd_lift_minors(mi, R[0], R[1]);
        if (!moved) {
#ifdef DD_TEST_BUILD
            if (orient4(t, w) <= 0) __builtin_trap();   /* a weight alone turns no cell */
#endif
        } else if (dd_lift_orient(mi, R[2]) > dd_lift_orient_err(m)) {
#ifdef DD_TEST_BUILD
            if (orient4(t, w) <= 0) __builtin_trap();   /* the filter is never wrong */
#endif
        } else if (orient4(t, w) <= 0) {
            return 0;
        }
        dd_lift_cofactors(K, R[2], mi);
        for (uint32_t j = 0; j < 4; j++) {
            if (j != i && c > nb[j] >> 2) continue;
            const uint32_t apex = dd_tv(t, nb[j] >> 2)[nb[j] & 3];
            if (apex != DD_INF) {
                double L[4];
                const double dw = t->wt[apex] - wv;
                const double Wa = dd_lift_max(W, fabs(dw));
                const double ma = dd_lift_max(m, dd_lift_row_power(L, dd_pt(t, apex), p, dw));
                if (dd_lift_dot4(K, L) > dd_lift_power_err(ma, Wa)) {
#ifdef DD_TEST_BUILD
                    if (dd_cell_power_conflict_fast(t, c, dd_pt(t, apex), t->wt[apex])) __builtin_trap();
#endif
                    continue;
                }
            }
            stack->a[stack->n++] = 4 * c + j;
        }
    }
    return 1;
}

/* Writes (p, w) as v's point and weight. */
static void put_point(dd_tri *t, uint32_t v, const double p[3], double w)
{
    double *x = t->xyz + 3 * (size_t)v;
    x[0] = p[0], x[1] = p[1], x[2] = p[2];
    t->wt[v] = w;
}

int dd_move_power_by_flips(dd_tri *t, uint32_t v, const double p[3], double w, int *flips, dd_status *err)
{
    *flips = 0;
    *err = dd_star_cells(t, v, &t->conflict);
    if (*err != DD_OK || dd_hidden_star_copies(t, v, t->conflict.a, t->conflict.n)) return 0;
    dd_vec *sc = t->flip;
    for (int k = 0; k < 5; k++) sc[k].n = 0;
    if ((*err = dd_vec_room(&sc[3], 4 * t->conflict.n)) != DD_OK) return 0;
    const dd_mark mark = dd_new_epoch(t, 2);
    flip_state f = {t, &sc[0], &sc[1], &sc[2], &sc[3], &sc[4], mark, (dd_mark)(mark + 1), 0, 1};
    const double *x = dd_pt(t, v);
    const double old[3] = {x[0], x[1], x[2]}, wold = t->wt[v];
    const int moved = old[0] != p[0] || old[1] != p[1] || old[2] != p[2];
    put_point(t, v, p, w);
    if (!star_test_power(&f, v, p, w, moved)) {
        put_point(t, v, old, wold);
        return 0;
    }
    const uint32_t ncell0 = t->ncell;
    *err = dd_reserve_cells(t, 3 * DD_FLIP_MAX);
    if (*err == DD_OK && t->hid && t->hid->keep) *err = dd_hidden_room(t, (size_t)ncell0 + 3 * DD_FLIP_MAX);
    int ok = *err == DD_OK && lawson(&f, err);
    dd_vec *homes = f.stack;                 /* empty once Lawson's loop succeeded */
    if (ok && t->hid && t->hid->keep)
        ok = dd_hidden_flips_hold(t, v, f.made, f.gone, f.replaced, moved, homes, err);
    if (!ok) {
        undo(&f, ncell0);
        put_point(t, v, old, wold);
        return 0;
    }
    commit(&f);
    if (t->hid && t->hid->keep) dd_hidden_flips_rehome(t, f.gone, homes);
    *flips = f.flips;
    return 1;
}
