// kdop<K> x point3 and contains(kdop, point): fixtures (on a cut face, one ulp beyond it, in a
// cube's corner, an empty 14-DOP whose slabs never meet, NaN and inverted bounds); the exact LP oracle (the k-DOP as its slabs lo <= d . x <= hi) on 5,000 random and 5,000
// near-degenerate cases for each K = 6, 14, 18, 26 (20,000 and 20,000 in all: the k-DOP of a few
// dyadic points, the other shape through one of its extreme points, along the face of that
// direction or not; then a random exact-or-nudged scale 2^-500..2^500 and translation); both
// argument orders, rewritten partners, exact translations of both.
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

namespace test_query_kdop_point { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::edge_cut;
using support::empty14;
using support::unit26;
using support::unit6;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_point"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("kdop_point: fixtures", "[kdop_point]") {
    CHECK(intersects(unit6, point3{1, 1, 1}));
    CHECK_FALSE(intersects(point3{1, 1, 0x1.0000000000001p0}, unit6));
    CHECK(intersects(corner_cut, point3{1, 1, 0.5}));                        // on the cut face
    CHECK_FALSE(intersects(corner_cut, point3{1, 1, 0x1.0000000000001p-1})); // one ulp beyond it
    CHECK_FALSE(intersects(corner_cut, point3{1, 1, 1}));                    // the cut corner
    CHECK(intersects(edge_cut, point3{1, 0.5, 0.25}));
    CHECK_FALSE(intersects(edge_cut, point3{1, 0x1.0000000000001p-1, 0.25}));
    CHECK_FALSE(intersects(empty14, point3{1, 1, 1}));
    CHECK(intersects(unit26, point3{0, 0, 0}));
    CHECK(contains(corner_cut, point3{0.5, 0.5, 0.5}));
    CHECK_FALSE(contains(corner_cut, point3{0.9, 0.9, 0.9}));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(intersects(kdop<6>{{0, 0, 0}, {1, nan, 1}}, point3{0.5, 0.5, 0.5}));
    CHECK_FALSE(intersects(kdop<6>{{0, 0, 0}, {1, -1, 1}}, point3{0.5, 0.5, 0.5})); // an inverted slab
    CHECK_FALSE(intersects(unit6, point3{0.5, nan, 0.5}));
    CHECK(kdop<14>::make(corner_cut.min, corner_cut.max).has_value());
    CHECK(kdop<6>::make({0, 0, 0}, {1, -1, 1}).error().code == errc::inverted_box);
}
TEST_CASE("kdop_point: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[kdop_point][oracle]") {
    const long n = support::cases(5000);
    support::kdop_oracle_every_k<point3>("kdop_point", n, approx_bound);
}
TEST_CASE("kdop_point: rewrites of the other shape and exact translations give the same answer", "[kdop_point]") {
    const long n = support::cases(5000);
    support::kdop_symmetries_every_k<point3>("kdop_point", n);
}

} // namespace test_query_kdop_point
