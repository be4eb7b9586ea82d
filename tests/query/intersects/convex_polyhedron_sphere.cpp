// convex_polyhedron3 x sphere3 (the ball): fixtures (the unit cube with a corner cut, a ball
// tangent at the cut's vertex (Pythagorean) and one ulp short; an empty set; a half-space; a wedge
// whose nearest point is its edge); every tier against the exact QP (CGAL's QP_solver over Gmpzf,
// the squared distance from the centre to the half-spaces) on 20,000 random polyhedra and 20,000
// near-degenerate ones (supporting planes of small dyadic clouds, unbounded, flat and empty sets
// among them) with balls tangent at a face, an edge or a vertex, exactly or within ulps
// (testkit/ball_halfspace_cases.hpp); contains(polyhedron, ball) against the rows in rationals on
// 20,000 + 20,000 such cases.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/polyhedron_fixtures.hpp"
#include "testkit/ball_halfspace_checks.hpp"

namespace test_query_convex_polyhedron_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("convex_polyhedron_sphere"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("convex_polyhedron_sphere: fixtures", "[convex_polyhedron_sphere]") {
    // the cut's vertex (1, 1, 1/2): rows x <= 1, y <= 1, x + y + z <= 5/2; (2, 2, 1) = e_x + e_y + (1, 1, 1), length 3
    CHECK(intersects(unit_cube_cut, sphere3{{3, 3, 1.5}, 3}));
    CHECK_FALSE(intersects(unit_cube_cut, sphere3{{3, 3, 1.5}, 0x1.7ffffffffffffp+1}));
    CHECK(intersects(sphere3{{3, 3, 1.5}, 3}, unit_cube_cut));
    CHECK_FALSE(intersects(empty_slab, sphere3{{1.5, 0, 0}, 100}));
    CHECK(intersects(half_space, sphere3{{3, 7, -9}, 3}));
    CHECK_FALSE(intersects(half_space, sphere3{{3, 7, -9}, 0x1.7ffffffffffffp+1}));
    CHECK(intersects(roof, sphere3{{0, 5, 1}, 1})); // the edge x = z = 0 is nearest
    CHECK_FALSE(intersects(roof, sphere3{{0, 5, 1}, 0x1.fffffffffffffp-1}));
    CHECK(contains(unit_cube_cut, sphere3{{0.5, 0.5, 0.5}, 0.5}));
    CHECK_FALSE(contains(unit_cube_cut, sphere3{{0.5, 0.5, 0.5}, 0x1.0000000000001p-1}));
    CHECK_FALSE(contains(empty_slab, sphere3{{1.5, 0, 0}, 0}));
    CHECK(contains(half_space, sphere3{{-3, 1e300, 0}, 3}));
    convex_polyhedron3 none = unit_cube_cut;
    none.count = 33; // outside [0, capacity]: no set
    CHECK_FALSE(intersects(none, sphere3{{0.5, 0.5, 0.5}, 1}));
    convex_polyhedron3 all{};
    all.count = 0; // no half-space: all of space
    CHECK(intersects(all, sphere3{{1e300, 0, 0}, 0}));
    CHECK(contains(all, sphere3{{1e300, 0, 0}, 1e300}));
}
TEST_CASE("convex_polyhedron_sphere: oracle, random and near-degenerate", "[convex_polyhedron_sphere][oracle]") {
    support::ball_halfspace_oracle<convex_polyhedron3>("convex_polyhedron_sphere", support::cases(20000), approx_bound);
}
TEST_CASE("convex_polyhedron_sphere: contains", "[convex_polyhedron_sphere][oracle]") {
    support::ball_halfspace_contains<convex_polyhedron3>("convex_polyhedron_sphere", support::cases(20000), approx_bound);
}

} // namespace test_query_convex_polyhedron_sphere
