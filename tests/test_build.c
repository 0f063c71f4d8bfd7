/*
 * test_build.c -- DT(S) equals CGAL's, simplex for simplex, and passes the
 * validator (DESIGN 5 and 8) on every dataset, degenerate ones included:
 * integer grids, cospherical integer points, stacked coplanar layers, a
 * grid perturbed by 1e-13, coordinates scaled by 1e16 and 1e-200, inputs
 * with duplicates, and a real model.
 */
#include "testlib.h"
#include "dtdel.h"
#include "cgal/cgal_shim.h"
#include "../datasets/datasets.h"

/* Builds both triangulations of pts and compares them. */
static void compare(tl_state *st, const char *name, const double *pts, uint32_t n)
{
    char msg[256], tname[128];
    dd_tri *t = NULL;
    dd_status s = dd_create(&t, pts, n, msg, sizeof msg);
    snprintf(tname, sizeof tname, "build/%s/created", name);
    tl_check(st, s == DD_OK, tname, "dd_create failed: %s", msg);
    if (s != DD_OK) return;
    snprintf(tname, sizeof tname, "build/%s/valid", name);
    s = dd_check_msg(t, msg, sizeof msg);
    tl_check(st, s == DD_OK, tname, "%s", msg);
    dd_cgal *c = dd_cgal_build(pts, n);
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    int ok = c && dd_canonical(t, &a, &na) == DD_OK && dd_cgal_canonical(c, &b, &nb) == 0;
    snprintf(tname, sizeof tname, "build/%s/equals-cgal", name);
    size_t firstdiff = 0;
    if (ok) {
        while (firstdiff < na && firstdiff < nb &&
               !memcmp(a + 4 * firstdiff, b + 4 * firstdiff, 4 * sizeof *a))
            firstdiff++;
    }
    tl_check(st, ok && na == nb && firstdiff == na, tname,
             "%zu cells vs CGAL's %zu; first difference at sorted cell %zu", na, nb, firstdiff);
    free(a);
    free(b);
    dd_cgal_free(c);
    dd_free(t);
}

static void compare_dataset(tl_state *st, const char *dataset, uint32_t n, double scale)
{
    double *pts;
    uint32_t np;
    char msg[256], name[96];
    dd_status s = dd_gen(dataset, n, 7, &pts, &np, msg, sizeof msg);
    snprintf(name, sizeof name, "%s-%u%s", dataset, n,
             scale == 1.0 ? "" : scale > 1 ? "-x1e16" : "-x1e-200");
    if (s != DD_OK) {
        tl_check(st, 0, name, "dd_gen failed: %s", msg);
        return;
    }
    for (uint32_t i = 0; i < 3 * np; i++) pts[i] *= scale;
    compare(st, name, pts, np);
    free(pts);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    /* argv[1] == "small": the sanitizer build runs smaller sizes. */
    int small = argc > 1 && !strcmp(argv[1], "small");
    uint32_t big = small ? 2000 : 20000;

    compare_dataset(&st, "uniform", big, 1.0);
    compare_dataset(&st, "sphere", big / 2, 1.0);
    compare_dataset(&st, "moment", 300, 1.0);
    compare_dataset(&st, "helix", big / 4, 1.0);
    compare_dataset(&st, "grid", 216, 1.0);             /* 6x6x6 */
    compare_dataset(&st, "grid", small ? 1000 : 4096, 1.0);
    compare_dataset(&st, "grid", 500, 1.0);             /* partial 8^3 grid */
    compare_dataset(&st, "cosphere", 300, 1.0);
    compare_dataset(&st, "cosphere", 1000, 1.0);
    compare_dataset(&st, "layers", 200, 1.0);
    compare_dataset(&st, "grid-perturbed", 1000, 1.0);
    compare_dataset(&st, "grid", 1000, 1e16);
    compare_dataset(&st, "grid", 1000, 1e-200);
    compare_dataset(&st, "cosphere", 500, 1e-200);
    compare_dataset(&st, "uniform", 2000, 1e16);
    compare_dataset(&st, "uniform", 2000, 1e-200);
    compare_dataset(&st, "bunny", small ? 3000 : 0, 1.0);
    /* 70000 insertions take 140000 mark values: the 16-bit epochs of
     * mesh.h wrap (and clear every stamp) twice during the construction. */
    compare_dataset(&st, "uniform", 70000, 1.0);

    /* Point location follows the segment from the vertex nearest p of
     * the last star (mesh.c, locate_inexact): on the helix, where p's
     * predecessor on the Hilbert curve is usually its neighbour, it
     * crosses a few tens of cells a point at n = 4000, the visibility
     * walk several times as many: the bound 40 tells them apart.        */
    {
        double *h = NULL;
        uint32_t nh = 0;
        char msg[256];
        dd_tri *t = NULL;
        dd_counters cnt = {0};
        if (dd_gen("helix", 4000, 1, &h, &nh, msg, sizeof msg) == DD_OK &&
            dd_create(&t, h, nh, msg, sizeof msg) == DD_OK)
            dd_get_counters(t, &cnt);
        double per = t ? (double)cnt.walk_steps / nh : 1e9;
        tl_check(&st, per < 40, "build/helix-4000/short-walk", "%.1f cells crossed a point (want < 40)", per);
        /* Re-inserting a deleted hull vertex from the hint the deletion
         * leaves: the exact walk tries first the hull facet the plain walk
         * stopped at (another facet could send it across the interior). */
        uint64_t most = 0;
        int failed = 0;
        tl_courses cs = tl_courses_all();   /* 6 deletions: every course */
        for (int r = 0; t && r < 3; r++) {
            const uint32_t vs[2] = {3966, 100};
            for (int k = 0; k < 2; k++) {
                dd_counters c0, c1;
                tl_course_next(&cs, t);
                failed += dd_delete_with(t, vs[k], "auto") != DD_OK;
                dd_get_counters(t, &c0);
                failed += dd_reinsert(t, vs[k]) != DD_OK;
                dd_get_counters(t, &c1);
                if (c1.walk_steps - c0.walk_steps > most) most = c1.walk_steps - c0.walk_steps;
            }
        }
        char unrun[96] = "";
        failed += !tl_courses_covered(&cs, unrun, sizeof unrun);
        tl_check(&st, t && !failed && most < 10, "build/helix-4000/reinsert-walk",
                 "%llu cells crossed (want < 10), %d deletions or re-insertions failed %s",
                 (unsigned long long)most, failed, unrun);
        dd_free(t);
        free(h);
    }

    /* Duplicates: every point of a grid three times, in shuffled order. */
    {
        double *g;
        uint32_t ng;
        char msg[256];
        if (dd_gen("grid", 125, 1, &g, &ng, msg, sizeof msg) == DD_OK) {
            double *d = malloc(3 * sizeof(double) * 3 * ng);
            tl_rng r = {99};
            for (uint32_t i = 0; i < 3 * ng; i++) {
                uint32_t j = (uint32_t)tl_int(&r, 0, ng - 1);
                memcpy(d + 3 * i, g + 3 * j, 3 * sizeof(double));
            }
            compare(&st, "duplicates", d, 3 * ng);
            dd_tri *t;
            dd_create(&t, d, 3 * ng, msg, sizeof msg);
            uint32_t distinct = 0;
            for (uint32_t i = 0; i < 3 * ng; i++) distinct += dd_alias(t, i) == i;
            tl_check(&st, t && dd_num_vertices(t) == distinct &&
                              dd_num_duplicates(t) == 3 * ng - distinct,
                     "build/duplicates/counted", "vertices %u, duplicates %u, distinct %u",
                     t ? dd_num_vertices(t) : 0, t ? dd_num_duplicates(t) : 0, distinct);
            /* every alias is the first occurrence of its point */
            int first_ok = 1;
            for (uint32_t i = 0; t && i < 3 * ng; i++) {
                uint32_t a = dd_alias(t, i);
                if (memcmp(d + 3 * a, d + 3 * i, 3 * sizeof(double))) first_ok = 0;
                for (uint32_t j = 0; j < a; j++)
                    if (!memcmp(d + 3 * j, d + 3 * i, 3 * sizeof(double))) first_ok = 0;
            }
            tl_check(&st, first_ok, "build/duplicates/first-kept", "an alias is not the first occurrence");
            dd_free(t);
            free(d);
            free(g);
        }
    }
    return tl_finish(&st);
}
