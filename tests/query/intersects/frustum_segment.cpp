// frustum3 x segment3: fixtures; the exact LP oracle (the frustum as its half-spaces n . x <= offset) on
// 20,000 random and 20,000 near-degenerate cases (an axis-aligned integer frustum (corners dyadic) or a camera frustum (frustum3::from_camera), the segment placed through one of its
// boundary points, along a face or not; then a random exact-or-nudged scale 2^-500..2^500 and
// translation); both argument orders, rewritten shapes, exact translations of both; contains.
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

namespace test_query_frustum_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_segment"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_segment: fixtures", "[frustum_segment]") {
    CHECK(intersects(camera, segment3{{0, 0, 0}, {0, 0, -200}}));
    CHECK_FALSE(intersects(camera, segment3{{0, 0, 0}, {0, 0, -0.5}}));
    CHECK(intersects(integer_frustum, segment3{{0, 0, 0}, {1, 1, 1}})); // from the eye to a near corner
    CHECK_FALSE(intersects(integer_frustum, segment3{{0, 0, 0}, {1, 1, 0x1.fffffffffffffp-1}}));
    CHECK(intersects(segment3{{2, 2, 2}, {2, 5, 2}}, integer_frustum)); // touches a side edge
    CHECK(contains(integer_frustum, segment3{{1, 1, 1}, {-4, -4, 4}})); // corner to corner
    CHECK_FALSE(contains(integer_frustum, segment3{{1, 1, 1}, {-4, -4, 0x1.0000000000001p2}}));
}
TEST_CASE("frustum_segment: oracle, random and near-degenerate", "[frustum_segment][oracle]") {
    support::halfspace_oracle<frustum3, segment3>("frustum_segment", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_segment: rewrites of both shapes and exact translations give the same answer", "[frustum_segment]") {
    support::halfspace_symmetries<frustum3, segment3>("frustum_segment", support::cases(10000));
}
TEST_CASE("frustum_segment: contains", "[frustum_segment][oracle]") {
    support::halfspace_contains_oracle<frustum3, segment3>("frustum_segment", support::cases(2000), approx_bound);
}

} // namespace test_query_frustum_segment
