// convex_polyhedron3 x plane3: fixtures (a face's plane and one ulp beyond, a corner's supporting plane, an unbounded
// wedge's ridge (two planes' normals span only a plane), a half-space and parallel planes, an empty set, zero normals);
// the exact LP oracle (the polyhedron as its half-spaces n . x <= offset, the plane as an equality) on 20,000 random
// and 20,000 near-degenerate cases (a polyhedron of 4 to 12 supporting half-spaces of a small dyadic cloud (unbounded,
// flat and empty ones included), the plane through one of its boundary points: a face's own plane, or containing a
// direction along the face, or any; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, rewritten shapes, exact translations of both.
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

namespace test_query_convex_polyhedron_plane { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("convex_polyhedron_plane"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("convex_polyhedron_plane: fixtures", "[convex_polyhedron_plane]") {
    CHECK(intersects(unit_cube_cut, plane3{{1, 1, 1}, 2.5})); // the cut face's own plane
    CHECK_FALSE(intersects(unit_cube_cut, plane3{{1, 1, 1}, 0x1.4000000000001p1}));
    CHECK(intersects(plane3{{1, 0, 0}, 1}, unit_cube_cut)); // the face x = 1
    CHECK_FALSE(intersects(plane3{{1, 0, 0}, 0x1.0000000000001p0}, unit_cube_cut));
    CHECK(intersects(unit_cube_cut, plane3{{1, 1, 1}, 0})); // the corner at the origin alone
    CHECK_FALSE(intersects(unit_cube_cut, plane3{{1, 1, 1}, -0x1p-1074}));
    CHECK(intersects(roof, plane3{{0, 0, 1}, 0})); // along the ridge x = z = 0 (normals of rank 2)
    CHECK_FALSE(intersects(roof, plane3{{0, 0, 1}, 0x1p-1074}));
    CHECK(intersects(roof, plane3{{0, 0, -1}, 1e300}));
    CHECK(intersects(half_space, plane3{{0, 1, 0}, 5}));  // across it
    CHECK(intersects(half_space, plane3{{-2, 0, 0}, 2})); // parallel, inside (normals of rank 1)
    CHECK(intersects(half_space, plane3{{1, 0, 0}, 0}));  // its own boundary
    CHECK_FALSE(intersects(half_space, plane3{{1, 0, 0}, 0x1p-1074}));
    CHECK_FALSE(intersects(empty_slab, plane3{{0, 1, 0}, 0}));
    CHECK(intersects(half_space, plane3{{0, 0, 0}, 0})); // a zero normal with offset 0: all of space
    CHECK_FALSE(intersects(half_space, plane3{{0, 0, 0}, 1}));
    CHECK_FALSE(intersects(unit_cube_cut, plane3{{1, 0, 0}, NAN}));
}
TEST_CASE("convex_polyhedron_plane: oracle, random and near-degenerate", "[convex_polyhedron_plane][oracle]") {
    support::halfspace_oracle<convex_polyhedron3, plane3>("convex_polyhedron_plane", support::cases(20000), approx_bound);
}
TEST_CASE("convex_polyhedron_plane: rewrites of both shapes and exact translations give the same answer", "[convex_polyhedron_plane]") {
    support::halfspace_symmetries<convex_polyhedron3, plane3>("convex_polyhedron_plane", support::cases(5000));
}

} // namespace test_query_convex_polyhedron_plane
