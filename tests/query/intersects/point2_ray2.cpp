// point2 x ray2: fixtures (points ahead of, at and behind the origin, one ulp off the ray, zero directions); the CGAL Epeck oracle (2D do_intersect / has_on, degenerate
// shapes as points) on 50,000 random and 50,000 near-degenerate cases (touching at an end point or an origin, crossing, just missing; collinear overlaps, touches and gaps, parallel lines; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, reversed, negated and doubled rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_point2_ray2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("point2_ray2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("point2_ray2: fixtures", "[point2_ray2]") {
    const ray2 r{{1, 1}, {1, 2}};
    CHECK(intersects(point2{3, 5}, r));
    CHECK(intersects(r, point2{1, 1}));         // the origin
    CHECK_FALSE(intersects(point2{-1, -3}, r)); // behind
    CHECK_FALSE(intersects(point2{3, 0x1.4000000000001p2}, r));
    CHECK(intersects(point2{1, 2}, ray2{{1, 2}, {0, 0}}));
}
TEST_CASE("point2_ray2: oracle, random and near-degenerate", "[point2_ray2][oracle]") {
    support::flat_oracle<point2, ray2>("point2_ray2", support::cases(50000), approx_bound);
}
TEST_CASE("point2_ray2: rewrites of either shape and exact translations give the same answer", "[point2_ray2]") {
    support::flat_symmetries<point2, ray2>("point2_ray2", support::cases(20000));
}

} // namespace test_query_point2_ray2
