// aabb3 x kdop<K>, and contains(kdop, aabb | segment): fixtures (a box whose slabs all overlap a
// k-DOP it misses, touching, NaN, inverted); the exact LP oracle (the box as three slabs, the
// k-DOP as its slabs lo <= d . x <= hi) on 5,000 random and 5,000 near-degenerate cases for each
// K = 6, 14, 18, 26 (20,000 and 20,000 in all: the k-DOP of a few dyadic points, the box through
// one of its extreme points, along the face of that direction or not; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); contains against every vertex in the LP
// oracle, on boxes and segments whose vertices are among the k-DOP's points (touching its
// boundary) or one ulp out; both argument orders, exact translations of both.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <limits>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/kdop_checks.hpp"
#include "testkit/kdop_fixtures.hpp"

namespace test_query_aabb_kdop { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::edge_cut;
using support::empty14;
using support::unit26;
using support::unit6;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_kdop"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("aabb_kdop: fixtures", "[aabb_kdop]") {
    // every slab of the box overlaps the 18-DOP's, yet x + y >= 1.75 > 1.5: disjoint
    CHECK_FALSE(intersects(edge_cut, aabb3{{0.875, 0.875, 0}, {2, 2, 1}}));
    CHECK(intersects(aabb3{{0.75, 0.75, 0}, {2, 2, 1}}, edge_cut)); // touching along an edge
    CHECK_FALSE(intersects(aabb3{{0x1.8000000000001p-1, 0.75, 0}, {2, 2, 1}}, edge_cut));
    CHECK_FALSE(intersects(corner_cut, aabb3{{0.875, 0.875, 0.875}, {2, 2, 2}}));
    CHECK(intersects(corner_cut, aabb3{{0.5, 0.5, 0.5}, {2, 2, 2}}));
    CHECK_FALSE(intersects(empty14, aabb3{{-5, -5, -5}, {5, 5, 5}}));
    CHECK(intersects(unit26, aabb3{{1, 1, 1}, {1, 1, 1}}));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(intersects(unit6, aabb3{{0, 0, 0}, {1, nan, 1}}));
    CHECK_FALSE(intersects(unit6, aabb3{{0, 0, 0}, {1, -1, 1}})); // inverted
    CHECK(contains(corner_cut, aabb3{{0, 0, 0}, {1, 1, 0.5}}));
    CHECK_FALSE(contains(corner_cut, aabb3{{0, 0, 0}, {1, 1, 0x1.0000000000001p-1}}));
    CHECK(contains(unit6, unit6.min[0] == 0 ? aabb3{{0, 0, 0}, {1, 1, 1}} : aabb3{}));
    CHECK_FALSE(contains(empty14, aabb3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}}));
    CHECK_FALSE(contains(unit6, aabb3{{0, 0, 0}, {1, -1, 1}}));
    CHECK(contains(edge_cut, segment3{{1, 0.5, 0}, {0.5, 1, 1}})); // along the cut face
    CHECK_FALSE(contains(edge_cut, segment3{{1, 0.5, 0}, {0.5, 0x1.0000000000001p0, 1}}));
}
TEST_CASE("aabb_kdop: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[aabb_kdop][oracle]") {
    const long n = support::cases(5000);
    support::kdop_oracle_every_k<aabb3>("aabb_kdop", n, approx_bound);
}
TEST_CASE("aabb_kdop: contains(kdop, aabb | segment) against the oracle", "[aabb_kdop][oracle]") {
    const long n = support::cases(500);
    support::kdop_contains_oracle<14, aabb3>("aabb_kdop", n, approx_bound);
    support::kdop_contains_oracle<26, aabb3>("aabb_kdop", n, approx_bound);
    support::kdop_contains_oracle<18, segment3>("kdop_segment", n, approx_bound);
}
TEST_CASE("aabb_kdop: both orders and exact translations give the same answer", "[aabb_kdop]") {
    const long n = support::cases(5000);
    support::kdop_symmetries_every_k<aabb3>("aabb_kdop", n);
}

} // namespace test_query_aabb_kdop
