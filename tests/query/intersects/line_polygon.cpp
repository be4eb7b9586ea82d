// line3 x polygon3: fixtures (vertical lines inside and through the hole, a line in the plane, a
// parallel line one ulp off it); the oracle (the polygon's CGAL constrained triangulation, each
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

namespace test_query_line_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("line_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line_polygon: fixtures", "[line_polygon]") {
    CHECK(intersects(line3{{0.5, 0.5, 9}, {0, 0, 1}}, holed));
    CHECK_FALSE(intersects(holed, line3{{2, 2, 9}, {0, 0, 1}}));
    CHECK(intersects(line3{{0, 2, 1}, {1, 0, 0}}, holed));
    CHECK_FALSE(intersects(line3{{0, 2, 0x1.0000000000001p0}, {1, 0, 0}}, holed));
    CHECK(intersects(line3{{1.5, 0.5, 0}, {0, 0, 1}}, tilted_l));
}
TEST_CASE("line_polygon: oracle, random and near-degenerate", "[line_polygon][oracle]") {
    support::polygon3_oracle<line3>("line_polygon", support::cases(20000), approx_bound);
}
TEST_CASE("line_polygon: rewritten shapes and exact translations give the same answer", "[line_polygon]") {
    support::polygon3_symmetries<line3>("line_polygon", support::cases(5000));
}

} // namespace test_query_line_polygon
