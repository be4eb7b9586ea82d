// frustum3 x triangle3: fixtures (a large triangle across the integer frustum whose edges miss it, on the far face
// and one ulp beyond, through the eye, a camera frustum); the exact LP oracle (the frustum as its half-spaces
// n . x <= offset, the triangle as the hull of its corners) on 20,000 random and 20,000 near-degenerate cases (an
// axis-aligned integer frustum (corners dyadic) or a camera frustum (frustum3::from_camera), the triangle placed
// through one of its boundary points, along a face or not; then a random exact-or-nudged scale 2^-500..2^500 and
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

namespace test_query_frustum_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_triangle"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_triangle: fixtures", "[frustum_triangle]") {
    CHECK(intersects(integer_frustum, wide_triangle(2))); // the edges miss the frustum: its section lies inside
    CHECK(intersects(wide_triangle(4), integer_frustum)); // the far face
    CHECK_FALSE(intersects(integer_frustum, wide_triangle(0x1.0000000000001p2)));
    CHECK_FALSE(intersects(integer_frustum, wide_triangle(0)));                     // through the eye, before the near face
    CHECK(intersects(integer_frustum, triangle3{{4, 4, 4}, {9, 4, 4}, {4, 9, 9}})); // a corner on the far corner
    CHECK_FALSE(intersects(integer_frustum, triangle3{{0x1.0000000000001p2, 4, 4}, {9, 4, 4}, {4, 9, 9}}));
    CHECK(intersects(camera, triangle3{{-50, -50, -10}, {50, -50, -10}, {0, 50, -10}}));
    CHECK_FALSE(intersects(camera, triangle3{{-50, -50, 10}, {50, -50, 10}, {0, 50, 10}})); // behind the eye
    CHECK(contains(integer_frustum, triangle3{{1, 1, 1}, {-4, -4, 4}, {4, -4, 4}}));
    CHECK_FALSE(contains(integer_frustum, triangle3{{1, 1, 1}, {-4, -4, 4}, {4, -4, 0x1.0000000000001p2}}));
}
TEST_CASE("frustum_triangle: oracle, random and near-degenerate", "[frustum_triangle][oracle]") {
    support::halfspace_oracle<frustum3, triangle3>("frustum_triangle", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_triangle: rewrites of both shapes and exact translations give the same answer", "[frustum_triangle]") {
    support::halfspace_symmetries<frustum3, triangle3>("frustum_triangle", support::cases(5000));
}
TEST_CASE("frustum_triangle: contains", "[frustum_triangle][oracle]") {
    support::halfspace_contains_oracle<frustum3, triangle3>("frustum_triangle", support::cases(2000), approx_bound);
}

} // namespace test_query_frustum_triangle
