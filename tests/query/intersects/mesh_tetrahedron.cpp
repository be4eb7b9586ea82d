// mesh3 x tetrahedron3: fixtures (inside, around the mesh, in the dent, touching the apex);
// the CGAL Epeck oracle (the triangles by
// do_intersect, the inside by crossing parity with CGAL::orientation) on 20,000 random and 20,000
// near-degenerate cases (closed non-convex star meshes; the other shape through a vertex, an edge
// midpoint or a face point, along a face edge or not, or around the inside centre; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and reversed
// triangles, rewritten partners, exact translations.
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

namespace test_query_mesh_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("mesh_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("mesh_tetrahedron: fixtures", "[mesh_tetrahedron]") {
    CHECK(intersects(cube, tetrahedron3{{0.2, 0.2, 0.2}, {0.3, 0.2, 0.2}, {0.2, 0.3, 0.2}, {0.2, 0.2, 0.3}}));
    CHECK(intersects(cube, tetrahedron3{{-10, -10, -10}, {30, -10, -10}, {-10, 30, -10}, {-10, -10, 30}}));
    CHECK_FALSE(intersects(dented, tetrahedron3{{0.45, 0.45, 0.5}, {0.55, 0.45, 0.5}, {0.5, 0.55, 0.5}, {0.5, 0.5, 0.9}}));
    CHECK(intersects(dented, tetrahedron3{{0.45, 0.45, 0.5}, {0.55, 0.45, 0.5}, {0.5, 0.55, 0.5}, {0.5, 0.5, 0.25}}));
}
TEST_CASE("mesh_tetrahedron: oracle, random and near-degenerate", "[mesh_tetrahedron][oracle]") {
    support::mesh_oracle<tetrahedron3>("mesh_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("mesh_tetrahedron: rewrites of either shape and exact translations give the same answer", "[mesh_tetrahedron]") {
    support::mesh_symmetries<tetrahedron3>("mesh_tetrahedron", support::cases(20000));
}

} // namespace test_query_mesh_tetrahedron
