// circle2 x circle2: fixtures (disks tangent from outside by a 3-4-5 step and one ulp apart, one
// inside another touching it, negative and NaN radii); every tier against exact rationals
// (oracle::ball_ball in the plane z = 0) on 10,000 random and 10,000 near-degenerate cases (tangent
// disks along axis and Pythagorean directions, radii nudged by ulps, halved or doubled, at a random
// scale; testkit/circle2_cases.hpp); and contains(circle2, circle2) (disks touching from inside,
// grown by an ulp or halved) against exact rationals (oracle::ball_contains_ball).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/circle2_checks.hpp"

namespace test_query_circle2_circle2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("circle2_circle2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("circle2_circle2: fixtures", "[circle2_circle2]") {
    const circle2 a{{0, 0}, 2};
    CHECK(intersects(a, circle2{{3, 4}, 3})); // tangent from outside: 5 = 2 + 3
    CHECK_FALSE(intersects(a, circle2{{3, 4}, 0x1.7ffffffffffffp1}));
    CHECK(intersects(a, circle2{{3, 4}, -3}));
    CHECK_FALSE(intersects(a, circle2{{3, 4}, __builtin_nan("")}));
    CHECK(contains(circle2{{0, 0}, 7}, circle2{{3, 4}, 2})); // touching from inside
    CHECK_FALSE(contains(circle2{{0, 0}, 7}, circle2{{3, 4}, 0x1.0000000000001p1}));
    CHECK(contains(a, a));
    CHECK_FALSE(contains(circle2{{3, 4}, 2}, circle2{{0, 0}, 7}));
}
TEST_CASE("circle2_circle2: oracle, random and near-degenerate", "[circle2_circle2][oracle]") {
    support::disk_oracle<circle2>("circle2_circle2", support::cases(10000), approx_bound);
}
TEST_CASE("circle2_circle2: contains", "[circle2_circle2][oracle]") {
    support::disk_contains<circle2>("circle2_circle2", support::cases(10000), approx_bound);
}

} // namespace test_query_circle2_circle2
