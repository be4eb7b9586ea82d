// obb3 x polygon3: fixtures (a turned box in the hole touching its edges and one ulp smaller, a box
// over the ring and one ulp short, flat boxes in the plane); the oracle (the polygon's CGAL
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

namespace test_query_obb_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("obb_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("obb_polygon: fixtures", "[obb_polygon]") {
    constexpr std::array<vec3, 3> turned{vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}};
    constexpr std::array<vec3, 3> unit{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
    CHECK(intersects(obb3{{2, 2, 1}, turned, {0.5, 0.5, 1}}, holed)); // |x - 2| + |y - 2| <= 1 touches the hole's edges
    CHECK_FALSE(intersects(obb3{{2, 2, 1}, turned, {0x1.fffffffffffffp-2, 0x1.fffffffffffffp-2, 1}}, holed));
    CHECK(intersects(holed, obb3{{0.5, 0.5, 5}, turned, {0.25, 0.25, 4}}));
    CHECK_FALSE(intersects(holed, obb3{{0.5, 0.5, 5}, turned, {0.25, 0.25, 0x1.fffffffffffffp1}}));
    CHECK(intersects(obb3{{3.5, 3.5, 1}, unit, {0.25, 0.25, 0}}, holed));   // flat, in the plane, inside
    CHECK_FALSE(intersects(obb3{{2, 2, 1}, unit, {0.25, 0.25, 0}}, holed)); // flat, in the hole
}
TEST_CASE("obb_polygon: oracle, random and near-degenerate", "[obb_polygon][oracle]") {
    support::polygon3_oracle<obb3>("obb_polygon", support::cases(20000), approx_bound);
}
TEST_CASE("obb_polygon: rewritten shapes and exact translations give the same answer", "[obb_polygon]") {
    support::polygon3_symmetries<obb3>("obb_polygon", support::cases(5000));
}

} // namespace test_query_obb_polygon
