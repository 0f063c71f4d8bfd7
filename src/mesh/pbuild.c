/*
 * pbuild.c -- parallel construction of a Delaunay triangulation (issue 59;
 * docs/architecture.md, "Parallel construction").
 *
 * Owns: the insertion of a range of vertex ids by several threads at once
 * into one cell array, each thread Bowyer-Watson inserting the points of
 * its own stretch of each BRIO round's Hilbert curve (Hxt's scheme:
 * Marot, Pellerin and Remacle, IJNME 2019).
 *
 * Regions.  During a round every vertex belongs to one thread: a vertex
 * of the round to the thread whose stretch holds it, a vertex of an
 * earlier round to the thread whose stretch takes the same share of that
 * round's curve (rounds are random samples sorted along one curve, so the
 * shares fall at nearly the same places).  A cell is a thread's when its
 * finite vertices all are.  A thread reads and writes only its own cells,
 * and the vertex slots of their neighbours (to learn whose they are).
 *
 * Why no cell is written by two threads, or read while another writes it:
 * an insertion replaces its conflict cells and rewrites the neighbour
 * entries of the cells across the cavity's boundary; it goes on only when
 * all of them are the thread's (else it changes nothing and puts the
 * point aside), and every cell it makes is the thread's (its vertices are
 * the new point and those of a boundary facet).  A cell X next to a cell
 * C of thread j can only change if its owner k has C in its cavity or on
 * its boundary, which needs C to be k's: so while j works in C, the cells
 * around C keep their vertices, and j's reads of them race with nothing.
 * No locks, no atomics but the high-water mark of the cell array.
 *
 * Cells.  Each thread recycles its own dead cells (no live cell points at
 * a dead one) and takes fresh ones in chunks from the shared high-water
 * mark (an atomic add).  When the capacity reserved runs out, the threads
 * put their remaining points aside.
 *
 * The result is the one-thread result: every insertion is the ordinary
 * Bowyer-Watson step of dd_build_insert, so after each one the cells are
 * the DT of the points inserted so far; the perturbed DT of a point set
 * is unique, so it does not depend on the order the threads happened to
 * insert in.  The points put aside are inserted on the caller's thread
 * once the others are done, by dd_build_insert.
 */
#include "mesh/mesh.h"
#include "dtdel/alloc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Fresh cells taken from the high-water mark at a time. */
#define CHUNK 1024u
/* Rounds smaller than this many points a thread go on one thread (test
 * builds: few, so that small inputs take the parallel path).           */
#ifdef DD_TEST_BUILD
#define MIN_SHARE 8u
#else
#define MIN_SHARE 4096u
#endif
/* The slots of a star's vertex table (more than DD_STAR_MAXV). */
#define LOCAL_SLOTS 256u
/* Ids either side of a point searched for a start of the walk to it. */
#define SAFE_LOOK 64u
/* States in a thread's table of the cells an insertion visits. */
#define CONFLICT 1u
#define TESTED 2u

/* A set of cell ids with a state each, open addressing; a slot is used
 * iff its tag's generation (tag >> 2) is the set's.                     */
typedef struct vset {
    uint32_t *cell, *tag;
    uint32_t mask, gen, n;
} vset;

typedef struct worker {
    dd_tri s;                 /* the thread's view: t's arrays, its own scratch */
    const uint16_t *part;     /* the region of each vertex id */
    uint16_t j;
    vset vis;                 /* the cells this insertion has visited */
    dd_vec aside;             /* points put aside */
    dd_vec todo;              /* the second pass's points */
    uint32_t next, end;       /* the fresh cells of its chunk */
    uint32_t lo, hi;          /* this thread's vertex ids in the round */
    uint32_t round_end;       /* the round's ids end here */
    uint32_t nfree;
    int64_t dlive, dfinite;
    uint64_t made, inserted;
    uint32_t *top;            /* the shared high-water mark (t->ncell) */
    uint32_t cap;
    uint32_t *etab;           /* oriented edge -> facet, DD_STAR_MAXV^2 */
    uint32_t gen, nl;         /* the star's vertex table: its generation, numbers */
    uint32_t lgen[LOCAL_SLOTS], lv[LOCAL_SLOTS];
    uint8_t ll[LOCAL_SLOTS];
    int full;
    dd_status err;
} worker;

/* ---- the visited cells ---------------------------------------------------- */

static dd_status vset_init(vset *v, uint32_t slots)
{
    v->cell = dd_malloc(slots * sizeof *v->cell);
    v->tag = dd_calloc(slots, sizeof *v->tag);
    if (!v->cell || !v->tag) return DD_ERR_NOMEM;
    v->mask = slots - 1;
    v->gen = 1;
    v->n = 0;
    return DD_OK;
}

static void vset_free(vset *v)
{
    dd_mfree(v->cell);
    dd_mfree(v->tag);
}

static inline void vset_clear(vset *v)
{
    v->n = 0;
    if (++v->gen == 1u << 30) {
        memset(v->tag, 0, ((size_t)v->mask + 1) * sizeof *v->tag);
        v->gen = 1;
    }
}

static inline uint32_t vset_slot(const vset *v, uint32_t c)
{
    return (uint32_t)(((uint64_t)c * 0x9E3779B97F4A7C15ull) >> 32) & v->mask;
}

/* The state of cell c (0: not visited). */
static inline uint32_t vset_get(const vset *v, uint32_t c)
{
    for (uint32_t h = vset_slot(v, c);; h = (h + 1) & v->mask) {
        uint32_t g = v->tag[h];
        if (g >> 2 != v->gen) return 0;
        if (v->cell[h] == c) return g & 3;
    }
}

/* Doubles v, keeping its entries.  DD_ERR_NOMEM, v unchanged. */
static dd_status vset_grow(vset *v)
{
    vset b;
    if (v->mask >= 1u << 30 || vset_init(&b, 2 * (v->mask + 1)) != DD_OK) {
        vset_free(&b);
        return DD_ERR_NOMEM;
    }
    for (uint32_t h = 0; h <= v->mask; h++) {
        if (v->tag[h] >> 2 != v->gen) continue;
        uint32_t k = vset_slot(&b, v->cell[h]);
        while (b.tag[k]) k = (k + 1) & b.mask;
        b.cell[k] = v->cell[h];
        b.tag[k] = 1u << 2 | (v->tag[h] & 3);
    }
    b.n = v->n;
    vset_free(v);
    *v = b;
    return DD_OK;
}

/* Sets the state of cell c (visited or not).  DD_ERR_NOMEM. */
static inline dd_status vset_put(vset *v, uint32_t c, uint32_t state)
{
    if (2 * (v->n + 1) > v->mask && vset_grow(v) != DD_OK) return DD_ERR_NOMEM;
    for (uint32_t h = vset_slot(v, c);; h = (h + 1) & v->mask) {
        if (v->tag[h] >> 2 != v->gen) {
            v->cell[h] = c;
            v->tag[h] = v->gen << 2 | state;
            v->n++;
            return DD_OK;
        }
        if (v->cell[h] == c) {
            v->tag[h] = v->gen << 2 | state;
            return DD_OK;
        }
    }
}

/* ---- regions ---------------------------------------------------------------- */

/* 1 when cell c is w's: a live cell whose finite vertices are all in w's
 * region.                                                               */
static inline int owned(const worker *w, uint32_t c)
{
    const uint32_t *v = dd_tv(&w->s, c);
    int finite = 0;
    for (int k = 0; k < 4; k++) {
        uint32_t x = v[k];
        if (x == DD_INF) continue;
        if (x >= DD_QD || w->part[x] != w->j) return 0;
        finite = 1;
    }
    return finite;
}

/* orient3d of cell c with its vertex i replaced by p (c finite). */
static int orient_replaced(worker *w, uint32_t c, uint32_t i, const double *p)
{
    const uint32_t *v = dd_tv(&w->s, c);
    const double *q[4];
    for (uint32_t k = 0; k < 4; k++) q[k] = k == i ? p : dd_pt(&w->s, v[k]);
    int f = dd_orient3d_filter(&w->s.pred, q[0], q[1], q[2], q[3]);
    return f != DD_FILTER_UNSURE ? f : dd_orient3d_unfiltered(&w->s.pred, q[0], q[1], q[2], q[3]);
}

/* The visibility walk of mesh.c from w's cell c to a finite cell whose
 * closure holds p or an infinite cell whose hull facet p sees, through
 * w's cells only: that cell, or DD_NONE when the way leaves them (or the
 * walk does not end: then w->err).                                     */
static uint32_t walk(worker *w, const double *p, uint32_t c)
{
    dd_tri *s = &w->s;
    uint32_t from = 4;
    if (dd_is_infinite_cell(s, c)) {
        c = dd_tn(s, c)[dd_index_of(s, c, DD_INF)] >> 2;
        if (!owned(w, c)) return DD_NONE;
    }
    for (uint64_t steps = 0, limit = 16 + 4 * (uint64_t)w->cap;; steps++) {
        if (steps > limit) { w->err = DD_ERR_INTERNAL; return DD_NONE; }
        if (dd_is_infinite_cell(s, c)) return c;
        uint32_t r = dd_xorshift(&s->rng) & 3, next = DD_NONE;
        for (uint32_t k = 0; k < 4; k++) {
            uint32_t i = (r + k) & 3;
            if (i == from) continue;
            if (orient_replaced(w, c, i, p) < 0) { next = dd_tn(s, c)[i]; break; }
        }
        if (next == DD_NONE) return c;
        s->walk_steps++;
        c = next >> 2;
        from = next & 3;
        if (!owned(w, c)) return DD_NONE;
    }
}

/* find_conflicts of mesh.c on w's cells, the states in w->vis: 0 when a
 * cell it must test or rewrite is not w's.                             */
static int find_conflicts(worker *w, const double *p, uint32_t c0)
{
    dd_tri *s = &w->s;
    vset *vis = &w->vis;
    s->stack.n = s->conflict.n = s->boundary.n = 0;
    vset_clear(vis);
    if (vset_put(vis, c0, CONFLICT) != DD_OK || dd_vec_push(&s->stack, c0) != DD_OK) goto nomem;
    while (s->stack.n > 0) {
        uint32_t c = s->stack.a[--s->stack.n];
        if (dd_vec_push(&s->conflict, c) != DD_OK) goto nomem;
        for (uint32_t j = 0; j < 4; j++) __builtin_prefetch(dd_tv(s, dd_tn(s, c)[j] >> 2));
        for (uint32_t i = 0; i < 4; i++) {
            uint32_t nb = dd_tn(s, c)[i] >> 2, state = vset_get(vis, nb);
            if (state == CONFLICT) continue;
            if (!state && !owned(w, nb)) return 0;
            dd_status st;
            if (!state && dd_cell_conflict_fast(s, nb, p)) {
                st = vset_put(vis, nb, CONFLICT);
                if (st == DD_OK) st = dd_vec_push(&s->stack, nb);
            } else {
                st = state ? DD_OK : vset_put(vis, nb, TESTED);
                if (st == DD_OK) st = dd_vec_push(&s->boundary, 4 * c + i);
            }
            if (st != DD_OK) goto nomem;
        }
    }
    return 1;
nomem:
    w->err = DD_ERR_NOMEM;
    return 0;
}

/* ---- cells ------------------------------------------------------------------ */

/* The rest of w's chunk onto its free list, as dead cells. */
static void spill_chunk(worker *w)
{
    dd_tri *s = &w->s;
    for (; w->next < w->end; w->next++) {
        uint32_t c = w->next;
        dd_tv(s, c)[0] = DD_DEAD;
        dd_tn(s, c)[0] = s->free_head;
        s->free_head = c;
        w->nfree++;
    }
    w->next = w->end = 0;
}

/* Room for k new cells: w's free list and chunk, a new chunk taken when
 * they fall short.  0 when the reserved capacity is used up (w->full);
 * a chunk cut short by the capacity is still w's.                      */
static int reserve(worker *w, uint32_t k)
{
    if (w->nfree + (w->end - w->next) >= k) return 1;
    spill_chunk(w);
    uint32_t want = k > CHUNK ? k : CHUNK;
    uint32_t base = __atomic_fetch_add(w->top, want, __ATOMIC_RELAXED);
    if (base < w->cap) {
        w->next = base;
        w->end = w->cap - base < want ? w->cap : base + want;
    }
    if (w->nfree + (w->end - w->next) >= k) return 1;
    w->full = 1;
    return 0;
}

/* A new cell (after reserve). */
static uint32_t new_cell(worker *w)
{
    dd_tri *s = &w->s;
    uint32_t c;
    if (s->free_head != DD_NONE) {
        c = s->free_head;
        s->free_head = dd_tn(s, c)[0];
        w->nfree--;
    } else {
        c = w->next++;
    }
    w->made++;
    w->dlive++;
    return c;
}

/* The local number of boundary vertex x in this star (mesh.c's edge
 * table; locals 0 and 2 are v and DD_INF), numbered on first sight in
 * w's vertex table: mesh.c numbers them in vcell, which other threads
 * read.  0 when the star has more than DD_STAR_MAXV numbers.           */
static inline uint32_t local_of(worker *w, uint32_t x)
{
    if (x == DD_INF) return 2;
    uint32_t h = (uint32_t)(((uint64_t)x * 0x9E3779B97F4A7C15ull) >> 56);   /* LOCAL_SLOTS = 256 */
    for (;; h = (h + 1) & (LOCAL_SLOTS - 1)) {
        if (w->lgen[h] != w->gen) {
            if (w->nl >= DD_STAR_MAXV) return 0;
            w->lgen[h] = w->gen;
            w->lv[h] = x;
            w->ll[h] = (uint8_t)w->nl;
            return w->nl++;
        }
        if (w->lv[h] == x) return w->ll[h];
    }
}

/* dd_fill_star of mesh.c on w's cells and tables: one new cell per
 * boundary facet, its three facets through v glued through the table of
 * oriented edges (or, past DD_STAR_MAXV local numbers, the edge hash),
 * vcell, then the conflict cells onto w's free list.                   */
static void fill_star(worker *w, uint32_t v)
{
    dd_tri *s = &w->s;
    size_t nb = s->boundary.n;
    uint32_t *e = w->etab, *pending = s->stack.a;
    if (++w->gen == 0) { memset(w->lgen, 0, sizeof w->lgen); w->gen = 1; }
    w->nl = 3;
    int table = 1;
    for (size_t k = 0; k < nb; k++) {
        uint32_t f = s->boundary.a[k], i = f & 3;
        uint32_t n = new_cell(w), loc[4];
        const uint32_t *dst = dd_star_cell(s, f, n, v);
        s->boundary.a[k] = n;
        if (!table) continue;
        for (uint32_t j = 0; j < 4; j++) {
            loc[j] = j == i ? 0 : local_of(w, dst[j]);
            if (j != i && !loc[j]) table = 0;
        }
        if (table) dd_star_edges(e, DD_STAR_MAXV, loc, i, n, pending + 6 * k);
    }
    if (table)
        for (size_t k = 0; k < nb; k++)
            for (uint32_t r = 0, *q = pending + 6 * k; r < 3; r++, q += 2) *dd_fn(s, q[0]) = e[q[1]];
    else
        dd_glue_new_cells(s, s->boundary.a, nb, v);
    for (size_t k = 0; k < nb; k++) {
        uint32_t n = s->boundary.a[k];
        int outer = 0;
        for (uint32_t j = 0; j < 4; j++) {
            uint32_t x = dd_tv(s, n)[j];
            if (x == DD_INF) { s->inf_cell = n; outer = 1; }
            else __atomic_store_n(&s->vcell[x], n, __ATOMIC_RELEASE);
        }
        w->dfinite += !outer;
    }
    if (nb) s->hint = s->boundary.a[nb - 1];
    for (size_t k = 0; k < s->conflict.n; k++) {
        uint32_t c = s->conflict.a[k];
        w->dfinite -= !dd_is_infinite_cell(s, c);
        dd_tv(s, c)[0] = DD_DEAD;
        dd_tn(s, c)[0] = s->free_head;
        s->free_head = c;
        w->nfree++;
        w->dlive--;
    }
}

/* One insertion of vertex v: 1 done, 0 put aside (or failed: w->err). */
static int insert_one(worker *w, uint32_t v)
{
    dd_tri *s = &w->s;
    const double *p = dd_pt(s, v);
    uint32_t c = s->hint;
    if (c == DD_NONE || !owned(w, c) || (c = walk(w, p, c)) == DD_NONE || !find_conflicts(w, p, c)) return 0;
    size_t nb = s->boundary.n;
    if (!reserve(w, (uint32_t)nb)) return 0;
    if (dd_reserve_edge_hash(s, nb) != DD_OK || dd_vec_reserve(&s->stack, 6 * nb) != DD_OK) {
        w->err = DD_ERR_NOMEM;
        return 0;
    }
    fill_star(w, v);
    w->inserted++;
    return 1;
}

/* Puts v aside: the next pass takes it. */
static void put_aside(worker *w, uint32_t v)
{
    if (!w->err && dd_vec_push(&w->aside, v) != DD_OK) w->err = DD_ERR_NOMEM;
}

/* Thread j's share of the round: its stretch of the curve. */
static void run_share(void *arg, unsigned j)
{
    worker *w = (worker *)arg + j;
    for (uint32_t v = w->lo; v < w->hi && !w->err; v++)
        if (w->full || !insert_one(w, v)) put_aside(w, v);
}

/* A start for the walk to vertex v's point: the cell of a vertex of
 * w's region near v on the curve (SAFE_LOOK ids either side), else w's
 * last new cell, else none.  Only w writes the cells that hold one of
 * its vertices, and their vcell entries, so reading them races with
 * nothing; a cell of no one's region may be another thread's.          */
static uint32_t safe_start(const worker *w, uint32_t v, uint32_t hi)
{
    const uint32_t *vcell = w->s.vcell;
    for (uint32_t d = 1; d <= SAFE_LOOK; d++) {
        if (v >= d && w->part[v - d] == w->j && vcell[v - d] != DD_NONE) return vcell[v - d];
        if (v + d < hi && w->part[v + d] == w->j && vcell[v + d] != DD_NONE) return vcell[v + d];
    }
    return w->s.hint;
}

/* Thread j's points put aside in the first pass (w->todo), each walk
 * from a safe start near it.                                           */
static void run_todo(void *arg, unsigned j)
{
    worker *w = (worker *)arg + j;
    w->s.hint = DD_NONE;                  /* the first pass's cells are not j's now */
    for (size_t k = 0; k < w->todo.n && !w->err; k++) {
        uint32_t v = w->todo.a[k];
        w->s.hint = safe_start(w, v, w->round_end);
        if (w->full || !insert_one(w, v)) put_aside(w, v);
    }
}

static dd_status worker_init(worker *w, dd_tri *t, const uint16_t *part, unsigned j)
{
    memcpy(&w->s, t, sizeof *t);
    dd_tri *s = &w->s;
    memset(&s->stack, 0, sizeof s->stack);
    memset(&s->conflict, 0, sizeof s->conflict);
    memset(&s->boundary, 0, sizeof s->boundary);
    s->ehash = NULL;
    s->ehash_cap = s->ehash_gen = s->ehash_mask = 0;
    s->etab = NULL;
    memset(&s->made, 0, sizeof s->made);
    s->del = NULL;
    s->free_head = DD_NONE;
    s->rng = dd_mix64(0x51A7E5EEDull + j) | 1;
    s->walk_steps = 0;
    w->part = part;
    w->j = (uint16_t)j;
    w->top = &t->ncell;
    memset(&w->aside, 0, sizeof w->aside);
    memset(&w->todo, 0, sizeof w->todo);
    w->gen = 0;
    memset(w->lgen, 0, sizeof w->lgen);
    dd_pred_init(&s->pred);
    w->etab = dd_malloc(DD_STAR_MAXV * DD_STAR_MAXV * sizeof *w->etab);
    if (!w->etab || vset_init(&w->vis, 1024) != DD_OK) return DD_ERR_NOMEM;
    return dd_pred_reserve(&s->pred);
}

static void worker_done(worker *w)
{
    dd_tri *s = &w->s;
    dd_vec_free(&s->stack);
    dd_vec_free(&s->conflict);
    dd_vec_free(&s->boundary);
    dd_mfree(s->ehash);
    dd_mfree(w->etab);
    vset_free(&w->vis);
    dd_pred_clear(&s->pred);
    dd_vec_free(&w->aside);
    dd_vec_free(&w->todo);
}

/* After a round: the workers' counts into t, their chunks' rest on their
 * free lists, t->ncell the cells handed out, and a live infinite cell. */
static void settle_round(dd_tri *t, worker *w, unsigned n)
{
    if (t->ncell > t->cap_c) t->ncell = t->cap_c;
    for (unsigned j = 0; j < n; j++) {
        spill_chunk(&w[j]);
        w[j].full = 0;
        t->nlive = (uint32_t)((int64_t)t->nlive + w[j].dlive);
        t->nfinite = (uint32_t)((int64_t)t->nfinite + w[j].dfinite);
        t->tets_created += w[j].made;
        t->nvert += (uint32_t)w[j].inserted;
        t->walk_steps += w[j].s.walk_steps;
        w[j].dlive = w[j].dfinite = 0;
        w[j].made = w[j].inserted = w[j].s.walk_steps = 0;
    }
    for (unsigned j = 0; j < n; j++) {
        uint32_t c = w[j].s.inf_cell;
        if (c != DD_NONE && dd_tv(t, c)[0] != DD_DEAD && dd_is_infinite_cell(t, c)) t->inf_cell = c;
    }
    if (dd_tv(t, t->inf_cell)[0] == DD_DEAD || !dd_is_infinite_cell(t, t->inf_cell))
        for (uint32_t c = 0; c < t->ncell; c++)
            if (dd_tv(t, c)[0] != DD_DEAD && dd_is_infinite_cell(t, c)) { t->inf_cell = c; break; }
    t->hint = t->inf_cell;
}

/* The points put aside, on this thread by mesh.c's insertion, each walk
 * from the cell of the vertex before it.                               */
static dd_status insert_aside(dd_tri *t, worker *w, unsigned n)
{
    dd_status st = DD_OK;
    for (unsigned j = 0; j < n && st == DD_OK; j++)
        for (size_t k = 0; k < w[j].aside.n && st == DD_OK; k++) {
            uint32_t v = w[j].aside.a[k];
            uint32_t h = v > 0 ? t->vcell[v - 1] : DD_NONE;
            if (h != DD_NONE) t->hint = h;
            st = dd_build_insert(t, v);
        }
    for (unsigned j = 0; j < n; j++) w[j].aside.n = 0;
    return st;
}

/* The workers' free lists onto t's. */
static void merge_free_lists(dd_tri *t, worker *w, unsigned n)
{
    for (unsigned j = 0; j < n; j++) {
        uint32_t c = w[j].s.free_head;
        while (c != DD_NONE) {
            uint32_t next = dd_tn(t, c)[0];
            dd_tn(t, c)[0] = t->free_head;
            t->free_head = c;
            t->nfree++;
            c = next;
        }
        w[j].s.free_head = DD_NONE;
        w[j].nfree = 0;
    }
}

/* The regions for the round of ids lo .. b - 1 on n threads: thread j's
 * share of each round so far, by position along its curve.             */
static void assign_regions(uint16_t *part, const uint32_t *rounds, uint32_t r, uint32_t lo, uint32_t b, unsigned n)
{
    for (uint32_t q = 0; q <= r; q++) {
        uint32_t a = q == 0 ? 0 : rounds[q] > lo || rounds[q + 1] > lo ? rounds[q] : lo;
        uint32_t e = q == r ? b : rounds[q + 1];
        if (e <= a) continue;
        uint64_t len = e - a;
        for (unsigned j = 0; j < n; j++) {
            uint32_t x0 = a + (uint32_t)(len * j / n), x1 = a + (uint32_t)(len * (j + 1) / n);
            for (uint32_t x = x0; x < x1; x++) part[x] = (uint16_t)j;
        }
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The regions of the second pass: slabs across the axis along which the
 * points put aside spread the most (they lie along the first pass's
 * borders, which the slabs then cut across), each holding as many of
 * them; vertex ids 0 .. b - 1.  DD_ERR_NOMEM.                          */
static dd_status assign_slabs(uint16_t *part, const dd_tri *t, const worker *w, unsigned n, uint32_t b)
{
    size_t m = 0;
    for (unsigned j = 0; j < n; j++) m += w[j].aside.n;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (unsigned j = 0; j < n; j++)
        for (size_t k = 0; k < w[j].aside.n; k++)
            for (int c = 0; c < 3; c++) {
                double x = dd_pt(t, w[j].aside.a[k])[c];
                lo[c] = x < lo[c] ? x : lo[c];
                hi[c] = x > hi[c] ? x : hi[c];
            }
    int axis = 0;
    for (int c = 1; c < 3; c++)
        if (hi[c] - lo[c] > hi[axis] - lo[axis]) axis = c;
    double *x = dd_malloc((m ? m : 1) * sizeof *x), cut[DD_THREADS_MAX];
    if (!x) return DD_ERR_NOMEM;
    m = 0;
    for (unsigned j = 0; j < n; j++)
        for (size_t k = 0; k < w[j].aside.n; k++) x[m++] = dd_pt(t, w[j].aside.a[k])[axis];
    qsort(x, m, sizeof *x, cmp_double);
    for (unsigned j = 1; j < n; j++) cut[j - 1] = m ? x[m * j / n] : 0;
    dd_mfree(x);
    for (uint32_t v = 0; v < b; v++) {
        double y = dd_pt(t, v)[axis];
        unsigned l = 0, h = n - 1;          /* the slab: the cuts at or below y */
        while (l < h) {
            unsigned mid = (l + h + 1) / 2;
            if (cut[mid - 1] <= y) l = mid;
            else h = mid - 1;
        }
        part[v] = (uint16_t)l;
    }
    return DD_OK;
}

/* The first pass's points put aside, to the thread whose slab holds
 * them, in curve order (thread j's lie before thread j + 1's).          */
static void deal_aside(worker *w, unsigned n, const uint16_t *part)
{
    for (unsigned j = 0; j < n; j++) w[j].todo.n = 0;
    for (unsigned j = 0; j < n; j++) {
        for (size_t k = 0; k < w[j].aside.n && !w[j].err; k++) {
            uint32_t v = w[j].aside.a[k];
            if (dd_vec_push(&w[part[v]].todo, v) != DD_OK) w[j].err = DD_ERR_NOMEM;
        }
        w[j].aside.n = 0;
    }
}

/* Thread j's start in the first pass: the cell of a vertex of its
 * region, the nearest to id x of the round before (ids below pb).       */
static uint32_t first_start(const dd_tri *t, const uint16_t *part, uint16_t j, uint32_t x, uint32_t pb)
{
    for (uint32_t d = 0; d <= x || x + d < pb; d++) {
        if (d <= x && part[x - d] == j && t->vcell[x - d] != DD_NONE) return t->vcell[x - d];
        if (x + d < pb && part[x + d] == j && t->vcell[x + d] != DD_NONE) return t->vcell[x + d];
    }
    return DD_NONE;
}

static dd_status workers_status(const worker *w, unsigned n)
{
    for (unsigned j = 0; j < n; j++)
        if (w[j].err != DD_OK) return w[j].err;
    return DD_OK;
}

/* One round of ids a .. b - 1 on n threads: the stretches, then the
 * points put aside on the shifted regions, then those put aside again,
 * here.  pa .. pb - 1: the round before, whose vertices give each thread
 * a start near its stretch.                                            */
static dd_status parallel_round(dd_tri *t, worker *w, unsigned n, uint16_t *part, const uint32_t *rounds,
                                uint32_t r, uint32_t lo, uint32_t a, uint32_t b, uint32_t pa, uint32_t pb)
{
    assign_regions(part, rounds, r, lo, b, n);
    for (unsigned j = 0; j < n; j++) {
        w[j].s.cell = t->cell;                 /* the serial steps may have grown them */
        w[j].s.stamp = t->stamp;
        w[j].cap = t->cap_c;
        w[j].lo = a + (uint32_t)((uint64_t)(b - a) * j / n);
        w[j].hi = a + (uint32_t)((uint64_t)(b - a) * (j + 1) / n);
        w[j].round_end = b;
        w[j].s.hint = first_start(t, part, (uint16_t)j, pa + (uint32_t)((uint64_t)(pb - pa) * (2 * j + 1) / (2 * n)), pb);
    }
    dd_run_threads(n, run_share, w);
    settle_round(t, w, n);
    dd_status st = workers_status(w, n);
    if (st != DD_OK) return st;
    if ((st = assign_slabs(part, t, w, n, b)) != DD_OK) return st;
    deal_aside(w, n, part);
    if ((st = workers_status(w, n)) != DD_OK) return st;
    dd_run_threads(n, run_todo, w);
    settle_round(t, w, n);
    st = workers_status(w, n);
    return st == DD_OK ? insert_aside(t, w, n) : st;
}

dd_status dd_build_parallel(dd_tri *t, uint32_t lo, uint32_t hi, const uint32_t *rounds, uint32_t nround)
{
    const unsigned n = t->nthreads;
    worker *w = dd_calloc(n, sizeof *w);
    uint16_t *part = dd_malloc((size_t)hi * sizeof *part);
    dd_status st = w && part ? DD_OK : DD_ERR_NOMEM;
    unsigned made = 0;
    for (; st == DD_OK && made < n; made++) st = worker_init(&w[made], t, part, made);
    uint32_t v = lo, pa = 0, pb = lo;         /* the round before: ids pa .. pb - 1 */
    for (uint32_t r = 0; r < nround && st == DD_OK; r++) {
        uint32_t a = rounds[r] > v ? rounds[r] : v, b = rounds[r + 1] < hi ? rounds[r + 1] : hi;
        if (b <= a) continue;
        if (b - a < MIN_SHARE * n) {
            for (uint32_t k = a; k < b && st == DD_OK; k++) st = dd_build_insert(t, k);
        } else {
            st = parallel_round(t, w, n, part, rounds, r, lo, a, b, pa, pb);
        }
        pa = a, pb = v = b;
    }
    for (; v < hi && st == DD_OK; v++) st = dd_build_insert(t, v);
    if (w) merge_free_lists(t, w, made);
    for (unsigned j = 0; j < made; j++) worker_done(&w[j]);
    dd_mfree(w);
    dd_mfree(part);
    if (st == DD_ERR_NOMEM) return dd_fail(t, st, "out of memory");
    if (st == DD_ERR_INTERNAL && !t->err[0]) return dd_fail(t, st, "point location did not terminate");
    return st;
}
