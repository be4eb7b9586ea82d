// line3 x mesh3: fixtures (through the cube, along an edge, one ulp beside it, through the dent's
// apex); the CGAL Epeck oracle (the triangles by
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

namespace test_query_line_mesh { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("line_mesh"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line_mesh: fixtures", "[line_mesh]") {
    CHECK(intersects(line3{{5, 0.5, 0.5}, {1, 0, 0}}, cube));
    CHECK(intersects(cube, line3{{5, 1, 1}, {1, 0, 0}})); // along an edge
    CHECK_FALSE(intersects(cube, line3{{5, 1, 0x1.0000000000001p0}, {1, 0, 0}}));
    CHECK(intersects(line3{{0.5, 0.5, 7}, {0, 0, 1}}, dented));
}
TEST_CASE("line_mesh: oracle, random and near-degenerate", "[line_mesh][oracle]") {
    support::mesh_oracle<line3>("line_mesh", support::cases(20000), approx_bound);
}
TEST_CASE("line_mesh: rewrites of either shape and exact translations give the same answer", "[line_mesh]") {
    support::mesh_symmetries<line3>("line_mesh", support::cases(20000));
}

} // namespace test_query_line_mesh
