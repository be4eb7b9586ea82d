// obb3 x triangle3: the 13 separating axes in every tier; the exact LP oracle on 20,000 random
// and 20,000 near-degenerate cases (a triangle's vertex or edge on a corner, edge or face point,
// flat boxes and collinear triangles, skew frames, ulp nudges, 2^+-500), rotated and reversed
// vertices and rewritten axes.
// contains(obb, triangle) against exact rationals (the vertices or the inner box's corners by
// Cramer's rule in the box's frame) on 10,000 random and 10,000 cases inside, on the boundary from
// inside or just beyond it.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/obb_check.hpp"
#include "testkit/contain_checks.hpp"

namespace test_query_obb_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("obb_triangle"); // stated in the catalog (modules/query/catalog.cppm)
std::pair<obb3, triangle3> near_case(support::rng& r) { return support::obb_case<obb3, triangle3>::near(r); }
std::pair<obb3, triangle3> random_case(support::rng& r) { return support::obb_case<obb3, triangle3>::random(r); }
std::vector<std::pair<obb3, triangle3>> variants(const obb3& a, const triangle3& b, support::rng& r) {
    (void)r;
    return {{support::rewritten(a, 0), triangle3{b.b, b.c, b.a}}, {support::rewritten(a, 1), triangle3{b.a, b.c, b.b}}};
}
} // namespace

TEST_CASE("obb_triangle: fixtures", "[obb_triangle]") {
    const obb3 D{{0, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    CHECK(intersects(D, triangle3{{2, 0, 0}, {3, 1, 0}, {3, -1, 0}})); // a vertex at the corner
    CHECK_FALSE(intersects(D, triangle3{{2.0000000000000004, 0, 0}, {3, 1, 0}, {3, -1, 0}}));
    CHECK(intersects(D, triangle3{{3, 0, -3}, {1, 0, 3}, {3, 0, 3}}));         // an edge through the corner edge
    CHECK(intersects(triangle3{{-5, -5, 0.5}, {5, -5, 0.5}, {0, 5, 0.5}}, D)); // cuts the box
    CHECK_FALSE(intersects(D, triangle3{{-5, -5, 1.0000000000000002}, {5, -5, 1.0000000000000002}, {0, 5, 1.0000000000000002}}));
}
TEST_CASE("obb_triangle: oracle", "[obb_triangle][oracle]") {
    support::run_obb_pair<obb3, triangle3>("obb_triangle", support::cases(20000), approx_bound, near_case, random_case);
}
TEST_CASE("obb_triangle: rewritten shapes give the same answer", "[obb_triangle]") {
    support::run_rewritten<obb3, triangle3>("obb_triangle", support::cases(20000), near_case, random_case, variants);
}

TEST_CASE("obb_triangle: contains(obb, triangle)", "[obb_triangle][oracle]") {
    support::contains_oracle<obb3, triangle3>(
        "obb_triangle (obb around triangle)", support::cases(10000), approx_bound,
        [](support::rng& r) { return support::obb_case<obb3, triangle3>::random(r); }, support::obb_holding<triangle3>);
}

} // namespace test_query_obb_triangle
