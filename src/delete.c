/*
 * delete.c -- DELETEVERTEX, the conflict DT and the sewing (paper 3-4,
 * DESIGN 6; the framework is described in delete.h).
 *
 * Owns: the deletion context (scratch reused across deletions, so the hot
 * path does not allocate once warm), star and link collection, the
 * all-or-nothing sewing, CREATEQCONFLICTDT and QCONFLICTDTINSERT, and the
 * public dd_delete / dd_insert / dd_reinsert.
 *
 * Invariant kept between deletions: the main triangulation is a valid
 * perturbed DT; d->qdt holds whatever the last strategy left (garbage).
 */
#include "delete.h"
#include "grr.h"
#include "qsmall.h"
#include "wrap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- context ------------------------------------------------------------- */

void dd_delete_ctx_free(dd_del *d)
{
    if (!d) return;
    dd_vec_free(&d->star); dd_vec_free(&d->nbr); dd_vec_free(&d->fill);
    dd_vec_free(&d->order); dd_vec_free(&d->sew_out); dd_vec_free(&d->cellmap);
    dd_trihash_free(&d->lhash);
    free(d->vmark);
    free(d->qdt_vcell);
    dd_free(d->qdt);
    dd_grr_free(d->grr);
    dd_qs_free(d->qs);
    dd_wrap_free(d->wrap);
    if (d->vscratch_free) d->vscratch_free(d->vscratch);
    free(d);
}

/* Makes t->del exist and fit the current vertex arrays. */
static dd_status get_ctx(dd_tri *t, dd_del **out)
{
    dd_del *d = t->del;
    if (!d) {
        d = calloc(1, sizeof *d);
        if (!d) return DD_ERR_NOMEM;
        d->t = t;            /* d->rng: seeded by each deletion */
        if (dd_tri_alloc_borrowed(&d->qdt) != DD_OK) { free(d); return DD_ERR_NOMEM; }
        t->del = d;
    }
    if (d->vmark_cap < t->cap_v) {
        uint32_t *m = realloc(d->vmark, (size_t)t->cap_v * sizeof *m);
        if (!m) return DD_ERR_NOMEM;
        d->vmark = m;
        uint32_t *c = realloc(d->qdt_vcell, (size_t)t->cap_v * sizeof *c);
        if (!c) return DD_ERR_NOMEM;
        d->qdt_vcell = c;
        memset(d->vmark + d->vmark_cap, 0, (size_t)(t->cap_v - d->vmark_cap) * sizeof *m);
        d->vmark_cap = t->cap_v;
    }
    d->qdt->xyz = t->xyz;
    d->qdt->v2in = t->v2in;
    d->qdt->vcell = d->qdt_vcell;
    *out = d;
    return DD_OK;
}

uint32_t dd_del_rand(dd_del *d)
{
    uint64_t x = d->rng;
    x ^= x << 13; x ^= x >> 7; x ^= x << 17;
    d->rng = x;
    return (uint32_t)(x >> 32);
}

void dd_del_shuffle(dd_del *d, uint32_t *a, size_t n)
{
    for (size_t k = n; k > 1; k--) {
        size_t j = dd_del_rand(d) % k;
        uint32_t s = a[k - 1]; a[k - 1] = a[j]; a[j] = s;
    }
}

#ifdef DD_COUNTERS
void dd_phase_begin(dd_del *d) { clock_gettime(CLOCK_MONOTONIC, &d->ph_t0); }
void dd_phase_end(dd_del *d, int phase)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    d->phase[phase] += (double)(now.tv_sec - d->ph_t0.tv_sec) + 1e-9 * (double)(now.tv_nsec - d->ph_t0.tv_nsec);
    d->ph_t0 = now;
}
#endif

/* ---- step 1: star, link, neighbours -------------------------------------- */

/* The star of q by a search over the cells through q, and its neighbours.
 * Without a branch on the marks (each candidate written at the end of its
 * list, which grows by the mark test) it ran no faster (uniform degree
 * [16,32), deletion / re-insertion, alternated runs: 1.89 against 1.84
 * with the branches), nor did a sew without a branch on inner and outer
 * facets (1.87 against 1.83).  Of the 44k instructions of a wrapped
 * deletion (callgrind on dtdel time, uniform 20000, vertex 102, degree
 * 19, 28 fill cells) this search makes 3.2k, the sew and the rest of
 * delete_vertex 5.4k, the wrap 35k (28k of them in w_run: 7.4k guessing,
 * 1.7k proving, the rest its bookkeeping of cells and facets);
 * re-inserting the vertex makes 26k.                                     */
static dd_status collect_star(dd_del *d)
{
    dd_tri *t = d->t;
    uint32_t q = d->q;
    dd_mark ep = dd_new_epoch(t, 1);
    if (++d->vepoch == 0) {
        memset(d->vmark, 0, (size_t)d->vmark_cap * sizeof *d->vmark);
        d->vepoch = 1;
    }
    uint32_t vep = d->vepoch;
    d->star.n = d->nbr.n = 0;
    d->star_inf = 0;
    uint32_t c0 = t->vcell[q];
    t->stamp[c0] = ep;
    dd_status s = dd_vec_push(&d->star, c0);
    for (size_t k = 0; k < d->star.n; k++) {
        /* room for the cell's three other vertices and neighbours: one
         * test a cell, none a push                                      */
        if ((s = dd_vec_room(&d->star, 3)) != DD_OK || (s = dd_vec_room(&d->nbr, 3)) != DD_OK) break;
        uint32_t c = d->star.a[k];
        const uint32_t *v = dd_tv(t, c);
        for (uint32_t j = 0; j < 4; j++) {
            uint32_t w = v[j];
            if (w == q) continue;
            if (w == DD_INF) d->star_inf++;          /* once per infinite cell */
            else if (d->vmark[w] != vep) {
                d->vmark[w] = vep;
                d->nbr.a[d->nbr.n++] = w;
            }
            uint32_t nb = dd_tn(t, c)[j] >> 2;
            if (t->stamp[nb] != ep) {
                t->stamp[nb] = ep;
                d->star.a[d->star.n++] = nb;
            }
        }
    }
    if (s != DD_OK) return s;
    d->on_hull = d->star_inf > 0;
    d->lhash_ready = 0;
    d->fill_in_mesh = 0;
    d->degree = (uint32_t)d->nbr.n + (uint32_t)d->on_hull;
    return DD_OK;
}

dd_status dd_del_link_hash(dd_del *d)
{
    if (d->lhash_ready) return DD_OK;
    dd_tri *t = d->t;
    dd_status s = dd_trihash_reset(&d->lhash, d->star.n);
    for (size_t k = 0; k < d->star.n && s == DD_OK; k++) {
        uint32_t c = d->star.a[k];
        const uint32_t *v = dd_tv(t, c);
        int i = dd_index_of(t, c, d->q);
        s = dd_trihash_put(&d->lhash, v[dd_facet[i][0]], v[dd_facet[i][1]], v[dd_facet[i][2]], (uint32_t)k);
    }
    d->lhash_ready = s == DD_OK;
    return s;
}

/* Moves four affinely independent points of a[0..n) to a[0..3] (first
 * found in a's order) and records them in d->base.  DD_ERR_COPLANAR when
 * there are none.                                                        */
dd_status dd_del_pick_base(dd_del *d, uint32_t *a, size_t n)
{
    dd_tri *t = d->t;
    if (n < 4) return DD_ERR_COPLANAR;
    const double *p0 = dd_pt(t, a[0]), *p1 = dd_pt(t, a[1]);
    size_t k = 2;
    while (k < n && dd_orient_coplanar(&t->pred, p0, p1, dd_pt(t, a[k])) == 0) k++;
    if (k == n) return DD_ERR_COPLANAR;
    uint32_t s = a[2]; a[2] = a[k]; a[k] = s;
    const double *p2 = dd_pt(t, a[2]);
    k = 3;
    while (k < n && dd_orient3d(&t->pred, p0, p1, p2, dd_pt(t, a[k])) == 0) k++;
    if (k == n) return DD_ERR_COPLANAR;
    s = a[3]; a[3] = a[k]; a[k] = s;
    memcpy(d->base, a, sizeof d->base);
    return DD_OK;
}

/* ---- the conflict DT ----------------------------------------------------- */

void dd_qdt_reset(dd_del *d, int qd)
{
    dd_clear_cells(d->qdt);
    d->qdt->qd_point = qd ? d->qp : NULL;
    d->qdt->tets_created = 0;
    d->fill.n = 0;
}

/* CREATEQCONFLICTDT: DT of the four base points, then the cells not in
 * conflict with q are replaced by the star of the dummy vertex: exactly a
 * Bowyer-Watson step whose "conflict region" is the complement.           */
dd_status dd_qdt_create(dd_del *d)
{
    dd_tri *x = d->qdt;
    dd_status s = dd_reserve_cells(x, 16);
    if (s != DD_OK) return s;
    uint32_t b[4];
    memcpy(b, d->base, sizeof b);
    dd_make_first_cells(x, b);
    dd_mark ep = dd_new_epoch(x, 2);
    x->conflict.n = x->boundary.n = 0;
    for (uint32_t c = 0; c < x->ncell && s == DD_OK; c++)
        if (!dd_cell_conflict(x, c, d->qp)) {
            x->stamp[c] = ep;
            s = dd_vec_push(&x->conflict, c);
        }
    for (size_t k = 0; k < x->conflict.n && s == DD_OK; k++) {
        uint32_t c = x->conflict.a[k];
        for (uint32_t i = 0; i < 4 && s == DD_OK; i++)
            if (x->stamp[dd_tn(x, c)[i] >> 2] != ep)
                s = dd_vec_push(&x->boundary, 4 * c + i);
    }
    if (s == DD_OK) s = dd_reserve_star(x);
    if (s != DD_OK) return s;
    dd_fill_star(x, DD_QD);
    return DD_OK;
}

/* QCONFLICTDTINSERT */
dd_status dd_qdt_insert(dd_del *d, uint32_t v, uint32_t start)
{
    dd_tri *x = d->qdt;
    dd_status s = dd_find_conflicts(x, dd_pt(x, v), start);
    if (s == DD_OK) s = dd_reserve_star(x);
    if (s != DD_OK) return s;
    dd_fill_star(x, v);
    return DD_OK;
}

static int has_qd(const dd_tri *x, uint32_t c)
{
    return dd_index_of(x, c, DD_QD) >= 0;
}

dd_status dd_qdt_scan(dd_del *d, uint32_t v, uint32_t *cell)
{
    dd_tri *x = d->qdt;
    const double *p = dd_pt(x, v);
    for (uint32_t c = 0; c < x->ncell; c++) {
        if (dd_tv(x, c)[0] == DD_DEAD || !has_qd(x, c)) continue;
        d->locate_steps++;
        if (dd_cell_conflict(x, c, p)) { *cell = c; return DD_OK; }
    }
    return dd_fail(d->t, DD_ERR_INTERNAL, "no dummy cell of the conflict DT conflicts with point %u",
                   d->t->v2in[v]);
}

dd_status dd_qdt_collect_fill(dd_del *d)
{
    dd_tri *x = d->qdt;
    d->fill.n = 0;
    dd_status s = DD_OK;
    for (uint32_t c = 0; c < x->ncell && s == DD_OK; c++)
        if (dd_tv(x, c)[0] != DD_DEAD && !has_qd(x, c)) s = dd_vec_push(&d->fill, c);
    return s;
}

dd_status dd_full_build(dd_del *d)
{
    dd_tri *x = d->qdt;
    dd_status s = dd_reserve_cells(x, (uint32_t)(8 * d->nbr.n + 16));
    if (s != DD_OK) return s;
    uint32_t b[4];
    memcpy(b, d->base, sizeof b);
    dd_make_first_cells(x, b);
    for (size_t k = 0; k < d->order.n && s == DD_OK; k++) {
        uint32_t v = d->order.a[k];
        if (v == d->base[0] || v == d->base[1] || v == d->base[2] || v == d->base[3]) continue;
        s = dd_insert_vertex(x, v);
    }
    return s;
}

dd_status dd_full_collect_fill(dd_del *d)
{
    dd_tri *x = d->qdt;
    d->fill.n = 0;
    dd_status s = DD_OK;
    for (uint32_t c = 0; c < x->ncell && s == DD_OK; c++)
        if (dd_tv(x, c)[0] != DD_DEAD && dd_cell_conflict(x, c, d->qp))
            s = dd_vec_push(&d->fill, c);
    return s;
}

/* The forced fill of a hull vertex whose finite neighbours are coplanar:
 * every finite star cell with q replaced by DD_INF.                       */
static dd_status fill_coplanar_hull(dd_del *d)
{
    dd_tri *t = d->t, *x = d->qdt;
    dd_qdt_reset(d, 0);
    dd_status s = dd_reserve_cells(x, (uint32_t)d->star.n);
    if (s == DD_OK) s = dd_reserve_edge_hash(x, d->star.n);
    for (size_t k = 0; k < d->star.n && s == DD_OK; k++) {
        uint32_t c = d->star.a[k];
        if (dd_is_infinite_cell(t, c)) continue;
        uint32_t n = dd_new_cell(x);
        for (uint32_t i = 0; i < 4; i++) {
            uint32_t w = dd_tv(t, c)[i];
            dd_tv(x, n)[i] = w == d->q ? DD_INF : w;
            dd_tn(x, n)[i] = DD_NONE;
        }
        s = dd_vec_push(&d->fill, n);
    }
    if (s == DD_OK) dd_glue_new_cells(x, d->fill.a, d->fill.n, DD_INF);
    return s;
}

/* ---- step 3: sewing ------------------------------------------------------ */

/* Matches every boundary facet of the fill with its link triangle, into
 * d->sew_out; checks that each link triangle is met exactly once.       */
static dd_status sew_match(dd_del *d)
{
    dd_tri *t = d->t, *x = d->qdt;
    size_t nf = d->fill.n;
    dd_status s = dd_del_link_hash(d);
    if (s != DD_OK) return s;
    dd_mark epx = dd_new_epoch(x, 1);
    for (size_t k = 0; k < nf; k++) x->stamp[d->fill.a[k]] = epx;
    dd_mark ep = dd_new_epoch(t, 1);
    size_t matched = 0;
    for (size_t k = 0; k < nf; k++) {
        uint32_t r = d->fill.a[k];
        const uint32_t *v = dd_tv(x, r);
        for (uint32_t j = 0; j < 4; j++) {
            uint32_t f = dd_tn(x, r)[j];
            if (f != DD_NONE && x->stamp[f >> 2] == epx) {
                d->sew_out.a[4 * k + j] = DD_NONE;
                continue;
            }
            uint32_t slot = dd_trihash_get(&d->lhash, v[dd_facet[j][0]], v[dd_facet[j][1]], v[dd_facet[j][2]]);
            if (slot == DD_NONE)
                return dd_fail(t, DD_ERR_INTERNAL, "deleting point %u: a cavity facet matches no link triangle",
                               t->v2in[d->q]);
            uint32_t c = d->star.a[slot];
            if (t->stamp[c] == ep)
                return dd_fail(t, DD_ERR_INTERNAL, "deleting point %u: a link triangle is covered twice",
                               t->v2in[d->q]);
            t->stamp[c] = ep;
            d->sew_out.a[4 * k + j] = dd_tn(t, c)[(uint32_t)dd_index_of(t, c, d->q)];
            matched++;
        }
    }
    if (matched != d->star.n)
        return dd_fail(t, DD_ERR_INTERNAL, "deleting point %u: the cavity fill covers %zu of %zu link triangles",
                       t->v2in[d->q], matched, d->star.n);
    return DD_OK;
}

/* The sew's last step for fill cell m, now in the mesh and glued: the
 * vertices' cells, the finite count, the hint.                          */
static inline void sew_settle(dd_tri *t, uint32_t m)
{
    int inf = 0;
    for (uint32_t j = 0; j < 4; j++) {
        uint32_t w = dd_tv(t, m)[j];
        if (w == DD_INF) { inf = 1; t->inf_cell = m; }
        else t->vcell[w] = m;
    }
    if (!inf) t->nfinite++;
    t->hint = m;
}

/* The star's cells from the k0-th on recycled (point of no return), in
 * reverse, so that the free list gives them back in the star's order;
 * those before, the fill has taken over.                                */
static void sew_recycle_star(dd_del *d, size_t k0)
{
    dd_tri *t = d->t;
    for (size_t k = d->star.n; k-- > k0;) dd_kill_cell(t, d->star.a[k]);
    t->nfinite -= (uint32_t)d->star.n - d->star_inf;
}

static dd_status sew(dd_del *d)
{
    dd_tri *t = d->t, *x = d->qdt;
    size_t nf = d->fill.n;
    if (d->fill_in_mesh) {
        /* The fill is in the mesh already (wrap.c), over the star's first
         * cells and past them in new ones, glued inside and matched to
         * the link: glue it to the outside.  Against making it in d->qdt
         * and copying it here: see w_run.                                */
        size_t taken = nf < d->star.n ? nf : d->star.n;
        sew_recycle_star(d, taken);
        t->tets_created += taken;
        for (size_t k = 0; k < nf; k++) {
            uint32_t m = d->fill.a[k];
            for (uint32_t j = 0; j < 4; j++) {
                uint32_t o = d->sew_out.a[4 * k + j];
                if (o != DD_NONE) dd_glue(t, 4 * m + j, o);
            }
            sew_settle(t, m);
        }
        t->vcell[d->q] = DD_NONE;
        t->nvert--;
        return DD_OK;
    }
    dd_status s = dd_vec_reserve(&d->sew_out, 4 * nf + 4);
    if (s == DD_OK) s = sew_match(d);
    if (s == DD_OK) s = dd_vec_reserve(&d->cellmap, (size_t)x->ncell + 1);
    if (s != DD_OK) return s;
    s = dd_reserve_cells(t, (uint32_t)nf);
    if (s != DD_OK) return s;

    /* Point of no return: recycle, copy, glue.  The star's cells go first
     * (in reverse, so the free list gives them back in the star's order),
     * so that the fill takes their places: where the deletion is, in
     * memory, whatever the free list held before.                        */
    sew_recycle_star(d, 0);
    for (size_t k = 0; k < nf; k++) {
        uint32_t r = d->fill.a[k], m = dd_new_cell(t);
        memcpy(dd_tv(t, m), dd_tv(x, r), 4 * sizeof(uint32_t));
        d->cellmap.a[r] = m;
    }
    for (size_t k = 0; k < nf; k++) {
        uint32_t r = d->fill.a[k], m = d->cellmap.a[r];
        for (uint32_t j = 0; j < 4; j++) {
            uint32_t o = d->sew_out.a[4 * k + j];
            if (o != DD_NONE) {
                dd_glue(t, 4 * m + j, o);
            } else {
                uint32_t f = dd_tn(x, r)[j];
                dd_tn(t, m)[j] = 4 * d->cellmap.a[f >> 2] + (f & 3);
            }
        }
        sew_settle(t, m);
    }
    t->vcell[d->q] = DD_NONE;
    t->nvert--;
    return DD_OK;
}

/* ---- DELETEVERTEX -------------------------------------------------------- */

static dd_status resolve_vertex(dd_tri *t, uint32_t input, uint32_t *v)
{
    if (input >= t->np)
        return dd_fail(t, DD_ERR_UNKNOWN_VERTEX, "no point %u (the input has %u points)", input, t->np);
    uint32_t id = t->in2v[input];
    if (t->v2in[id] != input)
        return dd_fail(t, DD_ERR_UNKNOWN_VERTEX, "point %u is a duplicate of point %u, not a vertex",
                       input, t->v2in[id]);
    if (t->vcell[id] == DD_NONE)
        return dd_fail(t, DD_ERR_UNKNOWN_VERTEX, "point %u is not a vertex (it was deleted)", input);
    *v = id;
    return DD_OK;
}

/* DELETEVERTEX(q) with strategy var; q a vertex id. */
static dd_status delete_vertex(dd_tri *t, uint32_t q, const dd_variant *var)
{
    if (t->nvert <= 4)
        return dd_fail(t, DD_ERR_DIMENSION, "deleting point %u would leave %u points: at least 4 are needed",
                       t->v2in[q], t->nvert - 1);
    dd_del *d;
    dd_status s = get_ctx(t, &d);
    if (s != DD_OK) return dd_fail(t, s, "out of memory");
    d->q = q;
    d->qp = dd_pt(t, q);
    /* The random choices of a deletion are seeded by the vertex: deleting
     * the same vertex of the same triangulation does the same work.     */
    uint64_t z = dd_mix64(t->v2in[q] + 0x9E3779B97F4A7C15ull);
    d->rng = z | 1;
    d->qdt->rng = (z * 0x2545F4914F6CDD1Dull) | 1;
    d->fallbacks = 0;
    d->locate_steps = 0;
    d->forced_fill = 0;
    d->wrap_how = DD_WRAP_NONE;
    d->wrap_guess = DD_GUESS_WIDE;
    d->wrap_narrow_refuted = 0;
    d->wrap_integer = 0;
    d->wrap_shift_guess = 0;
    d->wrap_single = d->wrap_single_back = 0;
    d->wrap_single_refuted = 0;
    d->wrap_hull_single = d->wrap_hull_back = 0;
    d->wrap_expansions = 0;
    memset(d->link_deletions, 0, sizeof d->link_deletions);
    d->qdt_created = 0;
    for (int i = 0; i < DD_NPHASES; i++) d->phase[i] = 0;
    DD_PHASE_BEGIN(d);
    s = collect_star(d);
    if (s != DD_OK) return dd_fail(t, s, "out of memory");
    /* Four independent neighbours, or the forced coplanar-hull fill. */
    d->order.n = 0;
    if ((s = dd_vec_room(&d->order, d->nbr.n)) != DD_OK) return dd_fail(t, s, "out of memory");
    memcpy(d->order.a, d->nbr.a, d->nbr.n * sizeof *d->nbr.a);
    d->order.n = d->nbr.n;
    DD_PHASE_END(d, DD_PH_LINK);
    if (dd_del_pick_base(d, d->order.a, d->order.n) != DD_OK) {
        /* Coplanar finite neighbours: q is on the hull.  If every finite
         * cell holds q, every other point is a neighbour: all coplanar.   */
        if (d->star.n - d->star_inf == t->nfinite)
            return dd_fail(t, DD_ERR_DIMENSION, "deleting point %u would leave only coplanar points",
                           t->v2in[q]);
        if (!d->on_hull)
            return dd_fail(t, DD_ERR_INTERNAL, "interior point %u has coplanar neighbours", t->v2in[q]);
        d->forced_fill = 1;
        s = fill_coplanar_hull(d);
    } else {
        s = var->fill_cavity(d);
    }
    if (s != DD_OK) {
        if (s == DD_ERR_NOMEM) return dd_fail(t, s, "out of memory");
        if (!t->err[0]) dd_fail(t, s, "the %s strategy failed on point %u", var->name, t->v2in[q]);
        return s;
    }
    d->qdt_created = d->qdt->tets_created;
    DD_PHASE_BEGIN(d);
    s = sew(d);
    DD_PHASE_END(d, DD_PH_SEW);
    if (s == DD_ERR_NOMEM) return dd_fail(t, s, "out of memory");
    return s;
}

/* The strategy named `variant` (NULL: the default) in *var, clearing the
 * message of an earlier failure; DD_ERR_UNKNOWN_VARIANT if none is.     */
static dd_status resolve_variant(dd_tri *t, const char *variant, const dd_variant **var)
{
    t->err[0] = 0;
    *var = dd_find_variant(variant);
    return *var ? DD_OK
                : dd_fail(t, DD_ERR_UNKNOWN_VARIANT, "unknown variant '%s'", variant ? variant : "(null)");
}

dd_status dd_delete(dd_tri *t, uint32_t input, const char *variant)
{
    const dd_variant *var;
    uint32_t q = 0;
    dd_status s = resolve_variant(t, variant, &var);
    if (s == DD_OK) s = resolve_vertex(t, input, &q);
    if (s != DD_OK) return s;
    return delete_vertex(t, q, var);
}

#ifdef DD_TEST_BUILD
/* Tests only: dd_delete_set fails at its deletion number k >= 0 as out of
 * memory would, so that the tests see the re-insertions undo the others. */
long dd_test_set_fail_at = -1;
#endif

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

/* Lists in left[0..max) the first vertices, in id order, that are not
 * among the sorted ids[0..n); returns how many.                          */
static uint32_t vertices_left(const dd_tri *t, const uint32_t *ids, size_t n, uint32_t *left, uint32_t max)
{
    uint32_t m = 0;
    size_t k = 0;
    for (uint32_t v = 0; v < t->nvid && m < max; v++) {
        if (t->vcell[v] == DD_NONE) continue;
        if (k < n && ids[k] == v) { k++; continue; }
        left[m++] = v;
    }
    return m;
}

/* Whether the vertices left after deleting the sorted ids[0..n) include
 * four affinely independent ones.  The first 64 left nearly always do, so
 * a small set costs no pass over the whole triangulation.               */
static dd_status check_left(dd_tri *t, const uint32_t *ids, size_t n)
{
    uint32_t few[64], m = vertices_left(t, ids, n, few, 64);
    if (dd_pick_simplex(t, t->xyz, few, m) == DD_OK) return DD_OK;
    dd_status s = DD_ERR_DIMENSION;
    if (m == 64) {                                   /* more are left: all of them */
        uint32_t *left = malloc((size_t)(t->nvert - n) * sizeof *left);
        if (!left) return dd_fail(t, DD_ERR_NOMEM, "out of memory");
        m = vertices_left(t, ids, n, left, t->nvert - (uint32_t)n);
        if (dd_pick_simplex(t, t->xyz, left, m) == DD_OK) s = DD_OK;
        free(left);
    }
    return s == DD_OK ? s : dd_fail(t, s, "deleting these %zu points would leave only coplanar points", n);
}

/* A set of deletions.  The result, DT of the points left, does not depend
 * on the order (the perturbed DT is unique), so they go in vertex id
 * order: the insertion order, BRIO rounds along a Hilbert curve, so that
 * consecutive deletions work in nearby cells and points, in space and in
 * memory (uniform 10^6, 10% of the vertices: 9.4 -> 6.6 us a deletion
 * against a random order, scratch harness).  Checked before the first:
 * every index a vertex and listed once, and the points left at least 4
 * and not all in one plane; then no deletion of the sequence can be
 * refused (each leaves a superset of them).  An unforeseen failure (out
 * of memory) re-inserts those done, in reverse, which restores DT(S).   */
dd_status dd_delete_set(dd_tri *t, const uint32_t *vs, size_t n, const char *variant)
{
    const dd_variant *var;
    dd_status s = resolve_variant(t, variant, &var);
    if (s != DD_OK || n == 0) return s;
    if (n > t->nvert)
        return dd_fail(t, DD_ERR_UNKNOWN_VERTEX, "%zu points listed, the triangulation has %u vertices", n,
                       t->nvert);
    uint32_t *ids = malloc(n * sizeof *ids);
    if (!ids) return dd_fail(t, DD_ERR_NOMEM, "out of memory");
    for (size_t k = 0; k < n && s == DD_OK; k++) s = resolve_vertex(t, vs[k], &ids[k]);
    if (s == DD_OK) {
        qsort(ids, n, sizeof *ids, cmp_u32);
        for (size_t k = 1; k < n && s == DD_OK; k++)
            if (ids[k] == ids[k - 1])
                s = dd_fail(t, DD_ERR_UNKNOWN_VERTEX, "point %u is listed twice", t->v2in[ids[k]]);
    }
    if (s == DD_OK && t->nvert - n < 4)
        s = dd_fail(t, DD_ERR_DIMENSION, "deleting %zu of %u points would leave %u: at least 4 are needed", n,
                    t->nvert, t->nvert - (uint32_t)n);
    if (s == DD_OK) s = check_left(t, ids, n);
    size_t done = 0;
    for (; done < n && s == DD_OK; done++) {
#ifdef DD_TEST_BUILD
        if ((long)done == dd_test_set_fail_at) { s = dd_fail(t, DD_ERR_NOMEM, "out of memory (test)"); continue; }
#endif
        s = delete_vertex(t, ids[done], var);
    }
    if (s != DD_OK && done > 0) {
        done--;                         /* the one that failed is not done */
        char why[sizeof t->err];
        memcpy(why, t->err, sizeof why);
        while (done > 0) {
            uint32_t v = ids[--done];
            if (dd_reinsert(t, t->v2in[v]) != DD_OK) break;
        }
        memcpy(t->err, why, sizeof why);
    }
    free(ids);
    return s;
}

/* Collects the star of input vertex v for the queries below. */
dd_status dd_del_star_of(dd_tri *t, uint32_t input, dd_del **out)
{
    uint32_t v = 0;
    dd_status s = resolve_vertex(t, input, &v);
    if (s == DD_OK) s = get_ctx(t, out);
    if (s != DD_OK) return s;
    (*out)->q = v;
    (*out)->qp = dd_pt(t, v);
    return collect_star(*out);
}

uint32_t dd_degree(dd_tri *t, uint32_t v)
{
    dd_del *d;
    return dd_del_star_of(t, v, &d) == DD_OK ? d->degree : 0;
}

int dd_on_hull(dd_tri *t, uint32_t v)
{
    dd_del *d;
    return dd_del_star_of(t, v, &d) == DD_OK ? d->on_hull : 0;
}

uint32_t dd_neighbors(dd_tri *t, uint32_t v, uint32_t *out, uint32_t max)
{
    dd_del *d;
    if (dd_del_star_of(t, v, &d) != DD_OK) return 0;
    for (size_t k = 0; k < d->nbr.n && k < max; k++) out[k] = t->v2in[d->nbr.a[k]];
    return (uint32_t)d->nbr.n;
}

static int cmp_cell4(const void *a, const void *b)
{
    const int32_t *p = a, *q = b;
    for (int i = 0; i < 4; i++)
        if (p[i] != q[i]) return p[i] < q[i] ? -1 : 1;
    return 0;
}

dd_status dd_local_canonical(dd_tri *t, const uint32_t *vs, size_t n, int32_t **tets, size_t *ntets)
{
    dd_del *d;
    size_t cap = 64, k = 0;
    int32_t *a = malloc(4 * cap * sizeof *a);
    if (!a) return DD_ERR_NOMEM;
    for (size_t i = 0; i < n; i++) {
        dd_status s = dd_del_star_of(t, vs[i], &d);
        if (s != DD_OK) { free(a); return s; }
        for (size_t j = 0; j < d->star.n; j++) {
            if (k == cap) {
                int32_t *b = realloc(a, 8 * cap * sizeof *a);
                if (!b) { free(a); return DD_ERR_NOMEM; }
                a = b;
                cap *= 2;
            }
            const uint32_t *v = dd_tv(t, d->star.a[j]);
            int32_t *o = a + 4 * k++;
            for (int m = 0; m < 4; m++) o[m] = dd_input_index(t, v[m]);
            for (int x = 1; x < 4; x++)          /* sort the four */
                for (int y = x; y > 0 && o[y - 1] > o[y]; y--) { int32_t s2 = o[y]; o[y] = o[y - 1]; o[y - 1] = s2; }
        }
    }
    qsort(a, k, 4 * sizeof *a, cmp_cell4);
    size_t u = 0;
    for (size_t i = 0; i < k; i++)
        if (u == 0 || cmp_cell4(a + 4 * (u - 1), a + 4 * i)) memmove(a + 4 * u++, a + 4 * i, 4 * sizeof *a);
    *tets = a;
    *ntets = u;
    return DD_OK;
}

void dd_last_delete_stats(const dd_tri *t, dd_delete_stats *st)
{
    memset(st, 0, sizeof *st);
    const dd_del *d = t->del;
    if (!d) return;
    st->degree = d->degree;
    st->on_hull = d->on_hull;
    st->tets_created = d->qdt_created;
    st->fallbacks = d->fallbacks;
    st->locate_steps = d->locate_steps;
    st->forced_fill = d->forced_fill;
    st->wrap = d->wrap_how;
    st->wrap_guess = d->wrap_guess;
    st->wrap_narrow_refuted = d->wrap_narrow_refuted;
    st->wrap_integer = d->wrap_integer;
    st->wrap_shift_guess = d->wrap_shift_guess;
    st->wrap_single = d->wrap_single;
    st->wrap_single_back = d->wrap_single_back;
    st->wrap_single_refuted = d->wrap_single_refuted;
    st->wrap_hull_single = d->wrap_hull_single;
    st->wrap_hull_back = d->wrap_hull_back;
    st->wrap_expansions = d->wrap_expansions;
    memcpy(st->link_deletions, d->link_deletions, sizeof st->link_deletions);
    st->link_us = 1e6 * d->phase[DD_PH_LINK];
    st->locate_us = 1e6 * d->phase[DD_PH_LOCATE];
    st->conflict_us = 1e6 * d->phase[DD_PH_CONFLICT];
    st->sew_us = 1e6 * d->phase[DD_PH_SEW];
}

/* ---- insertion ----------------------------------------------------------- */

dd_status dd_reinsert(dd_tri *t, uint32_t input)
{
    t->err[0] = 0;
    if (input >= t->np)
        return dd_fail(t, DD_ERR_UNKNOWN_VERTEX, "no point %u (the input has %u points)", input, t->np);
    uint32_t v = t->in2v[input];
    if (t->v2in[v] != input)
        return dd_fail(t, DD_ERR_DUPLICATE, "point %u is a duplicate of point %u", input, t->v2in[v]);
    if (t->vcell[v] != DD_NONE)
        return dd_fail(t, DD_ERR_DUPLICATE, "point %u is already a vertex", input);
    return dd_insert_vertex(t, v);
}

static dd_status grow_u32(uint32_t **a, size_t n)
{
    uint32_t *b = realloc(*a, n * sizeof **a);
    if (!b) return DD_ERR_NOMEM;
    *a = b;
    return DD_OK;
}

dd_status dd_insert(dd_tri *t, const double p[3], uint32_t *index)
{
    t->err[0] = 0;
    for (int c = 0; c < 3; c++) {
        if (isnan(p[c])) return dd_fail(t, DD_ERR_NAN, "coordinate %c is NaN", "xyz"[c]);
        if (isinf(p[c])) return dd_fail(t, DD_ERR_INFINITE, "coordinate %c is infinite", "xyz"[c]);
    }
    if (t->np == UINT32_MAX - 8 || t->nvid == UINT32_MAX - 8)
        return dd_fail(t, DD_ERR_NOMEM, "too many points");
    if (t->nvid == t->cap_v) {
        size_t cap = (size_t)t->cap_v * 2;
        double *xyz = realloc(t->xyz, 3 * cap * sizeof *xyz);
        if (!xyz) return dd_fail(t, DD_ERR_NOMEM, "out of memory");
        t->xyz = xyz;
        if (grow_u32(&t->vcell, cap) || grow_u32(&t->v2in, cap))
            return dd_fail(t, DD_ERR_NOMEM, "out of memory");
        t->cap_v = (uint32_t)cap;
    }
    if (t->np == t->cap_in) {
        if (grow_u32(&t->in2v, (size_t)t->cap_in * 2)) return dd_fail(t, DD_ERR_NOMEM, "out of memory");
        t->cap_in *= 2;
    }
    uint32_t v = t->nvid;
    memcpy(t->xyz + 3 * (size_t)v, p, 3 * sizeof *p);
    t->vcell[v] = DD_NONE;
    t->v2in[v] = t->np;
    t->in2v[t->np] = v;
    dd_status s = dd_insert_vertex(t, v);
    if (s != DD_OK) return s;   /* nvid, np unchanged: the slot is unused */
    t->nvid++;
    *index = t->np++;
    return DD_OK;
}

/* ---- the registry -------------------------------------------------------- */

const dd_variant *dd_find_variant(const char *name)
{
    if (!name) return dd_variant_table[0];
    for (const dd_variant *const *v = dd_variant_table; *v; v++)
        if (!strcmp((*v)->name, name)) return *v;
    return NULL;
}

const char *dd_variant_name(size_t i)
{
    for (size_t k = 0; k <= i; k++)
        if (!dd_variant_table[k]) return NULL;
    return dd_variant_table[i]->name;
}

const char *dd_variant_description(size_t i)
{
    for (size_t k = 0; k <= i; k++)
        if (!dd_variant_table[k]) return NULL;
    return dd_variant_table[i]->description;
}
