// capsule3 x polygon3: fixtures (a capsule through the face, one parallel above it, one along an
// edge, one through the hole, each touching and one ulp short); every tier against the polygon's
// CGAL constrained triangulation, each triangle by the exact QP against the capsule's segment
// (CGAL's QP_solver over Gmpzf), on 5,000 random and 5,000 near-degenerate cases
// (testkit/ball_view_cases.hpp: capsules grown from balls touching star polygons with holes,
// some parallel to the plane, at scales 2^-500..2^500); both argument orders.
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

namespace test_query_capsule_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_polygon"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_polygon: fixtures", "[capsule_polygon]") {
    // holed: the square [0, 4]^2 at z = 1 with the hole [1, 3]^2 (polygon3_fixtures.hpp)
    CHECK(intersects(capsule3{{0.5, 0.5, -5}, {0.5, 0.5, 5}, 0}, holed)); // through the face
    CHECK_FALSE(intersects(capsule3{{2, 2, -5}, {2, 2, 5}, 0.5}, holed)); // through the hole
    CHECK(intersects(capsule3{{2, 2, -5}, {2, 2, 5}, 1}, holed));         // touching the hole's edges
    CHECK_FALSE(intersects(capsule3{{2, 2, -5}, {2, 2, 5}, 0x1.fffffffffffffp-1}, holed));
    CHECK(intersects(holed, capsule3{{-10, 0.5, 3}, {10, 0.5, 3}, 2})); // parallel above the face
    CHECK_FALSE(intersects(holed, capsule3{{-10, 0.5, 3}, {10, 0.5, 3}, 0x1.fffffffffffffp0}));
    CHECK(intersects(holed, capsule3{{-10, -3, 5}, {10, -3, 5}, 5})); // along the edge y = 0: 3-4-5
    CHECK_FALSE(intersects(holed, capsule3{{-10, -3, 5}, {10, -3, 5}, 0x1.3ffffffffffffp2}));
    CHECK(intersects(holed, capsule3{{7, 8, 1}, {7, 8, 9}, 5})); // an end at the corner (4, 4)
    CHECK_FALSE(intersects(holed, capsule3{{7, 8, 1}, {7, 8, 9}, 0x1.3ffffffffffffp2}));
    CHECK_FALSE(intersects(holed, capsule3{{7, 8, 1}, {7, 8, 9}, std::nan("")}));
}
TEST_CASE("capsule_polygon: oracle, random and near-degenerate", "[capsule_polygon][oracle]") {
    support::round_view_oracle<polygon3, capsule3>("capsule_polygon", support::cases(5000), approx_bound);
}

} // namespace test_query_capsule_polygon
