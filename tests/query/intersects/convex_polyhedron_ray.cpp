// convex_polyhedron3 x ray3: fixtures; the exact LP oracle (the polyhedron as its half-spaces n . x <= offset) on
// 20,000 random and 20,000 near-degenerate cases (a polyhedron of 4 to 12 supporting half-spaces of a small dyadic cloud (unbounded, flat and empty ones included), the ray placed through one of its
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

namespace test_query_convex_polyhedron_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("convex_polyhedron_ray"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("convex_polyhedron_ray: fixtures", "[convex_polyhedron_ray]") {
    CHECK(intersects(unit_cube_cut, ray3{{2, 2, 2}, {-1, -1, -1}}));
    CHECK_FALSE(intersects(unit_cube_cut, ray3{{2, 2, 2}, {1, 1, 1}}));
    CHECK(intersects(ray3{{3, 3, 0.5}, {-1, -1, 0}}, unit_cube_cut)); // reaches the cut face
    CHECK(intersects(unit_cube_cut, ray3{{2, 0.5, 1}, {-1, 0, 0}}));  // grazes the top face
    CHECK_FALSE(intersects(unit_cube_cut, ray3{{2, 0.5, 0x1.0000000000001p0}, {-1, 0, 0}}));
    CHECK(intersects(half_space, ray3{{5, 0, 0}, {-1, 1e-300, 0}}));
    CHECK_FALSE(intersects(empty_slab, ray3{{0, 0, 0}, {1, 0, 0}}));
}
TEST_CASE("convex_polyhedron_ray: oracle, random and near-degenerate", "[convex_polyhedron_ray][oracle]") {
    support::halfspace_oracle<convex_polyhedron3, ray3>("convex_polyhedron_ray", support::cases(20000), approx_bound);
}
TEST_CASE("convex_polyhedron_ray: rewrites of both shapes and exact translations give the same answer", "[convex_polyhedron_ray]") {
    support::halfspace_symmetries<convex_polyhedron3, ray3>("convex_polyhedron_ray", support::cases(10000));
}

} // namespace test_query_convex_polyhedron_ray
