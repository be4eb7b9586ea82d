// aabb3 x mesh3: fixtures (inside, around, in the dent, touching the apex, one ulp above it);
// the CGAL Epeck oracle (the triangles by
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

namespace test_query_aabb_mesh { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
constexpr double approx_bound = 0x1p-36; // stated in modules/query/aabb_mesh.cppm
} // namespace

TEST_CASE("aabb_mesh: fixtures", "[aabb_mesh]") {
    CHECK(intersects(aabb3{{0.2, 0.2, 0.2}, {0.3, 0.3, 0.3}}, cube));
    CHECK(intersects(cube, aabb3{{-1, -1, -1}, {2, 2, 2}}));
    CHECK_FALSE(intersects(aabb3{{0.45, 0.45, 0.5}, {0.55, 0.55, 0.9}}, dented));
    CHECK(intersects(aabb3{{0.5, 0.5, 0.25}, {0.55, 0.55, 0.9}}, dented));
    CHECK_FALSE(intersects(aabb3{{0.5, 0.5, 0x1.0000000000001p-2}, {0.5, 0.5, 0.9}}, dented));
    CHECK_FALSE(intersects(aabb3{{2, 2, 2}, {-1, -1, -1}}, cube)); // inverted: empty
}
TEST_CASE("aabb_mesh: oracle, random and near-degenerate", "[aabb_mesh][oracle]") {
    support::mesh_oracle<aabb3>("aabb_mesh", support::cases(20000), approx_bound);
}
TEST_CASE("aabb_mesh: rewrites of either shape and exact translations give the same answer", "[aabb_mesh]") {
    support::mesh_symmetries<aabb3>("aabb_mesh", support::cases(20000));
}

} // namespace test_query_aabb_mesh
