/*
 * cgal_batch.cpp -- CGAL's range insertion and sorted, hinted location
 * behind cgal_batch.h.
 *
 * Invariants: no C++ exception crosses the extern "C" boundary; no
 * mutable globals.
 */
#include "cgal_batch.h"
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

namespace dd_batch {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Weighted_point_3 Wpoint;
typedef CGAL::Triangulation_vertex_base_with_info_3<uint32_t, K> Vb;
typedef CGAL::Delaunay_triangulation_cell_base_3<K> Cb;
typedef CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb, Cb>> Dt;
typedef CGAL::Regular_triangulation_vertex_base_3<K> Rvb;
typedef CGAL::Triangulation_vertex_base_with_info_3<uint32_t, K, Rvb> Wvb;
typedef CGAL::Regular_triangulation_cell_base_3<K, CGAL::Triangulation_cell_base_3<K>, CGAL::Keep_hidden_points> Rcb;
typedef CGAL::Regular_triangulation_3<K, CGAL::Triangulation_data_structure_3<Wvb, Rcb>> Rt;

inline double now()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

template <class T> void canonical_of(const T &t, std::vector<std::array<int32_t, 4>> &out)
{
    for (auto c = t.all_cells_begin(); c != t.all_cells_end(); ++c) {
        std::array<int32_t, 4> a;
        for (int i = 0; i < 4; i++) a[i] = t.is_infinite(c->vertex(i)) ? -1 : (int32_t)c->vertex(i)->info();
        std::sort(a.begin(), a.end());
        out.push_back(a);
    }
    std::sort(out.begin(), out.end());
}
} // namespace dd_batch

struct dd_cgalb {
    std::unique_ptr<dd_batch::Dt> dt;
    std::unique_ptr<dd_batch::Rt> rt;
};

namespace {
using namespace dd_batch;

std::vector<std::pair<Point, uint32_t>> plain_pairs(const double *xyz, size_t m, uint32_t first)
{
    std::vector<std::pair<Point, uint32_t>> v;
    v.reserve(m);
    for (size_t i = 0; i < m; i++) v.emplace_back(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), first + (uint32_t)i);
    return v;
}

std::vector<std::pair<Wpoint, uint32_t>> weighted_pairs(const double *xyz, const double *w, size_t m, uint32_t first)
{
    std::vector<std::pair<Wpoint, uint32_t>> v;
    v.reserve(m);
    for (size_t i = 0; i < m; i++)
        v.emplace_back(Wpoint(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), w[i]), first + (uint32_t)i);
    return v;
}
} // namespace

extern "C" {
dd_cgalb *dd_cgalb_build(const double *xyz, const double *w, uint32_t n)
{
    try {
        std::unique_ptr<dd_cgalb> g(new dd_cgalb);
        double secs;
        if (w) g->rt.reset(new Rt);
        else g->dt.reset(new Dt);
        if (dd_cgalb_insert_range(g.get(), xyz, w, n, 0, &secs)) return nullptr;
        if ((w ? g->rt->dimension() : g->dt->dimension()) != 3) return nullptr;
        return g.release();
    } catch (...) {
        return nullptr;
    }
}

void dd_cgalb_free(dd_cgalb *g)
{
    delete g;
}

int dd_cgalb_insert_range(dd_cgalb *g, const double *xyz, const double *w, size_t m, uint32_t first, double *secs)
{
    try {
        if ((w != nullptr) != (g->rt != nullptr)) return 1;
        if (w) {
            auto v = weighted_pairs(xyz, w, m, first);
            const double t0 = now();
            g->rt->insert(v.begin(), v.end());
            *secs = now() - t0;
        } else {
            auto v = plain_pairs(xyz, m, first);
            const double t0 = now();
            g->dt->insert(v.begin(), v.end());
            *secs = now() - t0;
        }
        return 0;
    } catch (...) {
        return 1;
    }
}

int dd_cgalb_locate_sorted(const dd_cgalb *g, const double *q, size_t m, int32_t *cells, double *secs)
{
    try {
        if (!g->dt) return 1;
        const Dt &dt = *g->dt;
        std::vector<Point> pts;
        pts.reserve(m);
        for (size_t i = 0; i < m; i++) pts.emplace_back(q[3 * i], q[3 * i + 1], q[3 * i + 2]);
        std::vector<std::size_t> order(m);
        std::vector<Dt::Cell_handle> found(m);
        typedef CGAL::Spatial_sort_traits_adapter_3<K, CGAL::Pointer_property_map<Point>::type> Traits;
        const double t0 = now();
        std::iota(order.begin(), order.end(), std::size_t(0));
        CGAL::spatial_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(pts)));
        Dt::Cell_handle c;
        for (std::size_t k = 0; k < m; k++) {
            c = dt.locate(pts[order[k]], c);
            found[order[k]] = c;
        }
        *secs = now() - t0;
        for (size_t i = 0; i < m; i++)
            for (int j = 0; j < 4; j++)
                cells[4 * i + j] = dt.is_infinite(found[i]->vertex(j)) ? -1 : (int32_t)found[i]->vertex(j)->info();
        return 0;
    } catch (...) {
        return 1;
    }
}

int dd_cgalb_canonical(const dd_cgalb *g, int32_t **tets, size_t *ntets)
{
    try {
        std::vector<std::array<int32_t, 4>> out;
        if (g->dt) canonical_of(*g->dt, out);
        else canonical_of(*g->rt, out);
        *tets = static_cast<int32_t *>(std::malloc((out.size() + 1) * 4 * sizeof(int32_t)));
        if (!*tets) return 1;
        if (!out.empty()) std::memcpy(*tets, out.data(), out.size() * 4 * sizeof(int32_t));
        *ntets = out.size();
        return 0;
    } catch (...) {
        return 1;
    }
}
}
