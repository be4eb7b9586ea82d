// intersects(obb3, sphere3): fixtures (balls tangent at a corner of a turned box, at an edge of a
// skew box, at a flat box's face and edge and at a point box, and one ulp short; negative and NaN
// extents); every tier against the exact QP (CGAL's QP_solver over Gmpzf, the squared distance
// from the centre to the box) on 20,000 random cases and 20,000 balls tangent at a corner, an edge or
// a face of small dyadic boxes (signed-permutation, near-rotation and skew frames, zero extents),
// exactly or within ulps (testkit/ball_halfspace_cases.hpp).
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
#include "testkit/ball_halfspace_checks.hpp"

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
TEST_CASE("obb_sphere: intersects, fixtures", "[obb_sphere]") {
    // the box turned 45 degrees about z (orthogonal axes of length sqrt 2, 1): its corner (0, 2, 2)
    // and the outward a0 + a1 = (0, 2, 0) of length 2
    const obb3 T{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 2}};
    CHECK(intersects(T, sphere3{{0, 4, 2}, 2}));
    CHECK_FALSE(intersects(T, sphere3{{0, 4, 2}, 0x1.fffffffffffffp+0}));
    CHECK(intersects(sphere3{{0, 0, 5}, 3}, T)); // the top face
    CHECK_FALSE(intersects(sphere3{{0, 0, 5}, 0x1.7ffffffffffffp+1}, T));
    CHECK(intersects(T, sphere3{{0.5, 0.5, 0.5}, 0})); // inside
    // a skew box: its faces s0 = 1 (outward normal a1 x a2 = (1, -1, 0)) and s2 = 1 (normal (0, 0, 1))
    // meet in the edge through (1, 0, 1); (2, -2, 1) is in the edge's normal cone, length 3
    const obb3 S{{0, 0, 0}, {vec3{1, 0, 0}, vec3{1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    CHECK(intersects(S, sphere3{{3, -2, 2}, 3}));
    CHECK_FALSE(intersects(S, sphere3{{3, -2, 2}, 0x1.7ffffffffffffp+1}));
    CHECK(intersects(S, sphere3{{3, -2, 2}, -3})); // an unchecked negative radius acts as |r|
    // the flat hexagon of three dependent axes, its vertices (2, 2, 0), (0, 2, 0), (2, 0, 0) and their
    // opposites: above its vertex, and beyond its edge x = 2
    const obb3 flat{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{1, 1, 0}}, {1, 1, 1}};
    CHECK(intersects(flat, sphere3{{2, 2, 3}, 3}));
    CHECK_FALSE(intersects(flat, sphere3{{2, 2, 3}, 0x1.7ffffffffffffp+1}));
    CHECK(intersects(flat, sphere3{{4, 1, 0}, 2}));
    CHECK_FALSE(intersects(flat, sphere3{{4, 1, 0}, 0x1.fffffffffffffp+0}));
    CHECK(intersects(flat, sphere3{{0.5, -0.5, 0}, 0}));
    const obb3 dot{{1, 1, 1}, T.axes, {0, 0, 0}}; // a point
    CHECK(intersects(dot, sphere3{{4, 5, 1}, 5}));
    CHECK_FALSE(intersects(dot, sphere3{{4, 5, 1}, 0x1.3ffffffffffffp+2}));
    CHECK_FALSE(intersects(obb3{{0, 0, 0}, T.axes, {1, -1, 1}}, sphere3{{0, 0, 0}, 9}));
    CHECK_FALSE(intersects(obb3{{0, 0, 0}, T.axes, {1, __builtin_nan(""), 1}}, sphere3{{0, 0, 0}, 9}));
    CHECK_FALSE(intersects(T, sphere3{{0, 0, 0}, __builtin_inf()}));
}
TEST_CASE("obb_sphere: intersects, oracle", "[obb_sphere][oracle]") {
    support::ball_halfspace_oracle<obb3>("obb_sphere", support::cases(20000), approx_bound);
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
