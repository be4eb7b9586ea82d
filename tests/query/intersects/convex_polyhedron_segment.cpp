// convex_polyhedron3 x segment3: fixtures; the exact LP oracle (the polyhedron as its half-spaces n . x <= offset) on
// 20,000 random and 20,000 near-degenerate cases (a polyhedron of 4 to 12 supporting half-spaces of a small dyadic cloud (unbounded, flat and empty ones included), the segment placed through one of its
// boundary points, along a face or not; then a random exact-or-nudged scale 2^-500..2^500 and
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

namespace test_query_convex_polyhedron_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("convex_polyhedron_segment"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("convex_polyhedron_segment: fixtures", "[convex_polyhedron_segment]") {
    CHECK(intersects(unit_cube_cut, segment3{{2, 2, 2}, {0.5, 0.5, 0.5}}));
    CHECK(intersects(segment3{{2, 2, 0.5}, {1, 1, 0.5}}, unit_cube_cut)); // ends on the cut face
    CHECK_FALSE(intersects(segment3{{2, 2, 0.5}, {0x1.0000000000001p0, 1, 0.5}}, unit_cube_cut));
    CHECK(intersects(unit_cube_cut, segment3{{-1, 0, 0}, {2, 0, 0}}));    // along an edge
    CHECK(intersects(unit_cube_cut, segment3{{1.5, 0, 1}, {0, 1.5, 1}})); // along the cut face's edge
    CHECK_FALSE(intersects(empty_slab, segment3{{-5, -5, -5}, {5, 5, 5}}));
    CHECK(contains(unit_cube_cut, segment3{{0, 0, 0}, {1, 1, 0.5}}));
    CHECK_FALSE(contains(unit_cube_cut, segment3{{0, 0, 0}, {1, 1, 1}}));
}
TEST_CASE("convex_polyhedron_segment: oracle, random and near-degenerate", "[convex_polyhedron_segment][oracle]") {
    support::halfspace_oracle<convex_polyhedron3, segment3>("convex_polyhedron_segment", support::cases(20000), approx_bound);
}
TEST_CASE("convex_polyhedron_segment: rewrites of both shapes and exact translations give the same answer", "[convex_polyhedron_segment]") {
    support::halfspace_symmetries<convex_polyhedron3, segment3>("convex_polyhedron_segment", support::cases(10000));
}
TEST_CASE("convex_polyhedron_segment: contains", "[convex_polyhedron_segment][oracle]") {
    support::halfspace_contains_oracle<convex_polyhedron3, segment3>("convex_polyhedron_segment", support::cases(2000), approx_bound);
}

} // namespace test_query_convex_polyhedron_segment
