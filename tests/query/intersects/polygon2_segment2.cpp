// polygon2 x segment2: fixtures (inside without touching, in the hole, through the C's notch,
// touching a vertex, crossing an edge, one ulp short of an edge); the CGAL Epeck oracle (the edges by do_intersect, the inside by
// Polygon_2::bounded_side per ring) on 20,000 random and 20,000 near-degenerate cases (simple
// non-convex star polygons, half with a hole; the other shape through a vertex, an edge's midpoint
// or quarter point, along the edge or not, at the centre or between the rings; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and
// reversed rings, a single ring's end listed or not, rewritten partners, exact translations.
// contains(polygon, segment): fixtures (along the frame's strip, along the hole's edges, across
// the hole, into the C's notch and along its walls, one ulp past the outer edge); the CGAL Epeck
// oracle (the segment split at its exact intersections with every edge, each piece's midpoint on
// an edge or on the bounded side of an odd number of rings) on 10,000 random and 10,000
// near-degenerate cases (support/polygon_cases.hpp: segment_in_polygon_near, _random).
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/polygon_checks.hpp"
#include "testkit/polygon_fixtures.hpp"

namespace test_query_polygon2_segment2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::c_shape;
using support::frame;

namespace {
const double approx_bound = catalog::approximate_bound("polygon2_segment2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("polygon2_segment2: fixtures", "[polygon2_segment2]") {
    CHECK(intersects(frame, segment2{{0.25, 0.25}, {0.5, 0.75}}));    // inside, touching nothing
    CHECK_FALSE(intersects(frame, segment2{{1.5, 1.5}, {2.5, 2.5}})); // in the hole
    CHECK(intersects(segment2{{1.5, 1.5}, {2.5, 3.5}}, frame));       // out of the hole
    CHECK_FALSE(intersects(c_shape, segment2{{1.5, 2}, {5, 2}}));     // through the notch
    CHECK(intersects(c_shape, segment2{{1, 2}, {5, 2}}));             // from the notch's wall
    CHECK(intersects(c_shape, segment2{{5, 5}, {4, 4}}));             // to a vertex
    CHECK_FALSE(intersects(c_shape, segment2{{5, 5}, {0x1.0000000000001p2, 4}}));
    CHECK_FALSE(intersects(frame, segment2{{0.5, 0.5}, {std::numeric_limits<double>::quiet_NaN(), 0.5}}));
}
TEST_CASE("polygon2_segment2: contains, fixtures", "[polygon2_segment2]") {
    CHECK(contains(frame, segment2{{0.25, 0.25}, {0.5, 3.75}}));    // in the left strip
    CHECK_FALSE(contains(frame, segment2{{0.5, 0.5}, {3.5, 3.5}})); // across the hole
    CHECK(contains(frame, segment2{{0, 0}, {4, 0}}));               // an outer edge
    CHECK(contains(frame, segment2{{1, 1}, {1, 3}}));               // the hole's edge
    CHECK(contains(frame, segment2{{0.5, 1}, {3.5, 1}}));           // along the hole's bottom edge
    CHECK_FALSE(contains(frame, segment2{{0.5, 1.5}, {3.5, 1.5}}));
    CHECK(contains(frame, segment2{{0.5, 0.5}, {0.5, 4}}));
    CHECK_FALSE(contains(frame, segment2{{0.5, 0.5}, {0.5, 0x1.0000000000001p2}})); // one ulp past the top edge
    CHECK(contains(frame, segment2{{0.5, 0.5}, {0.5, 0.5}}));
    CHECK_FALSE(contains(frame, segment2{{2, 2}, {2, 2}}));
    CHECK(contains(c_shape, segment2{{0.5, 0.5}, {0.5, 3.5}}));
    CHECK_FALSE(contains(c_shape, segment2{{0.5, 2}, {2, 2}})); // into the notch
    CHECK(contains(c_shape, segment2{{0.5, 1}, {3, 1}}));       // along the notch's floor
    CHECK(contains(c_shape, segment2{{1, 1}, {1, 3}}));         // its wall
    CHECK(contains<conservative>(frame, segment2{{0.25, 0.25}, {0.5, 3.75}}));
    CHECK_FALSE(contains<aggressive>(frame, segment2{{0.5, 0.5}, {3.5, 3.5}}));
    CHECK_FALSE(contains(frame, segment2{{0.5, 0.5}, {std::numeric_limits<double>::quiet_NaN(), 0.5}}));
}
TEST_CASE("polygon2_segment2: contains against the oracle, random and near-degenerate", "[polygon2_segment2][oracle]") {
    support::polygon_store store;
    support::contains_oracle_cases(
        "polygon2_segment2", support::cases(10000), approx_bound,
        [&](support::rng& r, bool near) -> std::optional<std::pair<polygon2, segment2>> {
            const segment2 s = near ? support::segment_in_polygon_near(r, store) : support::segment_in_polygon_random(r, store);
            if (!support::finite_shape(s) || !support::polygon_store_finite(store)) return std::nullopt;
            return std::pair{store.view(), s};
        },
        [](const polygon2& g, const segment2& s) { return support::segment_in_polygon_truth(g, s); },
        [](const polygon2& g, const segment2& s) { return support::shape_str(g) + " " + support::shape_str(s); });
}
TEST_CASE("polygon2_segment2: oracle, random and near-degenerate", "[polygon2_segment2][oracle]") {
    support::polygon_oracle<segment2>("polygon2_segment2", support::cases(20000), approx_bound);
}
TEST_CASE("polygon2_segment2: rewrites of either shape and exact translations give the same answer", "[polygon2_segment2]") {
    support::polygon_symmetries<segment2>("polygon2_segment2", support::cases(20000));
}

} // namespace test_query_polygon2_segment2
