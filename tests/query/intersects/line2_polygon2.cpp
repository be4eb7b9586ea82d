// line2 x polygon2: fixtures (through the hole, missing, along an edge, through a vertex, a
// zero direction); the CGAL Epeck oracle (the edges by do_intersect, the inside by
// Polygon_2::bounded_side per ring) on 20,000 random and 20,000 near-degenerate cases (simple
// non-convex star polygons, half with a hole; the other shape through a vertex, an edge's midpoint
// or quarter point, along the edge or not, at the centre or between the rings; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and
// reversed rings, a single ring's end listed or not, rewritten partners, exact translations.
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

namespace test_query_line2_polygon2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::c_shape;
using support::frame;

namespace {
const double approx_bound = catalog::approximate_bound("line2_polygon2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line2_polygon2: fixtures", "[line2_polygon2]") {
    CHECK(intersects(line2{{2, 2}, {1, 1}}, frame));
    CHECK_FALSE(intersects(line2{{5, 0}, {0, 1}}, frame));
    CHECK(intersects(line2{{4, 7}, {0, 1}}, frame));  // along the right edge
    CHECK(intersects(frame, line2{{0, 8}, {1, -1}})); // through the vertex (4, 4)
    CHECK_FALSE(intersects(frame, line2{{0, 0x1.0000000000001p3}, {1, -1}}));
    CHECK(intersects(c_shape, line2{{9, 2}, {1, 0}}));   // along the notch, meets its wall
    CHECK(intersects(line2{{0.5, 0.5}, {0, 0}}, frame)); // zero direction: the origin
    CHECK_FALSE(intersects(line2{{2, 2}, {0, 0}}, frame));
}
TEST_CASE("line2_polygon2: oracle, random and near-degenerate", "[line2_polygon2][oracle]") {
    support::polygon_oracle<line2>("line2_polygon2", support::cases(20000), approx_bound);
}
TEST_CASE("line2_polygon2: rewrites of either shape and exact translations give the same answer", "[line2_polygon2]") {
    support::polygon_symmetries<line2>("line2_polygon2", support::cases(20000));
}

} // namespace test_query_line2_polygon2
