// circle2 x polygon2: fixtures (a square with a square hole: a disk tangent to an outer edge by a
// 3-4-5 step and one ulp short, a disk in the hole touching its edges and one ulp smaller, a disk
// inside the polygon's ring, a disk around the whole polygon); every tier against CGAL (the centre
// in the polygon's set by Polygon_2 over Epeck, oracle::polygon_intersect, or an edge within the
// radius by the squared distance over Epeck) on 10,000 random and 10,000 near-degenerate cases
// (disks across a star polygon's edges at its vertices, midpoints and quarter points, or around
// its centre and between its rings, radii nudged by ulps, halved or doubled, at a random scale;
// testkit/circle2_cases.hpp); and contains(circle2, polygon2) (the radius the farthest vertex's
// distance, rounded, or a little more) against exact rationals; contains(polygon2, circle2):
// fixtures (the incircle of a 6-8-10 triangle and one ulp more, disks touching the square's edges
// and its hole from inside, a zero radius on an edge; rings that are not simple: a slit inside the
// square, an antenna outside it, two squares sharing part of an edge, where only the boundary
// covered an odd number of times separates inside from outside), and 10,000 random and 10,000
// disks in a star polygon of radius the distance to the nearest edge, rounded, nudged, halved or
// grown, against the centre by Polygon_2 and no edge strictly within the radius by CGAL's squared
// distance over Epeck (testkit/circle2_cases.hpp, disk_in_star).
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

TEST_CASE("circle2_polygon2: a polygon holding a disk, fixtures", "[circle2_polygon2]") {
    const std::vector<point2> tri{{0, 0}, {8, 0}, {0, 6}}; // its incircle: centre (2, 2), radius 2
    CHECK(contains(polygon2{tri, {}}, circle2{{2, 2}, 2}));
    CHECK(contains<conservative>(polygon2{tri, {}}, circle2{{2, 2}, -2})); // a negative radius acts as its size
    CHECK_FALSE(contains(polygon2{tri, {}}, circle2{{2, 2}, 0x1.0000000000001p1}));
    CHECK_FALSE(contains<aggressive>(polygon2{tri, {}}, circle2{{2, 2}, 0x1.0000000000001p1}));
    CHECK(classify_contains(polygon2{tri, {}}, circle2{{2, 2}, 1}) == certainty::yes);
    // [0, 10]^2 with the hole [4, 6]^2
    const std::vector<point2> v{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {4, 6}, {6, 6}, {6, 4}};
    const std::vector<std::uint32_t> ends{4, 8};
    const polygon2 g{v, ends};
    CHECK(contains(g, circle2{{2, 2}, 2}));
    CHECK_FALSE(contains(g, circle2{{2, 2}, 0x1.0000000000001p1}));
    CHECK(contains(g, circle2{{2, 5}, 2}));         // touching the outer edge and the hole's
    CHECK_FALSE(contains(g, circle2{{5, 5}, 0.5})); // in the hole
    CHECK_FALSE(contains(g, circle2{{5, 5}, 3}));   // around the hole
    CHECK(contains(g, circle2{{0, 5}, 0}));         // a point on an edge
    CHECK_FALSE(contains(g, circle2{{0, 5}, 0x1p-1074}));
    CHECK_FALSE(contains(g, circle2{{11, 5}, 0}));
    CHECK_FALSE(contains(g, circle2{{2, 2}, __builtin_nan("")}));
    CHECK_FALSE(contains(g, circle2{{2, __builtin_inf()}, 1}));
    CHECK_FALSE(contains(polygon2{v, std::vector<std::uint32_t>{4, 9}}, circle2{{2, 2}, 1})); // bad ring ends: no set
    // a slit into the square along y = 5, there and back: evenly covered, inside on both sides
    const std::vector<point2> slit{{0, 0}, {10, 0}, {10, 5}, {5, 5}, {10, 5}, {10, 10}, {0, 10}};
    CHECK(contains(polygon2{slit, {}}, circle2{{5, 5}, 1})); // the centre on the slit's end
    CHECK(contains(polygon2{slit, {}}, circle2{{7, 5}, 1}));
    CHECK_FALSE(contains(polygon2{slit, {}}, circle2{{9, 5}, 2}));
    // an antenna out of the square along y = 5: its points are in the set, the disk around it not
    const std::vector<point2> antenna{{0, 0}, {10, 0}, {10, 5}, {15, 5}, {10, 5}, {10, 10}, {0, 10}};
    CHECK_FALSE(contains(polygon2{antenna, {}}, circle2{{10, 5}, 1}));
    CHECK_FALSE(contains(polygon2{antenna, {}}, circle2{{12, 5}, 0.5}));
    CHECK(contains(polygon2{antenna, {}}, circle2{{12, 5}, 0}));
    CHECK(contains(polygon2{antenna, {}}, circle2{{8, 5}, 2})); // touching x = 10 where the antenna leaves
    CHECK(intersects(polygon2{antenna, {}}, circle2{{12, 5}, 0.5}));
    // [0, 10]^2 and [10, 20] x [2, 12]: x = 10 is covered twice for 2 <= y <= 10, once below and above
    const std::vector<point2> pair{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {10, 2}, {20, 2}, {20, 12}, {10, 12}};
    const polygon2 two{pair, ends};
    CHECK(contains(two, circle2{{10, 5}, 2}));
    CHECK(contains(two, circle2{{10, 5}, 3})); // touching y = 2 at (10, 2)
    CHECK_FALSE(contains(two, circle2{{10, 5}, 0x1.8000000000001p1}));
    CHECK_FALSE(contains<aggressive>(two, circle2{{10, 5}, 3.5}));
    CHECK(contains<conservative>(two, circle2{{10, 7}, 3}));
    CHECK_FALSE(contains(two, circle2{{10, 7}, 0x1.8000000000001p1}));
    CHECK(contains<approximate>(two, circle2{{10, 6}, 1}));
}
TEST_CASE("circle2_polygon2: a polygon holding a disk", "[circle2_polygon2][oracle]") {
    support::polygon_holds_disk("circle2_polygon2", support::cases(10000), approx_bound);
}

} // namespace test_query_circle2_polygon2
