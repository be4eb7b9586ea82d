// mesh3 x segment3: fixtures (through the cube, in the dent, touching the dent's apex, inside,
// one ulp off a face); the CGAL Epeck oracle (the triangles by
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

namespace test_query_mesh_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
constexpr double approx_bound = 0x1p-36; // stated in modules/query/mesh_segment.cppm
} // namespace

TEST_CASE("mesh_segment: fixtures", "[mesh_segment]") {
    CHECK(intersects(cube, segment3{{-1, 0.5, 0.5}, {2, 0.5, 0.5}}));
    CHECK(intersects(cube, segment3{{0.2, 0.2, 0.2}, {0.3, 0.3, 0.3}}));      // inside
    CHECK_FALSE(intersects(dented, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 2}})); // in the dent
    CHECK(intersects(dented, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.25}}));   // down to the apex
    CHECK_FALSE(intersects(dented, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0x1.0000000000001p-2}}));
    CHECK_FALSE(intersects(segment3{{0x1.0000000000001p0, 0, 0}, {2, 1, 1}}, cube));
}
TEST_CASE("mesh_segment: oracle, random and near-degenerate", "[mesh_segment][oracle]") {
    support::mesh_oracle<segment3>("mesh_segment", support::cases(20000), approx_bound);
}
TEST_CASE("mesh_segment: rewrites of either shape and exact translations give the same answer", "[mesh_segment]") {
    support::mesh_symmetries<segment3>("mesh_segment", support::cases(20000));
}

} // namespace test_query_mesh_segment
