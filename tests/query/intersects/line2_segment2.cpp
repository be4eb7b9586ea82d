// line2 x segment2: fixtures (segments crossing the line, ending on it, stopping short, collinear, point segments); the CGAL Epeck oracle (2D do_intersect / has_on, degenerate
// shapes as points) on 50,000 random and 50,000 near-degenerate cases (touching at an end point or an origin, crossing, just missing; collinear overlaps, touches and gaps, parallel lines; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, reversed, negated and doubled rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_line2_segment2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line2_segment2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line2_segment2: fixtures", "[line2_segment2]") {
    const line2 l{{0, 0}, {1, 1}};
    CHECK(intersects(l, segment2{{0, 2}, {2, 0}}));
    CHECK(intersects(l, segment2{{0, 2}, {1, 1}}));           // ends on it
    CHECK_FALSE(intersects(l, segment2{{0, 2}, {0.5, 1.5}})); // stops short
    CHECK(intersects(segment2{{5, 5}, {6, 6}}, l));           // collinear
    CHECK(intersects(l, segment2{{-3, -3}, {-3, -3}}));
}
TEST_CASE("line2_segment2: oracle, random and near-degenerate", "[line2_segment2][oracle]") {
    support::flat_oracle<line2, segment2>("line2_segment2", support::cases(50000), approx_bound);
}
TEST_CASE("line2_segment2: rewrites of either shape and exact translations give the same answer", "[line2_segment2]") {
    support::flat_symmetries<line2, segment2>("line2_segment2", support::cases(20000));
}

} // namespace test_query_line2_segment2
