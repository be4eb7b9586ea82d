// convex_polyhedron3 x polygon3: fixtures (the cut cube touching the holed square, a half-space at an
// edge, an empty set, a post whose section lies in the hole and over the ring); the oracle (the
// polygon's CGAL constrained triangulation, each triangle against the other shape by CGAL Epeck, the
// exact LP or the mesh oracle) on 20,000 random and 20,000 near-degenerate cases
// (support/polygon3_cases.hpp: exactly planar star polygons with holes at scales 2^-500..2^500, the
// other shape at a vertex, an edge point or inside, along the edge, in the plane or across it, nudged
// by ulps or not); both argument orders, rotated and reversed rings, rewritten partners, exact
// translations.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/mesh_checks.hpp"
#include "testkit/polygon3_cases.hpp"
#include "testkit/polygon3_checks.hpp"
#include "testkit/polygon3_fixtures.hpp"
#include "testkit/polyhedron_fixtures.hpp"
#include "testkit/kdop_fixtures.hpp"
#include "testkit/mesh_fixtures.hpp"

namespace test_query_convex_polyhedron_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("convex_polyhedron_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("convex_polyhedron_polygon: fixtures", "[convex_polyhedron_polygon]") {
    CHECK(intersects(unit_cube_cut, holed));
    CHECK(intersects(holed, half_space)); // x <= 0: the edge x = 0
    CHECK_FALSE(intersects(empty_slab, holed));
    // the post [1.25, 2.75]^2 x [0, 2]: its section by z = 1 lies in the hole, and over the ring's inner part
    const convex_polyhedron3 post{{plane3{{1, 0, 0}, 2.75}, plane3{{-1, 0, 0}, -1.25}, plane3{{0, 1, 0}, 2.75}, plane3{{0, -1, 0}, -1.25},
                                   plane3{{0, 0, 1}, 2}, plane3{{0, 0, -1}, 0}},
                                  6};
    CHECK_FALSE(intersects(post, holed));
    CHECK(intersects(post, ring));
}
TEST_CASE("convex_polyhedron_polygon: oracle, random and near-degenerate", "[convex_polyhedron_polygon][oracle]") {
    support::polygon3_oracle<convex_polyhedron3>("convex_polyhedron_polygon", support::cases(20000), approx_bound);
}
TEST_CASE("convex_polyhedron_polygon: rewritten shapes and exact translations give the same answer", "[convex_polyhedron_polygon]") {
    support::polygon3_symmetries<convex_polyhedron3>("convex_polyhedron_polygon", support::cases(5000));
}

} // namespace test_query_convex_polyhedron_polygon
