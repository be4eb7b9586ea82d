// kdop<K> x polygon3, K = 6, 14, 18, 26: fixtures (the corner-cut 14-DOP touching the holed square, an
// empty k-DOP, the 26-DOP around it); the oracle (the polygon's CGAL constrained triangulation, each
// triangle against the other shape by CGAL Epeck, the exact LP or the mesh oracle) on 5,000 random and
// 5,000 near-degenerate cases per K (20,000 and 20,000 in all) (support/polygon3_cases.hpp: exactly
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

namespace test_query_kdop_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("kdop_polygon: fixtures", "[kdop_polygon]") {
    CHECK(intersects(corner_cut, holed));
    CHECK_FALSE(intersects(empty14, holed));
    CHECK(intersects(unit26, holed));
    CHECK(intersects(holed, corner_cut));
}
TEST_CASE("kdop_polygon: oracle, random and near-degenerate", "[kdop_polygon][oracle]") {
    support::polygon3_oracle<kdop<6>>("kdop_polygon 6-dop", support::cases(5000), approx_bound);
    support::polygon3_oracle<kdop<14>>("kdop_polygon 14-dop", support::cases(5000), approx_bound);
    support::polygon3_oracle<kdop<18>>("kdop_polygon 18-dop", support::cases(5000), approx_bound);
    support::polygon3_oracle<kdop<26>>("kdop_polygon 26-dop", support::cases(5000), approx_bound);
}
TEST_CASE("kdop_polygon: rewritten shapes and exact translations give the same answer", "[kdop_polygon]") {
    support::polygon3_symmetries<kdop<14>>("kdop_polygon 14-dop", support::cases(1000));
    support::polygon3_symmetries<kdop<26>>("kdop_polygon 26-dop", support::cases(1000));
}

} // namespace test_query_kdop_polygon
