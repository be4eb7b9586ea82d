// polygon3 x sphere3: fixtures (a ball on the face, on an edge, at a vertex, over the hole, and one
// ulp short; a ball around the polygon); every tier against the polygon's CGAL constrained
// triangulation, each triangle by CGAL's squared distance from the centre over Epeck, on 10,000
// random and 10,000 near-degenerate cases (testkit/ball_view_cases.hpp: balls touching star
// polygons with holes at a vertex, an edge point or a face point, exactly or within ulps, at scales
// 2^-500..2^500); both argument orders.
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
#include "testkit/capsule_checks.hpp"
#include "testkit/ball_view_checks.hpp"

namespace test_query_polygon_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("polygon_sphere"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("polygon_sphere: fixtures", "[polygon_sphere]") {
    // holed: the square [0, 4]^2 at z = 1 with the hole [1, 3]^2 (polygon3_fixtures.hpp)
    CHECK(intersects(holed, sphere3{{0.5, 0.5, 3}, 2})); // on the face
    CHECK_FALSE(intersects(holed, sphere3{{0.5, 0.5, 3}, 0x1.fffffffffffffp0}));
    CHECK(intersects(sphere3{{2, 2, 1}, 1}, holed)); // in the hole, touching its edges
    CHECK_FALSE(intersects(sphere3{{2, 2, 1}, 0x1.fffffffffffffp-1}, holed));
    CHECK_FALSE(intersects(holed, sphere3{{2, 2, 1.5}, 1})); // over the hole
    CHECK(intersects(holed, sphere3{{7, 8, 1}, 5}));         // at the corner (4, 4): 3-4-5
    CHECK_FALSE(intersects(holed, sphere3{{7, 8, 1}, 0x1.3ffffffffffffp2}));
    CHECK(intersects(holed, sphere3{{2, 2, 1}, 100})); // around it
    CHECK(intersects(holed, sphere3{{2, -3, 5}, 5}));  // at the edge y = 0: 3-4-5
    CHECK_FALSE(intersects(holed, sphere3{{2, -3, 5}, 0x1.3ffffffffffffp2}));
    CHECK_FALSE(intersects(holed, sphere3{{2, 2, 1}, std::nan("")}));
}
TEST_CASE("polygon_sphere: oracle, random and near-degenerate", "[polygon_sphere][oracle]") {
    support::round_view_oracle<polygon3, sphere3>("polygon_sphere", support::cases(10000), approx_bound);
}

} // namespace test_query_polygon_sphere
