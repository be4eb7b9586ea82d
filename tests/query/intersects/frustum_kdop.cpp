// frustum3 x kdop<K>: fixtures (boxes at the near corner and at the far corner and one ulp off, a 26-DOP across, the camera frustum, an empty k-DOP); the exact LP oracle (both as their half-spaces) on 5,000 random and 5,000
// near-degenerate cases for each K = 6, 14, 18, 26 (20,000 and 20,000 in all: an axis-aligned integer frustum (corners dyadic) or a camera frustum (frustum3::from_camera), the k-DOP of a small dyadic
// cloud at one of its boundary points on the outer side of the face there, that point one of the cloud's two times in
// three, else the cloud a quarter out; then a random exact-or-nudged scale 2^-500..2^500 and translation); both
// argument orders, rewritten sets, exact translations of both (K = 14 and 26).
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/polyhedron_cases.hpp"
#include "testkit/polyhedron_checks.hpp"
#include "testkit/polyhedron_fixtures.hpp"
#include "testkit/kdop_fixtures.hpp"

namespace test_query_frustum_kdop { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_kdop"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_kdop: fixtures", "[frustum_kdop]") {
    CHECK(intersects(integer_frustum, support::unit6)); // (0, 0, 1): the near face's centre
    CHECK_FALSE(intersects(integer_frustum, kdop<6>{{0, 0, 0}, {1, 1, 0x1.fffffffffffffp-1}}));
    CHECK(intersects(kdop<6>{{4, 4, 4}, {5, 5, 5}}, integer_frustum)); // the far corner
    CHECK_FALSE(intersects(kdop<6>{{0x1.0000000000001p2, 4, 4}, {5, 5, 5}}, integer_frustum));
    CHECK(intersects(integer_frustum, support::unit26));
    CHECK(intersects(camera, kdop<14>{{-1, -1, -2, -5, -5, -5, -5}, {1, 1, -1, 5, 5, 5, 5}}));
    CHECK_FALSE(intersects(camera, kdop<14>{{-1, -1, 1, -5, -5, -5, -5}, {1, 1, 2, 5, 5, 5, 5}})); // behind the eye
    CHECK_FALSE(intersects(integer_frustum, support::empty14));
}
TEST_CASE("frustum_kdop: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[frustum_kdop][oracle]") {
    support::halfspace_oracle<frustum3, kdop<6>>("frustum_kdop K = 6", support::cases(5000), approx_bound);
    support::halfspace_oracle<frustum3, kdop<14>>("frustum_kdop K = 14", support::cases(5000), approx_bound);
    support::halfspace_oracle<frustum3, kdop<18>>("frustum_kdop K = 18", support::cases(5000), approx_bound);
    support::halfspace_oracle<frustum3, kdop<26>>("frustum_kdop K = 26", support::cases(5000), approx_bound);
}
TEST_CASE("frustum_kdop: rewrites of the set and exact translations give the same answer", "[frustum_kdop]") {
    support::halfspace_symmetries<frustum3, kdop<14>>("frustum_kdop K = 14", support::cases(2500));
    support::halfspace_symmetries<frustum3, kdop<26>>("frustum_kdop K = 26", support::cases(2500));
}

} // namespace test_query_frustum_kdop
