// point2 x polygon2: fixtures (inside, in the hole, on edges and vertices, a ray through vertices
// and along a hole's edge, one ulp off an edge, subnormal coordinates, make() refusing bad
// polygons, NaN); the CGAL Epeck oracle (the edges by do_intersect, the inside by
// Polygon_2::bounded_side per ring) on 20,000 random and 20,000 near-degenerate cases (simple
// non-convex star polygons, half with a hole; the other shape through a vertex, an edge's midpoint
// or quarter point, along the edge or not, at the centre or between the rings; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and
// reversed rings, a single ring's end listed or not, rewritten partners, exact translations.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <limits>
#include <span>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/polygon_checks.hpp"
#include "testkit/polygon_fixtures.hpp"

namespace test_query_point2_polygon2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::c_shape;
using support::frame;

namespace {
const double approx_bound = catalog::approximate_bound("point2_polygon2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("point2_polygon2: fixtures", "[point2_polygon2]") {
    CHECK(intersects(point2{0.5, 0.5}, frame));
    CHECK_FALSE(intersects(point2{2, 2}, frame));  // in the hole
    CHECK(intersects(frame, point2{1, 2}));        // on the hole's edge
    CHECK(intersects(point2{4, 4}, frame));        // a vertex
    CHECK(intersects(point2{0.5, 3}, frame));      // the ray along +x runs along the hole's top edge
    CHECK(intersects(point2{0.5, 1}, frame));      // ... and its bottom edge
    CHECK_FALSE(intersects(point2{-1, 4}, frame)); // level with the top edge, outside
    CHECK_FALSE(intersects(point2{-1, 0}, frame));
    CHECK(intersects(point2{4, 2}, frame));
    CHECK_FALSE(intersects(point2{0x1.0000000000001p2, 2}, frame)); // one ulp outside
    CHECK_FALSE(intersects(point2{3, 2}, c_shape));                 // in the notch
    CHECK(intersects(point2{3, 3.5}, c_shape));
    CHECK(contains(frame, point2{0.5, 3.5}));
    CHECK_FALSE(contains(frame, point2{2, 2}));
    // subnormal: the square [0, 2^-1072]^2, a point inside it and one just outside
    const std::array<point2, 4> tiny{{{0, 0}, {0x1p-1072, 0}, {0x1p-1072, 0x1p-1072}, {0, 0x1p-1072}}};
    CHECK(intersects(point2{0x1p-1074, 0x1p-1073}, polygon2{tiny, {}}));
    CHECK_FALSE(intersects(point2{0x1.8p-1072, 0x1p-1073}, polygon2{tiny, {}}));
    // bad input: checked make names the problem; unchecked queries say no
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::array<point2, 4> bowtie{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}};
    const std::array<point2, 4> repeated{{{0, 0}, {2, 0}, {2, 0}, {0, 2}}};
    const std::array<point2, 3> fold{{{0, 0}, {2, 0}, {1, 0}}};
    const std::array<point2, 3> with_nan{{{0, 0}, {nan, 0}, {0, 1}}};
    const std::array<point2, 6> touching{{{0, 0}, {4, 0}, {0, 4}, {1, 1}, {2, 2}, {1, 2}}}; // hole vertex (2, 2) on the outer edge
    const std::array<std::uint32_t, 2> touching_ends{{3, 6}}, bad_ends{{2, 6}}, past_end{{3, 7}};
    CHECK(polygon2::make(std::span<const point2>(support::frame_vertices), support::frame_ends).has_value());
    CHECK(polygon2::make({}, {}).error().code == errc::empty_input);
    CHECK(polygon2::make(with_nan, {}).error().code == errc::not_finite);
    CHECK(polygon2::make(bowtie, {}).error().code == errc::self_intersecting_polygon);
    CHECK(polygon2::make(repeated, {}).error().code == errc::self_intersecting_polygon);
    CHECK(polygon2::make(fold, {}).error().code == errc::self_intersecting_polygon);
    CHECK(polygon2::make(touching, touching_ends).error().code == errc::self_intersecting_polygon);
    CHECK(polygon2::make(touching, bad_ends).error().code == errc::degenerate_polygon);
    CHECK(polygon2::make(touching, past_end).error().code == errc::index_out_of_range);
    CHECK(polygon2::make(std::span<const point2>(support::c_vertices), {}).has_value());
    CHECK_FALSE(intersects(point2{0, 0.5}, polygon2{with_nan, {}}));
    CHECK_FALSE(intersects(point2{0.5, 0.5}, polygon2{support::frame_vertices, past_end}));
    CHECK_FALSE(intersects(point2{nan, 0.5}, frame));
    CHECK_FALSE(intersects(point2{0.5, std::numeric_limits<double>::infinity()}, frame));
}
TEST_CASE("point2_polygon2: oracle, random and near-degenerate", "[point2_polygon2][oracle]") {
    support::polygon_oracle<point2>("point2_polygon2", support::cases(20000), approx_bound);
}
TEST_CASE("point2_polygon2: rewrites of either shape and exact translations give the same answer", "[point2_polygon2]") {
    support::polygon_symmetries<point2>("point2_polygon2", support::cases(20000));
}

} // namespace test_query_point2_polygon2
