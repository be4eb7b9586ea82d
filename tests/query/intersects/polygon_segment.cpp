// polygon3 x segment3: fixtures (crossing inside, through the hole, ending on the polygon and one ulp
// short, in the plane inside the hole and across its edge); the oracle (the polygon's CGAL constrained
// triangulation, each triangle against the other shape by CGAL Epeck, the exact LP or the mesh oracle)
// on 20,000 random and 20,000 near-degenerate cases (support/polygon3_cases.hpp: exactly planar star
// polygons with holes at scales 2^-500..2^500, the other shape at a vertex, an edge point or inside,
// along the edge, in the plane or across it, nudged by ulps or not); both argument orders, rotated and
// reversed rings, rewritten partners, exact translations.
// contains(polygon3, segment3): fixtures (in the plane along the strip, across the hole, along the
// hole's edge, off the plane, one ulp past the outer edge); the oracle (in the plane by
// CGAL::orientation, then the projected segment split at its exact intersections with the edges of
// the polygon's CGAL triangulation, each piece's midpoint in a triangle) on 10,000 random and
// 10,000 near-degenerate cases (support/polygon3_cases.hpp: points_in_polygon3).
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

namespace test_query_polygon_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using namespace support::polygon3_fixtures;
using namespace support::polyhedron_fixtures;
using support::corner_cut;
using support::empty14;
using support::unit26;

namespace {
const double approx_bound = catalog::approximate_bound("polygon_segment"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("polygon_segment: fixtures", "[polygon_segment]") {
    CHECK(intersects(holed, segment3{{0.5, 0.5, 0}, {0.5, 0.5, 2}}));
    CHECK_FALSE(intersects(segment3{{2, 2, 0}, {2, 2, 2}}, holed));   // through the hole
    CHECK(intersects(holed, segment3{{0.5, 0.5, 0}, {0.5, 0.5, 1}})); // ends on it
    CHECK_FALSE(intersects(holed, segment3{{0.5, 0.5, 0}, {0.5, 0.5, 0x1.fffffffffffffp-1}}));
    CHECK_FALSE(intersects(holed, segment3{{1.5, 2, 1}, {2.5, 2, 1}})); // in the plane, in the hole
    CHECK(intersects(holed, segment3{{0.5, 2, 1}, {2, 2, 1}}));         // in the plane, across the hole's edge
    CHECK(intersects(holed, segment3{{3.5, 3.5, 1}, {3.75, 3.5, 1}}));  // in the plane, inside
    CHECK(intersects(tilted_l, segment3{{1.5, 0.5, 0}, {1.5, 0.5, 2}}));
    CHECK_FALSE(intersects(tilted_l, segment3{{1.5, 1.5, 0}, {1.5, 1.5, 2}})); // through the notch
}
TEST_CASE("polygon_segment: contains, fixtures", "[polygon_segment]") {
    CHECK(contains(holed, segment3{{0.5, 0.5, 1}, {0.5, 3.5, 1}}));
    CHECK_FALSE(contains(holed, segment3{{0.5, 0.5, 1}, {3.5, 3.5, 1}})); // across the hole
    CHECK(contains(holed, segment3{{1, 1, 1}, {1, 3, 1}}));               // the hole's edge
    CHECK_FALSE(contains(holed, segment3{{0.5, 0.5, 1}, {0.5, 0.5, 2}})); // off the plane
    CHECK(contains(holed, segment3{{0.5, 0.5, 1}, {0.5, 4, 1}}));
    CHECK_FALSE(contains(holed, segment3{{0.5, 0.5, 1}, {0.5, 0x1.0000000000001p2, 1}}));
    CHECK(contains(holed, segment3{{0.5, 0.5, 1}, {0.5, 0.5, 1}}));
    CHECK(contains(tilted_l, segment3{{0, 0, 2}, {2, 0, 0}}));                   // an edge of the tilted L
    CHECK_FALSE(contains(tilted_l, segment3{{0.5, 0.5, 1.5}, {1.5, 1.5, 0.5}})); // into the notch
}
TEST_CASE("polygon_segment: contains against the oracle, random and near-degenerate", "[polygon_segment][oracle]") {
    support::polygon3_store store;
    support::contains_oracle_cases(
        "polygon_segment", support::cases(10000), approx_bound,
        [&](support::rng& r, bool near) -> std::optional<std::pair<polygon3, segment3>> {
            const auto p = support::points_in_polygon3(r, store, near);
            if (!p) return std::nullopt;
            return std::pair{store.view(), segment3{(*p)[0], (*p)[1]}};
        },
        [](const polygon3& g, const segment3& s) { return support::segment_in_polygon3_truth(g, s); },
        [](const polygon3& g, const segment3& s) { return support::shape_str(g) + " " + support::shape_str(s); });
}
TEST_CASE("polygon_segment: oracle, random and near-degenerate", "[polygon_segment][oracle]") {
    support::polygon3_oracle<segment3>("polygon_segment", support::cases(20000), approx_bound);
}
TEST_CASE("polygon_segment: rewritten shapes and exact translations give the same answer", "[polygon_segment]") {
    support::polygon3_symmetries<segment3>("polygon_segment", support::cases(5000));
}

} // namespace test_query_polygon_segment
