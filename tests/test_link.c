/*
 * test_link.c -- LINKDTDELETE on its own (paper 4.1): after each deletion
 * of a link vertex, the link equals the link of q in DT(Q_i-1) computed
 * from scratch (Q_i-1 = q and the link vertices not yet deleted), on
 * random small cases: uniform points, cospherical integer points, grids
 * and hull vertices (the infinite vertex in the link).
 */
#include "testlib.h"
#include "delete/delete.h"
#include "delete/link.h"
#include "delete/bdst.h"
#include "../datasets/datasets.h"

/* An oriented triangle as input indices, rotated so the smallest leads
 * (-1 for the infinite vertex, which then always leads).                 */
typedef struct otri { int32_t v[3]; } otri;

static otri norm(int32_t a, int32_t b, int32_t c)
{
    otri t = {{a, b, c}};
    while (t.v[0] > t.v[1] || t.v[0] > t.v[2]) {
        int32_t s = t.v[0]; t.v[0] = t.v[1]; t.v[1] = t.v[2]; t.v[2] = s;
    }
    return t;
}

static int cmp_otri(const void *x, const void *y)
{
    const otri *a = x, *b = y;
    for (int i = 0; i < 3; i++)
        if (a->v[i] != b->v[i]) return a->v[i] < b->v[i] ? -1 : 1;
    return 0;
}

/* The link of input vertex qi in DT(pts restricted to keep[]), as oriented
 * triangles in the input indices of pts.                                  */
static size_t scratch_link(const double *pts, const uint32_t *keep, uint32_t nk, uint32_t qi, otri *out)
{
    double *sub = malloc(3 * sizeof(double) * nk);
    uint32_t qs = UINT32_MAX;
    for (uint32_t i = 0; i < nk; i++) {
        memcpy(sub + 3 * i, pts + 3 * keep[i], 3 * sizeof(double));
        if (keep[i] == qi) qs = i;
    }
    dd_tri *t;
    char msg[256];
    size_t n = 0;
    if (dd_create(&t, sub, nk, msg, sizeof msg) == DD_OK) {
        dd_del *d;
        if (dd_del_star_of(t, qs, &d) == DD_OK) {
            for (size_t k = 0; k < d->star.n; k++) {
                uint32_t c = d->star.a[k];
                int i = dd_index_of(t, c, d->q);
                int32_t w[3];
                for (int m = 0; m < 3; m++) {
                    int32_t x = dd_input_index(t, dd_tv(t, c)[(uint32_t)dd_facet[i][m]]);
                    w[m] = x < 0 ? -1 : (int32_t)keep[x];
                }
                out[n++] = norm(w[0], w[1], w[2]);
            }
        }
        dd_free(t);
    }
    free(sub);
    qsort(out, n, sizeof *out, cmp_otri);
    return n;
}

static size_t our_link(const dd_tri *t, const dd_link *l, otri *out)
{
    size_t n = 0;
    for (uint32_t s = 0; s < l->ntri; s++) {
        if (l->lv[3 * s] == DD_DEAD) continue;
        out[n++] = norm(dd_input_index(t, l->lv[3 * s]), dd_input_index(t, l->lv[3 * s + 1]),
                        dd_input_index(t, l->lv[3 * s + 2]));
    }
    qsort(out, n, sizeof *out, cmp_otri);
    return n;
}

/* Checks the link structure: symmetric neighbours sharing their edge, and
 * degrees equal to the number of triangles around each vertex.           */
static int link_consistent(const dd_link *l, char *why, size_t whylen)
{
    for (uint32_t s = 0; s < l->ntri; s++) {
        if (l->lv[3 * s] == DD_DEAD) continue;
        for (uint32_t m = 0; m < 3; m++) {
            uint32_t e = l->ln[3 * s + m], u = e / 3;
            if (l->ln[e] != 3 * s + m || l->lv[3 * u] == DD_DEAD) {
                snprintf(why, whylen, "triangle %u edge %u: neighbour not symmetric", s, m);
                return 0;
            }
            uint32_t x = l->lv[3 * s + (m + 1) % 3], y = l->lv[3 * s + (m + 2) % 3];
            uint32_t ux = l->lv[3 * u + (e % 3 + 1) % 3], uy = l->lv[3 * u + (e % 3 + 2) % 3];
            if (ux != y || uy != x) {
                snprintf(why, whylen, "triangle %u edge %u: neighbour does not share the edge reversed", s, m);
                return 0;
            }
        }
    }
    return 1;
}

/* The degree-3 spanning tree of the link of qi (grr-brio's guide): it
 * spans the link vertices, uses link edges only, has maximum degree 3 and
 * its BFS order starts at the requested root.                            */
static int tree_ok(const double *pts, uint32_t n, uint32_t qi, char *why, size_t whylen)
{
    dd_tri *t;
    char msg[256];
    if (dd_create(&t, pts, n, msg, sizeof msg) != DD_OK) return 1;
    dd_del *d;
    int ok = 1;
    if (dd_del_star_of(t, qi, &d) != DD_OK) { dd_free(t); return 1; }
    uint32_t nt = (uint32_t)d->star.n, nv = 0;
    uint32_t *tri = malloc(3 * nt * sizeof *tri), *ids = malloc((nt + 4) * sizeof *ids);
    uint32_t *parent = malloc((nt + 4) * sizeof *parent), *order = malloc((nt + 4) * sizeof *order);
    for (uint32_t k = 0; k < nt; k++) {
        uint32_t c = d->star.a[k];
        int i = dd_index_of(t, c, d->q);
        for (int m = 0; m < 3; m++) {
            uint32_t w = dd_tv(t, c)[(uint32_t)dd_facet[i][m]], j = 0;
            while (j < nv && ids[j] != w) j++;
            if (j == nv) ids[nv++] = w;
            tri[3 * k + (uint32_t)m] = j;
        }
    }
    dd_bdst_ws *ws = dd_bdst_ws_new();
    int rc = dd_bdst(ws, tri, nt, nv, 0, parent, order);
    if (rc != 0) { snprintf(why, whylen, "dd_bdst failed (%d) on a link of %u vertices", rc, nv); ok = 0; }
    uint32_t *deg = calloc(nv, sizeof *deg);
    for (uint32_t v = 0; ok && v < nv; v++) {
        if (v == 0) { ok = parent[v] == UINT32_MAX && order[0] == 0; continue; }
        uint32_t p = parent[v];
        if (p >= nv) { ok = 0; snprintf(why, whylen, "vertex %u has no parent", v); break; }
        deg[v]++; deg[p]++;
        int edge = 0;    /* p-v must be a link edge */
        for (uint32_t k = 0; k < nt && !edge; k++)
            for (int m = 0; m < 3; m++)
                if (tri[3 * k + (uint32_t)m] == v && tri[3 * k + (uint32_t)(m + 1) % 3] == p) edge = 1;
        if (!edge) { ok = 0; snprintf(why, whylen, "tree edge %u-%u is not a link edge", p, v); }
    }
    for (uint32_t v = 0; ok && v < nv; v++) {
        if (deg[v] > 3) { ok = 0; snprintf(why, whylen, "vertex %u has tree degree %u", v, deg[v]); }
        /* spanning: following parents from v reaches the root */
        uint32_t x = v, steps = 0;
        while (x != 0 && steps++ <= nv) x = parent[x];
        if (x != 0) { ok = 0; snprintf(why, whylen, "vertex %u is not connected to the root", v); }
    }
    free(deg); free(tri); free(ids); free(parent); free(order);
    dd_bdst_ws_free(ws);
    dd_free(t);
    return ok;
}

static void run_case(tl_state *st, const char *name, const double *pts, uint32_t n, uint32_t qi,
                     tl_rng *r, long *checks, long *bad, char *why, size_t whylen)
{
    dd_tri *t;
    char msg[256];
    if (dd_create(&t, pts, n, msg, sizeof msg) != DD_OK) return;
    dd_del *d;
    dd_link l;
    memset(&l, 0, sizeof l);
    if (dd_del_star_of(t, qi, &d) != DD_OK || dd_link_extract(&l, d) != DD_OK) {
        dd_free(t);
        return;
    }
    /* keep = q and its finite neighbours (input indices) */
    uint32_t nk = 0, *keep = malloc((d->nbr.n + 1) * sizeof *keep);
    keep[nk++] = qi;
    for (size_t k = 0; k < d->nbr.n; k++) keep[nk++] = (uint32_t)dd_input_index(t, d->nbr.a[k]);
    otri *a = malloc(8 * (nk + 8) * sizeof *a), *b = malloc(8 * (nk + 8) * sizeof *b);
    while (nk > 5) {
        /* delete a random finite link vertex; keep 4 finite ones at least */
        uint32_t j = 1 + (uint32_t)tl_int(r, 0, nk - 2);
        uint32_t victim = keep[j];
        /* Would DT of the rest be flat?  Then stop: no link to compare.   */
        keep[j] = keep[--nk];
        dd_status s = dd_link_delete(&l, d, t->in2v[victim]);
        (*checks)++;
        size_t na = s == DD_OK ? our_link(t, &l, a) : 0;
        size_t nb = scratch_link(pts, keep, nk, qi, b);
        if (nb == 0) break;                       /* the rest is coplanar */
        char w2[200] = "";
        int ok = s == DD_OK && na == nb && !memcmp(a, b, na * sizeof *a) && link_consistent(&l, w2, sizeof w2);
        if (!ok && (*bad)++ == 0)
            snprintf(why, whylen, "%s: deleting %u from the link of %u: %s %zu vs %zu triangles %s", name,
                     victim, qi, s == DD_OK ? "ok" : "FAILED", na, nb, w2);
        if (!ok) break;
    }
    (void)st;
    free(a); free(b); free(keep);
    dd_link_free(&l);
    dd_free(t);
}

/* dd_unmake_cells (mesh.c), which gives back the cells gift wrapping made
 * for a fill it does not keep (wrap/run.c, w_drop_fill): after deleting and
 * re-inserting vertices (a free list of some cells), k cells are made,
 * from the free list and, past it, from the end, then unmade: the free
 * list (cell by cell), the cell counts and dd_check as before; then the
 * same k cells are made again, in the same order.                     */
static void unmake_cells(tl_state *st, uint32_t k)
{
    char name[64], msg[256];
    snprintf(name, sizeof name, "mesh/unmake-cells-%u", k);
    uint32_t n;
    double *p = NULL;
    dd_tri *t;
    if (dd_gen("uniform", 400, 1, &p, &n, msg, sizeof msg) != DD_OK || dd_create(&t, p, n, msg, sizeof msg) != DD_OK) {
        tl_check(st, 0, name, "setup failed");
        free(p);
        return;
    }
    tl_courses cs = tl_courses_all();
    for (uint32_t v = 0; v < 40; v += 7) {            /* free cells, then none */
        tl_course_next(&cs, t);
        if (dd_delete(t, v) != DD_OK || dd_reinsert(t, v) != DD_OK) break;
    }
    uint32_t before[512], nb = 0, head = t->free_head, nfree = t->nfree, ncell = t->ncell, nlive = t->nlive;
    for (uint32_t c = t->free_head; c != DD_NONE && nb < 512; c = dd_tn(t, c)[0]) before[nb++] = c;
    uint32_t made[2][600];
    int ok = k <= 600 && dd_reserve_cells(t, k) == DD_OK, again = 1;
    for (int round = 0; ok && round < 2; round++) {
        uint32_t ncell0 = t->ncell;
        for (uint32_t i = 0; i < k; i++) {
            made[round][i] = dd_new_cell(t);
            dd_tv(t, made[round][i])[0] = 0;          /* as a fill cell would be */
        }
        dd_unmake_cells(t, made[round], k, ncell0);
        uint32_t nafter = 0;
        for (uint32_t c = t->free_head; c != DD_NONE && nafter < 512 && ok; c = dd_tn(t, c)[0])
            ok = nafter < nb && before[nafter++] == c;
        ok = ok && nafter == nb && t->free_head == head && t->nfree == nfree && t->ncell == ncell &&
             t->nlive == nlive && dd_check(t) == DD_OK;
        if (round == 1) again = !memcmp(made[0], made[1], k * sizeof made[0][0]);
    }
    /* k = 40 within the free list, k = 300 past it                      */
    int kind = k < 100 ? nfree >= k : nfree < k && nfree > 0;
    char unrun[96] = "";
    ok = ok && tl_courses_covered(&cs, unrun, sizeof unrun);
    tl_check(st, ok && again && kind, name, "free list or counts changed, or not the case meant (%u free cells, %u made): %s %s",
             nfree, k, dd_errmsg(t), unrun);
    dd_free(t);
    free(p);
}

int main(int argc, char **argv)
{
    tl_state st = {0, 0};
    int small = argc > 1 && !strcmp(argv[1], "small");
    unmake_cells(&st, 40);
    unmake_cells(&st, 300);
    tl_rng r = {2024};
    struct { const char *ds; uint32_t n; int cases; } sets[] = {
        {"uniform", 60, 300}, {"sphere", 40, 200}, {"cosphere", 60, 200}, {"grid", 64, 200},
        {"grid", 125, 100}, {"moment", 30, 60}, {"moment", 90, 4}, {"helix", 200, 100},
        {"helix", 3000, 3}, {"layers", 50, 100}};
    for (size_t i = 0; i < sizeof sets / sizeof *sets; i++) {
        long trees = 0, badtrees = 0;
        char twhy[200] = "";
        int tcases = small ? 20 : sets[i].cases < 10 ? 10 : 400;
        for (int c = 0; c < tcases; c++) {
            double *p;
            uint32_t np;
            char msg[256];
            if (dd_gen(sets[i].ds, sets[i].n * (c % 2 ? 1 : 4), (uint64_t)c + 7, &p, &np, msg, sizeof msg) != DD_OK) continue;
            uint32_t qi = (uint32_t)tl_int(&r, 0, np - 1);
            trees++;
            if (!tree_ok(p, np, qi, twhy, sizeof twhy)) badtrees++;
            free(p);
        }
        char tname[96];
        snprintf(tname, sizeof tname, "bdst-on-links/%s-%u", sets[i].ds, sets[i].n);
        tl_check(&st, badtrees == 0 && trees > 0, tname, "%ld of %ld trees wrong: %s", badtrees, trees, twhy);
        long checks = 0, bad = 0;
        char why[400] = "";
        int cases = small ? (sets[i].cases >= 10 ? sets[i].cases / 10 : 1) : sets[i].cases;
        for (int c = 0; c < cases; c++) {
            double *p;
            uint32_t np;
            char msg[256];
            if (dd_gen(sets[i].ds, sets[i].n, (uint64_t)c + 1, &p, &np, msg, sizeof msg) != DD_OK) continue;
            /* the uniform sets get a random translation of their points'
             * order by the seed; pick q at random                          */
            uint32_t qi = (uint32_t)tl_int(&r, 0, np - 1);
            run_case(&st, sets[i].ds, p, np, qi, &r, &checks, &bad, why, sizeof why);
            free(p);
        }
        char name[96];
        snprintf(name, sizeof name, "link/%s-%u", sets[i].ds, sets[i].n);
        tl_check(&st, bad == 0 && checks > 0, name, "%ld of %ld link deletions wrong; first: %s", bad, checks, why);
    }
    return tl_finish(&st);
}
