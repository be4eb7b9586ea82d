// point3 x segment3: fixtures (points at the ends, inside, just past an end, off the segment by one ulp, point segments); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_point_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("point_segment"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("point_segment: fixtures", "[point_segment]") {
    const segment3 s{{0, 0, 0}, {4, 2, 6}};
    CHECK(intersects(point3{2, 1, 3}, s));
    CHECK(intersects(s, point3{4, 2, 6}));       // an end
    CHECK_FALSE(intersects(point3{6, 3, 9}, s)); // past the end, on the line
    CHECK_FALSE(intersects(point3{2, 1, 0x1.8000000000001p1}, s));
    CHECK(intersects(point3{1, 1, 1}, segment3{{1, 1, 1}, {1, 1, 1}}));
}
TEST_CASE("point_segment: oracle, random and near-degenerate", "[point_segment][oracle]") {
    support::flat_oracle<point3, segment3>("point_segment", support::cases(50000), approx_bound);
}
TEST_CASE("point_segment: rewrites of either shape and exact translations give the same answer", "[point_segment]") {
    support::flat_symmetries<point3, segment3>("point_segment", support::cases(200000)); // about 0.2% of the cases meet
}

} // namespace test_query_point_segment
