// capsule3 x triangle3: fixtures (a capsule through the triangle, one parallel above its face,
// one near an edge, one ulp short; a collinear triangle); // every tier against the exact QP (CGAL's QP_solver over Gmpzf: the squared distance between the
// capsule's segment and the triangle, against the radii) on 10,000 random cases and 10,000 capsules
// grown from balls touching small dyadic triangles at a vertex, an edge or a face point, exactly or within ulps,
// at a random scale (testkit/capsule_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_triangle"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_triangle: fixtures", "[capsule_triangle]") {
    const triangle3 t{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
    CHECK(intersects(capsule3{{1, 1, -5}, {1, 1, 5}, 0}, t));   // through it
    CHECK(intersects(capsule3{{-10, 1, 3}, {10, 1, 3}, 3}, t)); // parallel above the face
    CHECK_FALSE(intersects(capsule3{{-10, 1, 3}, {10, 1, 3}, 0x1.7ffffffffffffp+1}, t));
    CHECK(intersects(t, capsule3{{-10, -3, 4}, {10, -3, 4}, 5})); // along the edge ab
    CHECK_FALSE(intersects(t, capsule3{{-10, -3, 4}, {10, -3, 4}, 0x1.3ffffffffffffp+2}));
    CHECK(intersects(t, capsule3{{2, -3, 4}, {2, -30, 40}, 5})); // an end nearest the edge
    const triangle3 line{{0, 0, 0}, {2, 0, 0}, {4, 0, 0}};
    CHECK(intersects(line, capsule3{{2, -5, 5}, {2, 5, 5}, 5}));
    CHECK_FALSE(intersects(line, capsule3{{2, -5, 5}, {2, 5, 5}, 0x1.3ffffffffffffp+2}));
}
TEST_CASE("capsule_triangle: oracle, random and near-degenerate", "[capsule_triangle][oracle]") {
    support::capsule_oracle<triangle3>("capsule_triangle", support::cases(10000), approx_bound);
}

TEST_CASE("capsule_triangle: contains", "[capsule_triangle][oracle]") {
    support::capsule_contains<triangle3>("capsule_triangle", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_triangle
