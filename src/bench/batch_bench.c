/*
 * batch_bench.c -- `dtdel batch-bench`: the whole-array calls against
 * CGAL's best for a batch, in the same run, each result compared with
 * CGAL's simplex for simplex.  What make bench writes to
 * results/batch.txt, one line a row:
 *   insert-many: M new uniform points into N: dtdel A us a point, CGAL
 *     insert(first, last) B us (Rx); identical to CGAL: yes|NO
 *     (dd_insert_many against CGAL's range insertion, which sorts the
 *     batch spatially itself; default M = 5*10^4, N = 2*10^5);
 *   locate-many: Q queries in N uniform points: dtdel A us a query, CGAL
 *     spatial_sort + hinted locate B us (Rx); identical to CGAL: yes|NO
 *     (dd_locate_many against CGAL::spatial_sort of the queries, then
 *     locate(p, hint) hinted by the last answer; queries uniform in
 *     [0.02, 0.98]^3, inside the hull for large N, so that each answer is
 *     one cell; outside the hull an infinite cell on both sides agrees, as
 *     several may see the point; default Q = 10^6);
 *   winsert-many: M new wuniform weighted points into N: dtdel A us a
 *     point, CGAL Regular_triangulation_3 insert(first, last) B us (Rx);
 *     identical to CGAL: yes|NO (hidden points kept);
 *   wmove-many: N wuniform weighted points, P passes of a step of 5% of
 *     the mean spacing: dtdel A us a move, CGAL move B us (Rx); identical
 *     to CGAL: yes|NO (K moves ...) (every vertex of a pass moved by
 *     dd_move_many, against CGAL's move() loop in input order,
 *     cgal_rbench.h's reference: move() where it gives the regular
 *     triangulation of the moved set, else remove() then insert(); a
 *     vertex an earlier move of the loop hid cannot be moved there: K
 *     such, CGAL's time per move made; the result compared with CGAL's
 *     regular triangulation of the moved points, built whole).
 * The weighted rows compare cells and hidden sets.
 */
#include "bench/bench.h"
#include "cgal/cgal_batch.h"
#include "cgal/cgal_rbench.h"
#include "cgal/cgal_regular.h"
#include "dtdel/alloc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct bb_opts {
    uint64_t n, m, q, nw, passes, seed;
} bb_opts;

/* Whether t's cells are g's. */
static int same_as_cgalb(const dd_tri *t, const dd_cgalb *g)
{
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    const int same = dd_canonical(t, &a, &na) == DD_OK && !dd_cgalb_canonical(g, &b, &nb) &&
                     same_canonical(a, na, b, nb);
    dd_mfree(a), dd_mfree(b);
    return same;
}

/* N points (weighted when w), then M more, built on both sides from the
 * first N: 0, or 1 after a message.                                     */
static int build_pair(const char *ds, uint32_t n, uint32_t m, uint64_t seed, double **p, double **w, dd_tri **t,
                      dd_cgalb **g)
{
    uint32_t np = 0;
    char msg[256];
    *t = NULL, *g = NULL, *p = NULL;
    dd_status s = w ? dd_gen_weighted(ds, n + m, seed, p, w, &np, msg, sizeof msg)
                    : dd_gen(ds, n + m, seed, p, &np, msg, sizeof msg);
    if (s != DD_OK || np != n + m) {
        fprintf(stderr, "dtdel batch-bench: %s\n", s != DD_OK ? msg : "the dataset gave too few points");
        return 1;
    }
    if (dd_create_ex(t, *p, w ? *w : NULL, n, 0, msg, sizeof msg) != DD_OK ||
        !(*g = dd_cgalb_build(*p, w ? *w : NULL, n))) {
        fprintf(stderr, "dtdel batch-bench: cannot build the triangulations\n");
        return 1;
    }
    return 0;
}

static int insert_many_row(const bb_opts *o, int weighted)
{
    double *p = NULL, *w = NULL;
    dd_tri *t;
    dd_cgalb *g;
    const uint32_t n = (uint32_t)o->n, m = (uint32_t)o->m;
    int rc = build_pair(weighted ? "wuniform" : "uniform", n, m, o->seed + 5, &p, weighted ? &w : NULL, &t, &g);
    uint32_t *idx = rc ? NULL : dd_malloc((size_t)m * sizeof *idx);
    double theirs = 0;
    rc = rc || !idx;
    const double t0 = now_seconds();
    rc = rc || dd_insert_many(t, p + 3 * (size_t)n, w ? w + n : NULL, m, idx, NULL) != DD_OK;
    const double ours = now_seconds() - t0;
    rc = rc || dd_cgalb_insert_range(g, p + 3 * (size_t)n, w ? w + n : NULL, m, n, &theirs);
    for (uint32_t i = 0; !rc && i < m; i++) rc = idx[i] != n + i;   /* no duplicates: the next indices */
    if (!rc) {
        const int same = same_as_cgalb(t, g);
        if (weighted)
            printf("winsert-many: %u new wuniform weighted points into %u: dtdel %.2f us a point, CGAL "
                   "Regular_triangulation_3 insert(first, last) %.2f us (%.1fx); identical to CGAL: %s\n",
                   m, n, 1e6 * ours / m, 1e6 * theirs / m, theirs / ours, same ? "yes" : "NO");
        else
            printf("insert-many: %u new uniform points into %u: dtdel %.2f us a point, CGAL insert(first, last) "
                   "%.2f us (%.1fx); identical to CGAL: %s\n",
                   m, n, 1e6 * ours / m, 1e6 * theirs / m, theirs / ours, same ? "yes" : "NO");
        rc = !same;
    }
    dd_free(t);
    dd_cgalb_free(g);
    dd_mfree(p), dd_mfree(w), dd_mfree(idx);
    return rc;
}

static int locate_many_row(const bb_opts *o)
{
    double *p = NULL;
    dd_tri *t;
    dd_cgalb *g;
    const uint32_t n = (uint32_t)o->n;
    const size_t q = (size_t)o->q;
    int rc = build_pair("uniform", n, 0, o->seed + 7, &p, NULL, &t, &g);
    double *qs = rc ? NULL : dd_malloc(3 * q * sizeof *qs);
    dd_cell_id *cells = rc ? NULL : dd_malloc(q * sizeof *cells);
    int32_t *ours4 = rc ? NULL : dd_malloc(4 * q * sizeof *ours4), *theirs4 = rc ? NULL : dd_malloc(4 * q * sizeof *theirs4);
    rc = rc || !qs || !cells || !ours4 || !theirs4;
    uint64_t x = o->seed * 0x9E3779B97F4A7C15ull | 1;
    for (size_t i = 0; !rc && i < 3 * q; i++) qs[i] = 0.02 + 0.96 * rand_below(&x, 1u << 30) / (double)(1u << 30);
    double theirs = 0;
    const double t0 = now_seconds();
    rc = rc || dd_locate_many(t, qs, q, cells) != DD_OK;
    const double ours = now_seconds() - t0;
    rc = rc || dd_cgalb_locate_sorted(g, qs, q, theirs4, &theirs) || dd_cells_vertices(t, cells, q, ours4) != DD_OK;
    size_t differ = 0;
    for (size_t i = 0; !rc && i < q; i++) {
        int32_t *a = ours4 + 4 * i, *b = theirs4 + 4 * i;
        int32_t sa[4], sb[4];
        memcpy(sa, a, sizeof sa), memcpy(sb, b, sizeof sb);
        for (int j = 1; j < 4; j++)
            for (int k = j; k > 0 && sa[k - 1] > sa[k]; k--) { int32_t s = sa[k]; sa[k] = sa[k - 1]; sa[k - 1] = s; }
        for (int j = 1; j < 4; j++)
            for (int k = j; k > 0 && sb[k - 1] > sb[k]; k--) { int32_t s = sb[k]; sb[k] = sb[k - 1]; sb[k - 1] = s; }
        differ += memcmp(sa, sb, sizeof sa) != 0 && !(sa[0] < 0 && sb[0] < 0);   /* outside: hull facets */
    }
    if (!rc)
        printf("locate-many: %zu queries in %u uniform points: dtdel %.3f us a query, CGAL spatial_sort + hinted "
               "locate %.3f us (%.1fx); identical to CGAL: %s\n",
               q, n, 1e6 * ours / (double)q, 1e6 * theirs / (double)q, theirs / ours, differ ? "NO" : "yes");
    rc = rc || differ;
    dd_free(t);
    dd_cgalb_free(g);
    dd_mfree(p), dd_mfree(qs), dd_mfree(cells), dd_mfree(ours4), dd_mfree(theirs4);
    return rc;
}

/* Whether t's cells and hidden set are those of CGAL's regular
 * triangulation built from t's points now (every index a point).       */
static int same_as_rt_of_points(const dd_tri *t)
{
    const uint32_t np = dd_num_input(t);
    double *p = dd_malloc(3 * (size_t)np * sizeof *p), *w = dd_malloc((size_t)np * sizeof *w);
    dd_cgal_rt *c = p && w && dd_points(t, p, w) == DD_OK ? dd_cgal_rt_build(p, w, np, 0) : NULL;
    int32_t *a = NULL, *b = NULL;
    uint32_t *ha = NULL, *hb = NULL;
    size_t na = 0, nb = 0, nha = 0, nhb = 0;
    int same = c && dd_canonical(t, &a, &na) == DD_OK && !dd_cgal_rt_canonical(c, &b, &nb) &&
               same_canonical(a, na, b, nb) && dd_hidden(t, &ha, &nha) == DD_OK && !dd_cgal_rt_hidden(c, &hb, &nhb) &&
               nha == nhb && (!nha || !memcmp(ha, hb, nha * sizeof *ha));
    dd_mfree(a), dd_mfree(b), dd_mfree(ha), dd_mfree(hb), dd_mfree(p), dd_mfree(w);
    dd_cgal_rt_free(c);
    return same;
}

static int wmove_many_row(const bb_opts *o)
{
    double *p = NULL, *w = NULL;
    uint32_t np = 0;
    char msg[256];
    dd_tri *t = NULL;
    if (dd_gen_weighted("wuniform", (uint32_t)o->nw, o->seed + 9, &p, &w, &np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel batch-bench: %s\n", msg);
        return 1;
    }
    dd_cgal_rb *c = dd_cgal_rb_build(p, w, np, 0);
    uint32_t *vs = dd_malloc((size_t)np * sizeof *vs);
    double *to = dd_malloc(3 * (size_t)np * sizeof *to), *tw = dd_malloc((size_t)np * sizeof *tw);
    int rc = !c || !vs || !to || !tw || dd_create_ex(&t, p, w, np, 0, msg, sizeof msg) != DD_OK;
    const double h = 0.05 * cbrt(1.0 / np);
    uint64_t x = o->seed * 0xD1B54A32D192ED03ull | 1, moves = 0, skipped = 0;
    double ours = 0, theirs = 0;
    for (uint64_t pass = 0; !rc && pass < o->passes; pass++) {
        uint32_t m = 0;                       /* the vertices now, in input order */
        for (uint32_t i = 0; i < np; i++) {
            if (!dd_is_vertex(t, i)) continue;
            double q[3];
            dd_point(t, i, q);
            vs[m] = i;
            for (int k = 0; k < 3; k++) to[3 * (size_t)m + k] = q[k] + h * (2.0 * rand_below(&x, 1u << 30) / (1u << 30) - 1);
            dd_weight(t, i, &tw[m]);
            m++;
        }
        const double t0 = now_seconds();
        rc = dd_move_many(t, vs, to, NULL, m) != DD_OK;
        ours += now_seconds() - t0;
        for (uint32_t k = 0; !rc && k < m; k++) {
            double secs = 0;
            int fb;
            if (dd_cgal_rb_state(c, vs[k]) != DD_RB_VERTEX) { skipped++; continue; }   /* hidden by an earlier move */
            rc = dd_cgal_rb_move(c, vs[k], to + 3 * (size_t)k, tw[k], &secs, &fb) != 0;
            theirs += secs;
        }
        moves += m;
    }
    if (!rc) {
        const int same = same_as_rt_of_points(t);
        printf("wmove-many: %u wuniform weighted points, %llu passes of a step of 5%% of the mean spacing: dtdel %.2f us "
               "a move, CGAL move %.2f us (%.1fx); identical to CGAL: %s (%llu moves CGAL's loop could not make: "
               "hidden by an earlier one)\n",
               np, (unsigned long long)o->passes, 1e6 * ours / (double)moves, 1e6 * theirs / (double)(moves - skipped),
               theirs / ours * (double)moves / (double)(moves - skipped), same ? "yes" : "NO", (unsigned long long)skipped);
        rc = !same;
    }
    dd_free(t);
    dd_cgal_rb_free(c);
    dd_mfree(p), dd_mfree(w), dd_mfree(vs), dd_mfree(to), dd_mfree(tw);
    return rc;
}

int cmd_batch_bench(int argc, char **argv)
{
    bb_opts o = {200000, 50000, 1000000, 100000, 2, 1};
    const num_opt opts[] = {{NULL, &o.n},           {"--inserts", &o.m}, {"--queries", &o.q},
                            {"--weighted", &o.nw}, {"--passes", &o.passes}, {"--seed", &o.seed}};
    int rc = parse_num_opts("batch-bench", argc, argv, opts, (int)(sizeof opts / sizeof *opts));
    if (rc) return rc;
    if (o.n < 8 || o.nw < 8 || o.m < 1 || o.q < 1)
        return usage_error("batch-bench", "N and --weighted must be at least 8, --inserts and --queries 1%s", "");
    rc |= insert_many_row(&o, 0);
    fflush(stdout);
    rc |= locate_many_row(&o);
    fflush(stdout);
    rc |= insert_many_row(&o, 1);
    fflush(stdout);
    rc |= wmove_many_row(&o);
    return rc ? EXIT_INPUT : 0;
}
