// convex_hull: the vertex set equals CGAL's extreme points (convex_hull_3 with Epeck); a 3D hull
// is a closed, consistently oriented triangle mesh (every directed edge once with its reverse,
// Euler characteristic 2) with every input point on the inner side of every face (exact);
// flat, collinear and single-point input give the lower-dimensional hull.
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <map>
#include <span>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/point_sets.hpp"

namespace test_bound_convex_hull { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
long sets = 0, wrong_vertices = 0, bad_mesh = 0, outside = 0;

void check(const std::string& name, std::span<const point3> pts, bool all_points_vs_faces) {
    INFO(name);
    const auto h = bound::convex_hull(pts);
    REQUIRE(h);
    ++sets;
    const auto& hv = h.value();
    std::vector<double> xyz;
    for (const auto& p : pts) xyz.insert(xyz.end(), {p.x, p.y, p.z});
    std::vector<std::array<double, 3>> ours;
    for (const auto& p : hv.vertices) ours.push_back({p.x, p.y, p.z});
    std::sort(ours.begin(), ours.end());
    std::vector<double> flat;
    for (const auto& p : ours) flat.insert(flat.end(), p.begin(), p.end());
    if (hv.dimension == 3 || hv.dimension == 2) {
        if (flat != oracle::hull_vertices_exact(xyz.data(), pts.size())) {
            ++wrong_vertices;
            std::printf("  vertex set differs from CGAL: %s (dimension %d, %zu vertices)\n", name.c_str(), hv.dimension,
                        hv.vertices.size());
        }
    }
    if (hv.dimension == 3) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
        for (const auto& t : hv.triangles)
            for (int e = 0; e < 3; ++e) ++edges[{t[std::size_t(e)], t[std::size_t((e + 1) % 3)]}];
        bool ok = true;
        for (const auto& [e, count] : edges) ok = ok && count == 1 && edges.count({e.second, e.first}) == 1;
        const long V = long(hv.vertices.size()), E = long(edges.size()) / 2, F = long(hv.triangles.size());
        ok = ok && V - E + F == 2;
        if (!ok) ++bad_mesh, std::printf("  not a closed oriented sphere: %s\n", name.c_str());
        const std::size_t step = all_points_vs_faces ? 1 : std::max<std::size_t>(1, pts.size() / 500);
        for (const auto& t : hv.triangles)
            for (std::size_t i = 0; i < pts.size(); i += step)
                if (orient3d(hv.vertices[t[0]], hv.vertices[t[1]], hv.vertices[t[2]], pts[i]) == sign::negative) {
                    ++outside;
                    break;
                }
    }
}
} // namespace

TEST_CASE("convex_hull: generated, degenerate and real point sets against CGAL", "[bound][convex_hull][oracle]") {
    support::rng r(support::seed());
    for (const auto& s : support::point_sets(r, support::cases(1000))) check(s.name, s.points, true);
    for (long i = 0; i < support::cases(3000); ++i) {
        std::vector<point3> pts(static_cast<std::size_t>(r.integer(1, 40)));
        const int kind = r.integer(0, 3);
        for (auto& p : pts) {
            if (kind == 0) p = {r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
            else if (kind == 1)
                p = {double(r.integer(-2, 2)), double(r.integer(-2, 2)), double(r.integer(-2, 2))}; // grid: coplanar faces, collinear edges
            else if (kind == 2)
                p = {support::nudge(1.0, r.integer(-2, 2)), support::nudge(2.0, r.integer(-2, 2)), support::nudge(3.0, r.integer(-2, 2))};
            else {
                static constexpr int q[][3] = {{3, 4, 12}, {4, 3, 12}, {12, 3, 4}, {12, 4, 3},
                                               {0, 5, 12}, {13, 0, 0}, {0, 13, 0}, {0, 0, 13}};
                const auto& e = q[r.integer(0, 7)];
                p = {(r.coin() ? 1 : -1) * double(e[0]), (r.coin() ? 1 : -1) * double(e[1]), (r.coin() ? 1 : -1) * double(e[2])};
            }
        }
        check("random set " + std::to_string(i) + " kind " + std::to_string(kind), pts, true);
    }
    auto meshes = support::real_meshes();
    if (support::meshes_required()) REQUIRE(meshes.size() == 5);
    for (const auto& m : meshes) check(m.name, m.points, false);
    std::printf("[cases] convex_hull vs CGAL: %ld sets (%zu real meshes), %ld vertex sets differ, %ld bad meshes, %ld with a "
                "point outside a face\n",
                sets, meshes.size(), wrong_vertices, bad_mesh, outside);
    CHECK(wrong_vertices == 0);
    CHECK(bad_mesh == 0);
    CHECK(outside == 0);
}

TEST_CASE("convex_hull: lower dimensions and bad input", "[bound][convex_hull]") {
    const point3 one[] = {{1, 2, 3}, {1, 2, 3}};
    CHECK(bound::convex_hull(std::span<const point3>(one)).value().dimension == 0);
    const point3 line[] = {{0, 0, 0}, {3, 3, 3}, {1, 1, 1}, {2, 2, 2}};
    const auto l = bound::convex_hull(std::span<const point3>(line)).value();
    CHECK(l.dimension == 1);
    CHECK(l.vertices.size() == 2);
    const point3 square[] = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {0.5, 0.5, 1}, {0.5, 0, 1}};
    const auto s = bound::convex_hull(std::span<const point3>(square)).value();
    CHECK(s.dimension == 2);
    CHECK(s.vertices.size() == 4);
    CHECK(s.triangles.size() == 2);
    CHECK(bound::convex_hull(std::span<const point3>()).error().code == errc::empty_input);
    const point3 nan_pt[] = {{0, 0, 0}, {__builtin_nan(""), 0, 0}};
    CHECK(bound::convex_hull(std::span<const point3>(nan_pt)).error().code == errc::not_finite);
}

} // namespace test_bound_convex_hull
