// kdop<K> x triangle3: fixtures (a large triangle across the cut cube whose edges miss it, on the cut face and
// just beyond it, one corner on the cut face, against the empty 14-DOP); the exact LP oracle (the k-DOP as its slabs lo <= d . x
// <= hi, the triangle as the hull of its corners) on 5,000 random and 5,000 near-degenerate cases for each K = 6,
// 14, 18, 26 (20,000 and 20,000 in all: the k-DOP of a few dyadic points, the triangle through one of its extreme
// points, along the face of that direction or not; then a random exact-or-nudged scale 2^-500..2^500 and
// translation); both argument orders, rewritten partners, exact translations of both; contains.
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

namespace test_query_kdop_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_triangle"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("kdop_triangle: fixtures", "[kdop_triangle]") {
    CHECK(intersects(corner_cut, triangle3{{-10, -10, 0.5}, {10, -10, 0.5}, {0, 10, 0.5}})); // the section lies inside
    CHECK(intersects(unit26, triangle3{{-10, -10, 0.5}, {10, -10, 0.5}, {0, 10, 0.5}}));
    // in the cut face's plane x + y + z = 5/2, around the face; then 2^-20 beyond it
    CHECK(intersects(corner_cut, triangle3{{20, -10, -7.5}, {-10, 20, -7.5}, {-10, -10, 22.5}}));
    constexpr double d = 0x1p-20;
    CHECK_FALSE(intersects(triangle3{{20, -10, -7.5 + d}, {-10, 20, -7.5 + d}, {-10, -10, 22.5 + d}}, corner_cut));
    CHECK(intersects(corner_cut, triangle3{{1, 1, 0.5}, {3, 3, 3}, {3, 2, 3}})); // a corner on the cut face
    CHECK_FALSE(intersects(corner_cut, triangle3{{1, 1, 0x1.0000000000001p-1}, {3, 3, 3}, {3, 2, 3}}));
    CHECK_FALSE(intersects(empty14, triangle3{{-5, -5, -5}, {5, 5, 5}, {5, -5, 0}}));
    CHECK(contains(corner_cut, triangle3{{0, 0, 0}, {1, 1, 0.5}, {0, 1, 1}}));
    CHECK_FALSE(contains(corner_cut, triangle3{{0, 0, 0}, {1, 1, 0.5}, {1, 1, 1}}));
}
TEST_CASE("kdop_triangle: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[kdop_triangle][oracle]") {
    support::kdop_oracle_every_k<triangle3>("kdop_triangle", support::cases(5000), approx_bound);
}
TEST_CASE("kdop_triangle: rewrites of the other shape and exact translations give the same answer", "[kdop_triangle]") {
    support::kdop_symmetries_every_k<triangle3>("kdop_triangle", support::cases(2500));
}
TEST_CASE("kdop_triangle: contains", "[kdop_triangle][oracle]") {
    support::kdop_contains_oracle<14, triangle3>("kdop_triangle", support::cases(2000), approx_bound);
    support::kdop_contains_oracle<26, triangle3>("kdop_triangle", support::cases(1000), approx_bound);
}

} // namespace test_query_kdop_triangle
