/*
 * testcgal.h -- helpers shared by the C tests that compare with CGAL or
 * with exact arithmetic: a dataset by name, the exact comparison of two
 * distances, and whether a located cell holds its point by CGAL's exact
 * orientations.  Include after testlib.h; link GMP, the datasets and the
 * CGAL shim (the Makefile's test rules do).
 */
#ifndef DD_TESTCGAL_H
#define DD_TESTCGAL_H

#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>

#include "dtdel.h"
#include "cgal/cgal_shim.h"
#include "../datasets/datasets.h"

/* n points of dataset ds with seed; exits the test on failure. */
static inline double *tl_gen(const char *ds, uint32_t n, uint64_t seed, uint32_t *np)
{
    double *p = NULL;
    char msg[256];
    if (dd_gen(ds, n, seed, &p, np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "gen %s: %s\n", ds, msg);
        exit(1);
    }
    return p;
}

/* sign(pow(p, a) - pow(p, b)) in exact rationals, pow(p, x) = |p - x|^2
 * - wx: the power distance (the Euclidean squared one with weights 0). */
static inline int tl_cmp_power_exact(const double *p, const double *a, double wa, const double *b, double wb)
{
    mpq_t x, y, s;
    mpq_inits(x, y, s, NULL);
    for (int c = 0; c < 3; c++) {
        mpq_set_d(x, p[c]);
        mpq_set_d(y, a[c]);
        mpq_sub(y, x, y);
        mpq_mul(y, y, y);
        mpq_add(s, s, y);
        mpq_set_d(y, b[c]);
        mpq_sub(y, x, y);
        mpq_mul(y, y, y);
        mpq_sub(s, s, y);
    }
    mpq_set_d(x, wa);
    mpq_sub(s, s, x);
    mpq_set_d(x, wb);
    mpq_add(s, s, x);
    const int r = mpq_sgn(s);
    mpq_clears(x, y, s, NULL);
    return r;
}

/* sign(|p - a|^2 - |p - b|^2) in exact rationals. */
static inline int tl_cmp_dist_exact(const double *p, const double *a, const double *b)
{
    return tl_cmp_power_exact(p, a, 0, b, 0);
}

/* Whether cell (input indices, -1 = infinite) holds p by CGAL's exact
 * orientations: every orientation with p in a vertex's place >= 0; for an
 * infinite cell, the one in the infinite vertex's place (p on the outer
 * side of its hull facet or in its plane).                               */
static inline int tl_holds(const dd_tri *t, const int32_t cell[4], const double *p)
{
    double x[4][3];
    int inf = -1;
    for (int i = 0; i < 4; i++) {
        if (cell[i] < 0) inf = i;
        else if (dd_point(t, (uint32_t)cell[i], x[i]) != DD_OK) return 0;
    }
    for (int i = 0; i < 4; i++) {
        if (inf >= 0 && i != inf) continue;
        const double *q[4] = {x[0], x[1], x[2], x[3]};
        q[i] = p;
        if (dd_cgal_orientation(q[0], q[1], q[2], q[3]) < 0) return 0;
    }
    return 1;
}

#endif
