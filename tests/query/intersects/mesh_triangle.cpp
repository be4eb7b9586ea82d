// mesh3 x triangle3: fixtures (inside, in the dent, cutting through, in a face's plane); the CGAL Epeck oracle (the triangles by
// do_intersect, the inside by crossing parity with CGAL::orientation) on 20,000 random and 20,000
// near-degenerate cases (closed non-convex star meshes; the other shape through a vertex, an edge
// midpoint or a face point, along a face edge or not, or around the inside centre; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and reversed
// triangles, rewritten partners, exact translations.
// contains(mesh, triangle): fixtures (inside, on a face, in a diagonal plane along edges, around
// and under the dent, touching its apex and one ulp above it, collinear, NaN; two overlapping
// boxes as one self-crossing surface); an oracle over CGAL Epeck (the surface's traces on the
// triangle and all their crossings, chords at the exact midpoints of their directions from a
// vertex, each chord split at its exact intersections) on 10,000 random and 10,000 near-degenerate
// cases (support/mesh_cases.hpp: triangle_in_mesh_near, triangle_in_mesh_random) and 2,000
// triangles on two star meshes kept as one self-crossing surface.
#include <catch2/catch_test_macros.hpp>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/mesh_checks.hpp"
#include "testkit/mesh_fixtures.hpp"

namespace test_query_mesh_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("mesh_triangle"); // stated in the catalog (modules/query/catalog.cppm)
} // namespace

TEST_CASE("mesh_triangle: fixtures", "[mesh_triangle]") {
    CHECK(intersects(cube, triangle3{{0.2, 0.2, 0.2}, {0.3, 0.2, 0.2}, {0.2, 0.3, 0.2}}));         // inside
    CHECK_FALSE(intersects(dented, triangle3{{0.4, 0.5, 0.5}, {0.6, 0.5, 0.5}, {0.5, 0.6, 0.9}})); // in the dent
    CHECK(intersects(dented, triangle3{{0.4, 0.5, 0.5}, {0.6, 0.5, 0.5}, {0.5, 0.5, 0.25}}));
    CHECK(intersects(cube, triangle3{{-1, -1, 0}, {3, -1, 0}, {-1, 3, 0}})); // in the bottom face's plane
    CHECK_FALSE(intersects(cube, triangle3{{-1, -1, -0x1p-1074}, {3, -1, -0x1p-1074}, {-1, 3, -0x1p-1074}}));
}
TEST_CASE("mesh_triangle: contains, fixtures", "[mesh_triangle]") {
    CHECK(contains(cube, triangle3{{0.2, 0.2, 0.2}, {0.8, 0.2, 0.2}, {0.2, 0.8, 0.8}}));
    CHECK(contains(cube, triangle3{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}));             // on the top face
    CHECK(contains(cube, triangle3{{0.2, 0.2, 1}, {0.8, 0.2, 1}, {0.2, 0.8, 1}})); // inside the top face
    CHECK(contains(cube, triangle3{{0, 0.1, 0.1}, {0, 0.9, 0.1}, {0, 0.5, 0.9}})); // on a side face
    CHECK(contains(cube, triangle3{{0, 0, 0}, {1, 1, 0}, {1, 1, 1}}));             // a diagonal plane, along edges
    CHECK(contains(cube, triangle3{{0, 0, 0}, {1, 0, 0}, {1, 1, 1}}));
    CHECK_FALSE(contains(cube, triangle3{{0, 0, 1}, {0x1.0000000000001p0, 0, 1}, {0, 1, 1}}));
    CHECK_FALSE(contains(dented, triangle3{{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.5, 0.9, 0.5}})); // around the dent
    CHECK(contains(dented, triangle3{{0.1, 0.1, 0.2}, {0.9, 0.1, 0.2}, {0.5, 0.9, 0.2}}));       // below its apex
    CHECK(contains(dented, triangle3{{0.1, 0.1, 0.25}, {0.9, 0.1, 0.25}, {0.5, 0.9, 0.25}}));    // touching the apex
    CHECK_FALSE(
        contains(dented, triangle3{{0.1, 0.1, 0x1.0000000000001p-2}, {0.9, 0.1, 0x1.0000000000001p-2}, {0.5, 0.9, 0x1.0000000000001p-2}}));
    CHECK_FALSE(contains(dented, triangle3{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}));        // over the dent's opening
    CHECK_FALSE(contains(dented, triangle3{{0, 0, 1}, {1, 1, 1}, {0.5, 0.5, 0.25}})); // down the dent, vertices on the surface
    CHECK(contains(dented, triangle3{{0, 0, 0}, {1, 1, 0}, {0.5, 0.5, 0.25}}));       // under the dent, up to its apex
    CHECK(contains(dented, triangle3{{0, 1, 0}, {1, 0, 0}, {0.5, 0.5, 0.25}}));
    CHECK_FALSE(contains(dented, triangle3{{0, 1, 0}, {1, 0, 0}, {0.5, 0.5, 0x1.0000000000001p-2}}));
    CHECK(contains(cube, triangle3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, {1, 1, 1}})); // collinear: a segment
    CHECK_FALSE(contains(cube, triangle3{{0.5, 0.5, 0.5}, {0.75, 0.75, 0.75}, {1.5, 1.5, 1.5}}));
    CHECK(contains<conservative>(cube, triangle3{{0.2, 0.2, 0.2}, {0.8, 0.2, 0.2}, {0.2, 0.8, 0.8}}));
    CHECK_FALSE(contains<aggressive>(dented, triangle3{{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.5, 0.9, 0.5}}));
    CHECK_FALSE(contains(mesh3{}, triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    CHECK_FALSE(contains(cube, triangle3{{0.5, 0.5, 0.5}, {0.6, 0.5, 0.5}, {0.5, std::nan(""), 0.5}}));
}
TEST_CASE("mesh_triangle: contains on a self-intersecting mesh", "[mesh_triangle]") {
    // Two overlapping boxes as one unchecked surface: [0, 1]^3 and [0.8, 1.2] x [0.4, 0.6] x
    // [0.5, 1.5]. Their common part has even parity (outside); the second box's faces cross the
    // first one's top face z = 1.
    std::vector<point3> v(support::cube_vertices.begin(), support::cube_vertices.begin() + 8);
    for (std::size_t i = 0; i < 8; ++i) {
        const point3 p = support::cube_vertices[i];
        v.push_back({0.8 + 0.4 * p.x, 0.4 + 0.2 * p.y, 0.5 + p.z});
    }
    std::vector<std::array<std::uint32_t, 3>> t(support::cube_triangles.begin(), support::cube_triangles.end());
    for (const auto& f : support::cube_triangles) t.push_back({f[0] + 8, f[1] + 8, f[2] + 8});
    const mesh3 two{v, t};
    CHECK(contains(two, triangle3{{0.5, 0.5, 1}, {1.1, 0.45, 1}, {1.1, 0.55, 1}})); // the top face, then the second box
    CHECK(contains(two, triangle3{{0.5, 0.5, 1}, {1.1, 0.41, 1}, {0.9, 0.45, 1}}));
    // a corner x > 1, y < 0.4 outside both, cut off by the top face's edge x = 1 and the second
    // box's face y = 0.4, which cross at (1, 0.4, 1)
    CHECK_FALSE(contains(two, triangle3{{0.5, 0.5, 1}, {1.1, 0.41, 1}, {0.9, 0.3, 1}}));
    CHECK_FALSE(contains(two, triangle3{{0.9, 0.5, 0.9}, {0.95, 0.5, 0.9}, {0.9, 0.55, 0.9}})); // in both: even
    CHECK(contains(two, triangle3{{0.5, 0.5, 0.9}, {0.6, 0.5, 0.9}, {0.5, 0.55, 0.9}}));
}
TEST_CASE("mesh_triangle: contains across two cubes glued face to face, one nudged by 2^-600", "[mesh_triangle]") {
    // [0, 1]^3 and [0, 1] x [1, 2] x [0, 1] as one surface, the second's corner (0, 1, 0) raised to
    // z = 2^-600: the glued faces (both split along x = z) cover y = 1 twice, and their diagonals
    // cross the plane x = 1/2 at z = 1/2 and 1/2 + 2^-601. Seen from any vertex of a triangle in
    // that plane, those two points are closer in direction than a sum of three doubles can resolve:
    // the sweep needs its pair chords there.
    std::vector<point3> v(support::cube_vertices.begin(), support::cube_vertices.begin() + 8);
    for (std::size_t i = 0; i < 8; ++i) v.push_back(support::cube_vertices[i] + vec3{0, 1, 0});
    v[8].z = 0x1p-600;
    std::vector<std::array<std::uint32_t, 3>> t(support::cube_triangles.begin(), support::cube_triangles.end());
    for (const auto& f : support::cube_triangles) t.push_back({f[0] + 8, f[1] + 8, f[2] + 8});
    const mesh3 two{v, t};
    const triangle3 across{{0.5, 0.25, 0.25}, {0.5, 1.75, 0.25}, {0.5, 1.75, 0.875}};
    CHECK(support::triangle_in_mesh_truth(two, across));
    CHECK(contains(two, across));
    CHECK(contains(two, triangle3{across.b, across.c, across.a}));
    CHECK(contains(two, triangle3{across.c, across.a, across.b}));
    const triangle3 above{{0.5, 0.25, 0.25}, {0.5, 1.75, 0.25}, {0.5, 1.75, 1.125}}; // past the top
    CHECK_FALSE(support::triangle_in_mesh_truth(two, above));
    CHECK_FALSE(contains(two, above));
}
TEST_CASE("mesh_triangle: contains in blocks glued, overlapping or nested, against the oracle", "[mesh_triangle][oracle]") {
    (void)support::contains_in_store(
        "mesh_triangle contains, blocks glued, overlapping or nested", support::cases(4000), 43, approx_bound,
        [](support::rng& r, support::mesh_store& store) { return support::triangle_in_blocks(r, store); },
        [](const mesh3& m, const triangle3& t) { return support::triangle_in_mesh_truth(m, t); },
        [](const mesh3&, const triangle3&) { return false; });
}
TEST_CASE("mesh_triangle: contains against the oracle, random and near-degenerate", "[mesh_triangle][oracle]") {
    support::mesh_store store;
    support::contains_oracle_cases(
        "mesh_triangle", support::cases(10000), approx_bound,
        [&](support::rng& r, bool near) -> std::optional<std::pair<mesh3, triangle3>> {
            const triangle3 t = near ? support::triangle_in_mesh_near(r, store) : support::triangle_in_mesh_random(r, store);
            bool fin = support::finite_shape(t);
            for (const auto& p : store.v) fin = fin && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
            if (!fin) return std::nullopt;
            return std::pair{store.view(), t};
        },
        [](const mesh3& m, const triangle3& t) { return support::triangle_in_mesh_truth(m, t); },
        [](const mesh3& m, const triangle3& t) { return support::shape_str(m) + " " + support::shape_str(t); });
}
TEST_CASE("mesh_triangle: contains on self-crossing surfaces against the oracle", "[mesh_triangle][oracle]") {
    // support::triangle_in_crossed_meshes: the oracle's traces include every crossing of two traces
    support::rng r(support::seed() + 31);
    support::mesh_store store;
    long n = 0, yes = 0, wrong = 0, skipped = 0;
    for (long i = 0; i < support::cases(2000); ++i) {
        const triangle3 t = support::triangle_in_crossed_meshes(r, store);
        const mesh3 m = store.view();
        bool truth = false;
        try {
            truth = support::triangle_in_mesh_truth(m, t);
        } catch (const std::runtime_error&) {
            ++skipped;
            continue;
        }
        ++n, yes += truth;
        if (contains(m, t) != truth) {
            ++wrong;
            UNSCOPED_INFO(support::shape_str(m) + " " + support::shape_str(t) + " truth " + (truth ? "contained" : "not contained"));
        }
    }
    std::printf("[cases] mesh_triangle contains, self-crossing surfaces: %ld cases, %ld contained, %ld skipped, exact disagreements %ld\n",
                n, yes, skipped, wrong);
    CHECK(wrong == 0);
    CHECK(yes > n / 20);
}
TEST_CASE("mesh_triangle: oracle, random and near-degenerate", "[mesh_triangle][oracle]") {
    support::mesh_oracle<triangle3>("mesh_triangle", support::cases(20000), approx_bound);
}
TEST_CASE("mesh_triangle: rewrites of either shape and exact translations give the same answer", "[mesh_triangle]") {
    support::mesh_symmetries<triangle3>("mesh_triangle", support::cases(20000));
}

} // namespace test_query_mesh_triangle
