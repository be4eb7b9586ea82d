// capsule3 x mesh3: fixtures (a capsule inside the cube, through it, parallel above a face, along an
// edge, in the dent, each touching and one ulp short); every tier against the mesh's triangles by
// the exact QP against the capsule's segment (CGAL's QP_solver over Gmpzf) and the end a inside by
// exact crossing parity, on 2,500 random and 2,500 near-degenerate cases
// (testkit/ball_view_cases.hpp: capsules grown from balls touching closed star meshes, some
// parallel to the face, at scales 2^-500..2^500 and translated); both argument orders.
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

namespace test_query_capsule_mesh { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_mesh"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_mesh: fixtures", "[capsule_mesh]") {
    CHECK(intersects(capsule3{{0.25, 0.5, 0.5}, {0.75, 0.5, 0.5}, 0.125}, cube)); // inside, touching nothing
    CHECK(intersects(cube, capsule3{{0.5, 0.5, -5}, {0.5, 0.5, 5}, 0}));          // through it
    CHECK(intersects(cube, capsule3{{-10, 0.5, 3}, {10, 0.5, 3}, 2}));            // parallel above the top face
    CHECK_FALSE(intersects(cube, capsule3{{-10, 0.5, 3}, {10, 0.5, 3}, 0x1.fffffffffffffp0}));
    CHECK(intersects(cube, capsule3{{-10, 4, 5}, {10, 4, 5}, 5})); // along the edge y = z = 1: 3-4-5
    CHECK_FALSE(intersects(cube, capsule3{{-10, 4, 5}, {10, 4, 5}, 0x1.3ffffffffffffp2}));
    CHECK_FALSE(intersects(dented, capsule3{{0.5, 0.5, 0.75}, {0.5, 0.5, 0.9}, 0.125})); // in the dent, above the apex
    CHECK(intersects(dented, capsule3{{0.5, 0.5, 0.75}, {0.5, 0.5, 0.9}, 0.5}));
    CHECK_FALSE(intersects(cube, capsule3{{0.5, 0.5, 0.5}, {1, 1, 1}, std::nan("")}));
}
TEST_CASE("capsule_mesh: oracle, random and near-degenerate", "[capsule_mesh][oracle]") {
    support::round_view_oracle<mesh3, capsule3>("capsule_mesh", support::cases(2500), approx_bound);
}

} // namespace test_query_capsule_mesh
