/*
 * regular.c -- insertion into a regular (weighted Delaunay) triangulation
 * and the nearest vertex in power distance (DESIGN 12).
 *
 * The insertion is Bowyer-Watson as mesh.c's, with the power test in
 * place of the in-sphere test (mesh.h, dd_cell_power_conflict_fast,
 * compiled into its own copy of the conflict search) and the two rules
 * that differ, both CGAL's (Triangulation_3::insert_in_conflict with
 * Regular_triangulation_3's conflict tester and hidden point visitor):
 *  - a point with a vertex's position and weight changes nothing (CGAL
 *    returns that vertex); with another weight it is an ordinary point,
 *    which either is hidden or swallows the vertex;
 *  - a point not in conflict with the cell that holds it is hidden: the
 *    lifted point lies above the lower hull there, as the power test of
 *    that cell says.
 * Otherwise the region in conflict is replaced by the new star; vertices
 * all of whose cells were in conflict are swallowed and become hidden
 * points (hidden.c keeps them, or forgets them), and the hidden points
 * of the region are re-homed.  Hull extreme points are never swallowed,
 * so the dimension stays 3.
 */
#include "mesh/mesh.h"
#include "mesh/hidden.h"

#include <stdlib.h>

dd_status dd_insert_power(dd_tri *t, uint32_t v, uint32_t start, int ahead, dd_fate *fate, uint32_t *dup)
{
    const double *p = dd_pt(t, v);
    const double wp = t->wt[v];
    if (start == DD_NONE || dd_tv(t, start)[0] == DD_DEAD) start = t->inf_cell;
    uint32_t c0 = DD_NONE;
    dd_status s = dd_walk_locate(t, p, start, &c0);
    if (s != DD_OK) return s;
    if (!dd_is_outer_cell(t, c0)) {
        for (uint32_t k = 0; k < 4; k++) {     /* p at a vertex: its weight decides */
            const uint32_t w = dd_tv(t, c0)[k];
            if (dd_lex_cmp(dd_pt(t, w), p) == 0 && t->wt[w] == wp) {
                *dup = w;
                *fate = DD_FATE_DUPLICATE;
                return DD_OK;
            }
        }
        if (!dd_cell_power_conflict_fast(t, c0, p, wp)) {
            *fate = t->hid->keep ? DD_FATE_HIDDEN : DD_FATE_FORGOTTEN;
            s = dd_hidden_add(t, c0, v);
            return s == DD_OK ? s : dd_fail(t, s, "out of memory inserting point %u", t->v2in[v]);
        }
    }
    s = dd_find_conflicts_power(t, p, wp, c0, ahead);
    if (s == DD_OK) s = dd_reserve_star(t);
    if (s == DD_OK) s = dd_hidden_take_region(t);
    if (s != DD_OK) return dd_fail(t, s, "out of memory inserting point %u", t->v2in[v]);
    dd_fill_star(t, v);
    t->nvert++;
    *fate = DD_FATE_VERTEX;
    s = dd_hidden_settle(t);
    return s == DD_OK ? s : dd_fail(t, s, "re-homing hidden points: point location did not terminate");
}

/* ---- nearest vertex in power distance ------------------------------------ */

static int in_list(const dd_vec *l, uint32_t x)
{
    for (size_t k = 0; k < l->n; k++)
        if (l->a[k] == x) return 1;
    return 0;
}

/* sign(pow(p, a) - pow(p, b)) for vertices a, b. */
static int compare_power(const dd_tri *t, dd_reader *r, const double *p, uint32_t a, uint32_t b)
{
    return dd_power_compare_distance(&r->pred, p, dd_pt(t, a), t->wt[a], dd_pt(t, b), t->wt[b]);
}

/* Why the descent ends at a nearest vertex: for the perturbed weights,
 * power cells of vertices are full-dimensional, and the segment from a
 * point of best's cell to p leaves it through a facet shared with a
 * neighbour strictly nearer p, unless best is nearest.  With exact
 * distances that neighbour is nearer or as near, so from a vertex that
 * is not nearest a path of edges with non-increasing distances leads to
 * a strictly nearer vertex: the search over the plateau (the vertices
 * at best's distance, connected by edges) finds it.  The plateau is one
 * vertex unless distances tie exactly.                                  */
dd_status dd_nearest_power_from(const dd_tri *t, dd_reader *r, const double *p, uint32_t c, uint32_t *nearest)
{
    uint32_t best = DD_NONE;
    for (int i = 0; i < 4; i++) {
        const uint32_t w = dd_tv(t, c)[i];
        if (w == DD_INF) continue;
        if (best == DD_NONE || compare_power(t, r, p, best, w) > 0) best = w;
    }
    dd_vec plateau = {NULL, 0, 0};
    dd_status s = DD_OK;
    for (int moved = 1; moved && s == DD_OK;) {
        moved = 0;
        plateau.n = 0;
        s = dd_vec_push(&plateau, best);
        for (size_t i = 0; i < plateau.n && !moved && s == DD_OK; i++) {
            const uint32_t u = plateau.a[i];
            if ((s = dd_star_read(t, r, u, &r->star)) != DD_OK) break;
            for (size_t k = 0; k < r->star.n && !moved && s == DD_OK; k++)
                for (int j = 0; j < 4; j++) {
                    const uint32_t w = dd_tv(t, r->star.a[k])[j];
                    if (w == DD_INF || w == u) continue;
                    const int cmp = compare_power(t, r, p, best, w);
                    if (cmp > 0) {
                        best = w;
                        moved = 1;
                        break;
                    }
                    if (cmp == 0 && !in_list(&plateau, w) && (s = dd_vec_push(&plateau, w)) != DD_OK) break;
                }
        }
    }
    dd_vec_free(&plateau);
    if (s == DD_OK) *nearest = best;
    return s;
}
