// polygon3 x polygon3: fixtures (the ring and the holed square, the tilted L through the holed square,
// a polygon in the hole); the oracle (the polygon's CGAL constrained triangulation, each triangle
// against the other shape by CGAL Epeck, the exact LP or the mesh oracle) on 20,000 random and 20,000
// near-degenerate cases (support/polygon3_cases.hpp: exactly planar star polygons with holes at scales
// 2^-500..2^500, the other shape at a vertex, an edge point or inside, along the edge, in the plane or
// across it, nudged by ulps or not); both argument orders, rotated and reversed rings, rewritten
// partners, exact translations.
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

namespace test_query_polygon_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("polygon_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("polygon_polygon: fixtures", "[polygon_polygon]") {
    CHECK(intersects(holed, ring));
    CHECK(intersects(tilted_l, holed)); // x + z = 2 crosses z = 1 along x = 1, the hole's edge
    CHECK(intersects(ring, tilted_l));
    static constexpr std::array<point3, 3> small_tri{{{1.5, 1.5, 1}, {2.5, 1.5, 1}, {2, 2.5, 1}}};
    CHECK_FALSE(intersects(holed, polygon3{small_tri, {}, {0, 1, 2}, 2})); // in the hole
}
TEST_CASE("polygon_polygon: oracle, random and near-degenerate", "[polygon_polygon][oracle]") {
    support::polygon3_oracle<polygon3>("polygon_polygon", support::cases(20000), approx_bound);
}
TEST_CASE("polygon_polygon: rewritten shapes and exact translations give the same answer", "[polygon_polygon]") {
    support::polygon3_symmetries<polygon3>("polygon_polygon", support::cases(5000));
}

} // namespace test_query_polygon_polygon
