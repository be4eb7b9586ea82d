// contains(obb3, sphere3) and contains(sphere3, obb3): fixtures (a ball tangent to a turned box's
// faces and one ulp larger, a box whose corners lie on the sphere, skew and dependent axes, NaN and
// negative extents); exact rationals (the centre's frame coordinates by Cramer's rule and its
// squared distances to the faces; the box's corners) on 10,000 random and 10,000 cases inside,
// touching from inside (in signed-permutation frames: radii equal to the distance to the nearest
// face, Pythagorean extents whose corners lie on the sphere; near-rotation and skew frames too) or
// just beyond, at a random exact-or-nudged scale and translation.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/contain_checks.hpp"

namespace test_query_obb_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("obb_sphere"); // stated in the catalog (modules/query/catalog.cppm)
std::pair<obb3, sphere3> random_case(support::rng& r) {
    const auto tr = support::random_transform(r, false);
    return {support::random_obb(r, tr), support::random_ball(r, tr)};
}
} // namespace

TEST_CASE("obb_sphere: fixtures", "[obb_sphere]") {
    // the box turned 45 degrees about z, its axes (1, 1, 0) and (-1, 1, 0) of length sqrt 2
    const obb3 T{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 2}};
    // its faces along the first two axes lie at distance sqrt 2 from the centre; along z at 2
    CHECK(contains(T, sphere3{{0, 0, 0}, 1.4142135623730949})); // below sqrt 2 (1.41421356237309504...)
    CHECK_FALSE(contains(T, sphere3{{0, 0, 0}, 1.4142135623730951}));
    CHECK(contains(T, sphere3{{0, 0, 1}, 1})); // tangent to the top face
    CHECK_FALSE(contains(T, sphere3{{0, 0, 1}, 0x1.0000000000001p+0}));
    CHECK(contains(T, sphere3{{2, 0, 0}, 0}));               // a ball of radius 0 at a corner of the section
    CHECK_FALSE(contains(T, sphere3{{1, 1, 0}, 0x1p-1074})); // on a face, a subnormal radius pokes out
    const obb3 U{{1, 1, 1}, {vec3{0, 1, 0}, vec3{0, 0, -1}, vec3{1, 0, 0}}, {1, 2, 2}};
    CHECK(contains(sphere3{{1, 1, 1}, 3}, U)); // corners (1 +- 2, 1 +- 1, 1 +- 2) on the sphere: 1-2-2-3
    CHECK_FALSE(contains(sphere3{{1, 1, 1}, 0x1.7ffffffffffffp+1}, U));
    // T's corners (0, +-2, +-2) and (+-2, 0, +-2) lie at sqrt 8 = 2.82842712474619009...
    CHECK(contains(sphere3{{0, 0, 0}, 2 * 1.4142135623730951}, T));
    CHECK_FALSE(contains(sphere3{{0, 0, 0}, 2.8284271247461898}, T));
    const obb3 flat{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{1, 1, 0}}, {1, 1, 1}}; // dependent axes
    CHECK(contains(flat, sphere3{{0, 0, 0}, 0}));
    CHECK_FALSE(contains(flat, sphere3{{0, 0, 0}, 0x1p-1074}));
    CHECK(contains(sphere3{{0, 0, 0}, 4}, flat)); // its farthest corners (+-2, +-2, 0), at sqrt 8
    CHECK_FALSE(contains(sphere3{{0, 0, 0}, 2.8284271247461898}, flat));
    CHECK_FALSE(contains(obb3{{0, 0, 0}, U.axes, {1, -1, 1}}, sphere3{{0, 0, 0}, 0})); // a negative extent: empty
    CHECK_FALSE(contains(sphere3{{0, 0, 0}, 9}, obb3{{0, 0, 0}, U.axes, {1, __builtin_nan(""), 1}}));
}
TEST_CASE("obb_sphere: contains", "[obb_sphere][oracle]") {
    support::contains_oracle<obb3, sphere3>("obb_sphere (obb around sphere)", support::cases(10000), approx_bound, random_case,
                                            support::obb_holding_ball);
    support::contains_oracle<sphere3, obb3>(
        "obb_sphere (sphere around obb)", support::cases(10000), approx_bound,
        [](support::rng& r) {
            const auto [b, s] = random_case(r);
            return std::pair{s, b};
        },
        support::ball_holding_obb);
}

} // namespace test_query_obb_sphere
