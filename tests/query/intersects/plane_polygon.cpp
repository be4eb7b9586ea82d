// plane3 x polygon3: fixtures (the polygon's own plane, one ulp off it, a plane through an edge,
// beside it, between two rings apart); the oracle (the polygon's CGAL constrained triangulation, each
// triangle against the other shape by CGAL Epeck, the exact LP or the mesh oracle) on 20,000 random
// and 20,000 near-degenerate cases (support/polygon3_cases.hpp: exactly planar star polygons with
// holes at scales 2^-500..2^500, the other shape at a vertex, an edge point or inside, along the edge,
// in the plane or across it, nudged by ulps or not); both argument orders, rotated and reversed rings,
// rewritten partners, exact translations.
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

namespace test_query_plane_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("plane_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("plane_polygon: fixtures", "[plane_polygon]") {
    CHECK(intersects(plane3{{0, 0, 1}, 1}, holed));
    CHECK_FALSE(intersects(holed, plane3{{0, 0, 1}, 0x1.0000000000001p0}));
    CHECK(intersects(plane3{{1, 0, 0}, 4}, holed));
    CHECK_FALSE(intersects(plane3{{1, 0, 0}, 0x1.0000000000001p2}, holed));
    CHECK(intersects(plane3{{1, 0, 0}, 2}, holed)); // across the hole too
    CHECK(intersects(plane3{{0, 0, 1}, 1.5}, tilted_l));
    // two triangles apart, one on each side of x = 0: the plane passes between them (found by the flat fuzzer)
    static constexpr std::array<point3, 6> apart{{{-3, 0, 0}, {-1, 0, 0}, {-2, 1, 0}, {1, 0, 0}, {3, 0, 0}, {2, 1, 0}}};
    static constexpr std::array<std::uint32_t, 2> apart_ends{3, 6};
    CHECK_FALSE(intersects(plane3{{1, 0, 0}, 0}, polygon3{apart, apart_ends, {0, 1, 2}, 2}));
    CHECK(intersects(plane3{{1, 0, 0}, -1}, polygon3{apart, apart_ends, {0, 1, 2}, 2}));
}
TEST_CASE("plane_polygon: oracle, random and near-degenerate", "[plane_polygon][oracle]") {
    support::polygon3_oracle<plane3>("plane_polygon", support::cases(20000), approx_bound);
}
TEST_CASE("plane_polygon: rewritten shapes and exact translations give the same answer", "[plane_polygon]") {
    support::polygon3_symmetries<plane3>("plane_polygon", support::cases(5000));
}

} // namespace test_query_plane_polygon
