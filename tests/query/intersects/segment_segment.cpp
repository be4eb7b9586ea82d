// segment3 x segment3: fixtures (crossing and touching segments in a plane, skew segments, collinear overlaps, touches and gaps, point segments); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_segment_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("segment_segment"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("segment_segment: fixtures", "[segment_segment]") {
    const segment3 s{{0, 0, 0}, {2, 0, 0}};
    CHECK(intersects(s, segment3{{1, -1, 0}, {1, 1, 0}}));                        // crossing
    CHECK(intersects(s, segment3{{2, 0, 0}, {3, 5, 0}}));                         // end to end
    CHECK(intersects(s, segment3{{1, 0, 0}, {1, 3, 4}}));                         // end on the interior
    CHECK_FALSE(intersects(s, segment3{{1, -1, 1}, {1, 1, 1}}));                  // skew
    CHECK_FALSE(intersects(s, segment3{{0x1.0000000000001p1, 0, 0}, {3, 0, 0}})); // collinear gap of one ulp
    CHECK(intersects(s, segment3{{3, 0, 0}, {1, 0, 0}}));                         // collinear overlap
    CHECK(intersects(s, segment3{{0.5, 0, 0}, {0.5, 0, 0}}));                     // a point segment on it
    CHECK_FALSE(intersects(s, segment3{{2.5, 1, 0}, {1.5, 0x1p-60, 0}}));         // passes just above the end
}
TEST_CASE("segment_segment: oracle, random and near-degenerate", "[segment_segment][oracle]") {
    support::flat_oracle<segment3, segment3>("segment_segment", support::cases(50000), approx_bound);
}
TEST_CASE("segment_segment: rewrites of either shape and exact translations give the same answer", "[segment_segment]") {
    support::flat_symmetries<segment3, segment3>("segment_segment", support::cases(20000));
}

} // namespace test_query_segment_segment
