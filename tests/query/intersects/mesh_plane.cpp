// mesh3 x plane3: fixtures (through a face, one ulp past it, through the dent's apex, zero
// normals); the CGAL Epeck oracle (the triangles by
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

namespace test_query_mesh_plane { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("mesh_plane"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("mesh_plane: fixtures", "[mesh_plane]") {
    CHECK(intersects(cube, plane3{{0, 0, 1}, 1}));
    CHECK_FALSE(intersects(cube, plane3{{0, 0, 1}, 0x1.0000000000001p0}));
    CHECK(intersects(plane3{{1, 1, 1}, 1.5}, dented));
    CHECK(intersects(dented, plane3{{0, 0, 1}, 0.25}));
    CHECK(intersects(cube, plane3{{0, 0, 0}, 0}));
    CHECK_FALSE(intersects(cube, plane3{{0, 0, 0}, 1}));
}
TEST_CASE("mesh_plane: oracle, random and near-degenerate", "[mesh_plane][oracle]") {
    support::mesh_oracle<plane3>("mesh_plane", support::cases(20000), approx_bound);
}
TEST_CASE("mesh_plane: rewrites of either shape and exact translations give the same answer", "[mesh_plane]") {
    support::mesh_symmetries<plane3>("mesh_plane", support::cases(20000));
}

} // namespace test_query_mesh_plane
