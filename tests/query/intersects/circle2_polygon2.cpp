// circle2 x polygon2: fixtures (a square with a square hole: a disk tangent to an outer edge by a
// 3-4-5 step and one ulp short, a disk in the hole touching its edges and one ulp smaller, a disk
// inside the polygon's ring, a disk around the whole polygon); every tier against CGAL (the centre
// in the polygon's set by Polygon_2 over Epeck, oracle::polygon_intersect, or an edge within the
// radius by the squared distance over Epeck) on 10,000 random and 10,000 near-degenerate cases
// (disks across a star polygon's edges at its vertices, midpoints and quarter points, or around
// its centre and between its rings, radii nudged by ulps, halved or doubled, at a random scale;
// testkit/circle2_cases.hpp); and contains(circle2, polygon2) (the radius the farthest vertex's
// distance, rounded, or a little more) against exact rationals.
#include <catch2/catch_test_macros.hpp>
#include <vector>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/circle2_checks.hpp"

namespace test_query_circle2_polygon2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("circle2_polygon2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("circle2_polygon2: fixtures", "[circle2_polygon2]") {
    // [0, 10]^2 with the hole [4, 6]^2
    const std::vector<point2> v{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {4, 6}, {6, 6}, {6, 4}};
    const std::vector<std::uint32_t> ends{4, 8};
    const polygon2 g{v, ends};
    CHECK(intersects(circle2{{13, 14}, 5}, g)); // the corner (10, 10) is (3, 4) away
    CHECK_FALSE(intersects(circle2{{13, 14}, 0x1.3ffffffffffffp2}, g));
    CHECK(intersects(g, circle2{{5, 5}, 1})); // in the hole, touching its four edges
    CHECK_FALSE(intersects(g, circle2{{5, 5}, 0x1.fffffffffffffp-1}));
    CHECK(intersects(circle2{{2, 2}, 0.5}, g)); // inside the ring
    CHECK(intersects(circle2{{5, 5}, 100}, g)); // around it all
    CHECK_FALSE(intersects(circle2{{5, 5}, __builtin_nan("")}, g));
    CHECK(contains(circle2{{5, 5}, 0x1.c48c6001f0acp2}, g)); // sqrt 50, rounded up: the corners inside
    CHECK_FALSE(contains(circle2{{5, 5}, 7}, g));
}
TEST_CASE("circle2_polygon2: oracle, random and near-degenerate", "[circle2_polygon2][oracle]") {
    support::disk_oracle<polygon2>("circle2_polygon2", support::cases(10000), approx_bound);
}
TEST_CASE("circle2_polygon2: contains", "[circle2_polygon2][oracle]") {
    support::disk_contains<polygon2>("circle2_polygon2", support::cases(10000), approx_bound);
}

} // namespace test_query_circle2_polygon2
