// aabb3 x sphere3 (the ball): fixtures (a ball touching a face, an edge and a corner from outside
// and one ulp away, a ball tangent to the faces from inside, a box with its corners on the sphere);
// intersects against CGAL Epeck (the Sphere_3 / Iso_cuboid_3 squared-distance test, the ball's) on
// 20,000 random and 20,000 near-degenerate cases (balls touching a box's face, edge or corner
// exactly, a little short or past it, or around an inside point; flat boxes; a random
// exact-or-nudged scale 2^-500..2^500 and translation); contains(aabb, sphere) and
// contains(sphere, aabb) against exact rationals on 10,000 random and 10,000 cases inside, touching
// from inside (radii equal to the distance to the nearest face; Pythagorean extents whose corners
// lie on the sphere) or just beyond.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/contain_checks.hpp"

namespace test_query_aabb_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_sphere"); // stated in the catalog (modules/query/catalog.cppm)
std::pair<aabb3, sphere3> random_case(support::rng& r) {
    const auto tr = support::random_transform(r, false);
    return {support::random_aabb(r, tr), support::random_ball(r, tr)};
}
} // namespace

TEST_CASE("aabb_sphere: fixtures", "[aabb_sphere]") {
    const aabb3 B{{0, 0, 0}, {1, 1, 1}};
    CHECK(intersects(B, sphere3{{2, 0.5, 0.5}, 1}));                          // touches the face x = 1
    CHECK_FALSE(intersects(B, sphere3{{2, 0.5, 0.5}, 0x1.fffffffffffffp-1})); // one ulp short
    CHECK(intersects(B, sphere3{{4, 5, 0.5}, 5}));                            // touches the edge x = y = 1: 3-4-5
    CHECK_FALSE(intersects(B, sphere3{{4, 5, 0.5}, 0x1.3ffffffffffffp+2}));
    CHECK(intersects(B, sphere3{{2, 3, 3}, 3})); // touches the corner (1, 1, 1): 1-2-2-3
    CHECK(intersects(sphere3{{2, 3, 3}, 3}, B));
    CHECK(contains(B, sphere3{{0.5, 0.5, 0.5}, 0.5})); // tangent to all six faces
    CHECK_FALSE(contains(B, sphere3{{0.5, 0.5, 0.5}, 0x1.0000000000001p-1}));
    CHECK(contains(sphere3{{0, 0, 0}, 3}, aabb3{{-1, -2, -2}, {1, 2, 2}})); // corners on the sphere
    CHECK_FALSE(contains(sphere3{{0, 0, 0}, 3}, aabb3{{-1, -2, -2}, {1, 2, 0x1.0000000000001p+1}}));
    CHECK(contains(sphere3{{0, 0, 0}, -3}, aabb3{{-1, -2, -2}, {1, 2, 2}}));           // an unchecked negative radius acts as |r|
    CHECK_FALSE(intersects(aabb3{{1, 1, 1}, {0, 0, 0}}, sphere3{{0.5, 0.5, 0.5}, 1})); // inverted box: empty
    CHECK_FALSE(intersects(B, sphere3{{__builtin_nan(""), 0.5, 0.5}, 1}));
    CHECK_FALSE(contains(aabb3{{-__builtin_inf(), 0, 0}, {1, 1, 1}}, sphere3{{0.5, 0.5, 0.5}, 0.25}));
    CHECK_FALSE(contains(sphere3{{0, 0, 0}, __builtin_inf()}, B));
}
TEST_CASE("aabb_sphere: oracle", "[aabb_sphere][oracle]") {
    auto truth = [](const aabb3& b, const sphere3& s) {
        double mn[3], mx[3], c[3];
        support::arr(b.min, mn), support::arr(b.max, mx), support::arr(s.center, c);
        return oracle::ball_aabb(mn, mx, c, s.radius);
    };
    auto skip = [](const aabb3&, const sphere3&) { return false; };
    auto describe = [](const aabb3& b, const sphere3& s) { return support::str(b) + " " + support::str(s); };
    support::run_oracle("aabb_sphere random", support::cases(20000), approx_bound, random_case, truth, skip, describe);
    support::run_oracle("aabb_sphere near-degenerate", support::cases(20000), approx_bound, support::ball_touching_aabb, truth, skip,
                        describe);
}
TEST_CASE("aabb_sphere: contains", "[aabb_sphere][oracle]") {
    support::contains_oracle<aabb3, sphere3>("aabb_sphere (aabb around sphere)", support::cases(10000), approx_bound, random_case,
                                             support::aabb_holding_ball);
    support::contains_oracle<sphere3, aabb3>(
        "aabb_sphere (sphere around aabb)", support::cases(10000), approx_bound,
        [](support::rng& r) {
            const auto [b, s] = random_case(r);
            return std::pair{s, b};
        },
        support::ball_holding_aabb);
}

} // namespace test_query_aabb_sphere
