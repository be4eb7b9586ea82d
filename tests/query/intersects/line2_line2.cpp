// line2 x line2: fixtures (crossing, parallel, identical lines, zero directions); the CGAL Epeck oracle (2D do_intersect / has_on, degenerate
// shapes as points) on 50,000 random and 50,000 near-degenerate cases (touching at an end point or an origin, crossing, just missing; collinear overlaps, touches and gaps, parallel lines; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, reversed, negated and doubled rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_line2_line2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line2_line2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line2_line2: fixtures", "[line2_line2]") {
    const line2 l{{0, 0}, {1, 0}};
    CHECK(intersects(l, line2{{5, 1}, {1, 1}}));
    CHECK_FALSE(intersects(l, line2{{0, 1}, {2, 0}}));         // parallel
    CHECK(intersects(l, line2{{7, 0}, {-3, 0}}));              // the same line
    CHECK(intersects(l, line2{{0, 1}, {1, 0x1p-1074}}));       // barely tilted: crosses far away
    CHECK_FALSE(intersects(l, line2{{7, 0x1p-1074}, {0, 0}})); // a point a subnormal off it
}
TEST_CASE("line2_line2: CGAL 5.5's do_intersect(Line_2, Line_2) says no for crossing lines past 2^340", "[line2_line2]") {
    // Line_2_Line_2_pair gives up when is_finite fails on the double approximation of b1 c2 - b2 c1;
    // the oracle decides these pairs with exact rationals (tests/oracle/cgal_flat.cpp).
    const line2 a{{0x1p350, 0}, {0x1p350, 0}}, b{{0, 0x1p350}, {0x1p350, 0x1p350}};
    CHECK(intersects(a, b));
    CHECK(support::flat_truth(a, b));
    CHECK_FALSE(oracle::flat_do_intersect_cgal(support::to_flat(a), support::to_flat(b))); // CGAL's wrong no
}
TEST_CASE("line2_line2: oracle, random and near-degenerate", "[line2_line2][oracle]") {
    support::flat_oracle<line2, line2>("line2_line2", support::cases(50000), approx_bound);
}
TEST_CASE("line2_line2: rewrites of either shape and exact translations give the same answer", "[line2_line2]") {
    support::flat_symmetries<line2, line2>("line2_line2", support::cases(20000));
}

} // namespace test_query_line2_line2
