// circle2 x point2: fixtures (a point on the circle by a 3-4-5 step and one ulp beyond, the centre, a
// zero and a negative radius, NaN); every tier against exact rationals (oracle::point_in_ball in
// the plane z = 0) on 10,000 random and 10,000 near-degenerate cases (points on the circle by
// Pythagorean steps, within ulps of it, at a random scale; testkit/circle2_cases.hpp); and
// contains(circle2, point2) on the same kinds of cases.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/circle2_checks.hpp"

namespace test_query_circle2_point2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("circle2_point2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("circle2_point2: fixtures", "[circle2_point2]") {
    const circle2 c{{1, 2}, 5};
    CHECK(intersects(c, point2{4, 6})); // (3, 4) away
    CHECK_FALSE(intersects(point2{4, 0x1.8000000000001p2}, c));
    CHECK(intersects(c, point2{1, 2}));
    CHECK(intersects(circle2{{1, 2}, 0}, point2{1, 2}));
    CHECK(intersects(circle2{{1, 2}, -5}, point2{4, 6})); // an unchecked negative radius acts as |r|
    CHECK_FALSE(intersects(circle2{{1, 2}, __builtin_nan("")}, point2{1, 2}));
    CHECK(contains(c, point2{-2, -2}));
    CHECK_FALSE(contains(c, point2{-2, -0x1.0000000000001p1}));
    CHECK_FALSE(circle2::make({1, 2}, -1).has_value());
    CHECK_FALSE(circle2::make({1, __builtin_inf()}, 1).has_value());
}
TEST_CASE("circle2_point2: oracle, random and near-degenerate", "[circle2_point2][oracle]") {
    support::disk_oracle<point2>("circle2_point2", support::cases(10000), approx_bound);
}
TEST_CASE("circle2_point2: contains", "[circle2_point2][oracle]") {
    support::disk_contains<point2>("circle2_point2", support::cases(10000), approx_bound);
}

} // namespace test_query_circle2_point2
