// frustum3 x sphere3 (the ball): fixtures (balls tangent to a face, an edge and a corner of the
// integer frustum, Pythagorean, and one ulp short; one that the classic plane-by-plane culling test
// keeps though it misses); every tier against the exact QP (the squared distance from the centre to
// the frustum's half-spaces, CGAL's QP_solver over Gmpzf) on 20,000 random camera frustums and
// 20,000 near-degenerate integer frustums with balls tangent at a face, an edge or a corner,
// exactly or within ulps (testkit/ball_halfspace_cases.hpp); contains(frustum, ball) against the
// rows in rationals on 20,000 + 20,000 such cases; the classic culling test as the catalog's
// alternative never drops a ball that meets.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/polyhedron_fixtures.hpp"
#include "testkit/ball_halfspace_checks.hpp"

namespace test_query_frustum_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_sphere"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("frustum_sphere: fixtures", "[frustum_sphere]") {
    // integer_frustum: |x|, |y| <= z, 1 <= z <= 4
    CHECK(intersects(integer_frustum, sphere3{{0, 0, -2}, 3})); // touches the near face at (0, 0, 1)
    CHECK_FALSE(intersects(integer_frustum, sphere3{{0, 0, -2}, 0x1.7ffffffffffffp+1}));
    CHECK(intersects(sphere3{{4, 0, -3}, 5}, integer_frustum)); // the edge x = z = 1: (3, 0, -4), a 3-4-5 triangle
    CHECK_FALSE(intersects(sphere3{{4, 0, -3}, 0x1.3ffffffffffffp+2}, integer_frustum));
    CHECK(intersects(integer_frustum, sphere3{{3, 4, -5}, 7})); // the corner (1, 1, 1): (2, 3, -6), 2-3-6-7
    CHECK_FALSE(intersects(integer_frustum, sphere3{{3, 4, -5}, 0x1.bffffffffffffp+2}));
    // the classic test finds no plane with the ball wholly beyond it, yet the ball misses the corner
    CHECK(method::frustum_sphere_planes(integer_frustum, sphere3{{3, 4, -5}, 6.5}));
    CHECK_FALSE(intersects(integer_frustum, sphere3{{3, 4, -5}, 6.5}));
    CHECK(intersects(integer_frustum, sphere3{{0, 0, 2}, 0}));   // a point inside
    CHECK(intersects(integer_frustum, sphere3{{3, 4, -5}, -7})); // an unchecked negative radius acts as |r|
    CHECK(contains(integer_frustum, sphere3{{0, 0, 2.5}, 1.5})); // tangent to the near and far faces
    CHECK_FALSE(contains(integer_frustum, sphere3{{0, 0, 2.5}, 0x1.8000000000001p+0}));
    CHECK(contains(integer_frustum, sphere3{{0, 0, 4}, 0}));
    CHECK_FALSE(intersects(integer_frustum, sphere3{{__builtin_nan(""), 0, 2}, 1}));
    CHECK_FALSE(intersects(integer_frustum, sphere3{{0, 0, 2}, __builtin_inf()}));
    CHECK(intersects(camera, sphere3{{0, 0, -50}, 1}));
    CHECK_FALSE(intersects(camera, sphere3{{0, 0, 50}, 1}));
    CHECK_FALSE(contains(camera, sphere3{{0, 0, -50}, 49}));
    CHECK(contains(camera, sphere3{{0, 0, -50}, 20}));
}
TEST_CASE("frustum_sphere: oracle, random and near-degenerate", "[frustum_sphere][oracle]") {
    support::ball_halfspace_oracle<frustum3>("frustum_sphere", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_sphere: contains", "[frustum_sphere][oracle]") {
    support::ball_halfspace_contains<frustum3>("frustum_sphere", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_sphere: the classic culling test keeps every ball that meets", "[frustum_sphere]") {
    support::rng r(support::seed() + 5);
    long kept = 0, wrongly_kept = 0, dropped = 0, n = 0;
    for (long i = 0; i < support::cases(4000); ++i) {
        const auto c = i % 2 ? support::ball_near<frustum3>(r) : support::ball_random<frustum3>(r);
        if (!c) continue;
        ++n;
        const bool meets = intersects(c->first, c->second), culled = !method::frustum_sphere_planes(c->first, c->second);
        kept += !culled;
        wrongly_kept += !culled && !meets;
        dropped += culled && meets && classify(c->first, c->second) == certainty::yes; // a clear hit dropped
    }
    std::printf("[cases] frustum_sphere planes: %ld cases, %ld kept, %ld of them missing the frustum\n", n, kept, wrongly_kept);
    CHECK(dropped == 0);
    CHECK(wrongly_kept > 0); // the corners' false positives exist
}

} // namespace test_query_frustum_sphere
