// mesh3 x obb3: fixtures (inside, around, a rotated box in the dent); the exact LP for the
// triangles and crossing parity by CGAL::orientation for the inside, on 20,000 random and 20,000
// near-degenerate cases (an LP per triangle near the box) (closed non-convex star meshes; a box's corner, edge or face point at a
// vertex, an edge midpoint or a face point of the mesh, or at its centre; skew frames, ulp nudges,
// 2^+-500); both argument orders, rotated and reversed triangles.
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

namespace test_query_mesh_obb { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("mesh_obb"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("mesh_obb: fixtures", "[mesh_obb]") {
    const std::array<vec3, 3> I{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
    CHECK(intersects(cube, obb3{{0.5, 0.5, 0.5}, I, {0.1, 0.1, 0.1}}));
    CHECK(intersects(obb3{{0.5, 0.5, 0.5}, I, {5, 5, 5}}, cube));
    const std::array<vec3, 3> R{vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}};
    CHECK_FALSE(intersects(dented, obb3{{0.5, 0.5, 0.8}, R, {0.05, 0.05, 0.1}}));
    CHECK(intersects(dented, obb3{{0.5, 0.5, 0.35}, R, {0.05, 0.05, 0.1}}));
}
TEST_CASE("mesh_obb: oracle, random and near-degenerate", "[mesh_obb][oracle]") {
    support::mesh_oracle<obb3>("mesh_obb", support::cases(20000), approx_bound); // an LP per triangle near the box
}
TEST_CASE("mesh_obb: rewrites of either shape give the same answer", "[mesh_obb]") {
    support::mesh_symmetries<obb3>("mesh_obb", support::cases(20000));
}

} // namespace test_query_mesh_obb
