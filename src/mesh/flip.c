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
 * Cost: O(star) tests, plus O(1) a flip.
 */
#include "mesh/mesh.h"

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
    int flips;
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
    for (size_t k = 0; k < f->gone->n; k++)
        if (f->gone->a[k] == c) return 1;
    return 0;
}

static void sort3(uint32_t *a)
{
    dd_sort3u(&a[0], &a[1], &a[2]);
}

/* Replaces the k old cells old[] by the m new cells of vertices nv[4m]
 * (positively oriented): facets shared by two new cells are glued to each
 * other, the others to the outside facet of the old cell that has them.
 * Pushes every facet of the new cells for testing.                      */
static dd_status replace(flip_state *f, const uint32_t *old, int k, const uint32_t (*nv)[4], int m)
{
    dd_tri *t = f->t;
    uint32_t nc[3], key[4][3], okey[3][4][3];
    dd_status s = DD_OK;
    for (int a = 0; a < k; a++)
        for (uint32_t i = 0; i < 4; i++) {
            for (int j = 0; j < 3; j++) okey[a][i][j] = dd_tv(t, old[a])[dd_facet[i][j]];
            sort3(okey[a][i]);
            if ((s = touch(f, dd_tn(t, old[a])[i] >> 2)) != DD_OK) return s;   /* its back pointer is rewritten */
        }
    for (int b = 0; b < m; b++) {
        nc[b] = dd_new_cell(t);
        memcpy(dd_tv(t, nc[b]), nv[b], 4 * sizeof **nv);
        if ((s = dd_vec_push(f->made, nc[b])) != DD_OK) return s;
    }
    for (int b = 0; b < m; b++)
        for (uint32_t i = 0; i < 4; i++) {
            for (int j = 0; j < 3; j++) key[i][j] = nv[b][dd_facet[i][j]];
            sort3(key[i]);
            uint32_t g = DD_NONE;
            for (int b2 = 0; b2 < m && g == DD_NONE; b2++)        /* another new cell */
                for (uint32_t i2 = 0; i2 < 4 && b2 != b; i2++) {
                    uint32_t k2[3] = {nv[b2][dd_facet[i2][0]], nv[b2][dd_facet[i2][1]], nv[b2][dd_facet[i2][2]]};
                    sort3(k2);
                    if (!memcmp(k2, key[i], sizeof k2)) { g = 4 * nc[b2] + i2; break; }
                }
            for (int a = 0; a < k && g == DD_NONE; a++)           /* the outside */
                for (uint32_t i2 = 0; i2 < 4; i2++)
                    if (!memcmp(okey[a][i2], key[i], sizeof key[i])) { g = dd_tn(t, old[a])[i2]; break; }
            if (g == DD_NONE) return DD_ERR_INTERNAL;
            dd_glue(t, 4 * nc[b] + i, g);
            if ((s = dd_vec_push(f->stack, 4 * nc[b] + i)) != DD_OK) return s;
        }
    for (int a = 0; a < k && s == DD_OK; a++) s = dd_vec_push(f->gone, old[a]);
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
        *err = replace(f, old, 2, (const uint32_t(*)[4])nv, 3);
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
    *err = replace(f, old, 3, (const uint32_t(*)[4])two, 2);
    return 0;
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
            const uint32_t g = dd_tn(t, c)[i], n = g >> 2, o = dd_tv(t, n)[g & 3];
            const int bad = o != DD_INF ? dd_cell_conflict_fast(t, c, dd_pt(t, o))
                                        : dd_tv(t, c)[i] != DD_INF && dd_cell_conflict(t, n, dd_pt(t, dd_tv(t, c)[i]));
            if (!bad) continue;
            if (dd_is_infinite_cell(t, c) || dd_is_infinite_cell(t, n) || f->flips >= DD_FLIP_MAX) { ok = 0; break; }
            const int r = flip(f, c, i, err);
            if (*err != DD_OK || r < 0) ok = 0;
            else if (r > 0 && (*err = dd_vec_push(later, fc)) != DD_OK) ok = 0;
        }
        if (ok && f->stack->n == 0 && later->n > 0 && round == 3) ok = 0;
    }
    return ok && *err == DD_OK;
}

int dd_move_by_flips(dd_tri *t, uint32_t v, const double p[3], int *flips, dd_status *err)
{
    *flips = 0;
    *err = dd_star_cells(t, v, &t->conflict);
    if (*err != DD_OK) return 0;
    double *x = t->xyz + 3 * (size_t)v, old[3] = {x[0], x[1], x[2]};
    x[0] = p[0], x[1] = p[1], x[2] = p[2];
    for (size_t k = 0; k < t->conflict.n; k++) {   /* the star stays a triangulation */
        const uint32_t *w = dd_tv(t, t->conflict.a[k]);
        if (has(w, DD_INF)) continue;
        if (orient4(t, w) <= 0) {
            x[0] = old[0], x[1] = old[1], x[2] = old[2];
            return 0;
        }
    }
    dd_vec *sc = t->flip;
    for (int k = 0; k < 5; k++) sc[k].n = 0;
    flip_state f = {t, &sc[0], &sc[1], &sc[2], &sc[3], &sc[4], dd_new_epoch(t, 1), 0};
    const uint32_t ncell0 = t->ncell;
    *err = dd_reserve_cells(t, 3 * DD_FLIP_MAX);
    /* every facet of the star once: a facet through v (between two star
     * cells) from the cell of lesser id, a link facet from the star     */
    for (size_t k = 0; *err == DD_OK && k < t->conflict.n; k++) {
        const uint32_t c = t->conflict.a[k];
        for (uint32_t i = 0; i < 4 && *err == DD_OK; i++)
            if (dd_tv(t, c)[i] == v || c < dd_tn(t, c)[i] >> 2) *err = dd_vec_push(f.stack, 4 * c + i);
    }
    const int ok = *err == DD_OK && lawson(&f, err);
    if (!ok) {
        undo(&f, ncell0);
        x[0] = old[0], x[1] = old[1], x[2] = old[2];
    } else {
        /* vertex links; the count of finite cells (every flipped cell is
         * finite): + the new ones kept, - the old ones replaced          */
        for (size_t k = 0; k < f.made->n; k++) {
            const uint32_t c = f.made->a[k];
            if (is_gone(&f, c)) continue;
            for (int i = 0; i < 4; i++) t->vcell[dd_tv(t, c)[i]] = c;
            t->nfinite++;
        }
        for (size_t k = 0; k < f.gone->n; k++) {
            const uint32_t c = f.gone->a[k];
            int made = 0;
            for (size_t j = 0; j < f.made->n && !made; j++) made = f.made->a[j] == c;
            if (!made) t->nfinite--;
            dd_kill_cell(t, c);
        }
        if (f.made->n) t->hint = f.made->a[f.made->n - 1];
        *flips = f.flips;
    }
    return ok;
}
