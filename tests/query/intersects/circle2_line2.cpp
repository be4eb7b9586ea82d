// circle2 x line2: fixtures (a line tangent by a 3-4-5 step and one ulp short, through the centre,
// a zero direction, NaN); every tier against CGAL's squared distance over Epeck (oracle::ball_flat,
// the line in the plane z = 0) on 10,000 random and 10,000 near-degenerate cases (disks tangent to
// lines along axis and Pythagorean directions, radii nudged by ulps, halved or doubled, at a random
// scale; testkit/circle2_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/circle2_checks.hpp"

namespace test_query_circle2_line2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("circle2_line2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("circle2_line2: fixtures", "[circle2_line2]") {
    const line2 l{{-1, 7}, {-4, 3}}; // through (3, 4): 5 from the origin
    CHECK(intersects(circle2{{0, 0}, 5}, l));
    CHECK_FALSE(intersects(l, circle2{{0, 0}, 0x1.3ffffffffffffp2}));
    CHECK(intersects(circle2{{1, 1}, 0}, line2{{-1, -1}, {2, 2}})); // a point disk on the line
    CHECK(intersects(circle2{{0, 0}, 5}, line2{{3, 4}, {0, 0}}));   // a zero direction: its origin
    CHECK_FALSE(intersects(circle2{{0, 0}, 5}, line2{{3, 4.5}, {0, 0}}));
    CHECK_FALSE(intersects(circle2{{0, 0}, __builtin_nan("")}, l));
}
TEST_CASE("circle2_line2: oracle, random and near-degenerate", "[circle2_line2][oracle]") {
    support::disk_oracle<line2>("circle2_line2", support::cases(10000), approx_bound);
}

} // namespace test_query_circle2_line2
