// capsule3 x convex_polyhedron3: fixtures (the box [0, 10]^3: a capsule parallel above a face, one along an
// edge, one whose middle is nearest an edge, one whose middle is nearest a corner, a ball at a
// corner, each touching and one ulp short); every tier against the exact QP between the capsule's
// segment and the set (CGAL's QP_solver over Gmpzf) on 5,000 random and 5,000 near-degenerate
// cases (capsules grown from balls touching the set at a face, an edge or a vertex, exactly or
// within ulps, at scales 2^-500..2^500; testkit/capsule_cases.hpp). contains(convex_polyhedron3, capsule3):
// fixtures (a capsule touching two faces from inside, one ulp too wide, an end outside); both end
// balls in the rows, in rationals (oracle::ball_in_rows), on 10,000 random cases (a capsule grown
// from a random ball) and 10,000 capsules from a point inside the set to a point of its boundary
// or halfway, thin or of radius zero (touching from inside).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_convex_polyhedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_convex_polyhedron"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_convex_polyhedron: fixtures", "[capsule_convex_polyhedron]") {
    // the box [0, 10]^3
    convex_polyhedron3 x{};
    const auto rows = std::array<plane3, 6>{plane3{{-1, 0, 0}, 0}, plane3{{1, 0, 0}, 10}, plane3{{0, -1, 0}, 0},
                                            plane3{{0, 1, 0}, 10}, plane3{{0, 0, -1}, 0}, plane3{{0, 0, 1}, 10}};
    for (unsigned i = 0; i < 6; ++i) x.planes[i] = rows[i];
    x.count = 6;
    support::capsule_box_set_fixtures(x);
}
TEST_CASE("capsule_convex_polyhedron: oracle, random and near-degenerate", "[capsule_convex_polyhedron][oracle]") {
    support::capsule_oracle<convex_polyhedron3>("capsule_convex_polyhedron", support::cases(5000), approx_bound);
}
TEST_CASE("capsule_convex_polyhedron: contains", "[capsule_convex_polyhedron][oracle]") {
    support::capsule_contained<convex_polyhedron3>("capsule_convex_polyhedron", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_convex_polyhedron
