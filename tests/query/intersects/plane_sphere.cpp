// plane3 x sphere3 (the closed ball): fixtures (a ball tangent to a plane of normal length 5 and one
// ulp short, zero normals, NaN); every tier against the exact QP (CGAL's QP_solver over Gmpzf) on
// 20,000 random cases and 20,000 balls touching small dyadic planes, exactly or within ulps, at a
// random scale (testkit/ball_halfspace_cases.hpp, flat_rows).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/ball_halfspace_checks.hpp"

namespace test_query_plane_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("plane_sphere"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("plane_sphere: fixtures", "[plane_sphere]") {
    const plane3 p{{0, 3, 4}, 10}; // at distance 2 from the origin
    CHECK(intersects(p, sphere3{{0, 0, 0}, 2}));
    CHECK_FALSE(intersects(sphere3{{0, 0, 0}, 0x1.fffffffffffffp+0}, p));
    CHECK(intersects(p, sphere3{{7, 0, 4}, 3})); // 6/5 beyond it
    CHECK(intersects(p, sphere3{{0, 6, 8}, 8})); // 40/5 beyond it: tangent
    CHECK_FALSE(intersects(p, sphere3{{0, 6, 8}, 0x1.fffffffffffffp+2}));
    CHECK(intersects(plane3{{0, 0, 0}, 0}, sphere3{{5, 5, 5}, 0})); // a zero normal with offset 0: everything
    CHECK_FALSE(intersects(plane3{{0, 0, 0}, 1}, sphere3{{5, 5, 5}, 9}));
    CHECK_FALSE(intersects(plane3{{0, 0, 1}, __builtin_nan("")}, sphere3{{0, 0, 0}, 9}));
}
TEST_CASE("plane_sphere: oracle, random and near-degenerate", "[plane_sphere][oracle]") {
    support::ball_halfspace_oracle<plane3>("plane_sphere", support::cases(20000), approx_bound);
}

} // namespace test_query_plane_sphere
