// ray2 x ray2: fixtures (rays crossing, crossing behind an origin, collinear facing or apart, common origins, parallel); the CGAL Epeck oracle (2D do_intersect / has_on, degenerate
// shapes as points) on 50,000 random and 50,000 near-degenerate cases (touching at an end point or an origin, crossing, just missing; collinear overlaps, touches and gaps, parallel lines; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, reversed, negated and doubled rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_ray2_ray2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("ray2_ray2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("ray2_ray2: fixtures", "[ray2_ray2]") {
    const ray2 r{{0, 0}, {1, 0}};
    CHECK(intersects(r, ray2{{3, 2}, {0, -1}}));
    CHECK_FALSE(intersects(r, ray2{{-3, 2}, {0, -1}}));                  // behind r's origin
    CHECK_FALSE(intersects(ray2{{1, 0}, {1, 0}}, ray2{{0, 1}, {0, 1}})); // the lines cross behind both
    CHECK(intersects(r, ray2{{5, 0}, {-1, 0}}));                         // collinear, facing
    CHECK_FALSE(intersects(r, ray2{{-5, 0}, {-1, 0}}));                  // collinear, apart
    CHECK(intersects(r, ray2{{0, 0}, {-1, 0}}));                         // common origin
}
TEST_CASE("ray2_ray2: oracle, random and near-degenerate", "[ray2_ray2][oracle]") {
    support::flat_oracle<ray2, ray2>("ray2_ray2", support::cases(50000), approx_bound);
}
TEST_CASE("ray2_ray2: rewrites of either shape and exact translations give the same answer", "[ray2_ray2]") {
    support::flat_symmetries<ray2, ray2>("ray2_ray2", support::cases(20000));
}

} // namespace test_query_ray2_ray2
