/*
 * test_rbench.c -- the bench's CGAL reference for weighted edits
 * (src/cgal/cgal_rbench.h) against CGAL itself: after moves (CGAL's
 * move() where it gives the reference result, remove and insert
 * otherwise), re-weightings and removals, each done through the kept
 * vertex handles with the index bookkeeping after them, the triangulation
 * must equal CGAL's scratch build of the points it holds, cells and
 * hidden set, input indices included: the regular triangulation of a
 * point set is unique (kept hidden points: the points given and not
 * removed; discarded: the vertices left), so any slip of the bookkeeping
 * (a vertex named wrong, a hidden point lost) shows.  Datasets: wgrid
 * (equal positions, power ties), wuniform, wuniform-most (most points
 * hidden), molecule; both hidden modes.
 *
 * Argument "small": smaller sizes (the sanitizer build).
 */
#include "testlib.h"
#include "cgal/cgal_rbench.h"
#include "datasets/datasets.h"

#include <math.h>

static uint64_t rng_state = 88172645463325252ull;

static double unit(void)
{
    rng_state ^= rng_state << 13, rng_state ^= rng_state >> 7, rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

static int cmp_cell(const void *a, const void *b)
{
    const int32_t *x = a, *y = b;
    for (int i = 0; i < 4; i++)
        if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
    return 0;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Whether c equals CGAL's scratch build of the points it holds (state
 * not none), renumbered back to their indices; *why says what differs. */
static int same_as_scratch(const dd_cgal_rb *c, const double *p, const double *w, uint32_t np, int discard,
                           char *why, size_t nwhy)
{
    uint32_t *live = malloc(np * sizeof *live), m = 0;
    double *pp = malloc(3 * (size_t)np * sizeof *pp), *ww = malloc(np * sizeof *ww);
    for (uint32_t i = 0; i < np; i++)
        if (dd_cgal_rb_state(c, i) != DD_RB_NONE) {
            memcpy(pp + 3 * (size_t)m, p + 3 * (size_t)i, 3 * sizeof *pp);
            ww[m] = w[i];
            live[m++] = i;
        }
    dd_cgal_rb *d = dd_cgal_rb_build(pp, ww, m, discard);
    int32_t *ta = NULL, *tb = NULL;
    uint32_t *ha = NULL, *hb = NULL;
    size_t na = 0, nb = 0, nha = 0, nhb = 0;
    int ok = d && !dd_cgal_rb_canonical(c, &ta, &na) && !dd_cgal_rb_canonical(d, &tb, &nb) &&
             !dd_cgal_rb_hidden(c, &ha, &nha) && !dd_cgal_rb_hidden(d, &hb, &nhb);
    if (!ok) snprintf(why, nwhy, "a build or a canonical form failed");
    for (size_t k = 0; ok && k < 4 * nb; k++)
        if (tb[k] >= 0) tb[k] = (int32_t)live[tb[k]];
    for (size_t k = 0; ok && k < nb; k++) {
        int32_t *t = tb + 4 * k;
        for (int a = 0; a < 4; a++)
            for (int b = a + 1; b < 4; b++)
                if (t[b] < t[a]) { int32_t x = t[a]; t[a] = t[b], t[b] = x; }
    }
    for (size_t k = 0; ok && k < nhb; k++) hb[k] = live[hb[k]];
    if (ok) {
        if (nb) qsort(tb, nb, 4 * sizeof *tb, cmp_cell);
        if (nhb) qsort(hb, nhb, sizeof *hb, cmp_u32);
        if (na != nb || memcmp(ta, tb, 4 * na * sizeof *ta))
            ok = 0, snprintf(why, nwhy, "cells differ (%zu against %zu)", na, nb);
        else if (nha != nhb || (nha && memcmp(ha, hb, nha * sizeof *ha)))
            ok = 0, snprintf(why, nwhy, "hidden sets differ (%zu against %zu)", nha, nhb);
    }
    dd_cgal_rb_free(d);
    free(ta), free(tb), free(ha), free(hb), free(live), free(pp), free(ww);
    return ok;
}

/* Every vertex moved by up to 5% of the spacing, then every vertex
 * re-weighted by a factor in [0.9, 1.1), then half the vertices removed;
 * compared with the scratch build after each phase.                    */
static void edit_case(tl_state *st, const char *dataset, uint32_t n, int discard)
{
    double *p = NULL, *w = NULL;
    uint32_t np = 0;
    char msg[256], name[96], why[160] = "";
    const char *mode = discard ? "discard" : "keep";
    int ok = dd_gen_weighted(dataset, n, 7, &p, &w, &np, msg, sizeof msg) == DD_OK;
    dd_cgal_rb *c = ok ? dd_cgal_rb_build(p, w, np, discard) : NULL;
    snprintf(name, sizeof name, "rbench/%s-%s/build", dataset, mode);
    tl_check(st, c != NULL, name, "%s", ok ? "CGAL cannot build it" : msg);
    if (!c) { free(p), free(w); return; }
    const double h = 0.05 * cbrt(1.0 / np);
    long failed = 0, fell_back = 0, moved = 0;
    static const char *const phase[3] = {"moves", "reweights", "removals"};
    for (int ph = 0; ph < 3; ph++) {
        for (uint32_t i = 0; i < np; i++) {
            if (dd_cgal_rb_state(c, i) != DD_RB_VERTEX) continue;
            double q[3] = {p[3 * (size_t)i], p[3 * (size_t)i + 1], p[3 * (size_t)i + 2]}, nw = w[i], secs;
            int fb = 0, rc;
            if (ph == 2) {
                if (unit() < 0.5) continue;
                rc = dd_cgal_rb_remove(c, i, &secs);
            } else {
                if (ph == 0)
                    for (int k = 0; k < 3; k++) q[k] += h * (2 * unit() - 1);
                else
                    nw *= 0.9 + 0.2 * unit();
                rc = dd_cgal_rb_move(c, i, q, nw, &secs, &fb);
                if (!rc) memcpy(p + 3 * (size_t)i, q, sizeof q), w[i] = nw;
                fell_back += fb, moved += !fb;
            }
            failed += rc != 0;
        }
        snprintf(name, sizeof name, "rbench/%s-%s/%s", dataset, mode, phase[ph]);
        int same = same_as_scratch(c, p, w, np, discard, why, sizeof why);
        tl_check(st, !failed && same, name, "%ld failed; %s", failed, why);
    }
    snprintf(name, sizeof name, "rbench/%s-%s/both-kinds-of-move", dataset, mode);
    tl_check(st, moved > 0 && fell_back > 0, name, "%ld by move(), %ld by remove+insert", moved, fell_back);
    dd_cgal_rb_free(c);
    free(p), free(w);
}

int main(int argc, char **argv)
{
    const int small = argc > 1 && !strcmp(argv[1], "small");
    tl_state st = {0, 0};
    static const char *const sets[] = {"wgrid", "wuniform", "wuniform-most", "molecule"};
    for (int discard = 0; discard < 2; discard++)
        for (size_t k = 0; k < sizeof sets / sizeof *sets; k++)
            edit_case(&st, sets[k], small ? 600 : 3000, discard);
    return tl_finish(&st);
}
