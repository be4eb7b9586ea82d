// capsule3 x segment3: fixtures (skew, parallel, end beyond end; one ulp short); // every tier against the exact QP (CGAL's QP_solver over Gmpzf: the squared distance between the
// capsule's segment and the segment, against the radii) on 10,000 random cases and 10,000 capsules
// grown from balls touching small dyadic segments at a vertex, an edge or a face point, exactly or within ulps,
// at a random scale (testkit/capsule_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_segment"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_segment: fixtures", "[capsule_segment]") {
    const capsule3 c{{0, 0, 0}, {10, 0, 0}, 5};
    CHECK(intersects(c, segment3{{5, -5, 5}, {5, 5, 5}})); // skew: the closest points (5, 0, 0), (5, 0, 5)
    CHECK_FALSE(intersects(capsule3{c.a, c.b, 0x1.3ffffffffffffp+2}, segment3{{5, -5, 5}, {5, 5, 5}}));
    CHECK(intersects(segment3{{3, 3, 4}, {30, 3, 4}}, c)); // parallel
    CHECK_FALSE(intersects(segment3{{3, 3, 0x1.0000000000001p+2}, {30, 3, 0x1.0000000000001p+2}}, c));
    CHECK(intersects(c, segment3{{13, 4, 0}, {20, 4, 0}})); // end to end
    CHECK_FALSE(intersects(c, segment3{{13, 0x1.0000000000001p+2, 0}, {20, 4, 0}}));
    CHECK(intersects(c, segment3{{5, 3, 4}, {5, 3, 4}})); // a point
}
TEST_CASE("capsule_segment: oracle, random and near-degenerate", "[capsule_segment][oracle]") {
    support::capsule_oracle<segment3>("capsule_segment", support::cases(10000), approx_bound);
}

TEST_CASE("capsule_segment: contains", "[capsule_segment][oracle]") {
    support::capsule_contains<segment3>("capsule_segment", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_segment
