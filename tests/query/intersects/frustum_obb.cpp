// frustum3 x obb3: fixtures (a skew box touching the integer frustum's far corner with an edge and
// one ulp away, a box beside a side edge that no single plane separates, a camera frustum,
// contains on the near face); the exact LP oracle (the frustum as its half-spaces, the box as its
// centre plus bounded multiples of its axes) on 20,000 random and 20,000 near-degenerate cases (an
// axis-aligned integer frustum (corners dyadic) or a camera frustum (frustum3::from_camera), the box
// placed with a corner, an edge or face point at one of its boundary points, in a permuted,
// near-rotation or skew frame; then a random exact-or-nudged scale 2^-500..2^500 and translation);
// both argument orders, rewritten shapes, exact translations of both; contains against the box's
// exact corners; the separating-axis and six-tetrahedra tests' (in double) answers beside the
// exact ones.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/polyhedron_cases.hpp"
#include "testkit/polyhedron_checks.hpp"
#include "testkit/polyhedron_fixtures.hpp"

namespace test_query_frustum_obb { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("frustum_obb");              // stated in the catalog (modules/query/catalog.cppm)
constexpr std::array<vec3, 3> turned{vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}; // 45 degrees about z, length sqrt 2
constexpr std::array<vec3, 3> unit{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
} // namespace

TEST_CASE("frustum_obb: fixtures", "[frustum_obb]") {
    // x + y >= 8 along the edge s0 = -1/2 through the far corner (4, 4, 4), z in [4, 5]
    const obb3 at_corner{{4.5, 4.5, 4.5}, turned, {0.5, 0.5, 0.5}};
    const obb3 short_of{{4.5, 4.5, 4.5}, turned, {0x1.fffffffffffffp-2, 0.5, 0.5}};
    CHECK(intersects(integer_frustum, at_corner));
    CHECK(intersects(at_corner, integer_frustum));
    CHECK_FALSE(intersects(integer_frustum, short_of));
    CHECK(method::frustum_obb_sat(integer_frustum, at_corner));
    CHECK(method::frustum_obb_decomposition(integer_frustum, at_corner));
    CHECK(intersects(integer_frustum, obb3{{0, 0, 2.5}, turned, {0.25, 0.25, 0.25}})); // inside
    // beside the edge of the side x <= z and the far plane: no single plane has it wholly beyond
    const obb3 beside{{4.75, 0, 3.875}, unit, {0.25, 0, 0.875}};
    CHECK_FALSE(intersects(integer_frustum, beside));
    CHECK_FALSE(method::frustum_obb_sat(integer_frustum, beside));
    CHECK_FALSE(method::frustum_obb_decomposition(integer_frustum, beside));
    CHECK(intersects(camera, obb3{{0, 0, -100}, turned, {1, 1, 50}}));
    CHECK(method::frustum_obb_decomposition(camera, obb3{{0, 0, -100}, turned, {1, 1, 50}}));
    CHECK_FALSE(intersects(camera, obb3{{0, 0, -0.25}, turned, {1, 1, 0.25}})); // before the near plane z = -1
    CHECK_FALSE(method::frustum_obb_sat(camera, obb3{{0, 0, -0.25}, turned, {1, 1, 0.25}}));
    CHECK(contains(integer_frustum, obb3{{0, 0, 1}, unit, {1, 1, 0}})); // the near face itself
    CHECK_FALSE(contains(integer_frustum, obb3{{0, 0, 1}, unit, {0x1.0000000000001p0, 1, 0}}));
    CHECK(contains(integer_frustum, obb3{{0, 0, 2}, turned, {0.5, 0.5, 0}}));        // the diamond |x| + |y| <= 1 at z = 2
    CHECK_FALSE(contains(integer_frustum, obb3{{0, 0, 2}, turned, {0.5, 0.5, -1}})); // negative extent: no box
}
TEST_CASE("frustum_obb: oracle, random and near-degenerate", "[frustum_obb][oracle]") {
    support::halfspace_oracle<frustum3, obb3>("frustum_obb", support::cases(20000), approx_bound);
}
TEST_CASE("frustum_obb: rewrites of both shapes and exact translations give the same answer", "[frustum_obb]") {
    support::halfspace_symmetries<frustum3, obb3>("frustum_obb", support::cases(5000));
}
TEST_CASE("frustum_obb: contains", "[frustum_obb][oracle]") {
    support::halfspace_contains_oracle<frustum3, obb3>("frustum_obb", support::cases(2000), approx_bound);
}
TEST_CASE("frustum_obb: the separating-axis and decomposition tests' wrong answers, counted against the exact tier", "[frustum_obb]") {
    support::rng r(support::seed() + 5);
    long n = 0, yes = 0, sat_wrong[2] = {0, 0}, split_wrong[2] = {0, 0};
    for (long i = 0; i < support::cases(20000); ++i) {
        const auto c = (i % 2) ? support::halfspace_near<frustum3, obb3>(r) : support::halfspace_random<frustum3, obb3>(r);
        if (!c) continue;
        ++n;
        const bool e = intersects(c->first, c->second);
        yes += e;
        sat_wrong[i % 2] += method::frustum_obb_sat(c->first, c->second) != e;
        split_wrong[i % 2] += method::frustum_obb_decomposition(c->first, c->second) != e;
    }
    std::printf("[cases] frustum_obb: %ld cases, %ld meet\n", n, yes);
    std::printf("[cases] frustum_obb separating axes in double: wrong on %ld random and %ld near-degenerate cases\n", sat_wrong[0],
                sat_wrong[1]);
    std::printf("[cases] frustum_obb six tetrahedra in double: wrong on %ld random and %ld near-degenerate cases\n", split_wrong[0],
                split_wrong[1]);
    CHECK(yes > 0);
    // Both run in double on corners computed from the planes (aabb_frustum.cpp says why the
    // decomposition errs away from the boundary too): counted, not required to be zero.
}

} // namespace test_query_frustum_obb
