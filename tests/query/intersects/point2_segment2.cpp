// point2 x segment2: fixtures (points at the ends, inside, just past an end, one ulp off, point segments); the CGAL Epeck oracle (2D do_intersect / has_on, degenerate
// shapes as points) on 50,000 random and 50,000 near-degenerate cases (touching at an end point or an origin, crossing, just missing; collinear overlaps, touches and gaps, parallel lines; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, reversed, negated and doubled rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_point2_segment2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("point2_segment2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("point2_segment2: fixtures", "[point2_segment2]") {
    const segment2 s{{0, 0}, {4, 2}};
    CHECK(intersects(point2{2, 1}, s));
    CHECK(intersects(s, point2{4, 2}));
    CHECK_FALSE(intersects(point2{6, 3}, s)); // past the end, on the line
    CHECK_FALSE(intersects(point2{2, 0x1.0000000000001p0}, s));
    CHECK(intersects(point2{1, 1}, segment2{{1, 1}, {1, 1}}));
}
TEST_CASE("point2_segment2: oracle, random and near-degenerate", "[point2_segment2][oracle]") {
    support::flat_oracle<point2, segment2>("point2_segment2", support::cases(50000), approx_bound);
}
TEST_CASE("point2_segment2: rewrites of either shape and exact translations give the same answer", "[point2_segment2]") {
    support::flat_symmetries<point2, segment2>("point2_segment2", support::cases(20000));
}

} // namespace test_query_point2_segment2
