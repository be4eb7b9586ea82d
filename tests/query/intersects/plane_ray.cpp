// plane3 x ray3: fixtures (rays heading to or away from the plane, starting on it, lying in it, parallel, zero normals and directions); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_plane_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("plane_ray"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("plane_ray: fixtures", "[plane_ray]") {
    const plane3 P{{0, 0, 1}, 2};
    CHECK(intersects(P, ray3{{0, 0, 0}, {1, 1, 1}}));
    CHECK_FALSE(intersects(P, ray3{{0, 0, 0}, {1, 1, -1}}));  // heads away
    CHECK(intersects(ray3{{5, 5, 2}, {1, 1, -1}}, P));        // starts on it
    CHECK(intersects(P, ray3{{0, 0, 2}, {1, 0, 0}}));         // in it
    CHECK_FALSE(intersects(P, ray3{{0, 0, 1}, {1, 0, 0}}));   // parallel below
    CHECK(intersects(P, ray3{{0, 0, 0}, {1, 0, 0x1p-1074}})); // a subnormal climb reaches it
    CHECK_FALSE(intersects(P, ray3{{0, 0, 3}, {0, 0, 0}}));   // a point above
}
TEST_CASE("plane_ray: oracle, random and near-degenerate", "[plane_ray][oracle]") {
    support::flat_oracle<plane3, ray3>("plane_ray", support::cases(50000), approx_bound);
}
TEST_CASE("plane_ray: rewrites of either shape and exact translations give the same answer", "[plane_ray]") {
    support::flat_symmetries<plane3, ray3>("plane_ray", support::cases(20000));
}

} // namespace test_query_plane_ray
