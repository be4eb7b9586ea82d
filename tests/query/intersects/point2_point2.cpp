// point2 x point2: fixtures (equal points, signed zeros, points one subnormal apart); the CGAL Epeck oracle (2D do_intersect / has_on, degenerate
// shapes as points) on 50,000 random and 50,000 near-degenerate cases (touching at an end point or an origin, crossing, just missing; collinear overlaps, touches and gaps, parallel lines; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, reversed, negated and doubled rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_point2_point2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("point2_point2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("point2_point2: fixtures", "[point2_point2]") {
    CHECK(intersects(point2{1, 2}, point2{1, 2}));
    CHECK(intersects(point2{0.0, -0.0}, point2{-0.0, 0.0}));
    CHECK_FALSE(intersects(point2{0x1p-1074, 0}, point2{0, 0}));
}
TEST_CASE("point2_point2: oracle, random and near-degenerate", "[point2_point2][oracle]") {
    support::flat_oracle<point2, point2>("point2_point2", support::cases(50000), approx_bound);
}
TEST_CASE("point2_point2: rewrites of either shape and exact translations give the same answer", "[point2_point2]") {
    support::flat_symmetries<point2, point2>("point2_point2", support::cases(20000));
}

} // namespace test_query_point2_point2
