// capsule3 x sphere3: fixtures (a ball tangent to the cylinder and to a cap, the radii summed
// exactly where their sum in double rounds; one ulp short); // every tier against the exact QP (CGAL's QP_solver over Gmpzf: the squared distance between the
// capsule's segment and the ball's centre, against the radii) on 10,000 random cases and 10,000 capsules
// grown from balls touching small dyadic points (each taking half the radius) at a vertex, an edge or a face point, exactly or within ulps,
// at a random scale (testkit/capsule_cases.hpp). contains both ways: fixtures, and 10,000 random and
// 10,000 touching-from-inside cases each, against CGAL's squared distance over Epeck with the radii's
// difference exact, and the end balls in the ball in rationals.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_sphere"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_sphere: fixtures", "[capsule_sphere]") {
    const capsule3 c{{0, 0, 0}, {10, 0, 0}, 2};
    CHECK(intersects(c, sphere3{{5, 3, 4}, 3}));
    CHECK_FALSE(intersects(sphere3{{5, 3, 4}, 0x1.7ffffffffffffp+1}, c));
    CHECK(intersects(c, sphere3{{13, 4, 0}, 3}));
    // the sum formed exactly: 1 + 2^-51 and 4 - 2^-51 are 5; 1 + 2^-52 and 4 - 2^-51 are less than
    // 5, though their sum in double rounds to 5
    CHECK(intersects(capsule3{{0, 0, 0}, {10, 0, 0}, 1 + 0x1p-51}, sphere3{{5, 3, 4}, 4 - 0x1p-51}));
    CHECK_FALSE(intersects(capsule3{{0, 0, 0}, {10, 0, 0}, 1 + 0x1p-52}, sphere3{{5, 3, 4}, 4 - 0x1p-51}));
    CHECK_FALSE(intersects(capsule3{{0, 0, 0}, {10, 0, 0}, 1}, sphere3{{5, 3, 4}, 4 - 0x1p-50}));
    CHECK(intersects(c, sphere3{{5, 3, 4}, -3}));
}
TEST_CASE("capsule_sphere: oracle, random and near-degenerate", "[capsule_sphere][oracle]") {
    support::capsule_oracle<sphere3>("capsule_sphere", support::cases(10000), approx_bound);
}

TEST_CASE("capsule_sphere: contains, fixtures", "[capsule_sphere]") {
    const capsule3 c{{0, 0, 0}, {10, 0, 0}, 5};
    CHECK(contains(c, sphere3{{5, 3, 0}, 2})); // touching the cylinder from inside
    CHECK_FALSE(contains(c, sphere3{{5, 3, 0}, 0x1.0000000000001p1}));
    CHECK(contains(c, sphere3{{13, 0, 0}, 2})); // touching the cap
    CHECK_FALSE(contains(c, sphere3{{13, 0, 0}, 0x1.0000000000001p1}));
    CHECK_FALSE(contains(c, sphere3{{5, 0, 0}, 6})); // larger than the capsule's radius
    CHECK(contains(sphere3{{0, 0, 0}, 5}, capsule3{{3, 0, 0}, {0, 3, 0}, 2}));
    CHECK_FALSE(contains(sphere3{{0, 0, 0}, 5}, capsule3{{3, 0, 0}, {0, 3, 0}, 0x1.0000000000001p1}));
    CHECK(contains(sphere3{{0, 0, 0}, 5}, capsule3{{0, 0, 0}, {0, 0, 0}, 5}));   // the same ball
    CHECK(contains(sphere3{{0, 0, 0}, -5}, capsule3{{3, 0, 0}, {0, 3, 0}, -2})); // negative radii act as |r|
}
TEST_CASE("capsule_sphere: contains", "[capsule_sphere][oracle]") {
    support::capsule_contains<sphere3>("capsule_sphere", support::cases(10000), approx_bound);
    support::capsule_contained<sphere3>("capsule_sphere", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_sphere
