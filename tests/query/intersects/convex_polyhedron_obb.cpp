// convex_polyhedron3 x obb3: fixtures (a skew box touching the cut cube along an edge and one ulp
// away, a box above a wedge that no single plane separates, empty and unbounded sets, flat boxes,
// NaN and negative extents); the exact LP oracle (the polyhedron as its half-spaces, the box as
// its centre plus bounded multiples of its axes) on 20,000 random and 20,000 near-degenerate cases
// (a polyhedron of 4 to 12 supporting half-spaces of a small dyadic cloud, unbounded, flat and
// empty ones included, the box placed with a corner, an edge or face point at one of its boundary
// points, in a permuted, near-rotation or skew frame, zero extents included; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, the box's axes
// rewritten, exact translations of both; contains against the box's exact corners.
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

namespace test_query_convex_polyhedron_obb { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("convex_polyhedron_obb"); // stated in the catalog (modules/query/catalog.cppm)
// A box turned 45 degrees about z (axes of length sqrt 2, read as given): x + y = 3 + 2 s0 and
// x - y = -2 s1 about the centre (3/2, 3/2).
constexpr obb3 diamond(double h0, double z, double h2) {
    return {{1.5, 1.5, z}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {h0, 0.5, h2}};
}
constexpr obb3 upright(point3 c, double hx, double hy, double hz) {
    return {c, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {hx, hy, hz}};
}
} // namespace

TEST_CASE("convex_polyhedron_obb: fixtures", "[convex_polyhedron_obb]") {
    CHECK(intersects(unit_cube_cut, diamond(0.5, 0.5, 0.5)));                        // touches along the edge x = y = 1, z <= 1/2
    CHECK_FALSE(intersects(diamond(0x1.fffffffffffffp-2, 0.5, 0.5), unit_cube_cut)); // x + y >= 2 + 2^-52
    CHECK(intersects(unit_cube_cut, diamond(0.5, 1, 0.5)));                          // the edge point (1, 1, 1/2) alone
    CHECK_FALSE(intersects(unit_cube_cut, diamond(0.5, 0x1.0000000000001p0, 0.5)));
    CHECK(intersects(unit_cube_cut, upright({0.5, 0.5, 0.5}, 5, 5, 5)));  // around it
    CHECK(intersects(unit_cube_cut, upright({0.5, 0.5, 0.5}, 0, 0, 0)));  // a point inside
    CHECK_FALSE(intersects(upright({0, 0.5, 0.75}, 1, 0.5, 0.25), roof)); // above the ridge: no single plane separates
    CHECK(intersects(upright({0, 0.5, 0.5}, 1, 0.5, 0.5), roof));         // touches along the ridge
    CHECK_FALSE(intersects(empty_slab, upright({0, 0, 0}, 5, 5, 5)));
    CHECK(intersects(half_space, obb3{{1, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {0.5, 0.5, 1}})); // x >= 0 at one edge
    CHECK_FALSE(intersects(half_space, obb3{{1, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {0.5, 0x1.fffffffffffffp-2, 1}}));
    CHECK_FALSE(intersects(unit_cube_cut, upright({0.5, 0.5, 0.5}, 1, 1, std::nan(""))));
    CHECK_FALSE(intersects(unit_cube_cut, upright({0.5, 0.5, 0.5}, 1, 1, -1)));
    CHECK_FALSE(intersects(unit_cube_cut, obb3{{0.5, 0.5, 0.5}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, HUGE_VAL}}, {1, 1, 1}}));
    const obb3 inside{{0.5, 0.5, 0.5}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {0.25, 0.25, 0.5}}; // x + y + z <= 5/2 at a corner
    CHECK(contains(unit_cube_cut, inside));
    CHECK_FALSE(contains(unit_cube_cut, obb3{inside.center, inside.axes, {0.25, 0.25, 0x1.0000000000001p-1}}));
    CHECK_FALSE(contains(empty_slab, upright({0, 0, 0}, 0, 0, 0)));
    CHECK(contains(half_space, upright({-1, 0, 0}, 1, 7, 7)));
}
TEST_CASE("convex_polyhedron_obb: oracle, random and near-degenerate", "[convex_polyhedron_obb][oracle]") {
    support::halfspace_oracle<convex_polyhedron3, obb3>("convex_polyhedron_obb", support::cases(20000), approx_bound);
}
TEST_CASE("convex_polyhedron_obb: rewrites of both shapes and exact translations give the same answer", "[convex_polyhedron_obb]") {
    support::halfspace_symmetries<convex_polyhedron3, obb3>("convex_polyhedron_obb", support::cases(5000));
}
TEST_CASE("convex_polyhedron_obb: contains", "[convex_polyhedron_obb][oracle]") {
    support::halfspace_contains_oracle<convex_polyhedron3, obb3>("convex_polyhedron_obb", support::cases(2000), approx_bound);
}

} // namespace test_query_convex_polyhedron_obb
