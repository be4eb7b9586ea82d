// kdop<K> x ray3: fixtures (onto the cut face, away from it, grazing a cut edge, one ulp past,
// from inside, a zero direction, against the empty 14-DOP); the exact LP oracle (the k-DOP as its slabs lo <= d . x <= hi) on 5,000 random and 5,000
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

namespace test_query_kdop_ray { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::edge_cut;
using support::empty14;
using support::unit26;
using support::unit6;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_ray"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("kdop_ray: fixtures", "[kdop_ray]") {
    CHECK(intersects(corner_cut, ray3{{2, 2, 2}, {-1, -1, -1}}));
    CHECK_FALSE(intersects(corner_cut, ray3{{2, 2, 2}, {1, 1, 1}}));
    CHECK(intersects(ray3{{2, 2, 0.5}, {-1, -1, 0}}, corner_cut));
    CHECK(intersects(corner_cut, ray3{{3, -1, 0.5}, {-1, 1, 0}})); // along the cut face's line x + y = 2, z = 1/2
    CHECK_FALSE(intersects(corner_cut, ray3{{3, -1, 0x1.0000000000001p-1}, {-1, 1, 0}}));
    CHECK(intersects(unit6, ray3{{0.5, 0.5, 0.5}, {0, 0, 0}})); // a zero direction: the origin
    CHECK_FALSE(intersects(unit6, ray3{{2, 0.5, 0.5}, {0, 0, 0}}));
    CHECK_FALSE(intersects(empty14, ray3{{-5, -5, -5}, {1, 1, 1}}));
}
TEST_CASE("kdop_ray: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[kdop_ray][oracle]") {
    const long n = support::cases(5000);
    support::kdop_oracle_every_k<ray3>("kdop_ray", n, approx_bound);
}
TEST_CASE("kdop_ray: rewrites of the other shape and exact translations give the same answer", "[kdop_ray]") {
    const long n = support::cases(5000);
    support::kdop_symmetries_every_k<ray3>("kdop_ray", n);
}

} // namespace test_query_kdop_ray
