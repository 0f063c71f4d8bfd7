/*
 * mesh.c -- cell storage, point location and Bowyer-Watson insertion
 * (DESIGN 4 and 5).
 *
 * Owns: the growth helpers (dd_grow, dd_vec), the vertex-triple hash,
 * growth of the cell arrays, the free list of dead cells, the visibility
 * walk, the conflict search and the star re-filling of the cavity.  Insertion is all-or-nothing: every allocation happens before
 * the first write to the mesh, so a failed insertion leaves it unchanged.
 */
#define _DEFAULT_SOURCE 1   /* madvise advice names (huge_pages) */
#include "mesh/mesh.h"
#include "mesh/hidden.h"
#include "dtdel/alloc.h"

#include <sys/mman.h>

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

dd_status dd_grow(void *pp, size_t n, size_t size)
{
    void *p;
    memcpy(&p, pp, sizeof p);           /* pp is a T **, not a void ** */
    if (n == 0) n = 1;
    if (n > SIZE_MAX / size) return DD_ERR_NOMEM;
    p = dd_realloc(p, n * size);
    if (!p) return DD_ERR_NOMEM;
    memcpy(pp, &p, sizeof p);
    return DD_OK;
}

dd_status dd_vec_reserve(dd_vec *v, size_t cap)
{
    if (cap <= v->cap) return DD_OK;
    if (dd_grow(&v->a, cap, sizeof *v->a) != DD_OK) return DD_ERR_NOMEM;
    v->cap = cap;
    return DD_OK;
}

void dd_vec_free(dd_vec *v)
{
    dd_mfree(v->a);
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

const char *dd_status_text(dd_status s)
{
    static const char *const names[DD_NUM_STATUS] = {
        "ok", "out of memory", "i/o error", "parse error", "NaN coordinate",
        "infinite coordinate", "too few points", "collinear points",
        "coplanar points", "unknown vertex", "unknown variant",
        "duplicate point", "dimension would drop", "internal error",
        "bad argument", "unsupported", "unknown cell", "unknown file format"};
    return (unsigned)s < DD_NUM_STATUS ? names[s] : "unknown status";
}

dd_status dd_end_call(dd_tri *t, dd_status s)
{
    if (s != DD_OK) snprintf(t->errmsg, sizeof t->errmsg, "%s", t->err[0] ? t->err : dd_status_text(s));
    return s;
}

dd_status dd_tri_alloc(dd_tri **out, uint32_t np)
{
    *out = NULL;
    dd_tri *t = dd_calloc(1, sizeof *t);
    if (!t) return DD_ERR_NOMEM;
    uint32_t cap = np < 16 ? 16 : np;
    t->xyz = dd_malloc(3 * (size_t)cap * sizeof *t->xyz);
    t->vcell = dd_malloc((size_t)cap * sizeof *t->vcell);
    t->v2in = dd_malloc((size_t)cap * sizeof *t->v2in);
    t->in2v = dd_malloc((size_t)cap * sizeof *t->in2v);
    dd_pred_init(&t->pred);
    if (!t->xyz || !t->vcell || !t->v2in || !t->in2v || dd_pred_reserve(&t->pred) != DD_OK) {
        dd_mfree(t->xyz); dd_mfree(t->vcell); dd_mfree(t->v2in); dd_mfree(t->in2v); dd_mfree(t);
        return DD_ERR_NOMEM;
    }
    t->cap_v = t->cap_in = cap;
    t->free_head = DD_NONE;
    t->inf_cell = DD_NONE;
    t->hint = DD_NONE;
    t->rng = 0x9E3779B97F4A7C15ull;
    t->nthreads = 1;
    *out = t;
    return DD_OK;
}

dd_status dd_tri_alloc_borrowed(dd_tri **out)
{
    dd_tri *t = dd_calloc(1, sizeof *t);
    if (!t) return DD_ERR_NOMEM;
    t->borrowed = 1;
    t->free_head = t->inf_cell = t->hint = DD_NONE;
    t->rng = 0x2545F4914F6CDD1Dull;
    t->nthreads = 1;
    dd_pred_init(&t->pred);
    if (dd_pred_reserve(&t->pred) != DD_OK) { dd_mfree(t); return DD_ERR_NOMEM; }
    *out = t;
    return DD_OK;
}

void dd_tri_destroy(dd_tri *t)
{
    if (!t) return;
    if (!t->borrowed) { dd_mfree(t->xyz); dd_mfree(t->vcell); dd_mfree(t->v2in); dd_mfree(t->in2v); dd_mfree(t->wt); }
    dd_hidden_free(t);
    dd_mfree(t->cell_block); dd_mfree(t->stamp);
    dd_vec_free(&t->stack); dd_vec_free(&t->conflict); dd_vec_free(&t->boundary);
    dd_mfree(t->ehash);
    dd_mfree(t->etab);
    dd_grid_free(&t->grid);
    dd_vec_free(&t->vfree);
    dd_made_free(&t->made);
    for (int k = 0; k < 5; k++) dd_vec_free(&t->flip[k]);
    dd_pred_clear(&t->pred);
    dd_mfree(t);
}

/* ---- the vertex-triple hash --------------------------------------------- */

static void trihash_insert(dd_tri_slot *s, uint32_t mask, uint32_t gen, const dd_tri_slot *e)
{
    for (uint32_t i = dd_tri_hash(e->a, e->b, e->c, mask);; i = (i + 1) & mask)
        if (s[i].gen != gen) {
            s[i] = *e;
            s[i].gen = gen;
            return;
        }
}

dd_status dd_gen_table_reset(void **tab, uint32_t *alloc, uint32_t *gen, uint32_t *mask, size_t min,
                             size_t elsize)
{
    size_t size = 64;
    while (size < min) size *= 2;
    if (size > *alloc) {
        void *s = dd_calloc(size, elsize);
        if (!s) return DD_ERR_NOMEM;
        dd_mfree(*tab);
        *tab = s;
        *alloc = (uint32_t)size;
        *gen = 0;
    }
    if (++*gen == 0) {                    /* wrapped: clear once */
        memset(*tab, 0, *alloc * elsize);
        *gen = 1;
    }
    *mask = (uint32_t)size - 1;
    return DD_OK;
}

dd_status dd_trihash_reset(dd_trihash *h, size_t expect)
{
    void *s = h->s;
    dd_status st = dd_gen_table_reset(&s, &h->alloc, &h->gen, &h->mask, 2 * expect, sizeof *h->s);
    h->s = s;
    h->n = 0;
    return st;
}

/* Doubles h (put does, when half full). */
static dd_status trihash_grow(dd_trihash *h)
{
    uint32_t size = 2 * (h->mask + 1);
    dd_tri_slot *s = dd_calloc(size, sizeof *s);
    if (!s) return DD_ERR_NOMEM;
    for (uint32_t i = 0; i <= h->mask; i++)
        if (h->s[i].gen == h->gen) trihash_insert(s, size - 1, 1, &h->s[i]);
    dd_mfree(h->s);
    h->s = s;
    h->alloc = size;
    h->mask = size - 1;
    h->gen = 1;
    return DD_OK;
}

dd_status dd_trihash_put(dd_trihash *h, uint32_t a, uint32_t b, uint32_t c, uint32_t val)
{
    if (2 * (h->n + 1) > h->mask + 1 && trihash_grow(h) != DD_OK) return DD_ERR_NOMEM;
    dd_sort3u(&a, &b, &c);
    dd_tri_slot e = {a, b, c, val, 0};
    trihash_insert(h->s, h->mask, h->gen, &e);
    h->n++;
    return DD_OK;
}

uint32_t dd_trihash_get(const dd_trihash *h, uint32_t a, uint32_t b, uint32_t c)
{
    dd_sort3u(&a, &b, &c);
    for (uint32_t i = dd_tri_hash(a, b, c, h->mask);; i = (i + 1) & h->mask) {
        const dd_tri_slot *e = &h->s[i];
        if (e->gen != h->gen) return DD_NONE;
        if (e->a == a && e->b == b && e->c == c) return e->val;
    }
}

void dd_trihash_free(dd_trihash *h)
{
    dd_mfree(h->s);
    memset(h, 0, sizeof *h);
}

/* ---- cell storage -------------------------------------------------------- */

/* Reallocates the cell arrays to cap cells; stamps of new cells are 0.
 * Growing fails with DD_ERR_NOMEM (the arrays already grown stay valid,
 * cap_c keeps the old capacity).  Shrinking never fails: an array whose
 * realloc is refused keeps its larger block, still room for cap cells.
 * The cell records start on a 64-byte boundary inside their block (two a
 * cache line, none straddling two): after a realloc that moved the block
 * to another offset, they are moved back into line.                     */
#define CELL_ALIGN 64

/* Asks the kernel for transparent huge pages under the 2 MiB-aligned part
 * of block b: the walks and conflict searches of random insertions and
 * queries jump across the cell array, where 4 KiB pages miss the TLB at
 * nearly every cell.  Advice only: ignored where unsupported.           */
static void huge_pages(void *b, size_t len)
{
#ifdef MADV_HUGEPAGE
    const uintptr_t page = (uintptr_t)2 << 20, lo = ((uintptr_t)b + page - 1) & ~(page - 1),
                    hi = ((uintptr_t)b + len) & ~(page - 1);
    if (hi > lo) (void)madvise((void *)lo, hi - lo, MADV_HUGEPAGE);
#else
    (void)b, (void)len;
#endif
}

static dd_status resize_cells(dd_tri *t, uint32_t cap)
{
    int grow = cap > t->cap_c;
    size_t rec = DD_CELL_WORDS * sizeof(uint32_t), keep = (size_t)(cap < t->cap_c ? cap : t->cap_c);
    size_t old_off = t->cell_block ? (size_t)((char *)t->cell - (char *)t->cell_block) : 0;
    char *b = dd_realloc(t->cell_block, (size_t)cap * rec + CELL_ALIGN);
    if (b) {
        size_t off = (size_t)(-(uintptr_t)b & (CELL_ALIGN - 1));
        if (off != old_off) memmove(b + off, b + old_off, keep * rec);
        t->cell_block = b;
        t->cell = (uint32_t *)(void *)(b + off);
        huge_pages(b, (size_t)cap * rec + CELL_ALIGN);
    } else if (grow) {
        return DD_ERR_NOMEM;
    }
    dd_mark *st = dd_realloc(t->stamp, (size_t)cap * sizeof *st);
    if (st) t->stamp = st; else if (grow) return DD_ERR_NOMEM;
    if (grow) memset(t->stamp + t->cap_c, 0, (size_t)(cap - t->cap_c) * sizeof *t->stamp);
    t->cap_c = cap;
    return DD_OK;
}

dd_status dd_reserve_cells(dd_tri *t, uint32_t k)
{
    /* Cells on the free list count as room. */
    if (t->nfree >= k) return DD_OK;
    uint64_t need = (uint64_t)t->ncell + (k - t->nfree);
    if (need <= t->cap_c) return DD_OK;
    if (need > (UINT32_MAX - 8) / 4) return DD_ERR_NOMEM;
    uint64_t cap = t->cap_c ? t->cap_c : need > 64 ? need : 64;   /* first: exact */
    while (cap < need) cap += cap / 2 + 1;
    if (cap > (UINT32_MAX - 8) / 4) cap = (UINT32_MAX - 8) / 4;
    return resize_cells(t, (uint32_t)cap);
}

/* Room kept past the cells in use: an edit makes its new cells before it
 * frees the old ones, so with no room the first edit after construction
 * would grow, and copy, the whole array.  A few stars' worth.           */
#define CELL_SLACK 4096u

void dd_shrink_cells(dd_tri *t)
{
    uint64_t cap = (uint64_t)t->ncell + CELL_SLACK;
    if (cap < t->cap_c) resize_cells(t, (uint32_t)cap);   /* cannot fail: see there */
}

uint32_t dd_new_cell(dd_tri *t)
{
    uint32_t c;
    if (t->free_head != DD_NONE) {
        c = t->free_head;
        t->free_head = dd_tn(t, c)[0];
        t->nfree--;
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
    dd_tv(t, c)[0] = DD_DEAD;
    dd_tn(t, c)[0] = t->free_head;
    t->free_head = c;
    t->nfree++;
    t->nlive--;
}

void dd_unmake_cells(dd_tri *t, const uint32_t *c, size_t n, uint32_t ncell0)
{
    for (size_t k = n; k-- > 0;) {
        if (c[k] >= ncell0) {                      /* c[k] == t->ncell - 1 */
            dd_tv(t, c[k])[0] = DD_DEAD;
            t->ncell--;
            t->nlive--;
        } else {
            dd_kill_cell(t, c[k]);
        }
    }
    t->tets_created -= n;
}

/* Five cells: the tetrahedron and one infinite cell on each of its facets. */
void dd_make_first_cells(dd_tri *t, uint32_t v[4])
{
    if (dd_orient3d(&t->pred, dd_pt(t, v[0]), dd_pt(t, v[1]), dd_pt(t, v[2]),
                    dd_pt(t, v[3])) < 0) {
        uint32_t s = v[0]; v[0] = v[1]; v[1] = s;
    }
    uint32_t c = dd_new_cell(t);
    for (int k = 0; k < 4; k++) dd_tv(t, c)[(uint32_t)k] = v[k];
    uint32_t inf[4];
    for (int i = 0; i < 4; i++) {
        /* The infinite cell across facet i: same vertices with v[i] replaced
         * by DD_INF and two others swapped, so it is oriented as required
         * (DD_INF on the far side of facet i from v[i]).                   */
        uint32_t d = inf[i] = dd_new_cell(t);
        uint32_t w[4] = {v[0], v[1], v[2], v[3]};
        w[i] = DD_INF;
        int a = dd_facet[i][0], b = dd_facet[i][1];
        uint32_t s = w[a]; w[a] = w[b]; w[b] = s;
        for (int k = 0; k < 4; k++) dd_tv(t, d)[(uint32_t)k] = w[k];
        dd_glue(t, 4 * c + (uint32_t)i, 4 * d + (uint32_t)i);
    }
    /* Infinite cells meet along the infinite facets: cell across facet i,
     * its facet opposite vertex x (x != INF) is shared with the infinite
     * cell across the facet opposite x.                                    */
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++) {
            uint32_t d = inf[i], x = dd_tv(t, d)[(uint32_t)k];
            if (x == DD_INF) continue;
            int xi = -1;
            for (int m = 0; m < 4; m++) if (v[m] == x) xi = m;
            uint32_t e = inf[xi];
            /* facet of e opposite v[i] */
            int j = dd_index_of(t, e, v[i]);
            dd_tn(t, d)[(uint32_t)k] = 4 * e + (uint32_t)j;
        }
    for (int k = 0; k < 4; k++) t->vcell[v[k]] = c;
    t->inf_cell = inf[0];
    t->hint = c;
    t->nfinite = 1;
    t->nvert = 4;
}

/* ---- predicates on cells ------------------------------------------------- */

int dd_points_conflict(dd_pred *pr, const double *q[4], int k, int kd, const double *p)
{
    if (kd >= 0) {               /* dummy cell: swap the first two others */
        int a = kd == 0 ? 1 : 0, b = kd <= 1 ? 2 : 1;
        const double *s = q[a]; q[a] = q[b]; q[b] = s;
        if (k == a) k = b; else if (k == b) k = a;
    }
    if (k < 0) return dd_insphere_perturbed(pr, q[0], q[1], q[2], q[3], p) > 0;
    return dd_inf_conflict(pr, q, k, p) > 0;
}

int dd_cell_conflict(dd_tri *t, uint32_t c, const double *p)
{
    return dd_cell_conflict_on(t, &t->pred, c, p);
}

int dd_cell_conflict_on(const dd_tri *t, dd_pred *pr, uint32_t c, const double *p)
{
    const uint32_t *v = dd_tv(t, c);
    const double *q[4];
    int k = -1, kd = -1;
    for (int i = 0; i < 4; i++) {
        if (v[i] == DD_INF) { k = i; q[i] = NULL; }
        else if (v[i] == DD_QD) { kd = i; q[i] = t->qd_point; }
        else q[i] = dd_pt(t, v[i]);
    }
    return dd_points_conflict(pr, q, k, kd, p);
}

int dd_cell_power_conflict_on(const dd_tri *t, dd_pred *pr, uint32_t c, const double *p, double wp)
{
    const uint32_t *v = dd_tv(t, c);
    const int k = dd_index_of(t, c, DD_INF);
    if (k < 0) {
        const double w[5] = {t->wt[v[0]], t->wt[v[1]], t->wt[v[2]], t->wt[v[3]], wp};
        return dd_power_perturbed(pr, dd_pt(t, v[0]), dd_pt(t, v[1]), dd_pt(t, v[2]), dd_pt(t, v[3]), p, w) > 0;
    }
    const uint32_t a = v[dd_facet[k][0]], b = v[dd_facet[k][1]], d = v[dd_facet[k][2]];
    const double w[4] = {t->wt[a], t->wt[b], t->wt[d], wp};
    return dd_power_infinite(pr, dd_pt(t, a), dd_pt(t, b), dd_pt(t, d), p, w) > 0;
}

/* orient3d of cell c with its vertex i replaced by p (c finite). */
static inline int orient_replaced(const dd_tri *t, dd_pred *pr, uint32_t c, int i, const double *p)
{
    const uint32_t *v = dd_tv(t, c);
    const double *q[4];
    for (int k = 0; k < 4; k++) q[k] = (k == i) ? p : dd_pt(t, v[k]);
    int f = dd_orient3d_filter(pr, q[0], q[1], q[2], q[3]);
    return f != DD_FILTER_UNSURE ? f : dd_orient3d_unfiltered(pr, q[0], q[1], q[2], q[3]);
}

/* ---- point location ------------------------------------------------------ */

/* The first leg of point location: a walk on plain floating-point
 * orientations (no error bound, as CGAL's structural filtering), which
 * only picks where the exact walk starts, so that nothing it decides
 * needs a proof.  It follows a segment from s to p: in a cell, orient3d
 * of a facet's corners with x, o_i(x), is affine along the segment, so
 * the segment leaves through the facet with p beyond it (o_i(p) < 0)
 * whose plane it crosses first, at tau_i = o_i(s) / (o_i(s) - o_i(p));
 * with p beyond one facet only, through that one.  s is made in the first
 * cell with p beyond two facets or more (mostly the start), next to its
 * vertex nearest p.  The walk stops in a cell with p beyond no facet,
 * in one where an orientation overflows (coordinates beyond about 1e100:
 * the exact walk takes over there), before an outer cell, or after
 * 2500 + cells/4 steps, in case rounding
 * makes it cycle (CGAL's bound, 2500, grows with the cells here: on the
 * large helices more points need the longer walks).
 *
 * Why a segment from a vertex: the start is the last insertion's star,
 * and on the curves the point inserted before p is on the Hilbert curve
 * next to it, usually its neighbour in the new DT; the cells that such
 * a new edge crosses are all in conflict with p.  The visibility walk
 * (the first facet with p beyond) crosses thousands of thin cells a
 * point on the large helices where this walk crosses tens
 * (`build/dtdel build-bench 64000 --dataset helix`); on uniform points
 * it costs a few percent more than the visibility walk.                 */
/* The segment's start s: in cell c, 1% of the way from its vertex
 * nearest p towards its centroid.  Any finite coordinates: a distance
 * that overflows (or is NaN) leaves the first vertex the nearest, and
 * the centroid is summed in quarters, which cannot overflow.            */
static void locate_segment_start(const dd_tri *t, uint32_t c, const double *p, double s[3])
{
    double d2min = HUGE_VAL;
    const double *near = dd_pt(t, dd_tv(t, c)[0]);
    s[0] = s[1] = s[2] = 0;
    for (int k = 0; k < 4; k++) {
        const double *x = dd_pt(t, dd_tv(t, c)[(uint32_t)k]);
        double dx = x[0] - p[0], dy = x[1] - p[1], dz = x[2] - p[2], d2 = dx * dx + dy * dy + dz * dz;
        if (d2 < d2min) { d2min = d2; near = x; }
        for (int j = 0; j < 3; j++) s[j] += 0.0025 * x[j];
    }
    for (int j = 0; j < 3; j++) s[j] += 0.99 * near[j];
}

/* The walk above from cell c: the cell it stops in; *exit the facet of
 * that cell towards the outer cell it stopped before, else DD_NONE; the
 * cells crossed added to *nsteps.                                       */
static uint32_t locate_inexact(const dd_tri *t, const double *p, uint32_t c, uint32_t *exit, uint64_t *nsteps)
{
    uint64_t crossed = 0;
    double s[3];
    int have_s = 0;                 /* made when first needed: p is often in c */
    uint32_t prev = DD_NONE;
    const uint32_t limit = 2500 + t->ncell / 4;
    *exit = DD_NONE;
    for (uint32_t steps = 0; steps < limit; steps++) {
        const uint32_t *v = dd_tv(t, c);
        const double *q[4] = {dd_pt(t, v[0]), dd_pt(t, v[1]), dd_pt(t, v[2]), dd_pt(t, v[3])};
        uint32_t nb[4], nbeyond = 0;
        int beyond[4];
        double op[4], sum = 0;
        for (int i = 0; i < 4; i++) {
            nb[i] = dd_tn(t, c)[(uint32_t)i] >> 2;
            if (nb[i] == prev) continue;
            const double *qi = q[i];
            q[i] = p;
            op[i] = dd_orient3d_det(q[0], q[1], q[2], q[3]);
            q[i] = qi;
            sum += op[i];
            if (op[i] < 0) beyond[nbeyond++] = i;
        }
        /* an orientation overflowed (sum - sum is NaN): the values say
         * nothing, the exact walk goes on from here                      */
        if (nbeyond == 0 || sum - sum != 0) break;
        /* p beyond one facet only: the segment leaves through it */
        int out = beyond[0];
        if (nbeyond > 1) {
            if (!have_s) locate_segment_start(t, c, p, s), have_s = 1;
            double tau_min = HUGE_VAL;
            for (uint32_t k = 0; k < nbeyond; k++) {
                int i = beyond[k];
                const double *qi = q[i];
                q[i] = s;
                double os = dd_orient3d_det(q[0], q[1], q[2], q[3]);
                q[i] = qi;
                double tau = os <= 0 ? 0 : os / (os - op[i]);
                if (tau < tau_min) { tau_min = tau; out = i; }
            }
        }
        if (dd_is_outer_cell(t, nb[out])) { *exit = (uint32_t)out; break; }
        prev = c;
        c = nb[out];
        crossed++;
    }
    *nsteps += crossed;
    return c;
}

/* Visibility walk from `start` to a cell in conflict with p: a finite cell
 * whose closure contains p, or an infinite cell whose hull facet p sees
 * strictly.  Each step crosses a facet whose plane strictly separates the
 * cell from p; the facet tried first is random (but in the first cell,
 * see below), so the walk cannot cycle.  pr, rng and nsteps are the
 * caller's: t's for an edit, a dd_reader's for a read.                  */
static dd_status walk_locate(const dd_tri *t, dd_pred *pr, uint64_t *rng, uint64_t *nsteps, const double *p,
                             uint32_t start, uint32_t *out)
{
    uint32_t c = start;
    uint32_t from = DD_NONE;            /* facet index we entered through */
    uint64_t steps = 0, limit = 16 + 4 * (uint64_t)t->ncell;
    if (dd_is_outer_cell(t, c)) {       /* start from its finite neighbour */
        int k = dd_index_of(t, c, DD_INF);
        if (k < 0) k = dd_index_of(t, c, DD_QD);
        uint32_t f = dd_tn(t, c)[(uint32_t)k];
        c = f >> 2;             /* nothing known about p yet: from stays */
    }
    /* The exact walk tries first the facet the plain one would have
     * crossed next: when that is a hull facet, another facet with p
     * beyond it could send the walk across the whole interior
     * (re-inserting a hull vertex of the helix; test_build).            */
    uint32_t exit = DD_NONE;
    c = locate_inexact(t, p, c, &exit, nsteps);
    for (;;) {
        if (++steps > limit) return DD_ERR_INTERNAL;
        if (dd_is_outer_cell(t, c)) { *out = c; break; }
        uint32_t r = exit != DD_NONE ? exit : dd_xorshift(rng) & 3, next = DD_NONE;
        exit = DD_NONE;
        for (uint32_t k = 0; k < 4; k++) {
            uint32_t i = (r + k) & 3;
            if (i == from) continue;
            if (orient_replaced(t, pr, c, (int)i, p) < 0) { next = dd_tn(t, c)[i]; break; }
        }
        if (next == DD_NONE) { *out = c; break; }
        c = next >> 2;
        from = next & 3;
    }
    *nsteps += steps;
    return DD_OK;
}

dd_status dd_walk_locate(dd_tri *t, const double *p, uint32_t start, uint32_t *out)
{
    dd_status s = walk_locate(t, &t->pred, &t->rng, &t->walk_steps, p, start, out);
    return s == DD_OK ? s : dd_fail(t, s, "point location did not terminate");
}

dd_status dd_walk_read(const dd_tri *t, dd_reader *r, const double *p, uint32_t start, uint32_t *out)
{
    return walk_locate(t, &r->pred, &r->rng, &r->steps, p, start, out);
}

/* ---- Bowyer-Watson insertion --------------------------------------------- */

/* Asks for the records and marks of c's neighbours ahead: the conflict
 * search tests them after it has tested c's siblings.  Construction only
 * (dd_build_insert), whose cells are out of cache (`build/dtdel
 * build-bench`); a re-insertion finds the cavity the deletion just left
 * in cache, and the prefetches would only add instructions (the bench's
 * insert row).  So the search is compiled twice, each copy a function of
 * its own (inlined into the insertion, its in-sphere filter compiles
 * worse).                                                               */
static inline void prefetch_neighbours(const dd_tri *t, uint32_t c)
{
    for (uint32_t j = 0; j < 4; j++) {
        uint32_t x = dd_tn(t, c)[j] >> 2;
        __builtin_prefetch(dd_tv(t, x));
        __builtin_prefetch(&t->stamp[x]);
    }
}

/* Marks the conflict region of p reachable from c0 (stamp == ep) and lists
 * its boundary facets (4c+i, c in conflict, its neighbour not).  Cells found
 * not in conflict get stamp ep+1 so they are tested once.                  */
__attribute__((always_inline)) static inline dd_status find_conflicts(dd_tri *t, const double *p, double wp,
                                                                   uint32_t c0, const int ahead, const int power)
{
    dd_mark ep = dd_new_epoch(t, 2), tested = (dd_mark)(ep + 1);
    t->stack.n = t->conflict.n = t->boundary.n = 0;
    t->stamp[c0] = ep;
    if (ahead) prefetch_neighbours(t, c0);
    dd_status s = dd_vec_push(&t->stack, c0);
    while (s == DD_OK && t->stack.n > 0) {
        uint32_t c = t->stack.a[--t->stack.n];
        s = dd_vec_push(&t->conflict, c);
        for (uint32_t i = 0; i < 4 && s == DD_OK; i++) {
            uint32_t nb = dd_tn(t, c)[i] >> 2;
            if (t->stamp[nb] == ep) continue;
            if (t->stamp[nb] != tested &&
                (power ? dd_cell_power_conflict_fast(t, nb, p, wp) : dd_cell_conflict_fast(t, nb, p))) {
                t->stamp[nb] = ep;
                if (ahead) prefetch_neighbours(t, nb);
                s = dd_vec_push(&t->stack, nb);
            } else {
                t->stamp[nb] = tested;
                s = dd_vec_push(&t->boundary, 4 * c + i);
            }
        }
    }
    return s;
}

dd_status dd_find_conflicts(dd_tri *t, const double *p, uint32_t c0)
{
    return find_conflicts(t, p, 0, c0, 0, 0);
}

static dd_status find_conflicts_ahead(dd_tri *t, const double *p, uint32_t c0)
{
    return find_conflicts(t, p, 0, c0, 1, 0);
}

/* The regular triangulation's two copies (the power test compiled in,
 * not chosen per cell).                                                  */
static dd_status find_power_conflicts(dd_tri *t, const double *p, double wp, uint32_t c0)
{
    return find_conflicts(t, p, wp, c0, 0, 1);
}

static dd_status find_power_conflicts_ahead(dd_tri *t, const double *p, double wp, uint32_t c0)
{
    return find_conflicts(t, p, wp, c0, 1, 1);
}

dd_status dd_find_conflicts_power(dd_tri *t, const double *p, double wp, uint32_t c0, int ahead)
{
    return ahead ? find_power_conflicts_ahead(t, p, wp, c0) : find_power_conflicts(t, p, wp, c0);
}

/* Makes sure the edge hash has at least 4 * nfacets slots (load <= 3/8
 * for the 3/2 * nfacets edges of a star) and starts a new generation.     */
dd_status dd_reserve_edge_hash(dd_tri *t, size_t nfacets)
{
    void *h = t->ehash;   /* the mask, not the capacity: small stars stay in cache */
    dd_status st = dd_gen_table_reset(&h, &t->ehash_cap, &t->ehash_gen, &t->ehash_mask, 4 * nfacets,
                                   sizeof *t->ehash);
    t->ehash = h;
    return st;
}

/* Glues the facets of the new cells that contain vertex v: such a facet
 * (cell n, opposite position j) holds v and an edge ab; the other facet
 * holding v and ab is its neighbour.  Matched through the edge hash.     */
void dd_glue_new_cells(dd_tri *t, const uint32_t *cells, size_t ncells, uint32_t v)
{
    uint32_t mask = t->ehash_mask, gen = t->ehash_gen;
    dd_edge_slot *hash = t->ehash;
    for (size_t k = 0; k < ncells; k++) {
        uint32_t n = cells[k];
        const uint32_t *w = dd_tv(t, n);
        uint32_t i = (uint32_t)dd_index_of(t, n, v);
        for (uint32_t j = 0; j < 4; j++) {
            if (j == i) continue;
            uint32_t a = w[dd_edge_of[i][j][0]], b = w[dd_edge_of[i][j][1]];
            uint64_t key = a < b ? ((uint64_t)a << 32 | b) : ((uint64_t)b << 32 | a);
            uint32_t h = (uint32_t)((key * 0x9E3779B97F4A7C15ull) >> 40) & mask;
            for (;; h = (h + 1) & mask) {
                dd_edge_slot *e = &hash[h];
                if (e->gen != gen) {
                    e->gen = gen; e->key = key; e->facet = 4 * n + j;
                    break;
                }
                if (e->key == key && e->facet != DD_NONE) {
                    dd_glue(t, 4 * n + j, e->facet);
                    e->facet = DD_NONE;          /* tombstone: edge done */
                    break;
                }
            }
        }
    }
}

/* Gluing a star through a table of oriented edges.  The facets through v
 * of the new cells form a closed surface around v; two new cells sharing
 * the facet (v, a, b) see it with opposite orientations, one as the cycle
 * (v, a, b), the other as (v, b, a).  So each facet writes itself under
 * its directed edge a->b and finds its partner under b->a: no search, no
 * branch.  The vertices of the cavity's boundary get local numbers in
 * vcell (tagged with STAR_TAG, a bit no cell id uses: dd_reserve_cells
 * keeps them below 2^30; vcell is rewritten for all of them when the
 * star is done), the table is indexed by pairs of local numbers.  Local 0
 * is DD_QD and 2 is DD_INF (w - DD_QD); larger cavities use the edge hash. */
#define STAR_TAG  0x80000000u

static inline uint32_t star_local(const uint32_t *vcell, uint32_t w)
{
    return w >= DD_QD ? w - DD_QD : vcell[w] & ~STAR_TAG;
}

/* Numbers the boundary vertices of the conflict region; returns how many
 * local numbers are in use, or 0 when more than DD_STAR_MAXV.            */
static uint32_t star_number_vertices(dd_tri *t)
{
    uint32_t nl = 3, *vc = t->vcell;
    for (size_t b = 0; b < t->boundary.n; b++) {
        uint32_t f = t->boundary.a[b], i = f & 3;
        const uint32_t *w = dd_tv(t, f >> 2);
        for (uint32_t k = 0; k < 4; k++) {
            if (k == i || w[k] >= DD_QD) continue;
            uint32_t x = vc[w[k]], fresh = !(x & STAR_TAG);
            vc[w[k]] = fresh ? STAR_TAG | nl : x;
            nl += fresh;
        }
    }
    return nl <= DD_STAR_MAXV ? nl : 0;
}

/* Replaces the marked conflict cells (stamp == ep) by the star of vertex v
 * over the boundary facets.  Room for the new cells and the edge hash must
 * be reserved: nothing here can fail.                                     */
void dd_fill_star(dd_tri *t, uint32_t v)
{
    uint32_t nl = star_number_vertices(t), *e = t->etab, *pending = t->stack.a;
    const uint32_t *vc = t->vcell;
    size_t nb = t->boundary.n;
    /* One new cell per boundary facet: the conflict cell's vertices with the
     * one opposite the facet replaced by v, glued to the outside cell.  Each
     * of its three facets through v writes itself into the edge table and
     * keeps the key of its partner (t->stack, 6 entries a cell).  The
     * boundary list then holds the new cells.                              */
    for (size_t k = 0; k < nb; k++) {
        uint32_t f = t->boundary.a[k], i = f & 3;
        uint32_t n = dd_new_cell(t), loc[4];
        const uint32_t *dst = dd_star_cell(t, f, n, v);
        t->boundary.a[k] = n;
        if (!nl) continue;
        for (uint32_t j = 0; j < 4; j++) loc[j] = j == i ? 0 : star_local(vc, dst[j]);
        dd_star_edges(e, nl, loc, i, n, pending + 6 * k);
    }
    if (!nl) dd_glue_new_cells(t, t->boundary.a, nb, v);
    /* The partners, then the vertex links (which also clears the local
     * numbers), then recycle the conflict cells.                           */
    for (size_t k = 0; k < nb; k++) {
        uint32_t n = t->boundary.a[k];
        if (nl)
            for (uint32_t r = 0, *p = pending + 6 * k; r < 3; r++, p += 2) *dd_fn(t, p[0]) = e[p[1]];
        int outer = 0;
        for (uint32_t j = 0; j < 4; j++) {
            uint32_t w = dd_tv(t, n)[j];
            if (w == DD_INF) { t->inf_cell = n; outer = 1; }
            else if (w == DD_QD) outer = 1;
            else t->vcell[w] = n;
        }
        if (!outer) t->nfinite++;
    }
    if (nb) t->hint = t->boundary.a[nb - 1];
    dd_note_made(t, t->boundary.a, nb);
    for (size_t k = 0; k < t->conflict.n; k++) {
        uint32_t c = t->conflict.a[k];
        if (!dd_is_outer_cell(t, c)) t->nfinite--;
        dd_kill_cell(t, c);
    }
}

dd_status dd_reserve_star(dd_tri *t)
{
    if (!t->etab && !(t->etab = dd_malloc(DD_STAR_MAXV * DD_STAR_MAXV * sizeof *t->etab)))
        return DD_ERR_NOMEM;
    dd_status s = dd_reserve_cells(t, (uint32_t)t->boundary.n);
    if (s == DD_OK) s = dd_reserve_edge_hash(t, t->boundary.n);
    if (s == DD_OK) s = dd_vec_reserve(&t->stack, 6 * t->boundary.n);
    return s;
}

void dd_clear_cells(dd_tri *t)
{
    t->ncell = t->nlive = t->nfinite = t->nfree = 0;
    t->free_head = DD_NONE;
    t->inf_cell = t->hint = DD_NONE;
}

/* dd_insert_vertex, dd_insert_vertex_at (from `start`) and dd_build_insert
 * (ahead = 1: the conflict search fetches cells ahead): locate, refuse a
 * duplicate, find the conflict region, reserve, fill the star.          */
/* Whether finite cell c's open circumsphere holds p, exactly: then p is
 * in conflict with c and no vertex (none is inside a Delaunay sphere).  */
static int strictly_in_sphere(dd_tri *t, uint32_t c, const double *p)
{
    if (dd_is_outer_cell(t, c)) return 0;
    const uint32_t *w = dd_tv(t, c);
    return dd_insphere(&t->pred, dd_pt(t, w[0]), dd_pt(t, w[1]), dd_pt(t, w[2]), dd_pt(t, w[3]), p) > 0;
}

static inline dd_status insert_vertex(dd_tri *t, uint32_t v, uint32_t start, const int ahead, uint32_t *dup,
                                      const int in_conflict)
{
    const double *p = dd_pt(t, v);
    if (start == DD_NONE || dd_tv(t, start)[0] == DD_DEAD) start = t->inf_cell;
    uint32_t c0 = DD_NONE;
    dd_status s = DD_OK;
    const int direct = in_conflict && strictly_in_sphere(t, start, p);   /* no walk, no duplicate */
    if (direct) c0 = start;
    else s = dd_walk_locate(t, p, start, &c0);
    if (s != DD_OK) return s;
    if (!direct && !dd_is_outer_cell(t, c0))            /* p in the closed cell c0 */
        for (uint32_t k = 0; k < 4; k++) {
            uint32_t w = dd_tv(t, c0)[k];
            if (dd_lex_cmp(dd_pt(t, w), p) != 0) continue;
            if (dup) {
                *dup = w;
                return DD_ERR_DUPLICATE;
            }
            return dd_fail(t, DD_ERR_DUPLICATE, "point %u equals vertex %u", t->v2in[v], t->v2in[w]);
        }
    s = ahead ? find_conflicts_ahead(t, p, c0) : dd_find_conflicts(t, p, c0);
    if (s == DD_OK) s = dd_reserve_star(t);
    if (s != DD_OK) return dd_fail(t, s, "out of memory inserting point %u", t->v2in[v]);
    dd_fill_star(t, v);
    t->nvert++;
    return DD_OK;
}

dd_status dd_insert_vertex(dd_tri *t, uint32_t v)
{
    return insert_vertex(t, v, t->hint, 0, NULL, 0);
}

dd_status dd_insert_vertex_at(dd_tri *t, uint32_t v, uint32_t start)
{
    return insert_vertex(t, v, start, 1, NULL, 0);
}

dd_status dd_insert_vertex_from(dd_tri *t, uint32_t v, uint32_t hint)
{
    return insert_vertex(t, v, hint, 1, NULL, 1);
}

dd_status dd_insert_vertex_dup(dd_tri *t, uint32_t v, uint32_t start, uint32_t *dup)
{
    return insert_vertex(t, v, start, 1, dup, 0);
}

dd_status dd_build_insert(dd_tri *t, uint32_t v)
{
    return insert_vertex(t, v, t->hint, 1, NULL, 0);
}

/* ---- vertex storage ------------------------------------------------------- */

dd_status dd_reserve_vertex(dd_tri *t)
{
    if (t->np >= UINT32_MAX - 8 || t->nvid >= UINT32_MAX - 8) return DD_ERR_NOMEM;
    if (t->nvid == t->cap_v) {
        size_t cap = (size_t)t->cap_v * 2;
        if (dd_grow(&t->xyz, 3 * cap, sizeof *t->xyz) || dd_grow(&t->vcell, cap, sizeof *t->vcell) ||
            dd_grow(&t->v2in, cap, sizeof *t->v2in) || (t->wt && dd_grow(&t->wt, cap, sizeof *t->wt)))
            return DD_ERR_NOMEM;
        t->cap_v = (uint32_t)cap;
    }
    if (t->np == t->cap_in) {
        if (dd_grow(&t->in2v, (size_t)t->cap_in * 2, sizeof *t->in2v)) return DD_ERR_NOMEM;
        t->cap_in *= 2;
    }
    return DD_OK;
}
