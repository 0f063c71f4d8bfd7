/*
 * test_move.c -- dd_move and dd_delete_set's courses against CGAL:
 *  - random move sequences (small steps, large jumps, onto free nodes of
 *    an integer grid, onto other vertices, onto the vertex's own point)
 *    end, after every move, in CGAL's triangulation of the moved points,
 *    and the validator passes after each filtered move;
 *  - a failed move (another vertex's point, NaN, infinity, a move that
 *    leaves only coplanar points) changes nothing and says why;
 *  - set deletion by each course (one at a time, rebuild; test controls)
 *    equals CGAL's triangulation of the points left.
 */
#include "testlib.h"
#include <math.h>
#include "dtdel.h"
#include "cgal/cgal_shim.h"
#include "../datasets/datasets.h"

typedef struct canon { int32_t *a; size_t n; } canon;

static int same_as_cgal(dd_tri *t, const double *pts, uint32_t n)
{
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    dd_cgal *g = dd_cgal_build(pts, n);
    int same = g && dd_canonical(t, &a, &na) == DD_OK && !dd_cgal_canonical(g, &b, &nb) && na == nb &&
               !memcmp(a, b, 4 * na * sizeof *a);
    dd_cgal_free(g);
    free(a), free(b);
    return same;
}

static uint64_t step(uint64_t *x)
{
    *x ^= *x << 13, *x ^= *x >> 7, *x ^= *x << 17;
    return *x;
}

/* k moves of random vertices of pts[0..n), each by `kind`: 0 a small
 * step (scale), 1 anywhere in the box, 2 onto a free node of the integer
 * grid [0, side)^3 (pts must be such a grid), 3 onto another vertex
 * (refused), 4 onto its own point (no change).  After each: CGAL's DT of
 * the moved points, and dd_check.                                       */
static void move_sequence(tl_state *st, const char *name, double *pts, uint32_t n, int kind, double scale,
                          uint32_t k, uint64_t seed)
{
    char tn[128], msg[256];
    snprintf(tn, sizeof tn, "move/%s", name);
    dd_tri *t;
    if (dd_create(&t, pts, n, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, tn, "dd_create: %s", msg);
        return;
    }
    uint64_t x = seed | 1;
    long bad = 0, kept = 0, flipped = 0;
    char why[200] = "";
    for (uint32_t i = 0; i < k && !bad; i++) {
        const uint32_t v = (uint32_t)(step(&x) % n);
        double p[3], *q = pts + 3 * (size_t)v;
        for (int c = 0; c < 3; c++) {
            const double r = (double)(step(&x) >> 11) / 9007199254740992.0;
            p[c] = kind == 0 ? q[c] + scale * (2 * r - 1) : kind == 1 ? r * scale : kind == 2 ? floor(r * scale) : q[c];
        }
        const uint32_t w = (uint32_t)(step(&x) % n);
        if (kind == 3) memcpy(p, pts + 3 * (size_t)w, sizeof p);
        int dup = 0;
        for (uint32_t j = 0; j < n; j++) dup |= j != v && !memcmp(pts + 3 * (size_t)j, p, sizeof p);
        dd_counters c0, c1;
        dd_get_counters(t, &c0);
        dd_status s = dd_move(t, v, p);
        dd_get_counters(t, &c1);
        if (dup ? s != DD_ERR_DUPLICATE : s != DD_OK) {
            snprintf(why, sizeof why, "move %u of vertex %u: status %s (%s), expected %s", i, v, dd_status_name(s),
                     dd_errmsg(t), dup ? "duplicate" : "ok");
            bad++;
            break;
        }
        if (!dup) memcpy(q, p, sizeof p);
        kept += c1.moves_kept > c0.moves_kept;
        flipped += c1.moves_flipped > c0.moves_flipped;
        if (!same_as_cgal(t, pts, n) || dd_check(t) != DD_OK) {
            snprintf(why, sizeof why, "move %u of vertex %u (%s): differs from CGAL or invalid", i, v,
                     c1.moves_kept > c0.moves_kept ? "filtered" : c1.moves_flipped > c0.moves_flipped ? "flipped" : "redone");
            bad++;
        }
    }
    tl_check(st, bad == 0, tn, "%s", why);
    printf("# %s: %u moves, %ld kept by the filter, %ld by flips\n", tn, k, kept, flipped);
    dd_free(t);
}

static void move_refused(tl_state *st)
{
    /* a square, an apex and a point inside: bad points are refused */
    double p[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.3, 0.4, 1, 0.7, 0.2, 0.5};
    char msg[256];
    dd_tri *t;
    dd_create(&t, p, 6, msg, sizeof msg);
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    dd_canonical(t, &a, &na);
    const double nanp[3] = {NAN, 0, 0}, infp[3] = {0, -INFINITY, 0}, flat[3] = {0.5, 0.5, 0};
    dd_status s2 = dd_move(t, 4, nanp), s3 = dd_move(t, 4, infp), s4 = dd_move(t, 4, p + 3),
              s5 = dd_move(t, 77, flat), s6 = dd_move(t, 4, p + 12);   /* the last: its own point */
    dd_canonical(t, &b, &nb);
    tl_check(st, s2 == DD_ERR_NAN && s3 == DD_ERR_INFINITE && s4 == DD_ERR_DUPLICATE && s5 == DD_ERR_UNKNOWN_VERTEX &&
                     s6 == DD_OK && na == nb && !memcmp(a, b, 4 * na * sizeof *a),
             "move-refused/bad-point", "statuses %s %s %s %s %s", dd_status_name(s2), dd_status_name(s3),
             dd_status_name(s4), dd_status_name(s5), dd_status_name(s6));
    free(a), free(b);
    dd_free(t);
    /* 4 points of a plane and one off it: moving it into the plane */
    double q[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 1};
    dd_create(&t, q, 5, msg, sizeof msg);
    a = b = NULL;
    dd_canonical(t, &a, &na);
    dd_status s7 = dd_move(t, 4, flat);
    dd_canonical(t, &b, &nb);
    tl_check(st, s7 == DD_ERR_DIMENSION && na == nb && !memcmp(a, b, 4 * na * sizeof *a), "move-refused/coplanar",
             "status %s: %s", dd_status_name(s7), dd_errmsg(t));
    free(a), free(b);
    dd_free(t);
}

/* A random fraction of the vertices deleted as a set, by `course` (test
 * builds: 1 one at a time, 2 rebuild; 0 the cheaper), against CGAL.     */
static void set_course(tl_state *st, const char *ds, uint32_t n, double fraction, int course)
{
    char tn[128], msg[256];
    snprintf(tn, sizeof tn, "delete-set-course/%s-%u/%.0f%%/%s", ds, n, 100 * fraction,
             course == 1 ? "one-by-one" : course == 2 ? "rebuild" : "cheaper");
    double *p = NULL;
    uint32_t np;
    dd_gen(ds, n, 13, &p, &np, msg, sizeof msg);
    dd_tri *t;
    dd_create(&t, p, np, msg, sizeof msg);
#ifdef DD_TEST_BUILD
    dd_test_control(t, DD_TEST_SET_COURSE, course);
#endif
    uint32_t *vs = malloc((size_t)np * sizeof *vs), k = 0;
    uint64_t x = 99;
    for (uint32_t i = 1; i < np; i++)   /* 0 stays: the points deleted become copies of it for CGAL */
        if (dd_is_vertex(t, i) && (double)(step(&x) >> 11) / 9007199254740992.0 < fraction) vs[k++] = i;
    dd_status s = dd_delete_set(t, vs, k);
    double *left = malloc(3 * (size_t)np * sizeof *left);
    memcpy(left, p, 3 * (size_t)np * sizeof *left);
    for (uint32_t j = 0; j < k; j++) memcpy(left + 3 * (size_t)vs[j], p, 3 * sizeof *left);   /* merged into 0 */
    const int ok = s == DD_OK && dd_check(t) == DD_OK && same_as_cgal(t, left, np);
    tl_check(st, ok, tn, "status %s (%s), %u of %u deleted", dd_status_name(s), dd_errmsg(t), k, np);
    free(vs), free(left), free(p);
    dd_free(t);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    int small = argc > 1 && !strcmp(argv[1], "small");
    const uint32_t k = small ? 60 : 300;
    char msg[256];
    double *p;
    uint32_t np;
    dd_gen("uniform", small ? 300 : 1000, 21, &p, &np, msg, sizeof msg);
    move_sequence(&st, "uniform/small-steps", p, np, 0, 0.005, k, 1);
    move_sequence(&st, "uniform/large-jumps", p, np, 1, 1.0, k / 2, 2);
    move_sequence(&st, "uniform/onto-vertices", p, np, 3, 0, k / 4, 3);
    move_sequence(&st, "uniform/own-point", p, np, 4, 0, k / 4, 4);
    free(p);
    dd_gen("grid", small ? 216 : 512, 1, &p, &np, msg, sizeof msg);
    double side = cbrt((double)np);
    move_sequence(&st, "grid/onto-nodes", p, np, 2, side + 1, k / 2, 5);
    move_sequence(&st, "grid/small-steps", p, np, 0, 0.25, k / 2, 6);
    free(p);
    dd_gen("cosphere", small ? 150 : 300, 1, &p, &np, msg, sizeof msg);
    move_sequence(&st, "cosphere/onto-vertices", p, np, 3, 0, k / 4, 7);
    move_sequence(&st, "cosphere/small-steps", p, np, 0, 1.0, k / 2, 8);
    free(p);
    move_refused(&st);
    for (int course = 0; course <= 2; course++) {
#ifndef DD_TEST_BUILD
        if (course) continue;   /* the courses are forced by test controls */
#endif
        set_course(&st, "uniform", small ? 1000 : 5000, 0.1, course);
        set_course(&st, "uniform", small ? 1000 : 5000, 0.9, course);
        set_course(&st, "grid", small ? 343 : 1000, 0.5, course);
    }
    return tl_finish(&st);
}
