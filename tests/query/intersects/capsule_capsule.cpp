// capsule3 x capsule3: fixtures (crossing, skew at distance 5, parallel, end to end, degenerate
// segments; one ulp short); // every tier against the exact QP (CGAL's QP_solver over Gmpzf: the squared distance between the
// capsule's segment and the other's segment, against the radii) on 10,000 random cases and 10,000 capsules
// grown from balls touching small dyadic segments (each taking half the radius) at a vertex, an edge or a face point, exactly or within ulps,
// at a random scale (testkit/capsule_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_capsule { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_capsule"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_capsule: fixtures", "[capsule_capsule]") {
    const capsule3 a{{0, 0, 0}, {10, 0, 0}, 2};
    CHECK(intersects(a, capsule3{{5, -5, 5}, {5, 5, 5}, 3})); // skew: the closest points (5, 0, 0), (5, 0, 5)
    CHECK_FALSE(intersects(a, capsule3{{5, -5, 5}, {5, 5, 5}, 0x1.7ffffffffffffp+1}));
    CHECK(intersects(a, capsule3{{-3, 4, 0}, {-3, 40, 0}, 3})); // the end a against the end (-3, 4, 0)
    CHECK_FALSE(intersects(a, capsule3{{-3, 4, 0}, {-3, 40, 0}, 0x1.7ffffffffffffp+1}));
    CHECK(intersects(a, capsule3{{3, 3, 4}, {30, 3, 4}, 3})); // parallel, overlapping spans
    CHECK_FALSE(intersects(a, capsule3{{3, 3, 4}, {30, 3, 4}, 0x1.7ffffffffffffp+1}));
    CHECK(intersects(a, capsule3{{13, 0, 4}, {30, 0, 4}, 3})); // parallel, end to end: (10, 0, 0) to (13, 0, 4)
    CHECK(intersects(a, capsule3{{5, 1, 1}, {5, 1, 1}, 0}));   // a point inside
    CHECK(intersects(capsule3{{0, 0, 0}, {0, 0, 0}, 1}, capsule3{{0, 3, 4}, {0, 3, 4}, 4})); // two balls
    CHECK_FALSE(intersects(capsule3{{0, 0, 0}, {0, 0, 0}, 1}, capsule3{{0, 3, 4}, {0, 3, 4}, 0x1.fffffffffffffp+1}));
}
TEST_CASE("capsule_capsule: oracle, random and near-degenerate", "[capsule_capsule][oracle]") {
    support::capsule_oracle<capsule3>("capsule_capsule", support::cases(10000), approx_bound);
}

TEST_CASE("capsule_capsule: contains, fixtures", "[capsule_capsule]") {
    const capsule3 c{{0, 0, 0}, {10, 0, 0}, 5};
    CHECK(contains(c, capsule3{{0, 3, 0}, {10, 3, 0}, 2})); // touching the cylinder along a line
    CHECK_FALSE(contains(c, capsule3{{0, 3, 0}, {10, 3, 0}, 0x1.0000000000001p1}));
    CHECK(contains(c, c));
    CHECK_FALSE(contains(c, capsule3{{0, 0, 0}, {10, 0, 0}, 0x1.4000000000001p2}));
}
TEST_CASE("capsule_capsule: contains", "[capsule_capsule][oracle]") {
    support::capsule_contains<capsule3>("capsule_capsule", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_capsule
