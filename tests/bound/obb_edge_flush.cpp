// obb_edge_flush: the shared OBB construction checks (every point inside by CGAL rationals and the
// library's exact test, valid axes, clear errors; bunny's 2632-vertex hull is over the size limit
// and must be refused with errc::too_large); a rotated box is recovered to 1e-9 of its volume; on
// random small sets and the real meshes within the limit, its volume is at most obb_min_volume's
// and CGAL oriented_bounding_box's (1e-7 relative slack for the rounding of the fitted extents).
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <span>
#include <vector>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/point_sets.hpp"
#include "testkit/box_checks.hpp"

namespace test_bound_obb_edge_flush { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
double cgal_volume(std::span<const point3> pts) {
    std::vector<double> xyz;
    for (const auto& p : pts) xyz.insert(xyz.end(), {p.x, p.y, p.z});
    double ms = 0;
    return oracle::obb_volume_cgal(xyz.data(), pts.size(), ms);
}
// A random rotation (unit quaternion) applied to v.
vec3 rotate(const std::array<double, 4>& q, vec3 v) {
    const vec3 u{q[1], q[2], q[3]};
    const vec3 t = cross(u, v) * 2.0;
    return v + t * q[0] + cross(u, t);
}
} // namespace

TEST_CASE("obb_edge_flush: every generated and real set", "[bound][obb_edge_flush]") {
    support::check_obb_construction(
        "obb_edge_flush", [](std::span<const point3> pts) { return bound::obb_edge_flush(pts); }, errc::too_large);
}

TEST_CASE("obb_edge_flush: a rotated box with points inside is recovered", "[bound][obb_edge_flush]") {
    support::rng r(support::seed());
    for (long c = 0; c < support::cases(40); ++c) {
        double q0 = r.uniform(-1, 1), q1 = r.uniform(-1, 1), q2 = r.uniform(-1, 1), q3 = r.uniform(-1, 1);
        const double n = std::sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3);
        const std::array<double, 4> q{q0 / n, q1 / n, q2 / n, q3 / n};
        const double a = r.uniform(0.5, 3), b = r.uniform(0.5, 3), h = r.uniform(0.5, 3);
        std::vector<point3> pts;
        for (int s = 0; s < 8; ++s) // the corners and interior points
            pts.push_back(point3{1, 2, 3} + rotate(q, vec3{(s & 1 ? a : -a), (s & 2 ? b : -b), (s & 4 ? h : -h)}));
        for (int k = 0; k < 30; ++k) pts.push_back(point3{1, 2, 3} + rotate(q, vec3{r.uniform(-a, a), r.uniform(-b, b), r.uniform(-h, h)}));
        const auto box = bound::obb_edge_flush(pts);
        REQUIRE(box);
        const double want = 8 * a * b * h;
        INFO("case " << c << " volume " << bound::volume(box.value()) << " want " << want);
        CHECK(std::abs(bound::volume(box.value()) - want) <= 1e-9 * want);
    }
}

TEST_CASE("obb_edge_flush: no larger than obb_min_volume or CGAL's box", "[bound][obb_edge_flush]") {
    support::rng r(support::seed());
    long sets = 0, above_minvol = 0, above_cgal = 0;
    double best_gain = 1;
    std::vector<std::pair<std::string, std::vector<point3>>> inputs;
    for (long c = 0; c < support::cases(150); ++c) {
        std::vector<point3> pts;
        const long n = r.integer(5, 60);
        const double sx = r.uniform(0.1, 3), sy = r.uniform(0.1, 3);
        for (long k = 0; k < n; ++k) {
            if (c % 2 == 0) pts.push_back({r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)});
            else { // points on a skewed ellipsoid: every hull edge has a small arc
                double x = r.uniform(-1, 1), y = r.uniform(-1, 1), z = r.uniform(-1, 1);
                const double l = std::sqrt(x * x + y * y + z * z) + 1e-9;
                x /= l, y /= l, z /= l;
                pts.push_back({sx * x + 0.3 * y, sy * y, z + 0.2 * x});
            }
        }
        inputs.push_back({"random " + std::to_string(c), pts});
    }
    for (auto& m : support::real_meshes())
        if (m.points.size() < 12000) inputs.push_back({m.name, m.points});
    for (const auto& [name, pts] : inputs) {
        INFO(name);
        const auto f = bound::obb_edge_flush(pts);
        const auto m = bound::obb_min_volume(pts);
        REQUIRE(f);
        REQUIRE(m);
        ++sets;
        const double vf = bound::volume(f.value()), vm = bound::volume(m.value()), vc = cgal_volume(pts);
        if (vf > vm * (1 + 1e-7)) ++above_minvol, std::printf("  %s: edge-flush %.9g > min_volume %.9g\n", name.c_str(), vf, vm);
        if (vf > vc * (1 + 1e-7)) ++above_cgal, std::printf("  %s: edge-flush %.9g > CGAL %.9g\n", name.c_str(), vf, vc);
        best_gain = std::min(best_gain, vf / vm);
        if (pts.size() > 1000)
            std::printf("[cases] obb_edge_flush %s: volume / obb_min_volume %.6f, / CGAL %.6f\n", name.c_str(), vf / vm, vf / vc);
    }
    std::printf("[cases] obb_edge_flush: %ld sets, larger than obb_min_volume on %ld, than CGAL on %ld; smallest ratio to "
                "obb_min_volume %.4f\n",
                sets, above_minvol, above_cgal, best_gain);
    CHECK(above_minvol == 0);
    CHECK(above_cgal == 0);
}

} // namespace test_bound_obb_edge_flush
