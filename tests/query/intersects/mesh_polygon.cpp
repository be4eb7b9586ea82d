// mesh3 x polygon3: fixtures (the unit cube's top face on the polygon, a triangle one ulp above the
// cube, a triangle wholly inside the solid cube, in the dent of the dented one and below it); the
// oracle (the polygon's CGAL constrained triangulation, each triangle against the other shape by CGAL
// Epeck, the exact LP or the mesh oracle) on 20,000 random and 20,000 near-degenerate cases
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

namespace test_query_mesh_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("mesh_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("mesh_polygon: fixtures", "[mesh_polygon]") {
    CHECK(intersects(support::cube, holed)); // the cube's top face is at z = 1
    static constexpr std::array<point3, 3> above{
        {{0.25, 0.25, 0x1.0000000000001p0}, {0.75, 0.25, 0x1.0000000000001p0}, {0.5, 0.75, 0x1.0000000000001p0}}};
    CHECK_FALSE(intersects(polygon3{above, {}, {0, 1, 2}, 2}, support::cube));
    static constexpr std::array<point3, 3> inside{{{0.25, 0.25, 0.75}, {0.75, 0.25, 0.75}, {0.5, 0.75, 0.75}}};
    CHECK(intersects(support::cube, polygon3{inside, {}, {0, 1, 2}, 2}));         // wholly inside the solid
    CHECK_FALSE(intersects(support::dented, polygon3{inside, {}, {0, 1, 2}, 2})); // in the dent, which reaches down to z = 1/4
    static constexpr std::array<point3, 3> low{{{0.25, 0.25, 0.125}, {0.75, 0.25, 0.125}, {0.5, 0.75, 0.125}}};
    CHECK(intersects(support::dented, polygon3{low, {}, {0, 1, 2}, 2})); // below the dent: inside the solid
}
TEST_CASE("mesh_polygon: oracle, random and near-degenerate", "[mesh_polygon][oracle]") {
    support::polygon3_oracle<mesh3>("mesh_polygon", support::cases(20000), approx_bound);
}
TEST_CASE("mesh_polygon: rewritten shapes and exact translations give the same answer", "[mesh_polygon]") {
    support::polygon3_symmetries<mesh3>("mesh_polygon", support::cases(1000));
}

} // namespace test_query_mesh_polygon
