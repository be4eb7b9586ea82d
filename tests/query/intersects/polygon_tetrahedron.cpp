// polygon3 x tetrahedron3: fixtures (an apex on the polygon and one ulp above, a tetrahedron through
// the hole alone, one around the polygon); the oracle (the polygon's CGAL constrained triangulation,
// each triangle against the other shape by CGAL Epeck, the exact LP or the mesh oracle) on 20,000
// random and 20,000 near-degenerate cases (support/polygon3_cases.hpp: exactly planar star polygons
// with holes at scales 2^-500..2^500, the other shape at a vertex, an edge point or inside, along the
// edge, in the plane or across it, nudged by ulps or not); both argument orders, rotated and reversed
// rings, rewritten partners, exact translations.
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

namespace test_query_polygon_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("polygon_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("polygon_tetrahedron: fixtures", "[polygon_tetrahedron]") {
    CHECK(intersects(holed, tetrahedron3{{0.5, 0.5, 1}, {0, 0, 3}, {1, 0, 3}, {0, 1, 3}}));
    CHECK_FALSE(intersects(holed, tetrahedron3{{0.5, 0.5, 0x1.0000000000001p0}, {0, 0, 3}, {1, 0, 3}, {0, 1, 3}}));
    CHECK_FALSE(intersects(tetrahedron3{{1.5, 1.5, 0}, {2.5, 1.5, 0}, {2, 2.5, 0}, {2, 2, 2}}, holed)); // through the hole
    CHECK(intersects(holed, tetrahedron3{{-20, -20, -5}, {20, -20, -5}, {0, 20, -5}, {0, 0, 20}}));     // around it
}
TEST_CASE("polygon_tetrahedron: oracle, random and near-degenerate", "[polygon_tetrahedron][oracle]") {
    support::polygon3_oracle<tetrahedron3>("polygon_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("polygon_tetrahedron: rewritten shapes and exact translations give the same answer", "[polygon_tetrahedron]") {
    support::polygon3_symmetries<tetrahedron3>("polygon_tetrahedron", support::cases(5000));
}

} // namespace test_query_polygon_tetrahedron
