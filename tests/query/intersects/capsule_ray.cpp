// capsule3 x ray3: fixtures (a ray pointing past the capsule, a ray starting beyond a cap and
// pointing away; one ulp short); // every tier against the exact QP (CGAL's QP_solver over Gmpzf: the squared distance between the
// capsule's segment and the ray, against the radii) on 10,000 random cases and 10,000 capsules
// grown from balls touching a ray along small dyadic segments at a vertex, an edge or a face point, exactly or within ulps,
// at a random scale (testkit/capsule_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_ray"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_ray: fixtures", "[capsule_ray]") {
    const capsule3 c{{0, 0, 0}, {10, 0, 0}, 5};
    CHECK(intersects(c, ray3{{5, -50, 5}, {0, 1, 0}})); // passes at distance 5 above (5, 0, 0)
    CHECK_FALSE(intersects(c, ray3{{5, -50, 0x1.4000000000001p+2}, {0, 1, 0}}));
    CHECK(intersects(c, ray3{{5, 0, 5}, {0, 1, 0}})); // touches at its origin
    CHECK_FALSE(intersects(c, ray3{{5, 0x1p-50, 5}, {0, 1, 0}}));
    CHECK(intersects(c, ray3{{13, 4, 0}, {1, 0, 0}})); // starts on the cap, points away
    CHECK_FALSE(intersects(c, ray3{{13, 0x1.0000000000001p+2, 0}, {1, 0, 0}}));
}
TEST_CASE("capsule_ray: oracle, random and near-degenerate", "[capsule_ray][oracle]") {
    support::capsule_oracle<ray3>("capsule_ray", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_ray
