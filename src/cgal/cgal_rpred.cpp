/*
 * cgal_rpred.cpp -- CGAL's regular-triangulation predicates behind
 * cgal_rpred.h (DESIGN 7, 12), for tests/test_power.c.
 *
 * Owns nothing between calls: the kernel's functors are stateless, the
 * perturbed rules are members of an empty Regular_triangulation_3 (made
 * per call: it holds no points), and the cell queries build a regular
 * triangulation of four weighted points per call.  No C++ exception
 * crosses the extern "C" boundary; a caught one reports failure.
 */
#include "cgal_rpred.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>

#include <cmath>

namespace dd_rpred {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Weighted_point_3 Wpoint;
typedef CGAL::Regular_triangulation_vertex_base_3<K> Vb0;
typedef CGAL::Triangulation_vertex_base_with_info_3<int, K, Vb0> Vb;
typedef CGAL::Regular_triangulation_cell_base_3<K> Cb;
typedef CGAL::Triangulation_data_structure_3<Vb, Cb> Tds;
typedef CGAL::Regular_triangulation_3<K, Tds> Base_rt;

/* Exposes CGAL's (protected) perturbed rules. */
struct Pred_rt : public Base_rt {
    using Base_rt::side_of_oriented_power_sphere;
    using Base_rt::side_of_bounded_power_circle;
};

static Wpoint wp(const double *p, double w) { return Wpoint(Point(p[0], p[1], p[2]), w); }

/* Inserts the four weighted points in order, info = argument index. 1 if
 * they end as the four vertices of a 3D triangulation.                 */
static bool build4(Base_rt &rt, const double *const v[4], const double w[4])
{
    for (int i = 0; i < 4; i++) {
        Base_rt::Vertex_handle h = rt.insert(wp(v[i], w[i]));
        if (h == Base_rt::Vertex_handle()) return false;
        h->info() = i;
    }
    return rt.dimension() == 3 && rt.number_of_vertices() == 4;
}

} // namespace dd_rpred

using namespace dd_rpred;

extern "C" {

int dd_cgal_power_test(const double *p0, const double *p1, const double *p2, const double *p3,
                       const double *p, const double w[5])
{
    try {
        return static_cast<int>(K().power_side_of_oriented_power_sphere_3_object()(
            wp(p0, w[0]), wp(p1, w[1]), wp(p2, w[2]), wp(p3, w[3]), wp(p, w[4])));
    } catch (...) {
        return 9;
    }
}

int dd_cgal_power_test4(const double *p0, const double *p1, const double *p2, const double *p,
                        const double w[4])
{
    try {
        return static_cast<int>(K().power_side_of_oriented_power_sphere_3_object()(
            wp(p0, w[0]), wp(p1, w[1]), wp(p2, w[2]), wp(p, w[3])));
    } catch (...) {
        return 9;
    }
}

int dd_cgal_power_sphere(const double *p0, const double *p1, const double *p2, const double *p3,
                         const double *p, const double w[5], int perturb)
{
    try {
        Pred_rt rt;
        return static_cast<int>(rt.side_of_oriented_power_sphere(wp(p0, w[0]), wp(p1, w[1]), wp(p2, w[2]),
                                                                 wp(p3, w[3]), wp(p, w[4]), perturb != 0));
    } catch (...) {
        return 9;
    }
}

int dd_cgal_power_circle(const double *p0, const double *p1, const double *p2, const double *p,
                         const double w[4], int perturb)
{
    try {
        Pred_rt rt;
        return static_cast<int>(rt.side_of_bounded_power_circle(wp(p0, w[0]), wp(p1, w[1]), wp(p2, w[2]),
                                                                wp(p, w[3]), perturb != 0));
    } catch (...) {
        return 9;
    }
}

int dd_cgal_power_cell(const double *p0, const double *p1, const double *p2, const double *p3,
                       const double *p, const double w[5], int *res)
{
    try {
        Base_rt rt;
        const double *v[4] = {p0, p1, p2, p3};
        if (!build4(rt, v, w)) return 1;
        for (Base_rt::Finite_cells_iterator c = rt.finite_cells_begin(); c != rt.finite_cells_end(); ++c) {
            *res = static_cast<int>(rt.side_of_power_sphere(c, wp(p, w[4]), true));
            return 0;
        }
        return 1;
    } catch (...) {
        return 1;
    }
}

int dd_cgal_power_infinite(const double *a, const double *b, const double *c, const double *p,
                           const double w[4], int *res)
{
    try {
        /* a fourth point d off the facet, with orient3d(a, b, c, d) < 0 */
        double ab[3], ac[3], n[3], m[3], len = 0, nn = 0;
        for (int k = 0; k < 3; k++) {
            ab[k] = b[k] - a[k];
            ac[k] = c[k] - a[k];
            m[k] = a[k] / 3 + b[k] / 3 + c[k] / 3;
            len = std::fmax(len, std::fmax(std::fabs(ab[k]), std::fabs(ac[k])));
        }
        n[0] = ab[1] * ac[2] - ab[2] * ac[1];
        n[1] = ab[2] * ac[0] - ab[0] * ac[2];
        n[2] = ab[0] * ac[1] - ab[1] * ac[0];
        for (int k = 0; k < 3; k++) nn = std::fmax(nn, std::fabs(n[k]));
        if (!(nn > 0) || !std::isfinite(nn) || !std::isfinite(len)) return 1;
        const Point pa(a[0], a[1], a[2]), pb(b[0], b[1], b[2]), pc(c[0], c[1], c[2]);
        double d[3];
        bool found = false;
        for (double s = -1; s <= 1 && !found; s += 2) {
            for (int k = 0; k < 3; k++) d[k] = m[k] + s * (n[k] / nn) * len;
            if (!std::isfinite(d[0]) || !std::isfinite(d[1]) || !std::isfinite(d[2])) continue;
            found = CGAL::orientation(pa, pb, pc, Point(d[0], d[1], d[2])) == CGAL::NEGATIVE;
        }
        if (!found) return 1;
        Base_rt rt;
        const double *v[4] = {a, b, c, d};
        const double w4[4] = {w[0], w[1], w[2], 0};
        if (!build4(rt, v, w4)) return 1;
        for (Base_rt::All_cells_iterator h = rt.all_cells_begin(); h != rt.all_cells_end(); ++h) {
            int inf;
            if (!h->has_vertex(rt.infinite_vertex(), inf)) continue;
            bool facet = true;
            for (int k = 0; k < 4; k++)
                if (k != inf && h->vertex(k)->info() == 3) facet = false;
            if (!facet) continue;
            *res = static_cast<int>(rt.side_of_power_sphere(h, wp(p, w[3]), true));
            return 0;
        }
        return 1;
    } catch (...) {
        return 1;
    }
}

int dd_cgal_power_compare_distance(const double *p, const double *a, double wa, const double *b, double wb)
{
    try {
        return static_cast<int>(
            K().compare_power_distance_3_object()(Point(p[0], p[1], p[2]), wp(a, wa), wp(b, wb)));
    } catch (...) {
        return 9;
    }
}

} // extern "C"
