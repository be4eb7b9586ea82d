// convex_polyhedron3 x triangle3: fixtures (a large triangle across the cut cube whose edges miss it, on the top face
// and one ulp above, through the cut face, against the empty set); the exact LP oracle (the polyhedron as its
// half-spaces n . x <= offset, the triangle as the hull of its corners) on 20,000 random and 20,000
// near-degenerate cases (a polyhedron of 4 to 12 supporting half-spaces of a small dyadic cloud (unbounded, flat
// and empty ones included), the triangle placed through one of its boundary points, along a face or not; then a
// random exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rewritten shapes, exact
// translations of both; contains.
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

namespace test_query_convex_polyhedron_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("convex_polyhedron_triangle"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("convex_polyhedron_triangle: fixtures", "[convex_polyhedron_triangle]") {
    CHECK(intersects(unit_cube_cut, wide_triangle(0.5))); // the edges miss the cube: its section lies inside
    CHECK(intersects(wide_triangle(1), unit_cube_cut));   // the top face
    CHECK_FALSE(intersects(unit_cube_cut, wide_triangle(0x1.0000000000001p0)));
    CHECK(intersects(unit_cube_cut, triangle3{{2, 0, 0.5}, {0, 2, 0.5}, {1, 1, 3}})); // through the cut face
    CHECK_FALSE(intersects(unit_cube_cut, triangle3{{2, 1, 0}, {1, 2, 0}, {2, 2, 5}}));
    CHECK(intersects(half_space, triangle3{{0, 5, 5}, {3, 0, 0}, {3, 1, 0}})); // a corner on x = 0
    CHECK(intersects(half_space, triangle3{{0, 5, 5}, {0, 5, 5}, {3, 1, 0}})); // collinear corners: a segment
    CHECK_FALSE(intersects(half_space, triangle3{{0x1p-1074, 5, 5}, {3, 0, 0}, {3, 1, 0}}));
    CHECK_FALSE(intersects(empty_slab, wide_triangle(0)));
    CHECK(contains(unit_cube_cut, triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 1}}));
    CHECK_FALSE(contains(unit_cube_cut, triangle3{{0, 0, 0}, {1, 0, 0}, {1, 1, 1}}));
}
TEST_CASE("convex_polyhedron_triangle: oracle, random and near-degenerate", "[convex_polyhedron_triangle][oracle]") {
    support::halfspace_oracle<convex_polyhedron3, triangle3>("convex_polyhedron_triangle", support::cases(20000), approx_bound);
}
TEST_CASE("convex_polyhedron_triangle: rewrites of both shapes and exact translations give the same answer",
          "[convex_polyhedron_triangle]") {
    support::halfspace_symmetries<convex_polyhedron3, triangle3>("convex_polyhedron_triangle", support::cases(5000));
}
TEST_CASE("convex_polyhedron_triangle: contains", "[convex_polyhedron_triangle][oracle]") {
    support::halfspace_contains_oracle<convex_polyhedron3, triangle3>("convex_polyhedron_triangle", support::cases(2000), approx_bound);
}

} // namespace test_query_convex_polyhedron_triangle
