// sphere3 x triangle3 (the closed ball, the closed triangle): fixtures (balls tangent to the face,
// to an edge, at a vertex, and one ulp short; a collinear triangle; NaN); every tier against the
// exact QP (CGAL's QP_solver over Gmpzf, the squared distance from the centre to the triangle) on
// 20,000 random cases and 20,000 balls touching small dyadic triangles at a vertex, an edge point or
// a face point from either side or the plane, exactly or within ulps, at a random scale
// (testkit/ball_halfspace_cases.hpp, flat_rows).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_sphere_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("sphere_triangle"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("sphere_triangle: fixtures", "[sphere_triangle]") {
    const triangle3 t{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
    CHECK(intersects(t, sphere3{{1, 1, 3}, 3})); // the face
    CHECK_FALSE(intersects(sphere3{{1, 1, -3}, 0x1.7ffffffffffffp+1}, t));
    CHECK(intersects(t, sphere3{{2, -3, 4}, 5})); // the edge ab at (2, 0, 0)
    CHECK_FALSE(intersects(t, sphere3{{2, -3, 4}, 0x1.3ffffffffffffp+2}));
    CHECK(intersects(t, sphere3{{-3, -4, 0}, 5})); // the vertex a, in the plane
    CHECK_FALSE(intersects(t, sphere3{{-3, -4, 0}, 0x1.3ffffffffffffp+2}));
    CHECK(intersects(t, sphere3{{1, 1, 0}, 0}));           // a point ball on the face
    const triangle3 line{{0, 0, 0}, {2, 0, 0}, {4, 0, 0}}; // collinear: the segment from 0 to 4
    CHECK(intersects(line, sphere3{{3, 3, 4}, 5}));
    CHECK_FALSE(intersects(line, sphere3{{3, 3, 4}, 0x1.3ffffffffffffp+2}));
    CHECK(intersects(line, sphere3{{7, 0, 4}, 5}));
    CHECK_FALSE(intersects(line, sphere3{{7, 0, 4}, 0x1.3ffffffffffffp+2}));
    CHECK_FALSE(intersects(triangle3{{0, 0, 0}, {1, 0, 0}, {0, __builtin_inf(), 0}}, sphere3{{0, 0, 0}, 9}));
}
TEST_CASE("sphere_triangle: oracle, random and near-degenerate", "[sphere_triangle][oracle]") {
    support::ball_halfspace_oracle<triangle3>("sphere_triangle", support::cases(20000), approx_bound);
}

TEST_CASE("sphere_triangle: contains", "[sphere_triangle][oracle]") {
    support::sphere_contains<triangle3>("sphere_triangle", support::cases(10000), approx_bound);
}

} // namespace test_query_sphere_triangle
