// kdop<K> x line3: fixtures (through the cut corner's face, missing it, along a face, one ulp
// beside an edge, a zero direction, against the empty 14-DOP); the exact LP oracle (the k-DOP as its slabs lo <= d . x <= hi) on 5,000 random and 5,000
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

namespace test_query_kdop_line { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::edge_cut;
using support::empty14;
using support::unit26;
using support::unit6;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_line"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("kdop_line: fixtures", "[kdop_line]") {
    CHECK(intersects(corner_cut, line3{{2, 2, 2}, {1, 1, 1}}));
    CHECK_FALSE(intersects(corner_cut, line3{{1, 1, 1}, {1, -1, 0}})); // only the cut corner on the box
    CHECK(intersects(corner_cut, line3{{1, 1, 0.5}, {1, -1, 0}}));     // touches at (1, 1, 1/2)
    CHECK(intersects(line3{{-3, 0, 0}, {1, 0, 0}}, unit6));            // along an edge
    CHECK_FALSE(intersects(line3{{-3, -0x1p-1074, 0}, {1, 0, 0}}, unit6));
    CHECK(intersects(unit26, line3{{0.5, 0.5, 0.5}, {0, 0, 0}}));
    CHECK_FALSE(intersects(empty14, line3{{-5, -5, -5}, {1, 1, 1}}));
}
TEST_CASE("kdop_line: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[kdop_line][oracle]") {
    const long n = support::cases(5000);
    support::kdop_oracle_every_k<line3>("kdop_line", n, approx_bound);
}
TEST_CASE("kdop_line: rewrites of the other shape and exact translations give the same answer", "[kdop_line]") {
    const long n = support::cases(5000);
    support::kdop_symmetries_every_k<line3>("kdop_line", n);
}

} // namespace test_query_kdop_line
