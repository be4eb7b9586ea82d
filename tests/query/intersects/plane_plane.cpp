// plane3 x plane3: fixtures (crossing planes, parallel planes one ulp apart, the same plane written with scaled or negated coefficients, zero normals); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_plane_plane { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("plane_plane"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("plane_plane: fixtures", "[plane_plane]") {
    const plane3 P{{0, 0, 1}, 2};
    CHECK(intersects(P, plane3{{1, 0, 0}, 7}));
    CHECK(intersects(P, plane3{{0, 0, -3}, -6}));                       // the same plane
    CHECK_FALSE(intersects(P, plane3{{0, 0, 3}, 0x1.8000000000001p2})); // parallel, one ulp apart
    CHECK(intersects(P, plane3{{0, 0x1p-1074, 1}, 0}));                 // barely tilted: they cross far away
    CHECK(intersects(P, plane3{{0, 0, 0}, 0}));                         // zero normal, zero offset: everything
    CHECK_FALSE(intersects(P, plane3{{0, 0, 0}, 1}));                   // zero normal, offset 1: nothing
    CHECK_FALSE(intersects(plane3{{0, 0, 0}, 0}, plane3{{0, 0, 0}, 1}));
}
TEST_CASE("plane_plane: oracle, random and near-degenerate", "[plane_plane][oracle]") {
    support::flat_oracle<plane3, plane3>("plane_plane", support::cases(50000), approx_bound);
}
TEST_CASE("plane_plane: rewrites of either shape and exact translations give the same answer", "[plane_plane]") {
    support::flat_symmetries<plane3, plane3>("plane_plane", support::cases(20000));
}

} // namespace test_query_plane_plane
