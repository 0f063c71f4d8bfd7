/*
 * cgal_refine.cpp -- CGAL's refinement loop behind cgal_refine.h.
 *
 * The queue holds (priority, sorted vertex indices, cell, stamp, point);
 * a cell's info is its stamp, set when it is queued and zeroed when
 * find_conflicts hands it over to insert_in_hole, so an entry is live
 * iff its cell's info still equals its stamp (a freed cell keeps info 0
 * until its memory holds a new cell, which gets a fresh stamp).
 *
 * Invariants: no C++ exception crosses the extern "C" boundary; no
 * mutable globals.
 */
#include "cgal_refine.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>

#include <algorithm>
#include <chrono>
#include <array>
#include <cstdlib>
#include <iterator>
#include <queue>
#include <utility>
#include <vector>

namespace dd_refine {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Triangulation_vertex_base_with_info_3<uint32_t, K> Vb;
typedef CGAL::Delaunay_triangulation_cell_base_3<K> Dcb;
typedef CGAL::Triangulation_cell_base_with_info_3<uint64_t, K, Dcb> Cb;
typedef CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb, Cb>> Dt;
typedef Dt::Cell_handle Cell;
typedef Dt::Facet Facet;

struct Entry {
    double r2;
    std::array<int32_t, 4> v;
    Cell c;
    uint64_t stamp;
    double p[3];
};

/* The rule's order (refine_rule.h): larger r2 first, then smaller v. */
struct Later {
    bool operator()(const Entry &a, const Entry &b) const
    {
        if (a.r2 != b.r2) return a.r2 < b.r2;
        return a.v > b.v;
    }
};

struct Refiner {
    Dt dt;
    uint32_t next = 0;
    uint64_t gen = 0;
    double core = 0;      /* seconds in find_conflicts + insert_in_hole */
    std::priority_queue<Entry, std::vector<Entry>, Later> queue;
    std::vector<Cell> hole;
    std::vector<Facet> bound, outside;

    /* Stamps cell c and queues it when the rule says so. */
    void consider(Cell c, const double lo[3], const double hi[3], dd_cgalr_rule rule)
    {
        c->info() = ++gen;
        if (dt.is_infinite(c)) return;
        std::array<std::pair<int32_t, const Point *>, 4> s;
        for (int i = 0; i < 4; i++) s[i] = {(int32_t)c->vertex(i)->info(), &c->vertex(i)->point()};
        std::sort(s.begin(), s.end(), [](const auto &a, const auto &b) { return a.first < b.first; });
        double xyz[4][3];
        const double *q[4];
        Entry e;
        for (int i = 0; i < 4; i++) {
            xyz[i][0] = s[i].second->x(), xyz[i][1] = s[i].second->y(), xyz[i][2] = s[i].second->z();
            q[i] = xyz[i];
            e.v[i] = s[i].first;
        }
        if (!rule(q, lo, hi, e.p, &e.r2)) return;
        e.c = c;
        e.stamp = gen;
        queue.push(e);
    }

    /* Inserts p, whose conflict region holds cell c or not; 0 when p is
     * a vertex already (nothing done), else 1 after queuing the new cells. */
    int insert(const Entry &e, const double lo[3], const double hi[3], dd_cgalr_rule rule)
    {
        const Point p(e.p[0], e.p[1], e.p[2]);
        const auto t0 = std::chrono::steady_clock::now();
        Cell c = e.c;
        if (dt.side_of_sphere(c, p) != CGAL::ON_BOUNDED_SIDE) {
            Dt::Locate_type lt;
            int li, lj;
            c = dt.locate(p, lt, li, lj, c);
            if (lt == Dt::VERTEX) return 0;
        }
        hole.clear();
        bound.clear();
        dt.find_conflicts(p, c, std::back_inserter(bound), std::back_inserter(hole));
        outside.clear();
        for (const Facet &f : bound) outside.push_back(dt.mirror_facet(f));
        for (Cell h : hole) h->info() = 0;
        Dt::Vertex_handle v = dt.insert_in_hole(p, hole.begin(), hole.end(), bound[0].first, bound[0].second);
        v->info() = next++;
        core += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        for (const Facet &f : outside) consider(f.first->neighbor(f.second), lo, hi, rule);
        return 1;
    }
};

} // namespace dd_refine

struct dd_cgalr {
    dd_refine::Refiner r;
};

extern "C" {

dd_cgalr *dd_cgalr_build(const double *xyz, uint32_t n)
{
    try {
        dd_cgalr *g = new dd_cgalr;
        std::vector<std::pair<dd_refine::Point, uint32_t>> pts;
        pts.reserve(n);
        for (uint32_t i = 0; i < n; i++) pts.emplace_back(dd_refine::Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), i);
        g->r.dt.insert(pts.begin(), pts.end());
        g->r.next = n;
        if (g->r.dt.dimension() == 3) return g;
        delete g;
    } catch (...) {
    }
    return nullptr;
}

void dd_cgalr_free(dd_cgalr *g)
{
    delete g;
}
double dd_cgalr_core_seconds(const dd_cgalr *g)
{
    return g->r.core;
}

int dd_cgalr_refine(dd_cgalr *g, uint32_t k, const double lo[3], const double hi[3], dd_cgalr_rule rule,
                    uint32_t *done)
{
    *done = 0;
    try {
        dd_refine::Refiner &r = g->r;
        for (auto c = r.dt.all_cells_begin(); c != r.dt.all_cells_end(); ++c) r.consider(c, lo, hi, rule);
        while (*done < k && !r.queue.empty()) {
            const dd_refine::Entry e = r.queue.top();
            r.queue.pop();
            if (e.c->info() != e.stamp) continue;
            *done += (uint32_t)r.insert(e, lo, hi, rule);
        }
        return 0;
    } catch (...) {
        return 1;
    }
}

int dd_cgalr_canonical(const dd_cgalr *g, int32_t **tets, size_t *ntets)
{
    try {
        const dd_refine::Dt &dt = g->r.dt;
        std::vector<std::array<int32_t, 4>> v;
        for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
            std::array<int32_t, 4> a;
            for (int i = 0; i < 4; i++) a[i] = dt.is_infinite(c->vertex(i)) ? -1 : (int32_t)c->vertex(i)->info();
            std::sort(a.begin(), a.end());
            v.push_back(a);
        }
        std::sort(v.begin(), v.end());
        int32_t *a = (int32_t *)malloc((4 * v.size() + 1) * sizeof *a);
        if (!a) return 1;
        for (size_t i = 0; i < v.size(); i++)
            for (int j = 0; j < 4; j++) a[4 * i + j] = v[i][j];
        *tets = a;
        *ntets = v.size();
        return 0;
    } catch (...) {
        return 1;
    }
}

} // extern "C"
