/*
 * test_fault.c -- every allocation of every operation fails in turn, and
 * the triangulation survives (issue 46; as SQLite's malloc tests).
 *
 * For each operation, on small inputs: one run counts its allocations,
 * N (dd_test_control DD_TEST_ALLOC_COUNT); then for k = 1..N a fresh
 * triangulation runs it with the k-th allocation refused
 * (DD_TEST_ALLOC_FAIL), and the test checks that the call returns
 * DD_ERR_NOMEM, or succeeds with CGAL's result when it has a way that
 * needs no memory; that on DD_ERR_NOMEM the canonical form, the counts,
 * the vertices and their points are those from before and dd_check
 * passes; and that the same operation then succeeds and gives CGAL's
 * result (the shim's build, remove, insert, move).  The ASan build
 * ("small") checks that nothing leaks.  The operations: dd_create and
 * dd_create_ex; dd_delete_with for every strategy on a low-degree, a
 * hull and a high-degree vertex (the moment curve: degree n-1), the gift
 * wrap under each of its courses too (spoiled and narrower guesses,
 * scalar scans); dd_delete_set by both courses; dd_insert inside and
 * outside the hull; dd_reinsert; dd_move by the relocation filter, by
 * flips and by re-insertion; and the reads that allocate (dd_canonical,
 * dd_local_canonical, dd_cells, dd_nearest_vertex, dd_write: a refused
 * allocation leaves no file).
 *
 * GMP aborts when it cannot allocate, so no operation may make it
 * allocate after creation: the test installs GMP memory functions that
 * count, and checks that none of the calls above, nor the predicates on
 * points spread over the whole double range (where the GMP stages run,
 * with the largest numbers they can meet), calls them.
 *
 * Release builds have no injection: there the test runs each operation
 * once against CGAL, with the GMP count.  Prints "N injected failures
 * survived" at the end (a "#: " line: tests/run.sh shows it).
 */
#include "testlib.h"
#include "testcgal.h"
#include "geom/pred.h"
#include "dtdel/alloc.h"

#include <float.h>
#include <math.h>
#include <unistd.h>

static tl_state st = {0, 0};
static int small;
static long survived, fallbacks;

/* ---- GMP's allocations, counted ------------------------------------------- */

static unsigned long gmp_calls;

static void *gmp_alloc(size_t n)
{
    __atomic_add_fetch(&gmp_calls, 1, __ATOMIC_RELAXED);
    void *p = malloc(n);
    if (!p) abort();
    return p;
}

static void *gmp_realloc(void *p, size_t old, size_t n)
{
    (void)old;
    __atomic_add_fetch(&gmp_calls, 1, __ATOMIC_RELAXED);
    void *q = realloc(p, n);
    if (!q) abort();
    return q;
}

static void gmp_free(void *p, size_t n)
{
    (void)n;
    free(p);
}

/* ---- what can be observed of a triangulation --------------------------------- */

typedef struct snap {
    int32_t *tets;
    size_t ntets, ncells, nfinite;
    uint32_t ninput, nvert, ndup;
    double *pts;            /* ninput points, NAN where no vertex */
} snap;

static void snap_take(const dd_tri *t, snap *s)
{
    memset(s, 0, sizeof *s);
    if (dd_canonical(t, &s->tets, &s->ntets) != DD_OK) {
        fprintf(stderr, "dd_canonical failed without injection\n");
        exit(1);
    }
    s->ncells = dd_num_tets(t);
    s->nfinite = dd_num_finite_tets(t);
    s->ninput = dd_num_input(t);
    s->nvert = dd_num_vertices(t);
    s->ndup = dd_num_duplicates(t);
    s->pts = malloc(3 * ((size_t)s->ninput + 1) * sizeof *s->pts);
    for (uint32_t i = 0; i < s->ninput; i++)
        if (dd_point(t, i, s->pts + 3 * i) != DD_OK) s->pts[3 * i] = s->pts[3 * i + 1] = s->pts[3 * i + 2] = NAN;
}

static void snap_free(snap *s)
{
    free(s->tets);
    free(s->pts);
}

/* 1 when a and b are the same; else 0 and what differs in why. */
static int snap_same(const snap *a, const snap *b, char *why, size_t nwhy)
{
    if (a->ntets != b->ntets || memcmp(a->tets, b->tets, 4 * a->ntets * sizeof *a->tets)) {
        snprintf(why, nwhy, "canonical form changed (%zu cells, was %zu)", b->ntets, a->ntets);
        return 0;
    }
    if (a->ncells != b->ncells || a->nfinite != b->nfinite || a->ninput != b->ninput || a->nvert != b->nvert ||
        a->ndup != b->ndup) {
        snprintf(why, nwhy, "counts changed: cells %zu/%zu finite %zu/%zu input %u/%u vertices %u/%u dup %u/%u",
                 b->ncells, a->ncells, b->nfinite, a->nfinite, b->ninput, a->ninput, b->nvert, a->nvert, b->ndup,
                 a->ndup);
        return 0;
    }
    for (size_t i = 0; i < 3 * (size_t)a->ninput; i++)
        if (!(a->pts[i] == b->pts[i] || (isnan(a->pts[i]) && isnan(b->pts[i])))) {
            snprintf(why, nwhy, "vertex %zu changed", i / 3);
            return 0;
        }
    return 1;
}

static int same_tets(const int32_t *a, size_t na, const int32_t *b, size_t nb)
{
    return na == nb && !memcmp(a, b, 4 * na * sizeof *a);
}

/* ---- the operations ---------------------------------------------------------- */

typedef enum { OP_DELETE, OP_DELETE_SET, OP_INSERT, OP_REINSERT, OP_MOVE, OP_INSERT_FROM, OP_INSERT_MANY, OP_MOVE_MANY } op_kind;

typedef struct op {
    char name[128];
    op_kind kind;
    const double *pts;
    uint32_t np;
    uint32_t v;                 /* the vertex deleted, reinserted, moved  */
    const char *variant;        /* dd_delete_with, dd_delete_set_with     */
    double p[3];                /* dd_insert, dd_move                     */
    const uint32_t *set;        /* dd_delete_set, dd_move_many            */
    size_t nset;
    const double *batch;        /* dd_insert_many's points, dd_move_many's targets */
    size_t nbatch;
    dd_cell_id hint;            /* dd_insert_from                         */
    long set_course;            /* DD_TEST_SET_COURSE                     */
    tl_course course;           /* the wrap's                             */
    int move_course;            /* 1 filter, 2 flips, 3 re-insertion      */
    int warm;                   /* 1 + a vertex deleted and put back first,
                                   with the same strategy: the warm
                                   scratch grows instead of being made   */
} op;

static dd_tri *create(const double *p, uint32_t n)
{
    dd_tri *t;
    char msg[256];
    if (dd_create(&t, p, n, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "create: %s\n", msg);
        exit(1);
    }
    return t;
}

/* A fresh triangulation for o, set up for it: its controls, and for a
 * reinsertion the vertex deleted.                                         */
static dd_tri *fresh(const op *o)
{
    dd_tri *t = create(o->pts, o->np);
#ifdef DD_TEST_BUILD
    tl_set_course(t, o->course);
    dd_test_control(t, DD_TEST_SET_COURSE, o->set_course);
#endif
    if (o->warm && (dd_delete_with(t, (uint32_t)o->warm - 1, o->variant) != DD_OK ||
                    dd_reinsert(t, (uint32_t)o->warm - 1) != DD_OK)) {
        fprintf(stderr, "%s: the warm-up failed\n", o->name);
        exit(1);
    }
    if (o->kind == OP_REINSERT && dd_delete(t, o->v) != DD_OK) {
        fprintf(stderr, "%s: the deletion before the reinsertion failed\n", o->name);
        exit(1);
    }
    return t;
}

static dd_status run(dd_tri *t, const op *o, uint32_t *index)
{
    switch (o->kind) {
    case OP_DELETE: return dd_delete_with(t, o->v, o->variant);
    case OP_DELETE_SET: return dd_delete_set_with(t, o->set, o->nset, o->variant);
    case OP_INSERT: return dd_insert(t, o->p, index);
    case OP_REINSERT: return dd_reinsert(t, o->v);
    case OP_MOVE: return dd_move(t, o->v, o->p);
    case OP_INSERT_FROM: return dd_insert_from(t, o->p, o->hint, index);
    case OP_INSERT_MANY: {
        uint32_t idx[64];
        return dd_insert_many(t, o->batch, NULL, o->nbatch, idx, NULL);
    }
    case OP_MOVE_MANY: return dd_move_many(t, o->set, o->batch, NULL, o->nset);
    }
    return DD_ERR_INTERNAL;
}

/* CGAL's canonical form after o (index: what dd_insert returned). */
static void expected(const op *o, uint32_t index, int32_t **tets, size_t *n)
{
    double all[3 * 256];              /* the batch's result, built whole */
    if (o->kind == OP_INSERT_MANY || o->kind == OP_MOVE_MANY) {
        memcpy(all, o->pts, 3 * o->np * sizeof *all);
        if (o->kind == OP_INSERT_MANY) memcpy(all + 3 * o->np, o->batch, 3 * o->nbatch * sizeof *all);
        for (size_t k = 0; o->kind == OP_MOVE_MANY && k < o->nset; k++)
            memcpy(all + 3 * o->set[k], o->batch + 3 * k, 3 * sizeof *all);
    }
    const int whole = o->kind == OP_INSERT_MANY || o->kind == OP_MOVE_MANY;
    dd_cgal *c = whole ? dd_cgal_build(all, o->np + (uint32_t)(o->kind == OP_INSERT_MANY ? o->nbatch : 0))
                       : dd_cgal_build(o->pts, o->np);
    int ok = c != NULL;
    switch (o->kind) {
    case OP_DELETE: ok = ok && dd_cgal_remove(c, o->v) == 0; break;
    case OP_DELETE_SET:
        for (size_t k = 0; ok && k < o->nset; k++) ok = dd_cgal_remove(c, o->set[k]) == 0;
        break;
    case OP_INSERT:
    case OP_INSERT_FROM: ok = ok && dd_cgal_insert(c, o->p, index) == 0; break;
    case OP_INSERT_MANY:
    case OP_MOVE_MANY: break;                      /* built whole above */
    case OP_REINSERT: break;                       /* the points as given */
    case OP_MOVE: ok = ok && dd_cgal_move(c, o->v, o->p) == 0; break;
    }
    if (!ok || dd_cgal_canonical(c, tets, n) != 0) {
        fprintf(stderr, "%s: the CGAL reference failed\n", o->name);
        exit(1);
    }
    dd_cgal_free(c);
}

/* The course dd_move took on t: 1 filter, 2 flips, 3 re-insertion. */
static int move_course_of(const dd_counters *a, const dd_counters *b)
{
    return b->moves_kept > a->moves_kept ? 1 : b->moves_flipped > a->moves_flipped ? 2 : 3;
}

/* Runs o once on a fresh triangulation: CGAL's result, and GMP silent.
 * Returns the allocations it made (test builds; 0 in release ones),
 * or -1 after a failed check.                                           */
static long count_run(const op *o, int32_t **want, size_t *nwant)
{
    char tn[160], why[200] = "";
    dd_tri *t = fresh(o);
    dd_counters c0, c1;
    dd_get_counters(t, &c0);
    uint32_t index = UINT32_MAX;
    unsigned long g0 = gmp_calls;
#ifdef DD_TEST_BUILD
    dd_test_control(NULL, DD_TEST_ALLOC_COUNT, 0);
#endif
    dd_status s = run(t, o, &index);
    long n = 0;
#ifdef DD_TEST_BUILD
    n = dd_test_control(NULL, DD_TEST_ALLOC_COUNT, 0);
#endif
    unsigned long g = gmp_calls - g0;
    dd_get_counters(t, &c1);
    expected(o, index, want, nwant);
    int32_t *got = NULL;
    size_t ngot = 0;
    int ok = s == DD_OK && dd_canonical(t, &got, &ngot) == DD_OK && same_tets(got, ngot, *want, *nwant);
    if (!ok) snprintf(why, sizeof why, "status %s (%s), or not CGAL's", dd_status_name(s), dd_errmsg(t));
    if (ok && dd_check(t) != DD_OK) ok = 0, snprintf(why, sizeof why, "dd_check fails");
    if (ok && g) ok = 0, snprintf(why, sizeof why, "GMP allocated %lu times", g);
    if (ok && o->kind == OP_MOVE && move_course_of(&c0, &c1) != o->move_course)
        ok = 0, snprintf(why, sizeof why, "the move took course %d, not %d", move_course_of(&c0, &c1), o->move_course);
    snprintf(tn, sizeof tn, "fault/%s/plain", o->name);
    tl_check(&st, ok, tn, "%s", why);
    free(got);
    dd_free(t);
    return ok ? n : -1;
}

/* o with its k-th allocation refused, on a fresh triangulation. */
#ifdef DD_TEST_BUILD
static int inject(const op *o, long k, const int32_t *want, size_t nwant, char *why, size_t nwhy)
{
    dd_tri *t = fresh(o);
    snap before, after;
    snap_take(t, &before);
    uint32_t index = UINT32_MAX;
    dd_test_control(NULL, DD_TEST_ALLOC_FAIL, k);
    dd_status s = run(t, o, &index);
    long left = dd_test_control(NULL, DD_TEST_ALLOC_FAIL, 0);
    int ok = 1;
    int32_t *got = NULL;
    size_t ngot = 0;
    if (left > 0) {
        snprintf(why, nwhy, "allocation %ld never came (%ld short)", k, left);
        ok = 0;
    } else if (s == DD_ERR_NOMEM) {
        snap_take(t, &after);
        ok = snap_same(&before, &after, why, nwhy);
        snap_free(&after);
        if (ok && dd_check(t) != DD_OK) ok = 0, snprintf(why, nwhy, "dd_check fails after the failure");
        if (ok) {
            survived++;
            s = run(t, o, &index);
            ok = s == DD_OK && dd_canonical(t, &got, &ngot) == DD_OK && same_tets(got, ngot, want, nwant) &&
                 dd_check(t) == DD_OK;
            if (!ok) snprintf(why, nwhy, "the retry: %s (%s), or not CGAL's", dd_status_name(s), dd_errmsg(t));
        }
    } else if (s == DD_OK) {            /* a way that needed no memory */
        ok = dd_canonical(t, &got, &ngot) == DD_OK && same_tets(got, ngot, want, nwant) && dd_check(t) == DD_OK;
        if (!ok) snprintf(why, nwhy, "succeeded without CGAL's result");
        else survived++, fallbacks++;
    } else {
        snprintf(why, nwhy, "status %s (%s), not out of memory", dd_status_name(s), dd_errmsg(t));
        ok = 0;
    }
    free(got);
    snap_free(&before);
    dd_free(t);
    return ok;
}
#endif

static void fault_op(const op *o)
{
    int32_t *want = NULL;
    size_t nwant = 0;
    long n = count_run(o, &want, &nwant);
#ifdef DD_TEST_BUILD
    if (n > 0) {
        char tn[200], why[256] = "";
        long bad = 0, first = 0;
        for (long k = 1; k <= n; k++) {
            char w[256] = "";
            if (!inject(o, k, want, nwant, w, sizeof w)) {
                if (!bad++) first = k, memcpy(why, w, sizeof why);
            }
        }
        snprintf(tn, sizeof tn, "fault/%s/each-of-%ld", o->name, n);
        tl_check(&st, bad == 0, tn, "%ld of %ld failed; the first, allocation %ld: %s", bad, n, first, why);
    }
#else
    (void)n;
#endif
    free(want);
}

/* ---- dd_create ------------------------------------------------------------ */

/* ex: dd_create_ex; threads > 1: on that many threads, whose number of
 * allocations may differ from run to run (which points a thread puts
 * aside depends on the others' progress): a run that never reaches the
 * k-th must then succeed with CGAL's result.                           */
static void fault_create(const char *name, const double *p, uint32_t n, int ex, unsigned threads)
{
    const unsigned flags = DD_STABLE_INDICES | (threads > 1 ? DD_THREADS(threads) : 0);
    char tn[200], msg[256];
    dd_tri *t = NULL;
    unsigned long g0 = gmp_calls;
#ifdef DD_TEST_BUILD
    dd_test_control(NULL, DD_TEST_ALLOC_COUNT, 0);
#endif
    dd_status s = ex ? dd_create_ex(&t, p, NULL, n, flags, msg, sizeof msg) : dd_create(&t, p, n, msg, sizeof msg);
    long calls = 0;
#ifdef DD_TEST_BUILD
    calls = dd_test_control(NULL, DD_TEST_ALLOC_COUNT, 0);
#endif
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    dd_cgal *c = dd_cgal_build(p, n);
    int ok = s == DD_OK && c && dd_cgal_canonical(c, &b, &nb) == 0 && dd_canonical(t, &a, &na) == DD_OK &&
             same_tets(a, na, b, nb) && dd_check(t) == DD_OK && gmp_calls == g0;
    snprintf(tn, sizeof tn, "fault/%s/plain", name);
    tl_check(&st, ok, tn, "status %s (%s), not CGAL's, or GMP allocated", dd_status_name(s), msg);
    free(a);
    dd_free(t);
    dd_cgal_free(c);
#ifdef DD_TEST_BUILD
    char why[600] = "";
    long bad = 0, first = 0;
    for (long k = 1; ok && k <= calls; k++) {
        t = NULL;
        dd_test_control(NULL, DD_TEST_ALLOC_FAIL, k);
        s = ex ? dd_create_ex(&t, p, NULL, n, flags, msg, sizeof msg) : dd_create(&t, p, n, msg, sizeof msg);
        long left = dd_test_control(NULL, DD_TEST_ALLOC_FAIL, 0);
        int good;
        if (left > 0 && (threads < 2 || s != DD_OK))
            good = 0, snprintf(why, sizeof why, "allocation %ld never came", k);
        else if (s == DD_ERR_NOMEM) good = t == NULL, survived += good;
        else if (s == DD_OK) {
            good = dd_canonical(t, &a, &na) == DD_OK && same_tets(a, na, b, nb) && dd_check(t) == DD_OK;
            free(a);
            survived += good, fallbacks += good;
        } else good = 0;
        if (!good && !bad++) {
            first = k;
            if (left <= 0) snprintf(why, sizeof why, "status %s (%s), out %p", dd_status_name(s), msg, (void *)t);
        }
        dd_free(t);
    }
    snprintf(tn, sizeof tn, "fault/%s/each-of-%ld", name, calls);
    if (ok) tl_check(&st, bad == 0, tn, "%ld of %ld failed; the first, allocation %ld: %s", bad, calls, first, why);
#else
    (void)calls;
#endif
    free(b);
}

/* ---- the reads that allocate ----------------------------------------------- */

typedef enum { RD_CANONICAL, RD_LOCAL, RD_CELLS, RD_NEAREST, RD_WRITE, RD_LOCATE_MANY, RD_NEAREST_MANY, RD_NREADS } read_kind;
static const char *const read_name[RD_NREADS] = {"canonical", "local-canonical", "cells", "nearest", "write",
                                                 "locate-many", "nearest-many"};

/* Read r of t into a canonical-like list (for comparing answers). */
static dd_status do_read(const dd_tri *t, read_kind r, const char *path, int32_t **out, size_t *n)
{
    *out = NULL;
    *n = 0;
    dd_status s = DD_OK;
    switch (r) {
    case RD_CANONICAL: return dd_canonical(t, out, n);
    case RD_LOCAL: {
        uint32_t vs[3] = {1, 2, 5};
        return dd_local_canonical(t, vs, 3, out, n);
    }
    case RD_CELLS: {
        int32_t *v, *nb;
        s = dd_cells(t, &v, &nb, n);
        if (s == DD_OK) free(nb), *out = v;
        return s;
    }
    case RD_NEAREST: {
        const double q[3] = {0.3, 0.6, 0.2};
        uint32_t v;
        s = dd_nearest_vertex(t, q, &v);
        if (s == DD_OK) *out = malloc(4 * sizeof **out), (*out)[0] = (int32_t)v, *n = 1;
        return s;
    }
    case RD_WRITE: {                    /* DD_ERR_NOMEM leaves no file */
        unlink(path);
        s = dd_write(t, path);
        if (s == DD_ERR_NOMEM && access(path, F_OK) == 0) return DD_ERR_INTERNAL;
        if (s == DD_OK) {
            FILE *f = fopen(path, "rb");
            if (!f) return DD_ERR_IO;
            fseek(f, 0, SEEK_END);
            long len = ftell(f);
            fclose(f);
            *out = malloc(4 * sizeof **out);
            (*out)[0] = (int32_t)len;
            *n = 1;
        }
        return s;
    }
    case RD_LOCATE_MANY:
    case RD_NEAREST_MANY: {             /* 3000 queries: the radix sort's path */
        enum { Q = 3000 };
        double *q = malloc(3 * Q * sizeof *q);
        tl_rng qr = {23};
        for (int i = 0; i < 3 * Q; i++) q[i] = tl_unif(&qr);
        dd_cell_id *c = malloc(Q * sizeof *c);
        uint32_t *v = malloc(Q * sizeof *v);
        s = r == RD_LOCATE_MANY ? dd_locate_many(t, q, Q, c) : dd_nearest_many(t, q, Q, v);
        if (s == DD_OK) {
            *out = malloc(Q * sizeof **out);
            for (int i = 0; i < Q; i++) (*out)[i] = r == RD_LOCATE_MANY ? (int32_t)c[i] : (int32_t)v[i];
            *n = Q / 4;
        }
        free(q), free(c), free(v);
        return s;
    }
    default: return DD_ERR_INTERNAL;
    }
}

static void fault_reads(const double *p, uint32_t np)
{
    char path[64];
    snprintf(path, sizeof path, "/tmp/dtdel-fault-%d.vtu", (int)getpid());
    dd_tri *t = create(p, np);
    snap before, after;
    snap_take(t, &before);
    for (int r = 0; r < RD_NREADS; r++) {
        char tn[160], why[200] = "";
        int32_t *want, *got;
        size_t nwant, ngot;
        unsigned long g0 = gmp_calls;
#ifdef DD_TEST_BUILD
        dd_test_control(NULL, DD_TEST_ALLOC_COUNT, 0);
#endif
        dd_status s = do_read(t, (read_kind)r, path, &want, &nwant);
        long calls = 0;
#ifdef DD_TEST_BUILD
        calls = dd_test_control(NULL, DD_TEST_ALLOC_COUNT, 0);
#endif
        snprintf(tn, sizeof tn, "fault/read/%s/plain", read_name[r]);
        tl_check(&st, s == DD_OK && gmp_calls == g0, tn, "status %s, or GMP allocated", dd_status_name(s));
        long bad = 0, first = 0;
        for (long k = 1; k <= calls; k++) {
#ifdef DD_TEST_BUILD
            dd_test_control(NULL, DD_TEST_ALLOC_FAIL, k);
#endif
            s = do_read(t, (read_kind)r, path, &got, &ngot);
            long left = 0;
#ifdef DD_TEST_BUILD
            left = dd_test_control(NULL, DD_TEST_ALLOC_FAIL, 0);
#endif
            int good = left == 0 && (s == DD_ERR_NOMEM || (s == DD_OK && same_tets(got, ngot, want, nwant)));
            if (good && s == DD_OK) fallbacks++;
            free(got);
            snap_take(t, &after);
            good = good && snap_same(&before, &after, why, sizeof why) && dd_check(t) == DD_OK;
            snap_free(&after);
            survived += good;
            if (!good && !bad++) first = k;
        }
        if (calls) {
            snprintf(tn, sizeof tn, "fault/read/%s/each-of-%ld", read_name[r], calls);
            tl_check(&st, bad == 0, tn, "%ld of %ld failed; the first, allocation %ld %s", bad, calls, first, why);
        }
        free(want);
    }
    snap_free(&before);
    dd_free(t);
    unlink(path);
}

/* ---- the predicates over the whole double range: no GMP allocation ------- */

/* A double m 2^e, m of 1 to 53 random bits, e anywhere from the
 * subnormals to the largest.                                              */
static double wide(tl_rng *r)
{
    switch (tl_next(r) % 8) {
    case 0: return DBL_MAX * (tl_next(r) & 1 ? 1 : -1);
    case 1: return 0x1p-1074 * (double)(1 + tl_next(r) % 7) * (tl_next(r) & 1 ? 1 : -1);
    default: break;
    }
    double m = (double)(tl_next(r) >> 11) * 0x1p-53 + 0.5;
    int e = (int)tl_int(r, -1074, 1023);
    double x = ldexp(m, e);
    if (!isfinite(x) || x == 0) x = 0x1p-1074;
    return tl_next(r) & 1 ? x : -x;
}

static void predicates_wide(void)
{
    tl_rng r = {77};
    dd_pred reserved, plain;
    dd_pred_init(&reserved);
    dd_pred_init(&plain);
    if (dd_pred_reserve(&reserved) != DD_OK) exit(1);
    const int rounds = small ? 300 : 3000;
    int bad = 0;
    char why[200] = "";
    for (int i = 0; i < rounds; i++) {
        double x[5][3];
        for (int k = 0; k < 5; k++)
            for (int c = 0; c < 3; c++) x[k][c] = wide(&r);
        double f[4][3];                                 /* coplanar: z = 0 */
        for (int k = 0; k < 4; k++) f[k][0] = x[k][0], f[k][1] = x[k][1], f[k][2] = 0;
        dd_pred *ctx[2] = {&reserved, &plain};
        for (int j = 0; j < 2; j++) {
            int o = dd_orient3d(ctx[j], x[0], x[1], x[2], x[3]);
            int s = dd_insphere(ctx[j], x[0], x[1], x[2], x[3], x[4]);
            int co = dd_orient_coplanar(ctx[j], f[0], f[1], f[2]);
            int ci = co ? dd_incircle_coplanar(ctx[j], f[0], f[1], f[2], f[3]) : 0;
            int d = dd_compare_distance(ctx[j], x[0], x[1], x[2]);
            int wo = dd_cgal_orientation(x[0], x[1], x[2], x[3]);
            int ws = dd_cgal_side_of_oriented_sphere(x[0], x[1], x[2], x[3], x[4], 0);
            int wco = dd_cgal_coplanar_orientation(f[0], f[1], f[2]);
            int wci = co ? dd_cgal_coplanar_side_of_bounded_circle(f[0], f[1], f[2], f[3], 0) : 0;
            int wd = tl_cmp_dist_exact(x[0], x[1], x[2]);
            if ((o != wo || s != ws || co != wco || ci != wci || d != wd) && !bad++)
                snprintf(why, sizeof why, "round %d (%s): orient %d/%d insphere %d/%d coplanar %d/%d circle %d/%d dist %d/%d",
                         i, j ? "unreserved" : "reserved", o, wo, s, ws, co, wco, ci, wci, d, wd);
        }
    }
    tl_check(&st, bad == 0, "fault/gmp/predicates-agree", "%d wrong; %s", bad, why);
    /* the same calls again, the references apart: GMP must stay silent */
    r.s = 77;
    unsigned long g0 = gmp_calls;
    for (int i = 0; i < rounds; i++) {
        double x[5][3], f[4][3];
        for (int k = 0; k < 5; k++)
            for (int c = 0; c < 3; c++) x[k][c] = wide(&r);
        for (int k = 0; k < 4; k++) f[k][0] = x[k][0], f[k][1] = x[k][1], f[k][2] = 0;
        dd_pred *ctx[2] = {&reserved, &plain};
        for (int j = 0; j < 2; j++) {
            (void)dd_orient3d(ctx[j], x[0], x[1], x[2], x[3]);
            (void)dd_insphere(ctx[j], x[0], x[1], x[2], x[3], x[4]);
            (void)dd_insphere_perturbed(ctx[j], x[0], x[1], x[2], x[3], x[4]);
            if (dd_orient_coplanar(ctx[j], f[0], f[1], f[2]))
                (void)dd_incircle_coplanar_perturbed(ctx[j], f[0], f[1], f[2], f[3]);
            (void)dd_compare_distance(ctx[j], x[0], x[1], x[2]);
        }
    }
    unsigned long g = gmp_calls - g0;
    tl_check(&st, g == 0, "fault/gmp/predicates-allocate-nothing", "GMP allocated %lu times", g);
    dd_pred_clear(&reserved);
    dd_pred_clear(&plain);
}

/* Operations on points of mixed magnitudes, where the GMP stages run:
 * CGAL's result, and no GMP allocation (count_run checks both).         */
static void edits_wide(void)
{
    tl_rng r = {5};
    const uint32_t n = small ? 24 : 48;
    double *p = malloc(3 * (size_t)n * sizeof *p);
    for (uint32_t i = 0; i < 3 * n; i++) {
        double m = tl_unif(&r) + 0.5;
        p[i] = ldexp(m, (int)tl_int(&r, -60, 60) * 15) * (tl_next(&r) & 1 ? 1 : -1);
    }
    fault_create("wide/create", p, n, 0, 1);
    dd_tri *t = create(p, n);
    op o = {.kind = OP_DELETE, .pts = p, .np = n};
    for (uint32_t v = 0; v < 3; v++) {
        o.v = v;
        snprintf(o.name, sizeof o.name, "wide/delete-%u", v);
        fault_op(&o);
    }
    o.kind = OP_INSERT;
    o.p[0] = p[0] * 0.5 + p[3] * 0.25, o.p[1] = p[1] * 0.5 + p[7] * 0.5, o.p[2] = p[2] * 0.75 + p[11] * 0.25;
    snprintf(o.name, sizeof o.name, "wide/insert");
    fault_op(&o);
    o.kind = OP_MOVE;
    o.v = 3;
    o.move_course = 0;
    dd_counters c0, c1;
    dd_tri *u = create(p, n);
    dd_get_counters(u, &c0);
    dd_move(u, o.v, o.p);
    dd_get_counters(u, &c1);
    o.move_course = move_course_of(&c0, &c1);
    dd_free(u);
    snprintf(o.name, sizeof o.name, "wide/move");
    fault_op(&o);
    unsigned long g0 = gmp_calls;
    int32_t cell[4];
    uint32_t v;
    int ok = 1;
    for (uint32_t i = 0; i < n; i++) {
        const double q[3] = {p[3 * i] * 0.75, p[3 * i + 1] * 1.25, p[3 * i + 2] * 0.5};
        ok = ok && dd_locate(t, q, cell) == DD_OK && tl_holds(t, cell, q) && dd_nearest_vertex(t, q, &v) == DD_OK;
    }
    ok = ok && dd_check(t) == DD_OK;
    /* tl_holds asks CGAL, which may allocate: the count is of ours alone */
    unsigned long g = gmp_calls - g0;
    g0 = gmp_calls;
    for (uint32_t i = 0; i < n; i++) {
        const double q[3] = {p[3 * i] * 0.75, p[3 * i + 1] * 1.25, p[3 * i + 2] * 0.5};
        dd_cell_id c;
        ok = ok && dd_locate(t, q, cell) == DD_OK && dd_nearest_vertex(t, q, &v) == DD_OK &&
             dd_locate_from(t, q, -1, &c) == DD_OK;
    }
    ok = ok && dd_check(t) == DD_OK;
    g = gmp_calls - g0;
    tl_check(&st, ok && g == 0, "fault/wide/reads", "a read failed or was wrong, or GMP allocated %lu times", g);
    dd_free(t);
    free(p);
}

/* ---- choosing the cases ------------------------------------------------------ */

/* An interior vertex of least degree, and a hull vertex. */
static void pick_vertices(const double *p, uint32_t np, uint32_t *low, uint32_t *hull)
{
    dd_tri *t = create(p, np);
    uint32_t best = UINT32_MAX;
    *low = *hull = 0;
    for (uint32_t v = 0; v < np; v++) {
        if (dd_on_hull(t, v)) { *hull = v; continue; }
        if (dd_degree(t, v) < best) best = dd_degree(t, v), *low = v;
    }
    dd_free(t);
}

/* A move of a vertex by `course` (1 filter, 2 flips, 3 re-insertion):
 * tries vertices and steps until dd_move takes it.  0 when none found.  */
static int find_move(op *o, int course)
{
    static const double step[3] = {1e-9, 0.02, 0.5};
    tl_rng r = {(uint64_t)course * 31};
    for (int tries = 0; tries < 400; tries++) {
        dd_tri *t = create(o->pts, o->np);
        uint32_t v = (uint32_t)tl_int(&r, 0, o->np - 1);
        double q[3];
        if (dd_point(t, v, q) != DD_OK || dd_on_hull(t, v)) { dd_free(t); continue; }
        for (int c = 0; c < 3; c++) q[c] += step[course - 1] * (tl_unif(&r) - 0.5) * (1 + tries / 100);
        dd_counters c0, c1;
        dd_get_counters(t, &c0);
        dd_status s = dd_move(t, v, q);
        dd_get_counters(t, &c1);
        dd_free(t);
        if (s == DD_OK && move_course_of(&c0, &c1) == course) {
            o->v = v;
            memcpy(o->p, q, sizeof q);
            return 1;
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    small = argc > 1 && !strcmp(argv[1], "small");
    mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free);
    uint32_t nu, nm;
    double *uni = tl_gen("uniform", small ? 40 : 64, 3, &nu);
    double *mom = tl_gen("moment", small ? 24 : 40, 1, &nm);

    fault_create("create", uni, nu, 0, 1);
    fault_create("create-ex", uni, nu, 1, 1);
    fault_create("create/moment", mom, nm, 0, 1);
    uint32_t nbig;
    double *big = tl_gen("uniform", small ? 600 : 2000, 4, &nbig);
    fault_create("create/threads-2", big, nbig, 1, 2);
    fault_create("create/threads-3", big, nbig, 1, 3);
    free(big);

    uint32_t low, hull;
    pick_vertices(uni, nu, &low, &hull);
    op o;
    for (size_t vi = 0; dd_variant_name(vi); vi++) {
        const char *var = dd_variant_name(vi);
        memset(&o, 0, sizeof o);
        o.kind = OP_DELETE, o.variant = var, o.pts = uni, o.np = nu;
        o.v = low;
        snprintf(o.name, sizeof o.name, "delete/%s/low-degree", var);
        fault_op(&o);
        o.v = hull;
        snprintf(o.name, sizeof o.name, "delete/%s/hull", var);
        fault_op(&o);
        o.warm = 1 + low;                 /* scratch warmed on less */
        snprintf(o.name, sizeof o.name, "delete/%s/hull/warm", var);
        fault_op(&o);
        o.warm = 0;
        o.pts = mom, o.np = nm, o.v = nm / 2;
        snprintf(o.name, sizeof o.name, "delete/%s/degree-%u", var, nm - 1);
        fault_op(&o);
        o.warm = 1 + nm / 2 + 1;
        snprintf(o.name, sizeof o.name, "delete/%s/degree-%u/warm", var, nm - 1);
        fault_op(&o);
    }
    /* the wrap's courses on the high degree: its guesses refuted, its
     * scalar scans, its exact scans after spoiled passes                 */
    for (int c = 1; c < TL_NCOURSES; c++) {
#ifndef DD_TEST_BUILD
        break;
#endif
        memset(&o, 0, sizeof o);
        o.kind = OP_DELETE, o.variant = "gift-wrap", o.pts = mom, o.np = nm, o.v = nm / 2;
        o.course = (tl_course)c;
        snprintf(o.name, sizeof o.name, "delete/gift-wrap/degree-%u/%s", nm - 1, tl_course_name[c]);
        fault_op(&o);
    }

    uint32_t set[64];
    size_t nset = 0;
    for (uint32_t v = 1; v < nu && nset < 64; v += 3) set[nset++] = v;
    for (long course = 1; course <= 2; course++) {
#ifndef DD_TEST_BUILD
        if (course == 2) break;
#endif
        memset(&o, 0, sizeof o);
        o.kind = OP_DELETE_SET, o.pts = uni, o.np = nu, o.set = set, o.nset = nset, o.set_course = course;
        snprintf(o.name, sizeof o.name, "delete-set/%s", course == 1 ? "one-by-one" : "rebuild");
        fault_op(&o);
    }

    memset(&o, 0, sizeof o);
    o.kind = OP_INSERT, o.pts = uni, o.np = nu;
    o.p[0] = 0.43, o.p[1] = 0.51, o.p[2] = 0.47;
    snprintf(o.name, sizeof o.name, "insert/inside");
    fault_op(&o);
    o.p[0] = 1.7, o.p[1] = -0.4, o.p[2] = 0.5;
    snprintf(o.name, sizeof o.name, "insert/outside");
    fault_op(&o);

    memset(&o, 0, sizeof o);                 /* from a cell in conflict, from a far one */
    o.kind = OP_INSERT_FROM, o.pts = uni, o.np = nu;
    o.p[0] = 0.43, o.p[1] = 0.51, o.p[2] = 0.47;
    dd_tri *h = create(uni, nu);
    dd_locate_from(h, o.p, -1, &o.hint);
    snprintf(o.name, sizeof o.name, "insert-from/in-conflict");
    fault_op(&o);
    o.p[0] = 1.7, o.p[1] = -0.4, o.p[2] = 0.5;
    snprintf(o.name, sizeof o.name, "insert-from/far");
    fault_op(&o);
    dd_free(h);

    /* batches: 12 new points (2 outside the hull), then every third
     * vertex moved a little, two of them swapping places                */
    double batch[3 * 64];
    uint32_t mv[64];
    tl_rng br = {17};
    for (int k = 0; k < 12; k++)
        for (int c = 0; c < 3; c++) batch[3 * k + c] = k < 10 ? tl_unif(&br) : 1.3 + 0.1 * k + 0.2 * c;
    memset(&o, 0, sizeof o);
    o.kind = OP_INSERT_MANY, o.pts = uni, o.np = nu, o.batch = batch, o.nbatch = 12;
    snprintf(o.name, sizeof o.name, "insert-many");
    fault_op(&o);
    size_t nmv = 0;
    for (uint32_t v = 0; v < nu && nmv < 14; v += 3, nmv++) {
        mv[nmv] = v;
        for (int c = 0; c < 3; c++) batch[3 * nmv + c] = uni[3 * v + c] + 0.02 * (tl_unif(&br) - 0.5);
    }
    memcpy(batch + 3 * 4, uni + 3 * mv[5], 3 * sizeof *batch);
    memcpy(batch + 3 * 5, uni + 3 * mv[4], 3 * sizeof *batch);
    memset(&o, 0, sizeof o);
    o.kind = OP_MOVE_MANY, o.pts = uni, o.np = nu, o.set = mv, o.nset = nmv, o.batch = batch;
    snprintf(o.name, sizeof o.name, "move-many/with-a-swap");
    fault_op(&o);

    memset(&o, 0, sizeof o);
    o.kind = OP_REINSERT, o.pts = uni, o.np = nu, o.v = low;
    snprintf(o.name, sizeof o.name, "reinsert");
    fault_op(&o);

    static const char *const move_name[4] = {"", "filter", "flips", "reinsertion"};
    for (int course = 1; course <= 3; course++) {
        memset(&o, 0, sizeof o);
        o.kind = OP_MOVE, o.pts = uni, o.np = nu, o.move_course = course;
        char tn[64];
        snprintf(tn, sizeof tn, "fault/move/%s/found", move_name[course]);
        int found = find_move(&o, course);
        tl_check(&st, found, tn, "no move found that takes this course");
        if (!found) continue;
        snprintf(o.name, sizeof o.name, "move/%s", move_name[course]);
        fault_op(&o);
    }

    fault_reads(uni, nu);
    predicates_wide();
    edits_wide();

    printf("#: %ld injected failures survived (%ld of them by a way that needs no memory)%s\n", survived, fallbacks,
           dd_alloc_faults ? "" : "; a release build injects none");
#ifdef DD_TEST_BUILD
    tl_check(&st, survived > 0, "fault/survived", "no failure injected");
#endif
    free(uni);
    free(mom);
    return tl_finish(&st);
}
