// cgal_par.cpp -- CGAL's parallel Delaunay construction (cgal_par.h).
#define CGAL_LINKED_WITH_TBB 1
#include "cgal_par.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_with_info_3<uint32_t, K> Vb;
typedef CGAL::Delaunay_triangulation_cell_base_3<K> Cb;
typedef CGAL::Triangulation_data_structure_3<Vb, Cb, CGAL::Parallel_tag> Tds;
typedef CGAL::Delaunay_triangulation_3<K, Tds> Dt;

} // namespace

struct dd_cgalp {
    Dt::Lock_data_structure lock;
    Dt dt;
    dd_cgalp(const CGAL::Bbox_3 &box) : lock(box, 50), dt(K(), &lock) {}
};

extern "C" dd_cgalp *dd_cgalp_build(const double *xyz, uint32_t n, unsigned threads, double *secs)
{
    try {
        if (n < 4) return NULL;
        std::vector<std::pair<K::Point_3, uint32_t> > pts;
        pts.reserve(n);
        double lo[3] = {xyz[0], xyz[1], xyz[2]}, hi[3] = {xyz[0], xyz[1], xyz[2]};
        for (uint32_t i = 0; i < n; i++) {
            const double *p = xyz + 3 * static_cast<size_t>(i);
            pts.push_back(std::make_pair(K::Point_3(p[0], p[1], p[2]), i));
            for (int c = 0; c < 3; c++) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
        }
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads ? threads : 1);
        auto t0 = std::chrono::steady_clock::now();
        dd_cgalp *g = new dd_cgalp(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]));
        g->dt.insert(pts.begin(), pts.end());
        auto t1 = std::chrono::steady_clock::now();
        if (secs) *secs = std::chrono::duration<double>(t1 - t0).count();
        if (g->dt.dimension() < 3) {
            delete g;
            return NULL;
        }
        return g;
    } catch (...) {
        return NULL;
    }
}

extern "C" void dd_cgalp_free(dd_cgalp *g)
{
    delete g;
}

extern "C" int dd_cgalp_canonical(const dd_cgalp *g, int32_t **tets, size_t *ntets)
{
    try {
        std::vector<std::array<int32_t, 4> > all;
        all.reserve(g->dt.number_of_cells());
        for (auto c = g->dt.all_cells_begin(); c != g->dt.all_cells_end(); ++c) {
            std::array<int32_t, 4> t;
            for (int k = 0; k < 4; k++) {
                auto v = c->vertex(k);
                t[static_cast<size_t>(k)] = g->dt.is_infinite(v) ? -1 : static_cast<int32_t>(v->info());
            }
            std::sort(t.begin(), t.end());
            all.push_back(t);
        }
        std::sort(all.begin(), all.end());
        int32_t *out = static_cast<int32_t *>(std::malloc(4 * sizeof(int32_t) * (all.empty() ? 1 : all.size())));
        if (!out) return 1;
        for (size_t i = 0; i < all.size(); i++) std::memcpy(out + 4 * i, all[i].data(), 4 * sizeof(int32_t));
        *tets = out;
        *ntets = all.size();
        return 0;
    } catch (...) {
        return 1;
    }
}
