/*
 * grr.c -- GRR-CONSTRUCT (paper 4.2; see grr.h).
 *
 * Owns: the sampling sets (link vertices of degree <= 7, one set per
 * degree; all remaining link vertices; each an array plus a position per
 * vertex, O(1) update) and the sampling rules on them, the removal
 * sequence with its guides, the hash of dummy cells for triangle guides,
 * and guided point location.  Everything is scratch kept in the deletion
 * context and reused.
 */
#include "delete/grr.h"
#include "delete/qdt.h"
#include "dtdel/alloc.h"

#include <stdlib.h>
#include <string.h>

struct dd_grr {
    dd_del *d;
    dd_link link;
    uint32_t *candpos, *rempos;   /* per vertex id: slot in rem, or DD_NONE;
                                     8 * slot + degree in cand[degree]    */
    uint32_t vcap;
    dd_vec cand[DD_LOWDEG + 1];   /* degree <= 7, by degree; base excluded */
    dd_vec rem;                   /* all, base points excluded            */
    dd_vec seq, gv, gt;           /* removal order, vertex guides, triangles */
    dd_vec walk;                  /* scratch for locate_from_vertex          */
    dd_trihash dh;                /* dummy cells by their other 3 vertices   */
    int weighted;                 /* this deletion's t is weighted: the power
                                     tests, chosen once per location       */
};

/* Frees a GRR scratch (the free function of its scratch kind). */
static void grr_free(void *p)
{
    dd_grr *g = p;
    if (!g) return;
    dd_link_free(&g->link);
    dd_mfree(g->candpos); dd_mfree(g->rempos);
    dd_trihash_free(&g->dh);
    for (int k = 0; k <= DD_LOWDEG; k++) dd_vec_free(&g->cand[k]);
    dd_vec_free(&g->rem); dd_vec_free(&g->seq);
    dd_vec_free(&g->gv); dd_vec_free(&g->gt); dd_vec_free(&g->walk);
    dd_mfree(g);
}

/* ---- sampling sets -------------------------------------------------------- */

/* Adds v to the set s (pos[v]: its slot in s, DD_NONE when out), if out. */
static dd_status set_add(dd_vec *s, uint32_t *pos, uint32_t v)
{
    if (pos[v] != DD_NONE) return DD_OK;
    pos[v] = (uint32_t)s->n;
    return dd_vec_push(s, v);
}

/* Takes v out of the set s, if in, the last element moving to its slot. */
static void set_del(dd_vec *s, uint32_t *pos, uint32_t v)
{
    uint32_t i = pos[v];
    if (i == DD_NONE) return;
    uint32_t last = s->a[--s->n];
    s->a[i] = last;
    pos[last] = i;
    pos[v] = DD_NONE;
}

/* The low-degree sets cand[0..DD_LOWDEG]: candpos[v] = 8 * slot + degree
 * while v is in one.                                                    */
_Static_assert(DD_LOWDEG < 8, "grr: a degree must fit the 3 low bits of candpos");

/* Takes v out of its low-degree set, if in one. */
static void cand_del(dd_grr *g, uint32_t v)
{
    uint32_t p = g->candpos[v];
    if (p == DD_NONE) return;
    dd_vec *s = &g->cand[p & 7];
    uint32_t i = p >> 3, last = s->a[--s->n];
    s->a[i] = last;
    g->candpos[last] = i << 3 | (p & 7);
    g->candpos[v] = DD_NONE;
}

/* Puts v (of link degree deg) into cand[deg], out of the set it was in,
 * if another.                                                           */
static dd_status cand_put(dd_grr *g, uint32_t v, uint32_t deg)
{
    uint32_t p = g->candpos[v];
    if (p != DD_NONE) {
        if ((p & 7) == deg) return DD_OK;
        cand_del(g, v);
    }
    dd_vec *s = &g->cand[deg];
    g->candpos[v] = (uint32_t)s->n << 3 | deg;
    return dd_vec_push(s, v);
}

uint32_t dd_grr_degree(const dd_grr *g, uint32_t v) { return g->link.deg[v]; }

/* A random link vertex of degree <= DD_LOWDEG, uniform over them (base
 * points excluded), or DD_NONE when there is none.                     */
static uint32_t random_lowdeg(dd_grr *g)
{
    size_t n = 0;
    for (int k = 0; k <= DD_LOWDEG; k++) n += g->cand[k].n;
    if (!n) return DD_NONE;
    size_t r = dd_del_rand(g->d) % n;
    int k = 0;
    while (r >= g->cand[k].n) r -= g->cand[k++].n;
    return g->cand[k].a[r];
}

/* A random link vertex of the least degree if that is <= DD_LOWDEG,
 * else DD_NONE.                                                         */
static uint32_t random_mindeg(dd_grr *g)
{
    for (int k = 0; k <= DD_LOWDEG; k++)
        if (g->cand[k].n) return g->cand[k].a[dd_del_rand(g->d) % g->cand[k].n];
    return DD_NONE;
}

/* A random remaining link vertex (base points excluded), or DD_NONE. */
static uint32_t random_any(dd_grr *g)
{
    return g->rem.n ? g->rem.a[dd_del_rand(g->d) % g->rem.n] : DD_NONE;
}

/* u, or (a counted fallback) a random remaining vertex when u is none. */
static uint32_t or_any(dd_grr *g, uint32_t u)
{
    if (u != DD_NONE) return u;
    g->d->fallbacks++;
    return random_any(g);
}

uint32_t dd_grr_sample_mindeg(dd_grr *g) { return or_any(g, random_mindeg(g)); }
uint32_t dd_grr_sample_lowdeg(dd_grr *g) { return or_any(g, random_lowdeg(g)); }

/* Writes v's link neighbours (the infinite vertex included) to out, in
 * ring order; returns how many (at most max).                            */
static uint32_t link_neighbours(const dd_grr *g, uint32_t v, uint32_t *out, uint32_t max)
{
    const dd_link *l = &g->link;
    uint32_t t0 = l->ltri[v], t = t0, k = 0;
    do {
        uint32_t m = 0;
        while (m < 3 && l->lv[3 * t + m] != v) m++;
        if (m == 3) break;                       /* broken link: a bug */
        if (k < max) out[k] = l->lv[3 * t + (m + 1) % 3];
        k++;
        t = l->ln[3 * t + (m + 1) % 3] / 3;
    } while (t != t0 && k <= l->ntri);
    return k < max ? k : max;
}

uint32_t dd_grr_sample_edge(dd_grr *g, uint32_t *guide)
{
    uint32_t nb[DD_LOWDEG + 1], u = DD_NONE;
    for (int tries = 0; tries < 8; tries++) {
        u = random_lowdeg(g);
        if (u == DD_NONE) break;
        uint32_t du = dd_grr_degree(g, u), k = link_neighbours(g, u, nb, DD_LOWDEG + 1), ok = 0;
        for (uint32_t j = 0; j < k; j++)
            if (nb[j] != DD_INF && du + dd_grr_degree(g, nb[j]) <= 15) nb[ok++] = nb[j];
        if (ok) {
            *guide = nb[dd_del_rand(g->d) % ok];
            return u;
        }
    }
    g->d->fallbacks++;
    if (u == DD_NONE) u = random_any(g);
    *guide = dd_grr_lowest_neighbour(g, u);
    return u;
}

uint32_t dd_grr_lowest_neighbour(const dd_grr *g, uint32_t v)
{
    const dd_link *l = &g->link;
    uint32_t t0 = l->ltri[v], t = t0, best = DD_NONE;
    uint32_t steps = 0;
    do {
        uint32_t m = 0;
        while (m < 3 && l->lv[3 * t + m] != v) m++;
        if (m == 3) break;                       /* broken link: a bug */
        uint32_t w = l->lv[3 * t + (m + 1) % 3];
        if (w != DD_INF && (best == DD_NONE || l->deg[w] < l->deg[best])) best = w;
        t = l->ln[3 * t + (m + 1) % 3] / 3;
    } while (t != t0 && ++steps <= l->ntri);
    return best;
}

/* Updates the sets after a link deletion of p (ring = p's old neighbours). */
static dd_status update_sets(dd_grr *g, uint32_t p)
{
    cand_del(g, p);
    set_del(&g->rem, g->rempos, p);
    dd_status s = DD_OK;
    const dd_link *l = &g->link;
    for (uint32_t j = 0; j < l->nring && s == DD_OK; j++) {
        uint32_t u = l->ring[j];
        if (u == DD_INF || g->rempos[u] == DD_NONE) continue;   /* base or INF */
        if (l->deg[u] <= DD_LOWDEG) s = cand_put(g, u, l->deg[u]);
        else cand_del(g, u);
    }
    return s;
}

/* Readies g for this deletion: its per-vertex arrays sized, the link of
 * q extracted, the sampling sets filled with every finite neighbour but
 * the base points, the sequence and guides emptied.                   */
static dd_status init(dd_grr *g)
{
    dd_del *d = g->d;
    dd_tri *t = d->t;
    if (g->vcap < t->cap_v) {
        if (dd_grow(&g->candpos, t->cap_v, sizeof *g->candpos) || dd_grow(&g->rempos, t->cap_v, sizeof *g->rempos))
            return DD_ERR_NOMEM;
        g->vcap = t->cap_v;
    }
    g->weighted = t->wt != NULL;
    dd_status s = dd_link_extract(&g->link, d);
    if (s != DD_OK) return s;
    for (int k = 0; k <= DD_LOWDEG; k++) g->cand[k].n = 0;
    g->rem.n = g->seq.n = g->gv.n = g->gt.n = 0;
    for (size_t k = 0; k < d->nbr.n; k++) g->candpos[d->nbr.a[k]] = g->rempos[d->nbr.a[k]] = DD_NONE;
    for (size_t k = 0; k < d->nbr.n && s == DD_OK; k++) {
        uint32_t v = d->nbr.a[k];
        if (v == d->base[0] || v == d->base[1] || v == d->base[2] || v == d->base[3]) continue;
        s = set_add(&g->rem, g->rempos, v);
        if (s == DD_OK && g->link.deg[v] <= DD_LOWDEG) s = cand_put(g, v, g->link.deg[v]);
    }
    return s;
}

/* ---- the dummy-cell hash (triangle guides) ------------------------------ */

/* Registers the dummy cell c of the conflict DT under its three other
 * vertices.  A triple is registered once: a link triangle destroyed by a
 * point never comes back while that point stays.                        */
static dd_status dh_put(dd_grr *g, uint32_t c)
{
    const uint32_t *v = dd_tv(g->d->qdt, c);
    uint32_t k[3], n = 0;
    for (uint32_t i = 0; i < 4; i++)
        if (v[i] != DD_QD) k[n++] = v[i];
    return dd_trihash_put(&g->dh, k[0], k[1], k[2], c);
}

/* The live dummy cell on triangle tri, or DD_NONE. */
static uint32_t dh_get(const dd_grr *g, const uint32_t tri[3])
{
    const dd_tri *x = g->d->qdt;
    uint32_t c = dd_trihash_get(&g->dh, tri[0], tri[1], tri[2]);
    if (c == DD_NONE || dd_tv(x, c)[0] == DD_DEAD || dd_index_of(x, c, DD_QD) < 0) return DD_NONE;
    for (int i = 0; i < 3; i++)            /* still that cell? (cells are recycled) */
        if (dd_index_of(x, c, tri[i]) < 0) return DD_NONE;
    return c;
}

/* ---- guided point location ------------------------------------------------ */

/* The conflict test of the location: the in-sphere test, or (w, a
 * constant of each compiled copy) the power test of qdt.h.           */
__attribute__((always_inline)) static inline int locate_conflict(dd_del *d, uint32_t c, uint32_t p, const int w)
{
    dd_tri *x = d->qdt;
    return w ? dd_qdt_power_conflict(d, c, dd_pt(x, p), x->wt[p]) : dd_cell_conflict(x, c, dd_pt(x, p));
}

/* A cell around vertex g in conflict with vertex p (see grr.h), or
 * DD_NONE; w as locate_conflict's.                                      */
__attribute__((always_inline)) static inline uint32_t locate_from_vertex_as(dd_grr *gr, uint32_t g, uint32_t p,
                                                                           const int w)
{
    dd_tri *x = gr->d->qdt;
    uint32_t c0 = x->vcell[g];
    if (c0 >= x->ncell || dd_tv(x, c0)[0] == DD_DEAD || dd_index_of(x, c0, g) < 0) return DD_NONE;
    dd_mark ep = dd_new_epoch(x, 1);
    gr->walk.n = 0;
    x->stamp[c0] = ep;
    if (dd_vec_push(&gr->walk, c0) != DD_OK) return DD_NONE;
    for (size_t k = 0; k < gr->walk.n; k++) {
        uint32_t c = gr->walk.a[k];
        gr->d->locate_steps++;
        if (locate_conflict(gr->d, c, p, w)) return c;
        for (uint32_t j = 0; j < 4; j++) {
            if (dd_tv(x, c)[j] == g) continue;
            uint32_t nb = dd_tn(x, c)[j] >> 2;
            if (x->stamp[nb] == ep) continue;
            x->stamp[nb] = ep;
            if (dd_vec_push(&gr->walk, nb) != DD_OK) return DD_NONE;
        }
    }
    return DD_NONE;
}

/* Any cell in conflict with p, by scanning (the fallback). */
__attribute__((always_inline)) static inline uint32_t locate_by_scan_as(dd_grr *gr, uint32_t p, const int w)
{
    dd_tri *x = gr->d->qdt;
    for (uint32_t c = 0; c < x->ncell; c++) {
        if (dd_tv(x, c)[0] == DD_DEAD) continue;
        gr->d->locate_steps++;
        if (locate_conflict(gr->d, c, p, w)) return c;
    }
    return DD_NONE;
}

/* The two compiled copies of each location, chosen per point. */
static uint32_t locate_from_vertex_plain(dd_grr *gr, uint32_t g, uint32_t p) { return locate_from_vertex_as(gr, g, p, 0); }
static uint32_t locate_from_vertex_power(dd_grr *gr, uint32_t g, uint32_t p) { return locate_from_vertex_as(gr, g, p, 1); }
static uint32_t locate_by_scan_plain(dd_grr *gr, uint32_t p) { return locate_by_scan_as(gr, p, 0); }
static uint32_t locate_by_scan_power(dd_grr *gr, uint32_t p) { return locate_by_scan_as(gr, p, 1); }

static uint32_t locate_from_vertex(dd_grr *gr, uint32_t g, uint32_t p)
{
    return gr->weighted ? locate_from_vertex_power(gr, g, p) : locate_from_vertex_plain(gr, g, p);
}

static uint32_t locate_by_scan(dd_grr *gr, uint32_t p)
{
    return gr->weighted ? locate_by_scan_power(gr, p) : locate_by_scan_plain(gr, p);
}

/* ---- GRR-CONSTRUCT --------------------------------------------------------- */

static const dd_scratch_kind grr_kind = {"GRR-CONSTRUCT", grr_free};

/* The GRR scratch kept in d, made on first use. */
static dd_status get_grr(dd_del *d, dd_grr **out)
{
    dd_grr *g = dd_del_scratch(d, &grr_kind);
    if (!g) {
        g = dd_calloc(1, sizeof *g);
        if (!g) return DD_ERR_NOMEM;
        g->d = d;
        dd_status s = dd_del_keep_scratch(d, &grr_kind, g);
        if (s != DD_OK) return s;
    }
    *out = g;
    return DD_OK;
}

dd_status dd_grr_begin(dd_del *d, dd_grr **out)
{
    dd_status s = get_grr(d, out);
    return s == DD_OK ? init(*out) : s;
}

dd_link *dd_grr_link(dd_grr *g) { return &g->link; }

const uint32_t *dd_grr_remaining(const dd_grr *g, size_t *n)
{
    *n = g->rem.n;
    return g->rem.a;
}

dd_status dd_grr_delete_point(dd_grr *g, uint32_t p)
{
    dd_status s = dd_link_delete(&g->link, g->d, p);
    return s == DD_OK ? update_sets(g, p) : s;
}

dd_status dd_grr_locate(dd_grr *g, uint32_t guide, uint32_t p, uint32_t *cell)
{
    uint32_t c = guide == DD_NONE ? DD_NONE : locate_from_vertex(g, guide, p);
    if (c == DD_NONE) {
        g->d->fallbacks++;
        c = locate_by_scan(g, p);
        if (c == DD_NONE) return DD_ERR_INTERNAL;
    }
    *cell = c;
    return DD_OK;
}

/* Step 2 of GRR-CONSTRUCT: the base, as DT(x) of the four base points
 * (or the conflict RT's, weighted) or their full DT (or RT).          */
static dd_status construct_base(dd_grr *g, const dd_grr_policy *pol)
{
    dd_del *d = g->d;
    dd_status s = DD_OK;
    dd_qdt_reset(d, !pol->full_dt);
    if (pol->full_dt) {
        s = dd_reserve_cells(d->qdt, 16);
        if (s == DD_OK) {
            uint32_t b[4];
            memcpy(b, d->base, sizeof b);
            dd_make_first_cells(d->qdt, b);
        }
    } else {
        s = g->weighted ? dd_qdt_create_power(d) : dd_qdt_create(d);
    }
    if (s == DD_OK && pol->triangle_guide) {
        s = dd_trihash_reset(&g->dh, 8 * g->seq.n + 16);
        for (uint32_t c = 0; c < d->qdt->ncell && s == DD_OK; c++)
            if (dd_tv(d->qdt, c)[0] != DD_DEAD && dd_index_of(d->qdt, c, DD_QD) >= 0) s = dh_put(g, c);
    }
    return s;
}

/* The fill of the built d->qdt: its cells without the dummy vertex, or
 * the full triangulation's cells in (power) conflict with q.  On a
 * weighted t the star's hidden points go in first (qdt.h).            */
static dd_status construct_finish(dd_grr *g, const dd_grr_policy *pol)
{
    dd_del *d = g->d;
    if (!g->weighted) return pol->full_dt ? dd_full_collect_fill(d) : dd_qdt_collect_fill(d);
    dd_status s = dd_qdt_insert_hidden(d);
    if (s != DD_OK) return s;
    return pol->full_dt ? dd_full_collect_fill_power(d) : dd_qdt_collect_fill(d);
}

dd_status dd_grr_construct(dd_del *d, const dd_grr_policy *pol)
{
    dd_grr *g;
    if (d->t->wt && dd_qdt_weighted_base(d) != DD_OK) return dd_full_fill_power(d);
    dd_status s = get_grr(d, &g);
    if (s != DD_OK) return s;
    DD_PHASE_BEGIN(d);
    s = init(g);
    /* 1. Link deletions, recording the order and the guides. */
    while (s == DD_OK && g->rem.n > 0) {
        uint32_t guide = DD_NONE;
        uint32_t p = pol->sample(g, &guide);
        if (p == DD_NONE || g->rempos[p] == DD_NONE) return DD_ERR_INTERNAL;
        s = dd_link_delete(&g->link, d, p);
        if (s == DD_OK) s = dd_vec_push(&g->seq, p);
        if (s == DD_OK) s = dd_vec_push(&g->gv, guide);
        if (s == DD_OK && pol->triangle_guide) {
            const uint32_t *tri = g->link.lv + 3 * (size_t)g->link.ring_tri[dd_del_rand(d) % g->link.nnew];
            for (int i = 0; i < 3 && s == DD_OK; i++) s = dd_vec_push(&g->gt, tri[i]);
        }
        if (s == DD_OK) s = update_sets(g, p);
    }
    DD_PHASE_END(d, DD_PH_LINK);
    if (s != DD_OK) return s;

    /* 2. The base. */
    s = construct_base(g, pol);
    DD_PHASE_END(d, DD_PH_CONFLICT);

    /* 3. Reinsertion in reverse order, each from its guide. */
    for (size_t i = g->seq.n; i-- > 0 && s == DD_OK;) {
        uint32_t p = g->seq.a[i], c = DD_NONE;
        if (pol->triangle_guide) c = dh_get(g, g->gt.a + 3 * i);
        else c = locate_from_vertex(g, g->gv.a[i], p);
        if (c == DD_NONE) {                 /* cannot happen; stay robust */
            d->fallbacks++;
            c = locate_by_scan(g, p);
            if (c == DD_NONE) return DD_ERR_INTERNAL;
        }
        DD_PHASE_END(d, DD_PH_LOCATE);
        s = g->weighted ? dd_qdt_insert_power(d, p, c) : dd_qdt_insert(d, p, c);
        if (s == DD_OK && pol->triangle_guide) {
            const dd_tri *x = d->qdt;
            for (size_t k = 0; k < x->boundary.n && s == DD_OK; k++) {
                uint32_t n = x->boundary.a[k];      /* the new cells */
                if (dd_index_of(x, n, DD_QD) >= 0) s = dh_put(g, n);
            }
        }
        DD_PHASE_END(d, DD_PH_CONFLICT);
    }
    if (s != DD_OK) return s;
    return construct_finish(g, pol);
}

static uint32_t mindeg_sample(dd_grr *g, uint32_t *guide)
{
    uint32_t u = dd_grr_sample_mindeg(g);
    *guide = dd_grr_lowest_neighbour(g, u);
    return u;
}

static const dd_grr_policy mindeg_policy = {mindeg_sample, 0, 0};

dd_status dd_grr_fill_mindeg(dd_del *d) { return dd_grr_construct(d, &mindeg_policy); }
