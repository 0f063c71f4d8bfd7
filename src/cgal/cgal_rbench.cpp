/*
 * cgal_rbench.cpp -- CGAL's Regular_triangulation_3 behind cgal_rbench.h:
 * the bench's reference for weighted deletions, moves and re-weightings.
 *
 * Owns: one regular triangulation (Epick, the vertex and cell bases of
 * cgal_regular.cpp, Keep_hidden_points or Discard_hidden_points), a vertex
 * handle and a state per input index, and a map from a weighted point
 * (x, y, z, w) to the live indices (vertex or hidden) that carry it: CGAL
 * stores a hidden point as a bare Weighted_point_3, so the map names it.
 *
 * Invariants:
 *  - state[i] == VERTEX iff vh[i] is a live vertex whose info is i.
 *  - keys[k] lists the indices in state VERTEX or HIDDEN whose weighted
 *    point is k; a vertex made by CGAL from a hidden point (a removal
 *    brings it back) has info UINT32_MAX until the bookkeeping after the
 *    removal names it.
 *  - The clock runs around CGAL's call only; the bookkeeping walks the
 *    edited region (the removed vertex's former neighbours and what they
 *    reach through vertices CGAL made; the cells an insertion conflicts
 *    with), never the whole triangulation.
 *  - No C++ exception crosses the extern "C" boundary.
 */
#include "cgal_rbench.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace dd_rbench {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Bare_point;
typedef K::Weighted_point_3 Wpoint;
typedef std::array<double, 4> Key;          /* x, y, z, w */

/* A vertex's input index; UINT32_MAX for a vertex CGAL made itself. */
struct Index {
    uint32_t i = UINT32_MAX;
};

typedef CGAL::Regular_triangulation_vertex_base_3<K> Rvb;
typedef CGAL::Triangulation_vertex_base_with_info_3<Index, K, Rvb> Vb;
template <class Policy>
using Rcb = CGAL::Regular_triangulation_cell_base_3<K, CGAL::Triangulation_cell_base_3<K>, Policy>;
template <class Policy>
using Rt = CGAL::Regular_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb, Rcb<Policy> > >;

inline Key key_of(const Wpoint &p)
{
    const Bare_point &b = p.point();
    Key k = {{b.x(), b.y(), b.z(), p.weight()}};
    return k;
}

inline double seconds_now()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/* What the C face needs from either hidden-point policy. */
struct Any {
    virtual ~Any() {}
    virtual bool build(const double *xyz, const double *w, uint32_t n) = 0;
    virtual int remove(uint32_t i, double *secs) = 0;
    virtual int insert(uint32_t i, const Wpoint &p, uint32_t hint, double *secs) = 0;
    virtual int move(uint32_t i, const Wpoint &p, double *secs, int *fell_back) = 0;
    virtual void cells(std::vector<std::array<int32_t, 4> > &out) const = 0;
    virtual bool local(const uint32_t *vs, std::size_t k, std::vector<std::array<int32_t, 4> > &out) const = 0;
    virtual void hidden(std::vector<uint32_t> &out) const = 0;
    std::vector<unsigned char> state;
    std::vector<uint32_t> released, neighbors;
};

template <class Policy>
struct Bench : public Any {
    typedef Rt<Policy> T;
    typedef typename T::Vertex_handle V;
    typedef typename T::Cell_handle C;
    static const bool keep = std::is_same<Policy, CGAL::Keep_hidden_points>::value;
    T rt;
    std::vector<V> vh;
    std::map<Key, std::vector<uint32_t> > keys;
    V last;                                   /* the last vertex made: a hint */

    void forget_key(const Key &k, uint32_t i)
    {
        typename std::map<Key, std::vector<uint32_t> >::iterator it = keys.find(k);
        if (it == keys.end()) return;
        it->second.erase(std::remove(it->second.begin(), it->second.end(), i), it->second.end());
        if (it->second.empty()) keys.erase(it);
    }

    /* The index of a hidden point CGAL made a vertex again. */
    uint32_t hidden_index(const Wpoint &p) const
    {
        typename std::map<Key, std::vector<uint32_t> >::const_iterator it = keys.find(key_of(p));
        if (it == keys.end()) return UINT32_MAX;
        for (std::size_t j = 0; j < it->second.size(); j++)
            if (state[it->second[j]] == DD_RB_HIDDEN) return it->second[j];
        return UINT32_MAX;
    }

    void set_vertex(V v, uint32_t i)
    {
        v->info().i = i;
        vh[i] = v;
        state[i] = DD_RB_VERTEX;
        last = v;
    }

    bool build(const double *xyz, const double *w, uint32_t n) override
    {
        std::vector<std::pair<Wpoint, Index> > in;
        in.reserve(n);
        state.assign(n, DD_RB_NONE);
        vh.assign(n, V());
        for (uint32_t i = 0; i < n; i++) {
            const double *p = xyz + 3 * static_cast<std::size_t>(i);
            const Key k = {{p[0], p[1], p[2], w[i]}};
            std::vector<uint32_t> &idx = keys[k];
            if (!idx.empty()) continue;           /* an exact duplicate: the first stays */
            idx.push_back(i);
            Index x;
            x.i = i;
            in.push_back(std::make_pair(Wpoint(Bare_point(p[0], p[1], p[2]), w[i]), x));
        }
        rt.insert(in.begin(), in.end());
        if (rt.dimension() != 3) return false;
        for (typename T::Finite_vertices_iterator it = rt.finite_vertices_begin(); it != rt.finite_vertices_end(); ++it)
            set_vertex(it, it->info().i);
        for (typename std::map<Key, std::vector<uint32_t> >::iterator it = keys.begin(); it != keys.end();) {
            const uint32_t i = it->second.front();
            if (state[i] == DD_RB_VERTEX) { ++it; continue; }
            if (keep) { state[i] = DD_RB_HIDDEN; ++it; }
            else keys.erase(it++);                /* forgotten */
        }
        return true;
    }

    void finite_neighbors(V v, std::vector<V> &out) const
    {
        out.clear();
        rt.finite_adjacent_vertices(v, std::back_inserter(out));
    }

    /* Names the vertices CGAL made from hidden points while removing a
     * vertex whose finite neighbours were nb: each such vertex is
     * adjacent to a neighbour or to another one of them.                */
    void name_released(const std::vector<V> &nb)
    {
        released.clear();
        std::vector<V> queue(nb), adj;
        for (std::size_t q = 0; q < queue.size(); q++) {
            finite_neighbors(queue[q], adj);
            for (std::size_t j = 0; j < adj.size(); j++) {
                if (adj[j]->info().i != UINT32_MAX) continue;
                const uint32_t i = hidden_index(adj[j]->point());
                if (i == UINT32_MAX) throw 1;         /* a vertex nobody gave */
                set_vertex(adj[j], i);
                released.push_back(i);
                queue.push_back(adj[j]);
            }
        }
    }

    int remove(uint32_t i, double *secs) override
    {
        *secs = 0;
        if (i >= state.size() || state[i] != DD_RB_VERTEX) return 1;
        if (rt.number_of_vertices() <= 4) return 3;
        const V v = vh[i];
        std::vector<V> nb;
        finite_neighbors(v, nb);
        neighbors.clear();
        for (std::size_t j = 0; j < nb.size(); j++) neighbors.push_back(nb[j]->info().i);
        const Key k = key_of(v->point());
        const double t0 = seconds_now();
        rt.remove(v);
        *secs = seconds_now() - t0;
        forget_key(k, i);
        state[i] = DD_RB_NONE;
        vh[i] = V();
        last = nb.front();
        name_released(nb);
        return rt.dimension() == 3 ? 0 : 3;
    }

    /* The indices of the vertices inserting p (located in c, lt, li)
     * hides; *hidden: p ends hidden; *dup: p is a vertex's weighted point. */
    void what_insert_hides(const Wpoint &p, C c, typename T::Locate_type lt, int li, std::vector<uint32_t> &gone,
                           bool *hidden, bool *dup) const
    {
        gone.clear();
        *hidden = *dup = false;
        /* CGAL's insert_in_conflict: a vertex's exact weighted point is
         * that vertex; otherwise, on a vertex's position too, the point
         * is hidden unless in conflict with the cell located, and then
         * hides the vertices inside its conflict zone.                   */
        if (lt == T::VERTEX && c->vertex(li)->point().weight() == p.weight()) {
            *dup = true;
            return;
        }
        if (rt.side_of_power_sphere(c, p, true) != CGAL::ON_BOUNDED_SIDE) {
            *hidden = true;
            return;
        }
        std::vector<V> in;
        rt.vertices_inside_conflict_zone(p, c, std::back_inserter(in));
        for (std::size_t j = 0; j < in.size(); j++) gone.push_back(in[j]->info().i);
    }

    int insert(uint32_t i, const Wpoint &p, uint32_t hint, double *secs) override
    {
        *secs = 0;
        if (i >= state.size() || state[i] != DD_RB_NONE) return 1;
        const C start = hint < state.size() && state[hint] == DD_RB_VERTEX ? vh[hint]->cell() : last->cell();
        typename T::Locate_type lt;
        int li, lj;
        const C c = rt.locate(p, lt, li, lj, start);
        std::vector<uint32_t> gone;
        std::vector<Key> gone_keys;
        bool hidden, dup;
        what_insert_hides(p, c, lt, li, gone, &hidden, &dup);
        if (dup) return 2;
        for (std::size_t j = 0; j < gone.size(); j++) gone_keys.push_back(key_of(vh[gone[j]]->point()));
        const double t0 = seconds_now();
        const V v = rt.insert(p, start);
        *secs = seconds_now() - t0;
        for (std::size_t j = 0; j < gone.size(); j++) {
            vh[gone[j]] = V();
            state[gone[j]] = keep ? DD_RB_HIDDEN : DD_RB_NONE;
            if (!keep) forget_key(gone_keys[j], gone[j]);
        }
        if ((v == V()) != hidden) throw 1;            /* the prediction was wrong */
        if (hidden) {
            if (keep) {
                keys[key_of(p)].push_back(i);
                state[i] = DD_RB_HIDDEN;
            }
            return 0;
        }
        keys[key_of(p)].push_back(i);
        set_vertex(v, i);
        return 0;
    }

    /* Whether CGAL's move() of v to p gives the reference result (see
     * cgal_rbench.h); *dup: p is another vertex's weighted point.        */
    bool move_is_reference(V v, const Wpoint &p, bool *dup) const
    {
        *dup = false;
        if (v->point().point() == p.point()) return false;
        typename T::Locate_type lt;
        int li, lj;
        const C c = rt.locate(p, lt, li, lj, v->cell());
        if (lt == T::VERTEX) {
            *dup = c->vertex(li)->point().weight() == p.weight();
            return false;
        }
        if (rt.side_of_power_sphere(c, p, true) != CGAL::ON_BOUNDED_SIDE) return false;
        std::vector<C> conflict;
        std::vector<typename T::Facet> boundary;
        rt.find_conflicts(p, c, std::back_inserter(boundary), std::back_inserter(conflict));
        std::vector<V> in;
        rt.vertices_inside_conflict_zone(p, c, std::back_inserter(in));
        if (!in.empty()) return false;
        if (!keep) return true;
        for (std::size_t j = 0; j < conflict.size(); j++)
            if (conflict[j]->hidden_points_begin() != conflict[j]->hidden_points_end()) return false;
        std::vector<C> star;
        rt.incident_cells(v, std::back_inserter(star));
        for (std::size_t j = 0; j < star.size(); j++)
            if (star[j]->hidden_points_begin() != star[j]->hidden_points_end()) return false;
        return true;
    }

    int move(uint32_t i, const Wpoint &p, double *secs, int *fell_back) override
    {
        *secs = 0;
        *fell_back = 0;
        if (i >= state.size() || state[i] != DD_RB_VERTEX) return 1;
        const V v = vh[i];
        bool dup;
        if (move_is_reference(v, p, &dup)) {
            const Key k = key_of(v->point());
            const double t0 = seconds_now();
            const V r = rt.move(v, p);
            *secs = seconds_now() - t0;
            if (r != v) throw 1;
            forget_key(k, i);
            keys[key_of(p)].push_back(i);
            last = v;
            return 0;
        }
        if (dup) return 2;
        *fell_back = 1;
        double s1, s2;
        int rc = remove(i, &s1);
        if (rc) return rc;
        const uint32_t hint = neighbors.empty() ? UINT32_MAX : neighbors.front();
        rc = insert(i, p, hint, &s2);
        *secs = s1 + s2;
        return rc;
    }

    std::array<int32_t, 4> cell_of(C c) const
    {
        std::array<int32_t, 4> t;
        for (int k = 0; k < 4; k++) {
            const V v = c->vertex(k);
            t[static_cast<std::size_t>(k)] = rt.is_infinite(v) ? -1 : static_cast<int32_t>(v->info().i);
        }
        std::sort(t.begin(), t.end());
        return t;
    }

    void cells(std::vector<std::array<int32_t, 4> > &out) const override
    {
        out.reserve(rt.number_of_cells());
        for (typename T::All_cells_iterator it = rt.all_cells_begin(); it != rt.all_cells_end(); ++it)
            out.push_back(cell_of(it));
    }

    bool local(const uint32_t *vs, std::size_t k, std::vector<std::array<int32_t, 4> > &out) const override
    {
        std::vector<C> inc;
        for (std::size_t j = 0; j < k; j++) {
            if (vs[j] >= state.size() || state[vs[j]] != DD_RB_VERTEX) return false;
            inc.clear();
            rt.incident_cells(vh[vs[j]], std::back_inserter(inc));
            for (std::size_t q = 0; q < inc.size(); q++) out.push_back(cell_of(inc[q]));
        }
        return true;
    }

    void hidden(std::vector<uint32_t> &out) const override
    {
        std::vector<Key> hk;
        for (typename T::All_cells_iterator it = rt.all_cells_begin(); it != rt.all_cells_end(); ++it)
            for (typename T::Cell::Point_const_iterator h = it->hidden_points_begin(); h != it->hidden_points_end(); ++h)
                hk.push_back(key_of(*h));
        std::sort(hk.begin(), hk.end());
        hk.erase(std::unique(hk.begin(), hk.end()), hk.end());
        for (std::size_t j = 0; j < hk.size(); j++) {
            typename std::map<Key, std::vector<uint32_t> >::const_iterator it = keys.find(hk[j]);
            if (it == keys.end()) throw 1;            /* a hidden point nobody gave */
            out.insert(out.end(), it->second.begin(), it->second.end());
        }
    }
};

} // namespace dd_rbench

using namespace dd_rbench;

struct dd_cgal_rb {
    std::unique_ptr<Any> b;
};

namespace {

bool finite_point(const double *p, double w)
{
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(w);
}

int emit_cells(std::vector<std::array<int32_t, 4> > &all, int32_t **tets, size_t *ntets)
{
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    int32_t *out = static_cast<int32_t *>(std::malloc(4 * sizeof(int32_t) * (all.empty() ? 1 : all.size())));
    if (out == NULL) return 1;
    for (std::size_t i = 0; i < all.size(); i++) std::memcpy(out + 4 * i, all[i].data(), 4 * sizeof(int32_t));
    *tets = out;
    *ntets = all.size();
    return 0;
}

} // namespace

extern "C" {

dd_cgal_rb *dd_cgal_rb_build(const double *xyz, const double *w, uint32_t n, int discard_hidden)
{
    if (xyz == NULL || w == NULL || n < 4 || n == UINT32_MAX) return NULL;
    try {
        for (uint32_t i = 0; i < n; i++)
            if (!finite_point(xyz + 3 * static_cast<std::size_t>(i), w[i])) return NULL;
        std::unique_ptr<dd_cgal_rb> c(new dd_cgal_rb);
        if (discard_hidden) c->b.reset(new Bench<CGAL::Discard_hidden_points>);
        else c->b.reset(new Bench<CGAL::Keep_hidden_points>);
        if (!c->b->build(xyz, w, n)) return NULL;
        return c.release();
    } catch (...) {
        return NULL;
    }
}

void dd_cgal_rb_free(dd_cgal_rb *c)
{
    try {
        delete c;
    } catch (...) {
    }
}

int dd_cgal_rb_state(const dd_cgal_rb *c, uint32_t i)
{
    return c == NULL || i >= c->b->state.size() ? static_cast<int>(DD_RB_NONE) : static_cast<int>(c->b->state[i]);
}

int dd_cgal_rb_remove(dd_cgal_rb *c, uint32_t i, double *secs)
{
    if (c == NULL || secs == NULL) return 1;
    try {
        return c->b->remove(i, secs);
    } catch (...) {
        return 1;
    }
}

size_t dd_cgal_rb_released(const dd_cgal_rb *c, const uint32_t **idx)
{
    *idx = c->b->released.empty() ? NULL : c->b->released.data();
    return c->b->released.size();
}

size_t dd_cgal_rb_last_neighbors(const dd_cgal_rb *c, const uint32_t **idx)
{
    *idx = c->b->neighbors.empty() ? NULL : c->b->neighbors.data();
    return c->b->neighbors.size();
}

int dd_cgal_rb_insert(dd_cgal_rb *c, uint32_t i, const double p[3], double w, uint32_t hint, double *secs)
{
    if (c == NULL || p == NULL || secs == NULL || !finite_point(p, w)) return 1;
    try {
        return c->b->insert(i, Wpoint(Bare_point(p[0], p[1], p[2]), w), hint, secs);
    } catch (...) {
        return 1;
    }
}

int dd_cgal_rb_move(dd_cgal_rb *c, uint32_t i, const double p[3], double w, double *secs, int *fell_back)
{
    if (c == NULL || p == NULL || secs == NULL || fell_back == NULL || !finite_point(p, w)) return 1;
    try {
        return c->b->move(i, Wpoint(Bare_point(p[0], p[1], p[2]), w), secs, fell_back);
    } catch (...) {
        return 1;
    }
}

int dd_cgal_rb_canonical(const dd_cgal_rb *c, int32_t **tets, size_t *ntets)
{
    if (c == NULL || tets == NULL || ntets == NULL) return 1;
    *tets = NULL;
    *ntets = 0;
    try {
        std::vector<std::array<int32_t, 4> > all;
        c->b->cells(all);
        return emit_cells(all, tets, ntets);
    } catch (...) {
        return 1;
    }
}

int dd_cgal_rb_local_canonical(const dd_cgal_rb *c, const uint32_t *vs, size_t k, int32_t **tets, size_t *ntets)
{
    if (c == NULL || tets == NULL || ntets == NULL || (vs == NULL && k)) return 1;
    *tets = NULL;
    *ntets = 0;
    try {
        std::vector<std::array<int32_t, 4> > all;
        if (!c->b->local(vs, k, all)) return 1;
        return emit_cells(all, tets, ntets);
    } catch (...) {
        return 1;
    }
}

int dd_cgal_rb_hidden(const dd_cgal_rb *c, uint32_t **idx, size_t *n)
{
    if (c == NULL || idx == NULL || n == NULL) return 1;
    *idx = NULL;
    *n = 0;
    try {
        std::vector<uint32_t> out;
        c->b->hidden(out);
        std::sort(out.begin(), out.end());
        if (!out.empty()) {
            *idx = static_cast<uint32_t *>(std::malloc(out.size() * sizeof(uint32_t)));
            if (*idx == NULL) return 1;
            std::memcpy(*idx, out.data(), out.size() * sizeof(uint32_t));
        }
        *n = out.size();
        return 0;
    } catch (...) {
        return 1;
    }
}

} // extern "C"
