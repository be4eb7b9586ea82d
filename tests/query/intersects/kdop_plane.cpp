// kdop<K> x plane3: fixtures (the cut face's plane and one ulp beyond, a corner's and an edge's supporting planes,
// a face, an empty and an inverted k-DOP); the exact LP oracle (the k-DOP as its slabs lo <= d . x <= hi, the plane
// as an equality) on 5,000 random and 5,000 near-degenerate cases for each K = 6, 14, 18, 26 (20,000 and 20,000 in
// all: the k-DOP of a few dyadic points, the plane through one of its extreme points: the face's own plane, or
// containing a direction along that face, or any; then a random exact-or-nudged scale 2^-500..2^500 and
// translation); both argument orders, rewritten planes, exact translations of both (2,000 cases per K).
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

namespace test_query_kdop_plane { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::empty14;
using support::unit26;
using support::unit6;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_plane"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("kdop_plane: fixtures", "[kdop_plane]") {
    CHECK(intersects(corner_cut, plane3{{1, 1, 1}, 2.5})); // the cut face
    CHECK_FALSE(intersects(corner_cut, plane3{{1, 1, 1}, 0x1.4000000000001p1}));
    CHECK(intersects(plane3{{1, 1, 1}, 0}, corner_cut)); // the corner at the origin alone
    CHECK_FALSE(intersects(plane3{{1, 1, 1}, -0x1p-1074}, corner_cut));
    CHECK(intersects(unit6, plane3{{1, 0, 0}, 1})); // a face
    CHECK_FALSE(intersects(unit6, plane3{{1, 0, 0}, 0x1.0000000000001p0}));
    CHECK(intersects(unit6, plane3{{1, 1, 0}, 2})); // the edge x = y = 1
    CHECK_FALSE(intersects(unit6, plane3{{1, 1, 0}, 0x1.0000000000001p1}));
    CHECK(intersects(unit26, plane3{{0, 0, 1}, 0.5}));
    CHECK_FALSE(intersects(empty14, plane3{{0, 0, 1}, 0.5}));
    CHECK_FALSE(intersects(kdop<6>{{0, 0, 1}, {1, 1, 0}}, plane3{{0, 0, 1}, 0.5})); // an inverted slab: no set
    CHECK(intersects(unit6, plane3{{0, 0, 0}, 0}));
    CHECK_FALSE(intersects(unit6, plane3{{0, 0, 0}, -1}));
}
TEST_CASE("kdop_plane: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[kdop_plane][oracle]") {
    support::kdop_oracle_every_k<plane3>("kdop_plane", support::cases(5000), approx_bound);
}
TEST_CASE("kdop_plane: rewrites of the other shape and exact translations give the same answer", "[kdop_plane]") {
    support::kdop_symmetries_every_k<plane3>("kdop_plane", support::cases(2000));
}

} // namespace test_query_kdop_plane
