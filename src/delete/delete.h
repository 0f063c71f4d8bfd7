/*
 * delete.h -- the deletion framework shared by every variant (paper 3-4,
 * DESIGN 6) and the strategy interface of variants/.
 *
 * DELETEVERTEX(q) (delete.c):
 *   1. collect the star of q, its link (one triangle per star cell, the
 *      facet opposite q) and P, q's neighbours (DD_INF among them when q is
 *      on the hull); refuse when the result would not be 3-dimensional;
 *   2. let the strategy fill d->qdt, a scratch triangulation that borrows
 *      the points of the main one, and list in d->fill the cells of d->qdt
 *      that fill the cavity;
 *   3. sew: match each fill facet that has no fill neighbour to its link
 *      triangle (through a hash of the link triangles), copy the fill
 *      cells into the mesh glued to the outside, recycle the star.  Gift
 *      wrapping (d->fill_in_mesh) makes its fill in the mesh, over the
 *      star's cells (then in new ones), and matches it itself: the sew
 *      then only glues it to the outside.  Steps 1-2 leave the
 *      triangulation as it was (wrapping keeps the star's cells aside
 *      and writes them back, and gives back the new cells, when its fill
 *      is not kept) and step 3 starts only once every boundary facet is
 *      matched: all or nothing.
 *
 * The conflict DT DT(x)_q(P_i) lives in d->qdt closed by the dummy vertex
 * DD_QD: each boundary triangle abc of DT(x) carries a dummy cell
 * (a,b,c,DD_QD), tested for conflict as the ordinary cell (b,a,c,q) (paper
 * 4.1, done by dd_cell_conflict).  Its dummy cells mirror the link DT
 * DT^l(Q_i): dummy (a,b,c,DD_QD) <-> link tetrahedron (a,b,c,q).  With that
 * rule, inserting into DT(x) is ordinary Bowyer-Watson: QCONFLICTDTINSERT.
 *
 * Special case handled by the framework before any strategy runs: a hull
 * vertex whose finite neighbours are all coplanar (and, on a weighted t,
 * the hidden points of its star too).  Then no finite cell can fill the
 * cavity and the fill is forced: each finite link triangle becomes a
 * hull facet, the cell (a,b,c,DD_INF); the star's hidden points, all on
 * that plane, stay hidden (delete.c, fill_step).
 */
#ifndef DD_DELETE_H
#define DD_DELETE_H

#include "mesh/mesh.h"
#include "dtdel/stats_types.h"   /* the statistics' table sizes */

#ifdef DD_COUNTERS
#include <time.h>
#endif

/* Phases of one deletion (seconds), measured in counting builds only. */
enum { DD_PH_LINK, DD_PH_LOCATE, DD_PH_CONFLICT, DD_PH_SEW, DD_NPHASES };

/* A strategy's scratch, kept in the deletion context across deletions (no
 * allocation once warm) and freed with it.  The framework knows a scratch
 * only by its kind: a descriptor the strategy defines once, statically. */
typedef struct dd_scratch_kind {
    const char *name;
    void (*free)(void *scratch);
} dd_scratch_kind;

typedef struct dd_scratch_slot {
    const dd_scratch_kind *kind;
    void *p;
} dd_scratch_slot;

/* Kinds of scratch one context can keep: four exist (GRR-CONSTRUCT,
 * grr-brio, the compact conflict DT, gift wrapping), room for more.    */
#define DD_SCRATCH_SLOTS 8

typedef struct dd_del {
    dd_tri *t;            /* the triangulation being edited               */
    uint32_t q;           /* vertex id being deleted                      */
    const double *qp;     /* its point                                    */
    double qw;            /* its weight (a weighted t; else 0)            */
    dd_vec hpts;          /* weighted t: the star's hidden points, taken
                             from hidden.c for this deletion              */
    int on_hull;          /* DD_INF is a neighbour of q                   */
    uint32_t star_inf;    /* infinite cells in the star                   */

    dd_vec star;          /* cells incident to q                          */
    dd_vec nbr;           /* P minus DD_INF: the finite neighbours of q   */
    uint32_t base[4];     /* 4 affinely independent points of nbr         */

    dd_trihash lhash;     /* link triangle (vertex triple) -> star slot,
                             built on demand: dd_del_link_hash            */
    int lhash_ready;      /* lhash holds this deletion's link             */
    uint32_t *vmark;      /* per vertex id, epoch marks (cap t->cap_v)    */
    uint32_t vmark_cap, vepoch;

    dd_scratch_slot scratch[DD_SCRATCH_SLOTS];   /* the strategies' own
                             scratch (dd_del_scratch), kept across calls */
    dd_tri *qdt;          /* the conflict DT, or the full DT of P         */
    uint32_t *qdt_vcell;  /* vertex -> cell of qdt (borrowed by qdt)      */
    dd_vec fill;          /* cells of qdt that fill the cavity (of the
                             mesh itself when fill_in_mesh)               */
    dd_vec order;         /* scratch: the strategy's insertion order      */
    dd_vec sew_out;       /* per fill facet 4k+j, its outside facet (or
                             DD_NONE: inside the fill); a strategy that
                             sets fill_in_mesh has filled it              */
    int fill_in_mesh;     /* the strategy made the fill in the mesh, over
                             the star's cells and in new ones, glued to
                             each other, and matched it to the link
                             (gift wrapping, src/wrap)                     */
    dd_vec cellmap;       /* scratch: qdt cell -> new mesh cell           */
    uint64_t rng;         /* dd_del_rand's state, seeded by q            */

    /* statistics of the last deletion */
    uint32_t degree;
    uint64_t qdt_created;         /* cells created in qdt                  */
    uint64_t fallbacks;           /* sampling fallbacks (guided variants)  */
    uint64_t locate_steps;        /* cells tested by guided/scan location  */
    int forced_fill;              /* fill_coplanar_hull ran                */
    const char *const *sstat_names;   /* the strategy's statistics: names */
    uint32_t nsstat;                  /* and how many (dd_del_strategy_stats) */
    uint32_t sstat[DD_STRATEGY_STATS];
    uint32_t link_deletions[DD_LINKDEG_BUCKETS];   /* by deleted degree     */
    double phase[DD_NPHASES];
#ifdef DD_COUNTERS
    struct timespec ph_t0;
#endif
} dd_del;

/* Phase timing: compiled in for counting builds only. */
#ifdef DD_COUNTERS
void dd_phase_begin(dd_del *d);
void dd_phase_end(dd_del *d, int phase);
#define DD_PHASE_BEGIN(d) dd_phase_begin(d)
#define DD_PHASE_END(d, ph) dd_phase_end(d, ph)
#else
#define DD_PHASE_BEGIN(d) ((void)0)
#define DD_PHASE_END(d, ph) ((void)0)
#endif

/* A deletion strategy: one const struct per file in variants/. */
typedef struct dd_variant {
    const char *name;
    const char *description;
    /* Fills d->qdt and d->fill for the cavity of d->q.  d->base holds four
     * affinely independent neighbours; d->nbr all finite neighbours.      */
    dd_status (*fill_cavity)(dd_del *d);
    /* The same on a weighted triangulation (DESIGN 12, issue 44): fills
     * d->qdt and d->fill with the cells of the regular triangulation of
     * P = d->order (q's finite neighbours, then the star's hidden points
     * d->hpts) in power conflict with (q, d->qw).  NULL: the strategy
     * does not delete weighted points, and the framework refuses with
     * DD_ERR_UNSUPPORTED naming it, changing nothing.                      */
    dd_status (*fill_weighted)(dd_del *d);
} dd_variant;

/* The scratch of kind k kept in d, or NULL if none was kept yet. */
static inline void *dd_del_scratch(const dd_del *d, const dd_scratch_kind *k)
{
    for (int i = 0; i < DD_SCRATCH_SLOTS && d->scratch[i].kind; i++)
        if (d->scratch[i].kind == k) return d->scratch[i].p;
    return NULL;
}
/* Keeps p as d's scratch of kind k (none kept yet), freed with d by
 * k->free.  DD_ERR_INTERNAL when the slots are full (a bug).            */
dd_status dd_del_keep_scratch(dd_del *d, const dd_scratch_kind *k, void *p);

/* Names the strategy's statistics of this deletion: d->sstat[0..n), at
 * most DD_STRATEGY_STATS, zero when the deletion began; names[i] says
 * what sstat[i] counts (dd_last_delete_stats copies both).              */
void dd_del_strategy_stats(dd_del *d, const char *const *names, uint32_t n);

/* DELETEVERTEX(q) with strategy var; q a vertex id (dd_del_resolve). */
dd_status dd_del_vertex(dd_tri *t, uint32_t q, const dd_variant *var);
/* The vertex id of input index `input`, or DD_ERR_UNKNOWN_VERTEX (with
 * a message) when it names no vertex now.                               */
dd_status dd_del_resolve(dd_tri *t, uint32_t input, uint32_t *v);
/* Frees the deletion context (dd_free). */
void dd_del_free(dd_del *d);

/* Sets up the context for input vertex v and collects its star, link
 * triangles and neighbours (step 1 of DELETEVERTEX), without deleting:
 * an edit (it writes t's marks and context), for tests that look at
 * the star; the public star queries read it with dd_star_read.       */
dd_status dd_del_star_of(dd_tri *t, uint32_t v, dd_del **out);

/* ---- services for strategies -------------------------------------------- */

/* Builds d->lhash for this deletion's link, once (collect_star does not:
 * most deletions never look a link triangle up by its vertices).       */
dd_status dd_del_link_hash(dd_del *d);

/* A random number of this deletion (dd_xorshift of d->rng). */
uint32_t dd_del_rand(dd_del *d);
/* Shuffles a[0..n) with d's generator. */
void dd_del_shuffle(dd_del *d, uint32_t *a, size_t n);

/* Moves four affinely independent points of a[0..n) to a[0..3] (the first
 * found in a's order) and records them in d->base; DD_ERR_COPLANAR if
 * there are none (the framework has already excluded that case).        */
dd_status dd_del_pick_base(dd_del *d, uint32_t *a, size_t n);

/* Starts d->qdt as an empty conflict DT (qd = 1) or full DT (qd = 0). */
void dd_qdt_reset(dd_del *d, int qd);

/* CREATEQCONFLICTDT(P_4): DT(x)_q of the four points d->base, closed by
 * dummy cells.                                                           */
dd_status dd_qdt_create(dd_del *d);
/* QCONFLICTDTINSERT: inserts vertex v into the conflict DT (or the full
 * DT) by Bowyer-Watson from `start`, a cell in conflict with v.          */
dd_status dd_qdt_insert(dd_del *d, uint32_t v, uint32_t start);
/* Unguided point location in a conflict DT: the first live cell found in
 * conflict with v by scanning the dummy cells (one always is).           */
dd_status dd_qdt_scan(dd_del *d, uint32_t v, uint32_t *cell);
/* Lists every live non-dummy cell of the conflict DT in d->fill. */
dd_status dd_qdt_collect_fill(dd_del *d);
/* Lists in d->fill the cells of a full DT(P) in d->qdt in conflict with q. */
dd_status dd_full_collect_fill(dd_del *d);
/* The weighted counterparts (t weighted, issue 44): the regular
 * triangulation of d->order (base first) in d->qdt by CGAL's insertion
 * rule (a point may end hidden there, or hide one inserted before), and
 * its cells in power conflict with (q, d->qw) in d->fill.                */
dd_status dd_full_build_power(dd_del *d);
dd_status dd_full_collect_fill_power(dd_del *d);
/* The weighted fill of sew-full (and of auto on a weighted t): the
 * neighbours in random order, then the star's hidden points in random
 * order, into the full regular triangulation, whose cells in power
 * conflict with q fill the cavity.  Why neighbours first: each is a
 * vertex of every regular triangulation of a subset of P holding it
 * (its link triangles are faces of the result), so none is ever hidden
 * and only hidden points can hide each other.                          */
dd_status dd_full_fill_power(dd_del *d);
/* Builds the full DT of d->nbr in d->qdt, inserting d->base first and then
 * the rest in the order of d->order (a permutation of d->nbr).           */
dd_status dd_full_build(dd_del *d);

#endif
