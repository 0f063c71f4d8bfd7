/*
 * mesh.h -- the tetrahedral mesh: the one place that fixes numbering and
 * orientation (DESIGN 4).  Every other file uses these tables; nobody keeps
 * a private copy.
 *
 * Cells.  Cell t has vertices tv(t)[0..3] and neighbours tn(t)[i] = 4u+j:
 * u is the cell across the facet opposite vertex i, and j is that facet's
 * index in u; facet f = 4t+i.  Invariant: fn(fn(f)) == f for every live
 * facet f (fn(f) = tn(f/4)[f%4]).  The two live side by side, one 32-byte
 * record a cell in a 64-byte aligned array (dd_tv, dd_tn, dd_fn): the walk
 * and the conflict search that read a cell's vertices then read its
 * neighbours (or write them, gluing), and so miss the cache once, not twice.
 *
 * Orientation.  A finite cell is positively oriented:
 * orient3d(p[tv0], p[tv1], p[tv2], p[tv3]) > 0.  An infinite cell has
 * exactly one vertex DD_INF; it is oriented as if DD_INF were a point
 * beyond its finite facet (replacing DD_INF by such a point gives a
 * positive orientation).  dd_facet[i] lists facet i's vertices so that
 * (facet i, then vertex i) has the cell's orientation:
 * orient3d(v[f0], v[f1], v[f2], x) > 0  iff  x is on v[i]'s side of facet i.
 *
 * Dead cells have tv(t)[0] == DD_DEAD; they are chained in a free list
 * through tn(t)[0] and reused before the array grows.
 *
 * Marks.  stamp[t] holds a 16-bit epoch; a cell is marked in the current
 * pass iff stamp[t] equals the pass's epoch.  Passes never clear marks:
 * they take fresh epochs (dd_new_epoch), O(1); when the 16 bits run out,
 * every stamp is cleared once (O(cells) per 65535 mark values: most passes
 * take one or two).  Two bytes, not four: the mesh stays within 40 bytes
 * per cell.  Only edits take epochs: a read-only call keeps its marks in
 * a dd_reader of its own (below), as it keeps all its scratch.
 *
 * Vertices.  Inside the engine a vertex is a vertex id: its position in
 * insertion order (BRIO + Hilbert), so that vertices close in space are
 * close in memory.  The public API speaks input indices; v2in and in2v
 * translate (a duplicate input maps to the id of its first occurrence).
 * vcell[v] is a live cell containing vertex v, or DD_NONE when v is not in
 * the triangulation (deleted, not yet inserted, or, in a regular
 * triangulation, hidden or forgotten).  inf_cell is a live infinite cell.
 *
 * Weights (DESIGN 12).  A regular triangulation has wt[v], the weight of
 * vertex id v (hidden points included); its conflict test is the power
 * test (dd_cell_power_conflict below) where the Delaunay triangulation's
 * is the in-sphere test, chosen once per triangulation or per edit, never
 * per cell.  Its hidden points belong to hidden.c (hidden.h).
 */
#ifndef DD_MESH_H
#define DD_MESH_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "dtdel/types.h"          /* dd_status, dd_tri: not dtdel.h (below the API) */
#include "dtdel/stats_types.h"    /* the test controls' names                */
#include "geom/pred.h"
#include "geom/power.h"

#define DD_INF  UINT32_MAX          /* the infinite vertex                 */
#define DD_DEAD (UINT32_MAX - 1)    /* tv(t)[0] of a dead cell             */
#define DD_NONE UINT32_MAX          /* no cell / no facet                  */
#define DD_QD   (UINT32_MAX - 2)    /* the dummy vertex q-boundary of a
                                       conflict DT (delete.h)              */

/* Facet i's vertex positions, ordered as described above (same as the
 * order CGAL's side_of_sphere uses for an infinite vertex at i).         */
static const int dd_facet[4][3] = {{2, 1, 3}, {2, 3, 0}, {1, 0, 3}, {0, 1, 2}};

/* dd_edge_of[i][j] (i != j): the two positions other than i and j, the
 * edge that facet j of a cell shares with facet i.                       */
static const uint8_t dd_edge_of[4][4][2] = {
    {{0, 0}, {2, 3}, {1, 3}, {1, 2}}, {{2, 3}, {0, 0}, {0, 3}, {0, 2}},
    {{1, 3}, {0, 3}, {0, 0}, {0, 1}}, {{1, 2}, {0, 2}, {0, 1}, {0, 0}}};

/* dd_star_edge[i][j] (j != i): positions (a, b) such that facet j of a
 * cell, in its dd_facet cyclic order, is (i, a, b): the directed edge a
 * star's facet through vertex i writes itself under (mesh.c, pbuild.c). */
static const uint8_t dd_star_edge[4][4][2] = {
    {{0, 0}, {2, 3}, {3, 1}, {1, 2}}, {{3, 2}, {0, 0}, {0, 3}, {2, 0}},
    {{1, 3}, {3, 0}, {0, 0}, {0, 1}}, {{2, 1}, {0, 2}, {1, 0}, {0, 0}}};

/* Stars whose boundary has at most this many vertices (the infinite and
 * dummy vertices count 3) are glued through a direct edge table of
 * DD_STAR_MAXV^2 entries (64 KB, kept in t->etab); larger ones through
 * the edge hash.                                                        */
#define DD_STAR_MAXV 128

/* A pass's mark value (see Marks above). */
typedef uint16_t dd_mark;
#define DD_MARK_MAX UINT16_MAX
/* Most mark values one pass may take: link.c numbers the cells of stars
 * up to this size by marks (larger ones through a hash), and the 16-bit
 * counter then wraps, clearing every stamp, at most once in 16 passes. */
#define DD_EPOCH_STEP_MAX 4096

/* A slot of the edge hash used to glue the cells of a star together. */
typedef struct dd_edge_slot {
    uint64_t key;      /* (min vertex << 32) | max vertex                 */
    uint32_t facet;    /* 4c+j waiting for its partner                   */
    uint32_t gen;      /* slot is used iff gen == t->ehash_gen           */
} dd_edge_slot;

/* A hash from vertex triples (unordered) to a value, open addressing.
 * A slot is used iff its gen equals the table's: a reset is O(1) (the
 * part in use is only cleared when the generation counter wraps).  It
 * grows by rehashing when half full.                                     */
typedef struct dd_tri_slot {
    uint32_t a, b, c;     /* a <= b <= c (DD_INF sorts last)              */
    uint32_t val;
    uint32_t gen;
} dd_tri_slot;

typedef struct dd_trihash {
    dd_tri_slot *s;
    uint32_t alloc, mask, n, gen;
} dd_trihash;

/* Open-addressing tables whose slots carry a generation (a slot is used
 * iff its gen is the table's): sizes *tab to the least power of two of at
 * least 64 and `min` slots of `elsize` bytes (*mask = that size - 1), all
 * unused, by taking a new generation in *gen.  O(1) unless it grows or
 * the generation counter wraps (then it clears once: a zeroed slot is
 * unused, generations start at 1).                                      */
dd_status dd_gen_table_reset(void **tab, uint32_t *alloc, uint32_t *gen, uint32_t *mask, size_t min,
                             size_t elsize);

/* Empties h and sizes it for about `expect` entries. */
dd_status dd_trihash_reset(dd_trihash *h, size_t expect);
/* Puts val under the triple {a, b, c} (any order; a triple is put once),
 * doubling h when half full.  DD_ERR_NOMEM, h unchanged, on refusal.   */
dd_status dd_trihash_put(dd_trihash *h, uint32_t a, uint32_t b, uint32_t c, uint32_t val);
/* The value stored under the triple {a, b, c}, or DD_NONE. */
uint32_t dd_trihash_get(const dd_trihash *h, uint32_t a, uint32_t b, uint32_t c);

/* a <= b <= c, the same three values: least, greatest and, from the
 * exclusive or of all five, the middle.  No branch on the data's order:
 * compare-and-swap branches, whose outcome is that order, mispredict in
 * the wrap's facet keys past 63 neighbours (`build/dtdel bench --dataset
 * helix` shows what they cost).                                        */
static inline void dd_sort3u(uint32_t *a, uint32_t *b, uint32_t *c)
{
    const uint32_t x = *a, y = *b, z = *c;
    const uint32_t lo = x < y ? x : y, hi = x < y ? y : x;
    const uint32_t l = lo < z ? lo : z, h = hi > z ? hi : z;
    *a = l;
    *b = x ^ y ^ z ^ l ^ h;
    *c = h;
}

/* The slot of the sorted triple (a, b, c) in a table of mask + 1 slots. */
static inline uint32_t dd_tri_hash(uint32_t a, uint32_t b, uint32_t c, uint32_t mask)
{
    uint64_t h = (uint64_t)a * 0x9E3779B97F4A7C15ull ^ (uint64_t)b * 0xC2B2AE3D27D4EB4Full
               ^ (uint64_t)c * 0x165667B19E3779F9ull;
    return (uint32_t)(h >> 40) & mask;
}

void dd_trihash_free(dd_trihash *h);

/* Resizes the array whose pointer is at pp (a T ** for any object type
 * T) to n elements of `size` bytes, as realloc (the first elements
 * kept; n = 0 keeps room for one).  DD_ERR_NOMEM, the array unchanged,
 * when the memory is refused.  The engine's one growth helper for
 * arrays sized by hand; dd_vec below grows itself with it.              */
dd_status dd_grow(void *pp, size_t n, size_t size);

/* A growable array of uint32_t (scratch; reused, never shrunk). */
typedef struct dd_vec {
    uint32_t *a;
    size_t n, cap;
} dd_vec;

dd_status dd_vec_reserve(dd_vec *v, size_t cap);
/* Room for `more` more entries, the capacity doubling (at least 64). */
static inline dd_status dd_vec_room(dd_vec *v, size_t more)
{
    if (v->n + more <= v->cap) return DD_OK;
    size_t cap = v->cap ? 2 * v->cap : 64;
    while (cap < v->n + more) cap *= 2;
    return dd_vec_reserve(v, cap);
}
static inline dd_status dd_vec_push(dd_vec *v, uint32_t x)
{
    if (v->n == v->cap) {
        dd_status s = dd_vec_room(v, 1);
        if (s != DD_OK) return s;
    }
    v->a[v->n++] = x;
    return DD_OK;
}
void dd_vec_free(dd_vec *v);

/* Where point location starts for a query or a new point (locate.c): per
 * box of a grid over the vertices' bounding box, one vertex id or
 * DD_NONE.  Made by dd_create and kept by the edits (dd_grid_ready);
 * read-only calls only read it.  Empty (box NULL) when it could not be
 * made: walks then start from t->hint.                                  */
typedef struct dd_grid {
    uint32_t *box;
    size_t nbox, cap;
    uint32_t dim[3];
    double pre[3], lo[3], inv[3]; /* box of x: (x * pre - lo) * inv, per
                                 axis (pre a power of two, lo scaled by it) */
    uint32_t made_for;        /* t->nvert when it was made                */
} dd_grid;

/* The cells the last edit made (cells.c): noted where the edit commits
 * them, straight into the public list of dd_created_cells; filtered when
 * the outermost edit ends if more than one step noted some.            */
typedef struct dd_made {
    int64_t *list;            /* live cells, each once, once filtered    */
    size_t n, cap;
    int depth;                /* edits open (a set's rollback re-inserts) */
    int notes;                /* dd_note_made calls in this edit          */
    int all;                  /* this edit replaced every cell            */
    int lost;                 /* a note could not be kept (no memory)     */
} dd_made;

struct dd_hidset;

struct dd_tri {
    /* vertices, indexed by vertex id */
    double *xyz;
    uint32_t *vcell;
    uint32_t *v2in;           /* vertex id -> input index                */
    uint32_t nvid, cap_v;     /* vertex ids in use, capacity             */
    /* input points, indexed by input index */
    uint32_t *in2v;           /* input index -> vertex id                */
    uint32_t np, cap_in;
    uint32_t nvert, ndup;     /* vertices in DT now, duplicates merged   */
    uint32_t inf_cell;
    const double *qd_point;   /* conflict DT only: q, see dd_cell_conflict */
    int borrowed;             /* xyz, vcell, v2in belong to another dd_tri */

    /* cells */
    uint32_t *cell;           /* DD_CELL_WORDS a cell: vertices, neighbours */
    void *cell_block;         /* the allocation holding cell (aligned in it) */
    dd_mark *stamp;
    uint32_t ncell, cap_c;    /* high-water mark and capacity            */
    uint32_t nlive, nfinite;
    uint32_t free_head;       /* free list through tn(t)[0], DD_NONE = empty */
    uint32_t nfree;           /* cells on the free list                  */
    uint32_t epoch;
    uint32_t hint;            /* where the next point location starts    */

    uint64_t rng;             /* dd_xorshift state for walks             */
    dd_pred pred;
    uint64_t tets_created, walk_steps;
    uint64_t moves_kept, moves_flipped, moves_redone;   /* dd_move's courses */

    struct dd_del *del;       /* deletion context (delete.c), lazily made */
    dd_grid grid;             /* location starts (locate.c), kept by edits */
    dd_vec flip[5];           /* dd_move_by_flips' scratch (flip.c)       */
    dd_vec vfree;             /* ids of deleted vertices, for dd_insert to
                                 reuse (api.c); may hold stale entries   */

    /* scratch for insertion (dd_fill_star also keeps its pending facet
     * pairs in stack)                                                    */
    dd_vec stack, conflict, boundary;
    uint32_t *etab;               /* oriented edge -> facet, see fill_star:
                                     DD_STAR_MAXV^2 entries, made lazily  */
    struct dd_edge_slot *ehash;   /* edge -> facet, see glue_new_cells   */
    uint32_t ehash_cap, ehash_gen, ehash_mask;  /* mask: this star's size */

    unsigned flags;           /* dd_create_ex's DD_* flags               */
    unsigned nthreads;        /* threads its calls may use (par.c), >= 1 */
    dd_made made;             /* the cells the last edit made (cells.c)   */
    char err[256];            /* the message of the failure at hand (dd_fail) */
    char errmsg[256];         /* dd_errmsg: the last failed public call's */
#ifdef DD_TEST_BUILD
    long testctl[DD_TEST_NCTL];   /* dd_test_control (dtdel_stats.h)     */
#endif
    /* a regular triangulation's (DESIGN 12), last: the Delaunay
     * triangulation's hot fields keep their places                      */
    double *wt;               /* weights by vertex id, else NULL: the one
                                 place weights enter                    */
    struct dd_hidset *hid;    /* hidden points (hidden.c): weighted only  */
};

/* Sets t->err and returns s. */
dd_status dd_fail(dd_tri *t, dd_status s, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* The end of a public call on t that returns s: a failure's message (t->err,
 * or the status's name if the failure set none) becomes dd_errmsg's; a
 * success leaves dd_errmsg as it was.  Returns s.  Public calls clear
 * t->err when they start, so that a message is the call's own.          */
dd_status dd_end_call(dd_tri *t, dd_status s);
/* The short fixed name of a status: dd_status_name (dtdel.h). */
const char *dd_status_text(dd_status s);

static inline const double *dd_pt(const dd_tri *t, uint32_t v)
{
    return t->xyz + 3 * (size_t)v;
}

#define DD_CELL_WORDS 8

/* The four vertices of cell c. */
static inline uint32_t *dd_tv(const dd_tri *t, uint32_t c)
{
    return t->cell + DD_CELL_WORDS * (size_t)c;
}

/* The four neighbour facets of cell c. */
static inline uint32_t *dd_tn(const dd_tri *t, uint32_t c)
{
    return t->cell + DD_CELL_WORDS * (size_t)c + 4;
}

/* The neighbour entry of facet f = 4c+i (dd_tn(t, c) + i), and the vertex
 * opposite it (dd_tv(t, c) + i).                                          */
static inline uint32_t *dd_fn(const dd_tri *t, uint32_t f)
{
    return t->cell + 2 * (size_t)f - (f & 3) + 4;
}

static inline uint32_t *dd_fv(const dd_tri *t, uint32_t f)
{
    return t->cell + 2 * (size_t)f - (f & 3);
}

static inline int dd_is_infinite_cell(const dd_tri *t, uint32_t c)
{
    const uint32_t *v = dd_tv(t, c);
    return v[0] == DD_INF || v[1] == DD_INF || v[2] == DD_INF || v[3] == DD_INF;
}

/* A cell with DD_INF or DD_QD: not a finite tetrahedron of the domain. */
static inline int dd_is_outer_cell(const dd_tri *t, uint32_t c)
{
    const uint32_t *v = dd_tv(t, c);
    for (int i = 0; i < 4; i++)
        if (v[i] >= DD_QD) return 1;
    return 0;
}

/* Position of vertex x in cell c, or -1. */
static inline int dd_index_of(const dd_tri *t, uint32_t c, uint32_t x)
{
    const uint32_t *v = dd_tv(t, c);
    return v[0] == x ? 0 : v[1] == x ? 1 : v[2] == x ? 2 : v[3] == x ? 3 : -1;
}

/* The position of x among a cell's vertices v[0..4), x being one of them:
 * free of branches, since where x sits is data no processor predicts.   */
static inline uint32_t dd_slot_of(const uint32_t *v, uint32_t x)
{
    const uint32_t at3 = v[3] == x;       /* bits: 1 at 1 or 3, 2 at 2 or 3 */
    return ((uint32_t)(v[1] == x) | at3) | ((uint32_t)(v[2] == x) | at3) << 1;
}

/* Reserves `step` (at most DD_EPOCH_STEP_MAX) fresh mark values for a
 * pass and returns the first; the pass may use first .. first + step - 1. */
static inline dd_mark dd_new_epoch(dd_tri *t, uint32_t step)
{
#ifdef DD_TEST_BUILD
    if (step == 0 || step > DD_EPOCH_STEP_MAX) __builtin_trap();
#endif
    if (t->epoch > DD_MARK_MAX - step) {   /* wrap: clear once */
        memset(t->stamp, 0, (size_t)t->ncell * sizeof *t->stamp);
        t->epoch = 0;
    }
    t->epoch += step;
    return (dd_mark)(t->epoch - step + 1);
}

/* splitmix64's finaliser: a bijection of 64-bit words, every output bit
 * depending on every input bit (hashing and seeding).                    */
static inline uint64_t dd_mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* The engine's one pseudo-random generator: a step of Marsaglia's
 * xorshift64 (shifts 13, 7, 17) of *state, which must not be 0; returns
 * the high half of the new state.  Seeded per use, so that the same
 * input does the same work.                                             */
static inline uint32_t dd_xorshift(uint64_t *state)
{
    uint64_t x = *state;
    x ^= x << 13; x ^= x >> 7; x ^= x << 17;
    *state = x;
    return (uint32_t)(x >> 32);
}

/* Cell storage. dd_reserve_cells makes room for k more cells so that the
 * next k dd_new_cell calls cannot fail.                                  */
dd_status dd_reserve_cells(dd_tri *t, uint32_t k);
uint32_t dd_new_cell(dd_tri *t);     /* after dd_reserve_cells */
/* Gives back the capacity beyond the cells in use (after construction). */
void dd_shrink_cells(dd_tri *t);
void dd_kill_cell(dd_tri *t, uint32_t c);
/* Undoes the dd_new_cell calls that made c[0..n), in that order, with no
 * other change of the cells between; ncell0: t->ncell before them.  The
 * free list, the cell count and the counters are as before them (a cell
 * made past the end, at or above ncell0, is taken back from the end, one
 * from the free list goes back on top).                               */
void dd_unmake_cells(dd_tri *t, const uint32_t *c, size_t n, uint32_t ncell0);

static inline void dd_glue(dd_tri *t, uint32_t f, uint32_t g)
{
    *dd_fn(t, f) = g;
    *dd_fn(t, g) = f;
}

/* The star's cell n over boundary facet f (cell c, opposite position i):
 * c's vertices with the one at i replaced by v, glued to the cell across
 * f.  Returns n's vertices.                                            */
static inline uint32_t *dd_star_cell(dd_tri *t, uint32_t f, uint32_t n, uint32_t v)
{
    const uint32_t *src = dd_tv(t, f >> 2);
    uint32_t *dst = dd_tv(t, n);
    for (uint32_t j = 0; j < 4; j++) dst[j] = src[j];
    dst[f & 3] = v;
    dd_glue(t, 4 * n + (f & 3), *dd_fn(t, f));
    return dst;
}

/* The three facets through v (at position i) of star cell n, whose
 * vertices have local numbers loc: each written into the edge table e
 * (rows of `stride`) under its directed edge, and (facet, partner's key)
 * into q[0..6).                                                        */
static inline void dd_star_edges(uint32_t *e, uint32_t stride, const uint32_t loc[4], uint32_t i, uint32_t n,
                                 uint32_t *q)
{
    for (uint32_t j = 0; j < 4; j++) {
        if (j == i) continue;
        uint32_t a = loc[dd_star_edge[i][j][0]], b = loc[dd_star_edge[i][j][1]];
        e[a * stride + b] = 4 * n + j;
        *q++ = 4 * n + j;
        *q++ = b * stride + a;
    }
}

/* Conflict test of the perturbed Delaunay triangulation: 1 when point p
 * lies inside the (perturbed) circumsphere of cell c, CGAL's rule for
 * infinite cells included.  In a conflict DT, a cell with the dummy vertex
 * DD_QD at position k is tested as the cell with q in place of DD_QD and
 * two other vertices swapped (paper 4.1: (a,b,c,q_d) is tested as the
 * ordinary cell (b,a,c,q)).                                               */
int dd_cell_conflict(dd_tri *t, uint32_t c, const double *p);
/* dd_cell_conflict on the predicates pr (a read-only call's own).      */
int dd_cell_conflict_on(const dd_tri *t, dd_pred *pr, uint32_t c, const double *p);
/* dd_cell_conflict with the filter inlined for finite cells (the hot
 * tests of the conflict search and of the flips): only these sites
 * inline the filter, which elsewhere would grow the code for no gain.   */
static inline int dd_cell_conflict_fast(dd_tri *t, uint32_t c, const double *p)
{
    const uint32_t *v = dd_tv(t, c);
    if ((v[0] < DD_QD) & (v[1] < DD_QD) & (v[2] < DD_QD) & (v[3] < DD_QD)) {
        const double *a = dd_pt(t, v[0]), *b = dd_pt(t, v[1]);
        const double *d = dd_pt(t, v[2]), *e = dd_pt(t, v[3]);
        int f = dd_insphere_filter(&t->pred, a, b, d, e, p);
        if (f == DD_FILTER_UNSURE) f = dd_insphere_unfiltered(&t->pred, a, b, d, e, p);
        if (f == 0) f = dd_insphere_symbolic(&t->pred, a, b, d, e, p);
        return f > 0;
    }
    return dd_cell_conflict(t, c, p);
}

/* The same rule on the cell's points q[0..3] (q[k] ignored: k is the
 * infinite vertex's position or -1; kd the dummy vertex's or -1, with
 * q[kd] = q's point).  q is permuted.                                    */
int dd_points_conflict(dd_pred *pr, const double *q[4], int k, int kd, const double *p);

/* The conflict test of a regular triangulation (DESIGN 12): 1 when the
 * weighted point (p, wp) is in conflict with cell c, CGAL's
 * Regular_triangulation_3::in_conflict_3 (the perturbed power test on a
 * finite cell; on an infinite one, p beyond the hull facet or in its
 * plane and inside its perturbed power circle).  t is weighted and has
 * no dummy vertex.  _on: on the predicates pr (a read-only call's own).  */
int dd_cell_power_conflict_on(const dd_tri *t, dd_pred *pr, uint32_t c, const double *p, double wp);
__attribute__((always_inline)) static inline int dd_cell_power_conflict_fast(dd_tri *t, uint32_t c, const double *p,
                                                                           double wp)
{
    const uint32_t *v = dd_tv(t, c);
    if ((v[0] != DD_INF) & (v[1] != DD_INF) & (v[2] != DD_INF) & (v[3] != DD_INF)) {
        const double *a = dd_pt(t, v[0]), *b = dd_pt(t, v[1]);
        const double *d = dd_pt(t, v[2]), *e = dd_pt(t, v[3]);
        const double w[5] = {t->wt[v[0]], t->wt[v[1]], t->wt[v[2]], t->wt[v[3]], wp};
        int f = dd_power_filter(&t->pred, a, b, d, e, p, w);
        if (f == DD_FILTER_UNSURE) f = dd_power_exact(&t->pred, a, b, d, e, p, w);
        if (f == 0) f = dd_power_symbolic(&t->pred, a, b, d, e, p, w);
        return f > 0;
    }
    return dd_cell_power_conflict_on(t, &t->pred, c, p, wp);
}

/* The scratch of one read-only call (dtdel.h: any number of them may run
 * at once on one triangulation, which they must not write): its own
 * predicate context, walk generator and step count, and a set of ids
 * (cells or vertices: visited marks) by open addressing, whose first
 * DD_READER_INLINE slots are in the struct and larger tables malloc'd.
 * On the caller's stack: dd_reader_init, then dd_reader_done, which
 * frees what it took.  The generator starts from the same seed in every
 * call, so a query's answer depends on the triangulation and p alone.  */
#define DD_READER_INLINE 256
typedef struct dd_reader {
    dd_pred pred;
    uint64_t rng;
    uint64_t steps;           /* cells crossed by this call's walks     */
    uint32_t *set;            /* inl, or malloc'd when larger           */
    uint32_t set_cap, set_mask, set_n;
    dd_vec star;              /* dd_star_read's list, for its callers    */
    uint32_t inl[DD_READER_INLINE];
} dd_reader;

void dd_reader_init(dd_reader *r);
void dd_reader_done(dd_reader *r);
/* Empties r's set, sized for about `expect` ids.  DD_ERR_NOMEM.        */
dd_status dd_reader_set_reset(dd_reader *r, size_t expect);
/* Puts id x (not DD_NONE) in r's set: 1 if it was not there, 0 if it
 * was, -1 when the set cannot grow (out of memory).  It doubles when
 * half full; O(1) expected.                                             */
int dd_reader_set_add(dd_reader *r, uint32_t x);

/* Point location from cell `start`: a walk on plain floating-point
 * orientations towards p (mesh.c, locate_inexact), then the exact
 * visibility walk; stops in a finite cell whose closure holds p, or in
 * the first outer cell entered (which p sees).  dd_walk_locate is the
 * edits' (t's predicates, generator and walk_steps); dd_walk_read the
 * read-only calls', which writes only r.  DD_ERR_INTERNAL (and, for the
 * edits', a message) if the walk does not end.                          */
dd_status dd_walk_locate(dd_tri *t, const double *p, uint32_t start, uint32_t *out);
dd_status dd_walk_read(const dd_tri *t, dd_reader *r, const double *p, uint32_t start, uint32_t *out);

/* Bowyer-Watson in three steps, shared by construction and deletion:
 * dd_find_conflicts marks the conflict region of p reachable from c0 (which
 * must be in conflict) in t->conflict and its boundary facets in
 * t->boundary; dd_reserve_star makes room so that dd_fill_star, which
 * replaces the region by the star of vertex v, cannot fail.               */
dd_status dd_find_conflicts(dd_tri *t, const double *p, uint32_t c0);
dd_status dd_reserve_star(dd_tri *t);
void dd_fill_star(dd_tri *t, uint32_t v);

/* Inserts vertex v (its point already in xyz, vcell[v] == DD_NONE) into a
 * 3D triangulation by Bowyer-Watson, starting the walk at t->hint
 * (dd_insert_vertex) or at cell `start` (dd_insert_vertex_at).           */
dd_status dd_insert_vertex(dd_tri *t, uint32_t v);
dd_status dd_insert_vertex_at(dd_tri *t, uint32_t v, uint32_t start);
/* dd_insert_vertex_at from a caller's cell: when p is strictly inside
 * hint's circumsphere the conflict search starts there, with no walk. */
dd_status dd_insert_vertex_from(dd_tri *t, uint32_t v, uint32_t hint);
/* dd_insert_vertex_at, the conflict cells fetched ahead, refusing a
 * duplicate quietly: DD_ERR_DUPLICATE with no message, *dup the vertex
 * whose point v's is, nothing changed (a batch merges it).              */
dd_status dd_insert_vertex_dup(dd_tri *t, uint32_t v, uint32_t start, uint32_t *dup);

/* Reorders ids[0..n) (ids of points pts[3 id..]; ascending when brio) along
 * the Hilbert curve of their bounding box, in BRIO rounds (smallest
 * first, a round drawn from a hash of the id) when brio, else in one.
 * Stable.  Cost O(n) (a radix sort; O(n log n) below 2048 points), 16n
 * bytes of scratch plus 128 KiB from 2048 points on.  DD_ERR_NOMEM.   */
dd_status dd_spatial_order(const double *pts, uint32_t *ids, uint32_t n, int brio);
/* dd_spatial_order on up to nthreads threads (one a 65536 points), the
 * same order; 128 KiB of counters a thread.  DD_ERR_NOMEM.              */
dd_status dd_spatial_order_threads(const double *pts, uint32_t *ids, uint32_t n, int brio, unsigned nthreads);

/* first[i] = the smallest i' holding the same point as point i of
 * pts[0..3n) (with w not NULL, the same weighted point); writes the kept
 * ones (first[i] == i, ascending) to ids[0..*nkept).  O(n) expected, 16
 * bytes a point of scratch; DD_ERR_NOMEM with t's message.             */
dd_status dd_dedup_points(dd_tri *t, const double *pts, const double *w, uint32_t n, uint32_t *first,
                          uint32_t *ids, uint32_t *nkept);

/* ---- regular triangulations (regular.c; DESIGN 12) ----------------------- */

/* dd_find_conflicts with the power test of the weighted point (p, wp)
 * (t weighted); ahead: fetch the cells ahead (construction).           */
dd_status dd_find_conflicts_power(dd_tri *t, const double *p, double wp, uint32_t c0, int ahead);

/* What a weighted insertion did with its point. */
typedef enum dd_fate {
    DD_FATE_VERTEX,       /* a vertex now (it may have hidden others)     */
    DD_FATE_HIDDEN,       /* kept as a hidden point                       */
    DD_FATE_FORGOTTEN,    /* hidden, and forgotten (DD_DISCARD_HIDDEN)     */
    DD_FATE_DUPLICATE     /* a vertex has its point and weight: nothing
                             changed (CGAL returns that vertex)           */
} dd_fate;

/* Inserts vertex id v (its point and weight stored, vcell[v] DD_NONE)
 * into the weighted 3D triangulation t by CGAL's rule
 * (Triangulation_3::insert_in_conflict with Regular_triangulation_3's
 * tester and hidden point visitor): located from cell `start`
 * (DD_NONE: t->hint); a vertex with v's point and weight makes it a
 * duplicate (*dup = that vertex); a point not in conflict with its cell
 * is hidden (or forgotten); else the conflict region is replaced by v's
 * star, the vertices it swallows become hidden points (or are
 * forgotten), and the hidden points of the region are re-homed.  ahead:
 * construction's prefetching search.  All or nothing: DD_ERR_NOMEM, or
 * DD_ERR_INTERNAL from a broken mesh, change nothing.  O(conflict region
 * + walk), plus a walk for each hidden point re-homed.                  */
dd_status dd_insert_power(dd_tri *t, uint32_t v, uint32_t start, int ahead, dd_fate *fate, uint32_t *dup);

/* As dd_nearest_from for a weighted t: a vertex of least power distance
 * |p - x|^2 - w(x) (any one of ties), exactly, by greedy descent over the
 * edges; where no neighbour is strictly nearer, the descent searches the
 * vertices at the same power distance connected by edges (degenerate
 * power cells) before it stops.                                         */
dd_status dd_nearest_power_from(const dd_tri *t, dd_reader *r, const double *p, uint32_t c, uint32_t *nearest);

/* ---- location for queries and new points (locate.c) ---------------------- */

/* Makes t->grid fit the vertices now (made by dd_create, remade when
 * their number has doubled or halved), O(nvid) when it is made, else
 * O(1).  The edits call it; a failure (out of memory) leaves no grid,
 * which only makes walks longer.                                       */
dd_status dd_grid_ready(dd_tri *t);
/* Records vertex v, just inserted, in its box (if the grid exists).      */
void dd_grid_note(dd_tri *t, uint32_t v);
void dd_grid_free(dd_grid *g);
/* A live cell near p to start a walk from: the cell of a vertex of p's
 * box or a box next to it, else t->hint, else the infinite cell.        */
uint32_t dd_start_near(const dd_tri *t, const double *p);
/* The cells incident to vertex v, in out (reset first), O(star):
 * dd_star_cells marks them with an epoch of t (edits), dd_star_read in
 * r's set (read-only calls).                                            */
dd_status dd_star_cells(dd_tri *t, uint32_t v, dd_vec *out);
dd_status dd_star_read(const dd_tri *t, dd_reader *r, uint32_t v, dd_vec *out);
/* A vertex nearest to p (exactly; any one of ties), by greedy descent
 * over the Delaunay edges from the vertices of cell c; r's predicates,
 * set and r->star as scratch.                                          */
dd_status dd_nearest_from(const dd_tri *t, dd_reader *r, const double *p, uint32_t c, uint32_t *nearest);

/* ---- moving a vertex in place (flip.c) ---------------------------------- */

/* Moves vertex v to p and repairs the mesh by 2-3 and 3-2 flips: 1 when
 * that yields the DT of the moved set (*flips of them; 0 flips: v's star
 * stayed positive and locally Delaunay, the relocation filter), else 0
 * with the mesh and v's point unchanged (an inverted star cell, a hull
 * facet or a flat configuration in the way, an unflippable facet, or too
 * many flips).  Exact, perturbation included.  O(star) plus O(1) a flip;
 * t->conflict as scratch; *err DD_ERR_NOMEM (and 0) when out of memory. */
int dd_move_by_flips(dd_tri *t, uint32_t v, const double p[3], int *flips, dd_status *err);
/* The same for construction, whose cells are mostly out of cache: the
 * conflict search fetches the next cells ahead.                          */
dd_status dd_build_insert(dd_tri *t, uint32_t v);

/* The first tetrahedron v[0..3] (any orientation) and its four infinite
 * cells, in an empty t.  Room for 5 cells must be reserved.              */
void dd_make_first_cells(dd_tri *t, uint32_t v[4]);
/* Moves four affinely independent points of the points pts[3 ids[k]..],
 * k < n (distinct, or weighted points some of which share a position),
 * to ids[0..3]: ids[0], the first point at another position to ids[1],
 * the first off their line to ids[2], the first off their plane to ids[3].
 * DD_ERR_TOO_FEW (n < 2), DD_ERR_COLLINEAR or DD_ERR_COPLANAR when there
 * are none, without a message.  The one search for a first simplex.     */
dd_status dd_find_simplex(dd_pred *pr, const double *pts, uint32_t *ids, uint32_t n);
/* The same for construction: DD_ERR_TOO_FEW when n < 4, and a message
 * in t->err on every failure.                                          */
dd_status dd_pick_simplex(dd_tri *t, const double *pts, uint32_t *ids, uint32_t n);

/* Replaces the cells of t by DT of its vertices but the vertex ids
 * ids[0..n) (sorted ascending), which leave it (vcell DD_NONE): the kept
 * ones inserted in id order into a scratch triangulation whose cells are
 * then swapped in, so a failure (out of memory, or DD_ERR_COPLANAR when
 * the kept points are: the caller checks that first) changes nothing.
 * O(kept log kept) expected, as construction.                           */
dd_status dd_rebuild_without(dd_tri *t, const uint32_t *ids, size_t n);

/* Empties the cell arrays (keeps their capacity), O(1). */
void dd_clear_cells(dd_tri *t);

/* Glues the facets through vertex v of the given new cells to each other,
 * by matching their edges in the edge hash (reserve it first with
 * dd_reserve_edge_hash for at least ncells cells).  Facets without a
 * partner keep tn == DD_NONE.                                            */
dd_status dd_reserve_edge_hash(dd_tri *t, size_t ncells);
void dd_glue_new_cells(dd_tri *t, const uint32_t *cells, size_t ncells, uint32_t v);

/* The vertex id of input index `input` if it is a vertex now, else
 * DD_NONE (a duplicate, a deleted point, out of range).                 */
static inline uint32_t dd_vertex_of(const dd_tri *t, uint32_t input)
{
    if (input >= t->np) return DD_NONE;
    const uint32_t v = t->in2v[input];
    return t->v2in[v] == input && t->vcell[v] != DD_NONE ? v : DD_NONE;
}

/* Input index of vertex v, as the public API reports it (-1 for DD_INF). */
static inline int32_t dd_input_index(const dd_tri *t, uint32_t v)
{
    return v == DD_INF ? -1 : (int32_t)t->v2in[v];
}

/* Canonical form (dtdel.h, dd_canonical) of the cells cells[0..n) of t:
 * each as its four input indices sorted ascending (-1 for DD_INF), the
 * list sorted, repeated cells once.  *tets is malloc'd, 4 * *ntets ints.
 * The one builder behind dd_canonical and dd_local_canonical.           */
dd_status dd_canonical_of_cells(const dd_tri *t, const uint32_t *cells, size_t n, int32_t **tets,
                                size_t *ntets);

/* A scratch triangulation with its own cells that borrows the points
 * (xyz, v2in, vcell: the caller sets them) of another one.              */
dd_status dd_tri_alloc_borrowed(dd_tri **out);

/* Frees t's own arrays and t; its deletion context (t->del) must have
 * been freed already (dd_free, src/api.c).                               */
void dd_tri_destroy(dd_tri *t);

/* Room for one more vertex id (t->nvid < cap_v) and input index (t->np <
 * cap_in), the arrays doubled if needed: DD_ERR_NOMEM if they cannot.  */
dd_status dd_reserve_vertex(dd_tri *t);

/* ---- cell handles (cells.c) -------------------------------------------- */

/* An edit of t begins and ends (the public edits of src/ call them;
 * nested pairs count as one, the outermost).  dd_edit_end(t, s) returns
 * s; when the outermost edit ends, dd_created_cells lists the live cells
 * it noted, each once, or none if it succeeded without a note; an edit
 * that failed with no note leaves the list as it was; a failure's
 * message becomes dd_errmsg's (dd_end_call).  O(1), or O(cells noted)
 * when several steps noted cells (a cell of one step may have died in a
 * later one).                                                         */
static inline void dd_edit_begin(dd_tri *t)
{
    if (t->made.depth++ == 0) {
        t->made.notes = t->made.all = 0;
        t->err[0] = 0;
    }
}
void dd_edit_settle(dd_tri *t, dd_status s);
static inline dd_status dd_edit_end(dd_tri *t, dd_status s)
{
    if (--t->made.depth != 0) return s;
    if (t->made.notes != 1 || t->made.all) dd_edit_settle(t, s);
    return dd_end_call(t, s);
}
/* Notes cells made by the edit under way (nothing outside an edit, as in
 * the scratch triangulations).  Where the edit commits them: the star of
 * an insertion, the fill a deletion sews in, the flips a move keeps.
 * Never fails: a note that cannot be kept makes dd_created_cells say
 * DD_ERR_NOMEM.  dd_note_all: the edit replaced every cell.            */
void dd_note_made(dd_tri *t, const uint32_t *cells, size_t n);
void dd_note_all(dd_tri *t);
static inline void dd_note_cell(dd_tri *t, uint32_t c)
{
    if (t->made.depth) dd_note_made(t, &c, 1);
}
/* Publishes every live cell as made (dd_create).  DD_ERR_NOMEM.        */
dd_status dd_publish_all_cells(dd_tri *t);
void dd_made_free(dd_made *m);
/* The exact visibility walk from live cell `start` to a cell whose
 * closure holds p, or an infinite cell whose hull facet p sees (strictly
 * beyond it); writes nothing to t (pr: the caller's predicate context,
 * rng: the caller's dd_xorshift state, not 0).  DD_ERR_INTERNAL if it
 * does not end (a broken mesh).                                       */
dd_status dd_walk_const(const dd_tri *t, dd_pred *pr, uint64_t *rng, const double *p, uint32_t start,
                        uint32_t *out);

/* dd_create_ex's flag DD_DISCARD_HIDDEN (dtdel.h, which this layer does
 * not include; access.c asserts that the two agree).                    */
#define DD_DISCARD_HIDDEN_FLAG (1u << 1)

/* dd_create_ex's DD_THREADS(n) and DD_THREADS_ALL (dtdel.h; access.c
 * asserts that they agree): n in bits 8..18, "every core" in bit 19.     */
#define DD_THREADS_SHIFT 8
#define DD_THREADS_MASK 0x7FFu
#define DD_THREADS_ALL_FLAG (1u << 19)

/* ---- threads (par.c) ------------------------------------------------------ */

/* The most threads one call uses (a larger request uses this many). */
#define DD_THREADS_MAX 1024u
/* The cores online (1 if unknown), at most DD_THREADS_MAX. */
unsigned dd_cores(void);
/* The count a triangulation starts with when its creator names none:
 * DTDEL_THREADS if set (a count; 0 or "all": dd_cores()), else 1.      */
unsigned dd_threads_default(void);
/* Runs fn(arg, j) for j = 0 .. n - 1, j = 0 in the calling thread, the
 * others each in a thread of its own, and returns when all have; a job
 * whose thread cannot be started runs in the caller after its own.    */
void dd_run_threads(unsigned n, void (*fn)(void *arg, unsigned j), void *arg);

/* Inserts vertex ids lo .. hi - 1 (points stored, vcell DD_NONE, all
 * distinct, in BRIO + Hilbert order; rounds[0..nround] the first id of
 * each BRIO round, then hi) into the Delaunay triangulation t (not
 * weighted), on t->nthreads threads (pbuild.c).  The result is the one
 * dd_build_insert gives in order, whatever the schedule; the numbering
 * of the cells is not.  DD_ERR_NOMEM, DD_ERR_INTERNAL (t then unusable:
 * construction destroys it).                                           */
dd_status dd_build_parallel(dd_tri *t, uint32_t lo, uint32_t hi, const uint32_t *rounds, uint32_t nround);
/* The first vertex id of each BRIO round of the m vertex ids whose input
 * indices are v2in[0..m) (build.c's rounds), in starts[0..*nround), and
 * m in starts[*nround]; starts has room for 16 + 1.                    */
void dd_brio_rounds(const uint32_t *v2in, uint32_t m, uint32_t *starts, uint32_t *nround);

/* Creates an empty dd_tri with room for np points. */
dd_status dd_tri_alloc(dd_tri **out, uint32_t np);

/* dd_create_ex (dtdel.h) with flags already checked (kept in t->flags),
 * but on failure msg (if not NULL) holds t->err, which may be empty (out
 * of memory): dd_create_ex names the status then.  weights NULL: the
 * Delaunay triangulation; else the regular one (weights checked here). */
dd_status dd_mesh_create(dd_tri **out, const double *xyz, const double *weights, uint32_t n, unsigned flags,
                         char *msg, size_t msglen);

/* dd_check_msg (dtdel.h): the validator, src/mesh/check.c; reads t
 * only, its scratch its own.                                           */
dd_status dd_mesh_check(const dd_tri *t, char *msg, size_t msglen);

#endif
