// line3 x triangle3: fixtures (lines through the interior, an edge or a vertex, lines in the triangle's plane, parallel lines, collinear triangles); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_line_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line_triangle"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line_triangle: fixtures", "[line_triangle]") {
    const triangle3 t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(intersects(line3{{0.25, 0.25, 5}, {0, 0, 1}}, t));                       // both sides: no start
    CHECK(intersects(line3{{0.5, 0, 5}, {0, 0, -1}}, t));                          // through an edge
    CHECK(intersects(t, line3{{1, 0, 5}, {0, 0, 3}}));                             // through a vertex
    CHECK_FALSE(intersects(line3{{0.5, 0x1.0000000000001p-1, 5}, {0, 0, -1}}, t)); // one ulp outside
    CHECK(intersects(line3{{-1, 0.5, 0}, {1, 0, 0}}, t));                          // in the plane, across
    CHECK_FALSE(intersects(line3{{-1, 0.5, 1}, {1, 0, 0}}, t));                    // parallel above
    CHECK(intersects(line3{{0, 0, 0}, {1, 1, 0}}, triangle3{{1, 1, 1}, {2, 2, 2}, {3, 3, 3}}) == false);
    CHECK(intersects(line3{{0, 0, 0}, {1, 1, 1}}, triangle3{{1, 1, 1}, {2, 2, 2}, {3, 3, 3}})); // collinear triangle on the line
}
TEST_CASE("line_triangle: oracle, random and near-degenerate", "[line_triangle][oracle]") {
    support::flat_oracle<line3, triangle3>("line_triangle", support::cases(50000), approx_bound);
}
TEST_CASE("line_triangle: rewrites of either shape and exact translations give the same answer", "[line_triangle]") {
    support::flat_symmetries<line3, triangle3>("line_triangle", support::cases(20000));
}

} // namespace test_query_line_triangle
