// frustum3 x tetrahedron3: fixtures (a large tetrahedron holding the integer frustum whole, its top face on the near
// face and one ulp below it, a vertex on the far corner and one ulp off, a camera frustum); the exact LP oracle (the
// frustum as its half-spaces n . x <= offset, the tetrahedron as the hull of its vertices) on 20,000 random and
// 20,000 near-degenerate cases (an axis-aligned integer frustum (corners dyadic) or a camera frustum
// (frustum3::from_camera), the tetrahedron placed through one of its boundary points, along a face or not; then a
// random exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rewritten shapes, exact
// translations of both; contains.
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

namespace test_query_frustum_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_tetrahedron: fixtures", "[frustum_tetrahedron]") {
    CHECK(intersects(integer_frustum, wide_tetrahedron(5))); // no face meets the frustum: it lies inside
    CHECK(intersects(wide_tetrahedron(4), integer_frustum)); // through the far face
    CHECK(intersects(integer_frustum, wide_tetrahedron(1))); // the near face
    CHECK_FALSE(intersects(integer_frustum, wide_tetrahedron(0x1.fffffffffffffp-1)));
    CHECK(intersects(integer_frustum, tetrahedron3{{4, 4, 4}, {9, 4, 4}, {4, 9, 9}, {9, 9, 9}})); // a vertex on the far corner
    CHECK_FALSE(intersects(integer_frustum, tetrahedron3{{0x1.0000000000001p2, 4, 4}, {9, 4, 4}, {4, 9, 9}, {9, 9, 9}}));
    CHECK(intersects(camera, tetrahedron3{{-50, -50, -10}, {50, -50, -10}, {0, 50, -10}, {0, 0, -20}}));
    CHECK_FALSE(intersects(camera, tetrahedron3{{-50, -50, 10}, {50, -50, 10}, {0, 50, 10}, {0, 0, 20}})); // behind the eye
    CHECK(contains(integer_frustum, tetrahedron3{{1, 1, 1}, {-4, -4, 4}, {4, -4, 4}, {0, 4, 4}}));
    CHECK_FALSE(contains(integer_frustum, tetrahedron3{{1, 1, 1}, {-4, -4, 4}, {4, -4, 4}, {0, 4, 0x1.0000000000001p2}}));
}
TEST_CASE("frustum_tetrahedron: oracle, random and near-degenerate", "[frustum_tetrahedron][oracle]") {
    support::halfspace_oracle<frustum3, tetrahedron3>("frustum_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_tetrahedron: rewrites of both shapes and exact translations give the same answer", "[frustum_tetrahedron]") {
    support::halfspace_symmetries<frustum3, tetrahedron3>("frustum_tetrahedron", support::cases(5000));
}
TEST_CASE("frustum_tetrahedron: contains", "[frustum_tetrahedron][oracle]") {
    support::halfspace_contains_oracle<frustum3, tetrahedron3>("frustum_tetrahedron", support::cases(2000), approx_bound);
}

} // namespace test_query_frustum_tetrahedron
