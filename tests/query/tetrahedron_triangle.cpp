// tetrahedron3 x triangle3: fixtures (piercing it with no vertex inside, in a face's plane, one
// ulp below it, inside, touching at a vertex, coplanar tetrahedra and collinear triangles, NaN);
// the CGAL Epeck oracle (Tetrahedron_3; the exact LP for coplanar tetrahedra) on 20,000 random and
// 20,000 near-degenerate cases (touching at a vertex, an edge or face point, crossing, just
// missing; triangles in and parallel to a face's plane; degenerate shapes; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and
// reflected vertex orders of both, exact translations.
#include <catch2/catch_test_macros.hpp>
#include "../oracle/cgal_oracle.hpp"
import incidence;
#include "../support/testing.hpp"
#include "../support/check.hpp"
#include "../support/flat_checks.hpp"

namespace test_query_tetrahedron_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
constexpr double approx_bound = 0x1p-36; // stated in modules/query/tetrahedron_triangle.cppm
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("tetrahedron_triangle: fixtures", "[tetrahedron_triangle]") {
    CHECK(intersects(T, triangle3{{-5, -5, 0.5}, {5, -5, 0.5}, {0, 5, 0.5}}));   // cuts it, no vertex inside
    CHECK(intersects(triangle3{{-1, -1, 0}, {3, -1, 0}, {-1, 3, 0}}, T));        // in the face z = 0
    CHECK_FALSE(intersects(T, triangle3{{-1, -1, -0x1p-1074}, {3, -1, -0x1p-1074}, {-1, 3, -0x1p-1074}}));
    CHECK(intersects(T, triangle3{{0.1, 0.1, 0.1}, {0.2, 0.1, 0.1}, {0.1, 0.2, 0.1}})); // inside
    CHECK(intersects(T, triangle3{{1, 0, 0}, {2, 0, 0}, {2, 1, 0}}));            // a shared vertex
    CHECK_FALSE(intersects(T, triangle3{{0x1.0000000000001p0, 0, 0}, {2, 0, 0}, {2, 1, 0}}));
    CHECK(intersects(T, triangle3{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0}}));   // its edge through an edge point
    CHECK(intersects(T, triangle3{{0.2, 0.2, -1}, {0.2, 0.2, 1}, {0.2, 0.2, 3}})); // collinear, through the solid
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};
    CHECK(intersects(flat, triangle3{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 1}}));
    CHECK_FALSE(intersects(flat, triangle3{{0.5, 0.5, 0x1p-1000}, {0.5, 0.6, 1}, {3, 3, 1}}));
    CHECK_FALSE(intersects(T, triangle3{{-5, -5, 0.5}, {5, -5, 0.5}, {0, 5, std::nan("")}}));
}
TEST_CASE("tetrahedron_triangle: oracle, random and near-degenerate", "[tetrahedron_triangle][oracle]") {
    support::flat_oracle<tetrahedron3, triangle3>("tetrahedron_triangle", support::cases(20000), approx_bound);
}
TEST_CASE("tetrahedron_triangle: rewrites of either shape and exact translations give the same answer", "[tetrahedron_triangle]") {
    support::flat_symmetries<tetrahedron3, triangle3>("tetrahedron_triangle", support::cases(20000));
}

} // namespace test_query_tetrahedron_triangle
