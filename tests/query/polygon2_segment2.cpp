// polygon2 x segment2: fixtures (inside without touching, in the hole, through the C's notch,
// touching a vertex, crossing an edge, one ulp short of an edge); the CGAL Epeck oracle (the edges by do_intersect, the inside by
// Polygon_2::bounded_side per ring) on 20,000 random and 20,000 near-degenerate cases (simple
// non-convex star polygons, half with a hole; the other shape through a vertex, an edge's midpoint
// or quarter point, along the edge or not, at the centre or between the rings; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and
// reversed rings, a single ring's end listed or not, rewritten partners, exact translations.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <limits>
#include "../oracle/cgal_oracle.hpp"
import incidence;
#include "../support/testing.hpp"
#include "../support/check.hpp"
#include "../support/flat_checks.hpp"
#include "../support/polygon_checks.hpp"
#include "../support/polygon_fixtures.hpp"

namespace test_query_polygon2_segment2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::c_shape;
using support::frame;

namespace {
constexpr double approx_bound = 0x1p-44; // stated in modules/query/polygon2_segment2.cppm
} // namespace

TEST_CASE("polygon2_segment2: fixtures", "[polygon2_segment2]") {
    CHECK(intersects(frame, segment2{{0.25, 0.25}, {0.5, 0.75}}));   // inside, touching nothing
    CHECK_FALSE(intersects(frame, segment2{{1.5, 1.5}, {2.5, 2.5}})); // in the hole
    CHECK(intersects(segment2{{1.5, 1.5}, {2.5, 3.5}}, frame));       // out of the hole
    CHECK_FALSE(intersects(c_shape, segment2{{1.5, 2}, {5, 2}}));     // through the notch
    CHECK(intersects(c_shape, segment2{{1, 2}, {5, 2}}));             // from the notch's wall
    CHECK(intersects(c_shape, segment2{{5, 5}, {4, 4}}));             // to a vertex
    CHECK_FALSE(intersects(c_shape, segment2{{5, 5}, {0x1.0000000000001p2, 4}}));
    CHECK_FALSE(intersects(frame, segment2{{0.5, 0.5}, {std::numeric_limits<double>::quiet_NaN(), 0.5}}));
}
TEST_CASE("polygon2_segment2: oracle, random and near-degenerate", "[polygon2_segment2][oracle]") {
    support::polygon_oracle<segment2>("polygon2_segment2", support::cases(20000), approx_bound);
}
TEST_CASE("polygon2_segment2: rewrites of either shape and exact translations give the same answer", "[polygon2_segment2]") {
    support::polygon_symmetries<segment2>("polygon2_segment2", support::cases(20000));
}

} // namespace test_query_polygon2_segment2
