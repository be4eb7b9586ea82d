// aabb_of: tight (every face touched), containing, and clear errors.
#include <catch2/catch_test_macros.hpp>
#include <span>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/point_sets.hpp"

namespace test_bound_aabb_of { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

TEST_CASE("aabb_of: every generated and real set", "[bound][aabb_of]") {
    support::rng r(support::seed());
    auto sets = support::point_sets(r, support::cases(2000));
    for (auto& m : support::real_meshes()) sets.push_back(std::move(m));
    long checked = 0;
    for (const auto& s : sets) {
        const auto b = bound::aabb_of(std::span<const point3>(s.points));
        REQUIRE(b);
        bool touches[6] = {};
        for (const point3& p : s.points) {
            CHECK((p.x >= b.value().min.x && p.x <= b.value().max.x && p.y >= b.value().min.y && p.y <= b.value().max.y &&
                   p.z >= b.value().min.z && p.z <= b.value().max.z));
            touches[0] |= p.x == b.value().min.x, touches[1] |= p.x == b.value().max.x, touches[2] |= p.y == b.value().min.y;
            touches[3] |= p.y == b.value().max.y, touches[4] |= p.z == b.value().min.z, touches[5] |= p.z == b.value().max.z;
            ++checked;
        }
        for (bool t : touches) CHECK(t);
    }
    std::printf("[cases] aabb_of: %zu point sets, %ld points inside and every face touched\n", sets.size(), checked);
}

TEST_CASE("aabb_of: boxes, and bad input", "[bound][aabb_of]") {
    const aabb3 boxes[] = {{{0, 0, 0}, {1, 1, 1}}, {{-2, 0.5, 0}, {0, 3, 0.5}}};
    const auto b = bound::aabb_of(std::span<const aabb3>(boxes));
    REQUIRE(b);
    CHECK(b.value().min == point3{-2, 0, 0});
    CHECK(b.value().max == point3{1, 3, 1});
    CHECK(bound::aabb_of(std::span<const point3>()).error().code == errc::empty_input);
    const point3 nan_pt[] = {{0, 0, 0}, {0, __builtin_nan(""), 0}};
    CHECK(bound::aabb_of(std::span<const point3>(nan_pt)).error().code == errc::not_finite);
    const aabb3 inverted[] = {{{1, 0, 0}, {0, 1, 1}}};
    CHECK(bound::aabb_of(std::span<const aabb3>(inverted)).error().code == errc::inverted_box);
    constexpr point3 cp[] = {{1, 2, 3}, {-1, 5, 0}};
    static_assert(bound::aabb_of(std::span<const point3>(cp)).value().max == point3{1, 5, 3});
}

TEST_CASE("every construction: a million copies of one point", "[bound]") {
    const std::vector<point3> same(1000000, point3{0.1, -0.2, 0.3});
    const std::span<const point3> s(same);
    CHECK(bound::aabb_of(s).value().min == same[0]);
    CHECK(bound::aabb_of(s).value().max == same[0]);
    const auto k = bound::kdop_of<26>(s).value();
    CHECK(bound::contains(k, same[0]));
    CHECK(bound::sphere_from_aabb(s).value().radius == 0.0);
    CHECK(bound::sphere_from_aabb_farthest(s).value().radius == 0.0);
    CHECK(bound::sphere_ritter(s).value().radius == 0.0);
    const auto h = bound::convex_hull(s).value();
    CHECK(h.dimension == 0);
    CHECK(h.vertices.size() == 1);
    const auto o = bound::obb_min_volume(s).value();
    CHECK(bound::contains(o, same[0]));
    CHECK(bound::volume(o) < 1e-30);
    std::printf("[cases] 1e6 copies of one point: every construction gives the point (or a box of volume %g around it)\n",
                bound::volume(o));
}

} // namespace test_bound_aabb_of
