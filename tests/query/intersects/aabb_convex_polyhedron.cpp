// aabb3 x convex_polyhedron3: fixtures; the exact LP oracle (the polyhedron as its half-spaces n . x <= offset) on
// 20,000 random and 20,000 near-degenerate cases (a polyhedron of 4 to 12 supporting half-spaces of a small dyadic cloud (unbounded, flat and empty ones included), the box placed at one of its
// boundary points, flat or not; then a random exact-or-nudged scale 2^-500..2^500 and
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

namespace test_query_aabb_convex_polyhedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_convex_polyhedron"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("aabb_convex_polyhedron: fixtures", "[aabb_convex_polyhedron]") {
    CHECK(intersects(aabb3{{0.75, 0.75, 0.75}, {2, 2, 2}}, unit_cube_cut));
    CHECK_FALSE(intersects(unit_cube_cut, aabb3{{0.875, 0.875, 0.875}, {2, 2, 2}})); // beyond the cut
    CHECK(intersects(aabb3{{0.5, 1, 1}, {2, 2, 2}}, unit_cube_cut));                 // touches at (1/2, 1, 1) alone
    CHECK_FALSE(intersects(aabb3{{0x1.0000000000001p-1, 1, 1}, {2, 2, 2}}, unit_cube_cut));
    CHECK(intersects(aabb3{{1, -1, -1}, {3, 2, 2}}, unit_cube_cut)); // along the face x = 1
    CHECK_FALSE(intersects(aabb3{{-1, 0, 0.5}, {1, 1, 1}}, roof));   // no single plane separates
    CHECK(intersects(aabb3{{-1, 0, 0}, {1, 1, 1}}, roof));           // touches along the ridge
    CHECK_FALSE(intersects(aabb3{{-5, -5, -5}, {5, 5, 5}}, empty_slab));
    CHECK(intersects(aabb3{{-5, -5, -5}, {0, 5, 5}}, half_space));
    CHECK_FALSE(intersects(aabb3{{0x1p-1074, -5, -5}, {1, 5, 5}}, half_space));
    CHECK_FALSE(intersects(aabb3{{1, 1, 1}, {0, 0, 0}}, unit_cube_cut)); // inverted: empty
    CHECK(contains(unit_cube_cut, aabb3{{0, 0, 0}, {1, 1, 0.5}}));
    CHECK_FALSE(contains(unit_cube_cut, aabb3{{0, 0, 0}, {1, 1, 0x1.0000000000001p-1}}));
    CHECK_FALSE(contains(unit_cube_cut, aabb3{{1, 1, 1}, {0, 0, 0}}));
}
TEST_CASE("aabb_convex_polyhedron: oracle, random and near-degenerate", "[aabb_convex_polyhedron][oracle]") {
    support::halfspace_oracle<convex_polyhedron3, aabb3>("aabb_convex_polyhedron", support::cases(20000), approx_bound);
}
TEST_CASE("aabb_convex_polyhedron: rewrites of both shapes and exact translations give the same answer", "[aabb_convex_polyhedron]") {
    support::halfspace_symmetries<convex_polyhedron3, aabb3>("aabb_convex_polyhedron", support::cases(5000));
}
TEST_CASE("aabb_convex_polyhedron: contains", "[aabb_convex_polyhedron][oracle]") {
    support::halfspace_contains_oracle<convex_polyhedron3, aabb3>("aabb_convex_polyhedron", support::cases(2000), approx_bound);
}

} // namespace test_query_aabb_convex_polyhedron
