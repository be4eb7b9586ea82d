// polygon2 x ray2: fixtures (from the hole outwards, away from it, along an edge, grazing a
// vertex, through the C's notch); the CGAL Epeck oracle (the edges by do_intersect, the inside by
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

namespace test_query_polygon2_ray2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::c_shape;
using support::frame;

namespace {
const double approx_bound = catalog::approximate_bound("polygon2_ray2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("polygon2_ray2: fixtures", "[polygon2_ray2]") {
    CHECK(intersects(frame, ray2{{2, 2}, {1, 0}}));       // from the hole outwards
    CHECK(intersects(frame, ray2{{0.5, 0.5}, {-1, -1}})); // from inside
    CHECK_FALSE(intersects(frame, ray2{{5, 5}, {1, 0}}));
    CHECK(intersects(ray2{{8, 0}, {-1, 1}}, frame)); // grazes the vertex (4, 4)
    CHECK_FALSE(intersects(ray2{{0x1.0000000000001p3, 0}, {-1, 1}}, frame));
    CHECK(intersects(frame, ray2{{-1, 0}, {1, 0}}));        // along the bottom edge
    CHECK_FALSE(intersects(c_shape, ray2{{2, 2}, {1, 0}})); // out of the notch
    CHECK(intersects(c_shape, ray2{{2, 2}, {-1, 0}}));
    CHECK(intersects(frame, ray2{{0.5, 0.5}, {0, 0}})); // a zero direction: the origin
    CHECK_FALSE(intersects(frame, ray2{{2, 2}, {0, 0}}));
}
TEST_CASE("polygon2_ray2: oracle, random and near-degenerate", "[polygon2_ray2][oracle]") {
    support::polygon_oracle<ray2>("polygon2_ray2", support::cases(20000), approx_bound);
}
TEST_CASE("polygon2_ray2: rewrites of either shape and exact translations give the same answer", "[polygon2_ray2]") {
    support::polygon_symmetries<ray2>("polygon2_ray2", support::cases(20000));
}

} // namespace test_query_polygon2_ray2
