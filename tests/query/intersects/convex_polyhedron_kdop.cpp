// convex_polyhedron3 x kdop<K>: fixtures (a k-DOP on the cut face of a cut cube and one ulp beyond, a half-space along a face and one ulp off, a wedge and a 26-DOP at its ridge, an empty set and an empty k-DOP); the exact LP oracle (both as their half-spaces) on 5,000 random and 5,000
// near-degenerate cases for each K = 6, 14, 18, 26 (20,000 and 20,000 in all: the supporting half-spaces of a small dyadic cloud (a few unbounded, flat or empty), the k-DOP of a small dyadic
// cloud at one of its boundary points on the outer side of the face there, that point one of the cloud's two times in
// three, else the cloud a quarter out; then a random exact-or-nudged scale 2^-500..2^500 and translation); both
// argument orders, rewritten sets, exact translations of both (K = 14 and 26).
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
#include "testkit/kdop_fixtures.hpp"

namespace test_query_convex_polyhedron_kdop { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("convex_polyhedron_kdop"); // stated in the catalog (modules/query/catalog.cppm)
// [1/2, 1]^3 with x + y + z >= lo (the other diagonal slabs wide open).
constexpr kdop<14> beyond_cut(double lo) { return {{0.5, 0.5, 0.5, lo, -5, -5, -5}, {1, 1, 1, 3, 5, 5, 5}}; }
} // namespace

TEST_CASE("convex_polyhedron_kdop: fixtures", "[convex_polyhedron_kdop]") {
    CHECK(intersects(unit_cube_cut, beyond_cut(2.5))); // on the cut face x + y + z = 5/2
    CHECK_FALSE(intersects(beyond_cut(0x1.4000000000001p1), unit_cube_cut));
    CHECK(intersects(unit_cube_cut, support::corner_cut));
    CHECK(intersects(half_space, support::unit6)); // x <= 0 against [0, 1]^3: the face x = 0
    CHECK_FALSE(intersects(half_space, kdop<6>{{0x1p-1074, 0, 0}, {1, 1, 1}}));
    CHECK(intersects(roof, support::unit26)); // the ridge's point (0, 0, 0)
    CHECK_FALSE(
        intersects(roof, kdop<26>{{0, 0, 0x1p-1074, -5, -5, -5, -5, -5, -5, -5, -5, -5, -5}, {1, 1, 1, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5}}));
    CHECK_FALSE(intersects(empty_slab, support::unit6));
    CHECK_FALSE(intersects(unit_cube_cut, support::empty14));
    CHECK_FALSE(intersects(unit_cube_cut, kdop<6>{{0, 0, 1}, {1, 1, 0}})); // an inverted slab: no set
}
TEST_CASE("convex_polyhedron_kdop: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[convex_polyhedron_kdop][oracle]") {
    support::halfspace_oracle<convex_polyhedron3, kdop<6>>("convex_polyhedron_kdop K = 6", support::cases(5000), approx_bound);
    support::halfspace_oracle<convex_polyhedron3, kdop<14>>("convex_polyhedron_kdop K = 14", support::cases(5000), approx_bound);
    support::halfspace_oracle<convex_polyhedron3, kdop<18>>("convex_polyhedron_kdop K = 18", support::cases(5000), approx_bound);
    support::halfspace_oracle<convex_polyhedron3, kdop<26>>("convex_polyhedron_kdop K = 26", support::cases(5000), approx_bound);
}
TEST_CASE("convex_polyhedron_kdop: rewrites of the set and exact translations give the same answer", "[convex_polyhedron_kdop]") {
    support::halfspace_symmetries<convex_polyhedron3, kdop<14>>("convex_polyhedron_kdop K = 14", support::cases(2500));
    support::halfspace_symmetries<convex_polyhedron3, kdop<26>>("convex_polyhedron_kdop K = 26", support::cases(2500));
}

} // namespace test_query_convex_polyhedron_kdop
