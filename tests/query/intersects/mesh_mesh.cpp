// mesh3 x mesh3: fixtures (the dented cube against a copy in its dent, moved one ulp up, inside
// a larger cube); CGAL::Polygon_mesh_processing::do_intersect (Epeck, with the bounded sides'
// overlap test) on 20,000 random and 20,000 near-degenerate cases (closed non-convex star meshes,
// the second with a surface point at one of the first's: a vertex, an edge midpoint or a face
// point; then a random exact-or-nudged scale 2^-500..2^500 and translation); both argument
// orders, rotated and reversed triangles.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/mesh_checks.hpp"
#include "testkit/mesh_fixtures.hpp"

namespace test_query_mesh_mesh { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("mesh_mesh"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("mesh_mesh: fixtures", "[mesh_mesh]") {
    std::array<point3, 8> up;
    for (unsigned i = 0; i < 8; ++i) up[i] = cube.vertices[i] + vec3{0.5, 0, 0.25};
    CHECK(intersects(dented, mesh3{up, support::cube_triangles})); // overlaps
    std::array<point3, 8> small;
    for (unsigned i = 0; i < 8; ++i)
        small[i] = point3{0.4 + 0.1 * cube.vertices[i].x, 0.4 + 0.1 * cube.vertices[i].y, 0.6 + 0.1 * cube.vertices[i].z};
    CHECK_FALSE(intersects(dented, mesh3{small, support::cube_triangles})); // a small cube in the dent
    for (unsigned i = 0; i < 8; ++i) small[i].z -= 0.5;                     // now inside, under the dent
    CHECK(intersects(dented, mesh3{small, support::cube_triangles}));
}
TEST_CASE("mesh_mesh: oracle, random and near-degenerate", "[mesh_mesh][oracle]") {
    support::mesh_oracle<mesh3>("mesh_mesh", support::cases(20000), approx_bound);
}
TEST_CASE("mesh_mesh: rewrites of either shape give the same answer", "[mesh_mesh]") {
    support::mesh_symmetries<mesh3>("mesh_mesh", support::cases(20000));
}

} // namespace test_query_mesh_mesh
