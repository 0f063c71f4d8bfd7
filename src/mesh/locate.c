/*
 * locate.c -- point location for queries and for the insertion of
 * arbitrary points: where the exact walk starts (a grid of vertices), the
 * star of a vertex, the exact nearest vertex, and the scratch of the
 * read-only calls (dd_reader: mesh.h).
 *
 * The grid.  A walk from the last insertion's cell (t->hint) crosses
 * O(n^(1/3)) cells to reach a random point; a start near the point makes
 * it a few.  The grid divides the bounding box of the vertices, as it was
 * when the grid was made, into about nvert / DD_GRID_LOAD boxes and keeps
 * for each box one vertex id that fell in it (the last inserted there),
 * or DD_NONE.  It only chooses where the walk starts: a stale entry (a
 * vertex deleted since) or an empty box costs a longer walk, never a
 * wrong answer, since the walk itself is exact.  Made by dd_create (O(n),
 * beside construction's O(n log n)) and kept by the edits, remade when
 * the vertex count has doubled or halved since: the edits have the
 * triangulation to themselves, while queries run at once on it and only
 * read the grid (dtdel.h, threads).
 *
 * Why a grid and not a Delaunay hierarchy (CGAL's Fast_location): the
 * hierarchy keeps a triangulation per level and must delete from each of
 * them; the grid costs 4 bytes a box and nothing on deletion, and the
 * bench's insertion row (`dtdel bench --dataset insert`) measures the
 * difference that matters, the walk's length.
 *
 * Invariant: every non-DD_NONE entry of t->grid.box is a vertex id below
 * t->nvid (possibly not a vertex any more).
 */
#include "mesh/mesh.h"
#include "dtdel/alloc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Vertices per box: the walk from a box's vertex crosses a few cells,
 * and the grid stays at 1 byte a vertex.                                */
#define DD_GRID_LOAD 4

void dd_grid_free(dd_grid *g)
{
    dd_mfree(g->box);
    *g = (dd_grid){0};
}

/* The box of point p (clamped to the grid: points outside the box of the
 * vertices go to its border).  Any finite p: an overflow makes f
 * infinite (the far border) or NaN (the near one), never an index out
 * of the grid.                                                          */
static uint32_t grid_box(const dd_grid *g, const double *p)
{
    uint32_t ix[3];
    for (int c = 0; c < 3; c++) {
        double f = (p[c] * g->pre[c] - g->lo[c]) * g->inv[c];
        ix[c] = !(f > 0) ? 0 : f >= (double)(g->dim[c] - 1) ? g->dim[c] - 1 : (uint32_t)f;
    }
    return (ix[2] * g->dim[1] + ix[1]) * g->dim[0] + ix[0];
}

/* Makes the grid for the vertices now in t, O(nvid).                   */
static dd_status grid_make(dd_tri *t)
{
    dd_grid *g = &t->grid;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t v = 0; v < t->nvid; v++) {
        if (t->vcell[v] == DD_NONE) continue;
        for (int c = 0; c < 3; c++) {
            const double x = dd_pt(t, v)[c];
            lo[c] = x < lo[c] ? x : lo[c];
            hi[c] = x > hi[c] ? x : hi[c];
        }
    }
    /* Boxes of side h, about nvert / DD_GRID_LOAD of them; an extent of 0
     * (all points in a plane) gets one box.  Any finite coordinates: each
     * axis is first scaled by pre, a power of two (1/2, or 2^599 for
     * extents below 2^-960), so that its extent neither overflows
     * (coordinates of both signs near DBL_MAX) nor has a reciprocal that
     * does (subnormal extents); h is found from logarithms, which cannot
     * overflow or underflow as the product of the extents can.           */
    double ext[3], lvol = 0;
    int used = 0;
    for (int c = 0; c < 3; c++) {
        const double half = 0.5 * hi[c] - 0.5 * lo[c];   /* then |hi|, |lo| < 2^-906 */
        g->pre[c] = half > 0 && half < 0x1p-960 ? 0x1p599 : 0.5;
        ext[c] = hi[c] * g->pre[c] - lo[c] * g->pre[c];
        if (ext[c] > 0) lvol += log2(ext[c]), used++;
    }
    const double boxes = (double)t->nvert / DD_GRID_LOAD + 1;
    const double lh = used ? (lvol - log2(boxes)) / used : 0;      /* log2 h */
    size_t total = 1;
    for (int c = 0; c < 3; c++) {
        double d = ext[c] > 0 ? ceil(exp2(log2(ext[c]) - lh)) : 1;
        d = !(d >= 1) ? 1 : d > 1024 ? 1024 : d;
        g->dim[c] = (uint32_t)d;
        g->lo[c] = lo[c] * g->pre[c];
        g->inv[c] = ext[c] > 0 ? d / ext[c] : 0;
        total *= g->dim[c];
    }
    if (total > g->cap) {
        uint32_t *b = dd_realloc(g->box, total * sizeof *b);
        if (!b) {                     /* dims no longer fit the boxes: none */
            dd_grid_free(g);
            return DD_ERR_NOMEM;
        }
        g->box = b;
        g->cap = total;
    }
    for (size_t k = 0; k < total; k++) g->box[k] = DD_NONE;
    g->nbox = total;
    for (uint32_t v = 0; v < t->nvid; v++)
        if (t->vcell[v] != DD_NONE) g->box[grid_box(g, dd_pt(t, v))] = v;
    g->made_for = t->nvert;
    return DD_OK;
}

dd_status dd_grid_ready(dd_tri *t)
{
    const dd_grid *g = &t->grid;
    if (g->box && t->nvert <= 2 * g->made_for && 2 * t->nvert >= g->made_for) return DD_OK;
    return grid_make(t);
}

void dd_grid_note(dd_tri *t, uint32_t v)
{
    if (t->grid.box) t->grid.box[grid_box(&t->grid, dd_pt(t, v))] = v;
}

/* A vertex of p's box or of one next to it (in the 3 x 3 x 3 block), or
 * DD_NONE.                                                              */
static uint32_t grid_vertex(const dd_tri *t, const double *p)
{
    const dd_grid *g = &t->grid;
    const uint32_t b = grid_box(g, p);
    uint32_t v = g->box[b];
    if (v != DD_NONE && t->vcell[v] != DD_NONE) return v;
    const uint32_t x = b % g->dim[0], y = b / g->dim[0] % g->dim[1], z = b / g->dim[0] / g->dim[1];
    for (int dz = -1; dz <= 1; dz++)
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                const int64_t X = (int64_t)x + dx, Y = (int64_t)y + dy, Z = (int64_t)z + dz;
                if (X < 0 || Y < 0 || Z < 0 || X >= (int64_t)g->dim[0] || Y >= (int64_t)g->dim[1] || Z >= (int64_t)g->dim[2])
                    continue;
                v = g->box[(size_t)((Z * g->dim[1] + Y) * g->dim[0] + X)];
                if (v != DD_NONE && t->vcell[v] != DD_NONE) return v;
            }
    return DD_NONE;
}

uint32_t dd_start_near(const dd_tri *t, const double *p)
{
    uint32_t v = t->grid.box ? grid_vertex(t, p) : DD_NONE;
    if (v != DD_NONE) return t->vcell[v];
    uint32_t c = t->hint;
    return c == DD_NONE || dd_tv(t, c)[0] == DD_DEAD ? t->inf_cell : c;
}

/* ---- the star of a vertex --------------------------------------------- */

dd_status dd_star_cells(dd_tri *t, uint32_t v, dd_vec *out)
{
    const dd_mark ep = dd_new_epoch(t, 1);
    out->n = 0;
    const uint32_t c0 = t->vcell[v];
    t->stamp[c0] = ep;
    dd_status s = dd_vec_push(out, c0);
    for (size_t k = 0; k < out->n && s == DD_OK; k++) {
        const uint32_t c = out->a[k];
        for (uint32_t j = 0; j < 4 && s == DD_OK; j++) {
            if (dd_tv(t, c)[j] == v) continue;     /* the facet opposite v */
            const uint32_t nb = dd_tn(t, c)[j] >> 2;
            if (t->stamp[nb] == ep) continue;
            t->stamp[nb] = ep;
            s = dd_vec_push(out, nb);
        }
    }
    return s;
}

/* ---- the scratch of a read-only call ---------------------------------------- */

void dd_reader_init(dd_reader *r)
{
    dd_pred_init(&r->pred);
    r->rng = 0x9E3779B97F4A7C15ull;
    r->steps = 0;
    r->set = r->inl;
    r->set_cap = DD_READER_INLINE;
    r->set_mask = 0;
    r->set_n = 0;
    r->star = (dd_vec){NULL, 0, 0};
}

void dd_reader_done(dd_reader *r)
{
    dd_pred_clear(&r->pred);
    if (r->set != r->inl) dd_mfree(r->set);
    r->set = r->inl;
    dd_vec_free(&r->star);
}

static inline uint32_t set_slot(uint32_t x, uint32_t mask)
{
    return (uint32_t)((x * 0x9E3779B97F4A7C15ull) >> 40) & mask;
}

/* Sizes r's set to `size` slots (a power of two, at most 2^31), all
 * empty, in the inline array or a malloc'd one.                        */
static dd_status set_make(dd_reader *r, uint32_t size)
{
    if (size > r->set_cap) {
        uint32_t *s = dd_malloc((size_t)size * sizeof *s);
        if (!s) return DD_ERR_NOMEM;
        if (r->set != r->inl) dd_mfree(r->set);
        r->set = s;
        r->set_cap = size;
    }
    memset(r->set, 0xFF, (size_t)size * sizeof *r->set);      /* DD_NONE */
    r->set_mask = size - 1;
    r->set_n = 0;
    return DD_OK;
}

dd_status dd_reader_set_reset(dd_reader *r, size_t expect)
{
    uint32_t size = 128;
    while (size < 2 * expect && size < (1u << 31)) size *= 2;
    return set_make(r, size);
}

static int set_add(dd_reader *r, uint32_t x);

/* set_add's slow path: the set is half full, so it doubles first.       */
static __attribute__((noinline)) int set_grow_add(dd_reader *r, uint32_t x)
{
    const uint32_t n = r->set_n, size = r->set_mask + 1;
    if (size >= (1u << 31)) return -1;
    uint32_t small[DD_READER_INLINE / 2];         /* the ids, while it grows */
    uint32_t *keep = n <= DD_READER_INLINE / 2 ? small : dd_malloc((size_t)n * sizeof *keep);
    if (!keep) return -1;
    uint32_t m = 0;
    for (uint32_t k = 0; k < size; k++)
        if (r->set[k] != DD_NONE) keep[m++] = r->set[k];
    dd_status s = set_make(r, 2 * size);
    if (s == DD_OK)
        for (uint32_t k = 0; k < m; k++) (void)set_add(r, keep[k]);
    if (keep != small) dd_mfree(keep);
    if (s != DD_OK) return -1;      /* the set is empty now: a failed call */
    return set_add(r, x);
}

/* dd_reader_set_add, inlined into the star's search: its hot loop.  The
 * table's pointer and mask are read once, as the stores into the table
 * could otherwise alias them.                                          */
static inline int set_add(dd_reader *r, uint32_t x)
{
    uint32_t *const set = r->set;
    const uint32_t mask = r->set_mask;
    uint32_t i = set_slot(x, mask);
    for (uint32_t y; (y = set[i]) != DD_NONE; i = (i + 1) & mask)
        if (y == x) return 0;
    if (2 * (r->set_n + 1) > mask + 1) return set_grow_add(r, x);
    set[i] = x;
    r->set_n++;
    return 1;
}

int dd_reader_set_add(dd_reader *r, uint32_t x) { return set_add(r, x); }

/* As dd_star_cells, with the marks in r's set. */
dd_status dd_star_read(const dd_tri *t, dd_reader *r, uint32_t v, dd_vec *out)
{
    out->n = 0;
    const uint32_t c0 = t->vcell[v];
    dd_status s = dd_reader_set_reset(r, 64);
    if (s == DD_OK) s = dd_vec_push(out, c0);
    if (s == DD_OK) (void)set_add(r, c0);
    for (size_t k = 0; k < out->n && s == DD_OK; k++) {
        const uint32_t c = out->a[k];
        for (uint32_t j = 0; j < 4 && s == DD_OK; j++) {
            if (dd_tv(t, c)[j] == v) continue;     /* the facet opposite v */
            const uint32_t nb = dd_tn(t, c)[j] >> 2;
            const int added = set_add(r, nb);
            if (added < 0) s = DD_ERR_NOMEM;
            else if (added) s = dd_vec_push(out, nb);
        }
    }
    return s;
}

/* ---- nearest vertex ------------------------------------------------------ */

/* Greedy descent over the Delaunay edges: a vertex that is not nearest to
 * p has a neighbour nearer to p (the segment from it to p leaves its
 * Voronoi cell through a facet of positive area, which is a Delaunay edge
 * of every triangulation of the perturbed set), so the walk ends at a
 * nearest vertex; each step is strictly nearer, so it ends.  Distances
 * are compared exactly (dd_compare_distance).                           */
dd_status dd_nearest_from(const dd_tri *t, dd_reader *r, const double *p, uint32_t c, uint32_t *nearest)
{
    uint32_t best = DD_NONE;
    for (int i = 0; i < 4; i++) {
        const uint32_t w = dd_tv(t, c)[i];
        if (w >= DD_QD) continue;
        if (best == DD_NONE || dd_compare_distance(&r->pred, p, dd_pt(t, best), dd_pt(t, w)) > 0) best = w;
    }
    dd_vec *star = &r->star;
    for (int moved = 1; moved;) {
        moved = 0;
        dd_status s = dd_star_read(t, r, best, star);
        if (s != DD_OK) return s;
        for (size_t k = 0; k < star->n && !moved; k++)
            for (int i = 0; i < 4; i++) {
                const uint32_t w = dd_tv(t, star->a[k])[i];
                if (w >= DD_QD || w == best) continue;
                if (dd_compare_distance(&r->pred, p, dd_pt(t, best), dd_pt(t, w)) > 0) {
                    best = w;
                    moved = 1;
                    break;
                }
            }
    }
    *nearest = best;
    return DD_OK;
}
