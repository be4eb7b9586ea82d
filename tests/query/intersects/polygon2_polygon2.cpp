// polygon2 x polygon2: fixtures (one in the other's hole, around it, touching at a vertex,
// one ulp apart, nested C shapes); the CGAL Epeck oracle (the edges by do_intersect, the inside by
// Polygon_2::bounded_side per ring) on 20,000 random and 20,000 near-degenerate cases (simple
// non-convex star polygons, half with a hole; the second with a ring point at a vertex, an edge's
// midpoint or quarter point of the first's; then a random exact-or-nudged scale 2^-500..2^500 and
// translation); both argument orders, rotated and reversed rings, a single ring's end listed or
// not, exact translations.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <limits>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/polygon_checks.hpp"
#include "testkit/polygon_fixtures.hpp"

namespace test_query_polygon2_polygon2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::c_shape;
using support::frame;

namespace {
const double approx_bound = catalog::approximate_bound("polygon2_polygon2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("polygon2_polygon2: fixtures", "[polygon2_polygon2]") {
    const std::array<point2, 3> in_hole{{{1.5, 1.5}, {2.5, 1.5}, {2, 2.5}}};
    const std::array<point2, 4> around{{{-1, -1}, {5, -1}, {5, 5}, {-1, 5}}};
    const std::array<point2, 3> at_vertex{{{4, 4}, {5, 4}, {5, 5}}};
    const std::array<point2, 3> one_ulp{{{0x1.0000000000001p2, 4}, {5, 4}, {5, 5}}};
    const std::array<point2, 4> in_notch{{{1.5, 1.5}, {3, 1.5}, {3, 2.5}, {1.5, 2.5}}};
    CHECK_FALSE(intersects(frame, polygon2{in_hole, {}}));
    CHECK(intersects(polygon2{around, {}}, frame));
    CHECK(intersects(frame, polygon2{around, {}}));
    CHECK(intersects(frame, polygon2{at_vertex, {}}));
    CHECK_FALSE(intersects(frame, polygon2{one_ulp, {}}));
    CHECK_FALSE(intersects(c_shape, polygon2{in_notch, {}}));
    CHECK(intersects(frame, frame));
}
TEST_CASE("polygon2_polygon2: oracle, random and near-degenerate", "[polygon2_polygon2][oracle]") {
    support::polygon_oracle<polygon2>("polygon2_polygon2", support::cases(20000), approx_bound);
}
TEST_CASE("polygon2_polygon2: rewrites of either shape and exact translations give the same answer", "[polygon2_polygon2]") {
    support::polygon_symmetries<polygon2>("polygon2_polygon2", support::cases(20000));
}

} // namespace test_query_polygon2_polygon2
