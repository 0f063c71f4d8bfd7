/*
 * api.c -- the public calls of dtdel.h that sit on the whole engine: the
 * strategy resolved by name (the registry of variants/), deletion of one
 * vertex or a set, insertion, the star queries, the last deletion's
 * statistics (dtdel_stats.h), and freeing a triangulation with its
 * deletion context.  Thin: each call checks its arguments and hands over
 * to the layers below (docs/architecture.md).
 */
#include "dtdel.h"
#include "dtdel_stats.h"
#include "delete/delete.h"
#include "mesh/hidden_move.h"
#include "geom/expansion.h"
#include "dtdel/alloc.h"
#include "api/api_int.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The registry (variants/registry.c): NULL-terminated, first = default. */
extern const dd_variant *const dd_variant_table[];

const char *dd_version(void) { return DD_VERSION; }

void dd_free(dd_tri *t)
{
    if (!t) return;
    dd_del_free(t->del);
    t->del = NULL;
    dd_tri_destroy(t);
}

/* ---- the registry -------------------------------------------------------- */

static const dd_variant *find_variant(const char *name)
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

/* Records deleted vertex q for dd_insert to reuse (not with
 * DD_STABLE_INDICES, which reuses none).  Entries of vertices re-inserted
 * since are stale and skipped; when stale entries make the list longer
 * than the vertex ids, it is compacted (amortised O(1)).  A failed push
 * only forgoes the reuse.                                                */
static void note_deleted(dd_tri *t, uint32_t q)
{
    if (t->flags & DD_STABLE_INDICES) return;
    dd_vec *f = &t->vfree;
    if (f->n >= t->nvid && f->n > 64) {
        size_t m = 0;
        for (size_t k = 0; k < f->n; k++) {
            uint32_t v = f->a[k];
            if (t->vcell[v] == DD_NONE) {
                t->vcell[v] = DD_DEAD;       /* mark: keep once */
                f->a[m++] = v;
            }
        }
        for (size_t k = 0; k < m; k++) t->vcell[f->a[k]] = DD_NONE;
        f->n = m;
    }
    (void)dd_vec_push(f, q);
}

/* The strategy named `variant` (NULL: the default) in *var;
 * DD_ERR_UNKNOWN_VARIANT if none is.                                     */
static dd_status resolve_variant(dd_tri *t, const char *variant, const dd_variant **var)
{
    *var = find_variant(variant);
    return *var ? DD_OK
                : dd_fail(t, DD_ERR_UNKNOWN_VARIANT, "unknown variant '%s'", variant ? variant : "(null)");
}

/* The vertex id of input index `input` when it names a kept hidden
 * point of a weighted t (not a duplicate of one), else DD_NONE.        */
static uint32_t hidden_id(const dd_tri *t, uint32_t input)
{
    if (!t->wt || input >= t->np) return DD_NONE;
    const uint32_t v = t->in2v[input];
    return t->v2in[v] == input && dd_hidden_has(t, v) ? v : DD_NONE;
}

dd_status dd_put_back(dd_tri *t, uint32_t v)
{
    if (!t->wt) return dd_insert_vertex(t, v);
    dd_fate fate;
    uint32_t dup;
    dd_status s = dd_insert_power(t, v, dd_start_near(t, dd_pt(t, v)), 0, &fate, &dup);
    if (s == DD_OK && fate == DD_FATE_DUPLICATE)
        s = dd_fail(t, DD_ERR_DUPLICATE, "point %u is the weighted point of vertex %u", t->v2in[v], t->v2in[dup]);
    if (s == DD_OK && fate == DD_FATE_VERTEX) dd_grid_note(t, v);
    return s;
}

/* The public edits below are each the body of a dd_edit_begin / end
 * pair: the cells they make become dd_created_cells' list, and a
 * failure's message dd_errmsg's.                                      */
static dd_status delete_one(dd_tri *t, uint32_t input, const char *variant)
{
    const dd_variant *var;
    uint32_t q = 0, h = hidden_id(t, input), cell;
    dd_status s = resolve_variant(t, variant, &var);
    if (s == DD_OK && h != DD_NONE) {       /* a kept hidden point: forgotten */
        dd_hidden_forget(t, h, &cell);
        return DD_OK;
    }
    if (s == DD_OK) s = dd_del_resolve(t, input, &q);
    if (s == DD_OK) s = dd_del_vertex(t, q, var);
    if (s == DD_OK && !t->wt) note_deleted(t, q);   /* weighted t: indices never reused */
    if (s == DD_OK) (void)dd_grid_ready(t);     /* the queries' starts (locate.c) */
    return s;
}

dd_status dd_delete_with(dd_tri *t, uint32_t v, const char *variant)
{
    dd_edit_begin(t);
    return dd_edit_end(t, delete_one(t, v, variant));
}

dd_status dd_delete(dd_tri *t, uint32_t v) { return dd_delete_with(t, v, NULL); }

/* The predicate counters of t and of its deletions' conflict DT. */
void dd_get_counters(const dd_tri *t, dd_counters *c)
{
    memset(c, 0, sizeof *c);
#ifdef DD_COUNTERS
    /* the triangulation's own tests, plus its deletions' conflict DT */
    const dd_pred *p[2] = {&t->pred, t->del && t->del->qdt ? &t->del->qdt->pred : NULL};
    for (int i = 0; i < 2 && p[i]; i++) {
        c->orient_calls += p[i]->orient_calls;
        c->orient_exact += p[i]->orient_exact;
        c->insphere_calls += p[i]->insphere_calls;
        c->insphere_exact += p[i]->insphere_exact;
        c->perturbed += p[i]->perturbed;
    }
#endif
    c->tets_created = t->tets_created;
    c->walk_steps = t->walk_steps;
    c->moves_kept = t->moves_kept;
    c->moves_flipped = t->moves_flipped;
    c->moves_redone = t->moves_redone;
}

void dd_reset_counters(dd_tri *t)
{
#ifdef DD_COUNTERS
    t->pred.orient_calls = t->pred.orient_exact = 0;
    t->pred.insphere_calls = t->pred.insphere_exact = 0;
    t->pred.perturbed = 0;
#endif
    t->tets_created = t->walk_steps = 0;
    t->moves_kept = t->moves_flipped = t->moves_redone = 0;
}

#ifdef DD_TEST_BUILD
long dd_test_control(dd_tri *t, dd_test_ctl ctl, long value)
{
    if (ctl == DD_TEST_EXP_PLAIN) {   /* process-wide: kept by geom */
        long was = dd_exp_plain_forced();
        dd_exp_force_plain((int)value);
        return was;
    }
    if (ctl == DD_TEST_ALLOC_FAIL || ctl == DD_TEST_ALLOC_COUNT) return dd_alloc_control(ctl == DD_TEST_ALLOC_FAIL, value);
    if (!t || ctl < 0 || ctl >= DD_TEST_NCTL) return 0;
    long was = t->testctl[ctl];
    t->testctl[ctl] = value;
    return was;
}
#endif

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return x < y ? -1 : x > y;
}

/* Lists in left[0..max) the first points in t (vertices, and kept
 * hidden points), in id order, that are not among the sorted ids[0..n);
 * returns how many.                                                      */
static uint32_t vertices_left(const dd_tri *t, const uint32_t *ids, size_t n, uint32_t *left, uint32_t max)
{
    uint32_t m = 0;
    size_t k = 0;
    for (uint32_t v = 0; v < t->nvid && m < max; v++) {
        if (!dd_present(t, v)) continue;
        if (k < n && ids[k] == v) { k++; continue; }
        left[m++] = v;
    }
    return m;
}

/* Whether the points left after deleting the sorted ids[0..n) (of the
 * `total` in t) include four affinely independent ones: on a weighted t
 * kept hidden points count, since the regular triangulation of the
 * points left spans their hull.  The first 64 left nearly always do, so
 * a small set costs no pass over the whole triangulation.               */
static dd_status check_left(dd_tri *t, const uint32_t *ids, size_t n, uint32_t total)
{
    uint32_t few[64], m = vertices_left(t, ids, n, few, 64);
    if (dd_pick_simplex(t, t->xyz, few, m) == DD_OK) return DD_OK;
    dd_status s = DD_ERR_DIMENSION;
    if (m == 64) {                                   /* more are left: all of them */
        uint32_t *left = dd_malloc((size_t)(total - n) * sizeof *left);
        if (!left) return dd_fail(t, DD_ERR_NOMEM, "out of memory");
        m = vertices_left(t, ids, n, left, total - (uint32_t)n);
        if (dd_pick_simplex(t, t->xyz, left, m) == DD_OK) s = DD_OK;
        dd_mfree(left);
    }
    return s == DD_OK ? s : dd_fail(t, s, "deleting these %zu points would leave only coplanar points", n);
}

/* The cost model of dd_delete_set: deleting k of the n vertices one at a
 * time costs about k * SET_DELETE_UNIT, rebuilding DT of the n - k left
 * about (n - k) * SET_BUILD_UNIT; the cheaper course is taken.  The units
 * are the time of one deletion along the insertion order and of one
 * point of a rebuild, relative to each other, on uniform points: the
 * crossover, about a third of the vertices, is where `dtdel edit-bench`
 * (or a dd_delete_set of each fraction, timed) shows both courses equal.
 * On a weighted t both a deletion (which fills the star with the
 * neighbours and the star's hidden points) and a point of the rebuild
 * (a power insertion, with hidden points re-homed) cost more; their
 * ratio, SET_WDELETE_UNIT, is set the same way, from the fraction where
 * a dd_delete_set of wuniform weighted points takes as long by either
 * course (forced in a test build by DD_TEST_SET_COURSE), in both hidden
 * modes alike.  Listed hidden points are only forgotten, so k counts the
 * listed vertices and the rebuild the points left, hidden or not.      */
#define SET_DELETE_UNIT 1.0
#define SET_WDELETE_UNIT 0.8
#define SET_BUILD_UNIT 0.55

static int rebuild_is_cheaper(const dd_tri *t, size_t k, size_t left)
{
#ifdef DD_TEST_BUILD
    if (t->testctl[DD_TEST_SET_COURSE]) return t->testctl[DD_TEST_SET_COURSE] == 2;
#endif
    const double unit = t->wt ? SET_WDELETE_UNIT : SET_DELETE_UNIT;
    return (double)k * unit > (double)left * SET_BUILD_UNIT;
}

/* Asks for the cells the next deletions start from, one and two ahead:
 * the first cell of the next one's star and its neighbours, and the first
 * cell of the one after (whose neighbours the next call asks for).  The
 * deletions in id order are near in space, not in memory.  A listed
 * hidden point (no cell) asks for nothing.                                */
static void prefetch_stars(const dd_tri *t, const uint32_t *next, size_t n)
{
    if (n > 1 && t->vcell[next[1]] != DD_NONE) __builtin_prefetch(dd_tv(t, t->vcell[next[1]]));
    if (n > 0 && t->vcell[next[0]] != DD_NONE) {
        const uint32_t *nb = dd_tn(t, t->vcell[next[0]]);
        for (int j = 0; j < 4; j++) __builtin_prefetch(dd_tv(t, nb[j] >> 2));
    }
}

/* The vertex id of listed input index `input`: a vertex, or on a
 * weighted t that keeps them a hidden point.                            */
static dd_status resolve_listed(dd_tri *t, uint32_t input, uint32_t *id)
{
    const uint32_t h = hidden_id(t, input);
    if (h == DD_NONE) return dd_del_resolve(t, input, id);
    *id = h;
    return DD_OK;
}

/* The set vs[0..n) checked (delete_set) into ids, sorted: every index a
 * vertex (or a kept hidden point) listed once; the points left at least
 * 4 and not all in one plane.  *k: how many of them are vertices.       */
static dd_status check_set(dd_tri *t, const uint32_t *vs, size_t n, uint32_t *ids, size_t *k)
{
    const uint32_t total = t->nvert + (uint32_t)dd_hidden_count(t);
    if (n > total)
        return dd_fail(t, DD_ERR_UNKNOWN_VERTEX, "%zu points listed, the triangulation has %u", n, total);
    dd_status s = DD_OK;
    for (size_t j = 0; j < n && s == DD_OK; j++) s = resolve_listed(t, vs[j], &ids[j]);
    if (s != DD_OK) return s;
    qsort(ids, n, sizeof *ids, cmp_u32);
    *k = 0;
    for (size_t j = 0; j < n; j++) {
        if (j > 0 && ids[j] == ids[j - 1]) return dd_fail(t, DD_ERR_ARG, "point %u is listed twice", t->v2in[ids[j]]);
        *k += t->vcell[ids[j]] != DD_NONE;
    }
    if (total - n < 4)
        return dd_fail(t, DD_ERR_DIMENSION, "deleting %zu of %u points would leave %u: at least 4 are needed", n,
                       total, total - (uint32_t)n);
    return check_left(t, ids, n, total);
}

/* The rebuild course: DT (RT on a weighted t) of the points left.
 * DD_ERR_DUPLICATE (a weighted t with two equal weighted points left,
 * nothing changed): the caller deletes one at a time.                   */
static dd_status rebuild_set(dd_tri *t, const uint32_t *ids, size_t n)
{
    dd_status s = t->wt ? dd_rebuild_power_without(t, ids, n) : dd_rebuild_without(t, ids, n);
    if (s == DD_OK) dd_note_all(t);
    return s;
}

/* Puts a weighted t's listed hidden points first in ids (the vertices
 * after them, still in id order): they are forgotten before any
 * deletion, which could otherwise bring one back only to delete it.     */
static void hidden_first(const dd_tri *t, uint32_t *ids, size_t n, uint32_t *tmp)
{
    size_t h = 0, m = 0;
    for (size_t j = 0; j < n; j++)
        if (dd_hidden_has(t, ids[j])) ids[h++] = ids[j];
        else tmp[m++] = ids[j];
    memcpy(ids + h, tmp, m * sizeof *tmp);
}

/* The one-at-a-time course, in ids' order (a kept hidden point is
 * forgotten; a vertex deleted, and no deletion hides a point, so each
 * listed vertex is one still).  An unforeseen failure (out of memory)
 * puts back those done, in reverse, which restores the triangulation:
 * DT(S) is unique, and so is the regular triangulation of the points
 * kept; under DD_DISCARD_HIDDEN only vertices are listed, and a vertex
 * put back hides none (each was a vertex with all of them).             */
static dd_status delete_each(dd_tri *t, const uint32_t *ids, size_t n, const dd_variant *var)
{
    dd_status s = DD_OK;
    size_t done = 0;
    for (; done < n && s == DD_OK; done++) {
#ifdef DD_TEST_BUILD
        if ((long)done + 1 == t->testctl[DD_TEST_SET_FAIL_AT]) {
            s = dd_fail(t, DD_ERR_NOMEM, "out of memory (test)");
            continue;
        }
#endif
        prefetch_stars(t, ids + done + 1, n - done - 1);
        uint32_t cell;
        if (dd_hidden_has(t, ids[done])) dd_hidden_forget(t, ids[done], &cell);
        else s = dd_del_vertex(t, ids[done], var);
    }
    if (s != DD_OK && done > 0) {
        done--;                         /* the one that failed is not done */
        char why[sizeof t->err];
        memcpy(why, t->err, sizeof why);
        int undone = 1;
        while (done > 0 && undone) undone = dd_put_back(t, ids[--done]) == DD_OK;
        memcpy(t->err, why, sizeof why);
        if (!undone)   /* a re-insertion failed too: not as it was (dtdel.h, NOMEM) */
            s = dd_fail(t, DD_ERR_INTERNAL, "deleting the set failed (%s) and could not be undone", why);
    }
    return s;
}

/* A set of deletions.  The result, DT of the points left, does not depend
 * on the order (the perturbed DT is unique; on a weighted t, the regular
 * triangulation of the points left, and under DD_DISCARD_HIDDEN of the
 * vertices left, none of which a removal hides), so they go in vertex id
 * order: the insertion order, BRIO rounds along a Hilbert curve, so that
 * consecutive deletions work in nearby cells and points, in space and in
 * memory (faster than a random order: `build/dtdel seq-bench` times
 * both).  Checked before the first (check_set); then no deletion of the
 * sequence can be refused (each leaves a superset of the points left). */
static dd_status delete_set(dd_tri *t, const uint32_t *vs, size_t n, const char *variant)
{
    const dd_variant *var;
    dd_status s = resolve_variant(t, variant, &var);
    if (s != DD_OK || n == 0) return s;
    uint32_t *ids = dd_malloc((t->wt ? 2 : 1) * n * sizeof *ids);
    if (!ids) return dd_fail(t, DD_ERR_NOMEM, "out of memory");
    size_t k = 0;
    s = check_set(t, vs, n, ids, &k);
    const size_t left = t->nvert + dd_hidden_count(t) - n;
    int each = 1;
    if (s == DD_OK && rebuild_is_cheaper(t, k, left)) {
        s = rebuild_set(t, ids, n);
        each = s == DD_ERR_DUPLICATE;
        if (each) s = DD_OK;
    }
    if (s == DD_OK && each) {
        if (t->wt) hidden_first(t, ids, n, ids + n);
        s = delete_each(t, ids, n, var);
    }
    for (size_t j = 0; s == DD_OK && !t->wt && j < n; j++) note_deleted(t, ids[j]);
    if (s == DD_OK) (void)dd_grid_ready(t);
    dd_mfree(ids);
    return s;
}

dd_status dd_delete_set_with(dd_tri *t, const uint32_t *vs, size_t n, const char *variant)
{
    dd_edit_begin(t);
    return dd_edit_end(t, delete_set(t, vs, n, variant));
}

dd_status dd_delete_set(dd_tri *t, const uint32_t *vs, size_t n)
{
    return dd_delete_set_with(t, vs, n, NULL);
}

/* The star queries below are read-only (dtdel.h, threads): the star of
 * input vertex v in r->star and, when nbr is not NULL, v's finite
 * neighbours in nbr (in the order the star's cells first meet them),
 * marks in r's set; *on_hull whether an infinite cell is in the star.
 * DD_ERR_UNKNOWN_VERTEX when v is not a vertex.                         */
static dd_status read_star(const dd_tri *t, dd_reader *r, uint32_t v, dd_vec *nbr, int *on_hull)
{
    const uint32_t q = dd_vertex_of(t, v);
    if (q == DD_NONE) return DD_ERR_UNKNOWN_VERTEX;
    dd_status s = dd_star_read(t, r, q, &r->star);
    *on_hull = 0;
    if (s == DD_OK && nbr) s = dd_reader_set_reset(r, r->star.n);
    for (size_t k = 0; k < r->star.n && s == DD_OK; k++) {
        const uint32_t *w = dd_tv(t, r->star.a[k]);
        for (int i = 0; i < 4 && s == DD_OK; i++) {
            if (w[i] == q) continue;
            if (w[i] == DD_INF) { *on_hull = 1; continue; }
            if (!nbr) continue;
            const int added = dd_reader_set_add(r, w[i]);
            if (added < 0) s = DD_ERR_NOMEM;
            else if (added) s = dd_vec_push(nbr, w[i]);
        }
    }
    return s;
}

uint32_t dd_degree(const dd_tri *t, uint32_t v)
{
    dd_reader r;
    dd_reader_init(&r);
    dd_vec nbr = {NULL, 0, 0};
    int hull = 0;
    dd_status s = read_star(t, &r, v, &nbr, &hull);
    const uint32_t degree = s == DD_OK ? (uint32_t)nbr.n + (uint32_t)hull : 0;
    dd_reader_done(&r);
    dd_vec_free(&nbr);
    return degree;
}

int dd_on_hull(const dd_tri *t, uint32_t v)
{
    dd_reader r;
    dd_reader_init(&r);
    int hull = 0;
    dd_status s = read_star(t, &r, v, NULL, &hull);
    dd_reader_done(&r);
    return s == DD_OK && hull;
}

uint32_t dd_neighbors(const dd_tri *t, uint32_t v, uint32_t *out, uint32_t max)
{
    dd_reader r;
    dd_reader_init(&r);
    dd_vec nbr = {NULL, 0, 0};
    int hull = 0;
    uint32_t n = 0;
    if (read_star(t, &r, v, &nbr, &hull) == DD_OK) {
        n = (uint32_t)nbr.n;
        for (size_t k = 0; k < nbr.n && k < max; k++) out[k] = t->v2in[nbr.a[k]];
    }
    dd_reader_done(&r);
    dd_vec_free(&nbr);
    return n;
}

/* The cells of the stars of vs[0..n), listed (a cell in two stars
 * twice), then their canonical form.                                    */
dd_status dd_local_canonical(const dd_tri *t, const uint32_t *vs, size_t n, int32_t **tets, size_t *ntets)
{
    dd_vec cells = {NULL, 0, 0};
    dd_reader r;
    dd_reader_init(&r);
    dd_status s = DD_OK;
    int hull;
    for (size_t i = 0; i < n && s == DD_OK; i++) {
        s = read_star(t, &r, vs[i], NULL, &hull);
        if (s == DD_OK) s = dd_vec_room(&cells, r.star.n);
        if (s == DD_OK) {
            memcpy(cells.a + cells.n, r.star.a, r.star.n * sizeof *cells.a);
            cells.n += r.star.n;
        }
    }
    dd_reader_done(&r);
    if (s == DD_OK) s = dd_canonical_of_cells(t, cells.a, cells.n, tets, ntets);
    dd_vec_free(&cells);
    return s;
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
    st->nstrategy = d->nsstat;
    for (uint32_t i = 0; i < d->nsstat; i++) {
        st->strategy_name[i] = d->sstat_names[i];
        st->strategy[i] = d->sstat[i];
    }
    memcpy(st->link_deletions, d->link_deletions, sizeof st->link_deletions);
    st->link_us = 1e6 * d->phase[DD_PH_LINK];
    st->locate_us = 1e6 * d->phase[DD_PH_LOCATE];
    st->conflict_us = 1e6 * d->phase[DD_PH_CONFLICT];
    st->sew_us = 1e6 * d->phase[DD_PH_SEW];
}

/* ---- insertion ----------------------------------------------------------- */

static dd_status reinsert(dd_tri *t, uint32_t input)
{
    if (input >= t->np)
        return dd_fail(t, DD_ERR_UNKNOWN_VERTEX, "no point %u (the input has %u points)", input, t->np);
    uint32_t v = t->in2v[input];
    if (t->v2in[v] != input)
        return dd_fail(t, DD_ERR_DUPLICATE, "point %u is a duplicate of point %u", input, t->v2in[v]);
    if (t->vcell[v] != DD_NONE)
        return dd_fail(t, DD_ERR_DUPLICATE, "point %u is already a vertex", input);
    if (dd_hidden_has(t, v))
        return dd_fail(t, DD_ERR_DUPLICATE, "point %u is already in the triangulation, hidden", input);
    dd_status s = dd_put_back(t, v);   /* weighted: it may end hidden, or forgotten */
    if (s == DD_OK) (void)dd_grid_ready(t);     /* the queries' starts (locate.c) */
    return s;
}

dd_status dd_reinsert(dd_tri *t, uint32_t v)
{
    dd_edit_begin(t);
    return dd_edit_end(t, reinsert(t, v));
}



dd_status dd_new_vertex_id(dd_tri *t, uint32_t *v, int *reused)
{
    while (t->vfree.n > 0) {
        const uint32_t x = t->vfree.a[--t->vfree.n];
        if (t->vcell[x] == DD_NONE) {
            *v = x;
            *reused = 1;
            return DD_OK;
        }
    }
    *reused = 0;
    dd_status s = dd_reserve_vertex(t);
    if (s != DD_OK) return dd_fail(t, s, "out of memory or too many points");
    *v = t->nvid;
    t->vcell[*v] = DD_NONE;
    t->v2in[*v] = t->np;
    t->in2v[t->np] = *v;
    return DD_OK;
}

dd_status dd_insert_start(dd_tri *t, const double p[3], dd_cell_id hint, uint32_t *start)
{
    for (int c = 0; c < 3; c++) {
        if (isnan(p[c])) return dd_fail(t, DD_ERR_NAN, "coordinate %c is NaN", "xyz"[c]);
        if (isinf(p[c])) return dd_fail(t, DD_ERR_INFINITE, "coordinate %c is infinite", "xyz"[c]);
    }
    if (hint != -1 && !dd_cell_alive(t, hint))
        return dd_fail(t, DD_ERR_UNKNOWN_CELL, "the hint %lld is not a live cell", (long long)hint);
    if (hint != -1) {
        *start = (uint32_t)hint;
        return DD_OK;
    }
    dd_status s = dd_grid_ready(t);
    if (s != DD_OK) return dd_fail(t, s, "out of memory");
    *start = dd_start_near(t, p);
    return DD_OK;
}

static dd_status insert_point(dd_tri *t, const double p[3], dd_cell_id hint, uint32_t *index)
{
    uint32_t v = 0, start;
    int reused = 0;
    dd_status s = dd_insert_start(t, p, hint, &start);
    if (s != DD_OK) return s;
    if ((s = dd_new_vertex_id(t, &v, &reused)) != DD_OK) return s;
    double old[3];                                   /* a reused slot's point, kept */
    memcpy(old, t->xyz + 3 * (size_t)v, sizeof old);
    memcpy(t->xyz + 3 * (size_t)v, p, sizeof old);
    s = hint != -1 ? dd_insert_vertex_from(t, v, start) : dd_insert_vertex_at(t, v, start);
    if (s != DD_OK) {                                /* nothing changes */
        memcpy(t->xyz + 3 * (size_t)v, old, sizeof old);
        if (reused) (void)dd_vec_push(&t->vfree, v);
        return s;
    }
    dd_grid_note(t, v);
    if (!reused) {
        t->nvid++;
        t->np++;
    }
    *index = t->v2in[v];
    return DD_OK;
}

dd_status dd_insert_from(dd_tri *t, const double p[3], dd_cell_id hint, uint32_t *index)
{
    if (t->wt) return dd_insert_weighted_from(t, p, 0.0, hint, index);    /* weight 0 */
    dd_edit_begin(t);
    return dd_edit_end(t, insert_point(t, p, hint, index));
}

dd_status dd_insert(dd_tri *t, const double p[3], uint32_t *index)
{
    return dd_insert_from(t, p, -1, index);
}
