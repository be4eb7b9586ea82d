// circle2 x segment2: fixtures (a segment tangent across the disk by a 3-4-5 step and one ulp short,
// an end nearest the centre, a segment through the disk, a point segment, NaN); every tier against
// CGAL's squared distance over Epeck (oracle::ball_flat, the segment in the plane z = 0) on 10,000
// random and 10,000 near-degenerate cases (disks tangent across a segment or beyond an end, along
// axis and Pythagorean directions, radii nudged by ulps, halved or doubled, at a random scale;
// testkit/circle2_cases.hpp); and contains(circle2, segment2) (ends on the circle or inside)
// against exact rationals.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/circle2_checks.hpp"

namespace test_query_circle2_segment2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("circle2_segment2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("circle2_segment2: fixtures", "[circle2_segment2]") {
    // the segment along (4, -3) through (3, 4): its line 5 from the origin
    const segment2 s{{-1, 7}, {7, 1}};
    CHECK(intersects(circle2{{0, 0}, 5}, s));
    CHECK_FALSE(intersects(circle2{{0, 0}, 0x1.3ffffffffffffp2}, s));
    CHECK(intersects(segment2{{3, 4}, {6, 8}}, circle2{{0, 0}, 5})); // its end on the circle
    CHECK_FALSE(intersects(segment2{{3, 0x1.0000000000001p2}, {6, 8}}, circle2{{0, 0}, 5}));
    CHECK_FALSE(intersects(circle2{{0, 0}, 4}, segment2{{3, 4}, {6, 8}})); // the end is nearest: 5 away
    CHECK(intersects(circle2{{0, 0}, 1}, segment2{{-9, 0}, {9, 0}}));      // through it
    CHECK(intersects(circle2{{0, 0}, 5}, segment2{{3, 4}, {3, 4}}));
    CHECK_FALSE(intersects(circle2{{0, 0}, 5}, segment2{{3, 4}, {3, __builtin_nan("")}}));
    CHECK(contains(circle2{{0, 0}, 5}, segment2{{3, 4}, {-4, -3}}));
    CHECK_FALSE(contains(circle2{{0, 0}, 5}, segment2{{3, 4}, {-4, -0x1.8000000000001p1}}));
}
TEST_CASE("circle2_segment2: oracle, random and near-degenerate", "[circle2_segment2][oracle]") {
    support::disk_oracle<segment2>("circle2_segment2", support::cases(10000), approx_bound);
}
TEST_CASE("circle2_segment2: contains", "[circle2_segment2][oracle]") {
    support::disk_contains<segment2>("circle2_segment2", support::cases(10000), approx_bound);
}

} // namespace test_query_circle2_segment2
