// convex_polyhedron3 x mesh3: fixtures (a small box inside the cube, above the dent, a flat one on the dent's apex and one
// ulp above it, a box reaching under the dent's side, around the whole mesh, half-spaces touching a face and one ulp off); the oracle (the
// triangles by the exact LP, the inside by crossing parity with CGAL::orientation over Epeck from the LP's exact
// rational point of the set) on 20,000 random and 20,000 near-degenerate cases (closed non-convex star meshes; the
// supporting planes of a small dyadic cloud around a vertex, an edge midpoint or a face point, or around the inside
// centre; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and
// reversed triangles, rewritten sets, exact translations.
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

namespace test_query_convex_polyhedron_mesh { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("convex_polyhedron_mesh"); // stated in the catalog (modules/query/catalog.cppm)
constexpr convex_polyhedron3 box(point3 lo, point3 hi) {
    return {{plane3{{1, 0, 0}, hi.x}, plane3{{-1, 0, 0}, -lo.x}, plane3{{0, 1, 0}, hi.y}, plane3{{0, -1, 0}, -lo.y},
             plane3{{0, 0, 1}, hi.z}, plane3{{0, 0, -1}, -lo.z}},
            6};
}
} // namespace

TEST_CASE("convex_polyhedron_mesh: fixtures", "[convex_polyhedron_mesh]") {
    CHECK(intersects(box({0.4, 0.4, 0.4}, {0.6, 0.6, 0.6}), cube));             // inside: no triangle meets it, its vertex decides
    CHECK(intersects(cube, box({-1, -1, -1}, {2, 2, 2})));                      // around the whole mesh
    CHECK_FALSE(intersects(box({0.45, 0.45, 0.5}, {0.55, 0.55, 0.9}), dented)); // above the dent
    CHECK(intersects(box({0.5, 0.5, 0.25}, {0.5, 0.5, 0.9}), dented));          // a flat box (a segment) on the dent's apex
    CHECK_FALSE(intersects(box({0.5, 0.5, 0x1.0000000000001p-2}, {0.5, 0.5, 0.9}), dented));
    CHECK(intersects(box({0.5, 0.5, 0x1.0000000000001p-2}, {0.55, 0.55, 0.9}), dented)); // reaching under the dent's side
    CHECK(intersects(convex_polyhedron3{{plane3{{1, 0, 0}, 0}}, 1}, cube));              // x <= 0: the face x = 0
    CHECK_FALSE(intersects(convex_polyhedron3{{plane3{{1, 0, 0}, -0x1p-1074}}, 1}, cube));
    CHECK_FALSE(intersects(convex_polyhedron3{{plane3{{1, 0, 0}, 1}, plane3{{-1, 0, 0}, -2}}, 2}, cube)); // empty
}
TEST_CASE("convex_polyhedron_mesh: oracle, random and near-degenerate", "[convex_polyhedron_mesh][oracle]") {
    support::mesh_oracle<convex_polyhedron3>("convex_polyhedron_mesh", support::cases(20000), approx_bound);
}
TEST_CASE("convex_polyhedron_mesh: rewrites of either shape and exact translations give the same answer", "[convex_polyhedron_mesh]") {
    support::mesh_symmetries<convex_polyhedron3>("convex_polyhedron_mesh", support::cases(5000));
}

} // namespace test_query_convex_polyhedron_mesh
