// aabb3 x capsule3: fixtures (a capsule along a box edge at distance 5, through a face, at a corner;
// one ulp short; a flat box); // every tier against the exact QP (CGAL's QP_solver over Gmpzf: the squared distance between the
// capsule's segment and the box, against the radii) on 10,000 random cases and 10,000 capsules
// grown from balls touching small dyadic boxes (zero extents too) at a vertex, an edge or a face point, exactly or within ulps,
// at a random scale (testkit/capsule_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_aabb_capsule { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_capsule"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("aabb_capsule: fixtures", "[aabb_capsule]") {
    const aabb3 b{{0, 0, 0}, {4, 4, 4}};
    CHECK(intersects(b, capsule3{{-10, -3, -4}, {10, -3, -4}, 5})); // along the edge y = z = 0
    CHECK_FALSE(intersects(b, capsule3{{-10, -3, -4}, {10, -3, -4}, 0x1.3ffffffffffffp+2}));
    CHECK(intersects(capsule3{{2, 2, -5}, {2, 2, 50}, 0}, b)); // through it
    CHECK(contains(b, capsule3{{1, 2, 2}, {3, 2, 2}, 1}));     // touching the faces x = 0 and x = 4 from inside
    CHECK_FALSE(contains(b, capsule3{{1, 2, 2}, {3, 2, 2}, 0x1.0000000000001p+0}));
    CHECK(contains(capsule3{{2, 2, -1}, {2, 2, 5}, 3}, aabb3{{2, 2, 0}, {2, 2, 4}})); // a flat box on the axis
    CHECK(intersects(b, capsule3{{-3, -4, 0}, {-30, -40, 0}, 5}));                    // an end at the corner
    CHECK_FALSE(intersects(b, capsule3{{-3, -4, 0}, {-30, -40, 0}, 0x1.3ffffffffffffp+2}));
    // parallel to the face x = 4, at distance 3 from it
    CHECK(intersects(b, capsule3{{7, -4, 2}, {7, 4, 2}, 3}));
    CHECK_FALSE(intersects(b, capsule3{{7, -4, 2}, {7, 4, 2}, 0x1.7ffffffffffffp+1}));
    CHECK(intersects(aabb3{{0, 0, 0}, {4, 4, 0}}, capsule3{{-10, 1, 3}, {10, 1, 3}, 3})); // a flat box
    CHECK_FALSE(intersects(aabb3{{0, 0, 0}, {4, 4, 0}}, capsule3{{-10, 1, 3}, {10, 1, 3}, 0x1.7ffffffffffffp+1}));
}
TEST_CASE("aabb_capsule: oracle, random and near-degenerate", "[aabb_capsule][oracle]") {
    support::capsule_oracle<aabb3>("aabb_capsule", support::cases(10000), approx_bound);
}

TEST_CASE("aabb_capsule: contains", "[aabb_capsule][oracle]") {
    support::capsule_contains<aabb3>("aabb_capsule", support::cases(10000), approx_bound);
    support::capsule_contained<aabb3>("aabb_capsule", support::cases(10000), approx_bound);
}

} // namespace test_query_aabb_capsule
