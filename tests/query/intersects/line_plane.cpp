// line3 x plane3: fixtures (lines crossing the plane, lying in it, parallel one ulp off it, zero normals and directions); the CGAL Epeck oracle (do_intersect / has_on, degenerate
// shapes as their point sets) on 50,000 random cases (half of them in one plane) and 50,000
// near-degenerate cases (touching at an end point, an origin, a vertex or an edge point, crossing, just missing; collinear, parallel and coplanar configurations; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, reversed, negated and doubled
// rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_line_plane { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line_plane"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line_plane: fixtures", "[line_plane]") {
    const plane3 P{{0, 0, 1}, 2};
    CHECK(intersects(line3{{0, 0, 0}, {1, 1, 1}}, P));
    CHECK(intersects(P, line3{{0, 0, 2}, {1, 1, 0}}));                         // in the plane
    CHECK_FALSE(intersects(line3{{0, 0, 0x1.0000000000001p1}, {1, 1, 0}}, P)); // parallel, one ulp above
    CHECK(intersects(line3{{0, 0, 0}, {1, 0, 0x1p-1074}}, P));                 // nearly parallel still crosses
    CHECK_FALSE(intersects(line3{{0, 0, 0}, {0, 0, 0}}, P));                   // a point off the plane
    CHECK(intersects(line3{{0, 0, 0}, {1, 0, 0}}, plane3{{0, 0, 0}, 0}));
    CHECK_FALSE(intersects(line3{{0, 0, 0}, {1, 0, 0}}, plane3{{0, 0, 0}, 1}));
}
TEST_CASE("line_plane: oracle, random and near-degenerate", "[line_plane][oracle]") {
    support::flat_oracle<line3, plane3>("line_plane", support::cases(50000), approx_bound);
}
TEST_CASE("line_plane: rewrites of either shape and exact translations give the same answer", "[line_plane]") {
    support::flat_symmetries<line3, plane3>("line_plane", support::cases(20000));
}

} // namespace test_query_line_plane
