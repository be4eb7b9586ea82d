// line3 x ray3: fixtures (rays crossing the line, starting on it, heading away from it, collinear and parallel rays); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_line_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line_ray"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line_ray: fixtures", "[line_ray]") {
    const line3 l{{0, 0, 0}, {1, 0, 0}};
    CHECK(intersects(l, ray3{{3, 2, 0}, {0, -1, 0}}));               // heads into it
    CHECK_FALSE(intersects(l, ray3{{3, 2, 0}, {0, 1, 0}}));          // heads away
    CHECK(intersects(l, ray3{{3, 0, 0}, {0, 1, 5}}));                // starts on it
    CHECK(intersects(ray3{{-9, 0, 0}, {-1, 0, 0}}, l));              // collinear
    CHECK_FALSE(intersects(l, ray3{{0, 1, 0}, {1, 0, 0}}));          // parallel
    CHECK_FALSE(intersects(l, ray3{{3, 2, 0x1p-1074}, {0, -1, 0}})); // skew by a subnormal
}
TEST_CASE("line_ray: CGAL 5.5's do_intersect(Line_3, Ray_3) is wrong when the line's point is on the far side", "[line_ray]") {
    // The oracle uses CGAL::intersection for this pair (tests/oracle/cgal_flat.cpp).
    const line3 l{{10, 0, 0}, {1, 0, 0}};
    const ray3 r{{5, 1, 0}, {0, -1, 0}}; // hits the line at (5, 0, 0)
    CHECK(intersects(l, r));
    CHECK(support::flat_truth(l, r));
    CHECK_FALSE(oracle::flat_do_intersect_cgal(support::to_flat(l), support::to_flat(r))); // CGAL's wrong no
}
TEST_CASE("line_ray: oracle, random and near-degenerate", "[line_ray][oracle]") {
    support::flat_oracle<line3, ray3>("line_ray", support::cases(50000), approx_bound);
}
TEST_CASE("line_ray: rewrites of either shape and exact translations give the same answer", "[line_ray]") {
    support::flat_symmetries<line3, ray3>("line_ray", support::cases(20000));
}

} // namespace test_query_line_ray
