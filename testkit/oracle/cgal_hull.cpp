// CGAL convex hulls and half-space intersections (volumes and areas for the bounding-volume
// tables). Its own translation unit: CGAL's graph code needs -fdelayed-template-parsing here.
#include "cgal_oracle.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Optimal_bounding_box/oriented_bounding_box.h>
#include <CGAL/convex_hull_3.h>
#include <iterator>
#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <vector>

namespace oracle {
namespace {
using KI = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<KI::Point_3>;
void measure(const Mesh& m, double& volume, double& area) {
    volume = CGAL::to_double(CGAL::Polygon_mesh_processing::volume(m));
    area = CGAL::to_double(CGAL::Polygon_mesh_processing::area(m));
}
} // namespace

void hull_volume_area(const double* xyz, unsigned long n, double& volume, double& area) {
    std::vector<KI::Point_3> pts;
    for (unsigned long i = 0; i < n; ++i) pts.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    Mesh m;
    CGAL::convex_hull_3(pts.begin(), pts.end(), m);
    volume = area = 0;
    if (m.number_of_faces() > 0 && CGAL::is_closed(m)) measure(m, volume, area);
}

std::vector<double> hull_vertices_exact(const double* xyz, unsigned long n) {
    using KE = CGAL::Exact_predicates_exact_constructions_kernel;
    std::vector<KE::Point_3> pts;
    for (unsigned long i = 0; i < n; ++i) pts.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    std::vector<KE::Point_3> ext;
    CGAL::extreme_points_3(pts, std::back_inserter(ext));
    std::vector<std::array<double, 3>> v;
    for (const auto& p : ext) v.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    std::vector<double> out;
    for (const auto& p : v) out.insert(out.end(), p.begin(), p.end());
    return out;
}

double obb_volume_cgal(const double* xyz, unsigned long n, double& ms) {
    std::vector<KI::Point_3> pts;
    for (unsigned long i = 0; i < n; ++i) pts.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    std::array<KI::Point_3, 8> box;
    const auto t0 = std::chrono::steady_clock::now();
    CGAL::oriented_bounding_box(pts, box, CGAL::parameters::random_seed(1));
    ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const auto a = box[1] - box[0], b = box[3] - box[0], c = box[5] - box[0];
    return std::abs(CGAL::to_double(a * CGAL::cross_product(b, c)));
}

double hull_time_ms(const double* xyz, unsigned long n, unsigned long& vertices) {
    std::vector<KI::Point_3> pts;
    for (unsigned long i = 0; i < n; ++i) pts.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    const auto t0 = std::chrono::steady_clock::now();
    Mesh m;
    CGAL::convex_hull_3(pts.begin(), pts.end(), m);
    const auto t1 = std::chrono::steady_clock::now();
    vertices = m.number_of_vertices();
    return std::chrono::duration<double, std::milli>(t1 - t0).count();
}

void halfspaces_volume_area(const double* dirs, const double* lo, const double* hi, unsigned long m, const double inside[3], double& volume,
                            double& area) {
    // The polytope is the convex hull of its vertices: every intersection point of three planes
    // that satisfies all the half-spaces (CGAL's halfspace_intersection_3 returned unshared
    // vertices when four or more k-DOP planes meet at a vertex, so it is not used).
    (void)inside;
    std::vector<std::array<double, 4>> pl; // n . x <= h
    double scale = 0;
    for (unsigned long i = 0; i < m; ++i) {
        const double a = dirs[3 * i], b = dirs[3 * i + 1], c = dirs[3 * i + 2];
        pl.push_back({a, b, c, hi[i]});
        pl.push_back({-a, -b, -c, -lo[i]});
        scale = std::max({scale, std::abs(lo[i]), std::abs(hi[i])});
    }
    std::vector<KI::Point_3> pts;
    for (std::size_t i = 0; i < pl.size(); ++i)
        for (std::size_t j = i + 1; j < pl.size(); ++j)
            for (std::size_t k = j + 1; k < pl.size(); ++k) {
                const auto &p = pl[i], &q = pl[j], &r = pl[k];
                const double det =
                    p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) + p[2] * (q[0] * r[1] - q[1] * r[0]);
                if (std::abs(det) < 1e-12) continue;
                const double x =
                    (p[3] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[3] * r[2] - q[2] * r[3]) + p[2] * (q[3] * r[1] - q[1] * r[3])) / det;
                const double y =
                    (p[0] * (q[3] * r[2] - q[2] * r[3]) - p[3] * (q[0] * r[2] - q[2] * r[0]) + p[2] * (q[0] * r[3] - q[3] * r[0])) / det;
                const double z =
                    (p[0] * (q[1] * r[3] - q[3] * r[1]) - p[1] * (q[0] * r[3] - q[3] * r[0]) + p[3] * (q[0] * r[1] - q[1] * r[0])) / det;
                bool ok = true;
                for (const auto& h : pl) ok = ok && h[0] * x + h[1] * y + h[2] * z <= h[3] + 1e-9 * (scale + 1e-300);
                if (ok) pts.emplace_back(x, y, z);
            }
    volume = area = 0;
    if (pts.size() < 4) return;
    Mesh hull;
    CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
    if (hull.number_of_faces() > 0 && CGAL::is_closed(hull)) measure(hull, volume, area);
}

} // namespace oracle
