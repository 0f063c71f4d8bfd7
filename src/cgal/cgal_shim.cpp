/*
 * cgal_shim.cpp -- the CGAL reference behind cgal_shim.h (DESIGN section 7).
 *
 * Owns: a dd_cgal handle = CGAL's Delaunay_triangulation_3 (Epick kernel,
 * vertex info = input index), a copy of the input points, and a table from
 * input index to Vertex_handle (null when that index is not a vertex now).
 * It implements the two reference rows of the bench: "cgal" (CGAL's own
 * remove()) and "cgal-rnd" (triangulate-and-sew with the temporary DT of the
 * link vertices built in a seeded random order, sewn in here with the public
 * TDS calls), plus CGAL's predicates for the tests (DESIGN section 3).
 *
 * Invariants:
 *  - vh[i] is non-null iff input point i is a vertex; then vh[i]->info()==i.
 *  - first[i] is 1 iff point i is the first occurrence of its coordinates
 *    (only such indices are ever vertices).
 *    A point added by dd_cgal_insert counts as a first occurrence (it was
 *    no vertex's equal when inserted).
 *  - dt.dimension() == 3 always: removals that would lower it are refused.
 *  - A refused or failed call leaves the triangulation exactly as it was
 *    (except on out-of-memory inside CGAL's own remove/insert, which CGAL
 *    itself cannot undo).
 *  - No C++ exception crosses the extern "C" boundary; no mutable globals.
 */
#include "cgal_shim.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/version.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <utility>
#include <vector>

/* Types live in a named namespace: struct dd_cgal (external linkage) holds
 * them, so they must not have internal linkage.                          */
namespace dd_shim {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;

/* The main triangulation: info = input index. */
typedef CGAL::Triangulation_vertex_base_with_info_3<uint32_t, K> Vb;
typedef CGAL::Delaunay_triangulation_cell_base_3<K> Cb;
typedef CGAL::Triangulation_data_structure_3<Vb, Cb> Tds;
typedef CGAL::Delaunay_triangulation_3<K, Tds> Base_dt;

/* Exposes CGAL's (protected) dimension-drop test, the one remove() uses. */
struct Main_dt : public Base_dt {
    using Base_dt::test_dim_down;
};

typedef Main_dt::Vertex_handle Vertex_handle;
typedef Main_dt::Cell_handle Cell_handle;
typedef Main_dt::Vertex Vertex;

/* The temporary DT of cgal-rnd: vertex info = the main vertex it copies;
 * cell info = 1 + its slot in the list of cells that fill the hole, 0 when
 * not (yet) reached.  Mark has a default initialiser because CGAL leaves
 * info of a plain integer type uninitialised.                            */
struct Mark {
    uint32_t slot = 0;
};
typedef CGAL::Triangulation_vertex_base_with_info_3<Vertex_handle, K> Tmp_vb;
typedef CGAL::Triangulation_cell_base_with_info_3<Mark, K, Cb> Tmp_cb;
typedef CGAL::Triangulation_data_structure_3<Tmp_vb, Tmp_cb> Tmp_tds;
typedef CGAL::Delaunay_triangulation_3<K, Tmp_tds> Tmp_dt;

/* Exposes CGAL's (protected) perturbed predicates.  Only ever used as a
 * const object; it holds nothing but an empty triangulation.            */
struct Pred_dt : public CGAL::Delaunay_triangulation_3<K> {
    using CGAL::Delaunay_triangulation_3<K>::side_of_oriented_sphere;
    using CGAL::Delaunay_triangulation_3<K>::coplanar_side_of_bounded_circle;
};

} // namespace dd_shim

using namespace dd_shim;

namespace {

const Pred_dt &pred_dt()
{
    static const Pred_dt dt;   /* immutable after its thread-safe init */
    return dt;
}

Point to_point(const double *p) { return Point(p[0], p[1], p[2]); }

} // namespace

struct dd_cgal {
    Main_dt dt;
    std::vector<Point> pts;              /* input points, all n of them    */
    std::vector<Vertex_handle> vh;       /* input index -> vertex or null  */
    std::vector<unsigned char> first;    /* 1 iff first of its coordinates */
};

namespace {

/* Is input index v a vertex of c now? */
bool has_vertex(const dd_cgal *c, uint32_t v)
{
    return v < c->vh.size() && c->vh[v] != Vertex_handle();
}

/* Would removing vertex h leave fewer than 4 vertices or a flat set?
 * (CGAL's own test: O(1) unless h is incident to the first finite cell.) */
bool removal_drops_dimension(const Main_dt &dt, Vertex_handle h)
{
    return dt.number_of_vertices() <= 4 || dt.test_dim_down(h);
}

/* ---- cgal-rnd: triangulate-and-sew in random order ------------------- */

/* A facet of the hole's boundary: the link triangle opposite v in hole cell
 * `hole`, keyed by its three main vertices sorted by address; `out` is the
 * cell outside the hole across it, and out_i the facet's index in `out`. */
struct Hole_facet {
    std::array<const Vertex *, 3> key;
    Cell_handle out;
    int out_i;
    unsigned matched;
};

typedef std::array<const Vertex *, 3> Facet_key;

Facet_key sorted_key(const Vertex *a, const Vertex *b, const Vertex *c)
{
    Facet_key k = {{a, b, c}};
    std::sort(k.begin(), k.end());
    return k;
}

/* Sign (+1/-1) of the permutation (p[0],p[1],p[2],p[3]) of 0..3. */
int permutation_sign(const int p[4])
{
    int inv = 0;
    for (int i = 0; i < 4; i++)
        for (int j = i + 1; j < 4; j++)
            if (p[i] > p[j])
                inv++;
    return (inv & 1) ? -1 : 1;
}

/* Index of the hole facet with key k, or -1.  `facets` is sorted by key. */
long find_hole_facet(const std::vector<Hole_facet> &facets, const Facet_key &k)
{
    std::vector<Hole_facet>::const_iterator it = std::lower_bound(
        facets.begin(), facets.end(), k,
        [](const Hole_facet &f, const Facet_key &key) { return f.key < key; });
    if (it == facets.end() || it->key != k)
        return -1;
    return static_cast<long>(it - facets.begin());
}

/*
 * remove_rnd: deletes finite vertex v (whose removal keeps dimension 3).
 * 1. The hole: the cells incident to v; its boundary facets with the outside
 *    cells across them.
 * 2. tmp = DT of v's finite neighbours inserted one by one in an order
 *    shuffled by `seed` (each insertion hinted by the previous vertex's
 *    cell).  If v is on the hull, tmp's infinite vertex stands for the main
 *    one; if the finite neighbours are coplanar (then v is on the hull),
 *    v's own point is inserted and stands for the infinite vertex, as in
 *    CGAL's remove_3D.
 * 3. Seed: a finite boundary facet, found in tmp with is_facet; of its two
 *    tmp cells, the one whose fourth vertex lies on v's side (same
 *    combinatorial orientation as the hole cell with v replaced).  Flood
 *    fill across tmp facets that are not boundary facets.  Every boundary
 *    facet must be met exactly once, else nothing is changed.
 * 4. Sew: create the mapped cells, link them to each other and to the
 *    outside cells, point every vertex of a new cell to it, delete the hole
 *    cells and v.
 * Returns 0 on success; nonzero (triangulation unchanged) on an internal
 * mismatch.  Cost: O(deg(v) log deg(v)) besides building tmp.
 */
int remove_rnd(Main_dt &dt, Vertex_handle v, uint64_t seed)
{
    const Vertex_handle inf = dt.infinite_vertex();

    /* 1. the hole and its boundary */
    std::vector<Cell_handle> hole;
    dt.incident_cells(v, std::back_inserter(hole));
    std::vector<Hole_facet> facets;
    facets.reserve(hole.size());
    long seed_cell = -1;
    for (std::size_t h = 0; h < hole.size(); h++) {
        const Cell_handle hc = hole[h];
        const int iv = hc->index(v);
        const Vertex_handle a = hc->vertex((iv + 1) & 3);
        const Vertex_handle b = hc->vertex((iv + 2) & 3);
        const Vertex_handle c = hc->vertex((iv + 3) & 3);
        Hole_facet f;
        f.key = sorted_key(&*a, &*b, &*c);
        f.out = hc->neighbor(iv);
        f.out_i = f.out->index(hc);
        f.matched = 0;
        facets.push_back(f);
        if (seed_cell < 0 && a != inf && b != inf && c != inf)
            seed_cell = static_cast<long>(h);
    }
    if (seed_cell < 0)
        return 1;
    std::sort(facets.begin(), facets.end(),
              [](const Hole_facet &x, const Hole_facet &y) {
                  return x.key < y.key;
              });

    /* 2. tmp = DT of the finite neighbours in random order */
    std::vector<Vertex_handle> adj;
    dt.adjacent_vertices(v, std::back_inserter(adj));
    bool on_hull = false;
    std::size_t nfin = 0;
    for (std::size_t i = 0; i < adj.size(); i++) {
        if (adj[i] == inf)
            on_hull = true;
        else
            adj[nfin++] = adj[i];
    }
    adj.resize(nfin);
    std::mt19937_64 rng(seed);
    for (std::size_t i = nfin; i > 1; i--) {        /* Fisher-Yates */
        const std::size_t j = static_cast<std::size_t>(rng() % i);
        std::swap(adj[i - 1], adj[j]);
    }
    Tmp_dt tmp;
    std::vector<Tmp_dt::Vertex_handle> tadj(nfin);
    Tmp_dt::Cell_handle hint;
    for (std::size_t i = 0; i < nfin; i++) {
        tadj[i] = tmp.insert(adj[i]->point(), hint);
        tadj[i]->info() = adj[i];
        hint = tadj[i]->cell();
    }
    if (tmp.dimension() == 2 && on_hull) {
        Tmp_dt::Vertex_handle fake = tmp.insert(v->point(), hint);
        fake->info() = inf;
    } else if (on_hull) {
        tmp.infinite_vertex()->info() = inf;
    }
    if (tmp.dimension() != 3)
        return 1;

    /* 3. seed, then flood fill over tmp */
    const Cell_handle sc = hole[static_cast<std::size_t>(seed_cell)];
    const int siv = sc->index(v);
    int hp[4] = {(siv + 1) & 3, (siv + 2) & 3, (siv + 3) & 3, siv};
    Tmp_dt::Vertex_handle tv[3];
    for (int k = 0; k < 3; k++) {
        const Vertex_handle m = sc->vertex(hp[k]);
        std::size_t i = 0;
        while (i < nfin && adj[i] != m)
            i++;
        if (i == nfin)
            return 1;
        tv[k] = tadj[i];
    }
    Tmp_dt::Cell_handle tc;
    int ti, tj, tk;
    if (!tmp.is_facet(tv[0], tv[1], tv[2], tc, ti, tj, tk))
        return 1;
    int tp[4] = {ti, tj, tk, 6 - ti - tj - tk};
    if (permutation_sign(hp) != permutation_sign(tp))
        tc = tc->neighbor(tp[3]);

    std::vector<Tmp_dt::Cell_handle> fill;    /* tmp cells filling the hole */
    std::vector<std::array<long, 4> > glue;   /* hole facet per facet or -1 */
    std::vector<Tmp_dt::Cell_handle> stack;
    const std::array<long, 4> unglued = {{-1, -1, -1, -1}};
    tc->info().slot = 1;
    fill.push_back(tc);
    glue.push_back(unglued);
    stack.push_back(tc);
    std::size_t nmatched = 0;
    while (!stack.empty()) {
        const Tmp_dt::Cell_handle t = stack.back();
        stack.pop_back();
        const Vertex *mv[4];
        for (int k = 0; k < 4; k++) {
            const Vertex_handle m = t->vertex(k)->info();
            if (m == Vertex_handle())
                return 1;              /* reached a vertex with no image */
            mv[k] = &*m;
        }
        std::array<long, 4> g;
        for (int f = 0; f < 4; f++) {
            const long hf = find_hole_facet(
                facets, sorted_key(mv[(f + 1) & 3], mv[(f + 2) & 3],
                                   mv[(f + 3) & 3]));
            g[static_cast<std::size_t>(f)] = hf;
            if (hf >= 0) {
                if (facets[static_cast<std::size_t>(hf)].matched++ != 0)
                    return 1;
                nmatched++;
                continue;
            }
            const Tmp_dt::Cell_handle n = t->neighbor(f);
            if (n->info().slot == 0) {
                fill.push_back(n);
                glue.push_back(unglued);
                n->info().slot = static_cast<uint32_t>(fill.size());
                stack.push_back(n);
            }
        }
        glue[t->info().slot - 1] = g;
    }
    if (nmatched != facets.size())
        return 1;

    /* 4. sew the new cells in; from here on nothing can fail but memory */
    Tds &tds = dt.tds();
    std::vector<Cell_handle> made(fill.size());
    for (std::size_t i = 0; i < fill.size(); i++) {
        const Tmp_dt::Cell_handle t = fill[i];
        made[i] = tds.create_cell(t->vertex(0)->info(), t->vertex(1)->info(),
                                  t->vertex(2)->info(), t->vertex(3)->info());
    }
    for (std::size_t i = 0; i < fill.size(); i++) {
        const Tmp_dt::Cell_handle t = fill[i];
        for (int f = 0; f < 4; f++) {
            const long hf = glue[i][static_cast<std::size_t>(f)];
            if (hf >= 0) {
                const Hole_facet &b = facets[static_cast<std::size_t>(hf)];
                made[i]->set_neighbor(f, b.out);
                b.out->set_neighbor(b.out_i, made[i]);
            } else {
                made[i]->set_neighbor(
                    f, made[t->neighbor(f)->info().slot - 1]);
            }
        }
        for (int k = 0; k < 4; k++)
            made[i]->vertex(k)->set_cell(made[i]);
    }
    tds.delete_cells(hole.begin(), hole.end());
    tds.delete_vertex(v);
    return 0;
}

/* The cell as its four input indices sorted, -1 for the infinite vertex. */
std::array<int32_t, 4> canonical_cell(const Main_dt &dt, Cell_handle c)
{
    std::array<int32_t, 4> t;
    for (std::size_t k = 0; k < 4; k++) {
        const Vertex_handle w = c->vertex(static_cast<int>(k));
        t[k] = dt.is_infinite(w) ? -1 : static_cast<int32_t>(w->info());
    }
    std::sort(t.begin(), t.end());
    return t;
}

/* Sorts and deduplicates the cells and hands them out as a malloc'd array. */
int emit_canonical(std::vector<std::array<int32_t, 4> > &all, int32_t **tets, size_t *ntets)
{
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    int32_t *out = static_cast<int32_t *>(
        std::malloc(4 * sizeof(int32_t) * (all.empty() ? 1 : all.size())));
    if (out == NULL)
        return 1;
    for (std::size_t i = 0; i < all.size(); i++)
        std::memcpy(out + 4 * i, all[i].data(), 4 * sizeof(int32_t));
    *tets = out;
    *ntets = all.size();
    return 0;
}

/* Deletes input vertex v of c with CGAL's remove() or, when rnd, with
 * remove_rnd (seeded by seed).  0; 1, c unchanged, when v is no vertex,
 * its removal would leave fewer than 4 or only coplanar points, or
 * remove_rnd finds a mismatch.                                          */
int remove_vertex(dd_cgal *c, uint32_t v, bool rnd, uint64_t seed)
{
    if (c == NULL || !has_vertex(c, v))
        return 1;
    try {
        const Vertex_handle h = c->vh[v];
        if (removal_drops_dimension(c->dt, h))
            return 1;
        if (!rnd)
            c->dt.remove(h);
        else if (remove_rnd(c->dt, h, seed) != 0)
            return 1;
        c->vh[v] = Vertex_handle();
        return 0;
    } catch (...) {
        return 1;
    }
}

} // namespace

extern "C" {

dd_cgal *dd_cgal_build(const double *xyz, uint32_t n)
{
    if (xyz == NULL || n < 4)
        return NULL;
    try {
        for (std::size_t i = 0; i < 3 * static_cast<std::size_t>(n); i++)
            if (!std::isfinite(xyz[i]))
                return NULL;
        dd_cgal *c = new dd_cgal;
        c->pts.reserve(n);
        for (uint32_t i = 0; i < n; i++)
            c->pts.push_back(to_point(xyz + 3 * static_cast<std::size_t>(i)));

        /* keep the first of equal points: sort by (x, y, z, index) */
        std::vector<uint32_t> order(n);
        for (uint32_t i = 0; i < n; i++)
            order[i] = i;
        std::sort(order.begin(), order.end(), [xyz](uint32_t a, uint32_t b) {
            const double *p = xyz + 3 * static_cast<std::size_t>(a);
            const double *q = xyz + 3 * static_cast<std::size_t>(b);
            for (int k = 0; k < 3; k++)
                if (p[k] != q[k])
                    return p[k] < q[k];
            return a < b;
        });
        c->first.assign(n, 0);
        std::vector<std::pair<Point, uint32_t> > input;
        input.reserve(n);
        for (uint32_t r = 0; r < n; r++) {
            const uint32_t i = order[r];
            if (r > 0 && c->pts[i] == c->pts[order[r - 1]])
                continue;
            c->first[i] = 1;
            input.push_back(std::make_pair(c->pts[i], i));
        }

        c->dt.insert(input.begin(), input.end());
        if (c->dt.dimension() != 3) {
            delete c;
            return NULL;
        }
        c->vh.assign(n, Vertex_handle());
        for (Main_dt::Finite_vertices_iterator it =
                 c->dt.finite_vertices_begin();
             it != c->dt.finite_vertices_end(); ++it)
            c->vh[it->info()] = it;
        return c;
    } catch (...) {
        return NULL;
    }
}

void dd_cgal_free(dd_cgal *c)
{
    try {
        delete c;
    } catch (...) {
    }
}

int dd_cgal_canonical(const dd_cgal *c, int32_t **tets, size_t *ntets)
{
    if (c == NULL || tets == NULL || ntets == NULL)
        return 1;
    *tets = NULL;
    *ntets = 0;
    try {
        const Main_dt &dt = c->dt;
        std::vector<std::array<int32_t, 4> > all;
        all.reserve(dt.number_of_cells());
        for (Main_dt::All_cells_iterator it = dt.all_cells_begin();
             it != dt.all_cells_end(); ++it)
            all.push_back(canonical_cell(dt, it));
        return emit_canonical(all, tets, ntets);
    } catch (...) {
        return 1;
    }
}

int dd_cgal_local_canonical(const dd_cgal *c, const uint32_t *verts, size_t nv,
                            int32_t **tets, size_t *ntets)
{
    if (c == NULL || tets == NULL || ntets == NULL)
        return 1;
    *tets = NULL;
    *ntets = 0;
    try {
        const Main_dt &dt = c->dt;
        std::vector<std::array<int32_t, 4> > all;
        std::vector<Cell_handle> cells;
        for (std::size_t i = 0; i < nv; i++) {
            if (!has_vertex(c, verts[i]))
                return 1;
            cells.clear();
            dt.incident_cells(c->vh[verts[i]], std::back_inserter(cells));
            for (std::size_t j = 0; j < cells.size(); j++)
                all.push_back(canonical_cell(dt, cells[j]));
        }
        return emit_canonical(all, tets, ntets);
    } catch (...) {
        return 1;
    }
}

int dd_cgal_remove(dd_cgal *c, uint32_t v)
{
    return remove_vertex(c, v, false, 0);
}

int dd_cgal_remove_rnd(dd_cgal *c, uint32_t v, uint64_t seed)
{
    return remove_vertex(c, v, true, seed);
}

int dd_cgal_reinsert(dd_cgal *c, uint32_t v)
{
    if (c == NULL || v >= c->vh.size() || has_vertex(c, v) || !c->first[v])
        return 1;
    try {
        const std::size_t before = c->dt.number_of_vertices();
        const Vertex_handle h = c->dt.insert(c->pts[v]);
        if (c->dt.number_of_vertices() != before + 1)
            return 1;                  /* equal to an existing vertex */
        h->info() = v;
        c->vh[v] = h;
        return 0;
    } catch (...) {
        return 1;
    }
}

int dd_cgal_insert(dd_cgal *c, const double p[3], uint32_t index)
{
    if (c == NULL || p == NULL || index > c->pts.size() || index == UINT32_MAX)
        return 1;
    const bool reuse = index < c->pts.size();   /* a removed vertex's index */
    if (reuse && (has_vertex(c, index) || !c->first[index]))
        return 1;
    for (int k = 0; k < 3; k++)
        if (!std::isfinite(p[k]))
            return 1;
    try {
        const Point pt = to_point(p);
        const std::size_t before = c->dt.number_of_vertices();
        Main_dt::Locate_type lt;
        int li, lj;
        const Cell_handle loc = c->dt.locate(pt, lt, li, lj);
        if (lt == Main_dt::VERTEX)
            return 2;                  /* equal to a vertex: no index taken */
        const Point old = reuse ? c->pts[index] : pt;
        if (reuse) {
            c->pts[index] = pt;
        } else {
            c->pts.push_back(pt);
            c->vh.push_back(Vertex_handle());
            c->first.push_back(1);
        }
        const Vertex_handle h = c->dt.insert(pt, lt, loc, li, lj);
        if (c->dt.number_of_vertices() != before + 1) {
            if (reuse) {
                c->pts[index] = old;
            } else {
                c->pts.pop_back();
                c->vh.pop_back();
                c->first.pop_back();
            }
            return 1;
        }
        h->info() = index;
        c->vh[index] = h;
        return 0;
    } catch (...) {
        return 1;
    }
}

int dd_cgal_move(dd_cgal *c, uint32_t v, const double p[3])
{
    if (c == NULL || p == NULL || !has_vertex(c, v))
        return 1;
    for (int k = 0; k < 3; k++)
        if (!std::isfinite(p[k]))
            return 1;
    try {
        const Point pt = to_point(p), old = c->pts[v];
        if (pt == old)
            return 0;
        Vertex_handle h = c->dt.move_if_no_collision(c->vh[v], pt);
        if (h->info() != v)
            return 2;                      /* p is another vertex's point */
        if (c->dt.dimension() != 3) {      /* put back: refused, as dd_move does */
            c->vh[v] = c->dt.move_if_no_collision(h, old);
            return c->dt.dimension() == 3 && c->vh[v]->info() == v ? 3 : 1;
        }
        c->vh[v] = h;
        c->pts[v] = pt;
        return 0;
    } catch (...) {
        return 1;
    }
}

uint32_t dd_cgal_num_input(const dd_cgal *c)
{
    return c == NULL ? 0 : static_cast<uint32_t>(c->pts.size());
}

/* Predicates.  On an exception (out of memory in the exact fallback) they
 * return 0, the only value left; it does not happen in practice.         */

int dd_cgal_orientation(const double *p, const double *q, const double *r,
                        const double *s)
{
    try {
        return static_cast<int>(K().orientation_3_object()(
            to_point(p), to_point(q), to_point(r), to_point(s)));
    } catch (...) {
        return 0;
    }
}

int dd_cgal_side_of_oriented_sphere(const double *p0, const double *p1,
                                    const double *p2, const double *p3,
                                    const double *p, int perturb)
{
    try {
        return static_cast<int>(pred_dt().side_of_oriented_sphere(
            to_point(p0), to_point(p1), to_point(p2), to_point(p3),
            to_point(p), perturb != 0));
    } catch (...) {
        return 0;
    }
}

int dd_cgal_coplanar_orientation(const double *p, const double *q,
                                 const double *r)
{
    try {
        return static_cast<int>(K().coplanar_orientation_3_object()(
            to_point(p), to_point(q), to_point(r)));
    } catch (...) {
        return 0;
    }
}

int dd_cgal_coplanar_side_of_bounded_circle(const double *p0,
                                            const double *p1,
                                            const double *p2,
                                            const double *p, int perturb)
{
    try {
        return static_cast<int>(pred_dt().coplanar_side_of_bounded_circle(
            to_point(p0), to_point(p1), to_point(p2), to_point(p),
            perturb != 0));
    } catch (...) {
        return 0;
    }
}

/* Mirrors the private Delaunay_triangulation_3::side_of_sphere(v0..v3, p,
 * perturb): for an infinite vertex, the orientation of the finite facet
 * (in CGAL's argument order) against p decides, and if p is in its plane
 * the perturbed in-circle test of that facet does.                       */
int dd_cgal_side_of_sphere_cell(const double *v0, const double *v1,
                                const double *v2, const double *v3,
                                int inf_index, const double *p, int perturb)
{
    try {
        const Pred_dt &dt = pred_dt();
        const bool pb = perturb != 0;
        const Point q = to_point(p);
        const double *a, *b, *c;
        switch (inf_index) {
        case -1:
            return static_cast<int>(dt.side_of_oriented_sphere(
                to_point(v0), to_point(v1), to_point(v2), to_point(v3), q,
                pb));
        case 0: a = v2; b = v1; c = v3; break;
        case 1: a = v2; b = v3; c = v0; break;
        case 2: a = v1; b = v0; c = v3; break;
        case 3: a = v0; b = v1; c = v2; break;
        default: return 0;
        }
        const Point pa = to_point(a), pb3 = to_point(b), pc = to_point(c);
        const CGAL::Orientation o =
            K().orientation_3_object()(pa, pb3, pc, q);
        if (o != CGAL::COPLANAR)
            return static_cast<int>(o);
        return static_cast<int>(
            dt.coplanar_side_of_bounded_circle(pa, pb3, pc, q, pb));
    } catch (...) {
        return 0;
    }
}

const char *dd_cgal_version(void)
{
    return "CGAL " CGAL_VERSION_STR;
}

} // extern "C"
