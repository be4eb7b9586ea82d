// ray3 x ray3: fixtures (rays crossing, one origin on the other ray, collinear rays facing each other or apart, parallel and skew rays); the CGAL Epeck oracle (do_intersect / has_on, degenerate
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

namespace test_query_ray_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("ray_ray"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("ray_ray: fixtures", "[ray_ray]") {
    const ray3 r{{0, 0, 0}, {1, 0, 0}};
    CHECK(intersects(r, ray3{{3, 2, 0}, {0, -1, 0}}));        // crossing
    CHECK_FALSE(intersects(r, ray3{{-3, 2, 0}, {0, -1, 0}})); // would cross behind r's origin
    CHECK(intersects(r, ray3{{5, 0, 0}, {-1, 0, 0}}));        // collinear, facing
    CHECK_FALSE(intersects(r, ray3{{-5, 0, 0}, {-1, 0, 0}})); // collinear, apart
    CHECK(intersects(r, ray3{{0, 0, 0}, {-1, 0, 0}}));        // common origin
    CHECK_FALSE(intersects(r, ray3{{0, 1, 0}, {1, 0, 0}}));   // parallel
}
TEST_CASE("ray_ray: CGAL 5.5's do_intersect(Ray_3, Ray_3) is wrong where the lines cross behind both origins", "[ray_ray]") {
    // The oracle uses CGAL::intersection for this pair (tests/oracle/cgal_flat.cpp).
    const ray3 a{{1, 0, 0}, {1, 0, 0}}, b{{0, 1, 0}, {0, 1, 0}};
    CHECK_FALSE(intersects(a, b));
    CHECK_FALSE(support::flat_truth(a, b));
    CHECK(oracle::flat_do_intersect_cgal(support::to_flat(a), support::to_flat(b))); // CGAL's wrong yes
}
TEST_CASE("ray_ray: oracle, random and near-degenerate", "[ray_ray][oracle]") {
    support::flat_oracle<ray3, ray3>("ray_ray", support::cases(50000), approx_bound);
}
TEST_CASE("ray_ray: rewrites of either shape and exact translations give the same answer", "[ray_ray]") {
    support::flat_symmetries<ray3, ray3>("ray_ray", support::cases(20000));
}

} // namespace test_query_ray_ray
