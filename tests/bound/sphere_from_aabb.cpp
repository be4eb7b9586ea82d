// sphere_from_aabb (box centre, half diagonal) and sphere_from_aabb_farthest (box centre,
// farthest point): every point inside (CGAL exact rationals), the box's corners inside the
// first, the second never larger than the first, clear errors.
#include <catch2/catch_test_macros.hpp>
#include <span>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/point_sets.hpp"
#include "testkit/sphere_checks.hpp"

namespace test_bound_sphere_from_aabb { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

TEST_CASE("sphere_from_aabb and _farthest: every generated and real set", "[bound][sphere_from_aabb]") {
    support::rng r(support::seed());
    auto sets = support::point_sets(r, support::cases(2000));
    for (auto& m : support::real_meshes()) sets.push_back(std::move(m));
    for (const auto& s : sets) {
        INFO(s.name);
        const std::span<const point3> pts(s.points);
        const auto a = bound::sphere_from_aabb(pts), f = bound::sphere_from_aabb_farthest(pts);
        REQUIRE(a);
        REQUIRE(f);
        CHECK(support::all_inside(pts, a.value()));
        CHECK(support::all_inside(pts, f.value()));
        const aabb3 b = bound::aabb_of(pts).value();
        const point3 corners[2] = {b.min, b.max};
        CHECK(support::all_inside(std::span<const point3>(corners), a.value()));
        CHECK(f.value().radius <= a.value().radius);
    }
    std::printf("[cases] sphere_from_aabb: %zu point sets, all points inside both spheres\n", sets.size());
}

TEST_CASE("sphere_from_aabb: bad input", "[bound][sphere_from_aabb]") {
    CHECK(bound::sphere_from_aabb(std::span<const point3>()).error().code == errc::empty_input);
    CHECK(bound::sphere_from_aabb(aabb3{{1, 0, 0}, {0, 1, 1}}).error().code == errc::inverted_box);
    const point3 huge[] = {{-1.7e308, -1.7e308, -1.7e308}, {1.7e308, 1.7e308, 1.7e308}};
    CHECK(bound::sphere_from_aabb(std::span<const point3>(huge)).error().code == errc::out_of_range);
    constexpr aabb3 unit{{0, 0, 0}, {2, 2, 2}};
    static_assert(bound::sphere_from_aabb(unit).value().center == point3{1, 1, 1});
}

} // namespace test_bound_sphere_from_aabb
