// capsule3 x tetrahedron3: fixtures (a capsule inside, one along an edge, one ulp short; a flat
// tetrahedron); // every tier against the exact QP (CGAL's QP_solver over Gmpzf: the squared distance between the
// capsule's segment and the solid tetrahedron, against the radii) on 10,000 random cases and 10,000 capsules
// grown from balls touching small dyadic tetrahedra at a vertex, an edge or a face point, exactly or within ulps,
// at a random scale (testkit/capsule_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_tetrahedron: fixtures", "[capsule_tetrahedron]") {
    const tetrahedron3 t{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}};
    CHECK(intersects(capsule3{{1, 1, 1}, {0.5, 0.5, 0.5}, 0}, t));  // inside
    CHECK(intersects(t, capsule3{{-10, -3, -4}, {10, -3, -4}, 5})); // along the edge on the x axis
    CHECK_FALSE(intersects(t, capsule3{{-10, -3, -4}, {10, -3, -4}, 0x1.3ffffffffffffp+2}));
    CHECK(intersects(t, capsule3{{1, 1, -3}, {1, 1, -30}, 3})); // an end below the face z = 0
    CHECK_FALSE(intersects(t, capsule3{{1, 1, -3}, {1, 1, -30}, 0x1.7ffffffffffffp+1}));
    const tetrahedron3 flat{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}};
    CHECK(intersects(flat, capsule3{{-10, 1, 3}, {10, 1, 3}, 3}));
    CHECK_FALSE(intersects(flat, capsule3{{-10, 1, 3}, {10, 1, 3}, 0x1.7ffffffffffffp+1}));
}
TEST_CASE("capsule_tetrahedron: oracle, random and near-degenerate", "[capsule_tetrahedron][oracle]") {
    support::capsule_oracle<tetrahedron3>("capsule_tetrahedron", support::cases(10000), approx_bound);
}

TEST_CASE("capsule_tetrahedron: contains", "[capsule_tetrahedron][oracle]") {
    support::capsule_contains<tetrahedron3>("capsule_tetrahedron", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_tetrahedron
