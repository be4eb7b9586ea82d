// segment2 x segment2: fixtures (crossing, end to end, collinear overlaps and one-ulp gaps, point segments); the CGAL Epeck oracle (2D do_intersect / has_on, degenerate
// shapes as points) on 50,000 random and 50,000 near-degenerate cases (touching at an end point or an origin, crossing, just missing; collinear overlaps, touches and gaps, parallel lines; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, reversed, negated and doubled rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_segment2_segment2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("segment2_segment2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("segment2_segment2: fixtures", "[segment2_segment2]") {
    const segment2 s{{0, 0}, {2, 0}};
    CHECK(intersects(s, segment2{{1, -1}, {1, 1}}));
    CHECK(intersects(s, segment2{{2, 0}, {3, 5}}));                                        // end to end
    CHECK_FALSE(intersects(s, segment2{{0x1.0000000000001p1, 0}, {3, 0}}));                // collinear gap of one ulp
    CHECK(intersects(s, segment2{{3, 0}, {1, 0}}));                                        // collinear overlap
    CHECK(intersects(s, segment2{{0.5, 0}, {0.5, 0}}));                                    // a point segment on it
    CHECK_FALSE(intersects(s, segment2{{1, 0x1p-1074}, {1, 1}}));                          // stops a subnormal short
    CHECK(intersects(segment2{{0.1, 0.1}, {0.3, 0.3}}, segment2{{0.1, 0.3}, {0.3, 0.1}})); // crossing at rounded coordinates
}
TEST_CASE("segment2_segment2: oracle, random and near-degenerate", "[segment2_segment2][oracle]") {
    support::flat_oracle<segment2, segment2>("segment2_segment2", support::cases(50000), approx_bound);
}
TEST_CASE("segment2_segment2: rewrites of either shape and exact translations give the same answer", "[segment2_segment2]") {
    support::flat_symmetries<segment2, segment2>("segment2_segment2", support::cases(20000));
}

} // namespace test_query_segment2_segment2
