// kdop<K> x segment3: fixtures (into the cut corner, ending on the cut face, one ulp short,
// along a face, inside, against the empty 14-DOP); the exact LP oracle (the k-DOP as its slabs lo <= d . x <= hi) on 5,000 random and 5,000
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

namespace test_query_kdop_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::edge_cut;
using support::empty14;
using support::unit26;
using support::unit6;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_segment"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("kdop_segment: fixtures", "[kdop_segment]") {
    CHECK_FALSE(intersects(corner_cut, segment3{{1, 1, 1}, {2, 2, 2}}));
    CHECK(intersects(corner_cut, segment3{{0.5, 0.5, 0.5}, {1, 1, 1}}));
    CHECK(intersects(segment3{{2, 2, 0.5}, {1, 1, 0.5}}, corner_cut)); // ends on the cut face
    CHECK_FALSE(intersects(segment3{{2, 2, 0.5}, {0x1.0000000000001p0, 1, 0.5}}, corner_cut));
    CHECK(intersects(unit6, segment3{{-1, 0, 0}, {2, 0, 0}})); // along an edge
    CHECK(intersects(unit6, segment3{{0.25, 0.25, 0.25}, {0.5, 0.5, 0.5}}));
    CHECK_FALSE(intersects(empty14, segment3{{-5, -5, -5}, {5, 5, 5}}));
    CHECK(intersects(edge_cut, segment3{{2, 1, 0.5}, {1, 2, 0.5}}) == false);
    CHECK(intersects(edge_cut, segment3{{1.5, 0, 0.5}, {0, 1.5, 0.5}})); // along the cut face
}
TEST_CASE("kdop_segment: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[kdop_segment][oracle]") {
    const long n = support::cases(5000);
    support::kdop_oracle_every_k<segment3>("kdop_segment", n, approx_bound);
}
TEST_CASE("kdop_segment: rewrites of the other shape and exact translations give the same answer", "[kdop_segment]") {
    const long n = support::cases(5000);
    support::kdop_symmetries_every_k<segment3>("kdop_segment", n);
}

} // namespace test_query_kdop_segment
