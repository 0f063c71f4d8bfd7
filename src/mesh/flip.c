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
 * A weighted move whose star cell inverts first flips that cell away
 * (unturn: a 2-3 or 3-2 flip with the cell across its link facet, valid
 * as a triangulation once its new cells are positively oriented), then
 * tests the new star as a whole; the facets Lawson's loop gets are the
 * same as for a star that stayed positive.
 *
 * In 3D a facet may stay unflippable (Lawson's flips can get stuck), and
 * the perturbed predicates are not used for flat configurations: then, or
 * when a star cell inverts (and, weighted, unturn cannot remove it), a
 * hull facet fails (the hull would change),
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
 * logged cells (id, then their 8 words as they were), the facet stack;
 * the sets of the cells logged and replaced, emptied at the first flip
 * (before it, both are empty: read them only once flips > 0).  The sets
 * (hidden_move.h's dd_cellset, on the stack, as is a move's star of at
 * most DD_STAR_LOCAL cells) hold at most 6 (logged) or 3 (replaced)
 * cells a flip, so never more than 6 * DD_FLIP_MAX = 144 of their
 * DD_SET_SLOTS = 256: the probes end.  They stand in for the per-cell
 * marks, whose reads and writes miss the cache on cells scattered
 * through the mesh.                                                     */
typedef struct flip_state {
    dd_tri *t;
    dd_vec *made, *gone, *log, *stack, *later;   /* t's scratch, reused   */
    int flips;
    int power;                  /* power tests: weighted t (DESIGN 12)    */
    int hull;                   /* the star tested has an infinite cell   */
    uint32_t touched_set[DD_SET_SLOTS], gone_set[DD_SET_SLOTS];
} flip_state;

/* A repair of t (power: weighted) about to start: t's scratch vectors as
 * its lists, no flip yet.  The sets are left as they are (2 KB that a
 * move without flips never reads).                                      */
static void start_repair(flip_state *f, dd_tri *t, int power)
{
    dd_vec *sc = t->flip;
    f->t = t;
    f->made = &sc[0], f->gone = &sc[1], f->log = &sc[2], f->stack = &sc[3], f->later = &sc[4];
    f->flips = 0;
    f->power = power;
    f->hull = 0;
}

/* Logs cell c before its first write in this repair. */
static dd_status touch(flip_state *f, uint32_t c)
{
    dd_tri *t = f->t;
    if (dd_cellset_has(f->touched_set, c)) return DD_OK;
    dd_status s = dd_vec_room(f->log, 1 + DD_CELL_WORDS);
    if (s != DD_OK) return s;
    f->log->a[f->log->n++] = c;
    memcpy(f->log->a + f->log->n, dd_tv(t, c), DD_CELL_WORDS * sizeof *f->log->a);
    f->log->n += DD_CELL_WORDS;
    dd_cellset_add(f->touched_set, c);
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
    return f->flips > 0 && dd_cellset_has(f->gone_set, c);
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
    if (f->flips == 0) {
        memset(f->touched_set, 0xff, sizeof f->touched_set);
        memset(f->gone_set, 0xff, sizeof f->gone_set);
    }
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
        dd_cellset_add(f->gone_set, old[a]);
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

/* The three cells of a 2-3 flip of facet tri between apexes x and o:
 * nv[e] = (edge e of tri, o, x).  -2 when one is flat, else the last
 * edge e whose cell is negatively oriented (the union's reflex edge),
 * or -1 when all three are positive (the union is convex).            */
static int cells_2_3(dd_tri *t, const uint32_t tri[3], uint32_t o, uint32_t x, uint32_t nv[3][4])
{
    int reflex = -1;
    for (int e = 0; e < 3; e++) {
        nv[e][0] = tri[e], nv[e][1] = tri[(e + 1) % 3], nv[e][2] = o, nv[e][3] = x;
        const int s = orient4(t, nv[e]);
        if (s == 0) return -2;
        if (s < 0) reflex = e;
    }
    return reflex;
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
    const int reflex = cells_2_3(t, tri, o, x, nv);
    if (reflex == -2) return -1;
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
 * tried again once the stack is empty, unless no flip was made since
 * the facets kept aside were last tried: the mesh is then the same, so
 * they would all be kept aside again, and the loop gives up at once
 * (the same answer as going round to the last round).                 */
static int lawson(flip_state *f, dd_status *err)
{
    dd_tri *t = f->t;
    dd_vec *later = f->later;
    int ok = 1, flips0 = -1;
    later->n = 0;
    for (int round = 0; ok && (f->stack->n > 0 || later->n > 0) && round < 4; round++) {
        if (f->stack->n == 0) {              /* the facets set aside, once more */
            if (f->flips == flips0) {        /* no flip since: stuck for good */
                ok = 0;
                break;
            }
            dd_vec *s = f->stack;
            f->stack = later;
            later = s;
            later->n = 0;
        }
        flips0 = f->flips;
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

/* ---- the star of the moved vertex ---------------------------------------- */

/* Largest star collected with the local set below (at most half full);
 * a larger one is collected by dd_star_cells with the epoch marks.     */
#define DD_STAR_LOCAL 128

/* What move_star prefetches besides the star's cells: the cell across
 * each link facet (for the link facets' tests), the vertices' points and
 * weights (for the star test's rows), the heads of the cells' lists of
 * hidden points (t->hid kept and nin[v] > 0: for dd_hidden_flips_hold). */
enum { DD_STAR_LINK = 1, DD_STAR_POINTS = 2, DD_STAR_LISTS = 4 };

/* v's star into out, as dd_star_cells (breadth first from t->vcell[v]),
 * without the per-cell marks: the cells seen are kept in a small set on
 * the stack, and each cell found is prefetched when it is found, so the
 * cells of a breadth-first level arrive together rather than one after
 * the other (what = DD_STAR_* adds the other prefetches).  A star of
 * more than DD_STAR_LOCAL cells is handed to dd_star_cells.  O(star);
 * DD_ERR_NOMEM when out cannot grow.                                    */
static dd_status move_star(dd_tri *t, uint32_t v, dd_vec *out, int what)
{
    dd_status s = dd_vec_room(out, DD_STAR_LOCAL + 4);
    if (s != DD_OK) return s;
    uint32_t set[DD_SET_SLOTS];
    memset(set, 0xff, sizeof set);
    uint32_t *a = out->a, n = 1;
    a[0] = t->vcell[v];
    dd_cellset_add(set, a[0]);
    int lists = what & DD_STAR_LISTS;
    for (uint32_t k = 0; k < n; k++) {
        const uint32_t *tv = dd_tv(t, a[k]), *tn = dd_tn(t, a[k]);
        if (k == 0 && lists) {      /* the lists are read only when v's bound says some hold points */
            lists = v < t->hid->vcap && t->hid->nin[v] > 0;
            if (lists && a[0] < t->hid->ncap) __builtin_prefetch(t->hid->head + a[0]);
        }
        for (uint32_t j = 0; j < 4; j++) {
            const uint32_t x = tv[j], nb = tn[j] >> 2;
            if (x == v) {
                if (what & DD_STAR_LINK) __builtin_prefetch(dd_tv(t, nb));
                continue;
            }
            if (what & DD_STAR_POINTS && x != DD_INF) {
                __builtin_prefetch(t->xyz + 3 * (size_t)x);
                __builtin_prefetch(t->wt + x);
            }
            if (!dd_cellset_add(set, nb)) continue;
            __builtin_prefetch(dd_tv(t, nb));
            if (lists && nb < t->hid->ncap) __builtin_prefetch(t->hid->head + nb);
            a[n++] = nb;
            if (n > DD_STAR_LOCAL) return dd_star_cells(t, v, out);
        }
    }
    out->n = n;
    return DD_OK;
}

int dd_move_by_flips(dd_tri *t, uint32_t v, const double p[3], int *flips, dd_status *err)
{
    *flips = 0;
    *err = move_star(t, v, &t->conflict, DD_STAR_LINK);
    if (*err != DD_OK) return 0;
    dd_vec *sc = t->flip;
    for (int k = 0; k < 5; k++) sc[k].n = 0;
    if ((*err = dd_vec_room(&sc[3], 4 * t->conflict.n)) != DD_OK) return 0;
    flip_state f;                            /* the sets: emptied at the first flip */
    start_repair(&f, t, 0);
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

/* A link facet's power test put off until the apex's point has arrived:
 * star cell c's cofactors K and its frame's m and W, the facet j, the
 * apex across it.                                                      */
typedef struct link_test {
    double K[4], m, W;
    uint32_t c, j, apex;
} link_test;

/* Pushes facet j of c unless the lifted filter certifies apex (finite)
 * not in power conflict with c: K . L[apex] beyond dd_lift_power_err. */
static void test_facet_power(flip_state *f, const double K[4], double m, double W, uint32_t c, uint32_t j,
                             uint32_t apex, const double *p, double wv)
{
    dd_tri *t = f->t;
    double L[4];
    const double dw = t->wt[apex] - wv;
    const double Wa = dd_lift_max(W, fabs(dw));
    const double ma = dd_lift_max(m, dd_lift_row_power(L, dd_pt(t, apex), p, dw));
    if (dd_lift_dot4(K, L) > dd_lift_power_err(ma, Wa)) {
#ifdef DD_TEST_BUILD
        if (dd_cell_power_conflict_fast(t, c, dd_pt(t, apex), t->wt[apex])) __builtin_trap();
#endif
        return;
    }
    f->stack->a[f->stack->n++] = 4 * c + j;
}

/* The weighted counterpart of star_test, v now at (p, w): every finite
 * star cell positively oriented (unchanged when only the weight changed:
 * how != DD_MOVE_POINT, no test) and each facet of the star locally
 * regular.  In the frame lifted at (p, w), a vertex x's row is (x - p,
 * |x - p|^2 - (w_x - w)) (lift.h's weighted lift), v's is 0, and a
 * cell's power test against an apex o is K . L[o] as in star_test,
 * certified beyond dd_lift_power_err of the frame's m and W = max |w_x -
 * w| (the cell's three rows and the apex's).  Pushes the facets the
 * filter cannot certify, or that fail, on f->stack (room made by the
 * caller) for Lawson's exact power tests; hull cells go there whole.
 *
 * A lighter v (DD_MOVE_LIGHTER) leaves every link facet of a finite star
 * cell locally regular, untested: with barycentric coordinates l wrt the
 * cell, the lifted plane of the cell at a point x moves by l_v(x) times
 * the rise of v's lift (w_old - w > 0), and the apex o across the link
 * facet has l_v(o) < 0 (the cell across is not flat), so o, which was
 * not below that plane, is strictly above it now.
 *
 * The link facets' tests come last: the apex's point is prefetched when
 * its cell is tested, and read once the rest of the star is done.
 * DD_NONE when every finite star cell is positively oriented, else the
 * first that is not (the stack then holds only part of the facets).    */
static uint32_t star_test_power(flip_state *f, uint32_t v, const double *p, double wv, int how)
{
    dd_tri *t = f->t;
    const dd_vec *star = &t->conflict;
    dd_vec *stack = f->stack;
    link_test lt[DD_STAR_LOCAL + 4];
    size_t nl = 0;
    const int defer = star->n <= DD_STAR_LOCAL + 4, links = how != DD_MOVE_LIGHTER;
    f->hull = 0;
    for (size_t k = 0; k < star->n; k++) {
        const uint32_t c = star->a[k], *w = dd_tv(t, c), *nb = dd_tn(t, c);
        const uint32_t i = dd_slot_of(w, v);
        if (has(w, DD_INF)) {
            for (uint32_t j = 0; j < 4; j++)
                if (j == i || c < nb[j] >> 2) stack->a[stack->n++] = 4 * c + j;
            f->hull = 1;
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
        if (how != DD_MOVE_POINT) {
#ifdef DD_TEST_BUILD
            if (orient4(t, w) <= 0) __builtin_trap();   /* a weight alone turns no cell */
#endif
        } else if (dd_lift_orient(mi, R[2]) > dd_lift_orient_err(m)) {
#ifdef DD_TEST_BUILD
            if (orient4(t, w) <= 0) __builtin_trap();   /* the filter is never wrong */
#endif
        } else if (orient4(t, w) <= 0) {
            return c;
        }
        dd_lift_cofactors(K, R[2], mi);
        for (uint32_t j = 0; j < 4; j++) {
            if (j == i && !links) {
#ifdef DD_TEST_BUILD
                if (facet_bad(f, c, j)) __builtin_trap();   /* the argument above */
#endif
                continue;
            }
            if (j != i && c > nb[j] >> 2) continue;
            const uint32_t apex = dd_tv(t, nb[j] >> 2)[nb[j] & 3];
            if (apex == DD_INF) {
                stack->a[stack->n++] = 4 * c + j;
            } else if (j == i && defer) {
                __builtin_prefetch(t->xyz + 3 * (size_t)apex);
                __builtin_prefetch(t->wt + apex);
                link_test *l = &lt[nl++];
                memcpy(l->K, K, sizeof K);
                l->m = m, l->W = W, l->c = c, l->j = j, l->apex = apex;
            } else {
                test_facet_power(f, K, m, W, c, j, apex, p, wv);
            }
        }
    }
    for (size_t k = 0; k < nl; k++) test_facet_power(f, lt[k].K, lt[k].m, lt[k].W, lt[k].c, lt[k].j, lt[k].apex, p, wv);
    return DD_NONE;
}

/* Writes (p, w) as v's point and weight. */
static void put_point(dd_tri *t, uint32_t v, const double p[3], double w)
{
    double *x = t->xyz + 3 * (size_t)v;
    x[0] = p[0], x[1] = p[1], x[2] = p[2];
    t->wt[v] = w;
}

/* Turned star cells a move removes by unturn before it gives up: a
 * small move turns one or two; more seldom end in a repair.           */
#define DD_UNTURN_MAX 2

/* Star cell c (finite) of v, now at p, is not positively oriented:
 * flipped away with the cell across its link facet F (apex o), keeping
 * a triangulation of the same vertices.  When o is no vertex of v's
 * star t->conflict, by a 2-3 flip: c and that cell become the three
 * cells (o, v, an edge of F) (edge vo is new, so are their faces).
 * When o is one, by a 3-2 flip around an edge pq of F whose only other
 * cell is (v, o, p, q): the three become (r, v, o, p) and (r, v, o, q),
 * r the third vertex of F, provided no star cell has the face rvo
 * already.  Either way the union's boundary stays, each new cell is c
 * or that cell with one vertex traded (its orientation so taken) and
 * must be positively oriented with v at p, and the facets to test are
 * all facets of v's new star: the caller collects it and runs the star
 * test again.  The flip is logged as Lawson's are (undone with them).
 * 1 when done; 0 with nothing changed when o is infinite, neither flip
 * applies, or a new cell is not positively oriented (or out of
 * memory: *err).                                                     */
static int unturn(flip_state *f, uint32_t v, uint32_t c, dd_status *err)
{
    dd_tri *t = f->t;
    const uint32_t *cv = dd_tv(t, c);
    const uint32_t i = dd_slot_of(cv, v), g = dd_tn(t, c)[i], n = g >> 2, o = dd_tv(t, n)[g & 3];
    if (o == DD_INF || f->flips >= DD_FLIP_MAX) return 0;
    const dd_vec *star = &t->conflict;
    int linked = 0;
    for (size_t k = 0; k < star->n && !linked; k++) linked = has(dd_tv(t, star->a[k]), o);
    const uint32_t tri[3] = {cv[dd_facet[i][0]], cv[dd_facet[i][1]], cv[dd_facet[i][2]]};
    const uint32_t loc[5] = {tri[0], tri[1], tri[2], o, v};
    uint32_t nv[3][4];
    if (!linked) {
        if (cells_2_3(t, tri, o, v, nv) != -1) return 0;    /* flip's 2-3, v the apex of c */
        const uint32_t old[2] = {c, n};
        *err = replace(f, loc, old, 2, (const uint32_t(*)[4])nv, 3);
        return *err == DD_OK;
    }
    for (int e = 0; e < 3; e++) {
        const uint32_t p = tri[e], q = tri[(e + 1) % 3], r = tri[(e + 2) % 3];
        const uint32_t m = dd_tn(t, c)[(uint32_t)dd_index_of(t, c, r)] >> 2;
        if (!has(dd_tv(t, m), o) || is_gone(f, m)) continue;
        int face = 0;                       /* rvo a face already: the flip would repeat it */
        for (size_t k = 0; k < star->n && !face; k++) face = has(dd_tv(t, star->a[k]), o) && has(dd_tv(t, star->a[k]), r);
        if (face) return 0;
        for (int a = 0; a < 4; a++) {
            nv[0][a] = cv[a] == q ? o : cv[a];
            nv[1][a] = cv[a] == p ? o : cv[a];
        }
        if (orient4(t, nv[0]) <= 0 || orient4(t, nv[1]) <= 0) return 0;
        const uint32_t old[3] = {c, n, m};
        *err = replace(f, loc, old, 3, (const uint32_t(*)[4])nv, 2);
        return *err == DD_OK;
    }
    return 0;
}

/* Room for a repair of DD_FLIP_MAX flips: cells, and the hidden
 * points' lists of the cells from ncell0 on.                          */
static dd_status reserve_repair(dd_tri *t, uint32_t ncell0)
{
    dd_status s = dd_reserve_cells(t, 3 * DD_FLIP_MAX);
    if (s == DD_OK && t->hid && t->hid->keep) s = dd_hidden_room(t, (size_t)ncell0 + 3 * DD_FLIP_MAX);
    return s;
}

int dd_move_power_by_flips(dd_tri *t, uint32_t v, const double p[3], double w, int *flips, int *inside,
                           dd_status *err)
{
    *flips = 0;
    *inside = 0;
    const double *x = dd_pt(t, v);
    const double old[3] = {x[0], x[1], x[2]}, wold = t->wt[v];
    const int how = old[0] != p[0] || old[1] != p[1] || old[2] != p[2] ? DD_MOVE_POINT
                    : w < wold                                         ? DD_MOVE_LIGHTER
                                                                       : DD_MOVE_HEAVIER;
    const int keep = t->hid && t->hid->keep;
    if (keep && v < t->hid->vcap) __builtin_prefetch(t->hid->nin + v);   /* read after the star */
    *err = move_star(t, v, &t->conflict,
                     (how == DD_MOVE_LIGHTER ? DD_STAR_POINTS : DD_STAR_POINTS | DD_STAR_LINK) | (keep ? DD_STAR_LISTS : 0));
    if (*err != DD_OK || dd_hidden_star_copies(t, v, t->conflict.a, t->conflict.n)) return 0;
    dd_vec *sc = t->flip;
    for (int k = 0; k < 5; k++) sc[k].n = 0;
    if ((*err = dd_vec_room(&sc[3], 4 * t->conflict.n)) != DD_OK) return 0;
    flip_state f;                            /* the sets: emptied at the first flip */
    start_repair(&f, t, 1);
    put_point(t, v, p, w);
    const uint32_t ncell0 = t->ncell, vcell0 = t->vcell[v];
    int ok = 1, room = 0;
    for (int k = 0; ok; k++) {               /* turned cells flipped away, the star tested again */
        const uint32_t turned = star_test_power(&f, v, p, w, how);
        if (turned == DD_NONE) break;
        ok = k < DD_UNTURN_MAX && how == DD_MOVE_POINT && t->conflict.n <= DD_STAR_LOCAL;
        if (ok && !room) {
            *err = reserve_repair(t, ncell0);
            ok = *err == DD_OK, room = 1;
        }
        ok = ok && unturn(&f, v, turned, err);
        if (ok) {
            t->vcell[v] = f.made->a[f.made->n - 1];
            f.stack->n = 0;
            *err = move_star(t, v, &t->conflict, DD_STAR_POINTS | DD_STAR_LINK | (keep ? DD_STAR_LISTS : 0));
            if (*err == DD_OK) *err = dd_vec_room(f.stack, 4 * t->conflict.n);
            ok = *err == DD_OK && t->conflict.n <= DD_STAR_LOCAL;
        }
    }
    if (ok && !room) {
        *err = reserve_repair(t, ncell0);
        ok = *err == DD_OK;
    }
    if (ok) *inside = how != DD_MOVE_POINT || !f.hull;
    ok = ok && lawson(&f, err);
    dd_vec *homes = f.stack;                 /* empty once Lawson's loop succeeded */
    if (ok && t->hid && t->hid->keep)
        ok = dd_hidden_flips_hold(t, v, f.made, f.gone, f.flips ? f.gone_set : NULL, how, homes, err);
    if (!ok) {
        undo(&f, ncell0);
        t->vcell[v] = vcell0;
        put_point(t, v, old, wold);
        return 0;
    }
    commit(&f);
    if (t->hid && t->hid->keep) dd_hidden_flips_rehome(t, f.gone, homes);
    *flips = f.flips;
    return 1;
}
