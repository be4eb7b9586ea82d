// frustum3 x plane3: fixtures (the near and far faces' planes and one ulp beyond, a far edge's and a far corner's
// supporting planes, a camera frustum); the exact LP oracle (the frustum as its half-spaces n . x <= offset, the plane
// as an equality) on 20,000 random and 20,000 near-degenerate cases (an axis-aligned integer frustum (corners dyadic)
// or a camera frustum (frustum3::from_camera), the plane through one of its boundary points: a face's own plane, or
// containing a direction along the face, or any; then a random exact-or-nudged scale 2^-500..2^500 and translation);
// both argument orders, rewritten shapes, exact translations of both.
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

namespace test_query_frustum_plane { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_plane"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_plane: fixtures", "[frustum_plane]") {
    CHECK(intersects(integer_frustum, plane3{{0, 0, 1}, 4})); // the far face
    CHECK_FALSE(intersects(integer_frustum, plane3{{0, 0, 1}, 0x1.0000000000001p2}));
    CHECK(intersects(plane3{{0, 0, 1}, 1}, integer_frustum)); // the near face
    CHECK_FALSE(intersects(plane3{{0, 0, 1}, 0x1.fffffffffffffp-1}, integer_frustum));
    CHECK(intersects(integer_frustum, plane3{{1, 0, 0}, 4})); // the far edge x = z = 4
    CHECK_FALSE(intersects(integer_frustum, plane3{{1, 0, 0}, 0x1.0000000000001p2}));
    CHECK(intersects(integer_frustum, plane3{{1, 1, 0}, 8})); // the far corner (4, 4, 4) alone
    CHECK_FALSE(intersects(integer_frustum, plane3{{1, 1, 0}, 0x1.0000000000001p3}));
    CHECK(intersects(integer_frustum, plane3{{1, 1, 1}, 0}));  // across: (-1, -1, 1) below, (1, 1, 1) above
    CHECK(intersects(integer_frustum, plane3{{1, 1, 1}, -4})); // the far corner (-4, -4, 4) alone
    CHECK_FALSE(intersects(integer_frustum, plane3{{1, 1, 1}, -0x1.0000000000001p2}));
    CHECK(intersects(camera, plane3{{0, 0, 1}, -50}));
    CHECK_FALSE(intersects(camera, plane3{{0, 0, 1}, 1}));
    CHECK_FALSE(intersects(integer_frustum, plane3{{0, 0, 0}, -1}));
}
TEST_CASE("frustum_plane: oracle, random and near-degenerate", "[frustum_plane][oracle]") {
    support::halfspace_oracle<frustum3, plane3>("frustum_plane", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_plane: rewrites of both shapes and exact translations give the same answer", "[frustum_plane]") {
    support::halfspace_symmetries<frustum3, plane3>("frustum_plane", support::cases(5000));
}

} // namespace test_query_frustum_plane
