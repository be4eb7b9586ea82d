// frustum3 x mesh3: fixtures (the integer frustum shrunk 16 times inside the cube, above the dent, the integer frustum
// on the cube's top face and 2^-52 above it, a camera frustum looking at the mesh and one looking away); the oracle
// (the triangles by the exact LP, the inside by crossing parity with CGAL::orientation over Epeck from the LP's exact
// rational point of the frustum) on 20,000 random and 20,000 near-degenerate cases (closed non-convex star meshes;
// an axis-aligned integer frustum shrunk 16 times with a boundary point at a vertex, an edge midpoint or a face
// point, or at the inside centre, or a camera frustum; then a random exact-or-nudged scale 2^-500..2^500 and
// translation); both argument orders, rotated and reversed triangles, rewritten frustums, exact translations.
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
#include "testkit/polyhedron_fixtures.hpp"

namespace test_query_frustum_mesh { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;
using support::polyhedron_fixtures::camera;
using support::polyhedron_fixtures::integer_frustum;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_mesh"); // stated in the catalog (modules/query/catalog.cppm)
// f scaled by s about the origin, then moved to c: n . x <= o becomes n . x <= n . c + s o (exact here)
constexpr frustum3 shrunk(const frustum3& f, double s, point3 c) {
    frustum3 g = f;
    for (auto& p : g.planes) p.offset = dot(p.normal, c - point3{0, 0, 0}) + s * p.offset;
    return g;
}
} // namespace

TEST_CASE("frustum_mesh: fixtures", "[frustum_mesh]") {
    CHECK(intersects(shrunk(integer_frustum, 0.0625, {0.5, 0.5, 0.25}), cube));        // inside: its vertex decides
    CHECK_FALSE(intersects(dented, shrunk(integer_frustum, 0.0625, {0.5, 0.5, 0.5}))); // above the dent
    CHECK(intersects(integer_frustum, cube));                                          // the near face on the top face
    CHECK_FALSE(intersects(shrunk(integer_frustum, 1, {0, 0, 0x1p-52}), cube));        // moved 2^-52 up
    CHECK_FALSE(intersects(camera, cube)); // looking down -z from the origin: the cube is behind
    CHECK(intersects(frustum3::from_camera({0.5, 0.5, 5}, {0, 0, -1}, {0, 1, 0}, 0.5, 1.0, 1.0, 100.0).value(), dented));
}
TEST_CASE("frustum_mesh: oracle, random and near-degenerate", "[frustum_mesh][oracle]") {
    support::mesh_oracle<frustum3>("frustum_mesh", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_mesh: rewrites of either shape and exact translations give the same answer", "[frustum_mesh]") {
    support::mesh_symmetries<frustum3>("frustum_mesh", support::cases(5000));
}

} // namespace test_query_frustum_mesh
