/*
 * test_threads.c -- concurrent reads (dtdel.h, Threads): 8 threads call
 * every read-only function at once on one triangulation, and each
 * thread's answers equal those of one thread alone, computed first.
 *
 * Datasets: uniform points, an integer grid (degenerate: cospherical
 * cells, queries on vertices, edges and facets), points on a sphere and
 * integer points on a sphere (every vertex on the hull); and weighted
 * (regular triangulations, hidden points kept): uniform points with
 * weights up to three squared spacings (many hidden) and the grid with
 * integer weights 0..2 (power ties), where the weighted reads
 * (dd_is_weighted, dd_weight, dd_is_hidden, dd_hidden, and dd_locate,
 * dd_nearest_vertex by power distance) meet the hidden-point lists.
 * Before the threads start, each triangulation has had vertices deleted
 * and new points inserted (dead cells, reused indices, a deletion
 * context; on the weighted ones, weighted insertions, some hidden), so
 * the reads meet the state that edits leave.
 *
 * Each item of the work (a query point and a vertex) gets one 64-bit
 * digest of every answer about it; each thread walks all items from its
 * own offset, so the threads are at different items and at the same
 * ones in turn.  The whole-triangulation calls (dd_canonical, dd_cells,
 * dd_check, dd_hidden, dd_created_cells, the counters and getters) run
 * once a round in every thread.
 * Afterwards the triangulation must be as before: canonical form,
 * counters and dd_errmsg unchanged.
 *
 * In the ThreadSanitizer build (build/tsan, make test) a data race fails
 * the run (TSAN_OPTIONS=halt_on_error=1, tests/run.sh).  Argument
 * "small": smaller sets (the sanitizer builds).
 */
#include "testlib.h"
#include <math.h>
#include <pthread.h>
#include "dtdel.h"
#include "../datasets/datasets.h"

#define NTHREADS 8

/* FNV-1a over 32-bit words. */
static uint64_t mix(uint64_t h, uint32_t x)
{
    for (int b = 0; b < 4; b++) {
        h ^= (x >> (8 * b)) & 0xFF;
        h *= 0x100000001b3ull;
    }
    return h;
}

static uint64_t mix_d(uint64_t h, double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return mix(mix(h, (uint32_t)u), (uint32_t)(u >> 32));
}

typedef struct work {
    const dd_tri *t;
    const double *q;          /* nq query points                         */
    uint32_t nq;
    uint32_t nin;             /* input indices 0 .. nin-1 are asked about */
    int rounds;
} work;

/* Every answer about item i: the query point q[i] and input index i. */
static uint64_t item_digest(const dd_tri *t, const work *w, uint32_t i)
{
    uint64_t h = 0xcbf29ce484222325ull;
    const double *p = w->q + 3 * (size_t)i;
    int32_t cell[4];
    dd_status s = dd_locate(t, p, cell);
    h = mix(h, (uint32_t)s);
    if (s == DD_OK)
        for (int k = 0; k < 4; k++) h = mix(h, (uint32_t)cell[k]);
    uint32_t nv = UINT32_MAX;
    h = mix(h, (uint32_t)dd_nearest_vertex(t, p, &nv));
    h = mix(h, nv);
    dd_cell_id hc = -1, nbc[4];
    int32_t cv[4];
    s = dd_locate_from(t, p, -1, &hc);
    h = mix(h, (uint32_t)s);
    if (s == DD_OK) {
        h = mix(mix(h, (uint32_t)dd_cell_alive(t, hc)), (uint32_t)dd_cell(t, hc, cv, nbc));
        for (int k = 0; k < 4; k++) h = mix(mix(h, (uint32_t)cv[k]), (uint32_t)nbc[k]);
    }

    const uint32_t v = i % w->nin;
    double x[3] = {0, 0, 0};
    h = mix(h, (uint32_t)dd_point(t, v, x));
    for (int c = 0; c < 3; c++) h = mix_d(h, x[c]);
    h = mix(h, dd_alias(t, v));
    h = mix(h, (uint32_t)dd_is_vertex(t, v));
    double wv = NAN;
    h = mix(h, (uint32_t)dd_weight(t, v, &wv));
    h = mix_d(h, wv);
    h = mix(h, (uint32_t)dd_weight(t, w->nin + v, &wv));       /* past the input: DD_ERR_ARG */
    h = mix(h, (uint32_t)dd_is_hidden(t, v));
    h = mix(h, dd_degree(t, v));
    h = mix(h, (uint32_t)dd_on_hull(t, v));
    uint32_t nbr[64];
    uint32_t nn = dd_neighbors(t, v, nbr, 64);
    h = mix(h, nn);
    for (uint32_t k = 0; k < nn && k < 64; k++) h = mix(h, nbr[k]);
    int32_t inc[128][4];
    uint32_t nc = dd_incident_cells(t, v, inc, 128);
    h = mix(h, nc);
    for (uint32_t k = 0; k < nc && k < 128; k++)
        for (int j = 0; j < 4; j++) h = mix(h, (uint32_t)inc[k][j]);
    const uint32_t two[2] = {v, (v + 1) % w->nin};
    int32_t *lc = NULL;
    size_t nlc = 0;
    s = dd_local_canonical(t, two, 2, &lc, &nlc);
    h = mix(h, (uint32_t)s);
    if (s == DD_OK) h = mix(mix(h, (uint32_t)nlc), (uint32_t)dd_canonical_hash(lc, nlc));
    free(lc);
    return h;
}

/* The whole-array reads of all the queries (the NaN one included: its
 * status), and every input point.                                      */
static uint64_t batch_digest(const dd_tri *t, const work *w)
{
    uint64_t h = 0xcbf29ce484222325ull;
    dd_cell_id *cells = malloc((w->nq + 1) * sizeof *cells);
    uint32_t *near = malloc((w->nq + 1) * sizeof *near);
    double *pts = malloc(4 * ((size_t)dd_num_input(t) + 1) * sizeof *pts);
    if (!cells || !near || !pts) exit(1);
    h = mix(h, (uint32_t)dd_locate_many(t, w->q, w->nq, cells));
    h = mix(h, (uint32_t)dd_nearest_many(t, w->q, w->nq, near));
    for (uint32_t i = 0; i < w->nq; i++) h = mix(mix(h, (uint32_t)cells[i]), near[i]);
    h = mix(h, (uint32_t)dd_points(t, pts, pts + 3 * (size_t)dd_num_input(t)));
    for (size_t i = 0; i < 4 * (size_t)dd_num_input(t); i++) h = mix_d(h, pts[i]);
    free(cells), free(near), free(pts);
    return h;
}

/* Every answer about the whole triangulation. */
static uint64_t whole_digest(const dd_tri *t, const work *w)
{
    uint64_t h = batch_digest(t, w);
    int32_t *a = NULL, *nb = NULL;
    size_t na = 0;
    dd_status s = dd_canonical(t, &a, &na);
    h = mix(h, (uint32_t)s);
    if (s == DD_OK) h = mix(mix(h, (uint32_t)na), (uint32_t)dd_canonical_hash(a, na));
    free(a);
    a = NULL;
    s = dd_cells(t, &a, &nb, &na);
    h = mix(h, (uint32_t)s);
    for (size_t k = 0; s == DD_OK && k < 4 * na; k++) h = mix(mix(h, (uint32_t)a[k]), (uint32_t)nb[k]);
    free(a);
    free(nb);
    uint32_t *hid = NULL;
    s = dd_hidden(t, &hid, &na);
    h = mix(mix(h, (uint32_t)s), (uint32_t)dd_is_weighted(t));
    for (size_t k = 0; s == DD_OK && k < na; k++) h = mix(h, hid[k]);
    free(hid);
    const dd_cell_id *made = NULL;
    s = dd_created_cells(t, &made, &na);
    h = mix(mix(h, (uint32_t)s), (uint32_t)dd_cell_end(t));
    for (size_t k = 0; s == DD_OK && k < na; k++) h = mix(h, (uint32_t)made[k]);
    char msg[200];
    h = mix(h, (uint32_t)dd_check_msg(t, msg, sizeof msg));
    h = mix(h, (uint32_t)dd_check(t));
    h = mix(h, dd_num_input(t));
    h = mix(h, dd_num_vertices(t));
    h = mix(h, dd_num_duplicates(t));
    h = mix(h, (uint32_t)dd_num_tets(t));
    h = mix(h, (uint32_t)dd_num_finite_tets(t));
    h = mix(h, (uint32_t)dd_memory_bytes(t));
    h = mix(h, (uint32_t)strlen(dd_errmsg(t)));
    dd_counters c;
    dd_get_counters(t, &c);
    h = mix(mix(h, (uint32_t)c.walk_steps), (uint32_t)c.tets_created);
    h = mix(mix(h, (uint32_t)c.orient_calls), (uint32_t)c.insphere_exact);
    dd_delete_stats ds;
    dd_last_delete_stats(t, &ds);
    h = mix(mix(h, ds.degree), (uint32_t)ds.tets_created);
    return h;
}

typedef struct job {
    const work *w;
    int id;
    uint64_t *items;          /* this thread's digest of each item        */
    uint64_t whole;           /* of the whole triangulation, round 0      */
    int later_differs;        /* a later round answered otherwise         */
} job;

static void *run_job(void *arg)
{
    job *j = arg;
    const work *w = j->w;
    const uint32_t start = (uint32_t)((uint64_t)w->nq * (uint32_t)j->id / NTHREADS);
    for (int r = 0; r < w->rounds; r++) {
        uint64_t whole = whole_digest(w->t, w);
        if (r == 0) j->whole = whole;
        else j->later_differs |= whole != j->whole;
        for (uint32_t k = 0; k < w->nq; k++) {
            const uint32_t i = (start + k) % w->nq;
            const uint64_t d = item_digest(w->t, w, i);
            if (r == 0) j->items[i] = d;
            else if (d != j->items[i]) j->later_differs = 1;
        }
    }
    return NULL;
}

/* Query points: uniform in the box of the points widened by a quarter
 * (some outside the hull), the points themselves, midpoints of pairs of
 * them (on the grid: on edges and facets), and one NaN.                 */
static double *make_queries(tl_rng *r, const double *pts, uint32_t n, uint32_t nq)
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], pts[3 * i + c]);
            hi[c] = fmax(hi[c], pts[3 * i + c]);
        }
    double *q = malloc(3 * (size_t)nq * sizeof *q);
    for (uint32_t i = 0; i < nq; i++) {
        double *p = q + 3 * (size_t)i;
        const uint32_t a = (uint32_t)tl_int(r, 0, n - 1), b = (uint32_t)tl_int(r, 0, n - 1);
        for (int c = 0; c < 3; c++) {
            const double ext = hi[c] - lo[c];
            switch (i % 3) {
            case 0: p[c] = lo[c] - ext / 8 + tl_unif(r) * ext * 1.25; break;
            case 1: p[c] = pts[3 * a + c]; break;
            default: p[c] = 0.5 * (pts[3 * a + c] + pts[3 * b + c]); break;
            }
        }
    }
    q[0] = NAN;
    return q;
}

/* Weights for the weighted sets: on the grid integers 0..2 (power ties),
 * elsewhere uniform up to three squared mean spacings (many hidden).   */
static double *make_weights(tl_rng *r, const char *name, uint32_t n)
{
    double *w = malloc((size_t)n * sizeof *w);
    const double h = pow((double)n, -1.0 / 3);
    for (uint32_t i = 0; i < n; i++)
        w[i] = !strcmp(name, "grid") ? (double)tl_int(r, 0, 2) : 3 * h * h * tl_unif(r);
    return w;
}

/* The reads of every thread against one thread's, on dataset `name`
 * (weighted: with weights, hidden points kept).                         */
static void run_set(tl_state *st, const char *name, uint32_t n, uint32_t nq, int rounds, int weighted)
{
    char msg[256], tn[128];
    double *pts = NULL;
    uint32_t np = 0;
    if (dd_gen(name, n, 7, &pts, &np, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, name, "dd_gen: %s", msg);
        return;
    }
    tl_rng r = {0x5EEDull + n};
    double *wt = weighted ? make_weights(&r, name, np) : NULL;
    dd_tri *t = NULL;
    dd_status s = dd_create_ex(&t, pts, wt, np, 0, msg, sizeof msg);
    const char *set = name;
    char wname[64];
    if (weighted) snprintf(wname, sizeof wname, "weighted-%s", name), set = wname;
    snprintf(tn, sizeof tn, "threads/%s/created", set);
    tl_check(st, s == DD_OK, tn, "dd_create: %s", msg);
    if (s != DD_OK) {
        free(pts);
        free(wt);
        return;
    }
    /* edits before the reads: deletions, a new point in a deleted slot,
     * new points past the input (weighted ones on a weighted t, some
     * hidden); a refused insertion sets dd_errmsg                       */
    for (uint32_t k = 0; k < np / 20; k++) (void)dd_delete(t, (uint32_t)tl_int(&r, 0, np - 1));
    for (uint32_t k = 0; k < 10; k++) {
        uint32_t idx;
        const uint32_t a = (uint32_t)tl_int(&r, 0, np - 1), b = (uint32_t)tl_int(&r, 0, np - 1);
        const double p[3] = {0.3 * pts[3 * a] + 0.7 * pts[3 * b], 0.3 * pts[3 * a + 1] + 0.7 * pts[3 * b + 1],
                             0.3 * pts[3 * a + 2] + 0.7 * pts[3 * b + 2]};
        if (weighted) (void)dd_insert_weighted(t, p, wt[a], &idx);
        else (void)dd_insert(t, p, &idx);
    }
    uint32_t idx;
    if (weighted) (void)dd_insert_weighted(t, pts, NAN, &idx);   /* refused: a message */
    else (void)dd_insert(t, pts, &idx);      /* refused if point 0 is a vertex: a message */

    work w = {t, make_queries(&r, pts, np, nq), nq, dd_num_input(t), rounds};
    /* one thread alone first */
    uint64_t *ref = malloc(nq * sizeof *ref);
    const uint64_t whole = whole_digest(t, &w);
    for (uint32_t i = 0; i < nq; i++) ref[i] = item_digest(t, &w, i);
    int32_t *before = NULL;
    size_t nbefore = 0;
    (void)dd_canonical(t, &before, &nbefore);
    dd_counters c0;
    dd_get_counters(t, &c0);
    char err0[256];
    snprintf(err0, sizeof err0, "%s", dd_errmsg(t));

    job jobs[NTHREADS];
    pthread_t th[NTHREADS];
    int started = 0;
    for (int k = 0; k < NTHREADS; k++) {
        jobs[k] = (job){&w, k, calloc(nq, sizeof(uint64_t)), 0, 0};
        if (pthread_create(&th[k], NULL, run_job, &jobs[k]) == 0) started++;
        else break;
    }
    for (int k = 0; k < started; k++) pthread_join(th[k], NULL);

    long bad_items = 0, bad_whole = 0;
    for (int k = 0; k < started; k++) {
        for (uint32_t i = 0; i < nq; i++) bad_items += jobs[k].items[i] != ref[i];
        bad_whole += jobs[k].whole != whole || jobs[k].later_differs;
    }
    snprintf(tn, sizeof tn, "threads/%s/same-answers", set);
    tl_check(st, started == NTHREADS && bad_items == 0 && bad_whole == 0, tn,
             "%d threads started; %ld of %ld item answers and %ld whole answers differ from one thread's",
             started, bad_items, (long)started * nq, bad_whole);

    int32_t *after = NULL;
    size_t nafter = 0;
    (void)dd_canonical(t, &after, &nafter);
    dd_counters c1;
    dd_get_counters(t, &c1);
    snprintf(tn, sizeof tn, "threads/%s/unchanged", set);
    tl_check(st, nafter == nbefore && !memcmp(before, after, 4 * nafter * sizeof *after) &&
                     !memcmp(&c0, &c1, sizeof c0) && !strcmp(err0, dd_errmsg(t)),
             tn, "the reads changed the triangulation, its counters (walk steps %llu, then %llu) or its message",
             (unsigned long long)c0.walk_steps, (unsigned long long)c1.walk_steps);

    /* the reads gave real answers: the NaN query refused, others located,
     * each vertex's degree its neighbours (and the infinite vertex on the
     * hull), at least 4, its cells 2 deg - 4 (the link is a sphere)        */
    long bad_star = 0;
    for (uint32_t v = 0; v < dd_num_input(t); v++) {
        if (!dd_is_vertex(t, v)) {
            bad_star += dd_degree(t, v) != 0 || dd_incident_cells(t, v, NULL, 0) != 0;
            continue;
        }
        const uint32_t deg = dd_degree(t, v), nn = dd_neighbors(t, v, NULL, 0);
        const uint32_t nc = dd_incident_cells(t, v, NULL, 0);
        bad_star += deg < 4 || deg != nn + (uint32_t)dd_on_hull(t, v) || nc != 2 * deg - 4;
    }
    snprintf(tn, sizeof tn, "threads/%s/stars", set);
    tl_check(st, bad_star == 0, tn, "%ld vertices with a wrong degree, neighbour or cell count", bad_star);
    int32_t cell[4];
    uint32_t nv = UINT32_MAX;
    snprintf(tn, sizeof tn, "threads/%s/statuses", set);
    tl_check(st, dd_locate(t, w.q, cell) == DD_ERR_NAN && dd_nearest_vertex(t, w.q, &nv) == DD_ERR_NAN &&
                     dd_locate(t, w.q + 3, cell) == DD_OK && dd_nearest_vertex(t, w.q + 3, &nv) == DD_OK &&
                     nv < dd_num_input(t) &&
                     dd_check(t) == DD_OK,
             tn, "%s", "NaN not refused, or a query not answered, or the check failed");

    if (weighted) {         /* the hidden-point reads had hidden points to meet */
        uint32_t *hid = NULL;
        size_t nh = 0, agree = 0, flagged = 0;
        const dd_status hs = dd_hidden(t, &hid, &nh);
        for (size_t k = 0; hs == DD_OK && k < nh; k++) agree += (size_t)dd_is_hidden(t, hid[k]);
        for (uint32_t i = 0; i < dd_num_input(t); i++) flagged += (size_t)dd_is_hidden(t, i);
        free(hid);
        snprintf(tn, sizeof tn, "threads/%s/hidden", set);
        tl_check(st, dd_is_weighted(t) && hs == DD_OK && nh > 0 && agree == nh && flagged == nh, tn,
                 "%s: %zu hidden listed, %zu of them dd_is_hidden, %zu flagged", dd_status_name(hs), nh, agree,
                 flagged);
    }

    for (int k = 0; k < started; k++) free(jobs[k].items);
    free(before);
    free(after);
    free(ref);
    free((void *)w.q);
    free(pts);
    free(wt);
    dd_free(t);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    const int small = argc > 1 && !strcmp(argv[1], "small");
    const uint32_t n = small ? 400 : 3000, nq = small ? 300 : 2000;
    const int rounds = small ? 1 : 2;
    run_set(&st, "uniform", n, nq, rounds, 0);
    run_set(&st, "grid", small ? 343 : 2744, nq, rounds, 0);
    run_set(&st, "sphere", n, nq, rounds, 0);
    run_set(&st, "cosphere", n, nq, rounds, 0);
    run_set(&st, "uniform", n, nq, rounds, 1);
    run_set(&st, "grid", small ? 343 : 2744, nq, rounds, 1);
    return tl_finish(&st);
}
