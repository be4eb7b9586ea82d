// convex_polyhedron3 x convex_polyhedron3: fixtures (along a face and one ulp apart, an unbounded wedge's ridge on a
// half-space (normals of rank 2), two half-spaces sharing a plane (rank 1), two wedges whose ridges cross at one
// point that no face of either separates when one ulp apart, an empty set); the exact LP oracle (each polyhedron as
// its half-spaces n . x <= offset) on 20,000 random and 20,000 near-degenerate cases (a polyhedron of 4 to 12
// supporting half-spaces of a small dyadic cloud (unbounded, flat and empty ones included), the second one the
// supporting half-spaces of a small dyadic cloud from one of the first's boundary points outwards, with that face's
// opposite half-space two times in three; then a random exact-or-nudged scale 2^-500..2^500 and translation); both
// argument orders, rewritten shapes, exact translations of both.
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

namespace test_query_convex_polyhedron_convex_polyhedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound =
    catalog::approximate_bound("convex_polyhedron_convex_polyhedron"); // stated in the catalog (modules/query/catalog.cppm)
// x + y + z >= t within a box of side 5: beyond the cut face of unit_cube_cut when t > 5/2
constexpr convex_polyhedron3 beyond_cut(double t) {
    return {{plane3{{-1, -1, -1}, -t}, plane3{{1, 0, 0}, 5}, plane3{{0, 1, 0}, 5}, plane3{{0, 0, 1}, 5}}, 4};
}
// z >= |y| + h: a wedge opening upwards whose ridge (along x) crosses the roof's (along y)
constexpr convex_polyhedron3 trough(double h) { return {{plane3{{0, 1, -1}, -h}, plane3{{0, -1, -1}, -h}}, 2}; }
} // namespace

TEST_CASE("convex_polyhedron_convex_polyhedron: fixtures", "[convex_polyhedron_convex_polyhedron]") {
    CHECK(intersects(unit_cube_cut, beyond_cut(2.5))); // along the cut face
    CHECK_FALSE(intersects(unit_cube_cut, beyond_cut(0x1.4000000000001p1)));
    CHECK(intersects(roof, convex_polyhedron3{{plane3{{0, 0, -1}, 0}}, 1})); // z >= 0: the ridge
    CHECK_FALSE(intersects(roof, convex_polyhedron3{{plane3{{0, 0, -1}, -0x1p-1074}}, 1}));
    CHECK(intersects(half_space, convex_polyhedron3{{plane3{{-2, 0, 0}, 0}}, 1})); // x >= 0: the plane x = 0
    CHECK_FALSE(intersects(half_space, convex_polyhedron3{{plane3{{-2, 0, 0}, -0x1p-1074}}, 1}));
    CHECK(intersects(roof, trough(0)));               // the ridges cross at the origin alone
    CHECK_FALSE(intersects(trough(0x1p-1074), roof)); // no face of either has the other beyond it
    CHECK(intersects(roof, trough(-1)));
    CHECK_FALSE(intersects(empty_slab, half_space));
    CHECK(intersects(unit_cube_cut, unit_cube_cut));
    CHECK_FALSE(intersects(unit_cube_cut, convex_polyhedron3{{plane3{{1, 0, 0}, NAN}}, 1}));
}
TEST_CASE("convex_polyhedron_convex_polyhedron: oracle, random and near-degenerate", "[convex_polyhedron_convex_polyhedron][oracle]") {
    support::halfspace_oracle<convex_polyhedron3, convex_polyhedron3>("convex_polyhedron_convex_polyhedron", support::cases(20000),
                                                                      approx_bound);
}
TEST_CASE("convex_polyhedron_convex_polyhedron: rewrites of both shapes and exact translations give the same answer",
          "[convex_polyhedron_convex_polyhedron]") {
    support::halfspace_symmetries<convex_polyhedron3, convex_polyhedron3>("convex_polyhedron_convex_polyhedron", support::cases(5000));
}

} // namespace test_query_convex_polyhedron_convex_polyhedron
