// point3 x polygon3 and contains(polygon, point): fixtures (inside, in the hole, on the hole's edge,
// one ulp above, a tilted non-convex polygon, make() refusing non-planar, collinear and self-crossing
// input with the deviation measured); the oracle (the polygon's CGAL constrained triangulation, each
// triangle against the other shape by CGAL Epeck, the exact LP or the mesh oracle) on 20,000 random
// and 20,000 near-degenerate cases (support/polygon3_cases.hpp: exactly planar star polygons with
// holes at scales 2^-500..2^500, the other shape at a vertex, an edge point or inside, along the edge,
// in the plane or across it, nudged by ulps or not); both argument orders, rotated and reversed rings,
// rewritten partners, exact translations.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "../oracle/cgal_oracle.hpp"
import incidence;
#include "../support/testing.hpp"
#include "../support/check.hpp"
#include "../support/flat_checks.hpp"
#include "../support/lp_shapes.hpp"
#include "../support/mesh_checks.hpp"
#include "../support/polygon3_cases.hpp"
#include "../support/polygon3_checks.hpp"
#include "../support/polygon3_fixtures.hpp"
#include "../support/polyhedron_fixtures.hpp"
#include "../support/kdop_fixtures.hpp"
#include "../support/mesh_fixtures.hpp"

namespace test_query_point_polygon { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
constexpr double approx_bound = 0x1p-40; // stated in modules/query/point_polygon.cppm
} // namespace

TEST_CASE("point_polygon: fixtures", "[point_polygon]") {
    CHECK(intersects(point3{0.5, 0.5, 1}, holed));
    CHECK_FALSE(intersects(point3{2, 2, 1}, holed));                  // in the hole
    CHECK(intersects(holed, point3{1, 2, 1}));                        // on the hole's edge
    CHECK(contains(holed, point3{3, 3, 1}));                          // a hole corner
    CHECK_FALSE(intersects(point3{0.5, 0.5, 0x1.0000000000001p0}, holed)); // one ulp above
    CHECK(intersects(point3{1.5, 0.5, 0.5}, tilted_l));               // x + z = 2 inside the L
    CHECK_FALSE(intersects(point3{1.5, 1.5, 0.5}, tilted_l));         // in the L's notch
    CHECK(intersects(point3{1, 1.5, 1}, tilted_l));                   // on its inner edge
    const auto made = polygon3::make(holed_vertices, holed_ends);
    REQUIRE(made.has_value());
    CHECK(intersects(point3{0.5, 0.5, 1}, made.value()));
    const std::array<point3, 4> bent{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0x1p-40}}};
    const auto refused = polygon3::make(bent);
    REQUIRE_FALSE(refused.has_value());
    CHECK(refused.error().code == errc::non_planar_polygon);
    CHECK(refused.error().measured > 0x1p-42);
    CHECK(refused.error().measured <= 0x1p-40); // the vertex off the plane of the other three: 2^-40 at most
    CHECK(refused.error().what().find("off the plane") != std::string::npos);
    const std::array<point3, 3> line{{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}};
    CHECK(polygon3::make(line).error().code == errc::degenerate_polygon);
    const std::array<point3, 4> bow{{{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}};
    CHECK(polygon3::make(bow).error().code == errc::self_intersecting_polygon);
    const std::array<point3, 3> bad{{{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}};
    CHECK(polygon3::make(bad).error().code == errc::not_finite);
    CHECK_FALSE(intersects(point3{0.5, 0.5, 1}, polygon3{holed_vertices, holed_ends, {0, 2, 9}, 2})); // bad plane index: no set
    CHECK_FALSE(intersects(point3{0.5, 0.5, 1}, polygon3{holed_vertices, holed_ends, {0, 2, 1}, 0}));  // n has no x component: no set
}
TEST_CASE("point_polygon: oracle, random and near-degenerate", "[point_polygon][oracle]") {
    support::polygon3_oracle<point3>("point_polygon", support::cases(20000), approx_bound);
}
TEST_CASE("point_polygon: rewritten shapes and exact translations give the same answer", "[point_polygon]") {
    support::polygon3_symmetries<point3>("point_polygon", support::cases(5000));
}

} // namespace test_query_point_polygon
