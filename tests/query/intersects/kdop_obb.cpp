// kdop<K> x obb3, K = 6, 14, 18, 26: fixtures (a skew box touching the corner-cut 14-DOP along an
// edge and one ulp away, around it, an empty k-DOP, contains); the exact LP oracle (the k-DOP as
// its slabs lo <= d . x <= hi, the box as its centre plus bounded multiples of its axes) on 5,000
// random and 5,000 near-degenerate cases per K (20,000 and 20,000 in all: the k-DOP of a small
// dyadic cloud, the box placed with a corner, an edge or face point at one of its extreme points,
// in a permuted, near-rotation or skew frame; then a random exact-or-nudged scale and
// translation); rewritten boxes and exact translations; contains against the box's exact corners.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/kdop_checks.hpp"
#include "testkit/kdop_fixtures.hpp"

namespace test_query_kdop_obb { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_obb");                 // stated in the catalog (modules/query/catalog.cppm)
constexpr std::array<vec3, 3> turned{vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}; // 45 degrees about z, length sqrt 2
} // namespace

TEST_CASE("kdop_obb: fixtures", "[kdop_obb]") {
    // x + y = 3 + 2 s0 >= 2: along the cube's edge x = y = 1, where x + y + z <= 5/2 leaves z <= 1/2
    CHECK(intersects(corner_cut, obb3{{1.5, 1.5, 0.5}, turned, {0.5, 0.5, 0.5}}));
    CHECK_FALSE(intersects(obb3{{1.5, 1.5, 0.5}, turned, {0x1.fffffffffffffp-2, 0.5, 0.5}}, corner_cut));
    CHECK(intersects(corner_cut, obb3{{1.5, 1.5, 1}, turned, {0.5, 0.5, 0.5}})); // the point (1, 1, 1/2) alone
    CHECK_FALSE(intersects(corner_cut, obb3{{1.5, 1.5, 0x1.0000000000001p0}, turned, {0.5, 0.5, 0.5}}));
    CHECK(intersects(unit26, obb3{{0.5, 0.5, 0.5}, turned, {9, 9, 9}})); // around it
    CHECK_FALSE(intersects(empty14, obb3{{0.5, 0.5, 0.5}, turned, {9, 9, 9}}));
    CHECK(contains(corner_cut, obb3{{0.5, 0.5, 0.5}, turned, {0.25, 0.25, 0.5}}));
    CHECK_FALSE(contains(corner_cut, obb3{{0.5, 0.5, 0.5}, turned, {0.25, 0.25, 0x1.0000000000001p-1}}));
    CHECK_FALSE(contains(empty14, obb3{{0.5, 0.5, 0.5}, turned, {0, 0, 0}}));
}
TEST_CASE("kdop_obb: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[kdop_obb][oracle]") {
    support::kdop_oracle_every_k<obb3>("kdop_obb", support::cases(5000), approx_bound);
}
TEST_CASE("kdop_obb: rewrites of the other shape and exact translations give the same answer", "[kdop_obb]") {
    support::kdop_symmetries_every_k<obb3>("kdop_obb", support::cases(2500));
}
TEST_CASE("kdop_obb: contains", "[kdop_obb][oracle]") {
    support::kdop_contains_oracle<14, obb3>("kdop_obb", support::cases(2000), approx_bound);
    support::kdop_contains_oracle<26, obb3>("kdop_obb", support::cases(1000), approx_bound);
}

} // namespace test_query_kdop_obb
