/*
 * link.c -- the link DT and LINKDTDELETE (paper 4.1; see link.h).
 *
 * Deleting p of link degree k leaves a hole bounded by the ring u_0..u_k-1
 * of p's neighbours (in the orientation of the link triangles).  The hole
 * is re-triangulated by clipping Delaunay ears: the ear (a, b, c) of three
 * consecutive ring vertices is a triangle of the new link iff
 *   - it is convex: the tetrahedron (a, b, c, q) is positively oriented
 *     (for an ear through the infinite vertex, whose tetrahedron is a hull
 *     facet of Q with the infinite vertex, convex means p lies beyond that
 *     facet, i.e. p is in conflict with it: deleting p exposes exactly the
 *     hull facets p saw); and
 *   - it is empty: no other ring vertex is in conflict with (a, b, c, q).
 * A clipped ear is a triangle of the unique (perturbed) Delaunay link, and
 * the rest of the hole is the Delaunay triangulation of the smaller ring.
 * Degree 3 needs one convexity test; degree 4 one ear test; 5 to 12 an ear
 * search over a fixed array on the stack; larger holes (and the hole into
 * which the infinite vertex enters) go through fill_by_dt.
 */
#include "delete/link.h"
#include "delete/delete.h"
#include "dtdel/alloc.h"
#include "mesh/hidden.h"

#include <stdlib.h>
#include <string.h>

void dd_link_free(dd_link *l)
{
    dd_mfree(l->lv); dd_mfree(l->ln); dd_mfree(l->ltri); dd_mfree(l->deg);
    dd_mfree(l->ring); dd_mfree(l->ring_tri); dd_mfree(l->ring_out); dd_mfree(l->newtri);
    dd_mfree(l->rpos); dd_mfree(l->rmark);
    dd_tri_destroy(l->scratch);
    memset(l, 0, sizeof *l);
}

/* Sizes l's arrays for d: per star cell (one link triangle each), per
 * vertex id of d->t, and per ring (the neighbours of a link vertex, at
 * most d->nbr.n + 1, the infinite vertex included).                   */
static dd_status fit_arrays(dd_link *l, const dd_del *d)
{
    const size_t u = sizeof(uint32_t), n = d->star.n, nv = d->t->cap_v, r = d->nbr.n + 2;
    if (l->cap < n) {
        if (dd_grow(&l->lv, 3 * n, u) || dd_grow(&l->ln, 3 * n, u)) return DD_ERR_NOMEM;
        l->cap = (uint32_t)n;
    }
    if (l->vcap < nv) {
        if (dd_grow(&l->ltri, nv, u) || dd_grow(&l->deg, nv, u) || dd_grow(&l->rpos, nv, u) ||
            dd_grow(&l->rmark, nv, u))
            return DD_ERR_NOMEM;
        memset(l->rmark, 0, nv * u);
        l->vcap = (uint32_t)nv;
    }
    if (l->ring_cap < r) {
        if (dd_grow(&l->ring, r, u) || dd_grow(&l->ring_tri, r, u) || dd_grow(&l->ring_out, r, u) ||
            dd_grow(&l->newtri, 4 * r + 12, u))
            return DD_ERR_NOMEM;
        l->ring_cap = (uint32_t)r;
    }
    return DD_OK;
}

dd_status dd_link_extract(dd_link *l, dd_del *d)
{
    dd_tri *t = d->t;
    uint32_t n = (uint32_t)d->star.n;
    if (fit_arrays(l, d) != DD_OK) return DD_ERR_NOMEM;
    /* Star slot of a cell: through its stamp (base + slot) when the star
     * fits in one pass's marks, else through its link triangle in the
     * link-triangle hash (dd_del_link_hash).                              */
    int by_stamp = n <= DD_EPOCH_STEP_MAX;
    if (!by_stamp) {
        dd_status s = dd_del_link_hash(d);
        if (s != DD_OK) return s;
    }
    dd_mark base = by_stamp ? dd_new_epoch(t, n) : 0;
    for (uint32_t k = 0; k < n; k++) {
        uint32_t c = d->star.a[k], *w = l->lv + 3 * k;
        int i = dd_index_of(t, c, d->q);
        for (int m = 0; m < 3; m++) w[m] = dd_tv(t, c)[(uint32_t)dd_facet[i][m]];
        if (by_stamp) t->stamp[c] = (dd_mark)(base + k);
    }
    for (size_t j = 0; j < d->nbr.n; j++) l->deg[d->nbr.a[j]] = 0;
    for (uint32_t k = 0; k < n; k++) {
        uint32_t c = d->star.a[k];
        int i = dd_index_of(t, c, d->q);
        for (uint32_t m = 0; m < 3; m++) {
            /* across the edge opposite lv[3k+m]: the star cell across the
             * cell facet opposite that vertex                              */
            uint32_t nb = dd_tn(t, c)[(uint32_t)dd_facet[i][m]] >> 2, sl;
            if (by_stamp) {
                sl = (uint32_t)(dd_mark)(t->stamp[nb] - base);
            } else {
                int inb = dd_index_of(t, nb, d->q);
                if (inb < 0) return DD_ERR_INTERNAL;
                const uint32_t *u = dd_tv(t, nb);
                sl = dd_trihash_get(&d->lhash, u[inb == 0], u[inb <= 1 ? 2 : 1], u[inb <= 2 ? 3 : 2]);
            }
            if (sl >= n) return DD_ERR_INTERNAL;
            uint32_t x = l->lv[3 * k + (m + 1) % 3], y = l->lv[3 * k + (m + 2) % 3];
            uint32_t j = 0;
            while (j < 3 && (l->lv[3 * sl + j] == x || l->lv[3 * sl + j] == y)) j++;
            l->ln[3 * k + m] = 3 * sl + j;
            uint32_t w = l->lv[3 * k + m];
            if (w != DD_INF) { l->deg[w]++; l->ltri[w] = k; }
        }
    }
    l->ntri = n;
    l->nnew = 0;
    l->inf_in_link = d->on_hull;
    l->weighted = t->wt != NULL;
    return DD_OK;
}

/* ---- the Delaunay test on the link ------------------------------------- */

/* 1 if point w conflicts with the link tetrahedron (a, b, c, q). */
static int link_conflict(dd_del *d, uint32_t a, uint32_t b, uint32_t c, const double *w)
{
    dd_tri *t = d->t;
    uint32_t v[3] = {a, b, c};
    const double *pts[4];
    int k = -1;
    for (int i = 0; i < 3; i++) {
        if (v[i] == DD_INF) { k = i; pts[i] = NULL; }
        else pts[i] = dd_pt(t, v[i]);
    }
    pts[3] = d->qp;
    return dd_points_conflict(&t->pred, pts, k, -1, w);
}

/* The weighted link (a regular triangulation's, issue 44): 1 if vertex
 * u is in power conflict with the link tetrahedron (a, b, c, q), CGAL's
 * perturbed power test (mesh.c's rule for an infinite one).             */
static int link_power_conflict(dd_del *d, uint32_t a, uint32_t b, uint32_t c, uint32_t u)
{
    dd_tri *t = d->t;
    const uint32_t v[3] = {a, b, c};
    const double *p = dd_pt(t, u), wp = t->wt[u];
    int k = -1;
    for (int i = 0; i < 3; i++)
        if (v[i] == DD_INF) k = i;
    if (k < 0) {
        const double w[5] = {t->wt[a], t->wt[b], t->wt[c], d->qw, wp};
        return dd_power_perturbed(&t->pred, dd_pt(t, a), dd_pt(t, b), dd_pt(t, c), d->qp, p, w) > 0;
    }
    /* (a, b, c, q) with DD_INF at k: its finite facet as dd_facet[k] lists it */
    const uint32_t id[4] = {a, b, c, d->q};
    const uint32_t f0 = id[dd_facet[k][0]], f1 = id[dd_facet[k][1]], f2 = id[dd_facet[k][2]];
    const double w[4] = {t->wt[f0], t->wt[f1], t->wt[f2], wp};
    return dd_power_infinite(&t->pred, dd_pt(t, f0), dd_pt(t, f1), dd_pt(t, f2), p, w) > 0;
}

/* The conflict test of the link: in-sphere, or (pw, a constant of each
 * compiled copy of the ear search) power.                               */
__attribute__((always_inline)) static inline int ear_conflict(dd_del *d, uint32_t a, uint32_t b, uint32_t c,
                                                              uint32_t u, const int pw)
{
    return pw ? link_power_conflict(d, a, b, c, u) : link_conflict(d, a, b, c, dd_pt(d->t, u));
}

/* Is the ear (r[a], r[b], r[c]) of the ring r[0..k) (only the positions in
 * alive[] count) a triangle of the new link?                              */
__attribute__((always_inline)) static inline int ear_ok(dd_del *d, const uint32_t *r, const uint32_t *alive,
                                                        uint32_t n, uint32_t a, uint32_t b, uint32_t c, uint32_t p,
                                                        const int pw)
{
    dd_tri *t = d->t;
    uint32_t x = r[a], y = r[b], z = r[c];
    if (x != DD_INF && y != DD_INF && z != DD_INF) {
        if (dd_orient3d(&t->pred, dd_pt(t, x), dd_pt(t, y), dd_pt(t, z), d->qp) <= 0) return 0;
    } else if (!ear_conflict(d, x, y, z, p, pw)) {
        return 0;
    }
    for (uint32_t m = 0; m < n; m++) {
        uint32_t w = alive[m];
        if (w == a || w == b || w == c || r[w] == DD_INF) continue;
        if (ear_conflict(d, x, y, z, r[w], pw)) return 0;
    }
    return 1;
}

/* Triangulates the ring positions alive[0..n) (cyclic order) into out
 * (triples of ring positions); returns the triangles written.  pw: the
 * power test (a weighted t), a constant of each compiled copy.           */
__attribute__((always_inline)) static inline uint32_t clip_ears_as(dd_del *d, const uint32_t *r, uint32_t *alive,
                                                                   uint32_t n, uint32_t p, uint32_t *out,
                                                                   const int pw)
{
    uint32_t w = 0;
    while (n > 3) {
        uint32_t j = 0;
        if (n == 4) {   /* one test decides between the two diagonals */
            j = ear_ok(d, r, alive, 4, alive[0], alive[1], alive[2], p, pw) ? 1 : 2;
            if (j == 2 && !ear_ok(d, r, alive, 4, alive[1], alive[2], alive[3], p, pw)) return UINT32_MAX;
        } else {
            while (j < n && !ear_ok(d, r, alive, n, alive[(j + n - 1) % n], alive[j], alive[(j + 1) % n], p, pw))
                j++;
            if (j == n) return UINT32_MAX;   /* no ear: infinity must enter */
        }
        out[3 * w] = alive[(j + n - 1) % n];
        out[3 * w + 1] = alive[j];
        out[3 * w + 2] = alive[(j + 1) % n];
        w++;
        memmove(alive + j, alive + j + 1, (n - j - 1) * sizeof *alive);
        n--;
    }
    /* The last triangle must be convex too; if not, infinity must enter. */
    if (!ear_ok(d, r, alive, 3, alive[0], alive[1], alive[2], p, pw)) return UINT32_MAX;
    out[3 * w] = alive[0];
    out[3 * w + 1] = alive[1];
    out[3 * w + 2] = alive[2];
    return w + 1;
}

static uint32_t clip_ears(dd_del *d, const uint32_t *r, uint32_t *alive, uint32_t n, uint32_t p, uint32_t *out)
{
    return clip_ears_as(d, r, alive, n, p, out, 0);
}

static uint32_t clip_ears_power(dd_del *d, const uint32_t *r, uint32_t *alive, uint32_t n, uint32_t p,
                                uint32_t *out)
{
    return clip_ears_as(d, r, alive, n, p, out, 1);
}

static uint32_t rpos_lookup(const dd_link *l, uint32_t v)
{
    if (v == DD_INF) return l->inf_rpos;
    return l->rmark[v] == l->rgen ? l->rpos[v] : DD_NONE;
}

/* The hole re-triangulated through a small 3D DT: the new link triangles
 * in the hole are exactly the triangles of the link of q in DT(ring + q)
 * on the hole's side of the ring (each is Delaunay for the remaining
 * points, and both sets triangulate the same disc).  Used for large holes
 * (expected O(k log k) instead of the O(k^3) worst case of ear search)
 * and when the infinite vertex enters the link (q leaves the interior of
 * the hull of the remaining points: then no finite Delaunay ear exists).
 * The hole side is flooded from the cell holding the ring edge u0 -> u1,
 * across facets through q, never across a ring edge.                     */
static dd_status fill_by_dt(dd_link *l, dd_del *d, uint32_t k, uint32_t *tri, uint32_t *nt)
{
    dd_tri *t = d->t;
    if (!l->scratch && dd_tri_alloc_borrowed(&l->scratch) != DD_OK) return DD_ERR_NOMEM;
    dd_tri *x = l->scratch;
    x->xyz = t->xyz;
    x->v2in = t->v2in;
    x->vcell = d->qdt_vcell;      /* free to use: qdt is not built yet */
    x->wt = t->wt;
    if (t->wt && !x->hid && dd_hidden_init(x, 0) != DD_OK) return DD_ERR_NOMEM;
    dd_clear_cells(x);
    x->qd_point = NULL;
    /* ids: q then the finite ring vertices; four independent ones first */
    uint32_t *ids = l->newtri + 3 * (size_t)(k + 2), n = 0, f = 0;   /* spare room */
    ids[n++] = d->q;
    for (uint32_t j = 0; j < k; j++)
        if (l->ring[j] != DD_INF) ids[n++] = l->ring[j];
    if (dd_find_simplex(&t->pred, t->xyz, ids, n) != DD_OK) {
        /* q and the ring are coplanar: only infinite link tetrahedra, the
         * fan of the finite ring edges around the infinite vertex.        */
        for (uint32_t j = 0; j < k; j++) {
            uint32_t a = l->ring[j], b = l->ring[(j + 1) % k];
            if (a == DD_INF || b == DD_INF) continue;
            tri[3 * f] = DD_INF; tri[3 * f + 1] = a; tri[3 * f + 2] = b;
            f++;
        }
        *nt = f;
        return DD_OK;
    }
    dd_status s = dd_reserve_cells(x, 8 * n + 16);
    if (s == DD_OK) {
        uint32_t b4[4] = {ids[0], ids[1], ids[2], ids[3]};
        dd_make_first_cells(x, b4);
    }
    for (uint32_t j = 4; j < n && s == DD_OK; j++) {
        if (!t->wt) {
            s = dd_insert_vertex(x, ids[j]);
            continue;
        }
        /* q and the ring are vertices of every regular triangulation of a
         * subset holding them (qdt.h): each insertion makes a vertex.    */
        dd_fate fate;
        uint32_t dup;
        s = dd_insert_power(x, ids[j], DD_NONE, 0, &fate, &dup);
        if (s == DD_OK && fate != DD_FATE_VERTEX) s = DD_ERR_INTERNAL;
    }
    if (s != DD_OK) return s;
    /* The seed: the cell around q whose link triangle has the directed edge
     * u0 -> u1 (the link orientation of the facets of mesh.h).            */
    uint32_t q = d->q, seed = DD_NONE, u0 = l->ring[0], u1 = l->ring[1 % k];
    for (uint32_t c = 0; c < x->ncell && seed == DD_NONE; c++) {
        if (dd_tv(x, c)[0] == DD_DEAD) continue;
        int i = dd_index_of(x, c, q);
        if (i < 0) continue;
        for (int m = 0; m < 3; m++)
            if (dd_tv(x, c)[(uint32_t)dd_facet[i][m]] == u0 &&
                dd_tv(x, c)[(uint32_t)dd_facet[i][(m + 1) % 3]] == u1)
                seed = c;
    }
    if (seed == DD_NONE) return DD_ERR_INTERNAL;
    dd_mark ep = dd_new_epoch(x, 1);
    dd_vec *st = &x->stack;
    st->n = 0;
    x->stamp[seed] = ep;
    s = dd_vec_push(st, seed);
    while (s == DD_OK && st->n > 0) {
        uint32_t c = st->a[--st->n];
        int i = dd_index_of(x, c, q);
        const uint32_t *v = dd_tv(x, c);
        if (f >= k) return DD_ERR_INTERNAL;
        for (int m = 0; m < 3; m++) tri[3 * f + (uint32_t)m] = v[dd_facet[i][m]];
        f++;
        for (uint32_t j = 0; j < 4 && s == DD_OK; j++) {
            if ((int)j == i) continue;
            /* the facet opposite j holds q and the edge of the other two */
            uint32_t e[2], ne = 0;
            for (uint32_t m = 0; m < 4; m++)
                if ((int)m != i && m != j) e[ne++] = v[m];
            uint32_t ra = rpos_lookup(l, e[0]), rb = rpos_lookup(l, e[1]);
            if (ra != DD_NONE && rb != DD_NONE && (rb == (ra + 1) % k || ra == (rb + 1) % k)) continue;
            uint32_t nb = dd_tn(x, c)[j] >> 2;
            if (x->stamp[nb] == ep) continue;
            x->stamp[nb] = ep;
            s = dd_vec_push(st, nb);
        }
    }
    *nt = f;
    return s;
}

dd_status dd_link_delete(dd_link *l, dd_del *d, uint32_t p)
{
    /* 1. The ring around p: triangle ring_tri[j] = (p, u_j, u_j+1). */
    uint32_t t0 = l->ltri[p], tt = t0, k = 0;
    if (++l->rgen == 0) { memset(l->rmark, 0, l->vcap * sizeof *l->rmark); l->rgen = 1; }
    l->inf_rpos = DD_NONE;
    do {
        uint32_t m = 0;
        while (m < 3 && l->lv[3 * tt + m] != p) m++;
        if (m == 3 || k >= l->ring_cap) return DD_ERR_INTERNAL;
        uint32_t u = l->lv[3 * tt + (m + 1) % 3];
        l->ring[k] = u;
        if (u == DD_INF) l->inf_rpos = k;
        else { l->rpos[u] = k; l->rmark[u] = l->rgen; }
        l->ring_tri[k] = tt;
        l->ring_out[k] = l->ln[3 * tt + m];
        k++;
        tt = l->ln[3 * tt + (m + 1) % 3] / 3;
    } while (tt != t0);
    if (k < 3) return DD_ERR_INTERNAL;
    d->link_deletions[k < DD_LINKDEG_BUCKETS - 1 ? k : DD_LINKDEG_BUCKETS - 1]++;

    /* 2. Re-triangulate the hole: Delaunay ears, or (once) the fill that
     *    brings in the infinite vertex.                                   */
    uint32_t alive[DD_LINK_EARS_UPTO], *tri = l->newtri, nt = UINT32_MAX;
    if (k <= DD_LINK_EARS_UPTO) {
        for (uint32_t j = 0; j < k; j++) alive[j] = j;
        nt = l->weighted ? clip_ears_power(d, l->ring, alive, k, p, tri) : clip_ears(d, l->ring, alive, k, p, tri);
        if (nt == k - 2)
            for (uint32_t j = 0; j < 3 * nt; j++) tri[j] = l->ring[tri[j]];   /* positions -> ids */
    }
    if (nt != k - 2) {   /* a large hole, or no ear: infinity enters */
        dd_status s = fill_by_dt(l, d, k, tri, &nt);
        if (s != DD_OK) return s;
        if (nt == k && l->inf_rpos == DD_NONE) l->inf_in_link = 1;
        else if (nt != k - 2) return DD_ERR_INTERNAL;
    }

    /* 3. Write them over the old triangles; unused old ones die. */
    for (uint32_t j = 0; j < nt; j++)
        memcpy(l->lv + 3 * (size_t)l->ring_tri[j], tri + 3 * j, 3 * sizeof *tri);
    for (uint32_t j = nt; j < k; j++) l->lv[3 * (size_t)l->ring_tri[j]] = DD_DEAD;
    /* 4. Neighbours: a ring edge u_j -> u_j+1 keeps its outside triangle;
     *    any other edge is shared by two new triangles.                   */
    for (uint32_t j = 0; j < nt; j++) {
        uint32_t s = l->ring_tri[j];
        for (uint32_t m = 0; m < 3; m++) {
            uint32_t x = tri[3 * j + (m + 1) % 3], y = tri[3 * j + (m + 2) % 3];
            uint32_t rx = rpos_lookup(l, x), ry = rpos_lookup(l, y);
            if (rx != DD_NONE && ry != DD_NONE && ry == (rx + 1) % k) {
                uint32_t o = l->ring_out[rx];
                l->ln[3 * s + m] = o;
                l->ln[o] = 3 * s + m;
                continue;
            }
            for (uint32_t jj = 0; jj < nt; jj++) {
                if (jj == j) continue;
                for (uint32_t mm = 0; mm < 3; mm++)
                    if (tri[3 * jj + (mm + 1) % 3] == y && tri[3 * jj + (mm + 2) % 3] == x)
                        l->ln[3 * s + m] = 3 * l->ring_tri[jj] + mm;
            }
        }
    }
    /* 5. Degrees and vertex links: each ring vertex loses p and gains one
     *    per new inner edge (seen once from each end).                    */
    for (uint32_t j = 0; j < k; j++)
        if (l->ring[j] != DD_INF) l->deg[l->ring[j]]--;
    for (uint32_t j = 0; j < nt; j++) {
        uint32_t s = l->ring_tri[j];
        for (uint32_t m = 0; m < 3; m++) {
            uint32_t x = tri[3 * j + m], y = tri[3 * j + (m + 1) % 3];
            if (x == DD_INF) continue;
            l->ltri[x] = s;
            uint32_t rx = rpos_lookup(l, x), ry = rpos_lookup(l, y);
            if (!(rx != DD_NONE && ry != DD_NONE && ry == (rx + 1) % k)) l->deg[x]++;
        }
    }
    l->deg[p] = 0;
    l->ltri[p] = DD_NONE;
    l->nnew = nt;
    l->nring = k;
    return DD_OK;
}
