// convex_polyhedron3 x frustum3: fixtures (a box touching the far corner and one ulp off, a half-space along the far
// face and one ulp off, a half-space across, a camera frustum, an empty set); the exact LP oracle (both as their
// half-spaces n . x <= offset) on 20,000 random and 20,000 near-degenerate cases (an axis-aligned integer frustum
// (corners dyadic) or a camera frustum (frustum3::from_camera), the polyhedron the supporting half-spaces of a
// small dyadic cloud from one of the frustum's boundary points outwards, with that face's opposite half-space two
// times in three; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument orders,
// rewritten shapes, exact translations of both.
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

namespace test_query_convex_polyhedron_frustum { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("convex_polyhedron_frustum"); // stated in the catalog (modules/query/catalog.cppm)
constexpr convex_polyhedron3 cube(double lo_z) {
    return {{plane3{{1, 0, 0}, 5}, plane3{{-1, 0, 0}, -4}, plane3{{0, 1, 0}, 5}, plane3{{0, -1, 0}, -4}, plane3{{0, 0, 1}, 5},
             plane3{{0, 0, -1}, -lo_z}},
            6};
}
} // namespace

TEST_CASE("convex_polyhedron_frustum: fixtures", "[convex_polyhedron_frustum]") {
    CHECK(intersects(cube(4), integer_frustum)); // the far corner (4, 4, 4)
    CHECK_FALSE(intersects(integer_frustum, cube(0x1.0000000000001p2)));
    CHECK(intersects(convex_polyhedron3{{plane3{{0, 0, -1}, -4}}, 1}, integer_frustum)); // z >= 4: the far face
    CHECK_FALSE(intersects(convex_polyhedron3{{plane3{{0, 0, -1}, -0x1.0000000000001p2}}, 1}, integer_frustum));
    CHECK(intersects(half_space, integer_frustum));
    CHECK(intersects(half_space, camera));
    CHECK_FALSE(intersects(convex_polyhedron3{{plane3{{0, 0, -1}, 0x1p-20}}, 1}, camera)); // z >= -2^-20: before the near plane
    CHECK_FALSE(intersects(empty_slab, integer_frustum));
}
TEST_CASE("convex_polyhedron_frustum: oracle, random and near-degenerate", "[convex_polyhedron_frustum][oracle]") {
    support::halfspace_oracle<frustum3, convex_polyhedron3>("convex_polyhedron_frustum", support::cases(20000), approx_bound);
}
TEST_CASE("convex_polyhedron_frustum: rewrites of both shapes and exact translations give the same answer", "[convex_polyhedron_frustum]") {
    support::halfspace_symmetries<frustum3, convex_polyhedron3>("convex_polyhedron_frustum", support::cases(5000));
}

} // namespace test_query_convex_polyhedron_frustum
