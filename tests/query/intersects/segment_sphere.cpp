// segment3 x sphere3 (the closed ball): fixtures (balls tangent inside the segment, beyond either
// end, at a point segment, and one ulp short; a negative radius; NaN); every tier against the exact
// QP (CGAL's QP_solver over Gmpzf, the squared distance from the centre to the segment) on 20,000
// random cases and 20,000 balls touching small dyadic segments at an end or inside, exactly or
// within ulps, at a random scale (testkit/ball_halfspace_cases.hpp, flat_rows).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_segment_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("segment_sphere"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("segment_sphere: fixtures", "[segment_sphere]") {
    const segment3 s{{0, 0, 0}, {10, 0, 0}};
    CHECK(intersects(s, sphere3{{5, 3, 4}, 5})); // inside the segment, 3-4-5
    CHECK_FALSE(intersects(s, sphere3{{5, 3, 4}, 0x1.3ffffffffffffp+2}));
    CHECK(intersects(sphere3{{13, 4, 0}, 5}, s)); // beyond b
    CHECK_FALSE(intersects(sphere3{{13, 4, 0}, 0x1.3ffffffffffffp+2}, s));
    CHECK(intersects(s, sphere3{{-3, 0, 4}, 5})); // beyond a
    CHECK_FALSE(intersects(s, sphere3{{-3, 0, 4}, 0x1.3ffffffffffffp+2}));
    CHECK(intersects(s, sphere3{{-3, 0, 4}, -5})); // an unchecked negative radius acts as |r|
    const segment3 dot{{1, 1, 1}, {1, 1, 1}};
    CHECK(intersects(dot, sphere3{{1, 1, 4}, 3}));
    CHECK_FALSE(intersects(dot, sphere3{{1, 1, 4}, 0x1.7ffffffffffffp+1}));
    CHECK(intersects(s, sphere3{{2, 0, 0}, 0})); // a point ball on the segment
    CHECK_FALSE(intersects(segment3{{0, 0, __builtin_nan("")}, {1, 1, 1}}, sphere3{{0, 0, 0}, 9}));
    CHECK_FALSE(intersects(s, sphere3{{0, 0, 0}, __builtin_inf()}));
    CHECK(contains(sphere3{{0, 0, 0}, 5}, segment3{{3, 4, 0}, {0, 0, 5}})); // both ends on the sphere
    CHECK_FALSE(contains(sphere3{{0, 0, 0}, 5}, segment3{{3, 4, 0x1p-1074}, {0, 0, 5}}));
}
TEST_CASE("segment_sphere: oracle, random and near-degenerate", "[segment_sphere][oracle]") {
    support::ball_halfspace_oracle<segment3>("segment_sphere", support::cases(20000), approx_bound);
}

TEST_CASE("segment_sphere: contains", "[segment_sphere][oracle]") {
    support::sphere_contains<segment3>("segment_sphere", support::cases(10000), approx_bound);
}

} // namespace test_query_segment_sphere
