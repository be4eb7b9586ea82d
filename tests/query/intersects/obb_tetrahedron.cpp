// obb3 x tetrahedron3: fixtures (touching a vertex, one ulp short of it, around it, inside it,
// skew frames, coplanar tetrahedra, NaN and negative extents); the exact LP oracle on 20,000
// random and 20,000 near-degenerate cases (a tetrahedron's vertex, edge or face point, inside or
// just outside, at a box corner, edge or face point; flat boxes and coplanar tetrahedra; skew
// frames, ulp nudges, 2^+-500), rewritten box axes and rotated and reflected vertex orders.
// contains(obb, tetrahedron) against exact rationals (the vertices or the inner box's corners by
// Cramer's rule in the box's frame) on 10,000 random and 10,000 cases inside, on the boundary from
// inside or just beyond it. contains(tetrahedron, obb) against the box's corners in exact rationals
// (CGAL's Tetrahedron_3 side test; a coplanar tetrahedron's faces) on 10,000 random and 10,000
// cases: a box in the corner of a tetrahedron that its far corner touches, or just misses, flat
// boxes in coplanar tetrahedra; fixtures for coplanar, collinear and one-point tetrahedra.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/obb_check.hpp"
#include "testkit/contain_checks.hpp"

namespace test_query_obb_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
const double approx_bound = catalog::approximate_bound("obb_tetrahedron"); // stated in the catalog (modules/query/catalog.cppm)
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
    CHECK(intersects(I, T));                                                              // x >= 1 touches the vertex (1,0,0)
    CHECK_FALSE(intersects(obb3{{2, 0, 0}, I.axes, {0x1.fffffffffffffp-1, 1, 1}}, T));    // x >= 1 + 2^-53
    CHECK(intersects(T, obb3{{0, 0, 0}, I.axes, {5, 5, 5}}));                             // around it
    CHECK(intersects(obb3{{0.2, 0.2, 0.2}, I.axes, {0.01, 0.01, 0.01}}, T));              // inside it
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
    support::contains_oracle<obb3, tetrahedron3>(
        "obb_tetrahedron (obb around tetrahedron)", support::cases(10000), approx_bound,
        [](support::rng& r) { return support::obb_case<obb3, tetrahedron3>::random(r); }, support::obb_holding<tetrahedron3>);
}

TEST_CASE("obb_tetrahedron: contains(tetrahedron, obb), fixtures", "[obb_tetrahedron]") {
    const vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    const obb3 cube{{0.5, 0.5, 0.5}, {x, y, z}, {0.5, 0.5, 0.5}};
    const tetrahedron3 T3{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}};
    CHECK(contains(T3, cube));                                   // the far corner (1, 1, 1) on the face x + y + z = 3
    CHECK(contains(tetrahedron3{T3.b, T3.a, T3.c, T3.d}, cube)); // the other orientation
    CHECK_FALSE(contains(tetrahedron3{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0, 0, 0x1.7ffffffffffffp+1}}, cube));
    CHECK_FALSE(contains(T3, obb3{{0.5, 0.5, 0.5}, {x, y, z}, {0.5, 0.5, 0x1.0000000000001p-1}}));
    CHECK(classify_contains(T3, cube) == certainty::uncertain); // touching: the exact path decides
    // a turned box: corners (1, 2, z), (2, 1, z), (0, 1, z), (1, 0, z) for z = 0, 1, touching four faces
    const tetrahedron3 T4{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}};
    const obb3 turned{{1, 1, 0.5}, {vec3{1, 1, 0}, vec3{-1, 1, 0}, z}, {0.5, 0.5, 0.5}};
    CHECK(contains(T4, turned));
    CHECK_FALSE(contains(T4, obb3{turned.center, turned.axes, {0x1.0000000000001p-1, 0.5, 0.5}})); // (2, 2, 1) pokes out
    // coplanar: the hull of (0,0,0), (2,0,0), (0,2,0) and (1,0,0) is a triangle
    const tetrahedron3 F{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}};
    const obb3 square{{0.5, 0.5, 0}, {x, y, z}, {0.5, 0.5, 0}};
    CHECK(contains(F, square));
    CHECK_FALSE(contains(F, obb3{{0.5, 0.5, 0}, {x, y, z}, {0.5, 0.5, 0x1p-60}})); // not flat
    CHECK_FALSE(contains(F, obb3{{0.5, 0.5, 0x1p-60}, {x, y, z}, {0.5, 0.5, 0}})); // above the plane
    CHECK_FALSE(contains(F, obb3{{0.5, 0.5, 0}, {x, y, z}, {0.5, 0x1.0000000000001p-1, 0}}));
    CHECK(contains(F, obb3{{0.5, 0.5, 0}, {x, y, vec3{1, 2, 0}}, {0.5, 0.5, 7}}) == false);
    CHECK(contains(F, obb3{{0.5, 0.5, 0}, {x, y, vec3{0, 0, 0}}, {0.5, 0.5, 7}})); // a zero axis spans nothing
    // collinear: the segment from (0,0,0) to (3,0,0)
    const tetrahedron3 C{{1, 0, 0}, {0, 0, 0}, {3, 0, 0}, {2, 0, 0}};
    CHECK(contains(C, obb3{{1.5, 0, 0}, {x, y, z}, {1.5, 0, 0}}));
    CHECK(contains(C, obb3{{1.5, 0, 0}, {vec3{-2, 0, 0}, y, z}, {0.75, 0, 0}}));
    CHECK_FALSE(contains(C, obb3{{1.5, 0, 0}, {x, y, z}, {0x1.8000000000001p+0, 0, 0}}));
    CHECK_FALSE(contains(C, obb3{{1.5, 0, 0}, {vec3{1, 0x1p-70, 0}, y, z}, {1, 0, 0}}));
    // a point
    const tetrahedron3 P{{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
    CHECK(contains(P, obb3{{1, 2, 3}, {x, y, z}, {0, 0, 0}}));
    CHECK_FALSE(contains(P, obb3{{1, 2, 3}, {x, y, z}, {0, 0, 0x1p-1074}}));
    // bad input holds nothing and lies in nothing
    CHECK_FALSE(contains(T3, obb3{{0.5, 0.5, 0.5}, {x, y, z}, {0.5, 0.5, std::nan("")}}));
    CHECK_FALSE(contains(T3, obb3{{0.5, 0.5, 0.5}, {x, y, z}, {0.5, 0.5, -0.25}}));
    CHECK_FALSE(contains(tetrahedron3{{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0, 0, HUGE_VAL}}, cube));
}
TEST_CASE("obb_tetrahedron: contains(tetrahedron, obb)", "[obb_tetrahedron][oracle]") {
    support::contains_oracle<tetrahedron3, obb3>(
        "obb_tetrahedron (tetrahedron around obb)", support::cases(10000), approx_bound,
        [](support::rng& r) {
            const auto [b, t] = support::obb_case<obb3, tetrahedron3>::random(r);
            return std::pair<tetrahedron3, obb3>{t, b};
        },
        support::tetrahedron_holding_obb);
}

} // namespace test_query_obb_tetrahedron
