// circle2 x ray2: fixtures (a ray tangent by a 3-4-5 step and one ulp short, a ray pointing away
// from the disk, its origin on the circle, a zero direction, NaN); every tier against CGAL's
// squared distance over Epeck (oracle::ball_flat, the ray in the plane z = 0) on 10,000 random and
// 10,000 near-degenerate cases (disks tangent across a ray or behind its origin, along axis and
// Pythagorean directions, radii nudged by ulps, halved or doubled, at a random scale;
// testkit/circle2_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/circle2_checks.hpp"

namespace test_query_circle2_ray2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("circle2_ray2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("circle2_ray2: fixtures", "[circle2_ray2]") {
    const ray2 r{{-1, 7}, {4, -3}}; // through (3, 4): its line 5 from the origin
    CHECK(intersects(circle2{{0, 0}, 5}, r));
    CHECK_FALSE(intersects(r, circle2{{0, 0}, 0x1.3ffffffffffffp2}));
    CHECK_FALSE(intersects(circle2{{0, 0}, 5}, ray2{{-1, 7}, {-4, 3}})); // pointing away: 7.07 from the origin
    CHECK(intersects(circle2{{0, 0}, 5}, ray2{{3, 4}, {3, 4}}));         // from the circle outwards
    CHECK(intersects(circle2{{0, 0}, 5}, ray2{{3, 4}, {0, 0}}));         // a zero direction: its origin
    CHECK_FALSE(intersects(circle2{{0, 0}, 5}, ray2{{3, 4}, {0, __builtin_nan("")}}));
}
TEST_CASE("circle2_ray2: oracle, random and near-degenerate", "[circle2_ray2][oracle]") {
    support::disk_oracle<ray2>("circle2_ray2", support::cases(10000), approx_bound);
}

} // namespace test_query_circle2_ray2
