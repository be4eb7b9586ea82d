// polygon3 x triangle3: fixtures (a vertical triangle through the hole alone and across the ring,
// coplanar triangles in the hole and over the ring, a vertex on the polygon and one ulp above); the
// oracle (the polygon's CGAL constrained triangulation, each triangle against the other shape by CGAL
// Epeck, the exact LP or the mesh oracle) on 20,000 random and 20,000 near-degenerate cases
// (support/polygon3_cases.hpp: exactly planar star polygons with holes at scales 2^-500..2^500, the
// other shape at a vertex, an edge point or inside, along the edge, in the plane or across it, nudged
// by ulps or not); both argument orders, rotated and reversed rings, rewritten partners, exact
// translations.
// contains(polygon3, triangle3): fixtures (a square with a triangular hole: the hole itself, a
// triangle around the hole whose edges all lie in the polygon, one sharing the hole's edge from
// outside, collinear triangles, a corner off the plane); the oracle (in the plane by
// CGAL::orientation, then the areas of the projected triangle's intersections with the polygon's
// CGAL triangulation, in Epeck, adding up to its own) on 10,000 random and 10,000 near-degenerate
// cases (support/polygon3_cases.hpp: points_in_polygon3).
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include <optional>
#include <utility>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/mesh_checks.hpp"
#include "testkit/polygon3_cases.hpp"
#include "testkit/polygon3_checks.hpp"
#include "testkit/polygon3_fixtures.hpp"
#include "testkit/polyhedron_fixtures.hpp"
#include "testkit/kdop_fixtures.hpp"
#include "testkit/mesh_fixtures.hpp"

namespace test_query_polygon_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("polygon_triangle"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("polygon_triangle: fixtures", "[polygon_triangle]") {
    CHECK_FALSE(intersects(holed, triangle3{{2, 1.5, 0}, {2, 2.5, 0}, {2, 2, 2}}));       // through the hole only
    CHECK(intersects(holed, triangle3{{2, -1, 0}, {2, 2.5, 0}, {2, 2, 2}}));              // across the ring: y from 1/2 to 9/4 at z = 1
    CHECK_FALSE(intersects(triangle3{{1.5, 1.5, 1}, {2.5, 1.5, 1}, {2, 2.5, 1}}, holed)); // coplanar, in the hole
    CHECK(intersects(holed, triangle3{{-9, -9, 1}, {9, -9, 1}, {0, 9, 1}}));              // coplanar, over it all
    CHECK(intersects(holed, triangle3{{0.5, 0.5, 1}, {9, 9, 5}, {9, 0, 5}}));             // a vertex on it
    CHECK_FALSE(intersects(holed, triangle3{{0.5, 0.5, 0x1.0000000000001p0}, {9, 9, 5}, {9, 0, 5}}));
}
TEST_CASE("polygon_triangle: contains, fixtures", "[polygon_triangle]") {
    // the square [0, 8]^2 in z = 0 less the triangle (2, 2), (6, 2), (2, 6)
    const std::array<point3, 7> v{{{0, 0, 0}, {8, 0, 0}, {8, 8, 0}, {0, 8, 0}, {2, 2, 0}, {2, 6, 0}, {6, 2, 0}}};
    const std::array<std::uint32_t, 2> ends{4, 7};
    const auto made = polygon3::make(v, ends);
    REQUIRE(made.has_value());
    const polygon3 g = made.value();
    CHECK_FALSE(contains(g, triangle3{{2, 2, 0}, {6, 2, 0}, {2, 6, 0}}));     // the hole: its edges are in the set
    CHECK_FALSE(contains(g, triangle3{{1, 1, 0}, {7.5, 1, 0}, {1, 7.5, 0}})); // around the hole, its edges in the set
    CHECK(contains(g, triangle3{{0, 0, 0}, {8, 0, 0}, {0, 2, 0}}));
    CHECK(contains(g, triangle3{{2, 2, 0}, {6, 2, 0}, {4, 0, 0}}));             // sharing the hole's edge from outside
    CHECK(contains(g, triangle3{{0, 1, 0}, {4, 1, 0}, {8, 1, 0}}));             // collinear
    CHECK_FALSE(contains(g, triangle3{{0, 3, 0}, {4, 3, 0}, {8, 3, 0}}));       // collinear, across the hole
    CHECK_FALSE(contains(g, triangle3{{0, 0, 0}, {8, 0, 0}, {0, 2, 0x1p-60}})); // a corner off the plane
    CHECK(contains(holed, triangle3{{0, 0, 1}, {4, 0, 1}, {0, 1, 1}}));
    CHECK_FALSE(contains(holed, triangle3{{0, 0, 1}, {4, 0, 1}, {0, 4, 1}}));
}
TEST_CASE("polygon_triangle: contains against the oracle, random and near-degenerate", "[polygon_triangle][oracle]") {
    support::polygon3_store store;
    support::contains_oracle_cases(
        "polygon_triangle", support::cases(10000), approx_bound,
        [&](support::rng& r, bool near) -> std::optional<std::pair<polygon3, triangle3>> {
            const auto p = support::points_in_polygon3(r, store, near);
            if (!p) return std::nullopt;
            return std::pair{store.view(), triangle3{(*p)[0], (*p)[1], (*p)[2]}};
        },
        [](const polygon3& g, const triangle3& t) { return support::triangle_in_polygon3_truth(g, t); },
        [](const polygon3& g, const triangle3& t) { return support::shape_str(g) + " " + support::shape_str(t); });
}
TEST_CASE("polygon_triangle: oracle, random and near-degenerate", "[polygon_triangle][oracle]") {
    support::polygon3_oracle<triangle3>("polygon_triangle", support::cases(20000), approx_bound);
}
TEST_CASE("polygon_triangle: rewritten shapes and exact translations give the same answer", "[polygon_triangle]") {
    support::polygon3_symmetries<triangle3>("polygon_triangle", support::cases(5000));
}

} // namespace test_query_polygon_triangle
