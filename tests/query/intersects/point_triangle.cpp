// point3 x triangle3: fixtures (points at vertices, on edges, inside, one ulp outside or above, collinear triangles); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_point_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("point_triangle"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("point_triangle: fixtures", "[point_triangle]") {
    const triangle3 t{{0, 0, 0}, {4, 0, 0}, {0, 4, 4}};
    CHECK(intersects(point3{1, 1, 1}, t));
    CHECK(intersects(t, point3{2, 2, 2}));                                          // on the edge b c
    CHECK(intersects(point3{4, 0, 0}, t));                                          // a vertex
    CHECK_FALSE(intersects(point3{2, 0x1.0000000000001p1, 2}, t));                  // one ulp off the plane
    CHECK_FALSE(intersects(point3{-0x1p-1074, 0, 0}, t));                           // a subnormal outside
    CHECK(intersects(point3{1, 1, 1}, triangle3{{0, 0, 0}, {2, 2, 2}, {3, 3, 3}})); // collinear triangle
    CHECK_FALSE(intersects(point3{4, 4, 4}, triangle3{{0, 0, 0}, {2, 2, 2}, {3, 3, 3}}));
}
TEST_CASE("point_triangle: oracle, random and near-degenerate", "[point_triangle][oracle]") {
    support::flat_oracle<point3, triangle3>("point_triangle", support::cases(50000), approx_bound);
}
TEST_CASE("point_triangle: rewrites of either shape and exact translations give the same answer", "[point_triangle]") {
    support::flat_symmetries<point3, triangle3>("point_triangle", support::cases(20000));
}

} // namespace test_query_point_triangle
