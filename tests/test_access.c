/*
 * test_access.c -- reading the mesh, point location, nearest vertex and
 * insertion of new points (dtdel.h), checked exactly:
 *  - dd_cells equals CGAL's triangulation, neighbours symmetric and
 *    sharing their facet, finite cells positively oriented (CGAL's exact
 *    orientation);
 *  - dd_locate's cell holds its point (exact orientations), on uniform,
 *    grid and cospherical sets, for queries on vertices, on edges, on
 *    facets, inside cells and outside the hull;
 *  - dd_nearest_vertex is as near as every vertex (distances compared in
 *    exact rationals, GMP);
 *  - sequences of deletions and insertions of new points (indices reused)
 *    end in CGAL's triangulation of the points left;
 *  - memory stays bounded under churn (dd_memory_bytes);
 *  - NaN or infinite queries get their status and change nothing.
 */
#include "testlib.h"
#include "testcgal.h"
#include <gmp.h>
#include <math.h>
#include "dtdel.h"
#include "cgal/cgal_shim.h"
#include "../datasets/datasets.h"

static int cmp_i4(const void *a, const void *b)
{
    const int32_t *x = a, *y = b;
    for (int i = 0; i < 4; i++)
        if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
    return 0;
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

/* dd_cells against CGAL, symmetric neighbours, positive orientation. */
static void check_cells(tl_state *st, const char *name, dd_tri *t, const double *pts, uint32_t n)
{
    char tn[128];
    snprintf(tn, sizeof tn, "cells/%s", name);
    int32_t *v, *nb, *ref = NULL;
    size_t nc, nref = 0;
    if (dd_cells(t, &v, &nb, &nc) != DD_OK) {
        tl_check(st, 0, tn, "dd_cells failed");
        return;
    }
    long asym = 0, negative = 0;
    for (size_t c = 0; c < nc; c++) {
        int finite = 1;
        for (int i = 0; i < 4; i++) {
            const int32_t d = nb[4 * c + i];
            int back = 0;
            for (int j = 0; j < 4 && d >= 0 && (size_t)d < nc; j++) {
                if (nb[4 * d + j] != (int32_t)c) continue;
                int shared = 0;   /* the facet's three vertices in both */
                for (int a = 0; a < 4; a++)
                    for (int b = 0; b < 4; b++) shared += a != i && b != j && v[4 * c + a] == v[4 * d + b];
                back |= shared == 3;
            }
            asym += !back;
            finite &= v[4 * c + i] >= 0;
        }
        if (finite) {
            const double *q[4];
            for (int i = 0; i < 4; i++) q[i] = pts + 3 * (size_t)v[4 * c + i];
            negative += dd_cgal_orientation(q[0], q[1], q[2], q[3]) <= 0;
        }
    }
    int32_t *mine = malloc(4 * nc * sizeof *mine);
    memcpy(mine, v, 4 * nc * sizeof *mine);
    for (size_t c = 0; c < nc; c++) sort4(mine + 4 * c);
    qsort(mine, nc, 4 * sizeof *mine, cmp_i4);
    dd_cgal *g = dd_cgal_build(pts, n);
    int same = g && !dd_cgal_canonical(g, &ref, &nref) && nref == nc && !memcmp(ref, mine, 4 * nc * sizeof *mine);
    tl_check(st, same && asym == 0 && negative == 0, tn, "equal to CGAL %d, %ld facets without their partner, %ld cells not positive",
             same, asym, negative);
    dd_cgal_free(g);
    free(ref), free(mine), free(v), free(nb);
}

/* The nearest vertex by brute force, exactly; 1 if v is as near. */
static int nearest_ok(dd_tri *t, const double *pts, uint32_t n, const double *p, uint32_t v)
{
    double a[3];
    if (dd_point(t, v, a) != DD_OK) return 0;
    for (uint32_t w = 0; w < n; w++)
        if (dd_is_vertex(t, w) && tl_cmp_dist_exact(p, a, pts + 3 * (size_t)w) > 0) return 0;
    return 1;
}

/* Queries: every vertex, edge midpoints, points of facets, random points
 * in and around the bounding box.                                        */
static void check_queries(tl_state *st, const char *name, dd_tri *t, const double *pts, uint32_t n, uint64_t seed)
{
    char tn[128];
    int32_t *v, *nb;
    size_t nc;
    if (dd_cells(t, &v, &nb, &nc) != DD_OK) return;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            lo[c] = fmin(lo[c], pts[3 * i + c]);
            hi[c] = fmax(hi[c], pts[3 * i + c]);
        }
    uint64_t x = seed | 1;
    const char *kinds[] = {"vertex", "edge", "facet", "inside", "outside"};
    for (int kind = 0; kind < 5; kind++) {
        long bad_loc = 0, bad_near = 0, done = 0;
        for (int k = 0; k < 60; k++) {
            double p[3];
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            const int32_t *c = v + 4 * (x % nc);
            int finite = c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[3] >= 0;
            if (kind <= 2 && !finite) continue;
            const double *a = pts + 3 * (size_t)(c[0] >= 0 ? c[0] : 0), *b = pts + 3 * (size_t)(c[1] >= 0 ? c[1] : 0),
                         *d = pts + 3 * (size_t)(c[2] >= 0 ? c[2] : 0);
            for (int i = 0; i < 3; i++) {
                const double r = (double)((x >> (8 + 16 * i)) & 0xffff) / 65536.0;
                p[i] = kind == 0   ? a[i]
                       : kind == 1 ? 0.5 * (a[i] + b[i])
                       : kind == 2 ? 0.25 * (a[i] + b[i]) + 0.5 * d[i]
                       : kind == 3 ? lo[i] + r * (hi[i] - lo[i])
                                   : lo[i] - (hi[i] - lo[i]) + 3 * r * (hi[i] - lo[i]);
            }
            int32_t cell[4];
            done++;
            bad_loc += dd_locate(t, p, cell) != DD_OK || !tl_holds(t, cell, p);
            uint32_t nv = UINT32_MAX;
            bad_near += dd_nearest_vertex(t, p, &nv) != DD_OK || !nearest_ok(t, pts, n, p, nv);
        }
        snprintf(tn, sizeof tn, "locate/%s/%s", name, kinds[kind]);
        tl_check(st, done > 0 && bad_loc == 0, tn, "%ld of %ld located cells do not hold their point", bad_loc, done);
        snprintf(tn, sizeof tn, "nearest/%s/%s", name, kinds[kind]);
        tl_check(st, done > 0 && bad_near == 0, tn, "%ld of %ld nearest vertices are not nearest", bad_near, done);
    }
    free(v), free(nb);
}

/* CGAL's canonical form of the live points of pts[0..n) (live[i]), in
 * their indices.                                                         */
static int cgal_of_live(const double *pts, const uint8_t *live, uint32_t n, int32_t **out, size_t *nout)
{
    double *q = malloc(3 * (size_t)n * sizeof *q);
    uint32_t *map = malloc((size_t)n * sizeof *map), m = 0;
    for (uint32_t i = 0; i < n; i++)
        if (live[i]) {
            memcpy(q + 3 * (size_t)m, pts + 3 * (size_t)i, 3 * sizeof *q);
            map[m++] = i;
        }
    dd_cgal *g = dd_cgal_build(q, m);
    int rc = !g || dd_cgal_canonical(g, out, nout);
    for (size_t k = 0; !rc && k < 4 * *nout; k++)
        if ((*out)[k] >= 0) (*out)[k] = (int32_t)map[(*out)[k]];
    for (size_t k = 0; !rc && k < *nout; k++) sort4(*out + 4 * k);
    if (!rc) qsort(*out, *nout, 4 * sizeof **out, cmp_i4);
    dd_cgal_free(g);
    free(q), free(map);
    return rc;
}

/* Deletes and inserts at random (new points from `ds`, reused indices
 * tracked), then compares with CGAL's triangulation of the points left. */
static void check_sequence(tl_state *st, const char *ds, uint32_t n, uint32_t ops, uint64_t seed)
{
    char tn[128], msg[256];
    snprintf(tn, sizeof tn, "insert-sequence/%s-%u", ds, n);
    uint32_t np, nn;
    double *p = tl_gen(ds, n, seed, &np), *fresh = tl_gen(ds, 2 * n, seed + 11, &nn);
    dd_tri *t;
    if (dd_create(&t, p, np, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, tn, "dd_create: %s", msg);
        return;
    }
    uint32_t cap = np + ops;
    double *pts = malloc(3 * (size_t)cap * sizeof *pts);
    uint8_t *live = calloc(cap, 1);
    memcpy(pts, p, 3 * (size_t)np * sizeof *pts);
    for (uint32_t i = 0; i < np; i++) live[i] = (uint8_t)dd_is_vertex(t, i);
    uint64_t x = seed * 0x9E3779B97F4A7C15ull | 1;
    long bad = 0, inserted = 0, reused = 0, deleted = 0;
    uint32_t next = 0, hi = np;
    tl_courses cs = tl_courses_all();   /* each deletion the next course */
    for (uint32_t k = 0; k < ops && !bad; k++) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        if (x % 3 == 0 && dd_num_vertices(t) > 16) {   /* delete a random vertex */
            uint32_t v = (uint32_t)((x >> 8) % hi);
            if (!live[v]) continue;
            tl_course_next(&cs, t);
            bad += dd_delete(t, v) != DD_OK;
            live[v] = 0;
            deleted++;
        } else if (next < nn) {                        /* insert a new point */
            uint32_t idx;
            const double *q = fresh + 3 * (size_t)next++;
            dd_status s = dd_insert(t, q, &idx);
            if (s == DD_ERR_DUPLICATE) continue;
            if (s != DD_OK || idx >= cap || live[idx]) {
                bad++;
                break;
            }
            reused += idx < hi;
            if (idx >= hi) hi = idx + 1;
            memcpy(pts + 3 * (size_t)idx, q, 3 * sizeof *pts);
            live[idx] = 1;
            inserted++;
        }
    }
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    int same = !bad && dd_canonical(t, &a, &na) == DD_OK && !cgal_of_live(pts, live, hi, &b, &nb) && na == nb &&
               !memcmp(a, b, 4 * na * sizeof *a);
    char unrun[96] = "";
    int covered = tl_courses_covered(&cs, unrun, sizeof unrun);
    tl_check(st, same && covered && dd_check(t) == DD_OK && reused > 0, tn,
             "%ld deletions, %ld insertions (%ld reused an index), %ld failed; equal to CGAL %d %s", deleted, inserted,
             reused, bad, same, unrun);
    free(a), free(b), free(pts), free(live), free(p), free(fresh);
    dd_free(t);
}

/* Rounds of deleting half the vertices and inserting as many new points:
 * the arrays after the last round at most 1.3 times those after round 2. */
static void check_churn(tl_state *st, uint32_t n, uint32_t rounds)
{
    char tn[64], msg[256];
    snprintf(tn, sizeof tn, "churn-memory/uniform-%u", n);
    uint32_t np;
    double *p = tl_gen("uniform", n, 3, &np);
    dd_tri *t;
    dd_create(&t, p, np, msg, sizeof msg);
    free(p);
    uint32_t *live = malloc((size_t)np * sizeof *live), half = np / 2;
    for (uint32_t i = 0; i < np; i++) live[i] = i;
    uint64_t x = 77;
    size_t mem2 = 0, mem = 0;
    long bad = 0;
    for (uint32_t r = 1; r <= rounds && !bad; r++) {
        for (uint32_t i = 0; i < half; i++) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            uint32_t j = i + (uint32_t)(x % (np - i)), s = live[i];
            live[i] = live[j], live[j] = s;
        }
        bad += dd_delete_set(t, live, half) != DD_OK;
        for (uint32_t i = 0; i < half && !bad; i++) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            double q[3] = {(double)(x & 0xfffff) / 1048576.0, (double)((x >> 20) & 0xfffff) / 1048576.0,
                           (double)((x >> 40) & 0xfffff) / 1048576.0};
            uint32_t idx;
            dd_status s = dd_insert(t, q, &idx);
            if (s == DD_ERR_DUPLICATE) { i--; continue; }
            bad += s != DD_OK;
            live[i] = idx;
        }
        mem = dd_memory_bytes(t);
        if (r == 2) mem2 = mem;
    }
    tl_check(st, !bad && dd_check(t) == DD_OK && dd_num_input(t) <= np && (double)mem <= 1.3 * (double)mem2, tn,
             "%ld failures; inputs %u of %u; arrays %zu bytes after round 2, %zu after round %u", bad,
             dd_num_input(t), np, mem2, mem, rounds);
    free(live);
    dd_free(t);
}

static void check_bad_input(tl_state *st)
{
    char msg[256];
    uint32_t np;
    double *p = tl_gen("uniform", 300, 9, &np);
    dd_tri *t;
    dd_create(&t, p, np, msg, sizeof msg);
    int32_t *before = NULL, *after = NULL;
    size_t nb = 0, na = 0;
    dd_canonical(t, &before, &nb);
    const double nanp[3] = {0.5, NAN, 0.5}, infp[3] = {INFINITY, 0, 0};
    int32_t cell[4];
    uint32_t idx;
    dd_status s1 = dd_locate(t, nanp, cell), s2 = dd_locate(t, infp, cell), s3 = dd_insert(t, infp, &idx);
    uint32_t nv = 77;
    dd_status s0 = dd_nearest_vertex(t, nanp, &nv);
    double q[3];
    dd_status s4 = dd_point(t, 100000, q);
    dd_delete(t, 7);                       /* a failed insert keeps 7's slot */
    dd_status s5 = dd_insert(t, p + 3 * 8, &idx), s6 = dd_reinsert(t, 7);
    dd_canonical(t, &after, &na);
    int same = na == nb && !memcmp(before, after, 4 * na * sizeof *after);
    tl_check(st, s1 == DD_ERR_NAN && s2 == DD_ERR_INFINITE && s3 == DD_ERR_INFINITE && s0 == DD_ERR_NAN &&
                     s4 == DD_ERR_UNKNOWN_VERTEX && s5 == DD_ERR_DUPLICATE && s6 == DD_OK && same,
             "access/bad-input", "statuses %s %s %s %s %s %s, nearest %u, unchanged %d", dd_status_name(s1),
             dd_status_name(s2), dd_status_name(s3), dd_status_name(s4), dd_status_name(s5), dd_status_name(s6), nv,
             same);
    free(before), free(after), free(p);
    dd_free(t);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    int small = argc > 1 && !strcmp(argv[1], "small");
    struct { const char *ds; uint32_t n; } sets[] = {
        {"uniform", 2000}, {"grid", 216}, {"grid", 1000}, {"cosphere", 300}, {"sphere", 500}, {"layers", 128}};
    for (size_t i = 0; i < sizeof sets / sizeof *sets; i++) {
        uint32_t np;
        double *p = tl_gen(sets[i].ds, small ? sets[i].n / 2 : sets[i].n, 5, &np);
        char name[64], msg[256];
        snprintf(name, sizeof name, "%s-%u", sets[i].ds, np);
        dd_tri *t;
        if (dd_create(&t, p, np, msg, sizeof msg) != DD_OK) {
            tl_check(&st, 0, name, "dd_create: %s", msg);
            free(p);
            continue;
        }
        check_cells(&st, name, t, p, np);
        check_queries(&st, name, t, p, np, 1 + i);
        dd_free(t);
        free(p);
    }
    check_sequence(&st, "uniform", small ? 300 : 2000, small ? 600 : 3000, 3);
    check_sequence(&st, "grid", small ? 125 : 512, small ? 300 : 1500, 4);
    check_sequence(&st, "cosphere", small ? 150 : 400, small ? 300 : 1200, 5);
    check_churn(&st, small ? 2000 : 20000, 12);
    check_bad_input(&st);
    return tl_finish(&st);
}
