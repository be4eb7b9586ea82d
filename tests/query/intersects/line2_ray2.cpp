// line2 x ray2: fixtures (rays heading into or away from the line, starting on it, collinear and parallel); the CGAL Epeck oracle (2D do_intersect / has_on, degenerate
// shapes as points) on 50,000 random and 50,000 near-degenerate cases (touching at an end point or an origin, crossing, just missing; collinear overlaps, touches and gaps, parallel lines; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, reversed, negated and doubled rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_line2_ray2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line2_ray2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line2_ray2: fixtures", "[line2_ray2]") {
    const line2 l{{10, 0}, {1, 0}};
    CHECK(intersects(l, ray2{{5, 1}, {0, -1}}));      // the line's point on the far side
    CHECK_FALSE(intersects(l, ray2{{5, 1}, {0, 1}})); // heads away
    CHECK(intersects(l, ray2{{5, 0}, {3, 3}}));       // starts on it
    CHECK(intersects(ray2{{-9, 0}, {-1, 0}}, l));     // collinear
    CHECK_FALSE(intersects(l, ray2{{0, 1}, {1, 0}})); // parallel
}
TEST_CASE("line2_ray2: oracle, random and near-degenerate", "[line2_ray2][oracle]") {
    support::flat_oracle<line2, ray2>("line2_ray2", support::cases(50000), approx_bound);
}
TEST_CASE("line2_ray2: rewrites of either shape and exact translations give the same answer", "[line2_ray2]") {
    support::flat_symmetries<line2, ray2>("line2_ray2", support::cases(20000));
}

} // namespace test_query_line2_ray2
