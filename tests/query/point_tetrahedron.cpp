// point3 x tetrahedron3, and contains(tetrahedron, point | segment | triangle | tetrahedron):
// fixtures (inside, on a face, an edge or a vertex, one ulp outside, a subnormal offset, coplanar
// tetrahedra, NaN); the CGAL Epeck oracle (Tetrahedron_3; the exact LP for coplanar tetrahedra) on
// 20,000 random and 20,000 near-degenerate cases (the point at a vertex, an edge, face or inside
// point of the tetrahedron or just outside; coplanar tetrahedra; then a random exact-or-nudged
// scale 2^-500..2^500 and translation); both argument orders, rotated and reflected vertex orders,
// exact translations.
#include <catch2/catch_test_macros.hpp>
#include "../oracle/cgal_oracle.hpp"
import incidence;
#include "../support/testing.hpp"
#include "../support/check.hpp"
#include "../support/flat_checks.hpp"

namespace test_query_point_tetrahedron { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;

namespace {
constexpr double approx_bound = 0x1p-40; // stated in modules/query/point_tetrahedron.cppm
const tetrahedron3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
} // namespace

TEST_CASE("point_tetrahedron: fixtures", "[point_tetrahedron]") {
    CHECK(intersects(point3{0.25, 0.25, 0.25}, T));
    CHECK(intersects(T, point3{0, 0, 1}));                                  // a vertex
    CHECK(intersects(point3{0.5, 0.5, 0}, T));                              // an edge
    CHECK(intersects(point3{0.5, 0.25, 0.25}, T));                          // the slanted face
    CHECK_FALSE(intersects(point3{0.5, 0.25, 0x1.0000000000001p-2}, T));    // one ulp beyond it
    CHECK(intersects(point3{0, 0.1, 0.1}, T));                              // the face x = 0
    CHECK_FALSE(intersects(point3{-0x1p-1074, 0.1, 0.1}, T));               // a subnormal outside it
    CHECK(intersects(point3{0.25, 0.25, 0.25}, tetrahedron3{T.b, T.a, T.c, T.d})); // the other orientation
    const tetrahedron3 flat{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0}};   // coplanar: the triangle's hull
    CHECK(intersects(point3{0.5, 0.5, 0}, flat));
    CHECK_FALSE(intersects(point3{0.5, 0.5, 0x1p-1000}, flat));
    CHECK_FALSE(intersects(point3{std::nan(""), 0.25, 0.25}, T));
    CHECK_FALSE(intersects(point3{0.25, 0.25, 0.25}, tetrahedron3{T.a, T.b, T.c, {0, 0, HUGE_VAL}}));
    CHECK_FALSE(tetrahedron3::make(flat.a, flat.b, flat.c, flat.d).has_value());
    CHECK(tetrahedron3::make(T.a, T.b, T.c, T.d).has_value());
}
TEST_CASE("point_tetrahedron: contains, fixtures", "[point_tetrahedron]") {
    CHECK(contains(T, point3{0.5, 0.25, 0.25}));
    CHECK(contains(T, segment3{{0, 0, 0}, {0.5, 0.25, 0.25}}));
    CHECK_FALSE(contains(T, segment3{{0, 0, 0}, {0.5, 0.25, 0x1.0000000000001p-2}}));
    CHECK(contains(T, triangle3{T.b, T.c, T.d}));
    CHECK(contains(T, T));
    CHECK(contains(T, tetrahedron3{T.a, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5}}));
    CHECK_FALSE(contains(tetrahedron3{T.a, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5}}, T));
    CHECK(contains(T, aabb3{{0, 0, 0}, {0.25, 0.25, 0.5}}));
    CHECK_FALSE(contains(T, aabb3{{0, 0, 0}, {0.25, 0.25, 0x1.0000000000001p-1}}));
    CHECK(contains(aabb3{{0, 0, 0}, {1, 1, 1}}, T));
    CHECK_FALSE(contains(aabb3{{0, 0, 0}, {1, 1, 0x1.fffffffffffffp-1}}, T));
}
TEST_CASE("point_tetrahedron: oracle, random and near-degenerate", "[point_tetrahedron][oracle]") {
    support::flat_oracle<point3, tetrahedron3>("point_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("point_tetrahedron: contains against the oracle", "[point_tetrahedron][oracle]") {
    support::flat_contains_oracle<tetrahedron3, point3>("tetrahedron_point", support::cases(20000), approx_bound);
    support::flat_contains_oracle<tetrahedron3, segment3>("tetrahedron_segment", support::cases(20000), approx_bound);
    support::flat_contains_oracle<tetrahedron3, triangle3>("tetrahedron_triangle", support::cases(20000), approx_bound);
    support::flat_contains_oracle<tetrahedron3, tetrahedron3>("tetrahedron_tetrahedron", support::cases(20000), approx_bound);
    support::flat_contains_oracle<tetrahedron3, aabb3>("tetrahedron_aabb", support::cases(20000), approx_bound);
    support::flat_contains_oracle<aabb3, tetrahedron3>("aabb_tetrahedron", support::cases(20000), approx_bound);
}
TEST_CASE("point_tetrahedron: rewrites of either shape and exact translations give the same answer", "[point_tetrahedron]") {
    support::flat_symmetries<point3, tetrahedron3>("point_tetrahedron", support::cases(20000));
}

} // namespace test_query_point_tetrahedron
