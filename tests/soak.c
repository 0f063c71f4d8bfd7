/*
 * soak.c -- `make soak`: a million deletions, each checked against CGAL,
 * and (soak_weighted.c, numbered after these cases) weighted deletions
 * and moves checked against CGAL's regular triangulation.
 *
 *   build/tests/soak [--scale F] [--jobs J] [--case K] [--weighted] [--seed S] [--quiet]
 *
 * Owns: the soak's case table and its driver.  Not part of `make test`
 * (it runs for tens of minutes at scale 1); SOAK_SCALE=F (or --scale)
 * multiplies the work, SOAK_SCALE=0.01 runs in minutes.
 *
 * A case is a dataset (every dd_gen name, real models included), a
 * transform of its coordinates and a mode:
 *  - transforms: none; times 1e16, 1e-16, 1e150, 1e-150, 1e300, 1e-300
 *    (not exact, but CGAL is given the same doubles); times 2^-1050, into
 *    the subnormals (rounded to multiples of 2^-1074: duplicates and
 *    degeneracies); mixed magnitudes, every other point times 1e-300 and
 *    the others times 1e300; centred and stretched to span nearly
 *    [-DBL_MAX, DBL_MAX] (coordinate differences overflow); translated by
 *    about 10^9 times the set's extent (rounded to the coordinates' new
 *    ulp), far from the origin.
 *  - modes: "seq", deletions one after another from DT(S), with now and
 *    then a set (dd_delete_set); "down", small random subsets (5 to 40
 *    points) deleted in random order down to the last 4 points, refusals
 *    (dimension drop) compared with CGAL's; "churn", deletions interleaved
 *    with insertions of new points (dd_insert, dd_cgal_insert: points
 *    held back from the set, coordinates of deleted points under new
 *    indices, and points equal to a vertex, which both must refuse) and
 *    with moves (dd_move, CGAL's move_if_no_collision: steps of up to
 *    the mean spacing, onto points held back or deleted, onto another
 *    vertex's point, which both must refuse, or onto the vertex's own).
 * Every deletion takes the next of the engine's strategies in turn
 * (dd_variant_name), so each takes a share.  Each deletion is checked
 * locally: the cells incident to the deleted vertex's neighbours (taken
 * before it goes) against CGAL's on the same neighbours; each insertion on
 * the cells of the new vertex.  At checkpoints (every 1000 operations of
 * a case, the end of each round, and after every deletion of "down") the
 * whole canonical form is compared with CGAL's and dd_check validates the
 * engine's triangulation.
 *
 * --jobs J forks J workers that take the cases from a queue, the dearest
 * first; the parent waits for them and sums.  The last line is "soak:
 * N deletions, I insertions, V moves, M mismatches".  On a mismatch the
 * worker names the case (dataset, transform, mode, seed), the round and
 * step, the variant and vertex, and the whole run exits 1; `--case K`
 * reruns that case alone.
 */
#include "dtdel.h"
#include "cgal/cgal_shim.h"
#include "datasets/datasets.h"
#include "soak.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define SOAK_BASE_QUOTA 3900.0  /* deletions of one case at scale 1   */
#define SOAK_CHECK_EVERY 1000   /* operations between full comparisons */
#define SOAK_MAX_JOBS 16

/* ---- the cases ------------------------------------------------------------ */

typedef enum { MODE_SEQ, MODE_DOWN, MODE_CHURN, NUM_MODES } soak_mode;
static const char *const mode_names[NUM_MODES] = {"seq", "down", "churn"};

const char *const soak_tf_names[NUM_TF] = {"x1",     "x1e16",     "x1e-16", "x1e150", "x1e-150", "far",
                                             "x1e300", "x1e-300", "x2^-1050", "mixed", "span"};

/* The unweighted dataset a weighted one's points come from, for the
 * sizes below: wmoment and whelix are the curves, wgrid a grid.        */
static const char *shape(const char *name)
{
    static const char *const w[][2] = {{"wmoment", "moment"}, {"whelix", "helix"}, {"wgrid", "grid"}};
    for (size_t i = 0; i < sizeof w / sizeof *w; i++)
        if (!strcmp(name, w[i][0])) return w[i][1];
    return name;
}

/* Largest set a case takes from a dataset: moment and helix have high
 * degrees (CGAL's remove() costs d^2 there), so their sets stay small.  */
static uint32_t dataset_cap(const char *name)
{
    name = shape(name);
    if (!strcmp(name, "moment")) return 96;
    if (!strcmp(name, "helix")) return 2000;
    if (!strcmp(name, "cosphere")) return 6000;
    return 50000;
}

/* Share of the base quota: moment and helix deletions cost CGAL and the
 * local check d^2 (d up to 95 and about 90 here), so they take fewer.  */
static double dataset_weight(const char *name)
{
    name = shape(name);
    return !strcmp(name, "moment") || !strcmp(name, "helix") ? 0.35 : 1.0;
}

/* Pool size for "down": small degenerate grids stay small so that their
 * subsets stay degenerate.                                              */
static uint32_t down_pool(const char *name)
{
    name = shape(name);
    if (!strcmp(name, "grid") || !strcmp(name, "grid-perturbed") || !strcmp(name, "layers")) return 64;
    if (!strcmp(name, "moment") || !strcmp(name, "cosphere")) return 60;
    return 400;
}

static size_t num_datasets(void)
{
    size_t n = 0;
    while (dd_dataset_name(n)) n++;
    return n;
}

static size_t num_unweighted(void) { return num_datasets() * NUM_TF * NUM_MODES; }
static size_t num_cases(void) { return num_unweighted() + soak_num_weighted(); }

/* Case k: the dataset varies fastest, then the mode, then the transform,
 * so that a worker taking every J-th case still meets all of them.     */
static soak_case make_case(size_t k, double scale, uint64_t seed)
{
    size_t nd = num_datasets();
    if (k >= num_unweighted()) return soak_weighted_case(k - num_unweighted(), (int)k, scale, seed);
    soak_case c;
    memset(&c, 0, sizeof c);
    c.index = (int)k;
    c.dataset = dd_dataset_name(k % nd);
    c.mode = (int)(k / nd % NUM_MODES);
    c.mode_name = mode_names[c.mode];
    c.tf = (soak_tf)(k / nd / NUM_MODES % NUM_TF);
    c.seed = seed * 1000003u + k;
    double q = SOAK_BASE_QUOTA * dataset_weight(c.dataset) * scale;
    c.quota = q < 12 ? 12 : (uint64_t)q;
    return c;
}

/* ---- the state of a worker ------------------------------------------------- */

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Reports a mismatch with everything needed to find it again. */
void soak_mismatch(soak *s, const char *fmt, ...)
{
    const soak_case *c = s->cs;
    s->st.mismatches++;
    printf("[w%d] MISMATCH case %d (dataset %s, transform %s, mode %s, seed %llu), round %llu, step %llu: ",
           s->worker, c->index, c->dataset, soak_tf_names[c->tf], c->mode_name,
           (unsigned long long)c->seed, (unsigned long long)s->round, (unsigned long long)s->step);
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n  rerun: build/tests/soak --case %d --scale %g --seed %llu\n", c->index, s->scale,
           (unsigned long long)s->seed);
    fflush(stdout);
}

/* Points of a dataset, at most n of them (models: all, copied).  The
 * caller frees *xyz.                                                     */
static int dataset_points(soak *s, const char *name, uint32_t n, uint64_t seed, double **xyz, uint32_t *np)
{
    char msg[256];
    for (size_t i = 0; i < s->nmodels; i++)
        if (!strcmp(s->model_name[i], name)) {
            *np = s->model_n[i];
            *xyz = malloc(3 * (size_t)*np * sizeof **xyz);
            if (!*xyz) return -1;
            memcpy(*xyz, s->model_xyz[i], 3 * (size_t)*np * sizeof **xyz);
            return 0;
        }
    dd_status st = dd_gen(name, n, seed, xyz, np, msg, sizeof msg);
    if (st != DD_OK) {
        printf("[w%d] cannot generate %s: %s\n", s->worker, name, msg);
        return -1;
    }
    return 0;
}

/* Real models are read from the CGAL data archive once per worker; the
 * weighted datasets are generated (dd_gen gives their points).          */
static int is_model(const char *name)
{
    if (dd_dataset_is_weighted(name)) return 0;
    static const char *const synthetic[] = {"moment", "helix", "uniform", "sphere", "grid",
                                            "cosphere", "layers", "grid-perturbed", NULL};
    for (size_t i = 0; synthetic[i]; i++)
        if (!strcmp(synthetic[i], name)) return 0;
    return 1;
}

static int load_models(soak *s)
{
    for (size_t i = 0; dd_dataset_name(i); i++) {
        const char *name = dd_dataset_name(i);
        if (!is_model(name) || s->nmodels == 32) continue;
        char msg[256];
        double *xyz;
        uint32_t np;
        if (dd_gen(name, 0, 1, &xyz, &np, msg, sizeof msg) != DD_OK) {
            printf("[w%d] cannot load model %s: %s\n", s->worker, name, msg);
            return -1;
        }
        s->model_name[s->nmodels] = name;
        s->model_xyz[s->nmodels] = xyz;
        s->model_n[s->nmodels] = np;
        s->nmodels++;
    }
    return 0;
}

/* w times f^2, as a squared length: +-DBL_MAX where that overflows. */
static double scale_weight(double w, double f)
{
    const double x = w * f * f;
    return w == 0 ? 0 : isfinite(x) ? x : copysign(DBL_MAX, w);
}

/* TF_SPAN moves the box's centre to 0 and its half-width (returned; 0
 * for a single point) to 0.9 DBL_MAX.                                    */
static double span_frame(const double *xyz, uint32_t n, double centre[3])
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, e = 0;
    for (size_t i = 0; i < 3 * (size_t)n; i++) lo[i % 3] = fmin(lo[i % 3], xyz[i]), hi[i % 3] = fmax(hi[i % 3], xyz[i]);
    for (int c = 0; c < 3; c++) e = fmax(e, 0.5 * (hi[c] - lo[c])), centre[c] = 0.5 * (lo[c] + hi[c]);
    return e;
}

void soak_transform(soak_tf tf, double *xyz, double *w, uint32_t n)
{
    double f = 1;
    switch (tf) {
    case TF_NONE: return;
    case TF_E16: f = 1e16; break;
    case TF_EM16: f = 1e-16; break;
    case TF_E150: f = 1e150; break;
    case TF_EM150: f = 1e-150; break;
    case TF_E300: f = 1e300; break;
    case TF_EM300: f = 1e-300; break;
    case TF_SUB: f = 0x1p-1050; break;
    case TF_MIXED:
        for (size_t i = 0; i < 3 * (size_t)n; i++) xyz[i] *= i / 3 % 2 ? 1e300 : 1e-300;
        for (size_t i = 0; w && i < n; i++) w[i] = scale_weight(w[i], i % 2 ? 1e300 : 1e-300);
        return;
    case TF_SPAN: {
        double centre[3];
        const double e = span_frame(xyz, n, centre);
        for (size_t i = 0; i < 3 * (size_t)n && e > 0; i++) xyz[i] = (xyz[i] - centre[i % 3]) / e * (0.9 * DBL_MAX);
        for (size_t i = 0; w && e > 0 && i < n; i++) w[i] = scale_weight(w[i], 0.9 * DBL_MAX / e);
        return;
    }
    case TF_FAR: {                                  /* weights unchanged: a translation */
        double e = 0;
        for (size_t i = 0; i < 3 * (size_t)n; i++) e = fmax(e, fabs(xyz[i]));
        int ex;
        frexp(e > 0 ? e : 1, &ex);
        double p2 = ldexp(1, ex);                   /* a power of two >= e */
        const double off[3] = {1e9 * p2, -1e9 * p2, 3e8 * p2};
        for (size_t i = 0; i < 3 * (size_t)n; i++) xyz[i] += off[i % 3];
        return;
    }
    default: return;
    }
    for (size_t i = 0; i < 3 * (size_t)n; i++) xyz[i] *= f;
    for (size_t i = 0; w && i < n; i++) w[i] = scale_weight(w[i], f);
}

/* Shuffles the n points and their weights (Fisher-Yates). */
void soak_shuffle(rng *r, double *xyz, double *w, uint32_t n)
{
    for (uint32_t i = n; i > 1; i--) {
        uint32_t j = below(r, i);
        double t[3];
        memcpy(t, xyz + 3 * (size_t)(i - 1), sizeof t);
        memcpy(xyz + 3 * (size_t)(i - 1), xyz + 3 * (size_t)j, sizeof t);
        memcpy(xyz + 3 * (size_t)j, t, sizeof t);
        if (w) {
            const double x = w[i - 1];
            w[i - 1] = w[j];
            w[j] = x;
        }
    }
}

/* ---- one triangulation on both sides ------------------------------------- */

typedef struct pair {
    dd_tri *t;
    dd_cgal *c;
    uint32_t *alive;         /* input indices of the vertices, any order */
    uint32_t nalive, cap;
    uint32_t *pos;           /* input index -> slot in alive, or UINT32_MAX */
    uint32_t npos;
    uint32_t *nb;            /* neighbour scratch */
    uint32_t nbcap;
    double *xyz;             /* the point of each input index so far */
    uint64_t ops;            /* since the last full comparison */
} pair;

static void pair_free(pair *p)
{
    dd_free(p->t);
    dd_cgal_free(p->c);
    free(p->alive);
    free(p->pos);
    free(p->nb);
    free(p->xyz);
    memset(p, 0, sizeof *p);
}

static int pair_grow(pair *p, uint32_t n)
{
    if (n <= p->cap) return 0;
    uint32_t cap = p->cap ? p->cap : 64;
    while (cap < n) cap *= 2;
    uint32_t *a = realloc(p->alive, cap * sizeof *a);
    if (!a) return -1;
    p->alive = a;
    uint32_t *q = realloc(p->pos, cap * sizeof *q);
    if (!q) return -1;
    p->pos = q;
    uint32_t *b = realloc(p->nb, 9 * (size_t)cap * sizeof *b);   /* sets: 8 lists */
    if (!b) return -1;
    p->nb = b;
    p->nbcap = 9 * cap;
    double *x = realloc(p->xyz, 3 * (size_t)cap * sizeof *x);
    if (!x) return -1;
    p->xyz = x;
    p->cap = cap;
    return 0;
}

static void alive_add(pair *p, uint32_t v)
{
    while (p->npos <= v) p->pos[p->npos++] = UINT32_MAX;
    p->pos[v] = p->nalive;
    p->alive[p->nalive++] = v;
}

static void alive_remove(pair *p, uint32_t v)
{
    uint32_t k = p->pos[v], last = p->alive[--p->nalive];
    p->alive[k] = last;
    p->pos[last] = k;
    p->pos[v] = UINT32_MAX;
}

/* Builds both triangulations.  1 if both refuse the set (the same way:
 * both fail), 0 if both built, -1 on a mismatch.                         */
static int pair_build(soak *s, pair *p, const double *xyz, uint32_t n)
{
    memset(p, 0, sizeof *p);
    char msg[256];
    dd_status st = dd_create(&p->t, xyz, n, msg, sizeof msg);
    p->c = dd_cgal_build(xyz, n);
    if ((st == DD_OK) != (p->c != NULL)) {
        soak_mismatch(s, "building DT of %u points: engine %s (%s), CGAL %s", n, dd_status_name(st),
                 st == DD_OK ? "" : msg, p->c ? "built it" : "refused");
        pair_free(p);
        return -1;
    }
    if (st != DD_OK) return 1;
    if (pair_grow(p, n + 16)) {
        soak_mismatch(s, "out of memory");
        return -1;
    }
    memcpy(p->xyz, xyz, 3 * (size_t)n * sizeof *xyz);
    for (uint32_t i = 0; i < n; i++) p->pos[i] = UINT32_MAX;
    p->npos = n;
    for (uint32_t i = 0; i < n; i++)
        if (dd_is_vertex(p->t, i)) alive_add(p, i);
    return 0;
}

static int same_tets(const int32_t *a, size_t na, const int32_t *b, size_t nb)
{
    return na == nb && (na == 0 || !memcmp(a, b, 4 * na * sizeof *a));
}

/* The first cell where two canonical lists differ, for the message. */
static void first_difference(const int32_t *a, size_t na, const int32_t *b, size_t nb, char *out, size_t len)
{
    size_t i = 0;
    while (i < na && i < nb && !memcmp(a + 4 * i, b + 4 * i, 4 * sizeof *a)) i++;
    if (i < na && i < nb)
        snprintf(out, len, "%zu vs %zu cells, first difference at %zu: engine %d %d %d %d, CGAL %d %d %d %d", na,
                 nb, i, a[4 * i], a[4 * i + 1], a[4 * i + 2], a[4 * i + 3], b[4 * i], b[4 * i + 1], b[4 * i + 2],
                 b[4 * i + 3]);
    else
        snprintf(out, len, "%zu vs %zu cells", na, nb);
}

/* The whole canonical form against CGAL's, and the validator. */
static int pair_full_check(soak *s, pair *p, const char *after)
{
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    s->st.checks++;
    p->ops = 0;
    if (dd_canonical(p->t, &a, &na) != DD_OK || dd_cgal_canonical(p->c, &b, &nb)) {
        soak_mismatch(s, "canonical form failed after %s", after);
        free(a);
        free(b);
        return -1;
    }
    int ok = same_tets(a, na, b, nb);
    if (!ok) {
        char d[256];
        first_difference(a, na, b, nb, d, sizeof d);
        soak_mismatch(s, "whole triangulation differs from CGAL's after %s: %s", after, d);
    }
    free(a);
    free(b);
    if (!ok) return -1;
    char why[256];
    dd_status st = dd_check_msg(p->t, why, sizeof why);
    if (st != DD_OK) {
        soak_mismatch(s, "dd_check after %s: %s: %s", after, dd_status_name(st), why);
        return -1;
    }
    return 0;
}

/* The cells incident to vs[0..n) on both sides. */
static int pair_local_check(soak *s, pair *p, const uint32_t *vs, size_t n, const char *after)
{
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    if (n == 0) return 0;
    dd_status st = dd_local_canonical(p->t, vs, n, &a, &na);
    int rc = dd_cgal_local_canonical(p->c, vs, n, &b, &nb);
    int ok = st == DD_OK && !rc && same_tets(a, na, b, nb);
    if (!ok) {
        char d[256];
        if (st != DD_OK || rc)
            snprintf(d, sizeof d, "engine %s, CGAL %s", dd_status_name(st), rc ? "failed" : "ok");
        else
            first_difference(a, na, b, nb, d, sizeof d);
        soak_mismatch(s, "cells around the %zu vertices differ after %s: %s", n, after, d);
    }
    free(a);
    free(b);
    return ok ? 0 : -1;
}

static int maybe_full_check(soak *s, pair *p, const char *after)
{
    if (++p->ops < SOAK_CHECK_EVERY) return 0;
    return pair_full_check(s, p, after);
}

/* Deletes input vertex v on both sides with the next strategy.  0 done,
 * 1 refused by both (dimension), -1 mismatch.                           */
static int pair_delete(soak *s, pair *p, uint32_t v)
{
    const char *var = s->variants[s->turn % s->nvariants];
    size_t vi = s->turn % s->nvariants;
    uint32_t k = dd_neighbors(p->t, v, p->nb, p->nbcap);
    if (k > p->nbcap) {
        soak_mismatch(s, "vertex %u has %u neighbours, more than the %u vertices", v, k, p->nbcap);
        return -1;
    }
    char what[96];
    snprintf(what, sizeof what, "deleting vertex %u with %s", v, var);
    dd_status st = dd_delete_with(p->t, v, var);
    int rc = dd_cgal_remove(p->c, v);
    if (st == DD_ERR_DIMENSION && rc) return 1;
    if (st != DD_OK || rc) {
        soak_mismatch(s, "%s: engine %s (%s), CGAL %s", what, dd_status_name(st), dd_errmsg(p->t),
                 rc ? "refused" : "removed it");
        return -1;
    }
    s->turn++;
    s->st.deletions++;
    s->st.per_variant[vi]++;
    alive_remove(p, v);
    if (pair_local_check(s, p, p->nb, k, what)) return -1;
    return maybe_full_check(s, p, what);
}

/* Deletes m random vertices as one set (dd_delete_set) on the engine's
 * side, one by one with CGAL's remove() on the other.                    */
static int pair_delete_set(soak *s, pair *p, rng *r, uint32_t m)
{
    const char *var = s->variants[s->turn % s->nvariants];
    size_t vi = s->turn % s->nvariants;
    uint32_t vs[16];
    for (uint32_t i = 0; i < m; i++) {
        uint32_t again;
        do {
            vs[i] = p->alive[below(r, p->nalive)];
            again = 0;
            for (uint32_t j = 0; j < i; j++) again |= vs[j] == vs[i];
        } while (again);
    }
    /* the union of their neighbours, the set itself left out */
    size_t nn = 0;
    for (uint32_t i = 0; i < m; i++) {
        uint32_t k = dd_neighbors(p->t, vs[i], p->nb + nn, (uint32_t)(p->nbcap - nn));
        if (nn + k > p->nbcap) {
            soak_mismatch(s, "neighbour lists overflow");
            return -1;
        }
        nn += k;
    }
    size_t u = 0;
    for (size_t i = 0; i < nn; i++) {
        int drop = 0;
        for (uint32_t j = 0; j < m; j++) drop |= p->nb[i] == vs[j];
        for (size_t j = 0; j < u && !drop; j++) drop |= p->nb[j] == p->nb[i];
        if (!drop) p->nb[u++] = p->nb[i];
    }
    char what[128];
    snprintf(what, sizeof what, "deleting the set of %u vertices %u, %u, ... with %s", m, vs[0], vs[1], var);
    dd_status st = dd_delete_set_with(p->t, vs, m, var);
    if (st != DD_OK) {
        soak_mismatch(s, "%s: engine %s (%s)", what, dd_status_name(st), dd_errmsg(p->t));
        return -1;
    }
    for (uint32_t i = 0; i < m; i++)
        if (dd_cgal_remove(p->c, vs[i])) {
            soak_mismatch(s, "%s: CGAL refused vertex %u", what, vs[i]);
            return -1;
        }
    s->turn++;
    s->st.deletions += m;
    s->st.per_variant[vi] += m;
    s->st.sets++;
    for (uint32_t i = 0; i < m; i++) alive_remove(p, vs[i]);
    if (pair_local_check(s, p, p->nb, u, what)) return -1;
    return maybe_full_check(s, p, what);
}

/* Inserts point q as a new vertex on both sides.  0 inserted, 1 refused
 * by both as equal to a vertex, -1 mismatch.                            */
static int pair_insert(soak *s, pair *p, const double q[3])
{
    uint32_t idx = UINT32_MAX, next = dd_num_input(p->t);
    char what[160];
    snprintf(what, sizeof what, "inserting (%.17g, %.17g, %.17g) as input %u", q[0], q[1], q[2], next);
    dd_status st = dd_insert(p->t, q, &idx);
    /* a new index, or a deleted vertex's (dd_insert reuses them) */
    const int fresh = idx == next || (idx < next && (idx >= p->npos || p->pos[idx] == UINT32_MAX));
    int rc = dd_cgal_insert(p->c, q, st == DD_OK && fresh ? idx : next);
    if (st == DD_ERR_DUPLICATE && rc == 2) return 1;
    if (st != DD_OK || rc != 0 || !fresh) {
        soak_mismatch(s, "%s: engine %s (%s) index %u, CGAL %s", what, dd_status_name(st), dd_errmsg(p->t), idx,
                 rc == 2 ? "found it equal to a vertex" : rc ? "failed" : "inserted it");
        return -1;
    }
    if (pair_grow(p, p->nalive + 1 > idx + 1 ? p->nalive + 1 : idx + 1)) {
        soak_mismatch(s, "out of memory");
        return -1;
    }
    memcpy(p->xyz + 3 * (size_t)idx, q, 3 * sizeof *q);
    alive_add(p, idx);
    s->st.insertions++;
    if (pair_local_check(s, p, &idx, 1, what)) return -1;
    return maybe_full_check(s, p, what);
}

/* Moves input vertex v to q on both sides (dd_move, CGAL's
 * move_if_no_collision).  0 moved, 1 refused by both the same way (q is
 * another vertex's point, or only coplanar points would remain), -1
 * mismatch.  Checks the cells around v and its neighbours, before the
 * move and after.                                                       */
static int pair_move(soak *s, pair *p, uint32_t v, const double q[3])
{
    char what[160];
    snprintf(what, sizeof what, "moving vertex %u to (%.17g, %.17g, %.17g)", v, q[0], q[1], q[2]);
    uint32_t k0 = dd_neighbors(p->t, v, p->nb, p->nbcap / 2);
    dd_status st = dd_move(p->t, v, q);
    int rc = dd_cgal_move(p->c, v, q);
    if ((st == DD_ERR_DUPLICATE && rc == 2) || (st == DD_ERR_DIMENSION && rc == 3)) return 1;
    if (st != DD_OK || rc != 0 || k0 > p->nbcap / 2) {
        soak_mismatch(s, "%s: engine %s (%s), CGAL %s", what, dd_status_name(st), dd_errmsg(p->t),
                 rc == 2 ? "found another vertex there" : rc == 3 ? "refused (coplanar)" : rc ? "failed" : "moved it");
        return -1;
    }
    memcpy(p->xyz + 3 * (size_t)v, q, 3 * sizeof *q);
    s->st.moves++;
    uint32_t k1 = dd_neighbors(p->t, v, p->nb + k0, p->nbcap / 2 - 1);
    if (k1 > p->nbcap / 2 - 1) {
        soak_mismatch(s, "%s: vertex %u has %u neighbours", what, v, k1);
        return -1;
    }
    p->nb[k0 + k1] = v;
    if (pair_local_check(s, p, p->nb, k0 + k1 + 1, what)) return -1;
    return maybe_full_check(s, p, what);
}

/* Where churn moves vertex v: by a step of about `h` per coordinate
 * (a fraction of the spacing), onto a point held back or deleted, onto
 * another vertex's point (refused by both) or onto its own (no change). */
static void move_target(rng *r, const pair *p, uint32_t v, double h, const double *spare, uint32_t nspare,
                        double q[3])
{
    const uint32_t coin = below(r, 100);
    const double *x = p->xyz + 3 * (size_t)v;
    if (coin < 70) {
        for (int c = 0; c < 3; c++) {
            q[c] = x[c] + h * ((double)below(r, 2001) / 1000.0 - 1.0);
            if (!isfinite(q[c])) q[c] = x[c];          /* a step past DBL_MAX */
        }
    } else if (coin < 85 && nspare > 0) {
        memcpy(q, spare + 3 * (size_t)below(r, nspare), 3 * sizeof *q);
    } else if (coin < 95) {
        memcpy(q, p->xyz + 3 * (size_t)p->alive[below(r, p->nalive)], 3 * sizeof *q);
    } else {
        memcpy(q, x, 3 * sizeof *q);
    }
}

/* Half the edge of the points' bounding box over the cube root of their
 * number: a step about the mean spacing.                                */
double soak_mean_spacing(const double *xyz, uint32_t n)
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, e = 0;
    for (uint32_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], xyz[3 * (size_t)i + c]);
            hi[c] = fmax(hi[c], xyz[3 * (size_t)i + c]);
        }
    for (int c = 0; c < 3; c++) e = fmax(e, 0.5 * hi[c] - 0.5 * lo[c]);   /* halves: no overflow */
    return e / cbrt(n > 0 ? n : 1);
}

/* ---- the modes ---------------------------------------------------------------- */

/* Picks n of the np points at random (order kept), in place. */
static uint32_t subset(rng *r, double *xyz, uint32_t np, uint32_t n)
{
    if (n >= np) return np;
    unsigned char *keep = calloc(np, 1);
    if (!keep) return np;
    for (uint32_t i = np - n; i < np; i++) {       /* Floyd's sampling */
        uint32_t j = below(r, i + 1);
        keep[keep[j] ? i : j] = 1;
    }
    uint32_t k = 0;
    for (uint32_t i = 0; i < np; i++)
        if (keep[i]) memmove(xyz + 3 * (size_t)k++, xyz + 3 * (size_t)i, 3 * sizeof *xyz);
    free(keep);
    return k;
}

static uint32_t set_size(const soak_case *c, uint64_t quota, uint32_t factor)
{
    uint64_t n = quota * factor;
    if (n < 1000) n = 1000;
    uint32_t cap = dataset_cap(c->dataset);
    return n > cap ? cap : (uint32_t)n;
}

/* seq: rounds of DT(S) with up to half of the vertices deleted one after
 * another, a set now and then.                                           */
static int run_seq(soak *s, const soak_case *c, rng *r)
{
    uint64_t done = 0;
    while (done < c->quota) {
        uint32_t want = set_size(c, c->quota, 6), np;
        double *xyz;
        if (dataset_points(s, c->dataset, want, c->seed + s->round, &xyz, &np)) return -1;
        np = subset(r, xyz, np, want);
        soak_transform(c->tf, xyz, NULL, np);
        pair p;
        int b = pair_build(s, &p, xyz, np);
        free(xyz);
        if (b < 0) return -1;
        if (b > 0) { soak_mismatch(s, "the set of %u points was refused by both", np); return -1; }
        uint64_t goal = p.nalive / 2;
        if (goal > c->quota - done) goal = c->quota - done;
        uint64_t start = s->st.deletions;
        for (s->step = 0; s->st.deletions - start < goal && p.nalive > 8; s->step++) {
            int rc;
            if (s->step % 32 == 5 && p.nalive > 64)
                rc = pair_delete_set(s, &p, r, 2 + below(r, 7));
            else
                rc = pair_delete(s, &p, p.alive[below(r, p.nalive)]);
            if (rc < 0) { pair_free(&p); return -1; }
        }
        int rc = pair_full_check(s, &p, "the end of the round");
        pair_free(&p);
        if (rc) return -1;
        done += s->st.deletions - start;
        s->round++;
    }
    return 0;
}

/* down: small subsets deleted in random order down to the last 4 points;
 * a deletion the engine refuses (dimension drop) CGAL must refuse too. */
static int run_down(soak *s, const soak_case *c, rng *r)
{
    uint64_t done = 0, tries = 0;
    double *reservoir;
    uint32_t npool;
    if (dataset_points(s, c->dataset, down_pool(c->dataset), c->seed, &reservoir, &npool)) return -1;
    soak_transform(c->tf, reservoir, NULL, npool);
    double *xyz = malloc(3 * 40 * sizeof *xyz);
    if (!xyz) { free(reservoir); return -1; }
    while (done < c->quota && tries++ < 100 * c->quota) {
        uint32_t k = 5 + below(r, 36);
        if (k > npool) k = npool;
        for (uint32_t i = 0; i < k; i++)       /* with repetition: duplicates too */
            memcpy(xyz + 3 * i, reservoir + 3 * (size_t)below(r, npool), 3 * sizeof *xyz);
        pair p;
        int b = pair_build(s, &p, xyz, k);
        if (b < 0) { free(reservoir); free(xyz); return -1; }
        if (b > 0) { s->round++; continue; }
        uint64_t start = s->st.deletions;
        s->step = 0;
        while (p.nalive > 4) {
            /* candidates in random order; the first one not refused goes */
            uint32_t n = p.nalive, order[40], gone = 0;
            for (uint32_t i = 0; i < n; i++) order[i] = p.alive[i];
            for (uint32_t i = n; i > 1; i--) {
                uint32_t j = below(r, i), t = order[i - 1];
                order[i - 1] = order[j];
                order[j] = t;
            }
            for (uint32_t i = 0; i < n && !gone; i++) {
                int rc = pair_delete(s, &p, order[i]);
                if (rc < 0) { pair_free(&p); free(reservoir); free(xyz); return -1; }
                if (rc == 0) gone = 1;
                else s->st.refusals++;
            }
            if (!gone) break;                    /* every deletion would drop the dimension */
            s->step++;
            if (pair_full_check(s, &p, "a deletion")) { pair_free(&p); free(reservoir); free(xyz); return -1; }
        }
        pair_free(&p);
        done += s->st.deletions - start;
        s->round++;
    }
    free(reservoir);
    free(xyz);
    return 0;
}

/* churn: deletions and insertions in turn at random; the inserted points
 * are held back from the set, or coordinates of deleted vertices (new
 * indices), or equal to a vertex (both must refuse).                     */
static int run_churn(soak *s, const soak_case *c, rng *r)
{
    uint64_t done = 0;
    while (done < c->quota) {
        uint32_t want = set_size(c, c->quota, 4), np;
        double *xyz;
        if (dataset_points(s, c->dataset, want, c->seed + s->round, &xyz, &np)) return -1;
        soak_shuffle(r, xyz, NULL, np);
        np = np > want ? want : np;
        soak_transform(c->tf, xyz, NULL, np);
        uint32_t n0 = np - np / 3;               /* the rest is held back */
        pair p;
        int b = pair_build(s, &p, xyz, n0);
        if (b != 0) {
            free(xyz);
            if (b > 0) soak_mismatch(s, "the set of %u points was refused by both", n0);
            return -1;
        }
        double *gone = malloc(3 * (size_t)np * sizeof *gone);   /* deleted points */
        uint32_t ngone = 0, next = n0;
        if (!gone) { pair_free(&p); free(xyz); return -1; }
        uint64_t goal = n0 / 2;
        if (goal > c->quota - done) goal = c->quota - done;
        const double h = soak_mean_spacing(xyz, n0);
        uint64_t start = s->st.deletions;
        for (s->step = 0; s->st.deletions - start < goal; s->step++) {
            int rc;
            uint32_t coin = below(r, 100);
            if (coin < 50 && p.nalive > 8) {
                uint32_t v = p.alive[below(r, p.nalive)];
                rc = pair_delete(s, &p, v);
                if (rc == 0 && ngone < np) memcpy(gone + 3 * (size_t)ngone++, p.xyz + 3 * (size_t)v, 3 * sizeof *gone);
            } else if (coin < 75) {
                double q[3];
                const uint32_t v = p.alive[below(r, p.nalive)];
                if (ngone > 0 && coin % 2)
                    move_target(r, &p, v, h / (1 + below(r, 20)), gone, ngone, q);
                else
                    move_target(r, &p, v, h / (1 + below(r, 20)), xyz + 3 * (size_t)next, np - next, q);
                rc = pair_move(s, &p, v, q);
            } else {
                double q[3];
                if (coin < 85 && next < np)
                    memcpy(q, xyz + 3 * (size_t)next++, sizeof q);
                else if (coin < 95 && ngone > 0)
                    memcpy(q, gone + 3 * (size_t)below(r, ngone), sizeof q);
                else
                    memcpy(q, p.xyz + 3 * (size_t)p.alive[below(r, p.nalive)], sizeof q);
                rc = pair_insert(s, &p, q);
            }
            if (rc < 0) { pair_free(&p); free(xyz); free(gone); return -1; }
        }
        int rc = pair_full_check(s, &p, "the end of the round");
        pair_free(&p);
        free(xyz);
        free(gone);
        if (rc) return -1;
        done += s->st.deletions - start;
        s->round++;
    }
    return 0;
}

static int run_case(soak *s, const soak_case *c)
{
    rng r = {c->seed};
    s->cs = c;
    s->round = 0;
    s->step = 0;
    uint64_t d0 = s->st.deletions, i0 = s->st.insertions, m0 = s->st.moves;
    double t0 = now_s();
    uint64_t w0 = 0, w1 = 0;
    for (int k = 0; k < NUM_WOPS; k++) w0 += s->st.wdone[k];
    int rc = c->weighted             ? soak_weighted_run(s, c, &r)
             : c->mode == MODE_SEQ  ? run_seq(s, c, &r)
             : c->mode == MODE_DOWN ? run_down(s, c, &r)
                                    : run_churn(s, c, &r);
    for (int k = 0; k < NUM_WOPS; k++) w1 += s->st.wdone[k];
    if ((!s->quiet || rc) && c->weighted)
        printf("[w%d] case %3d %-14s %-8s %-13s %7llu weighted operations %6.1f s%s\n", s->worker, c->index,
               c->dataset, soak_tf_names[c->tf], c->mode_name, (unsigned long long)(w1 - w0), now_s() - t0,
               rc ? "  FAILED" : "");
    else if (!s->quiet || rc)
        printf("[w%d] case %3d %-14s %-8s %-5s %7llu deletions %6llu insertions %6llu moves %6.1f s%s\n", s->worker,
               c->index, c->dataset, soak_tf_names[c->tf], c->mode_name, (unsigned long long)(s->st.deletions - d0),
               (unsigned long long)(s->st.insertions - i0), (unsigned long long)(s->st.moves - m0), now_s() - t0,
               rc ? "  FAILED" : "");
    fflush(stdout);
    return rc;
}

/* ---- workers ------------------------------------------------------------------ */

/* A rough cost of case k, to hand out the dearest first: a deletion on
 * moment or helix costs about 15 of another, under 1e+-150 (every
 * predicate exact) about 6.                                              */
static double case_cost(size_t k)
{
    soak_case c = make_case(k, 1, 1);
    if (c.weighted) return soak_weighted_cost(&c);
    double cost = (double)c.quota;
    if (!strcmp(shape(c.dataset), "moment") || !strcmp(shape(c.dataset), "helix")) cost *= 15;
    if (c.tf == TF_E150 || c.tf == TF_EM150) cost *= 6;
    return cost;
}

static int cmp_cost(const void *a, const void *b)
{
    double x = case_cost(*(const uint32_t *)a), y = case_cost(*(const uint32_t *)b);
    return x < y ? 1 : x > y ? -1 : (*(const uint32_t *)a > *(const uint32_t *)b) - (*(const uint32_t *)a < *(const uint32_t *)b);
}

/* Writes the case numbers to the queue, dearest first: the workers take
 * them one at a time (4-byte reads of a pipe filled before they start,
 * so each read takes one whole number), which keeps them busy to the end. */
static int fill_queue(int fd, long only, int weighted_only)
{
    size_t n = num_cases();
    uint32_t *order = malloc(n * sizeof *order);
    if (!order) return -1;
    for (size_t k = 0; k < n; k++) order[k] = (uint32_t)k;
    qsort(order, n, sizeof *order, cmp_cost);
    if (weighted_only) {                   /* the weighted cases, in the same order */
        size_t m = 0;
        for (size_t k = 0; k < n; k++)
            if (order[k] >= num_unweighted()) order[m++] = order[k];
        n = m;
    }
    if (only >= 0) {
        order[0] = (uint32_t)only;
        n = 1;
    }
    ssize_t w = write(fd, order, n * sizeof *order);
    free(order);
    return w == (ssize_t)(n * sizeof *order) ? 0 : -1;
}

/* Runs the cases taken from the queue until it is empty. */
static int run_worker(soak *s, double scale, uint64_t seed, int queue)
{
    if (load_models(s)) return -1;
    uint32_t k;
    while (read(queue, &k, sizeof k) == (ssize_t)sizeof k) {
        soak_case c = make_case(k, scale, seed);
        if (run_case(s, &c)) return -1;
    }
    return 0;
}

static void usage(void)
{
    fprintf(stderr, "usage: soak [--scale F] [--jobs J] [--case K] [--weighted] [--seed S] [--quiet]\n"
                    "  --weighted: only the weighted cases (soak_weighted.c)\n"
                    "  SOAK_SCALE=F in the environment is the default scale (1: about 10^6 deletions)\n");
}

int main(int argc, char **argv)
{
    double scale = 1;
    int jobs = 1, quiet = 0, weighted_only = 0;
    long only = -1;
    uint64_t seed = 1;
    const char *env = getenv("SOAK_SCALE");
    if (env && *env) scale = strtod(env, NULL);
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--scale") && i + 1 < argc) scale = strtod(argv[++i], NULL);
        else if (!strcmp(argv[i], "--jobs") && i + 1 < argc) jobs = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--case") && i + 1 < argc) only = atol(argv[++i]);
        else if (!strcmp(argv[i], "--seed") && i + 1 < argc) seed = strtoull(argv[++i], NULL, 10);
        else if (!strcmp(argv[i], "--quiet")) quiet = 1;
        else if (!strcmp(argv[i], "--weighted")) weighted_only = 1;
        else { usage(); return 2; }
    }
    if (!(scale > 0) || scale > 1000 || jobs < 1 || jobs > SOAK_MAX_JOBS || only >= (long)num_cases()) {
        usage();
        return 2;
    }
    if (only >= 0) jobs = 1;
    setvbuf(stdout, NULL, _IOLBF, 0);
    double t0 = now_s();
    printf("soak: scale %g, %zu cases, %d worker%s, %s\n", scale, only >= 0 ? (size_t)1 : weighted_only ? soak_num_weighted() : num_cases(), jobs,
           jobs > 1 ? "s" : "", dd_cgal_version());

    soak proto;
    memset(&proto, 0, sizeof proto);
    proto.quiet = quiet;
    proto.scale = scale;
    proto.seed = seed;
    while (proto.nvariants < SOAK_MAX_VARIANTS && dd_variant_name(proto.nvariants))
        proto.variants[proto.nvariants] = dd_variant_name(proto.nvariants), proto.nvariants++;

    /* the queue of cases; each worker writes its totals to the results
     * pipe as one binary record                                          */
    int fds[2], queue[2];
    if (pipe(fds) || pipe(queue)) { perror("soak: pipe"); return 1; }
    if (fill_queue(queue[1], only, weighted_only)) { perror("soak: queue"); return 1; }
    close(queue[1]);
    pid_t pids[SOAK_MAX_JOBS];
    for (int w = 0; w < jobs; w++) {
        pids[w] = fork();
        if (pids[w] < 0) { perror("soak: fork"); return 1; }
        if (pids[w] == 0) {
            close(fds[0]);
            soak s = proto;
            s.worker = w;
            s.turn = (uint64_t)w;     /* the workers start on different strategies */
            int rc = run_worker(&s, scale, seed, queue[0]);
            stats out = s.st;
            if (rc && out.mismatches == 0) out.mismatches = 1;   /* a failure to run counts */
            ssize_t wr = write(fds[1], &out, sizeof out);
            (void)wr;
            _exit(rc ? 1 : 0);
        }
    }
    close(fds[1]);
    close(queue[0]);
    int failed = 0;
    for (int left = jobs; left > 0; left--) {
        int ws;
        pid_t pid = wait(&ws);
        if (pid < 0) break;
        if (!WIFEXITED(ws) || WEXITSTATUS(ws) != 0) {
            if (!failed)
                for (int w = 0; w < jobs; w++)
                    if (pids[w] != pid) kill(pids[w], SIGTERM);   /* our own children */
            failed = 1;
        }
    }
    stats tot;
    memset(&tot, 0, sizeof tot);
    stats one;
    int got = 0;
    while (read(fds[0], &one, sizeof one) == (ssize_t)sizeof one) {
        got++;
        uint64_t a[sizeof one / sizeof(uint64_t)], b[sizeof one / sizeof(uint64_t)];
        memcpy(a, &tot, sizeof a);
        memcpy(b, &one, sizeof b);
        for (size_t i = 0; i < sizeof a / sizeof *a; i++) a[i] += b[i];
        memcpy(&tot, a, sizeof a);
    }
    if (got != jobs) failed = 1;
    if (failed && tot.mismatches == 0) tot.mismatches = 1;
    double secs = now_s() - t0;
    printf("soak: strategies' shares:");
    for (size_t v = 0; v < proto.nvariants; v++)
        printf(" %s %llu%s", proto.variants[v], (unsigned long long)tot.per_variant[v],
               v + 1 < proto.nvariants ? "," : "\n");
    printf("soak: %llu sets deleted by dd_delete_set, %llu refusals (dimension) matched, %llu whole-triangulation "
           "checks, %.0f s, %.0f deletions/s\n",
           (unsigned long long)tot.sets, (unsigned long long)tot.refusals, (unsigned long long)tot.checks, secs,
           (double)tot.deletions / (secs > 0 ? secs : 1));
    soak_weighted_report(&proto, &tot);
    printf("soak: %llu deletions, %llu insertions, %llu moves, %llu mismatches\n", (unsigned long long)tot.deletions,
           (unsigned long long)tot.insertions, (unsigned long long)tot.moves, (unsigned long long)tot.mismatches);
    return failed || tot.mismatches ? 1 : 0;
}
