// frustum3 x line3: fixtures; the exact LP oracle (the frustum as its half-spaces n . x <= offset) on
// 20,000 random and 20,000 near-degenerate cases (an axis-aligned integer frustum (corners dyadic) or a camera frustum (frustum3::from_camera), the line placed through one of its
// boundary points, along a face or not; then a random exact-or-nudged scale 2^-500..2^500 and
// translation); both argument orders, rewritten shapes, exact translations of both.
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

namespace test_query_frustum_line { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_line"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_line: fixtures", "[frustum_line]") {
    CHECK(intersects(camera, line3{{0, 0, 0}, {0, 0, 1}}));
    CHECK(intersects(integer_frustum, line3{{0, 0, 0}, {1, 1, 1}})); // through a side edge
    CHECK_FALSE(intersects(integer_frustum, line3{{0, 0, 0}, {1, 1, 0x1.fffffffffffffp-1}}));
    CHECK(intersects(line3{{0, 4, 4}, {1, 0, 0}}, integer_frustum)); // along a far edge
    CHECK_FALSE(intersects(integer_frustum, line3{{0, 0x1.0000000000001p2, 4}, {1, 0, 0}}));
    CHECK_FALSE(intersects(integer_frustum, line3{{0, 0, 0}, {1, 0, 0}}));
}
TEST_CASE("frustum_line: oracle, random and near-degenerate", "[frustum_line][oracle]") {
    support::halfspace_oracle<frustum3, line3>("frustum_line", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_line: rewrites of both shapes and exact translations give the same answer", "[frustum_line]") {
    support::halfspace_symmetries<frustum3, line3>("frustum_line", support::cases(10000));
}

} // namespace test_query_frustum_line
