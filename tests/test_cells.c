/*
 * test_cells.c -- the cell handles of dtdel.h, checked exactly:
 *  - dd_cell / dd_cell_end / dd_cell_alive agree with dd_cells (the same
 *    cells in slot order, the same vertices and neighbours), neighbours
 *    are symmetric through ids, dead and out-of-range ids are refused;
 *  - dd_locate_from, from no hint, good, far and infinite hints, holds
 *    its point (CGAL's exact orientations) and agrees with dd_locate on
 *    points inside cells; dead hints and bad points get their status;
 *  - dd_created_cells after every kind of edit: exactly the live cells
 *    that did not exist before for insertions and deletions (canonical
 *    sets before and after), and for every edit: listed cells alive and
 *    listed once, every live cell not listed unchanged under its id,
 *    every new cell listed; a failed edit leaves the list as it was;
 *  - a refinement loop whose queue is fed by dd_created_cells alone
 *    keeps the exact maximum and ends in CGAL's triangulation.
 */
#include "testlib.h"
#include "testcgal.h"
#include <math.h>
#include "dtdel.h"
#include "cgal/cgal_shim.h"
#include "bench/refine_rule.h"
#include "../datasets/datasets.h"

static int small;

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

static void sort4(int32_t *a)
{
    for (int i = 1; i < 4; i++)
        for (int j = i; j > 0 && a[j - 1] > a[j]; j--) {
            int32_t s = a[j];
            a[j] = a[j - 1];
            a[j - 1] = s;
        }
}

static int cmp_i4(const void *a, const void *b)
{
    const int32_t *x = a, *y = b;
    for (int i = 0; i < 4; i++)
        if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
    return 0;
}

/* ---- dd_cell against dd_cells ---------------------------------------------- */

static void check_cell_reads(tl_state *st, const char *name, dd_tri *t)
{
    char tn[128];
    int32_t *v, *nb;
    size_t nc;
    if (dd_cells(t, &v, &nb, &nc) != DD_OK) {
        snprintf(tn, sizeof tn, "cell/%s", name);
        tl_check(st, 0, tn, "dd_cells failed");
        return;
    }
    const dd_cell_id end = dd_cell_end(t);
    int64_t *number = malloc(((size_t)end + 1) * sizeof *number);
    size_t k = 0, dead = 0;
    long bad = 0, badstatus = 0, asym = 0;
    for (dd_cell_id c = 0; c < end; c++) {
        int32_t cv[4];
        dd_cell_id cn[4];
        if (!dd_cell_alive(t, c)) {
            number[c] = -1;
            dead++;
            badstatus += dd_cell(t, c, cv, cn) != DD_ERR_UNKNOWN_CELL;
            continue;
        }
        number[c] = (int64_t)k++;
    }
    for (dd_cell_id c = 0; c < end; c++) {
        if (number[c] < 0) continue;
        int32_t cv[4];
        dd_cell_id cn[4];
        if (dd_cell(t, c, cv, cn) != DD_OK) { bad++; continue; }
        const size_t m = (size_t)number[c];
        for (int i = 0; i < 4; i++) {
            bad += cv[i] != v[4 * m + i];
            bad += !dd_cell_alive(t, cn[i]) || number[cn[i]] != nb[4 * m + i];
            /* symmetric: the neighbour lists c across the facet of the
             * same three vertices                                         */
            int32_t dv[4];
            dd_cell_id dn[4];
            int back = 0;
            if (dd_cell(t, cn[i], dv, dn) == DD_OK)
                for (int j = 0; j < 4; j++) {
                    if (dn[j] != c) continue;
                    int shared = 0;
                    for (int a = 0; a < 4; a++)
                        for (int b = 0; b < 4; b++) shared += a != i && b != j && cv[a] == dv[b];
                    back |= shared == 3;
                }
            asym += !back;
        }
    }
    int32_t cv[4];
    badstatus += dd_cell(t, -1, cv, NULL) != DD_ERR_UNKNOWN_CELL || dd_cell(t, end, cv, NULL) != DD_ERR_UNKNOWN_CELL ||
                 dd_cell_alive(t, -1) || dd_cell_alive(t, end) || dd_cell_alive(t, INT64_MAX);
    snprintf(tn, sizeof tn, "cell/%s", name);
    tl_check(st, k == nc && k == dd_num_tets(t) && bad == 0 && asym == 0 && badstatus == 0, tn,
             "%zu live ids, dd_cells %zu; %ld differ, %ld facets without their partner, %ld bad statuses", k, nc, bad,
             asym, badstatus);
    snprintf(tn, sizeof tn, "cell/%s/dead-ids", name);
    tl_check(st, dead + k == (size_t)end, tn, "%zu dead + %zu live != %lld", dead, k, (long long)end);
    free(number), free(v), free(nb);
}

/* ---- dd_locate_from ------------------------------------------------------- */

/* Whether cell c holds p (as test_access's holds). */
static int holds(dd_tri *t, dd_cell_id c, const double *p)
{
    int32_t v[4];
    double x[4][3];
    int inf = -1;
    if (dd_cell(t, c, v, NULL) != DD_OK) return 0;
    for (int i = 0; i < 4; i++) {
        if (v[i] < 0) inf = i;
        else if (dd_point(t, (uint32_t)v[i], x[i]) != DD_OK) return 0;
    }
    for (int i = 0; i < 4; i++) {
        if (inf >= 0 && i != inf) continue;
        const double *q[4] = {x[0], x[1], x[2], x[3]};
        q[i] = p;
        if (dd_cgal_orientation(q[0], q[1], q[2], q[3]) < 0) return 0;
    }
    return 1;
}

static void check_locate_from(tl_state *st, const char *name, dd_tri *t, const double *pts, uint32_t n, uint64_t seed)
{
    char tn[128];
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) lo[c] = fmin(lo[c], pts[3 * i + c]), hi[c] = fmax(hi[c], pts[3 * i + c]);
    tl_rng r = {seed};
    const dd_cell_id end = dd_cell_end(t);
    dd_cell_id inf_cell = -1, dead = -1;
    for (dd_cell_id c = 0; c < end; c++) {
        int32_t v[4];
        if (dd_cell(t, c, v, NULL) != DD_OK) dead = c;
        else if (inf_cell < 0 && (v[0] < 0 || v[1] < 0 || v[2] < 0 || v[3] < 0)) inf_cell = c;
    }
    const char *kinds[] = {"vertex", "edge", "facet", "inside", "outside"};
    for (int kind = 0; kind < 5; kind++) {
        long bad = 0, differ = 0, done = 0;
        for (int q = 0; q < 80; q++) {
            dd_cell_id c;
            int32_t v[4];
            do c = tl_int(&r, 0, end - 1);
            while (dd_cell(t, c, v, NULL) != DD_OK || (kind <= 2 && (v[0] < 0 || v[1] < 0 || v[2] < 0 || v[3] < 0)));
            double a[3], b[3], d[3], p[3];
            if (kind <= 2) dd_point(t, (uint32_t)v[0], a), dd_point(t, (uint32_t)v[1], b), dd_point(t, (uint32_t)v[2], d);
            for (int i = 0; i < 3; i++) {
                const double u = tl_unif(&r);
                p[i] = kind == 0   ? a[i]
                       : kind == 1 ? 0.5 * (a[i] + b[i])
                       : kind == 2 ? 0.25 * (a[i] + b[i]) + 0.5 * d[i]
                       : kind == 3 ? lo[i] + u * (hi[i] - lo[i])
                                   : lo[i] - (hi[i] - lo[i]) + 3 * u * (hi[i] - lo[i]);
            }
            dd_cell_id got[4], far;
            do far = tl_int(&r, 0, end - 1);
            while (!dd_cell_alive(t, far));
            const dd_cell_id hints[4] = {-1, far, inf_cell, -2};
            for (int h = 0; h < 4; h++) {
                dd_cell_id hint = hints[h];
                if (h == 3) {                                  /* good: a neighbour of the answer */
                    dd_cell_id nb[4];
                    dd_cell(t, got[0], NULL, nb);
                    hint = nb[tl_int(&r, 0, 3)];
                }
                done++;
                if (dd_locate_from(t, p, hint, &got[h]) != DD_OK || !holds(t, got[h], p)) bad++;
            }
            if (kind == 3) {          /* inside a cell: one answer (or outside: any seen facet) */
                int32_t loc[4], mine[4];
                if (dd_locate(t, p, loc) == DD_OK && loc[0] >= 0 && loc[1] >= 0 && loc[2] >= 0 && loc[3] >= 0)
                    for (int h = 0; h < 4; h++) {
                        dd_cell(t, got[h], mine, NULL);
                        sort4(mine);
                        sort4(loc);
                        differ += cmp_i4(mine, loc) != 0;
                    }
            }
        }
        snprintf(tn, sizeof tn, "locate-from/%s/%s", name, kinds[kind]);
        tl_check(st, done > 0 && bad == 0 && differ == 0, tn,
                 "%ld of %ld located cells do not hold their point, %ld differ from dd_locate's", bad, done, differ);
    }
    const double p[3] = {0.5, 0.5, 0.5}, pn[3] = {NAN, 0, 0}, pi[3] = {0, INFINITY, 0};
    dd_cell_id c;
    snprintf(tn, sizeof tn, "locate-from/%s/refused", name);
    tl_check(st,
             (dead < 0 || dd_locate_from(t, p, dead, &c) == DD_ERR_UNKNOWN_CELL) &&
                 dd_locate_from(t, p, end, &c) == DD_ERR_UNKNOWN_CELL &&
                 dd_locate_from(t, p, -7, &c) == DD_ERR_UNKNOWN_CELL && dd_locate_from(t, pn, -1, &c) == DD_ERR_NAN &&
                 dd_locate_from(t, pi, -1, &c) == DD_ERR_INFINITE,
             tn, "a dead or out-of-range hint, or a NaN or infinite point, not refused with its status");
}

/* ---- created cells -------------------------------------------------------- */

/* What the cells were before an edit: per id its vertices (v[0] = -2:
 * dead), and the sorted canonical keys of the live ones.               */
typedef struct snapshot {
    dd_cell_id end;
    int32_t *v, *keys;
    size_t nkeys;
} snapshot;

static void take(dd_tri *t, snapshot *s)
{
    s->end = dd_cell_end(t);
    s->v = malloc(4 * ((size_t)s->end + 1) * sizeof *s->v);
    s->keys = malloc(4 * ((size_t)s->end + 1) * sizeof *s->keys);
    s->nkeys = 0;
    for (dd_cell_id c = 0; c < s->end; c++) {
        int32_t *v = s->v + 4 * c;
        if (dd_cell(t, c, v, NULL) != DD_OK) {
            v[0] = -2;
            continue;
        }
        int32_t *k = s->keys + 4 * s->nkeys++;
        memcpy(k, v, 4 * sizeof *k);
        sort4(k);
    }
    qsort(s->keys, s->nkeys, 4 * sizeof *s->keys, cmp_i4);
}

static void drop(snapshot *s)
{
    free(s->v), free(s->keys);
}

static int existed(const snapshot *s, const int32_t v[4])
{
    int32_t k[4];
    memcpy(k, v, sizeof k);
    sort4(k);
    return bsearch(k, s->keys, s->nkeys, 4 * sizeof *k, cmp_i4) != NULL;
}

/* The list after an edit against the snapshot before it.  exact: the
 * list is exactly the live cells whose vertex set is new.               */
static void check_created(tl_state *st, const char *name, dd_tri *t, const snapshot *b, int exact)
{
    const dd_cell_id *cells;
    size_t n;
    const dd_cell_id end = dd_cell_end(t);
    unsigned char *listed = calloc((size_t)end + 1, 1);
    long notalive = 0, twice = 0, changed = 0, missing = 0, old = 0;
    const dd_status s = dd_created_cells(t, &cells, &n);
    for (size_t k = 0; k < n; k++) {
        if (!dd_cell_alive(t, cells[k])) { notalive++; continue; }
        twice += listed[cells[k]];
        listed[cells[k]] = 1;
    }
    for (dd_cell_id c = 0; c < end; c++) {
        int32_t v[4];
        if (dd_cell(t, c, v, NULL) != DD_OK) continue;
        const int is_new = !existed(b, v);
        if (listed[c]) {
            old += exact && !is_new;
            continue;
        }
        missing += is_new;
        changed += c >= b->end || memcmp(v, b->v + 4 * c, sizeof v) != 0;
    }
    tl_check(st, s == DD_OK && notalive == 0 && twice == 0 && changed == 0 && missing == 0 && old == 0 &&
                     dd_check(t) == DD_OK,
             name,
             "status %d; listed: %ld dead, %ld twice, %ld old; not listed: %ld changed under their id, %ld new; "
             "dd_check %d",
             s, notalive, twice, old, changed, missing, dd_check(t));
    free(listed);
}

/* The list (ids and count) unchanged since `was`. */
static int same_list(dd_tri *t, const dd_cell_id *was, size_t nwas)
{
    const dd_cell_id *cells;
    size_t n;
    return dd_created_cells(t, &cells, &n) == DD_OK && n == nwas && !memcmp(cells, was, n * sizeof *cells);
}

static dd_cell_id *copy_list(dd_tri *t, size_t *n)
{
    const dd_cell_id *cells;
    dd_created_cells(t, &cells, n);
    dd_cell_id *c = malloc((*n + 1) * sizeof *c);
    memcpy(c, cells, *n * sizeof *c);
    return c;
}

static void check_edits(tl_state *st, uint64_t seed)
{
    uint32_t n0 = small ? 400 : 3000, np;
    double *pts = tl_gen("uniform", n0, seed, &np);
    dd_tri *t = create(pts, np);
    char tn[128];
    {
        const dd_cell_id *cells;
        size_t n;
        long bad = 0;
        dd_created_cells(t, &cells, &n);
        for (size_t k = 0; k < n; k++) bad += !dd_cell_alive(t, cells[k]) || (k && cells[k] <= cells[k - 1]);
        tl_check(st, n == dd_num_tets(t) && bad == 0, "created/create", "%zu listed of %zu cells, %ld bad", n,
                 dd_num_tets(t), bad);
    }
    tl_rng r = {seed * 7 + 1};
    long fails = 0;
    uint32_t deleted[64], nd = 0;
    snapshot b;
    /* insertions, deletions with every strategy, re-insertions */
    for (int k = 0; k < 12; k++) {
        double p[3] = {tl_unif(&r), tl_unif(&r), tl_unif(&r)};
        uint32_t idx;
        take(t, &b);
        fails += dd_insert(t, p, &idx) != DD_OK;
        snprintf(tn, sizeof tn, "created/insert/%d", k);
        check_created(st, tn, t, &b, 1);
        drop(&b);
    }
    tl_courses courses = tl_courses_all();
    for (size_t vi = 0; dd_variant_name(vi); vi++)
        for (int k = 0; k < 3; k++) {
            uint32_t v;
            do v = (uint32_t)tl_int(&r, 0, np - 1);
            while (!dd_is_vertex(t, v));
            tl_course_next(&courses, t);
            take(t, &b);
            fails += dd_delete_with(t, v, dd_variant_name(vi)) != DD_OK;
            deleted[nd++] = v;
            snprintf(tn, sizeof tn, "created/delete/%s/%d", dd_variant_name(vi), k);
            check_created(st, tn, t, &b, 1);
            drop(&b);
        }
    for (int k = 0; k < 6; k++) {
        take(t, &b);
        fails += dd_reinsert(t, deleted[--nd]) != DD_OK;
        snprintf(tn, sizeof tn, "created/reinsert/%d", k);
        check_created(st, tn, t, &b, 1);
        drop(&b);
    }
    /* failed edits: the list stays */
    {
        size_t nwas;
        dd_cell_id *was = copy_list(t, &nwas);
        double p[3], nanp[3] = {NAN, 0, 0};
        uint32_t idx, other = 0;
        while (!dd_is_vertex(t, other)) other++;
        dd_point(t, other, p);
        int ok = dd_delete(t, deleted[0]) == DD_ERR_UNKNOWN_VERTEX && same_list(t, was, nwas);
        ok &= dd_insert(t, p, &idx) == DD_ERR_DUPLICATE && same_list(t, was, nwas);
        ok &= dd_insert(t, nanp, &idx) == DD_ERR_NAN && same_list(t, was, nwas);
        ok &= dd_delete_with(t, other, "no-such-variant") == DD_ERR_UNKNOWN_VARIANT && same_list(t, was, nwas);
        uint32_t v = other + 1;
        while (!dd_is_vertex(t, v)) v++;
        ok &= dd_move(t, v, p) == DD_ERR_DUPLICATE && same_list(t, was, nwas);
        tl_check(st, ok && nwas > 0, "created/failed-edits-keep-the-list", "a failed edit changed the list");
        free(was);
    }
    /* moves: small steps (kept or flipped), large ones (re-inserted) */
    for (int k = 0; k < 24; k++) {
        uint32_t v;
        do v = (uint32_t)tl_int(&r, 0, np - 1);
        while (!dd_is_vertex(t, v));
        double p[3];
        dd_point(t, v, p);
        const double h = k < 16 ? 0.02 * cbrt(1.0 / np) * (k % 4 + 1) : 0.3;
        for (int c = 0; c < 3; c++) p[c] += h * (2 * tl_unif(&r) - 1);
        take(t, &b);
        fails += dd_move(t, v, p) != DD_OK;
        snprintf(tn, sizeof tn, "created/move/%s/%d", k < 16 ? "small" : "large", k);
        check_created(st, tn, t, &b, 0);
        drop(&b);
    }
    /* sets: one at a time (a few), and by rebuilding (half) */
    for (int big = 0; big < 2; big++) {
        uint32_t want = big ? dd_num_vertices(t) / 2 : 8, *vs = malloc(want * sizeof *vs), m = 0;
        unsigned char *used = calloc(np + 64, 1);
        while (m < want) {
            uint32_t v = (uint32_t)tl_int(&r, 0, dd_num_input(t) - 1);
            if (dd_is_vertex(t, v) && !used[v]) used[v] = 1, vs[m++] = v;
        }
        take(t, &b);
        fails += dd_delete_set(t, vs, m) != DD_OK;
        snprintf(tn, sizeof tn, "created/delete-set/%s", big ? "rebuild" : "one-at-a-time");
        check_created(st, tn, t, &b, !big);
        if (big) {
            const dd_cell_id *cells;
            size_t n;
            dd_created_cells(t, &cells, &n);
            tl_check(st, n == dd_num_tets(t), "created/delete-set/rebuild-lists-all", "%zu of %zu", n, dd_num_tets(t));
        }
        drop(&b);
        free(vs), free(used);
    }
    tl_check(st, fails == 0, "created/edits-succeed", "%ld edits failed", fails);
    check_cell_reads(st, "after-edits", t);
    check_locate_from(st, "after-edits", t, pts, np, seed);
    dd_free(t);
    free(pts);
}

/* ---- a refinement loop on created cells ------------------------------------ */

typedef struct qentry {
    double r2, p[3];
    int32_t v[4];
    dd_cell_id c;
    uint32_t stamp;
} qentry;

typedef struct queue {
    qentry *a;
    size_t n, cap;
} queue;

static int qbefore(const qentry *x, const qentry *y) { return refine_before(x->r2, x->v, y->r2, y->v); }

static void qpush(queue *q, const qentry *e)
{
    if (q->n == q->cap) q->a = realloc(q->a, (q->cap = q->cap ? 2 * q->cap : 1024) * sizeof *q->a);
    size_t i = q->n++;
    while (i > 0 && qbefore(e, &q->a[(i - 1) / 2])) q->a[i] = q->a[(i - 1) / 2], i = (i - 1) / 2;
    q->a[i] = *e;
}

static qentry qpop(queue *q)
{
    qentry top = q->a[0], last = q->a[--q->n];
    size_t i = 0;
    for (;;) {
        size_t k = 2 * i + 1;
        if (k >= q->n) break;
        if (k + 1 < q->n && qbefore(&q->a[k + 1], &q->a[k])) k++;
        if (!qbefore(&q->a[k], &last)) break;
        q->a[i] = q->a[k], i = k;
    }
    if (q->n) q->a[i] = last;
    return top;
}

static const double unit_lo[3] = {0, 0, 0}, unit_hi[3] = {1, 1, 1};

/* Cell c as a queue entry; 0 if the rule does not queue it. */
static int entry_of(dd_tri *t, const double *pts, dd_cell_id c, qentry *e)
{
    if (dd_cell(t, c, e->v, NULL) != DD_OK || e->v[0] < 0 || e->v[1] < 0 || e->v[2] < 0 || e->v[3] < 0) return 0;
    sort4(e->v);
    const double *q[4];
    for (int i = 0; i < 4; i++) q[i] = pts + 3 * (size_t)e->v[i];
    e->c = c;
    return refine_rule(q, unit_lo, unit_hi, e->p, &e->r2);
}

static void check_refinement(tl_state *st, uint64_t seed)
{
    uint32_t n0 = small ? 300 : 2000, k = small ? 150 : 1500, np;
    double *pts = tl_gen("uniform", n0, seed, &np);
    pts = realloc(pts, 3 * ((size_t)np + k) * sizeof *pts);
    dd_tri *t = create(pts, np);
    queue q = {0};
    uint32_t *stamp = NULL, gen_ = 0, done = 0;
    size_t capst = 0;
    long notmax = 0, checks = 0, fails = 0;
    for (;;) {
        const dd_cell_id *cells;
        size_t n;
        if (dd_created_cells(t, &cells, &n) != DD_OK) { fails++; break; }
        if ((size_t)dd_cell_end(t) > capst) stamp = realloc(stamp, (capst = 2 * (size_t)dd_cell_end(t)) * sizeof *stamp);
        for (size_t j = 0; j < n; j++) {
            qentry e;
            stamp[cells[j]] = ++gen_;
            e.stamp = gen_;
            if (entry_of(t, pts, cells[j], &e)) qpush(&q, &e);
        }
        while (q.n > 0 && (!dd_cell_alive(t, q.a[0].c) || stamp[q.a[0].c] != q.a[0].stamp)) qpop(&q);
        if (done == k || q.n == 0) break;
        if (done % (small ? 25 : 100) == 0) {          /* the queue's top is the true maximum */
            qentry best = {0}, e;
            int have = 0;
            for (dd_cell_id c = 0; c < dd_cell_end(t); c++)
                if (entry_of(t, pts, c, &e) && (!have || qbefore(&e, &best))) best = e, have = 1;
            checks++;
            notmax += !have || best.c != q.a[0].c;
        }
        const qentry e = qpop(&q);
        uint32_t idx;
        const dd_status s = dd_insert(t, e.p, &idx);
        if (s == DD_ERR_DUPLICATE) continue;
        if (s != DD_OK || idx != np + done) { fails++; break; }
        memcpy(pts + 3 * (size_t)idx, e.p, sizeof e.p);
        done++;
    }
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    dd_cgal *g = dd_cgal_build(pts, np + done);
    const int same = g && dd_canonical(t, &a, &na) == DD_OK && !dd_cgal_canonical(g, &b, &nb) && na == nb &&
                     !memcmp(a, b, 4 * na * sizeof *a);
    tl_check(st, same && fails == 0 && notmax == 0 && done == k && dd_check(t) == DD_OK, "refine/created-cells-queue",
             "%u of %u inserted, %ld failures, queue top not the maximum %ld of %ld times, equal to CGAL %d", done, k,
             fails, notmax, checks, same);
    dd_cgal_free(g);
    free(a), free(b), free(q.a), free(stamp), free(pts);
    dd_free(t);
}

int main(int argc, char **argv)
{
    small = argc > 1 && !strcmp(argv[1], "small");
    tl_state st = {0, 0};
    uint32_t np;
    const char *sets[] = {"uniform", "grid", "cosphere"};
    for (int i = 0; i < 3; i++) {
        double *pts = tl_gen(sets[i], small ? 300 : 2000, 5, &np);
        dd_tri *t = create(pts, np);
        check_cell_reads(&st, sets[i], t);
        check_locate_from(&st, sets[i], t, pts, np, 11 + (uint64_t)i);
        dd_free(t);
        free(pts);
    }
    check_edits(&st, 3);
    check_refinement(&st, 9);
    return tl_finish(&st);
}
