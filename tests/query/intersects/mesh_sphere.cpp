// mesh3 x sphere3: fixtures (a ball inside the cube, around it, on a face, at a corner, in the dent,
// each touching and one ulp short); every tier against the mesh's triangles by CGAL's squared
// distance from the centre over Epeck and the centre inside by exact crossing parity, on 10,000
// random and 10,000 near-degenerate cases (testkit/ball_view_cases.hpp: balls touching closed star
// meshes at a vertex, an edge point or a face point, exactly or within ulps, at scales
// 2^-500..2^500 and translated); both argument orders.
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
#include "testkit/polygon3_cases.hpp"
#include "testkit/polygon3_checks.hpp"
#include "testkit/capsule_checks.hpp"
#include "testkit/ball_view_checks.hpp"

namespace test_query_mesh_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("mesh_sphere"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("mesh_sphere: fixtures", "[mesh_sphere]") {
    CHECK(intersects(cube, sphere3{{0.5, 0.5, 0.5}, 0.125})); // inside, touching nothing
    CHECK(intersects(sphere3{{0.5, 0.5, 0.5}, 10}, cube));    // around it
    CHECK(intersects(cube, sphere3{{0.5, 0.5, 3}, 2}));       // on the top face
    CHECK_FALSE(intersects(cube, sphere3{{0.5, 0.5, 3}, 0x1.fffffffffffffp0}));
    CHECK(intersects(cube, sphere3{{4, 5, 1}, 5})); // at the corner (1, 1, 1): 3-4-5
    CHECK_FALSE(intersects(cube, sphere3{{4, 5, 1}, 0x1.3ffffffffffffp2}));
    CHECK_FALSE(intersects(dented, sphere3{{0.5, 0.5, 0.75}, 0.125})); // in the dent, above the apex (1/2, 1/2, 1/4)
    CHECK(intersects(dented, sphere3{{0.5, 0.5, 0.75}, 0.5}));
    CHECK_FALSE(intersects(cube, sphere3{{0.5, 0.5, 0.5}, std::nan("")}));
}
TEST_CASE("mesh_sphere: oracle, random and near-degenerate", "[mesh_sphere][oracle]") {
    support::round_view_oracle<mesh3, sphere3>("mesh_sphere", support::cases(10000), approx_bound);
}

} // namespace test_query_mesh_sphere
