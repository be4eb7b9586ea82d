// mesh3 x segment3: fixtures (through the cube, in the dent, touching the dent's apex, inside,
// one ulp off a face); the CGAL Epeck oracle (the triangles by
// do_intersect, the inside by crossing parity with CGAL::orientation) on 20,000 random and 20,000
// near-degenerate cases (closed non-convex star meshes; the other shape through a vertex, an edge
// midpoint or a face point, along a face edge or not, or around the inside centre; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and reversed
// triangles, rewritten partners, exact translations.
// contains(mesh, segment): fixtures (through the cube, along its edges and faces, into the dent,
// on a fin of two back-to-back triangles and past its edge); the CGAL Epeck oracle (the segment
// split at its exact intersections with every triangle, each piece's midpoint on a triangle or
// inside) on 10,000 random and 10,000 near-degenerate cases (support/mesh_cases.hpp:
// segment_in_mesh_near, segment_in_mesh_random).
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
#include "testkit/mesh_checks.hpp"
#include "testkit/mesh_fixtures.hpp"

namespace test_query_mesh_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("mesh_segment"); // stated in the catalog (modules/query/catalog.cppm)

// The unit cube and a fin on its top face: two back-to-back triangles (0.5, 0.5, 1), (2, 0.5, 1),
// (0.5, 2, 1) (closed: each edge used twice), reaching past the cube.
constexpr std::array<point3, 11> fin_vertices{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {0.5, 0.5, 1}, {2, 0.5, 1}, {0.5, 2, 1}}};
constexpr std::array<std::array<std::uint32_t, 3>, 14> fin_triangles{{{0, 4, 6},
                                                                      {0, 6, 2},
                                                                      {1, 3, 7},
                                                                      {1, 7, 5},
                                                                      {0, 1, 5},
                                                                      {0, 5, 4},
                                                                      {2, 6, 7},
                                                                      {2, 7, 3},
                                                                      {0, 2, 3},
                                                                      {0, 3, 1},
                                                                      {4, 5, 7},
                                                                      {4, 7, 6},
                                                                      {8, 9, 10},
                                                                      {8, 10, 9}}};
constexpr mesh3 finned{fin_vertices, fin_triangles};
// The box [-2048, 1] x [0, 1] x [0, 1] (the cube's triangles): a segment along it ending 2^-52 past
// x = 1 leaves it at t = 1 - 2^-52 / 1025, with no double between that and 1, so the last piece is
// decided at its exact rational midpoint.
constexpr std::array<point3, 8> long_vertices{
    {{-2048, 0, 0}, {1, 0, 0}, {-2048, 1, 0}, {1, 1, 0}, {-2048, 0, 1}, {1, 0, 1}, {-2048, 1, 1}, {1, 1, 1}}};
constexpr mesh3 long_box{long_vertices, support::cube_triangles};
} // namespace

TEST_CASE("mesh_segment: fixtures", "[mesh_segment]") {
    CHECK(intersects(cube, segment3{{-1, 0.5, 0.5}, {2, 0.5, 0.5}}));
    CHECK(intersects(cube, segment3{{0.2, 0.2, 0.2}, {0.3, 0.3, 0.3}}));       // inside
    CHECK_FALSE(intersects(dented, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 2}})); // in the dent
    CHECK(intersects(dented, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.25}}));    // down to the apex
    CHECK_FALSE(intersects(dented, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0x1.0000000000001p-2}}));
    CHECK_FALSE(intersects(segment3{{0x1.0000000000001p0, 0, 0}, {2, 1, 1}}, cube));
}
TEST_CASE("mesh_segment: contains, fixtures", "[mesh_segment]") {
    using support::cube;
    CHECK(contains(cube, segment3{{0.2, 0.2, 0.2}, {0.8, 0.8, 0.8}}));
    CHECK(contains(cube, segment3{{0, 0, 0}, {1, 1, 1}}));           // corner to corner
    CHECK(contains(cube, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 1}})); // up to the top face
    CHECK_FALSE(contains(cube, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0x1.0000000000001p0}}));
    CHECK(contains(cube, segment3{{0.1, 0.2, 1}, {0.9, 0.7, 1}})); // on the top face, across its diagonal
    CHECK(contains(cube, segment3{{0, 0, 0}, {1, 0, 0}}));         // along an edge
    CHECK_FALSE(contains(cube, segment3{{0, 0, 0}, {1.5, 0, 0}}));
    CHECK_FALSE(contains(cube, segment3{{0.5, 0.5, 1}, {1.5, 0.5, 1}})); // on the top face's plane, then past it
    CHECK(contains(cube, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}}));
    CHECK_FALSE(contains(cube, segment3{{2, 2, 2}, {2, 2, 2}}));
    CHECK(contains(support::dented, segment3{{0.5, 0.5, 0.1}, {0.5, 0.5, 0.25}})); // up to the dent's apex
    CHECK_FALSE(contains(support::dented, segment3{{0.5, 0.5, 0.1}, {0.5, 0.5, 0x1.0000000000001p-2}}));
    CHECK(contains(support::dented, segment3{{0.1, 0.1, 0.2}, {0.9, 0.9, 0.2}}));       // below the apex
    CHECK_FALSE(contains(support::dented, segment3{{0.1, 0.5, 0.9}, {0.9, 0.5, 0.9}})); // through the dent
    CHECK_FALSE(contains(support::dented, segment3{{0, 0, 1}, {1, 1, 1}}));             // over the dent's opening, corner to corner
    CHECK(contains(support::dented, segment3{{0, 0, 1}, {1, 0, 1}}));                   // its rim
    REQUIRE(mesh3::make(fin_vertices, fin_triangles).has_value());
    CHECK(contains(finned, segment3{{0.2, 0.6, 1}, {1.5, 0.6, 1}}));                            // the top face, then the fin
    CHECK(contains(finned, segment3{{1.2, 0.6, 1}, {1.5, 0.9, 1}}));                            // on the fin alone
    CHECK(contains(finned, segment3{{0.25, 0.625, 1}, {1.875, 0.625, 1}}));                     // to the fin's edge x + y = 5/2
    CHECK_FALSE(contains(finned, segment3{{0.25, 0.625, 1}, {0x1.e000000000001p0, 0.625, 1}})); // one ulp past it
    CHECK_FALSE(contains(finned, segment3{{0.2, 0.6, 1}, {2.2, 0.6, 1}}));
    CHECK_FALSE(contains(finned, segment3{{1.5, 0.6, 0.5}, {1.5, 0.6, 1.5}})); // across the fin, outside the cube
    CHECK(contains(long_box, segment3{{-1024, 0.5, 0.5}, {1, 0.5, 0.5}}));
    CHECK_FALSE(contains(long_box, segment3{{-1024, 0.5, 0.5}, {0x1.0000000000001p0, 0.5, 0.5}}));
    CHECK_FALSE(contains<approximate>(long_box, segment3{{-1024, 0.5, 0.5}, {0x1.0000000000001p0, 0.5, 0.5}}));
    // an unchecked octahedron with three vertices at the origin (the triangles there are collinear
    // or points): a zero-length edge holds no piece of the segment (found by fuzz/solids)
    const std::array<point3, 6> collapsed{{{0x0.07f9f5bae8dap-1022, 0x0.0000000000007p-1022, 0x0.0000000002p-1022},
                                           {0x0.7007ap-1022, 0, 0x1.000000f001ep+737},
                                           {0x0.000000000056ep-1022, 0x1.e6e6e6e6e6ep+743, 0x1.e6e6e6e6e6e6ep+743},
                                           {0, 0, 0},
                                           {0, 0, 0},
                                           {0, 0, 0}}};
    const std::array<std::array<std::uint32_t, 3>, 8> octahedron{
        {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
    const mesh3 odd{collapsed, octahedron};
    CHECK_FALSE(contains(odd, segment3{{0, 0, 0}, {0, 0, 0x1.e6e6ep+743}})); // the far end is outside
    CHECK_FALSE(contains(odd, point3{0, 0, 0x1.e6e6ep+743}));
    CHECK(contains(odd, segment3{{0, 0, 0}, {0, 0, 0}}));
    CHECK(contains<conservative>(cube, segment3{{0.2, 0.2, 0.2}, {0.8, 0.8, 0.8}}));
    CHECK_FALSE(contains<aggressive>(cube, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 2}}));
    CHECK(classify_contains(cube, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 1}}) == certainty::yes); // touching: settled in the filter pass
    CHECK_FALSE(contains(mesh3{}, segment3{{0, 0, 0}, {1, 1, 1}}));
    CHECK_FALSE(contains(cube, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, std::nan("")}}));
}
TEST_CASE("mesh_segment: contains against the oracle, random and near-degenerate", "[mesh_segment][oracle]") {
    support::mesh_store store;
    support::contains_oracle_cases(
        "mesh_segment", support::cases(10000), approx_bound,
        [&](support::rng& r, bool near) -> std::optional<std::pair<mesh3, segment3>> {
            const segment3 s = near ? support::segment_in_mesh_near(r, store) : support::segment_in_mesh_random(r, store);
            bool fin = support::finite_shape(s);
            for (const auto& p : store.v) fin = fin && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
            if (!fin) return std::nullopt;
            return std::pair{store.view(), s};
        },
        [](const mesh3& m, const segment3& s) { return support::segment_in_mesh_truth(m, s); },
        [](const mesh3& m, const segment3& s) { return support::shape_str(m) + " " + support::shape_str(s); });
}
TEST_CASE("mesh_segment: oracle, random and near-degenerate", "[mesh_segment][oracle]") {
    support::mesh_oracle<segment3>("mesh_segment", support::cases(20000), approx_bound);
}
TEST_CASE("mesh_segment: rewrites of either shape and exact translations give the same answer", "[mesh_segment]") {
    support::mesh_symmetries<segment3>("mesh_segment", support::cases(20000));
}

} // namespace test_query_mesh_segment
