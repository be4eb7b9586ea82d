// aabb3 x polygon3: fixtures (a box through the hole alone, through the ring, one ulp above, a box
// with its side faces along the hole's edges, an inverted box); the oracle (the polygon's CGAL
// constrained triangulation, each triangle against the other shape by CGAL Epeck, the exact LP or the
// mesh oracle) on 20,000 random and 20,000 near-degenerate cases (support/polygon3_cases.hpp: exactly
// planar star polygons with holes at scales 2^-500..2^500, the other shape at a vertex, an edge point
// or inside, along the edge, in the plane or across it, nudged by ulps or not); both argument orders,
// rotated and reversed rings, rewritten partners, exact translations.
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

namespace test_query_aabb_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("aabb_polygon: fixtures", "[aabb_polygon]") {
    CHECK_FALSE(intersects(aabb3{{1.5, 1.5, 0}, {2.5, 2.5, 2}}, holed));
    CHECK(intersects(aabb3{{0.25, 0.25, 0}, {0.75, 0.75, 2}}, holed));
    CHECK_FALSE(intersects(holed, aabb3{{0.25, 0.25, 0x1.0000000000001p0}, {0.75, 0.75, 2}}));
    CHECK(intersects(aabb3{{1, 1, 0}, {3, 3, 2}}, holed));       // its side faces along the hole's edges
    CHECK_FALSE(intersects(aabb3{{1, 1, 0}, {0, 0, 2}}, holed)); // inverted: empty
}
TEST_CASE("aabb_polygon: oracle, random and near-degenerate", "[aabb_polygon][oracle]") {
    support::polygon3_oracle<aabb3>("aabb_polygon", support::cases(20000), approx_bound);
}
TEST_CASE("aabb_polygon: rewritten shapes and exact translations give the same answer", "[aabb_polygon]") {
    support::polygon3_symmetries<aabb3>("aabb_polygon", support::cases(5000));
}

} // namespace test_query_aabb_polygon
