// mesh3 x point3 and contains(mesh, point): fixtures (inside the cube with the first ray through
// an edge, on a face, one ulp outside, in the dent of a non-convex cube; make() refusing open,
// empty, out-of-range and non-finite meshes; unchecked bad meshes answering no); the CGAL Epeck oracle (the triangles by
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

namespace test_query_mesh_point { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("mesh_point"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("mesh_point: fixtures", "[mesh_point]") {
    CHECK(intersects(cube, point3{0.3, 0.3, 0.3})); // the ray along +x meets the diagonal y = z: retried
    CHECK(intersects(point3{1, 0.5, 0.25}, cube));  // on a face
    CHECK_FALSE(intersects(cube, point3{0x1.0000000000001p0, 0.5, 0.25}));
    CHECK(intersects(dented, point3{0.5, 0.5, 0.2}));       // under the dent
    CHECK_FALSE(intersects(dented, point3{0.5, 0.5, 0.5})); // in the dent
    CHECK(intersects(dented, point3{0.5, 0.5, 0.25}));      // its apex
    CHECK(intersects(dented, point3{0.1, 0.5, 0.8}));
    CHECK_FALSE(intersects(dented, point3{0.1, 0.5, 0.9}));
    CHECK(contains(dented, point3{0.5, 0.5, 0.2}));
    CHECK_FALSE(contains(dented, point3{0.5, 0.5, 0.3}));
    CHECK(mesh3::make(cube.vertices, cube.triangles).has_value());
    CHECK(mesh3::make(dented.vertices, dented.triangles).has_value());
    CHECK(mesh3::make(cube.vertices, cube.triangles.first(11)).error().code == errc::open_mesh);
    CHECK(mesh3::make(cube.vertices.first(7), cube.triangles).error().code == errc::index_out_of_range);
    CHECK(mesh3::make(cube.vertices, {}).error().code == errc::empty_input);
    std::array<point3, 8> bad;
    for (unsigned i = 0; i < 8; ++i) bad[i] = cube.vertices[i];
    bad[3].y = std::nan("");
    CHECK(mesh3::make(bad, cube.triangles).error().code == errc::not_finite);
    CHECK_FALSE(intersects(mesh3{bad, cube.triangles}, point3{0.3, 0.3, 0.3}));
    CHECK_FALSE(intersects(mesh3{cube.vertices.first(7), cube.triangles}, point3{0.3, 0.3, 0.3})); // an index out of range
}
TEST_CASE("mesh_point: oracle, random and near-degenerate", "[mesh_point][oracle]") {
    support::mesh_oracle<point3>("mesh_point", support::cases(20000), approx_bound);
}
TEST_CASE("mesh_point: rewrites of either shape and exact translations give the same answer", "[mesh_point]") {
    support::mesh_symmetries<point3>("mesh_point", support::cases(20000));
}

} // namespace test_query_mesh_point
