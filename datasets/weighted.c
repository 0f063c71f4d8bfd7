/*
 * weighted.c -- the weighted datasets (DESIGN 9, 12): point sets with a
 * weight per point, for regular triangulations.
 *
 * Owns: the table of weighted datasets behind dd_gen_weighted (and behind
 * dd_gen for their names, weights dropped).
 *
 * Invariants:
 *  - A generator is a pure function of (name, n, seed); its PRNG (rng.h)
 *    lives on its stack.  Points and weights are finite doubles; uniform
 *    and molecule use only IEEE +,-,*,/ and sqrt (bit-identical on every
 *    IEEE machine), whelix libm's cos and sin, wgrid only small integers.
 *  - Input index = order of the point in the generator's output.
 */
#include "datasets.h"
#include "msg.h"
#include "rng.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


/* Each fills xyz[0 .. 3n) and w[0 .. n) (allocated by the caller). */
typedef dd_status (*wgen_fn)(uint32_t n, uint64_t seed, double alpha, double *xyz, double *w, char *msg,
                             size_t msglen);

/* Fills xyz with n points of the unweighted dataset `name`. */
static dd_status base_points(const char *name, uint32_t n, uint64_t seed, double *xyz, char *msg, size_t msglen)
{
    double *p;
    uint32_t np;
    dd_status st = dd_gen(name, n, seed, &p, &np, msg, msglen);
    if (st != DD_OK) return st;
    memcpy(xyz, p, 3 * (size_t)np * sizeof *p);
    free(p);
    return DD_OK;
}

/* Uniform in the unit cube (dataset uniform's points), weight (alpha s)^2 u
 * with s = n^(-1/3) the mean spacing and u uniform in [0, 1): alpha sets
 * how many points end hidden, from few (alpha 0.3) to most (alpha 3).   */
static dd_status gen_wuniform(uint32_t n, uint64_t seed, double alpha, double *xyz, double *w, char *msg,
                              size_t msglen)
{
    dd_status st = base_points("uniform", n, seed, xyz, msg, msglen);
    if (st != DD_OK) return st;
    rng g;
    seed_rng(&g, seed ^ 0x5765696768747321ULL);   /* a stream apart from the points' */
    const double s = n ? alpha / cbrt((double)n) : 0;
    for (uint32_t i = 0; i < n; i++) w[i] = s * s * next_unit(&g);
    return DD_OK;
}

/* Distance from p to the nearest edge of the unit cube. */
static double edge_distance(const double *p)
{
    double d[3], best = INFINITY;
    for (int k = 0; k < 3; k++) d[k] = fmin(p[k], 1 - p[k]);
    for (int k = 0; k < 3; k++) best = fmin(best, hypot(d[(k + 1) % 3], d[(k + 2) % 3]));
    return best;
}

/* Mesh_3-like protecting balls: the 12 edges of the unit cube are sharp
 * features, sampled by about n/8 points at spacing d (the 8 corners
 * included), each with a ball of radius 0.6 d (weight 0.36 d^2) so that
 * neighbouring balls overlap, as Mesh_3 protects features; the other
 * points are unweighted, uniform in the cube outside every ball.  Points
 * in a random order (features and volume mixed).                        */
static dd_status gen_protecting(uint32_t n, uint64_t seed, double alpha, double *xyz, double *w, char *msg,
                                size_t msglen)
{
    (void)alpha;
    if (n < 8) {
        set_msg(msg, msglen, "protecting: n = %u is below the 8 corners", n);
        return DD_ERR_PARSE;
    }
    rng g;
    seed_rng(&g, seed);
    uint32_t per = n / 8 > 8 ? (n / 8 - 8) / 12 : 0;   /* inner points per edge */
    const double d = 1.0 / (per + 1), r = 0.6 * d;
    uint32_t m = 0;
    for (int c = 0; c < 8; c++, m++) {
        for (int k = 0; k < 3; k++) xyz[3 * m + k] = (c >> k) & 1;
        w[m] = r * r;
    }
    for (int axis = 0; axis < 3; axis++)
        for (int e = 0; e < 4; e++)
            for (uint32_t j = 1; j <= per; j++, m++) {
                double *p = xyz + 3 * (size_t)m;
                p[axis] = j * d;
                p[(axis + 1) % 3] = e & 1;
                p[(axis + 2) % 3] = (e >> 1) & 1;
                w[m] = r * r;
            }
    for (; m < n; m++) {
        double *p = xyz + 3 * (size_t)m;
        do
            for (int k = 0; k < 3; k++) p[k] = next_unit(&g);
        while (edge_distance(p) < r);
        w[m] = 0;
    }
    for (uint32_t i = n - 1; i > 0; i--) {    /* Fisher-Yates */
        uint32_t j = (uint32_t)next_below(&g, (uint64_t)i + 1);
        double t[3], tw = w[i];
        memcpy(t, xyz + 3 * (size_t)i, sizeof t);
        memcpy(xyz + 3 * (size_t)i, xyz + 3 * (size_t)j, sizeof t);
        memcpy(xyz + 3 * (size_t)j, t, sizeof t);
        w[i] = w[j];
        w[j] = tw;
    }
    return DD_OK;
}

/* A synthetic molecule: n atoms packed in a ball, on the cells of a cubic
 * lattice of spacing 1.45 (angstrom, a covalent bond) taken in a random
 * order, each jittered by up to 0.3 of the spacing; an element drawn by
 * frequency (H 1.2, C 1.7, N 1.55, O 1.52, S 1.8, P 1.9: van der Waals
 * radii), weight = radius^2, as an .xyzr file of atoms gives.             */
static dd_status gen_molecule(uint32_t n, uint64_t seed, double alpha, double *xyz, double *w, char *msg,
                              size_t msglen)
{
    (void)alpha;
    static const struct { double r; unsigned per_mille; } elements[] = {
        {1.2, 450}, {1.7, 330}, {1.55, 80}, {1.52, 110}, {1.8, 20}, {1.9, 10}};
    const double a = 1.45;
    rng g;
    seed_rng(&g, seed);
    /* lattice cells within radius R (in cells), R the smallest with room */
    int64_t R = (int64_t)cbrt(3.0 * n / (4.0 * 3.14159265358979)) + 1;
    uint64_t cells;
    for (;; R++) {
        cells = 0;
        for (int64_t x = -R; x <= R; x++)
            for (int64_t y = -R; y <= R; y++)
                for (int64_t z = -R; z <= R; z++) cells += x * x + y * y + z * z <= R * R;
        if (cells >= n) break;
    }
    int32_t *cell = malloc(3 * cells * sizeof *cell);
    if (cell == NULL) {
        set_msg(msg, msglen, "molecule: out of memory for %llu lattice cells", (unsigned long long)cells);
        return DD_ERR_NOMEM;
    }
    uint64_t c = 0;
    for (int64_t x = -R; x <= R; x++)
        for (int64_t y = -R; y <= R; y++)
            for (int64_t z = -R; z <= R; z++)
                if (x * x + y * y + z * z <= R * R) {
                    cell[3 * c] = (int32_t)x;
                    cell[3 * c + 1] = (int32_t)y;
                    cell[3 * c + 2] = (int32_t)z;
                    c++;
                }
    for (uint32_t i = 0; i < n; i++) {        /* a partial Fisher-Yates: n cells */
        uint64_t j = i + next_below(&g, cells - i);
        for (int k = 0; k < 3; k++) {
            int32_t t = cell[3 * i + k];
            cell[3 * i + k] = cell[3 * j + k];
            cell[3 * j + k] = t;
            xyz[3 * (size_t)i + k] = a * (cell[3 * i + k] + 0.6 * (next_unit(&g) - 0.5));
        }
        unsigned u = (unsigned)next_below(&g, 1000), e = 0;
        while (u >= elements[e].per_mille) u -= elements[e++].per_mille;
        w[i] = elements[e].r * elements[e].r;
    }
    free(cell);
    return DD_OK;
}

/* Degenerate: the first m = n - n/8 points of the k x k x k integer grid
 * (dataset grid's) with integer weights 0, 1 or 2 (power ties), then n/8
 * points at grid positions already taken, with another of those weights
 * (equal positions, different weights).                                  */
static dd_status gen_wgrid(uint32_t n, uint64_t seed, double alpha, double *xyz, double *w, char *msg,
                           size_t msglen)
{
    (void)alpha;
    const uint32_t extra = n / 8, m = n - extra;
    dd_status st = base_points("grid", m, seed, xyz, msg, msglen);
    if (st != DD_OK) return st;
    rng g;
    seed_rng(&g, seed);
    for (uint32_t i = 0; i < m; i++) w[i] = (double)next_below(&g, 3);
    for (uint32_t i = m; i < n; i++) {
        uint32_t j = (uint32_t)next_below(&g, m);
        memcpy(xyz + 3 * (size_t)i, xyz + 3 * (size_t)j, 3 * sizeof *xyz);
        w[i] = (double)(((uint64_t)w[j] + 1 + next_below(&g, 2)) % 3);
    }
    return DD_OK;
}

/* A curve dataset (moment, helix) with weight 2 u d^2 / n, u uniform in
 * [0, 1) and d the distance to the nearer neighbour along the curve.
 * Both curves are in convex position, so no point is hidden; the weights
 * change the cells.  Why d^2 / n and not d^2: the curves owe their high
 * degrees to spheres that pass close to many other points, and those
 * margins shrink as the curve gets denser (on the helix, with about
 * sqrt(n) points per turn, they are of the order of the rise per point,
 * d / sqrt(n), squared).  Weights of the order of d^2 outweigh them and
 * leave the curves with the low degrees of any dense sample, which
 * wuniform already covers; weights of the order of d^2 / n make the
 * heavier points take neighbours from the lighter ones (stars and cells
 * differ from the unweighted curve's) while the stars keep most of the
 * curve's high degree.                                                   */
static dd_status curve_weights(const char *curve, uint32_t n, uint64_t seed, double *xyz, double *w, char *msg,
                               size_t msglen)
{
    dd_status st = base_points(curve, n, seed, xyz, msg, msglen);
    if (st != DD_OK) return st;
    rng g;
    seed_rng(&g, seed);
    for (uint32_t i = 0; i < n; i++) {
        double d2 = INFINITY;
        for (int s = -1; s <= 1; s += 2) {
            if ((s < 0 && i == 0) || (s > 0 && i + 1 == n)) continue;
            const double *p = xyz + 3 * (size_t)i, *q = p + 3 * s;
            double e = 0;
            for (int k = 0; k < 3; k++) e += (p[k] - q[k]) * (p[k] - q[k]);
            d2 = fmin(d2, e);
        }
        w[i] = isinf(d2) ? 0 : 2 * d2 * next_unit(&g) / (double)n;
    }
    return DD_OK;
}

static dd_status gen_wmoment(uint32_t n, uint64_t seed, double alpha, double *xyz, double *w, char *msg,
                             size_t msglen)
{
    (void)alpha;
    return curve_weights("moment", n, seed, xyz, w, msg, msglen);
}

static dd_status gen_whelix(uint32_t n, uint64_t seed, double alpha, double *xyz, double *w, char *msg,
                            size_t msglen)
{
    (void)alpha;
    return curve_weights("helix", n, seed, xyz, w, msg, msglen);
}

typedef struct wdataset {
    const char *name;
    wgen_fn gen;
    double alpha;
} wdataset;

static const wdataset wdatasets[] = {
    {"wuniform-few", gen_wuniform, 0.5}, {"wuniform", gen_wuniform, 1.0}, {"wuniform-most", gen_wuniform, 4.0},
    {"protecting", gen_protecting, 0},   {"molecule", gen_molecule, 0},   {"wgrid", gen_wgrid, 0},
    {"wmoment", gen_wmoment, 0},         {"whelix", gen_whelix, 0},
};
#define NUM_WDATASETS (sizeof wdatasets / sizeof *wdatasets)

const char *dd_weighted_dataset_name(size_t i)
{
    return i < NUM_WDATASETS ? wdatasets[i].name : NULL;
}

int dd_dataset_is_weighted(const char *name)
{
    for (size_t i = 0; name != NULL && i < NUM_WDATASETS; i++)
        if (!strcmp(name, wdatasets[i].name)) return 1;
    return 0;
}

dd_status dd_gen_weighted(const char *name, uint32_t n, uint64_t seed, double **xyz, double **w, uint32_t *np,
                          char *msg, size_t msglen)
{
    *xyz = NULL;
    *w = NULL;
    *np = 0;
    const wdataset *d = NULL;
    for (size_t i = 0; name != NULL && i < NUM_WDATASETS; i++)
        if (!strcmp(name, wdatasets[i].name)) d = &wdatasets[i];
    if (d == NULL) return dd_gen(name, n, seed, xyz, np, msg, msglen);
    double *p = malloc((n ? 3 * (size_t)n : 3) * sizeof *p), *q = malloc((n ? n : 1) * sizeof *q);
    if (p == NULL || q == NULL) {
        free(p);
        free(q);
        set_msg(msg, msglen, "out of memory for %lu points of '%s'", (unsigned long)n, d->name);
        return DD_ERR_NOMEM;
    }
    dd_status st = n ? d->gen(n, seed, d->alpha, p, q, msg, msglen) : DD_OK;
    if (st != DD_OK) {
        free(p);
        free(q);
        return st;
    }
    *xyz = p;
    *w = q;
    *np = n;
    return DD_OK;
}
