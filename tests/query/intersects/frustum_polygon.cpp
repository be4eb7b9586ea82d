// frustum3 x polygon3: fixtures (the integer frustum's section [-1, 1]^2 at z = 1 inside a ring's hole
// and touching a tighter hole's edges, the holed square, a camera frustum behind the eye); the oracle
// (the polygon's CGAL constrained triangulation, each triangle against the other shape by CGAL Epeck,
// the exact LP or the mesh oracle) on 20,000 random and 20,000 near-degenerate cases
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

namespace test_query_frustum_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_polygon: fixtures", "[frustum_polygon]") {
    CHECK_FALSE(intersects(integer_frustum, ring)); // its section lies in the hole
    CHECK(intersects(integer_frustum, holed));      // [0, 1]^2 at z = 1
    CHECK(intersects(holed, integer_frustum));
    static constexpr std::array<point3, 8> tight{
        {{-2, -2, 1}, {2, -2, 1}, {2, 2, 1}, {-2, 2, 1}, {-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}}};
    CHECK(intersects(integer_frustum, polygon3{tight, holed_ends, {0, 2, 1}, 2})); // the hole's edges on its section's
    CHECK_FALSE(intersects(camera, holed)); // the camera looks down -z from the origin: z = 1 is behind it
}
TEST_CASE("frustum_polygon: oracle, random and near-degenerate", "[frustum_polygon][oracle]") {
    support::polygon3_oracle<frustum3>("frustum_polygon", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_polygon: rewritten shapes and exact translations give the same answer", "[frustum_polygon]") {
    support::polygon3_symmetries<frustum3>("frustum_polygon", support::cases(5000));
}

} // namespace test_query_frustum_polygon
