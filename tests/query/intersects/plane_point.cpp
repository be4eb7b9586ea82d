// plane3 x point3: fixtures (points on the plane from small integers, one ulp off it, zero normals); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_plane_point { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("plane_point"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("plane_point: fixtures", "[plane_point]") {
    const plane3 P{{1, 2, 3}, 6};
    CHECK(intersects(P, point3{1, 1, 1}));
    CHECK(intersects(point3{6, 0, 0}, P));
    CHECK_FALSE(intersects(P, point3{1, 1, 0x1.0000000000001p0}));
    CHECK(intersects(plane3{{0, 0, 0}, 0}, point3{5, 6, 7}));       // zero normal, zero offset: everything
    CHECK_FALSE(intersects(plane3{{0, 0, 0}, 1}, point3{5, 6, 7})); // zero normal, offset 1: nothing
}
TEST_CASE("plane_point: oracle, random and near-degenerate", "[plane_point][oracle]") {
    support::flat_oracle<plane3, point3>("plane_point", support::cases(50000), approx_bound);
}
TEST_CASE("plane_point: rewrites of either shape and exact translations give the same answer", "[plane_point]") {
    support::flat_symmetries<plane3, point3>("plane_point", support::cases(20000));
}

} // namespace test_query_plane_point
