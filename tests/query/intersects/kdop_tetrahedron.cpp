// kdop<K> x tetrahedron3: fixtures (a large tetrahedron holding the cut cube whole, its top face on the cube's top face,
// below it a subnormal step away, one vertex on the cut face and one ulp off, against the empty 14-DOP); the exact LP oracle (the
// k-DOP as its slabs lo <= d . x <= hi, the tetrahedron as the hull of its vertices) on 5,000 random and 5,000
// near-degenerate cases for each K = 6, 14, 18, 26 (20,000 and 20,000 in all: the k-DOP of a few dyadic points, the
// tetrahedron through one of its extreme points, along the face of that direction or not; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rewritten partners, exact translations
// of both; contains.
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
#include "testkit/polyhedron_fixtures.hpp"

namespace test_query_kdop_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::corner_cut;
using support::empty14;
using support::unit26;
using support::polyhedron_fixtures::wide_tetrahedron;

namespace {
const double approx_bound = catalog::approximate_bound("kdop_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("kdop_tetrahedron: fixtures", "[kdop_tetrahedron]") {
    CHECK(intersects(corner_cut, wide_tetrahedron(2))); // no face meets the k-DOP: it lies inside
    CHECK(intersects(unit26, wide_tetrahedron(2)));
    CHECK(intersects(wide_tetrahedron(1), corner_cut)); // the top faces in one plane
    CHECK_FALSE(intersects(corner_cut, wide_tetrahedron(-0x1p-1074)));
    CHECK(intersects(corner_cut, tetrahedron3{{1, 1, 0.5}, {3, 3, 3}, {3, 2, 3}, {2, 3, 2}})); // a vertex on the cut face
    CHECK_FALSE(intersects(tetrahedron3{{1, 1, 0x1.0000000000001p-1}, {3, 3, 3}, {3, 2, 3}, {2, 3, 2}}, corner_cut));
    CHECK_FALSE(intersects(empty14, wide_tetrahedron(2)));
    CHECK(contains(corner_cut, tetrahedron3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 1}}));
    CHECK_FALSE(contains(corner_cut, tetrahedron3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}}));
}
TEST_CASE("kdop_tetrahedron: oracle, random and near-degenerate, K = 6, 14, 18, 26", "[kdop_tetrahedron][oracle]") {
    support::kdop_oracle_every_k<tetrahedron3>("kdop_tetrahedron", support::cases(5000), approx_bound);
}
TEST_CASE("kdop_tetrahedron: rewrites of the other shape and exact translations give the same answer", "[kdop_tetrahedron]") {
    support::kdop_symmetries_every_k<tetrahedron3>("kdop_tetrahedron", support::cases(2500));
}
TEST_CASE("kdop_tetrahedron: contains", "[kdop_tetrahedron][oracle]") {
    support::kdop_contains_oracle<14, tetrahedron3>("kdop_tetrahedron", support::cases(2000), approx_bound);
    support::kdop_contains_oracle<26, tetrahedron3>("kdop_tetrahedron", support::cases(1000), approx_bound);
}

} // namespace test_query_kdop_tetrahedron
