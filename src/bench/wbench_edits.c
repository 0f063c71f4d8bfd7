/*
 * wbench_edits.c -- `dtdel wedits-bench`: the weighted edits mesh
 * generators run most, against CGAL's Regular_triangulation_3 in the same
 * run (issue 44, DESIGN 10 and 12), in one hidden mode (the bench's:
 * kept; --discard-hidden for the other).  What make bench writes to
 * results/wedits.txt:
 *  - re-weighting (sliver exudation's pumping): every vertex of N wuniform
 *    weighted points, in input-index order, re-weighted by a random
 *    factor in [0.9, 1.1), dd_move_weighted(t, v, its own point, w)
 *    against CGAL's remove() then insert() (CGAL's move() ignores a
 *    weight change at the same position; Mesh_3's exuder does the same);
 *  - moves (Mesh_3's optimisers): every vertex of N wuniform weighted
 *    points moved by 5% of the mean spacing in a random direction, P
 *    passes, in input-index order, its weight kept: dd_move against
 *    CGAL's move() where move() gives the reference result, else remove()
 *    then insert() (cgal_rbench.h; the count of those is printed);
 *  - set deletion: a random 10% and 90% of the vertices of M wuniform
 *    weighted points, dd_delete_set against CGAL's remove() one vertex at
 *    a time in the same random order.
 * --set-only runs the set deletions alone.
 * The passes run in batches of edits (a checkpoint's, cut where an input
 * index would come twice): our side makes the batch's edits, then CGAL's
 * side the same edits, so each library runs with its own working set in
 * cache, as a mesh generator's pass does (the set deletions are whole
 * calls on each side already).  --interleaved makes each edit on both
 * sides in turn instead, each library evicting the other's data between
 * two of its edits; the lines say which ("batched" or "interleaved").
 * A point hidden when its turn comes is not a vertex: it is skipped (on
 * both sides, each asked; a point that is a vertex on one side only is a
 * mismatch).  CGAL's figures are its calls alone, timed in the shim; the
 * bookkeeping that names vertices by index is not timed.
 * The results are compared whole (cells and hidden set) at five
 * checkpoints of each pass and after each set deletion; a difference is
 * a mismatch, printed, and exits 1.  A call the engine refuses
 * (DD_ERR_UNSUPPORTED) prints "dtdel n/a" beside CGAL's figures.  After
 * each edit row, stderr gets the engine's edits that fell back to a
 * removal and an insertion (dd_counters' moves_redone), their count and
 * time, for profiling; the row itself is unchanged.
 */
#include "bench/wbench.h"
#include "dtdel/alloc.h"
#include "dtdel_stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CHECKPOINTS 5

typedef struct we_opts {
    uint64_t n, passes, m, seed;
    int discard, set_only, interleave;
} we_opts;

static int parse_opts(int argc, char **argv, we_opts *o)
{
    *o = (we_opts){100000, 2, 200000, 1, 0, 0, 0};
    int k = 0;
    char *args[64];
    for (int i = 0; i < argc && k < 64; i++)         /* the flags without a value, then the numbers */
        if (!strcmp(argv[i], "--discard-hidden")) o->discard = 1;
        else if (!strcmp(argv[i], "--set-only")) o->set_only = 1;
        else if (!strcmp(argv[i], "--interleaved")) o->interleave = 1;
        else args[k++] = argv[i];
    const num_opt opts[] = {{NULL, &o->n}, {"--passes", &o->passes}, {"--set", &o->m}, {"--seed", &o->seed}};
    int rc = parse_num_opts("wedits-bench", k, args, opts, (int)(sizeof opts / sizeof *opts));
    if (rc) return rc;
    if (o->n < 64 || o->m < 64) return usage_error("wedits-bench", "N and --set must be at least %s", "64");
    return 0;
}

static double unit(uint64_t *x)
{
    return rand_below(x, 1u << 30) / (double)(1u << 30);
}

/* q: from c by a step of length h in a random direction, uniform on
 * the sphere.                                                          */
static void random_step(uint64_t *x, const double c[3], double h, double q[3])
{
    double d[3], len;
    do {
        for (int k = 0; k < 3; k++) d[k] = 2 * unit(x) - 1;
        len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    } while (len > 1 || len < 1e-3);
    for (int k = 0; k < 3; k++) q[k] = c[k] + h * d[k] / len;
}

/* A pass's totals. */
typedef struct tally {
    double ours, theirs;          /* seconds                            */
    double redone;                /* seconds of ours in the moves redone */
    uint64_t done, fell_back, nredone;
    long bad;
    dd_status refused;            /* DD_OK, or the engine's refusal     */
} tally;

/* One edit: input index i to (q, w); vertex: i was a vertex of ours
 * when its turn came (so the edit was made on our side).               */
typedef struct wedit {
    double q[3], w;
    uint32_t i;
    int vertex;
} wedit;

/* Our side of edit e (dd_move when same_weight, else dd_move_weighted),
 * made only if e->i is a vertex of ours (noted in e->vertex).           */
static void edit_ours(wpair *p, tally *s, wedit *e, int same_weight)
{
    e->vertex = dd_is_vertex(p->t, e->i);
    if (!e->vertex || s->refused != DD_OK) return;
    dd_counters c0, c1;
    dd_get_counters(p->t, &c0);
    double t0 = now_seconds();
    dd_status st = same_weight ? dd_move(p->t, e->i, e->q) : dd_move_weighted(p->t, e->i, e->q, e->w);
    const double dt = now_seconds() - t0;
    s->ours += dt;
    dd_get_counters(p->t, &c1);
    if (c1.moves_redone > c0.moves_redone) s->redone += dt, s->nredone++;
    if (st == DD_ERR_UNSUPPORTED) s->refused = st;
    else if (st != DD_OK) s->bad++;
}

/* CGAL's side of edit e, made only if e->i is a vertex there; a point
 * that is a vertex on one side only is a mismatch.                      */
static void edit_theirs(wpair *p, tally *s, const wedit *e)
{
    const int vertex = dd_cgal_rb_state(p->c, e->i) == DD_RB_VERTEX;
    if (s->refused == DD_OK) s->bad += vertex != e->vertex;
    if (!vertex) return;
    double secs;
    int fb;
    s->bad += dd_cgal_rb_move(p->c, e->i, e->q, e->w, &secs, &fb) != 0;
    s->theirs += secs;
    s->fell_back += (uint64_t)fb;
    s->done++;
}

/* A batch of edits (no input index twice) on both sides: ours, then
 * CGAL's, so that each library runs with its own working set in cache,
 * as a mesh generator runs it; with interleave, each edit on our side
 * then on CGAL's, each library evicting the other's data between two
 * of its edits.                                                         */
static void edit_batch(wpair *p, tally *s, wedit *e, size_t n, int same_weight, int interleave)
{
    for (size_t k = 0; k < n; k++) {
        edit_ours(p, s, e + k, same_weight);
        if (interleave) edit_theirs(p, s, e + k);
    }
    for (size_t k = 0; k < n && !interleave; k++) edit_theirs(p, s, e + k);
}

static void print_tally(const tally *s, const char *theirs_name, int checks)
{
    if (s->refused == DD_OK)
        printf("dtdel %.2f us, %s %.2f us (%.1fx); ", 1e6 * s->ours / (double)s->done, theirs_name,
               1e6 * s->theirs / (double)s->done, s->theirs / s->ours);
    else
        printf("dtdel n/a (%s), %s %.2f us; ", dd_status_name(s->refused), theirs_name, 1e6 * s->theirs / (double)s->done);
    printf("%llu edits, %llu by CGAL's remove+insert; ", (unsigned long long)s->done, (unsigned long long)s->fell_back);
    if (s->refused == DD_OK) printf("%ld mismatches in %d checkpoints\n", s->bad, checks);
    else printf("mismatches n/a\n");
    fflush(stdout);
    if (s->refused == DD_OK && s->done)     /* the share of the moves that fell back to remove+insert */
        fprintf(stderr, "  dtdel: %llu edits redone by removal and insertion, %.2f us each, %.2f us an edit of %.2f\n",
                (unsigned long long)s->nredone, s->nredone ? 1e6 * s->redone / (double)s->nredone : 0.0,
                1e6 * s->redone / (double)s->done, 1e6 * s->ours / (double)s->done);
}

/* Every vertex re-weighted by a random factor in [0.9, 1.1). */
static int reweighting(const we_opts *o)
{
    wpair p;
    if (wpair_build("wedits-bench", "wuniform", (uint32_t)o->n, o->seed, o->discard, &p)) return 1;
    wedit *e = dd_malloc((size_t)p.np * sizeof *e);
    if (!e) { wpair_free(&p); return 1; }
    tally s = {0};
    uint64_t x = o->seed * 0x9E3779B97F4A7C15ull | 1;
    for (uint32_t k = 0; k < CHECKPOINTS; k++) {
        const uint32_t lo = (uint32_t)((uint64_t)p.np * k / CHECKPOINTS), hi = (uint32_t)((uint64_t)p.np * (k + 1) / CHECKPOINTS);
        for (uint32_t i = lo; i < hi; i++) {
            wedit *d = &e[i - lo];
            memcpy(d->q, p.xyz + 3 * (size_t)i, sizeof d->q);
            d->w = p.w[i] * (0.9 + 0.2 * unit(&x));
            d->i = i;
        }
        edit_batch(&p, &s, e, hi - lo, 0, o->interleave);
        if (s.refused == DD_OK) s.bad += wpair_compare(p.t, p.c);
    }
    dd_mfree(e);
    printf("wreweight: %u wuniform weighted points, each vertex re-weighted by a random factor in [0.9, 1.1) (%s, %s): ",
           p.np, wmode_name(o->discard), o->interleave ? "interleaved" : "batched");
    print_tally(&s, "CGAL remove+insert", CHECKPOINTS);
    wpair_free(&p);
    return s.bad || s.done == 0 ? 1 : 0;
}

/* P passes of a step of 5% of the mean spacing in a random direction. */
static int moves(const we_opts *o)
{
    wpair p;
    if (wpair_build("wedits-bench", "wuniform", (uint32_t)o->n, o->seed + 1, o->discard, &p)) return 1;
    double *cur = dd_malloc(3 * (size_t)p.np * sizeof *cur);
    wedit *e = dd_malloc((size_t)p.np * sizeof *e);
    if (!cur || !e) { dd_mfree(cur), dd_mfree(e), wpair_free(&p); return 1; }
    memcpy(cur, p.xyz, 3 * (size_t)p.np * sizeof *cur);
    const double h = 0.05 * cbrt(1.0 / p.np);
    tally s = {0};
    uint64_t x = o->seed * 0xD1B54A32D192ED03ull | 1;
    const uint64_t total = o->passes * p.np;
    for (uint32_t k = 0; k < CHECKPOINTS; k++) {
        const uint64_t lo = total * k / CHECKPOINTS, hi = total * (k + 1) / CHECKPOINTS;
        for (uint64_t b = lo, end; b < hi; b = end) {     /* batches within a pass: no index twice */
            end = (b / p.np + 1) * p.np < hi ? (b / p.np + 1) * p.np : hi;
            for (uint64_t j = b; j < end; j++) {
                wedit *d = &e[j - b];
                d->i = (uint32_t)(j % p.np);
                random_step(&x, cur + 3 * (size_t)d->i, h, d->q);
                d->w = p.w[d->i];
            }
            edit_batch(&p, &s, e, end - b, 1, o->interleave);
            for (uint64_t j = b; j < end; j++)                /* a point moves where it was a vertex */
                if (e[j - b].vertex) memcpy(cur + 3 * (size_t)e[j - b].i, e[j - b].q, sizeof e->q);
        }
        if (s.refused == DD_OK) s.bad += wpair_compare(p.t, p.c);
    }
    printf("wmove: %u wuniform weighted points, %llu passes of a step of 5%% of the mean spacing (%s, %s): ", p.np,
           (unsigned long long)o->passes, wmode_name(o->discard), o->interleave ? "interleaved" : "batched");
    print_tally(&s, "CGAL move", CHECKPOINTS);
    dd_mfree(cur), dd_mfree(e);
    wpair_free(&p);
    return s.bad || s.done == 0 ? 1 : 0;
}

/* A random `fraction` of the vertices deleted as a set. */
static int set_deletion(const we_opts *o, double fraction)
{
    wpair p;
    if (wpair_build("wedits-bench", "wuniform", (uint32_t)o->m, o->seed + 3, o->discard, &p)) return 1;
    uint32_t *vs = dd_malloc((size_t)p.np * sizeof *vs), k = 0;
    if (!vs) { wpair_free(&p); return 1; }
    uint64_t x = o->seed * 0x2545F4914F6CDD1Dull | 1;
    for (uint32_t i = 0; i < p.np; i++)
        if (dd_cgal_rb_state(p.c, i) == DD_RB_VERTEX && unit(&x) < fraction) vs[k++] = i;
    for (uint32_t i = k; i > 1; i--) {          /* a random order: the caller's */
        uint32_t j = rand_below(&x, i), t = vs[i - 1];
        vs[i - 1] = vs[j], vs[j] = t;
    }
    double t0 = now_seconds();
    dd_status st = dd_delete_set(p.t, vs, k);
    double ours = now_seconds() - t0, theirs = 0;
    long bad = 0;
    for (uint32_t i = 0; i < k; i++) {
        double secs;
        bad += dd_cgal_rb_remove(p.c, vs[i], &secs) != 0;
        theirs += secs;
    }
    printf("wdelete-set %.0f%%: %u of %u wuniform weighted points (%s): ", 100 * fraction, k, p.np,
           wmode_name(o->discard));
    if (st == DD_OK) {
        bad += wpair_compare(p.t, p.c);
        printf("dtdel %.2f us a vertex, CGAL remove one by one %.2f us (%.1fx); %ld mismatches\n", 1e6 * ours / k,
               1e6 * theirs / k, theirs / ours, bad);
    } else {
        printf("dtdel n/a (%s), CGAL remove one by one %.2f us; mismatches n/a\n", dd_status_name(st), 1e6 * theirs / k);
        if (st != DD_ERR_UNSUPPORTED) bad++;
    }
    dd_mfree(vs);
    wpair_free(&p);
    return bad ? 1 : 0;
}

int cmd_wedits_bench(int argc, char **argv)
{
    we_opts o;
    int rc = parse_opts(argc, argv, &o);
    if (rc) return rc;
    if (!o.set_only) {
        rc |= reweighting(&o);
        fflush(stdout);
        rc |= moves(&o);
        fflush(stdout);
    }
    const double fractions[2] = {0.1, 0.9};
    for (int i = 0; i < 2; i++) {
        rc |= set_deletion(&o, fractions[i]);
        fflush(stdout);
    }
    return rc ? EXIT_INPUT : 0;
}
