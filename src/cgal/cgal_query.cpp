/*
 * cgal_query.cpp -- the CGAL reference for location and insertion behind
 * cgal_query.h.  One template, Q<Dt>, instantiated for CGAL's default
 * Delaunay_triangulation_3 (Compact_location) and for Fast_location (the
 * Delaunay hierarchy); the handle keeps which one it holds.
 *
 * Invariants: vh[i] is the vertex of input index i or null; the last
 * inserted vertex is the hint of the next insertion.  No C++ exception
 * crosses the extern "C" boundary; no mutable globals.
 */
#include "cgal_query.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Triangulation_hierarchy_vertex_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <utility>
#include <vector>

namespace dd_query {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Triangulation_vertex_base_with_info_3<uint32_t, K> Vb;
typedef CGAL::Delaunay_triangulation_cell_base_3<K> Cb;
typedef CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb, Cb>> Plain_dt;
typedef CGAL::Triangulation_hierarchy_vertex_base_3<Vb> Hvb;
typedef CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Hvb, Cb>, CGAL::Fast_location> Fast_dt;

struct Base {
    virtual ~Base() {}
    virtual int insert(const double p[3], uint32_t index) = 0;
    virtual int remove(uint32_t index) = 0;
    virtual int move(uint32_t index, const double p[3]) = 0;
    virtual int remove_set(const uint32_t *idx, size_t k) = 0;
    virtual void locate(const double p[3], int32_t cell[4]) const = 0;
    virtual int64_t nearest(const double p[3]) const = 0;
    virtual void canonical(std::vector<std::array<int32_t, 4>> &out) const = 0;
};

template <class Dt> struct Q : Base {
    Dt dt;
    std::vector<typename Dt::Vertex_handle> vh;
    typename Dt::Vertex_handle last;

    int32_t index_of(typename Dt::Vertex_handle v) const { return dt.is_infinite(v) ? -1 : (int32_t)v->info(); }

    void build(const double *xyz, uint32_t n)
    {
        std::vector<std::pair<Point, uint32_t>> pts;
        pts.reserve(n);
        for (uint32_t i = 0; i < n; i++) pts.emplace_back(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), i);
        dt.insert(pts.begin(), pts.end());
        vh.assign(n, typename Dt::Vertex_handle());
        for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) vh[v->info()] = v;
    }
    int insert(const double p[3], uint32_t index) override
    {
        typename Dt::Cell_handle hint = last == typename Dt::Vertex_handle() ? typename Dt::Cell_handle() : last->cell();
        const auto before = dt.number_of_vertices();
        typename Dt::Vertex_handle v = dt.insert(Point(p[0], p[1], p[2]), hint);
        if (dt.number_of_vertices() == before) return 1;   /* a duplicate: nothing changed */
        v->info() = index;
        if (index >= vh.size()) vh.resize(index + 1);
        vh[index] = v;
        last = v;
        return 0;
    }
    int remove(uint32_t index) override
    {
        if (index >= vh.size() || vh[index] == typename Dt::Vertex_handle()) return 1;
        if (last == vh[index]) last = typename Dt::Vertex_handle();
        dt.remove(vh[index]);
        vh[index] = typename Dt::Vertex_handle();
        return 0;
    }
    int move(uint32_t index, const double p[3]) override
    {
        if (index >= vh.size() || vh[index] == typename Dt::Vertex_handle()) return 1;
        typename Dt::Vertex_handle v = dt.move_if_no_collision(vh[index], Point(p[0], p[1], p[2]));
        if (v != vh[index] && v->info() != index) return 1;   /* collided with another vertex */
        vh[index] = v;
        return 0;
    }
    int remove_set(const uint32_t *idx, size_t k) override
    {
        std::vector<typename Dt::Vertex_handle> vs;
        vs.reserve(k);
        for (size_t i = 0; i < k; i++) {
            if (idx[i] >= vh.size() || vh[idx[i]] == typename Dt::Vertex_handle()) return 1;
            vs.push_back(vh[idx[i]]);
        }
        if (dt.remove(vs.begin(), vs.end()) != k) return 1;
        for (size_t i = 0; i < k; i++) vh[idx[i]] = typename Dt::Vertex_handle();
        last = typename Dt::Vertex_handle();
        return 0;
    }
    void locate(const double p[3], int32_t cell[4]) const override
    {
        typename Dt::Cell_handle c = dt.locate(Point(p[0], p[1], p[2]));
        for (int i = 0; i < 4; i++) cell[i] = index_of(c->vertex(i));
    }
    int64_t nearest(const double p[3]) const override
    {
        typename Dt::Vertex_handle v = dt.nearest_vertex(Point(p[0], p[1], p[2]));
        return v == typename Dt::Vertex_handle() ? -1 : index_of(v);
    }
    void canonical(std::vector<std::array<int32_t, 4>> &out) const override
    {
        for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
            std::array<int32_t, 4> a;
            for (int i = 0; i < 4; i++) a[i] = index_of(c->vertex(i));
            std::sort(a.begin(), a.end());
            out.push_back(a);
        }
        std::sort(out.begin(), out.end());
    }
};

} // namespace dd_query

struct dd_cgalq {
    dd_query::Base *q;
};

extern "C" {

dd_cgalq *dd_cgalq_build(const double *xyz, uint32_t n, int fast)
{
    try {
        dd_cgalq *c = new dd_cgalq;
        if (fast) {
            auto *q = new dd_query::Q<dd_query::Fast_dt>;
            q->build(xyz, n);
            c->q = q;
            if (q->dt.dimension() == 3) return c;
        } else {
            auto *q = new dd_query::Q<dd_query::Plain_dt>;
            q->build(xyz, n);
            c->q = q;
            if (q->dt.dimension() == 3) return c;
        }
        dd_cgalq_free(c);
    } catch (...) {
    }
    return nullptr;
}

void dd_cgalq_free(dd_cgalq *c)
{
    if (!c) return;
    delete c->q;
    delete c;
}

int dd_cgalq_insert(dd_cgalq *c, const double p[3], uint32_t index)
{
    try {
        return c->q->insert(p, index);
    } catch (...) {
        return 1;
    }
}

int dd_cgalq_remove(dd_cgalq *c, uint32_t index)
{
    try {
        return c->q->remove(index);
    } catch (...) {
        return 1;
    }
}

int dd_cgalq_move(dd_cgalq *c, uint32_t index, const double p[3])
{
    try {
        return c->q->move(index, p);
    } catch (...) {
        return 1;
    }
}

int dd_cgalq_remove_set(dd_cgalq *c, const uint32_t *idx, size_t k)
{
    try {
        return c->q->remove_set(idx, k);
    } catch (...) {
        return 1;
    }
}

int dd_cgalq_locate(const dd_cgalq *c, const double p[3], int32_t cell[4])
{
    try {
        c->q->locate(p, cell);
        return 0;
    } catch (...) {
        return 1;
    }
}

int64_t dd_cgalq_nearest(const dd_cgalq *c, const double p[3])
{
    try {
        return c->q->nearest(p);
    } catch (...) {
        return -1;
    }
}

int dd_cgalq_canonical(const dd_cgalq *c, int32_t **tets, size_t *ntets)
{
    try {
        std::vector<std::array<int32_t, 4>> v;
        c->q->canonical(v);
        int32_t *a = (int32_t *)malloc((4 * v.size() + 1) * sizeof *a);
        if (!a) return 1;
        for (size_t k = 0; k < v.size(); k++)
            for (int i = 0; i < 4; i++) a[4 * k + i] = v[k][i];
        *tets = a;
        *ntets = v.size();
        return 0;
    } catch (...) {
        return 1;
    }
}

} // extern "C"
