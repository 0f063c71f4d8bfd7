/*
 * cgal_regular.cpp -- CGAL's Regular_triangulation_3 behind cgal_regular.h
 * (DESIGN sections 7 and 12): the reference for weighted points.
 *
 * Owns: a dd_cgal_rt handle = one regular triangulation over the Epick
 * kernel, vertex info = input index, with either CGAL's Keep_hidden_points
 * or its Discard_hidden_points cell base (chosen at creation); the
 * hint for the next insertion; and a map from a weighted point (x, y, z, w)
 * to the input indices that carry it.  CGAL stores a hidden point in a cell
 * as a bare Weighted_point_3, without the vertex info, so the map is how a
 * hidden point is named by its input index.
 *
 * Equal points:
 *  - Exact duplicates in the input of dd_cgal_rt_build (same position and
 *    same weight) are collapsed before CGAL sees them: the first index is
 *    kept, the later ones are neither vertices nor hidden.  CGAL's own
 *    range insert would give the vertex the info of whichever copy its
 *    spatial sort puts last, an order the engine cannot reproduce.
 *  - Equal positions with different weights all go to CGAL: the heavier
 *    one hides the lighter ones, by CGAL's insert.
 *  - dd_cgal_rt_insert of an exact duplicate of a vertex changes nothing
 *    (returns 2, no index taken), as CGAL's insert returns that vertex;
 *    an exact duplicate of a kept hidden point is hidden again, as CGAL
 *    does, and both indices are reported hidden.
 *  - remove() re-inserts the hidden points of the star: when one comes
 *    back as a vertex it takes the lowest index of its weighted point,
 *    and the indices of its other copies (CGAL's insert on that vertex
 *    kept nothing of them) leave keys: neither vertices nor hidden.
 *
 * Invariants:
 *  - Every vertex's info is the input index of its weighted point, and
 *    keys[(x, y, z, w)] lists, in increasing order, every input index
 *    given to CGAL with that weighted point.
 *  - hint is a live vertex: it is replaced by every insertion that makes
 *    a vertex, and only such an insertion can remove one.
 *  - No C++ exception crosses the extern "C" boundary; no mutable globals.
 */
#include "cgal_regular.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <map>
#include <memory>
#include <utility>
#include <vector>

/* Types live in a named namespace: struct dd_cgal_rt (external linkage)
 * holds them, so they must not have internal linkage.                    */
namespace dd_regular {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Bare_point;
typedef K::Weighted_point_3 Wpoint;
typedef std::array<double, 4> Key;          /* x, y, z, w */

typedef CGAL::Regular_triangulation_vertex_base_3<K> Rvb;
typedef CGAL::Triangulation_vertex_base_with_info_3<uint32_t, K, Rvb> Vb;

template <class Policy>
using Rcb = CGAL::Regular_triangulation_cell_base_3<K, CGAL::Triangulation_cell_base_3<K>, Policy>;
template <class Policy>
using Rt = CGAL::Regular_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb, Rcb<Policy> > >;

/* What the C face needs from either hidden-point policy. */
struct Any_rt {
    virtual ~Any_rt() {}
    virtual bool build(const std::vector<std::pair<Wpoint, uint32_t> > &in) = 0;
    virtual void cells(std::vector<std::array<int32_t, 4> > &out) const = 0;
    virtual void hidden(std::vector<Key> &out) const = 0;
    virtual void vertices(std::vector<uint32_t> &out) const = 0;
    /* 0 done (vertex, hidden or forgotten), 2 exact duplicate of a vertex. */
    virtual int insert(const Wpoint &p, uint32_t index) = 0;
    /* As insert, the walk from the finite cell whose vertices' indices
     * are cell[0..4) (any order); 1 when there is none.                 */
    virtual int insert_in(const Wpoint &p, uint32_t index, const uint32_t cell[4]) = 0;
};

inline Key key_of(const Wpoint &p)
{
    const Bare_point &b = p.point();
    Key k = {{b.x(), b.y(), b.z(), p.weight()}};
    return k;
}

template <class Policy>
struct Rt_of : public Any_rt {
    typedef Rt<Policy> T;
    T rt;
    typename T::Vertex_handle hint;

    bool build(const std::vector<std::pair<Wpoint, uint32_t> > &in) override
    {
        rt.insert(in.begin(), in.end());
        if (rt.dimension() != 3)
            return false;
        hint = rt.finite_vertices_begin();
        return true;
    }

    void cells(std::vector<std::array<int32_t, 4> > &out) const override
    {
        out.reserve(rt.number_of_cells());
        for (typename T::All_cells_iterator it = rt.all_cells_begin(); it != rt.all_cells_end(); ++it) {
            std::array<int32_t, 4> t;
            for (int k = 0; k < 4; k++) {
                const typename T::Vertex_handle v = it->vertex(k);
                t[static_cast<std::size_t>(k)] = rt.is_infinite(v) ? -1 : static_cast<int32_t>(v->info());
            }
            std::sort(t.begin(), t.end());
            out.push_back(t);
        }
    }

    void hidden(std::vector<Key> &out) const override
    {
        for (typename T::All_cells_iterator it = rt.all_cells_begin(); it != rt.all_cells_end(); ++it)
            for (typename T::Cell::Point_const_iterator h = it->hidden_points_begin();
                 h != it->hidden_points_end(); ++h)
                out.push_back(key_of(*h));
    }

    void vertices(std::vector<uint32_t> &out) const override
    {
        for (typename T::Finite_vertices_iterator it = rt.finite_vertices_begin();
             it != rt.finite_vertices_end(); ++it)
            out.push_back(it->info());
    }

    int insert(const Wpoint &p, uint32_t index) override { return insert_from(p, index, hint->cell()); }

    int insert_in(const Wpoint &p, uint32_t index, const uint32_t cell[4]) override
    {
        std::array<uint32_t, 4> want = {{cell[0], cell[1], cell[2], cell[3]}};
        std::sort(want.begin(), want.end());
        for (typename T::Finite_cells_iterator it = rt.finite_cells_begin(); it != rt.finite_cells_end(); ++it) {
            std::array<uint32_t, 4> have;
            for (int k = 0; k < 4; k++) have[static_cast<std::size_t>(k)] = it->vertex(k)->info();
            std::sort(have.begin(), have.end());
            if (have == want) return insert_from(p, index, it);
        }
        return 1;
    }

    /* CGAL's insert of p walking from cell `start` (its locate, then the
     * insert at that location: what insert(p, start) does).            */
    int insert_from(const Wpoint &p, uint32_t index, typename T::Cell_handle start)
    {
        typename T::Locate_type lt;
        int li, lj;
        const typename T::Cell_handle c = rt.locate(p, lt, li, lj, start);
        /* Weighted_point_3's == compares the bare points only; CGAL's
         * insert returns the vertex when the weights are equal too.    */
        if (lt == T::VERTEX && c->vertex(li)->point().point() == p.point() &&
            c->vertex(li)->point().weight() == p.weight())
            return 2;
        const typename T::Vertex_handle v = rt.insert(p, lt, c, li, lj);
        if (v != typename T::Vertex_handle()) {
            v->info() = index;
            hint = v;
        }
        return 0;
    }
};

} // namespace dd_regular

using namespace dd_regular;

struct dd_cgal_rt {
    std::unique_ptr<Any_rt> rt;
    std::map<Key, std::vector<uint32_t> > keys;   /* weighted point -> indices */
    uint32_t ninput;                                /* indices given so far    */
};

namespace {

bool finite_point(const double *p, double w)
{
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(w);
}

Wpoint weighted_point(const double *p, double w)
{
    return Wpoint(Bare_point(p[0], p[1], p[2]), w);
}

/* Hands out a sorted index list as a malloc'd array (NULL when empty). */
int emit_indices(std::vector<uint32_t> &v, uint32_t **idx, size_t *n)
{
    std::sort(v.begin(), v.end());
    if (!v.empty()) {
        *idx = static_cast<uint32_t *>(std::malloc(v.size() * sizeof(uint32_t)));
        if (*idx == NULL)
            return 1;
        std::memcpy(*idx, v.data(), v.size() * sizeof(uint32_t));
    }
    *n = v.size();
    return 0;
}

} // namespace

extern "C" {

dd_cgal_rt *dd_cgal_rt_build(const double *xyz, const double *w, uint32_t n, int discard_hidden)
{
    if (xyz == NULL || w == NULL || n < 4 || n == UINT32_MAX)
        return NULL;
    try {
        for (uint32_t i = 0; i < n; i++)
            if (!finite_point(xyz + 3 * static_cast<std::size_t>(i), w[i]))
                return NULL;
        std::unique_ptr<dd_cgal_rt> c(new dd_cgal_rt);
        if (discard_hidden)
            c->rt.reset(new Rt_of<CGAL::Discard_hidden_points>);
        else
            c->rt.reset(new Rt_of<CGAL::Keep_hidden_points>);
        c->ninput = n;
        std::vector<std::pair<Wpoint, uint32_t> > input;
        input.reserve(n);
        for (uint32_t i = 0; i < n; i++) {
            const double *p = xyz + 3 * static_cast<std::size_t>(i);
            const Key k = {{p[0], p[1], p[2], w[i]}};
            std::vector<uint32_t> &idx = c->keys[k];
            if (!idx.empty())
                continue;                 /* an exact duplicate: the first stays */
            idx.push_back(i);
            input.push_back(std::make_pair(weighted_point(p, w[i]), i));
        }
        if (!c->rt->build(input))
            return NULL;
        return c.release();
    } catch (...) {
        return NULL;
    }
}

void dd_cgal_rt_free(dd_cgal_rt *c)
{
    try {
        delete c;
    } catch (...) {
    }
}

int dd_cgal_rt_canonical(const dd_cgal_rt *c, int32_t **tets, size_t *ntets)
{
    if (c == NULL || tets == NULL || ntets == NULL)
        return 1;
    *tets = NULL;
    *ntets = 0;
    try {
        std::vector<std::array<int32_t, 4> > all;
        c->rt->cells(all);
        std::sort(all.begin(), all.end());
        int32_t *out = static_cast<int32_t *>(std::malloc(4 * sizeof(int32_t) * (all.empty() ? 1 : all.size())));
        if (out == NULL)
            return 1;
        for (std::size_t i = 0; i < all.size(); i++)
            std::memcpy(out + 4 * i, all[i].data(), 4 * sizeof(int32_t));
        *tets = out;
        *ntets = all.size();
        return 0;
    } catch (...) {
        return 1;
    }
}

int dd_cgal_rt_hidden(const dd_cgal_rt *c, uint32_t **idx, size_t *n)
{
    if (c == NULL || idx == NULL || n == NULL)
        return 1;
    *idx = NULL;
    *n = 0;
    try {
        std::vector<Key> hk;
        c->rt->hidden(hk);
        std::sort(hk.begin(), hk.end());
        std::vector<uint32_t> out;
        for (std::size_t i = 0, j; i < hk.size(); i = j) {
            for (j = i + 1; j < hk.size() && hk[j] == hk[i]; j++) {}
            std::map<Key, std::vector<uint32_t> >::const_iterator it = c->keys.find(hk[i]);
            if (it == c->keys.end() || it->second.size() != j - i)
                return 1;                 /* a hidden point nobody gave, or its copies miscounted */
            out.insert(out.end(), it->second.begin(), it->second.end());
        }
        return emit_indices(out, idx, n);
    } catch (...) {
        return 1;
    }
}

int dd_cgal_rt_vertices(const dd_cgal_rt *c, uint32_t **idx, size_t *n)
{
    if (c == NULL || idx == NULL || n == NULL)
        return 1;
    *idx = NULL;
    *n = 0;
    try {
        std::vector<uint32_t> out;
        c->rt->vertices(out);
        return emit_indices(out, idx, n);
    } catch (...) {
        return 1;
    }
}

int dd_cgal_rt_insert(dd_cgal_rt *c, const double p[3], double w, uint32_t index)
{
    if (c == NULL || p == NULL || index != c->ninput || index == UINT32_MAX || !finite_point(p, w))
        return 1;
    try {
        const Key k = {{p[0], p[1], p[2], w}};
        std::vector<uint32_t> &idx = c->keys[k];
        idx.reserve(idx.size() + 1);      /* nothing can throw after insert */
        const int r = c->rt->insert(weighted_point(p, w), index);
        if (r == 0) {
            idx.push_back(index);
            c->ninput++;
        } else if (idx.empty()) {
            c->keys.erase(k);
        }
        return r;
    } catch (...) {
        return 1;
    }
}

int dd_cgal_rt_insert_in(dd_cgal_rt *c, const double p[3], double w, uint32_t index, const uint32_t cell[4])
{
    if (c == NULL || p == NULL || cell == NULL || index != c->ninput || index == UINT32_MAX || !finite_point(p, w))
        return 1;
    try {
        const Key k = {{p[0], p[1], p[2], w}};
        std::vector<uint32_t> &idx = c->keys[k];
        idx.reserve(idx.size() + 1);      /* nothing can throw after insert */
        const int r = c->rt->insert_in(weighted_point(p, w), index, cell);
        if (r == 0) {
            idx.push_back(index);
            c->ninput++;
        } else if (idx.empty()) {
            c->keys.erase(k);
        }
        return r;
    } catch (...) {
        return 1;
    }
}

uint32_t dd_cgal_rt_num_input(const dd_cgal_rt *c)
{
    return c == NULL ? 0 : c->ninput;
}

} // extern "C"

/* ---- removal (issue 44) ---------------------------------------------------- */

namespace {

/* After remove() re-inserted the hidden points `back`: a hidden point
 * that came back as a vertex took the lowest index of its weighted
 * point, and CGAL's insert of an exact copy of that vertex kept nothing:
 * those copies' indices leave keys, which keeps the vertex's index and
 * as many others as CGAL still hides copies of it.  A copy may also come
 * back for a while, its twins dropped, and be hidden again by a later
 * re-insertion: keys then keeps the lowest indices, as many as CGAL
 * hides (which ones is CGAL's order; the engine keeps every copy, so the
 * comparisons accept a subset: soak_weighted.c).  O(n).                 */
template <class Policy>
void drop_copies(Rt_of<Policy> *r, std::map<Key, std::vector<uint32_t> > &keys, std::vector<Key> &back)
{
    typedef typename Rt_of<Policy>::T T;
    std::sort(back.begin(), back.end());
    back.erase(std::unique(back.begin(), back.end()), back.end());
    std::map<Key, std::size_t> still;  /* raw cells: in dimension 2 or less too */
    for (typename T::Cell_iterator it = r->rt.tds().raw_cells_begin(); it != r->rt.tds().raw_cells_end(); ++it)
        for (typename T::Cell::Point_iterator h = it->hidden_points_begin(); h != it->hidden_points_end(); ++h) {
            const Key k = key_of(*h);
            if (std::binary_search(back.begin(), back.end(), k)) still[k]++;
        }
    for (typename T::Finite_vertices_iterator it = r->rt.finite_vertices_begin(); it != r->rt.finite_vertices_end();
         ++it) {
        const Key k = key_of(it->point());
        if (!std::binary_search(back.begin(), back.end(), k)) continue;
        std::vector<uint32_t> &idx = keys[k];
        std::vector<uint32_t> kept(1, it->info());
        std::size_t more = still[k];
        for (std::size_t i = 0; i < idx.size() && more; i++)
            if (idx[i] != it->info()) kept.push_back(idx[i]), more--;
        std::sort(kept.begin(), kept.end());
        idx.swap(kept);
        still[k] = idx.size();             /* done: the trim below keeps it */
    }
    for (std::size_t i = 0; i < back.size(); i++) {
        std::map<Key, std::vector<uint32_t> >::iterator it = keys.find(back[i]);
        if (it != keys.end() && it->second.size() > still[back[i]]) it->second.resize(still[back[i]]);
    }
}

/* CGAL's remove() of the vertex whose info is `index` in r: 0 done, 1 no
 * such vertex (a hidden point, a deleted or an unknown index), 3 when CGAL
 * refuses (the vertices left would span less than 3D).  The hint moves
 * off the removed vertex.  CGAL makes a new vertex for each hidden point
 * that comes back, its info not set (a hidden point is a bare weighted
 * point): every vertex's info is set again from keys, the index a vertex
 * had kept when keys lists it for that weighted point; the copies CGAL
 * dropped leave keys (drop_copies).  any_dim: CGAL's remove() may leave
 * fewer than 4 vertices or drop the dimension (it re-inserts the hidden
 * points then, which may raise it again), and it is done in whatever
 * dimension.  O(n): a reference, not a bench.                           */
template <class Policy>
int remove_index(Rt_of<Policy> *r, std::map<Key, std::vector<uint32_t> > &keys, uint32_t index, bool any_dim)
{
    typedef typename Rt_of<Policy>::T T;
    typename T::Vertex_handle v;
    for (typename T::Finite_vertices_iterator it = r->rt.finite_vertices_begin(); it != r->rt.finite_vertices_end();
         ++it)
        if (it->info() == index) {
            v = it;
            break;
        }
    if (v == typename T::Vertex_handle())
        return 1;
    if (!any_dim && r->rt.number_of_vertices() <= 4)
        return 3;
    std::vector<uint32_t> &gone = keys[key_of(v->point())];
    gone.erase(std::remove(gone.begin(), gone.end(), index), gone.end());
    std::vector<Key> back;                /* the star's hidden points: CGAL re-inserts them */
    std::vector<typename T::Cell_handle> star;
    r->rt.incident_cells(v, std::back_inserter(star));
    for (std::size_t i = 0; i < star.size(); i++)
        for (typename T::Cell::Point_iterator h = star[i]->hidden_points_begin(); h != star[i]->hidden_points_end(); ++h)
            back.push_back(key_of(*h));
    r->rt.remove(v);
    if (!any_dim && r->rt.dimension() != 3)
        return 3;
    std::sort(back.begin(), back.end());
    for (typename T::Finite_vertices_iterator it = r->rt.finite_vertices_begin(); it != r->rt.finite_vertices_end();
         ++it) {
        const Key key = key_of(it->point());
        const std::map<Key, std::vector<uint32_t> >::const_iterator k = keys.find(key);
        if (k == keys.end() || k->second.empty())
            return 1;                     /* a vertex nobody gave */
        /* a point that came back takes the lowest index: CGAL's new
         * vertex may hold a stale info from a reused vertex slot, even
         * one of its own copies                                        */
        if (std::binary_search(back.begin(), back.end(), key) ||
            std::find(k->second.begin(), k->second.end(), it->info()) == k->second.end())
            it->info() = k->second.front();
    }
    if (!back.empty()) drop_copies(r, keys, back);
    r->hint = r->rt.finite_vertices_begin();
    return 0;
}

} // namespace

extern "C" int dd_cgal_rt_remove(dd_cgal_rt *c, uint32_t input_index)
{
    if (c == NULL)
        return 1;
    try {
        if (Rt_of<CGAL::Keep_hidden_points> *k = dynamic_cast<Rt_of<CGAL::Keep_hidden_points> *>(c->rt.get()))
            return remove_index(k, c->keys, input_index, false);
        if (Rt_of<CGAL::Discard_hidden_points> *d = dynamic_cast<Rt_of<CGAL::Discard_hidden_points> *>(c->rt.get()))
            return remove_index(d, c->keys, input_index, false);
        return 1;
    } catch (...) {
        return 1;
    }
}

/* ---- hidden points forgotten, moves (issue 44) ------------------------------ */

namespace {

/* The key of input index `index`, if keys lists it. */
bool key_of_index(const std::map<Key, std::vector<uint32_t> > &keys, uint32_t index, Key &out)
{
    for (std::map<Key, std::vector<uint32_t> >::const_iterator it = keys.begin(); it != keys.end(); ++it)
        if (std::find(it->second.begin(), it->second.end(), index) != it->second.end()) {
            out = it->first;
            return true;
        }
    return false;
}

/* Whether input index `index` is a vertex of r. */
template <class Policy>
bool is_vertex(const Rt_of<Policy> *r, uint32_t index)
{
    typedef typename Rt_of<Policy>::T T;
    for (typename T::Finite_vertices_iterator it = r->rt.finite_vertices_begin(); it != r->rt.finite_vertices_end();
         ++it)
        if (it->info() == index) return true;
    return false;
}

/* Forgets the kept hidden point of input index `index`: one copy of its
 * weighted point leaves the hidden list of the cell that keeps it, and
 * the index leaves keys.  0 done, 1 when it is no kept hidden point.
 * O(n): a reference.                                                    */
template <class Policy>
int forget_index(Rt_of<Policy> *r, std::map<Key, std::vector<uint32_t> > &keys, uint32_t index)
{
    typedef typename Rt_of<Policy>::T T;
    Key k;
    if (!key_of_index(keys, index, k) || is_vertex(r, index)) return 1;
    for (typename T::All_cells_iterator it = r->rt.all_cells_begin(); it != r->rt.all_cells_end(); ++it)
        for (typename T::Cell::Point_iterator h = it->hidden_points_begin(); h != it->hidden_points_end(); ++h)
            if (key_of(*h) == k) {
                it->unhide_point(h);
                std::vector<uint32_t> &idx = keys[k];
                idx.erase(std::remove(idx.begin(), idx.end(), index), idx.end());
                return 0;
            }
    return 1;
}

/* (p, w) inserted as input index `index` (any index, not only the next
 * one): as insert, keys kept in increasing order.  0, or 2 when (p, w)
 * is a vertex's weighted point (nothing changed).                       */
int insert_as(dd_cgal_rt *c, const Wpoint &p, uint32_t index)
{
    const Key k = key_of(p);
    std::vector<uint32_t> &idx = c->keys[k];
    idx.reserve(idx.size() + 1);
    const int r = c->rt->insert(p, index);
    if (r == 0)
        idx.insert(std::upper_bound(idx.begin(), idx.end(), index), index);
    else if (idx.empty())
        c->keys.erase(k);
    return r;
}

/* any_dim: the removal in any dimension (remove_index), and 3 only when
 * the moved set ends in less than 3D.                                   */
template <class Policy>
int move_index(dd_cgal_rt *c, Rt_of<Policy> *r, uint32_t index, const double p[3], double w, bool any_dim)
{
    Key old;
    if (!key_of_index(c->keys, index, old)) return 1;
    const Key now = {{p[0], p[1], p[2], w}};
    if (now == old) return 0;
    const bool vertex = is_vertex(r, index);
    /* the weighted point of another vertex: refused before any change */
    typename std::map<Key, std::vector<uint32_t> >::const_iterator same = c->keys.find(now);
    if (same != c->keys.end())
        for (std::size_t i = 0; i < same->second.size(); i++)
            if (same->second[i] != index && is_vertex(r, same->second[i])) return 2;
    const int gone = !vertex ? forget_index(r, c->keys, index) : remove_index(r, c->keys, index, any_dim);
    if (gone != 0) return gone;
    const int ins = insert_as(c, weighted_point(p, w), index);
    if (ins == 2) {              /* a point the removal brought back: put v back */
        const Wpoint back(Bare_point(old[0], old[1], old[2]), old[3]);
        return insert_as(c, back, index) == 0 && (!any_dim || r->rt.dimension() == 3) ? 2 : 1;
    }
    if (any_dim && ins == 0 && r->rt.dimension() != 3) return 3;
    return ins;
}

} // namespace

extern "C" int dd_cgal_rt_forget(dd_cgal_rt *c, uint32_t input_index)
{
    if (c == NULL)
        return 1;
    try {
        if (Rt_of<CGAL::Keep_hidden_points> *k = dynamic_cast<Rt_of<CGAL::Keep_hidden_points> *>(c->rt.get()))
            return forget_index(k, c->keys, input_index);
        return 1;
    } catch (...) {
        return 1;
    }
}

extern "C" int dd_cgal_rt_move(dd_cgal_rt *c, uint32_t input_index, const double p[3], double w)
{
    if (c == NULL || p == NULL || !finite_point(p, w))
        return 1;
    try {
        if (Rt_of<CGAL::Keep_hidden_points> *k = dynamic_cast<Rt_of<CGAL::Keep_hidden_points> *>(c->rt.get()))
            return move_index(c, k, input_index, p, w, false);
        if (Rt_of<CGAL::Discard_hidden_points> *d = dynamic_cast<Rt_of<CGAL::Discard_hidden_points> *>(c->rt.get()))
            return move_index(c, d, input_index, p, w, false);
        return 1;
    } catch (...) {
        return 1;
    }
}

extern "C" int dd_cgal_rt_insert_as(dd_cgal_rt *c, const double p[3], double w, uint32_t index)
{
    if (c == NULL || p == NULL || index >= c->ninput || !finite_point(p, w))
        return 1;
    try {
        Key k;
        if (key_of_index(c->keys, index, k)) {
            /* a vertex or a kept hidden point is there still; a point
             * forgotten (discarding) is listed but gone                 */
            Rt_of<CGAL::Discard_hidden_points> *d = dynamic_cast<Rt_of<CGAL::Discard_hidden_points> *>(c->rt.get());
            if (d == NULL || is_vertex(d, index))
                return 1;
            std::vector<uint32_t> &idx = c->keys[k];
            idx.erase(std::remove(idx.begin(), idx.end(), index), idx.end());
            if (idx.empty()) c->keys.erase(k);
        }
        return insert_as(c, weighted_point(p, w), index);
    } catch (...) {
        return 1;
    }
}

/* ---- moves through a lower dimension (issue 44) ------------------------------ */

extern "C" int dd_cgal_rt_move_any_dim(dd_cgal_rt *c, uint32_t input_index, const double p[3], double w)
{
    if (c == NULL || p == NULL || !finite_point(p, w))
        return 1;
    try {
        if (Rt_of<CGAL::Keep_hidden_points> *k = dynamic_cast<Rt_of<CGAL::Keep_hidden_points> *>(c->rt.get()))
            return move_index(c, k, input_index, p, w, true);
        if (Rt_of<CGAL::Discard_hidden_points> *d = dynamic_cast<Rt_of<CGAL::Discard_hidden_points> *>(c->rt.get()))
            return move_index(c, d, input_index, p, w, true);
        return 1;
    } catch (...) {
        return 1;
    }
}
