// line3 x segment3: fixtures (segments crossing the line, ending on it, stopping short, collinear, point segments); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_line_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line_segment"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line_segment: fixtures", "[line_segment]") {
    const line3 l{{0, 0, 0}, {1, 1, 0}};
    CHECK(intersects(l, segment3{{0, 2, 0}, {2, 0, 0}}));           // crossing at (1, 1, 0)
    CHECK(intersects(l, segment3{{0, 2, 0}, {1, 1, 0}}));           // ends on it
    CHECK_FALSE(intersects(l, segment3{{0, 2, 0}, {0.5, 1.5, 0}})); // stops short
    CHECK(intersects(segment3{{5, 5, 0}, {6, 6, 0}}, l));           // collinear
    CHECK(intersects(l, segment3{{-3, -3, 0}, {-3, -3, 0}}));       // a point segment on it
    CHECK_FALSE(intersects(l, segment3{{0, 2, 1}, {2, 0, 1}}));     // skew
}
TEST_CASE("line_segment: oracle, random and near-degenerate", "[line_segment][oracle]") {
    support::flat_oracle<line3, segment3>("line_segment", support::cases(50000), approx_bound);
}
TEST_CASE("line_segment: rewrites of either shape and exact translations give the same answer", "[line_segment]") {
    support::flat_symmetries<line3, segment3>("line_segment", support::cases(20000));
}

} // namespace test_query_line_segment
