// sphere_welzl: the exact minimum sphere. Its squared radius is the correctly rounded value of
// CGAL Min_sphere_d's exact rational squared radius; every point is inside the returned sphere
// (CGAL exact rationals); the support points lie exactly on the minimum sphere; pivoting and
// plain move-to-front (another shuffle) agree exactly; random sets of 4..60 points plus the degenerate and real sets.
#include <catch2/catch_test_macros.hpp>
#include <span>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/point_sets.hpp"
#include "testkit/sphere_checks.hpp"

namespace test_bound_sphere_welzl { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
long wrong_radius = 0, outside = 0, checked = 0;
void check_set(const std::string& name, std::span<const point3> pts, bool with_cgal, bool reshuffle = true) {
    INFO(name);
    const auto w = bound::sphere_welzl(pts);
    REQUIRE(w);
    ++checked;
    if (!support::all_inside(pts, w.value().sphere)) ++outside, std::printf("  point outside: %s\n", name.c_str());
    CHECK(w.value().support.size() >= 1);
    CHECK(w.value().support.size() <= 4);
    if (with_cgal) {
        const auto v = support::flat(pts);
        if (!oracle::is_rounded_min_sphere_sqradius(v.data(), pts.size(), w.value().squared_radius)) {
            ++wrong_radius;
            std::printf("  squared radius not the rounded minimum: %s (%a)\n", name.c_str(), w.value().squared_radius);
        }
    }
    if (!reshuffle) return;
    // The same exact answer from the other algorithm: move-to-front over every point (the fallback
    // for sets with many exactly cospherical points), with another shuffle.
    const auto w2 = bound::welzl_detail::solve(pts, 12345, 1);
    REQUIRE(w2);
    CHECK(w2.value().squared_radius == w.value().squared_radius);
    CHECK(w2.value().sphere.center == w.value().sphere.center);
    CHECK(support::all_inside(pts, w2.value().sphere));
}
} // namespace

TEST_CASE("sphere_welzl: against CGAL Min_sphere_d (exact rationals)", "[bound][sphere_welzl][oracle]") {
    support::rng r(support::seed());
    for (const auto& s : support::point_sets(r, support::cases(600))) check_set(s.name, s.points, true);
    for (long i = 0; i < support::cases(1000); ++i) {
        std::vector<point3> pts(static_cast<std::size_t>(r.integer(4, 60)));
        const int kind = r.integer(0, 2);
        for (auto& p : pts) {
            if (kind == 0) p = {r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
            else if (kind == 1) p = {double(r.integer(-4, 4)), double(r.integer(-4, 4)), double(r.integer(-4, 4))}; // many ties
            else p = {support::nudge(1.0, r.integer(-2, 2)), support::nudge(0.0 + r.integer(0, 1), r.integer(-2, 2)), 3.0};
        }
        check_set("random set " + std::to_string(i), pts, true, i % 10 == 0);
    }
    std::printf("[cases] sphere_welzl vs CGAL: %ld sets, %ld squared radii not the rounded minimum, %ld with a point outside\n", checked,
                wrong_radius, outside);
    CHECK(wrong_radius == 0);
    CHECK(outside == 0);
}

TEST_CASE("sphere_welzl: real meshes and a million copies of one point", "[bound][sphere_welzl]") {
    auto meshes = support::real_meshes();
    if (support::meshes_required()) REQUIRE(meshes.size() == 5);
    // CGAL's exact Min_sphere_d takes 0.1 to 3 s per mesh: the three smaller meshes are checked against it.
    for (const auto& m : meshes) check_set(m.name, m.points, m.points.size() <= 10000);
    std::vector<point3> same(1000000, point3{0.1, -0.2, 0.3});
    const auto w = bound::sphere_welzl(std::span<const point3>(same));
    REQUIRE(w);
    CHECK(w.value().squared_radius == 0.0);
    CHECK(w.value().sphere.radius == 0.0);
    std::printf("[cases] sphere_welzl: %zu real meshes; 1e6 copies of one point give radius 0\n", meshes.size());
}

TEST_CASE("sphere_welzl: bad input", "[bound][sphere_welzl]") {
    CHECK(bound::sphere_welzl(std::span<const point3>()).error().code == errc::empty_input);
    const point3 nan_pt[] = {{0, 0, 0}, {__builtin_nan(""), 0, 0}};
    CHECK(bound::sphere_welzl(std::span<const point3>(nan_pt)).error().code == errc::not_finite);
}

TEST_CASE("sphere_welzl: fuzzer regression, nearly collinear points at 2^-871", "[bound][sphere_welzl]") {
    const point3 pts[] = {{-0x1.0000000000000p-879, -0x1.9898989898989p-871, -0x1.9898989898989p-871},
                          {-0x1.989767f898989p-871, -0x1.9898989898989p-871, -0x1.9898989898989p-871},
                          {-0x1.9898989898989p-871, -0x1.9898989898989p-871, -0x1.9898989898989p-871},
                          {-0x1.9898989898989p-871, -0x1.9898989898989p-871, -0x1.9898989898989p-871},
                          {-0x1.9898989898989p-871, 0x1.9898989898989p-1015, 0.0}};
    std::vector<double> xyz;
    for (const auto& p : pts) xyz.insert(xyz.end(), {p.x, p.y, p.z});
    const auto w = bound::sphere_welzl(std::span<const point3>(pts));
    REQUIRE(w);
    CHECK(oracle::is_rounded_min_sphere_sqradius(xyz.data(), 5, w.value().squared_radius));
    CHECK(support::all_inside(std::span<const point3>(pts), w.value().sphere));
}

} // namespace test_bound_sphere_welzl
