// ray3 x segment3: fixtures (segments crossing the ray, behind its origin, ending on it, collinear ahead and behind, point segments); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_ray_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("ray_segment"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("ray_segment: fixtures", "[ray_segment]") {
    const ray3 r{{0, 0, 0}, {1, 1, 0}};
    CHECK(intersects(r, segment3{{0, 4, 0}, {4, 0, 0}}));
    CHECK_FALSE(intersects(r, segment3{{0, -4, 0}, {-4, 0, 0}}));               // behind the origin
    CHECK(intersects(segment3{{0, 0, 0}, {0, -4, 0}}, r));                      // ends at the origin
    CHECK(intersects(r, segment3{{-1, -1, 0}, {1, 1, 0}}));                     // collinear, across the origin
    CHECK_FALSE(intersects(r, segment3{{-1, -1, 0}, {-0.5, -0.5, 0}}));         // collinear, behind
    CHECK_FALSE(intersects(r, segment3{{0, 4, 0x1p-1074}, {4, 0, 0x1p-1074}})); // a subnormal above
}
TEST_CASE("ray_segment: oracle, random and near-degenerate", "[ray_segment][oracle]") {
    support::flat_oracle<ray3, segment3>("ray_segment", support::cases(50000), approx_bound);
}
TEST_CASE("ray_segment: rewrites of either shape and exact translations give the same answer", "[ray_segment]") {
    support::flat_symmetries<ray3, segment3>("ray_segment", support::cases(20000));
}

} // namespace test_query_ray_segment
