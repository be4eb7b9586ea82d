// ray2 x segment2: fixtures (segments crossing the ray, behind its origin, ending on it, collinear ahead and behind); the CGAL Epeck oracle (2D do_intersect / has_on, degenerate
// shapes as points) on 50,000 random and 50,000 near-degenerate cases (touching at an end point or an origin, crossing, just missing; collinear overlaps, touches and gaps, parallel lines; degenerate shapes; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, reversed, negated and doubled rewrites, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"

namespace test_query_ray2_segment2 { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("ray2_segment2"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("ray2_segment2: fixtures", "[ray2_segment2]") {
    const ray2 r{{0, 0}, {1, 1}};
    CHECK(intersects(r, segment2{{0, 4}, {4, 0}}));
    CHECK_FALSE(intersects(r, segment2{{0, -4}, {-4, 0}}));       // behind the origin
    CHECK(intersects(segment2{{0, 0}, {0, -4}}, r));              // ends at the origin
    CHECK(intersects(r, segment2{{-1, -1}, {1, 1}}));             // collinear, across the origin
    CHECK_FALSE(intersects(r, segment2{{-1, -1}, {-0.5, -0.5}})); // collinear, behind
}
TEST_CASE("ray2_segment2: oracle, random and near-degenerate", "[ray2_segment2][oracle]") {
    support::flat_oracle<ray2, segment2>("ray2_segment2", support::cases(50000), approx_bound);
}
TEST_CASE("ray2_segment2: rewrites of either shape and exact translations give the same answer", "[ray2_segment2]") {
    support::flat_symmetries<ray2, segment2>("ray2_segment2", support::cases(20000));
}

} // namespace test_query_ray2_segment2
