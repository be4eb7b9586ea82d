// polygon3 x ray3: fixtures (down onto the polygon, away from it, through the hole, along the plane,
// onto a hole corner and one ulp beside it); the oracle (the polygon's CGAL constrained triangulation,
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

namespace test_query_polygon_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("polygon_ray"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("polygon_ray: fixtures", "[polygon_ray]") {
    CHECK(intersects(holed, ray3{{0.5, 0.5, 3}, {0, 0, -1}}));
    CHECK_FALSE(intersects(ray3{{0.5, 0.5, 3}, {0, 0, 1}}, holed));
    CHECK_FALSE(intersects(holed, ray3{{2, 2, 3}, {0, 0, -1}})); // through the hole
    CHECK(intersects(holed, ray3{{2, 2, 1}, {1, 0, 0}}));        // in the plane, from the hole outwards
    CHECK(intersects(holed, ray3{{2.5, 2.5, 3}, {1, 1, -4}}));   // lands at (3, 3, 1), a hole corner
    CHECK_FALSE(intersects(holed, ray3{{2.5, 2.5, 3}, {1, 1, -0x1.0000000000001p2}}));
}
TEST_CASE("polygon_ray: oracle, random and near-degenerate", "[polygon_ray][oracle]") {
    support::polygon3_oracle<ray3>("polygon_ray", support::cases(20000), approx_bound);
}
TEST_CASE("polygon_ray: rewritten shapes and exact translations give the same answer", "[polygon_ray]") {
    support::polygon3_symmetries<ray3>("polygon_ray", support::cases(5000));
}

} // namespace test_query_polygon_ray
