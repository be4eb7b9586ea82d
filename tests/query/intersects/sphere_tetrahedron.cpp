// sphere3 x tetrahedron3 (the closed ball, the closed solid): fixtures (a centre inside, balls
// tangent to a face and at a vertex, and one ulp short; a flat tetrahedron; NaN); every tier against
// the exact QP (CGAL's QP_solver over Gmpzf) on 20,000 random cases and 20,000 balls touching small
// dyadic tetrahedra at a vertex, an edge point or a face point, exactly or within ulps, at a random
// scale (testkit/ball_halfspace_cases.hpp, flat_rows).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_sphere_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("sphere_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("sphere_tetrahedron: fixtures", "[sphere_tetrahedron]") {
    const tetrahedron3 t{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}};
    CHECK(intersects(t, sphere3{{1, 1, 1}, 0}));  // the centre inside
    CHECK(intersects(sphere3{{1, 1, -3}, 3}, t)); // the face z = 0
    CHECK_FALSE(intersects(sphere3{{1, 1, -3}, 0x1.7ffffffffffffp+1}, t));
    // the vertex (4, 0, 0): (3, -4, 0) = 7 (0, -1, 0) + 3 (0, 0, -1) + 3 (1, 1, 1), in its normal cone
    CHECK(intersects(t, sphere3{{7, -4, 0}, 5}));
    CHECK_FALSE(intersects(t, sphere3{{7, -4, 0}, 0x1.3ffffffffffffp+2}));
    const tetrahedron3 flat{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}}; // coplanar: the triangle's hull
    CHECK(intersects(flat, sphere3{{1, 1, 3}, 3}));
    CHECK_FALSE(intersects(flat, sphere3{{1, 1, 3}, 0x1.7ffffffffffffp+1}));
    CHECK_FALSE(intersects(tetrahedron3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, __builtin_nan("")}}, sphere3{{0, 0, 0}, 9}));
}
TEST_CASE("sphere_tetrahedron: oracle, random and near-degenerate", "[sphere_tetrahedron][oracle]") {
    support::ball_halfspace_oracle<tetrahedron3>("sphere_tetrahedron", support::cases(20000), approx_bound);
}

TEST_CASE("sphere_tetrahedron: contains", "[sphere_tetrahedron][oracle]") {
    support::sphere_contains<tetrahedron3>("sphere_tetrahedron", support::cases(10000), approx_bound);
}

} // namespace test_query_sphere_tetrahedron
