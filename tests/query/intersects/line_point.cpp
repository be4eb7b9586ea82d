// line3 x point3: fixtures (points on the line, one ulp off it, zero directions); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_line_point { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line_point"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line_point: fixtures", "[line_point]") {
    const line3 l{{1, 1, 1}, {1, 2, 3}};
    CHECK(intersects(l, point3{3, 5, 7}));
    CHECK(intersects(point3{-1, -3, -5}, l)); // behind the origin: a line has no start
    CHECK_FALSE(intersects(l, point3{3, 5, 0x1.0000000000001p2 + 3}));
    CHECK(intersects(line3{{1, 2, 3}, {0, 0, 0}}, point3{1, 2, 3})); // zero direction: the point itself
    CHECK_FALSE(intersects(line3{{1, 2, 3}, {0, 0, 0}}, point3{1, 2, 4}));
}
TEST_CASE("line_point: oracle, random and near-degenerate", "[line_point][oracle]") {
    support::flat_oracle<line3, point3>("line_point", support::cases(50000), approx_bound);
}
TEST_CASE("line_point: rewrites of either shape and exact translations give the same answer", "[line_point]") {
    support::flat_symmetries<line3, point3>("line_point", support::cases(200000)); // about 0.2% of the cases meet
}

} // namespace test_query_line_point
