// mesh3 x ray3: fixtures (from inside, out of the dent upwards, down onto the apex, along a face);
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

namespace test_query_mesh_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("mesh_ray"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("mesh_ray: fixtures", "[mesh_ray]") {
    CHECK(intersects(cube, ray3{{0.3, 0.3, 0.3}, {1, 2, 3}}));
    CHECK_FALSE(intersects(dented, ray3{{0.5, 0.5, 0.5}, {0, 0, 1}}));
    CHECK(intersects(dented, ray3{{0.5, 0.5, 0.5}, {0, 0, -1}}));
    CHECK(intersects(ray3{{-1, 0, 0.5}, {1, 0, 0}}, cube)); // along the face y = 0
    CHECK_FALSE(intersects(ray3{{-1, -0x1p-1074, 0.5}, {1, 0, 0}}, cube));
}
TEST_CASE("mesh_ray: oracle, random and near-degenerate", "[mesh_ray][oracle]") {
    support::mesh_oracle<ray3>("mesh_ray", support::cases(20000), approx_bound);
}
TEST_CASE("mesh_ray: rewrites of either shape and exact translations give the same answer", "[mesh_ray]") {
    support::mesh_symmetries<ray3>("mesh_ray", support::cases(20000));
}

} // namespace test_query_mesh_ray
