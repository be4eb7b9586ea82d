// kdop<K> x sphere3 (the ball), K = 6, 14, 18, 26: fixtures (a ball tangent at a corner of the unit
// 6-DOP and at a vertex of a 14-DOP's cut, Pythagorean, and one ulp short; an empty slab); every
// tier against the exact QP (CGAL's QP_solver over Gmpzf, the squared distance from the centre to
// the slabs) on the k-DOPs of 5,000 random and 5,000 small dyadic clouds per K with balls tangent
// at a face, an edge or a vertex, exactly or within ulps (testkit/ball_halfspace_cases.hpp);
// contains(k-DOP, ball) against the slabs in rationals (K = 14 and 26, 5,000 + 5,000 each).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/kdop_fixtures.hpp"
#include "testkit/ball_halfspace_checks.hpp"

namespace test_query_kdop_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_sphere"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("kdop_sphere: fixtures", "[kdop_sphere]") {
    using namespace support;
    CHECK(intersects(unit6, sphere3{{2, 3, 3}, 3})); // the corner (1, 1, 1): 1-2-2-3
    CHECK_FALSE(intersects(unit6, sphere3{{2, 3, 3}, 0x1.7ffffffffffffp+1}));
    // corner_cut's vertex (1, 1, 1/2) on x + y + z = 5/2: (2, 2, 1) = e_x + e_y + (1, 1, 1), length 3
    CHECK(intersects(corner_cut, sphere3{{3, 3, 1.5}, 3}));
    CHECK_FALSE(intersects(sphere3{{3, 3, 1.5}, 0x1.7ffffffffffffp+1}, corner_cut));
    CHECK_FALSE(intersects(empty14, sphere3{{0.5, 0.5, 0.5}, 10}));
    CHECK(intersects(unit26, sphere3{{0.5, 0.5, 0.5}, 0}));
    CHECK(contains(unit6, sphere3{{0.5, 0.5, 0.5}, 0.5}));
    CHECK_FALSE(contains(unit6, sphere3{{0.5, 0.5, 0.5}, 0x1.0000000000001p-1}));
    CHECK_FALSE(contains(empty14, sphere3{{0.5, 0.5, 0.5}, 0}));
    kdop<6> inf = unit6;
    inf.max[0] = __builtin_inf();
    CHECK_FALSE(intersects(inf, sphere3{{0.5, 0.5, 0.5}, 1}));
}
TEST_CASE("kdop_sphere: oracle, random and near-degenerate", "[kdop_sphere][oracle]") {
    support::ball_halfspace_oracle<kdop<6>>("kdop_sphere (6)", support::cases(5000), approx_bound);
    support::ball_halfspace_oracle<kdop<14>>("kdop_sphere (14)", support::cases(5000), approx_bound);
    support::ball_halfspace_oracle<kdop<18>>("kdop_sphere (18)", support::cases(5000), approx_bound);
    support::ball_halfspace_oracle<kdop<26>>("kdop_sphere (26)", support::cases(5000), approx_bound);
}
TEST_CASE("kdop_sphere: contains", "[kdop_sphere][oracle]") {
    support::ball_halfspace_contains<kdop<14>>("kdop_sphere (14)", support::cases(5000), approx_bound);
    support::ball_halfspace_contains<kdop<26>>("kdop_sphere (26)", support::cases(5000), approx_bound);
}

} // namespace test_query_kdop_sphere
