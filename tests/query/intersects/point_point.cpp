// point3 x point3: fixtures (equal points, points one ulp or one subnormal apart, signed zeros); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_point_point { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("point_point"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("point_point: fixtures", "[point_point]") {
    CHECK(intersects(point3{1, 2, 3}, point3{1, 2, 3}));
    CHECK(intersects(point3{0.0, -0.0, 0}, point3{-0.0, 0.0, 0})); // signed zeros are one value
    CHECK_FALSE(intersects(point3{1, 2, 3}, point3{1, 2, 0x1.8000000000001p1}));
    CHECK_FALSE(intersects(point3{0x1p-1074, 0, 0}, point3{0, 0, 0}));
}
TEST_CASE("point_point: oracle, random and near-degenerate", "[point_point][oracle]") {
    support::flat_oracle<point3, point3>("point_point", support::cases(50000), approx_bound);
}
TEST_CASE("point_point: rewrites of either shape and exact translations give the same answer", "[point_point]") {
    support::flat_symmetries<point3, point3>("point_point", support::cases(200000)); // about 0.2% of the cases meet
}

} // namespace test_query_point_point
