// aabb3 x frustum3: fixtures; the exact LP oracle (the frustum as its half-spaces n . x <= offset) on
// 20,000 random and 20,000 near-degenerate cases (an axis-aligned integer frustum (corners dyadic) or a camera frustum (frustum3::from_camera), the box placed at one of its
// boundary points, flat or not; then a random exact-or-nudged scale 2^-500..2^500 and
// translation); both argument orders, rewritten shapes, exact translations of both; contains; the
// culling, separating-axis and six-tetrahedra tests' (in double) answers beside the exact ones.
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

namespace test_query_aabb_frustum { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polyhedron_fixtures;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_frustum"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("aabb_frustum: fixtures", "[aabb_frustum]") {
    CHECK(intersects(aabb3{{-0.5, -0.5, 2}, {0.5, 0.5, 3}}, integer_frustum));
    CHECK(intersects(integer_frustum, aabb3{{4, 4, 4}, {5, 5, 5}})); // touches a far corner
    CHECK_FALSE(intersects(integer_frustum, aabb3{{4, 4, 0x1.0000000000001p2}, {5, 5, 5}}));
    CHECK(intersects(aabb3{{-1, -1, 0}, {1, 1, 1}}, integer_frustum)); // the near face
    CHECK_FALSE(intersects(aabb3{{-1, -1, 0}, {1, 1, 0x1.fffffffffffffp-1}}, integer_frustum));
    // beside the edge of the side x <= z and the far plane: no single plane has it wholly beyond
    const aabb3 beside{{4.5, 0, 3}, {5, 0, 4.75}};
    CHECK_FALSE(intersects(beside, integer_frustum));
    CHECK(method::aabb_frustum_culling(beside, integer_frustum));
    CHECK_FALSE(method::aabb_frustum_sat(beside, integer_frustum)); // an edge-cross-axis separates it
    CHECK(method::aabb_frustum_sat(aabb3{{4, 4, 4}, {5, 5, 5}}, integer_frustum));
    CHECK_FALSE(method::aabb_frustum_decomposition(beside, integer_frustum));                          // no tetrahedron meets it
    CHECK(method::aabb_frustum_decomposition(aabb3{{4, 4, 4}, {5, 5, 5}}, integer_frustum));           // the far corner
    CHECK(method::aabb_frustum_decomposition(aabb3{{-0.5, -0.5, 2}, {0.5, 0.5, 3}}, integer_frustum)); // inside
    CHECK(method::aabb_frustum_decomposition(aabb3{{-1, -1, -200}, {1, 1, -50}}, camera));
    CHECK_FALSE(method::aabb_frustum_decomposition(aabb3{{-1, -1, -0.5}, {1, 1, 0}}, camera)); // before the near plane
    CHECK_FALSE(method::aabb_frustum_decomposition(aabb3{{4, 4, 0x1.0000000000001p2}, {5, 5, 5}}, integer_frustum));
    CHECK(intersects(aabb3{{-1, -1, -200}, {1, 1, -50}}, camera));
    CHECK_FALSE(intersects(aabb3{{-1, -1, -0.5}, {1, 1, 0}}, camera));
    CHECK(contains(integer_frustum, aabb3{{-1, -1, 1}, {1, 1, 1}})); // the near face itself
    CHECK_FALSE(contains(integer_frustum, aabb3{{-1, -1, 1}, {0x1.0000000000001p0, 1, 1}}));
    CHECK_FALSE(contains(integer_frustum, aabb3{{1, 1, 1}, {-1, -1, 1}})); // inverted: not a set
}
TEST_CASE("aabb_frustum: oracle, random and near-degenerate", "[aabb_frustum][oracle]") {
    support::halfspace_oracle<frustum3, aabb3>("aabb_frustum", support::cases(20000), approx_bound);
}
TEST_CASE("aabb_frustum: rewrites of both shapes and exact translations give the same answer", "[aabb_frustum]") {
    support::halfspace_symmetries<frustum3, aabb3>("aabb_frustum", support::cases(5000));
}
TEST_CASE("aabb_frustum: contains", "[aabb_frustum][oracle]") {
    support::halfspace_contains_oracle<frustum3, aabb3>("aabb_frustum", support::cases(2000), approx_bound);
}
TEST_CASE("aabb_frustum: the culling, separating-axis and decomposition tests' wrong answers, counted against the exact tier",
          "[aabb_frustum]") {
    support::rng r(support::seed() + 5);
    long n = 0, yes = 0, culling_yes_wrongly = 0, culling_no_wrongly = 0, sat_wrong[2] = {0, 0}, split_wrong[2] = {0, 0};
    for (long i = 0; i < support::cases(20000); ++i) {
        const auto c = (i % 2) ? support::halfspace_near<frustum3, aabb3>(r) : support::halfspace_random<frustum3, aabb3>(r);
        if (!c) continue;
        ++n;
        const bool e = intersects(c->first, c->second), cull = method::aabb_frustum_culling(c->second, c->first);
        yes += e;
        culling_yes_wrongly += cull && !e;
        culling_no_wrongly += !cull && e;
        sat_wrong[i % 2] += method::aabb_frustum_sat(c->second, c->first) != e;
        split_wrong[i % 2] += method::aabb_frustum_decomposition(c->second, c->first) != e;
    }
    std::printf("[cases] aabb_frustum culling test: %ld cases, %ld meet; culling says yes for %ld that miss, no for %ld that meet\n", n,
                yes, culling_yes_wrongly, culling_no_wrongly);
    std::printf("[cases] aabb_frustum separating axes in double: wrong on %ld random and %ld near-degenerate cases\n", sat_wrong[0],
                sat_wrong[1]);
    std::printf("[cases] aabb_frustum six tetrahedra in double: wrong on %ld random and %ld near-degenerate cases\n", split_wrong[0],
                split_wrong[1]);
    CHECK(yes > 0);
    CHECK(culling_yes_wrongly > 0); // its known weakness: boxes beside an edge or a corner
    CHECK(sat_wrong[0] == 0);       // the axes are complete: wrong only by rounding, at the boundary
    // The six tetrahedra cover the frustum exactly, but their corners are computed in double from the
    // planes: for a frustum far from the origin against its size (random translations), the offsets
    // nearly cancel and the corners lose most of their bits, so the test errs away from the boundary
    // too (about 0.8% of the random cases). Counted, not required to be zero; the fixtures check
    // its geometry.
}

} // namespace test_query_aabb_frustum
