// frustum3 x frustum3: fixtures (the integer frustum and its reflections through a corner, an edge midpoint and a
// face centre, touching, and one ulp or 2^-38 apart; a camera frustum; a frustum with an empty pair of planes); the exact LP
// oracle (both as their half-spaces n . x <= offset) on 20,000 random and 20,000 near-degenerate cases (an
// axis-aligned integer frustum (corners dyadic) with the second reflected through one of its boundary points or a
// second such frustum moved there, a third of the time moved a quarter or 2^-20 out along the face; then a random
// exact-or-nudged scale 2^-500..2^500 and translation; random: two camera frustums, frustum3::from_camera); both
// argument orders in every tier, rewritten shapes, exact translations of both.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/polyhedron_cases.hpp"
#include "testkit/polyhedron_checks.hpp"
#include "testkit/polyhedron_fixtures.hpp"

namespace test_query_frustum_frustum { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_frustum"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_frustum: fixtures", "[frustum_frustum]") {
    CHECK(intersects(integer_frustum, integer_frustum));
    CHECK(intersects(integer_frustum, reflected(integer_frustum, {4, 4, 4}))); // the far corner: touching there only
    CHECK(intersects(reflected(integer_frustum, {0, 4, 4}), integer_frustum)); // a far edge's midpoint: along that edge
    CHECK(intersects(integer_frustum, reflected(integer_frustum, {0, 0, 1}))); // the near face's centre: the near face
    CHECK_FALSE(intersects(integer_frustum, reflected(integer_frustum, {0x1.0000000001p2, 4, 4}))); // 2^-38 beyond it (exact planes)
    CHECK_FALSE(intersects(reflected(integer_frustum, {0, 0, 0x1.fffffffffffffp-1}), integer_frustum));
    CHECK(intersects(camera, reflected(integer_frustum, {0, 0, -1}))); // z in [-6, -3], inside the camera's view
    CHECK_FALSE(intersects(camera, integer_frustum));                  // z >= 1 against z <= -1
    frustum3 empty = integer_frustum;
    empty.planes[1] = plane3{{0, 0, 1}, 0.5}; // near z >= 1 and far z <= 1/2
    CHECK_FALSE(intersects(empty, integer_frustum));
    CHECK_FALSE(intersects(integer_frustum, empty));
}
TEST_CASE("frustum_frustum: oracle, random and near-degenerate", "[frustum_frustum][oracle]") {
    support::halfspace_oracle<frustum3, frustum3>("frustum_frustum", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_frustum: rewrites of both shapes and exact translations give the same answer", "[frustum_frustum]") {
    support::halfspace_symmetries<frustum3, frustum3>("frustum_frustum", support::cases(5000));
}

} // namespace test_query_frustum_frustum
