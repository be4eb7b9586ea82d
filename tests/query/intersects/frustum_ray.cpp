// frustum3 x ray3: fixtures; the exact LP oracle (the frustum as its half-spaces n . x <= offset) on
// 20,000 random and 20,000 near-degenerate cases (an axis-aligned integer frustum (corners dyadic) or a camera frustum (frustum3::from_camera), the ray placed through one of its
// boundary points, along a face or not; then a random exact-or-nudged scale 2^-500..2^500 and
// translation); both argument orders, rewritten shapes, exact translations of both.
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

namespace test_query_frustum_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_ray"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_ray: fixtures", "[frustum_ray]") {
    CHECK(intersects(camera, ray3{{0, 0, 0}, {0, 0, -1}}));
    CHECK_FALSE(intersects(camera, ray3{{0, 0, 0}, {0, 0, 1}}));
    CHECK(intersects(integer_frustum, ray3{{0, 0, 0}, {1, 1, 1}})); // along a side edge from the eye
    CHECK_FALSE(intersects(integer_frustum, ray3{{0, 0, 0}, {1, 1, 0x1.fffffffffffffp-1}}));
    CHECK(intersects(ray3{{8, 0, 4}, {-1, 0, 0}}, integer_frustum)); // across the far face
    CHECK_FALSE(intersects(integer_frustum, ray3{{8, 0, 0x1.0000000000001p2}, {-1, 0, 0}}));
}
TEST_CASE("frustum_ray: oracle, random and near-degenerate", "[frustum_ray][oracle]") {
    support::halfspace_oracle<frustum3, ray3>("frustum_ray", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_ray: rewrites of both shapes and exact translations give the same answer", "[frustum_ray]") {
    support::halfspace_symmetries<frustum3, ray3>("frustum_ray", support::cases(10000));
}

} // namespace test_query_frustum_ray
