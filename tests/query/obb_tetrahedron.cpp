// obb3 x tetrahedron3: fixtures (touching a vertex, one ulp short of it, around it, inside it,
// skew frames, coplanar tetrahedra, NaN and negative extents); the exact LP oracle on 20,000
// random and 20,000 near-degenerate cases (a tetrahedron's vertex, edge or face point, inside or
// just outside, at a box corner, edge or face point; flat boxes and coplanar tetrahedra; skew
// frames, ulp nudges, 2^+-500), rewritten box axes and rotated and reflected vertex orders.
// contains(obb, tetrahedron) against exact rationals (the vertices or the inner box's corners by
// Cramer's rule in the box's frame) on 10,000 random and 10,000 cases inside, on the boundary from
// inside or just beyond it.
#include <catch2/catch_test_macros.hpp>
#include "../oracle/cgal_oracle.hpp"
import incidence;
#include "../support/testing.hpp"
#include "../support/check.hpp"
#include "../support/obb_cases.hpp"
#include "../support/obb_check.hpp"
#include "../support/contain_cases.hpp"

namespace test_query_obb_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
constexpr double approx_bound = 0x1p-40; // stated in modules/query/obb_tetrahedron.cppm
std::pair<obb3, tetrahedron3> near_case(support::rng& r) { return support::obb_case<obb3, tetrahedron3>::near(r); }
std::pair<obb3, tetrahedron3> random_case(support::rng& r) { return support::obb_case<obb3, tetrahedron3>::random(r); }
std::vector<std::pair<obb3, tetrahedron3>> variants(const obb3& a, const tetrahedron3& b, support::rng& r) {
    (void)r;
    return {{support::rewritten(a, 0), tetrahedron3{b.b, b.c, b.d, b.a}}, {support::rewritten(a, 1), tetrahedron3{b.a, b.c, b.b, b.d}}};
}
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("obb_tetrahedron: fixtures", "[obb_tetrahedron]") {
    const obb3 I{{2, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}};
    CHECK(intersects(I, T));                                                     // x >= 1 touches the vertex (1,0,0)
    CHECK_FALSE(intersects(obb3{{2, 0, 0}, I.axes, {0x1.fffffffffffffp-1, 1, 1}}, T)); // x >= 1 + 2^-53
    CHECK(intersects(T, obb3{{0, 0, 0}, I.axes, {5, 5, 5}}));                    // around it
    CHECK(intersects(obb3{{0.2, 0.2, 0.2}, I.axes, {0.01, 0.01, 0.01}}, T));     // inside it
    const obb3 D{{1, 1, 0}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}}, {0.5, 1, 1}}; // skew: x + y >= 1, on the edge
    CHECK(intersects(D, T));
    CHECK_FALSE(intersects(obb3{D.center, D.axes, {0x1.fffffffffffffp-2, 1, 1}}, T));
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};
    CHECK(intersects(obb3{{1, 1, 5}, I.axes, {0.5, 0.5, 5}}, flat));
    CHECK_FALSE(intersects(obb3{{1, 1, 5}, I.axes, {0.5, 0.5, 0x1.fffffffffffffp1}}, flat));
    CHECK_FALSE(intersects(obb3{{0, 0, 0}, I.axes, {5, 5, std::nan("")}}, T));
    CHECK_FALSE(intersects(obb3{{0, 0, 0}, I.axes, {5, 5, -1}}, T));
    CHECK_FALSE(intersects(obb3{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, HUGE_VAL}}, {5, 5, 5}}, T));
}
TEST_CASE("obb_tetrahedron: oracle", "[obb_tetrahedron][oracle]") {
    support::run_obb_pair<obb3, tetrahedron3>("obb_tetrahedron", support::cases(20000), approx_bound, near_case, random_case);
}
TEST_CASE("obb_tetrahedron: rewritten shapes give the same answer", "[obb_tetrahedron]") {
    support::run_rewritten<obb3, tetrahedron3>("obb_tetrahedron", support::cases(20000), near_case, random_case, variants);
}

TEST_CASE("obb_tetrahedron: contains(obb, tetrahedron)", "[obb_tetrahedron][oracle]") {
    support::contains_oracle<obb3, tetrahedron3>("obb_tetrahedron (obb around tetrahedron)", support::cases(10000), approx_bound,
                                     [](support::rng& r) { return support::obb_case<obb3, tetrahedron3>::random(r); },
                                     support::obb_holding<tetrahedron3>);
}

} // namespace test_query_obb_tetrahedron
