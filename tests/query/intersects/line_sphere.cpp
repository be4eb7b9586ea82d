// line3 x sphere3 (the closed ball): fixtures (a ball tangent to a line far along it and one ulp
// short, a zero direction, NaN); every tier against the exact QP (CGAL's QP_solver over Gmpzf) on
// 20,000 random cases and 20,000 balls touching small dyadic lines, exactly or within ulps, at a
// random scale (testkit/ball_halfspace_cases.hpp, flat_rows).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/ball_halfspace_checks.hpp"

namespace test_query_line_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("line_sphere"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("line_sphere: fixtures", "[line_sphere]") {
    const line3 l{{0, 0, 0}, {1, 0, 0}};
    CHECK(intersects(l, sphere3{{100, 3, 4}, 5}));
    CHECK_FALSE(intersects(sphere3{{100, 3, 4}, 0x1.3ffffffffffffp+2}, l));
    CHECK(intersects(l, sphere3{{-1e300, 3, 4}, 5})); // far along it, either way
    const line3 dot{{1, 1, 1}, {0, 0, 0}};            // a zero direction: the origin point
    CHECK(intersects(dot, sphere3{{1, 1, 4}, 3}));
    CHECK_FALSE(intersects(dot, sphere3{{1, 1, 4}, 0x1.7ffffffffffffp+1}));
    CHECK_FALSE(intersects(line3{{0, 0, 0}, {__builtin_nan(""), 1, 1}}, sphere3{{0, 0, 0}, 9}));
}
TEST_CASE("line_sphere: oracle, random and near-degenerate", "[line_sphere][oracle]") {
    support::ball_halfspace_oracle<line3>("line_sphere", support::cases(20000), approx_bound);
}

} // namespace test_query_line_sphere
