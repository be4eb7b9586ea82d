// frustum3 x point3: fixtures; the exact LP oracle (the frustum as its half-spaces n . x <= offset) on
// 20,000 random and 20,000 near-degenerate cases (an axis-aligned integer frustum (corners dyadic) or a camera frustum (frustum3::from_camera), the point placed through one of its
// boundary points, along a face or not; then a random exact-or-nudged scale 2^-500..2^500 and
// translation); both argument orders, rewritten shapes, exact translations of both; contains.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/polyhedron_cases.hpp"
#include "testkit/polyhedron_checks.hpp"
#include "testkit/polyhedron_fixtures.hpp"

namespace test_query_frustum_point { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_point"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_point: fixtures", "[frustum_point]") {
    CHECK(intersects(camera, point3{0, 0, -5}));
    CHECK(intersects(point3{0, 0, -1}, camera)); // on the near plane
    CHECK_FALSE(intersects(camera, point3{0, 0, -0x1.fffffffffffffp-1}));
    CHECK(intersects(integer_frustum, point3{1, 1, 1})); // a near corner
    CHECK_FALSE(intersects(integer_frustum, point3{0x1.0000000000001p0, 1, 1}));
    CHECK(intersects(integer_frustum, point3{4, -4, 4}));      // a far corner
    CHECK_FALSE(intersects(integer_frustum, point3{0, 0, 0})); // the eye, apex of the sides
    CHECK(contains(integer_frustum, point3{0, 0.5, 2}));
}
TEST_CASE("frustum_point: oracle, random and near-degenerate", "[frustum_point][oracle]") {
    support::halfspace_oracle<frustum3, point3>("frustum_point", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_point: rewrites of both shapes and exact translations give the same answer", "[frustum_point]") {
    support::halfspace_symmetries<frustum3, point3>("frustum_point", support::cases(10000));
}
TEST_CASE("frustum_point: contains", "[frustum_point][oracle]") {
    support::halfspace_contains_oracle<frustum3, point3>("frustum_point", support::cases(2000), approx_bound);
}

} // namespace test_query_frustum_point
