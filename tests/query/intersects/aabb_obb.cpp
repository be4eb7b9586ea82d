// aabb3 x obb3: the 15 separating axes with the aabb3 as a zonotope, in every tier; the exact LP
// oracle (CGAL QP_solver over Gmpzf) on 20,000 random and 20,000 near-degenerate cases (a box's
// corner, edge or face point on the other's boundary, flat boxes, skew and near-rotated frames,
// ulp nudges, 2^+-500), and rewritten axes.
// contains(aabb, obb) and contains(obb, aabb) against exact rationals (the vertices or corners by
// Cramer's rule in the outer box's frame; the oriented box's corners against the box's slabs) on
// 10,000 random and 10,000 cases inside, on the boundary from inside or just beyond it.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/obb_check.hpp"
#include "testkit/contain_checks.hpp"

namespace test_query_aabb_obb { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_obb"); // stated in the catalog (modules/query/catalog.cppm)
std::pair<aabb3, obb3> near_case(support::rng& r) { return support::obb_case<aabb3, obb3>::near(r); }
std::pair<aabb3, obb3> random_case(support::rng& r) { return support::obb_case<aabb3, obb3>::random(r); }
std::vector<std::pair<aabb3, obb3>> variants(const aabb3& a, const obb3& b, support::rng& r) {
    (void)r;
    return {{a, support::rewritten(b, 0)}, {a, support::rewritten(b, 1)}};
}
} // namespace

TEST_CASE("aabb_obb: fixtures", "[aabb_obb]") {
    const aabb3 B{{0, 0, 0}, {1, 1, 1}};
    const obb3 D{{3, 0.5, 0.5}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 0.5}};
    CHECK(intersects(B, D)); // D's corner (1, 0.5, 0.5) on the face x = 1
    CHECK_FALSE(intersects(B, obb3{{3.0000000000000004, 0.5, 0.5}, D.axes, D.half_extents}));
    CHECK(intersects(D, B));
    CHECK(intersects(aabb3{{1, 1, 1}, {1, 1, 1}},
                     obb3{{2, 2, 2}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}})); // a point box at a corner
    CHECK_FALSE(intersects(aabb3{{1, 1, 1}, {0, 0, 0}}, D));                                      // inverted box: empty
}
TEST_CASE("aabb_obb: oracle", "[aabb_obb][oracle]") {
    support::run_obb_pair<aabb3, obb3>("aabb_obb", support::cases(20000), approx_bound, near_case, random_case);
}
TEST_CASE("aabb_obb: rewritten shapes give the same answer", "[aabb_obb]") {
    support::run_rewritten<aabb3, obb3>("aabb_obb", support::cases(20000), near_case, random_case, variants);
}

TEST_CASE("aabb_obb: contains(aabb, obb)", "[aabb_obb][oracle]") {
    support::contains_oracle<aabb3, obb3>(
        "aabb_obb (aabb around obb)", support::cases(10000), approx_bound,
        [](support::rng& r) { return support::obb_case<aabb3, obb3>::random(r); }, support::aabb_holding_obb);
}
TEST_CASE("aabb_obb: contains(obb, aabb)", "[aabb_obb][oracle]") {
    support::contains_oracle<obb3, aabb3>(
        "aabb_obb (obb around aabb)", support::cases(10000), approx_bound,
        [](support::rng& r) {
            const auto [a, b] = support::obb_case<aabb3, obb3>::random(r);
            return std::pair{b, a};
        },
        support::obb_holding<aabb3>);
}

} // namespace test_query_aabb_obb
