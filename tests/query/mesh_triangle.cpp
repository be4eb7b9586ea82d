// mesh3 x triangle3: fixtures (inside, in the dent, cutting through, in a face's plane); the CGAL Epeck oracle (the triangles by
// do_intersect, the inside by crossing parity with CGAL::orientation) on 20,000 random and 20,000
// near-degenerate cases (closed non-convex star meshes; the other shape through a vertex, an edge
// midpoint or a face point, along a face edge or not, or around the inside centre; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and reversed
// triangles, rewritten partners, exact translations.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "../oracle/cgal_oracle.hpp"
import incidence;
#include "../support/testing.hpp"
#include "../support/check.hpp"
#include "../support/flat_checks.hpp"
#include "../support/mesh_checks.hpp"
#include "../support/mesh_fixtures.hpp"

namespace test_query_mesh_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
constexpr double approx_bound = 0x1p-36; // stated in modules/query/mesh_triangle.cppm
} // namespace

TEST_CASE("mesh_triangle: fixtures", "[mesh_triangle]") {
    CHECK(intersects(cube, triangle3{{0.2, 0.2, 0.2}, {0.3, 0.2, 0.2}, {0.2, 0.3, 0.2}})); // inside
    CHECK_FALSE(intersects(dented, triangle3{{0.4, 0.5, 0.5}, {0.6, 0.5, 0.5}, {0.5, 0.6, 0.9}})); // in the dent
    CHECK(intersects(dented, triangle3{{0.4, 0.5, 0.5}, {0.6, 0.5, 0.5}, {0.5, 0.5, 0.25}}));
    CHECK(intersects(cube, triangle3{{-1, -1, 0}, {3, -1, 0}, {-1, 3, 0}}));                 // in the bottom face's plane
    CHECK_FALSE(intersects(cube, triangle3{{-1, -1, -0x1p-1074}, {3, -1, -0x1p-1074}, {-1, 3, -0x1p-1074}}));
}
TEST_CASE("mesh_triangle: oracle, random and near-degenerate", "[mesh_triangle][oracle]") {
    support::mesh_oracle<triangle3>("mesh_triangle", support::cases(20000), approx_bound);
}
TEST_CASE("mesh_triangle: rewrites of either shape and exact translations give the same answer", "[mesh_triangle]") {
    support::mesh_symmetries<triangle3>("mesh_triangle", support::cases(20000));
}

} // namespace test_query_mesh_triangle
