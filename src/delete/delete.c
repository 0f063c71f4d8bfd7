/*
 * delete.c -- DELETEVERTEX, the conflict DT and the sewing (paper 3-4,
 * DESIGN 6; the framework is described in delete.h).
 *
 * Owns: the deletion context (scratch reused across deletions, so the hot
 * path does not allocate once warm; the strategies' own scratch in its
 * slots), star and link collection, the forced fill of a flat hull, the
 * all-or-nothing sewing, and DELETEVERTEX itself (dd_del_vertex).  The
 * conflict DT is in qdt.c; the public calls are in src/api.c.
 *
 * Invariant kept between deletions: the main triangulation is a valid
 * perturbed DT; d->qdt holds whatever the last strategy left (garbage).
 */
#include "delete/delete.h"
#include "mesh/hidden.h"
#include "dtdel/alloc.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- context ------------------------------------------------------------- */

void dd_del_free(dd_del *d)
{
    if (!d) return;
    dd_vec_free(&d->star); dd_vec_free(&d->nbr); dd_vec_free(&d->fill);
    dd_vec_free(&d->order); dd_vec_free(&d->sew_out); dd_vec_free(&d->cellmap);
    dd_vec_free(&d->hpts);
    dd_trihash_free(&d->lhash);
    dd_mfree(d->vmark);
    dd_mfree(d->qdt_vcell);
    dd_tri_destroy(d->qdt);
    for (int i = 0; i < DD_SCRATCH_SLOTS && d->scratch[i].kind; i++) d->scratch[i].kind->free(d->scratch[i].p);
    dd_mfree(d);
}

/* Makes t->del exist and fit the current vertex arrays. */
static dd_status get_ctx(dd_tri *t, dd_del **out)
{
    dd_del *d = t->del;
    if (!d) {
        d = dd_calloc(1, sizeof *d);
        if (!d) return DD_ERR_NOMEM;
        d->t = t;            /* d->rng: seeded by each deletion */
        if (dd_tri_alloc_borrowed(&d->qdt) != DD_OK) { dd_mfree(d); return DD_ERR_NOMEM; }
        t->del = d;
    }
    if (d->vmark_cap < t->cap_v) {
        if (dd_grow(&d->vmark, t->cap_v, sizeof *d->vmark) || dd_grow(&d->qdt_vcell, t->cap_v, sizeof *d->qdt_vcell))
            return DD_ERR_NOMEM;
        memset(d->vmark + d->vmark_cap, 0, (size_t)(t->cap_v - d->vmark_cap) * sizeof *d->vmark);
        d->vmark_cap = t->cap_v;
    }
    d->qdt->xyz = t->xyz;
    d->qdt->v2in = t->v2in;
    d->qdt->vcell = d->qdt_vcell;
    d->qdt->wt = t->wt;
    *out = d;
    return DD_OK;
}

dd_status dd_del_keep_scratch(dd_del *d, const dd_scratch_kind *k, void *p)
{
    for (int i = 0; i < DD_SCRATCH_SLOTS; i++)
        if (!d->scratch[i].kind) {
            d->scratch[i] = (dd_scratch_slot){k, p};
            return DD_OK;
        }
    k->free(p);
    return dd_fail(d->t, DD_ERR_INTERNAL, "more than %d kinds of strategy scratch (%s)", DD_SCRATCH_SLOTS, k->name);
}

void dd_del_strategy_stats(dd_del *d, const char *const *names, uint32_t n)
{
    d->sstat_names = names;
    d->nsstat = n < DD_STRATEGY_STATS ? n : DD_STRATEGY_STATS;
}

uint32_t dd_del_rand(dd_del *d)
{
    return dd_xorshift(&d->rng);
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

/* A fresh epoch of d->vmark. */
static uint32_t new_vepoch(dd_del *d)
{
    if (++d->vepoch == 0) {
        memset(d->vmark, 0, (size_t)d->vmark_cap * sizeof *d->vmark);
        d->vepoch = 1;
    }
    return d->vepoch;
}

/* Step 1: the star of q (d->star) by a search over the cells through q,
 * marked with a fresh epoch; q's finite neighbours (d->nbr, marked in
 * d->vmark); the infinite cells of the star, q's degree, whether it is
 * on the hull.  Each cell makes room for its three other vertices and
 * neighbours once, so the pushes need no test.  O(degree).            */
static dd_status collect_star(dd_del *d)
{
    dd_tri *t = d->t;
    uint32_t q = d->q;
    dd_mark ep = dd_new_epoch(t, 1);
    uint32_t vep = new_vepoch(d);
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
                __builtin_prefetch(t->xyz + 3 * (size_t)w);   /* the fill lifts it */
            }
            uint32_t nb = dd_tn(t, c)[j] >> 2;
            if (t->stamp[nb] != ep) {
                t->stamp[nb] = ep;
                d->star.a[d->star.n++] = nb;
                __builtin_prefetch(dd_tv(t, nb));    /* read when its turn comes */
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

dd_status dd_del_pick_base(dd_del *d, uint32_t *a, size_t n)
{
    dd_tri *t = d->t;
    if (n < 4 || dd_find_simplex(&t->pred, t->xyz, a, (uint32_t)n) != DD_OK) return DD_ERR_COPLANAR;
    memcpy(d->base, a, sizeof d->base);
    return DD_OK;
}

/* The forced fill of a hull vertex whose finite neighbours are coplanar
 * (delete.h): in d->qdt, every finite star cell with q replaced by
 * DD_INF, glued to each other; d->fill lists them.                    */
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

/* Step 3 (delete.h): the fill in place of the star, glued to the
 * outside, q gone.  Everything that can fail (the matching, the room)
 * comes before the point of no return.                                */
static dd_status sew(dd_del *d)
{
    dd_tri *t = d->t, *x = d->qdt;
    size_t nf = d->fill.n;
    if (d->fill_in_mesh) {
        /* The fill is in the mesh already (src/wrap), over the star's first
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
        dd_note_made(t, d->fill.a, nf);
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
        dd_note_cell(t, m);
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

dd_status dd_del_resolve(dd_tri *t, uint32_t input, uint32_t *v)
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

/* ---- weighted points (DESIGN 12, issue 44) ------------------------------ */

/* Step 1 on a weighted t: takes the hidden points of the star from
 * hidden.c into d->hpts (none when they are forgotten).  They are sites
 * of the fill as q's neighbours are.  On failure nothing is taken.     */
static dd_status take_hidden(dd_del *d)
{
    dd_tri *t = d->t;
    const uint32_t *pts;
    size_t np;
    dd_status s = dd_hidden_take(t, d->star.a, d->star.n, d->q, &pts, &np);
    if (s != DD_OK) return s;
    if ((s = dd_vec_room(&d->hpts, np)) != DD_OK) {
        (void)dd_hidden_settle(t);              /* back where they were */
        return s;
    }
    if (np) memcpy(d->hpts.a, pts, np * sizeof *pts);
    d->hpts.n = np;
    return DD_OK;
}

/* Whether vertex ids a and b carry the same weighted point exactly. */
static int same_wpoint(const dd_tri *t, uint32_t a, uint32_t b)
{
    const double *p = dd_pt(t, a), *q = dd_pt(t, b);
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2] && t->wt[a] == t->wt[b];
}

/* After sort_released's partition (the m released points first): the
 * exact copies of a released point are forgotten, as CGAL's remove
 * re-inserts the hidden points one by one and its insert of a vertex's
 * exact weighted point keeps nothing.  The copy that is the vertex is
 * the one of lowest input index (the CGAL shim's rule for exact
 * duplicates), renamed in the fill x if the fill chose another.  Moves
 * the forgotten points to d->hpts.a[m..m+f) and returns f.  O(m h).   */
static size_t drop_copies(dd_del *d, dd_tri *x, size_t m)
{
    dd_tri *t = d->t;
    uint32_t *a = d->hpts.a;
    size_t f = 0;
    for (size_t r = 0; r < m; r++) {
        const uint32_t v = a[r];
        size_t keep = r;
        for (size_t k = m + f; k < d->hpts.n; k++) {
            const uint32_t h = a[k];
            if (!same_wpoint(t, v, h)) continue;
            a[k] = a[m + f];
            a[m + f] = h;
            if (t->v2in[h] < t->v2in[a[keep]]) keep = m + f;
            f++;
        }
        if (keep == r) continue;
        const uint32_t c = a[keep];             /* the vertex is c, not v */
        a[keep] = v;
        a[r] = c;
        for (size_t k = 0; k < d->fill.n; k++) {
            uint32_t *tv = dd_tv(x, d->fill.a[k]);
            for (uint32_t j = 0; j < 4; j++)
                if (tv[j] == v) tv[j] = c;
        }
    }
    return f;
}

/* Before the sew on a weighted t: moves the points of d->hpts that are
 * vertices of the fill (no longer hidden) to its front, returning how
 * many in *nrel, then their exact copies (drop_copies: *nforg of them,
 * forgotten), and makes room for the others in the cells the sew makes. */
static dd_status sort_released(dd_del *d, size_t *nrel, size_t *nforg)
{
    dd_tri *t = d->t, *x = d->fill_in_mesh ? t : d->qdt;   /* where the fill is */
    *nrel = 0;
    *nforg = 0;
    if (!d->hpts.n) return dd_hidden_room(t, (size_t)t->ncell + d->fill.n);   /* nothing to sort */
    const uint32_t ep = new_vepoch(d);
    for (size_t k = 0; k < d->fill.n; k++)
        for (uint32_t j = 0; j < 4; j++) {
            const uint32_t w = dd_tv(x, d->fill.a[k])[j];
            if (w != DD_INF) d->vmark[w] = ep;
        }
    size_t m = 0;
    for (size_t k = 0; k < d->hpts.n; k++)
        if (d->vmark[d->hpts.a[k]] == ep) {
            const uint32_t v = d->hpts.a[k];
            d->hpts.a[k] = d->hpts.a[m];
            d->hpts.a[m++] = v;
        }
    *nrel = m;
    *nforg = drop_copies(d, x, m);
    return dd_hidden_room(t, (size_t)t->ncell + d->fill.n);
}

/* After the sew on a weighted t (s its status): the released points are
 * vertices now, their exact copies (the nforg after them) forgotten, the
 * others re-homed in the new cells; after a failure (the mesh unchanged)
 * every point taken goes back.                                          */
static dd_status settle_hidden(dd_del *d, dd_status s, size_t nrel, size_t nforg)
{
    dd_tri *t = d->t;
    if (s == DD_OK) {
        for (size_t k = 0; k < nrel; k++) {
            dd_hidden_release(t, d->hpts.a[k]);
            t->nvert++;
        }
        for (size_t k = nrel; k < nrel + nforg; k++) dd_hidden_release(t, d->hpts.a[k]);
    }
    d->hpts.n = 0;
    const dd_status r = dd_hidden_settle(t);
    if (s == DD_OK && r != DD_OK)
        return dd_fail(t, r, "deleting point %u: re-homing hidden points did not terminate", t->v2in[d->q]);
    return s;
}

/* ---- DELETEVERTEX -------------------------------------------------------- */

/* Step 2: four independent sites and the strategy's fill, or the forced
 * coplanar-hull fill.
 *
 * The forced fill also serves when the star holds hidden points: every
 * site is then on the plane P of q's finite neighbours (else the base
 * exists), so each hidden point h lies in the polygon D of the finite
 * link triangles, on P.  None comes back: the cell (a,b,c,d) across a
 * link triangle abc of D from q stays, and on P its power sphere is the
 * power circle of a, b, c (the power of a point of P is the same for
 * both, for every weight d has, so CGAL's perturbation of the 3D test
 * skips d and matches its 2D one); h was not in conflict with that cell,
 * so h stays hidden in the 2D regular triangulation of D's sites, whose
 * triangles are D's.  CGAL's remove() fills the hole alike (the link's
 * plane triangulated, q's point as the infinite vertex) and hides each
 * re-inserted h again, on the new hull.  They are re-homed in the cells
 * across D (hidden.c's settle), as without the fill.                    */
static dd_status fill_step(dd_del *d, dd_status (*fill)(dd_del *))
{
    dd_tri *t = d->t;
    if (dd_del_pick_base(d, d->order.a, d->order.n) == DD_OK) return fill(d);
    /* Coplanar sites: q is on the hull.  If every finite cell holds q,
     * every other vertex is a neighbour, and every hidden point of t is
     * in the star: all the points left are coplanar.                    */
    const uint32_t q = d->q;
    if (d->star.n - d->star_inf == t->nfinite)
        return dd_fail(t, DD_ERR_DIMENSION, "deleting point %u would leave only coplanar points", t->v2in[q]);
    if (!d->on_hull) return dd_fail(t, DD_ERR_INTERNAL, "interior point %u has coplanar neighbours", t->v2in[q]);
    d->forced_fill = 1;
    return fill_coplanar_hull(d);
}

/* DELETEVERTEX(q): step 1 (collect_star; on a weighted t, the star's
 * hidden points too), step 2 (fill_step), step 3 (sew; then the hidden
 * points released or re-homed).  Steps 1-2 leave the mesh as it was;
 * whether t is weighted is decided here, once.                         */
dd_status dd_del_vertex(dd_tri *t, uint32_t q, const dd_variant *var)
{
    const int weighted = t->wt != NULL;
    if (weighted && !var->fill_weighted)
        return dd_fail(t, DD_ERR_UNSUPPORTED,
                       "the %s strategy does not delete from a weighted triangulation yet (sew-full and auto do)",
                       var->name);
    if (t->nvert <= 4)
        return dd_fail(t, DD_ERR_DIMENSION, "deleting point %u would leave %u points: at least 4 are needed",
                       t->v2in[q], t->nvert - 1);
    dd_del *d;
    dd_status s = get_ctx(t, &d);
    if (s != DD_OK) return dd_fail(t, s, "out of memory");
    d->q = q;
    d->qp = dd_pt(t, q);
    d->qw = weighted ? t->wt[q] : 0.0;
    /* The random choices of a deletion are seeded by the vertex: deleting
     * the same vertex of the same triangulation does the same work.     */
    uint64_t z = dd_mix64(t->v2in[q] + 0x9E3779B97F4A7C15ull);
    d->rng = z | 1;
    d->qdt->rng = (z * 0x2545F4914F6CDD1Dull) | 1;
    d->fallbacks = 0;
    d->locate_steps = 0;
    d->forced_fill = 0;
    d->sstat_names = NULL;
    d->nsstat = 0;
    memset(d->sstat, 0, sizeof d->sstat);
    memset(d->link_deletions, 0, sizeof d->link_deletions);
    d->qdt_created = 0;
    for (int i = 0; i < DD_NPHASES; i++) d->phase[i] = 0;
    DD_PHASE_BEGIN(d);
    s = collect_star(d);
    d->hpts.n = 0;
    if (s == DD_OK && weighted) s = take_hidden(d);
    if (s != DD_OK) return dd_fail(t, s, "out of memory");
    /* The sites: q's neighbours, then the star's hidden points. */
    d->order.n = 0;
    if ((s = dd_vec_room(&d->order, d->nbr.n + d->hpts.n)) != DD_OK) {
        if (weighted) (void)settle_hidden(d, s, 0, 0);
        return dd_fail(t, s, "out of memory");
    }
    memcpy(d->order.a, d->nbr.a, d->nbr.n * sizeof *d->nbr.a);
    if (d->hpts.n) memcpy(d->order.a + d->nbr.n, d->hpts.a, d->hpts.n * sizeof *d->hpts.a);
    d->order.n = d->nbr.n + d->hpts.n;
    DD_PHASE_END(d, DD_PH_LINK);
    s = fill_step(d, weighted ? var->fill_weighted : var->fill_cavity);
    size_t nrel = 0, nforg = 0;
    if (s == DD_OK) {
        d->qdt_created = d->qdt->tets_created;
        if (weighted) s = sort_released(d, &nrel, &nforg);
        DD_PHASE_BEGIN(d);
        if (s == DD_OK) s = sew(d);
        DD_PHASE_END(d, DD_PH_SEW);
    } else if (s != DD_ERR_NOMEM && !t->err[0]) {
        dd_fail(t, s, "the %s strategy failed on point %u", var->name, t->v2in[q]);
    }
    if (weighted) s = settle_hidden(d, s, nrel, nforg);
    if (s == DD_ERR_NOMEM) return dd_fail(t, s, "out of memory");
    return s;
}

/* Step 1 alone (delete.h). */
dd_status dd_del_star_of(dd_tri *t, uint32_t input, dd_del **out)
{
    uint32_t v = 0;
    dd_status s = dd_del_resolve(t, input, &v);
    if (s == DD_OK) s = get_ctx(t, out);
    if (s != DD_OK) return s;
    (*out)->q = v;
    (*out)->qp = dd_pt(t, v);
    return collect_star(*out);
}

