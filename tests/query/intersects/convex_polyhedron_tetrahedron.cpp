// convex_polyhedron3 x tetrahedron3: fixtures (a large tetrahedron holding the cut cube whole, its top face on the
// cube's top face, below the cube touching it and a subnormal step lower; a vertex on the cut face and one ulp off); the
// exact LP oracle (the set as its half-spaces n . x <= offset, the tetrahedron as the hull of its vertices) on 20,000
// random and 20,000 near-degenerate cases (a polyhedron of 4 to 12 supporting planes of a dyadic cloud, the
// tetrahedron placed through one of its boundary points, along a face or not; then a random exact-or-nudged scale
// 2^-500..2^500 and translation); both argument orders, rewritten shapes, exact translations of both; contains.
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

namespace test_query_convex_polyhedron_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound =
    catalog::approximate_bound("convex_polyhedron_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("convex_polyhedron_tetrahedron: fixtures", "[convex_polyhedron_tetrahedron]") {
    CHECK(intersects(unit_cube_cut, wide_tetrahedron(2)));   // no face meets the cube: it lies inside
    CHECK(intersects(wide_tetrahedron(1), unit_cube_cut));   // the top faces in one plane
    CHECK(intersects(unit_cube_cut, wide_tetrahedron(0.5))); // a face through the cube
    CHECK(intersects(unit_cube_cut, wide_tetrahedron(0)));   // below, touching the bottom face
    CHECK_FALSE(intersects(unit_cube_cut, wide_tetrahedron(-0x1p-1074)));
    CHECK(intersects(unit_cube_cut, tetrahedron3{{1, 1, 0.5}, {3, 3, 3}, {3, 2, 3}, {2, 3, 2}})); // a vertex on the cut face
    CHECK_FALSE(intersects(unit_cube_cut, tetrahedron3{{1, 1, 0x1.0000000000001p-1}, {3, 3, 3}, {3, 2, 3}, {2, 3, 2}}));
    CHECK(intersects(half_space, wide_tetrahedron(0))); // unbounded: through a face
    CHECK_FALSE(intersects(empty_slab, wide_tetrahedron(0)));
    CHECK(intersects(unit_cube_cut, tetrahedron3{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {5, 5, 5}})); // flat: a segment
    CHECK(contains(unit_cube_cut, tetrahedron3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 1}}));
    CHECK_FALSE(contains(unit_cube_cut, tetrahedron3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}}));
}
TEST_CASE("convex_polyhedron_tetrahedron: oracle, random and near-degenerate", "[convex_polyhedron_tetrahedron][oracle]") {
    support::halfspace_oracle<convex_polyhedron3, tetrahedron3>("convex_polyhedron_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("convex_polyhedron_tetrahedron: rewrites of both shapes and exact translations give the same answer",
          "[convex_polyhedron_tetrahedron]") {
    support::halfspace_symmetries<convex_polyhedron3, tetrahedron3>("convex_polyhedron_tetrahedron", support::cases(5000));
}
TEST_CASE("convex_polyhedron_tetrahedron: contains", "[convex_polyhedron_tetrahedron][oracle]") {
    support::halfspace_contains_oracle<convex_polyhedron3, tetrahedron3>("convex_polyhedron_tetrahedron", support::cases(2000),
                                                                         approx_bound);
}

} // namespace test_query_convex_polyhedron_tetrahedron
