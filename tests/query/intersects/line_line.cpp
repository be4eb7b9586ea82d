// line3 x line3: fixtures (crossing, skew, parallel and identical lines, zero directions (points)); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_line_line { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line_line"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line_line: fixtures", "[line_line]") {
    const line3 l{{0, 0, 0}, {1, 0, 0}};
    CHECK(intersects(l, line3{{5, 1, 0}, {0, 1, 0}}));                                   // crossing at (5, 0, 0)
    CHECK_FALSE(intersects(l, line3{{5, 1, 1}, {0, 1, 0}}));                             // skew
    CHECK_FALSE(intersects(l, line3{{0, 1, 0}, {2, 0, 0}}));                             // parallel
    CHECK(intersects(l, line3{{7, 0, 0}, {-3, 0, 0}}));                                  // the same line
    CHECK(intersects(l, line3{{7, 0, 0}, {0, 0, 0}}));                                   // a point on it
    CHECK_FALSE(intersects(l, line3{{7, 0x1p-1074, 0}, {0, 0, 0}}));                     // a point one subnormal off it
    CHECK(intersects(line3{{0, 0, 0}, {1, 1, 1}}, line3{{1e300, 1e300, 0}, {0, 0, 1}})); // meets far away
}
TEST_CASE("line_line: oracle, random and near-degenerate", "[line_line][oracle]") {
    support::flat_oracle<line3, line3>("line_line", support::cases(50000), approx_bound);
}
TEST_CASE("line_line: rewrites of either shape and exact translations give the same answer", "[line_line]") {
    support::flat_symmetries<line3, line3>("line_line", support::cases(20000));
}

} // namespace test_query_line_line
