// capsule3 x plane3: fixtures (a capsule crossing a plane, one above it touching with an end, one
// parallel to it; one ulp short; zero normals); // every tier against the exact QP (CGAL's QP_solver over Gmpzf: the squared distance between the
// capsule's segment and the plane, against the radii) on 10,000 random cases and 10,000 capsules
// grown from balls touching small dyadic planes at a vertex, an edge or a face point, exactly or within ulps,
// at a random scale (testkit/capsule_cases.hpp).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_query_capsule_plane { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("capsule_plane"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("capsule_plane: fixtures", "[capsule_plane]") {
    const plane3 p{{0, 3, 4}, 10};                             // at distance 2 from the origin
    CHECK(intersects(capsule3{{0, 0, 0}, {0, 6, 8}, 0}, p));   // crosses it
    CHECK(intersects(p, capsule3{{0, -3, -4}, {0, 0, 0}, 2})); // the end at the origin, 2 away
    CHECK_FALSE(intersects(p, capsule3{{0, -3, -4}, {0, 0, 0}, 0x1.fffffffffffffp+0}));
    CHECK(intersects(p, capsule3{{-50, 0, 0}, {50, 0, 0}, 2})); // parallel
    CHECK_FALSE(intersects(p, capsule3{{-50, 0, 0}, {50, 0, 0}, 0x1.fffffffffffffp+0}));
    CHECK(intersects(plane3{{0, 0, 0}, 0}, capsule3{{1, 1, 1}, {2, 2, 2}, 0}));
    CHECK_FALSE(intersects(plane3{{0, 0, 0}, 1}, capsule3{{1, 1, 1}, {2, 2, 2}, 9}));
}
TEST_CASE("capsule_plane: oracle, random and near-degenerate", "[capsule_plane][oracle]") {
    support::capsule_oracle<plane3>("capsule_plane", support::cases(10000), approx_bound);
}

} // namespace test_query_capsule_plane
