// point3 x ray3: fixtures (points ahead of, at and just behind the origin, off the ray by one ulp, zero directions); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_point_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("point_ray"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("point_ray: fixtures", "[point_ray]") {
    const ray3 r{{1, 1, 1}, {1, 2, 3}};
    CHECK(intersects(point3{3, 5, 7}, r));
    CHECK(intersects(r, point3{1, 1, 1}));          // the origin
    CHECK_FALSE(intersects(point3{-1, -3, -5}, r)); // behind the origin
    CHECK_FALSE(intersects(point3{3, 5, 0x1.c000000000001p2}, r));
    CHECK(intersects(point3{1, 2, 3}, ray3{{1, 2, 3}, {0, 0, 0}})); // zero direction: its origin
}
TEST_CASE("point_ray: oracle, random and near-degenerate", "[point_ray][oracle]") {
    support::flat_oracle<point3, ray3>("point_ray", support::cases(50000), approx_bound);
}
TEST_CASE("point_ray: rewrites of either shape and exact translations give the same answer", "[point_ray]") {
    support::flat_symmetries<point3, ray3>("point_ray", support::cases(200000)); // about 0.2% of the cases meet
}

} // namespace test_query_point_ray
