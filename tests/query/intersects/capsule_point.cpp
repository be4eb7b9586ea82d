// capsule3 x point3: fixtures (points on the capsule's cylinder and caps, one ulp beyond; a
// capsule whose ends agree; a negative radius; NaN); // every tier against the exact QP (CGAL's QP_solver over Gmpzf: the squared distance between the
// capsule's segment and the point, against the radii) on 10,000 random cases and 10,000 capsules
// grown from balls touching small dyadic points at a vertex, an edge or a face point, exactly or within ulps,
// at a random scale (testkit/capsule_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_point { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_point"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_point: fixtures", "[capsule_point]") {
    const capsule3 c{{0, 0, 0}, {10, 0, 0}, 5};
    CHECK(intersects(c, point3{5, 3, 4})); // on the cylinder
    CHECK_FALSE(intersects(c, point3{5, 3, 0x1.0000000000001p+2}));
    CHECK(intersects(point3{13, 4, 0}, c)); // on the cap beyond b
    CHECK_FALSE(intersects(point3{13, 0x1.0000000000001p+2, 0}, c));
    CHECK(intersects(capsule3{{1, 1, 1}, {1, 1, 1}, 3}, point3{1, 1, 4})); // a ball
    CHECK(contains(c, point3{5, 3, 4}));
    CHECK_FALSE(contains(c, point3{5, 3, 0x1.0000000000001p+2}));
    CHECK(intersects(capsule3{{0, 0, 0}, {10, 0, 0}, -5}, point3{5, 3, 4})); // an unchecked negative radius acts as |r|
    CHECK_FALSE(intersects(capsule3{{0, 0, 0}, {10, 0, __builtin_nan("")}, 5}, point3{0, 0, 0}));
}
TEST_CASE("capsule_point: oracle, random and near-degenerate", "[capsule_point][oracle]") {
    support::capsule_oracle<point3>("capsule_point", support::cases(10000), approx_bound);
}

TEST_CASE("capsule_point: contains", "[capsule_point][oracle]") {
    support::capsule_contains<point3>("capsule_point", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_point
