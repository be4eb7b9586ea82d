// kdop<K> x mesh3: fixtures (a small 6-DOP and 14-DOP inside the cube, above the dent, a flat one on the dent's apex and one
// ulp above it, the cut cube on the cube); the oracle (the triangles by the exact LP, the inside by crossing
// parity with CGAL::orientation over Epeck from the LP's exact rational point of the k-DOP) on 5,000 random and 5,000
// near-degenerate cases for each K = 6, 14, 18, 26 (20,000 and 20,000 in all: closed non-convex star meshes; the
// k-DOP of a small dyadic cloud around a vertex, an edge midpoint or a face point, or around the inside centre; then
// a random exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and reversed
// triangles, exact translations.
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
#include "testkit/mesh_fixtures.hpp"
#include "testkit/kdop_fixtures.hpp"

namespace test_query_kdop_mesh { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_mesh"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("kdop_mesh: fixtures", "[kdop_mesh]") {
    CHECK(intersects(kdop<6>{{0.4, 0.4, 0.4}, {0.6, 0.6, 0.6}}, cube)); // inside: its vertex decides
    CHECK(intersects(cube, kdop<14>{{0.4, 0.4, 0.4, -5, -5, -5, -5}, {0.6, 0.6, 0.6, 5, 5, 5, 5}}));
    CHECK_FALSE(intersects(kdop<6>{{0.45, 0.45, 0.5}, {0.55, 0.55, 0.9}}, dented)); // above the dent
    CHECK(intersects(kdop<6>{{0.5, 0.5, 0.25}, {0.5, 0.5, 0.9}}, dented));          // a flat 6-DOP (a segment) on the dent's apex
    CHECK_FALSE(intersects(kdop<6>{{0.5, 0.5, 0x1.0000000000001p-2}, {0.5, 0.5, 0.9}}, dented));
    CHECK(intersects(corner_cut, cube));
}
TEST_CASE("kdop_mesh: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[kdop_mesh][oracle]") {
    support::mesh_oracle<kdop<6>>("kdop_mesh 6-dop", support::cases(5000), approx_bound);
    support::mesh_oracle<kdop<14>>("kdop_mesh 14-dop", support::cases(5000), approx_bound);
    support::mesh_oracle<kdop<18>>("kdop_mesh 18-dop", support::cases(5000), approx_bound);
    support::mesh_oracle<kdop<26>>("kdop_mesh 26-dop", support::cases(5000), approx_bound);
}
TEST_CASE("kdop_mesh: rewrites of either shape and exact translations give the same answer", "[kdop_mesh]") {
    support::mesh_symmetries<kdop<14>>("kdop_mesh 14-dop", support::cases(2500));
    support::mesh_symmetries<kdop<26>>("kdop_mesh 26-dop", support::cases(2500));
}

} // namespace test_query_kdop_mesh
