// line2 x point2: fixtures (points on the line, one ulp off it, zero directions); the CGAL Epeck oracle (2D do_intersect / has_on, degenerate
// shapes as points) on 50,000 random and 50,000 near-degenerate cases (touching at an end point or an origin, crossing, just missing; collinear overlaps, touches and gaps, parallel lines; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, reversed, negated and doubled rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_line2_point2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line2_point2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line2_point2: fixtures", "[line2_point2]") {
    const line2 l{{1, 1}, {1, 2}};
    CHECK(intersects(l, point2{3, 5}));
    CHECK(intersects(point2{-1, -3}, l));
    CHECK_FALSE(intersects(l, point2{3, 0x1.4000000000001p2}));
    CHECK(intersects(line2{{1, 2}, {0, 0}}, point2{1, 2}));
}
TEST_CASE("line2_point2: oracle, random and near-degenerate", "[line2_point2][oracle]") {
    support::flat_oracle<line2, point2>("line2_point2", support::cases(50000), approx_bound);
}
TEST_CASE("line2_point2: rewrites of either shape and exact translations give the same answer", "[line2_point2]") {
    support::flat_symmetries<line2, point2>("line2_point2", support::cases(20000));
}

} // namespace test_query_line2_point2
