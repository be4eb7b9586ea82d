// obb3 x obb3: the 15 separating axes in every tier; the exact LP oracle (CGAL QP_solver over
// Gmpzf) on 20,000 random and 20,000 near-degenerate cases (boxes touching corner to face, edge
// to edge and face to face, flat boxes, signed-permutation, dyadic near-rotation and skew
// frames, ulp nudges, 2^+-500), and rewritten axes. (FCL's test and Gottschalk's are measured
// against the same oracle in bench/: wrong_pct.)
// contains(obb, obb) against exact rationals (the vertices or the inner box's corners by Cramer's
// rule in the box's frame) on 10,000 random and 10,000 cases inside, on the boundary from inside or
// just beyond it.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/obb_check.hpp"
#include "testkit/contain_checks.hpp"

namespace test_query_obb_obb { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("obb_obb"); // stated in the catalog (modules/query/catalog.cppm)

std::pair<obb3, obb3> near_case(support::rng& r) { return support::obb_case<obb3, obb3>::near(r); }
std::pair<obb3, obb3> random_case(support::rng& r) { return support::obb_case<obb3, obb3>::random(r); }
std::vector<std::pair<obb3, obb3>> variants(const obb3& a, const obb3& b, support::rng&) {
    return {{support::rewritten(a, 0), b}, {a, support::rewritten(b, 1)}, {b, a}};
}
} // namespace

TEST_CASE("obb_obb: fixtures (closed boxes, touching counts)", "[obb_obb]") {
    const obb3 A{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    // a box rotated 45 degrees about z (axes (1, 1, 0) and (-1, 1, 0), not unit: a parallelepiped)
    const obb3 D{{3, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    CHECK(intersects(A, D)); // D's corner (3 - 2, 0, 0) = (1, 0, 0) lies on A's face x = 1
    CHECK_FALSE(intersects(A, obb3{{3.0000000000000004, 0, 0}, D.axes, D.half_extents}));
    CHECK(intersects(A, obb3{{2, 2, 2}, A.axes, {1, 1, 1}})); // corner to corner
    CHECK_FALSE(intersects(A, obb3{{2, 2, 2.0000000000000004}, A.axes, {1, 1, 1}}));
    CHECK(intersects(A, obb3{{0.5, 0.5, 0.5}, D.axes, {0.1, 0.1, 0.1}})); // inside
    CHECK(intersects(A, obb3{{0, 0, 5}, A.axes, {0, 0, 4}}));             // a flat box (a point) on the face
    CHECK_FALSE(intersects(A, obb3{{0, 0, 5}, A.axes, {0, 0, 0x1.fffffffffffffp1}}));
    // two coplanar flat boxes (rectangles in z = 0) missing each other in the plane: needs the
    // in-plane axes, none of the 15 separates them
    const obb3 R1{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 0}};
    const obb3 R2{{3, 0, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {0.75, 0.75, 0}};
    CHECK_FALSE(intersects(R1, R2));
    CHECK(intersects(R1, obb3{{2.5, 0, 0}, R2.axes, R2.half_extents}));
    CHECK_FALSE(intersects(obb3{{0, 0, 0}, A.axes, {-1, 1, 1}}, A)); // negative extent: empty
}
TEST_CASE("obb_obb: oracle", "[obb_obb][oracle]") {
    support::run_obb_pair<obb3, obb3>("obb_obb", support::cases(20000), approx_bound, near_case, random_case);
}
TEST_CASE("obb_obb: rewritten boxes and swapped arguments give the same answer", "[obb_obb]") {
    support::run_rewritten<obb3, obb3>("obb_obb", support::cases(20000), near_case, random_case, variants);
}

TEST_CASE("obb_obb: contains(obb, obb)", "[obb_obb][oracle]") {
    support::contains_oracle<obb3, obb3>(
        "obb_obb (obb around obb)", support::cases(10000), approx_bound,
        [](support::rng& r) { return support::obb_case<obb3, obb3>::random(r); }, support::obb_holding<obb3>);
}

} // namespace test_query_obb_obb
