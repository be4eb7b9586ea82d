// aabb3 x mesh3: fixtures (inside, around, in the dent, touching the apex, one ulp above it);
// the CGAL Epeck oracle (the triangles by
// do_intersect, the inside by crossing parity with CGAL::orientation) on 20,000 random and 20,000
// near-degenerate cases (closed non-convex star meshes; the other shape through a vertex, an edge
// midpoint or a face point, along a face edge or not, or around the inside centre; then a random
// exact-or-nudged scale 2^-500..2^500 and translation); both argument orders, rotated and reversed
// triangles, rewritten partners, exact translations.
// contains(mesh, box): fixtures (the cube's own box and one ulp more, under the dent up to its
// apex and one ulp above, faces, edges and points of the cube, two cubes glued face to face with
// different diagonals and shifted, a cavity, two overlapping cubes, bad input); an oracle over
// CGAL Epeck (each plane cutting the box cut into the cells of its triangles' edge lines and the
// box's traces, a witness per cell counting the triangles over it, then one point's crossing
// parity) on 10,000 random and 10,000 near-degenerate cases (support/mesh_cases.hpp:
// box_in_mesh_near, box_in_mesh_random) and 4,000 boxes in blocks glued face to face,
// overlapping or nested (box_in_blocks); the box split in two at a double between its bounds,
// rotated and reversed triangles and exact translations give the same answer.
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

namespace test_query_aabb_mesh { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::cube;
using support::dented;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_mesh"); // stated in the catalog (modules/query/catalog.cppm)
constexpr double above1 = 0x1.0000000000001p0;

// Two unit cubes as one surface: [0, 1]^3 and the one above it moved by (dx, 0, 1), the second's
// faces split along the other diagonals when `other_diagonals`.
struct two_cubes {
    std::vector<point3> v;
    std::vector<std::array<std::uint32_t, 3>> t;
    two_cubes(double dx, double dz, bool other_diagonals) {
        v.assign(support::cube_vertices.begin(), support::cube_vertices.begin() + 8);
        for (std::size_t i = 0; i < 8; ++i) v.push_back(support::cube_vertices[i] + vec3{dx, 0, dz});
        t.assign(support::cube_triangles.begin(), support::cube_triangles.end());
        for (const auto& f : support::cube_triangles) t.push_back({f[0] + 8, f[1] + 8, f[2] + 8});
        if (other_diagonals) // each face's pair {p, q, r}, {p, r, s} becomes {p, q, s}, {q, r, s}
            for (std::size_t i = 12; i < 24; i += 2) {
                const auto a = t[i], b = t[i + 1];
                t[i] = {a[0], a[1], b[2]}, t[i + 1] = {a[1], a[2], b[2]};
            }
    }
    [[nodiscard]] mesh3 view() const { return {v, t}; }
};
// The cube [0, 3]^3 with the cube [1, 2]^3 as an inward shell: a cavity.
struct hollow_cube {
    std::vector<point3> v;
    std::vector<std::array<std::uint32_t, 3>> t;
    hollow_cube() {
        for (std::size_t i = 0; i < 8; ++i) v.push_back(point3{0, 0, 0} + (support::cube_vertices[i] - point3{0, 0, 0}) * 3.0);
        for (std::size_t i = 0; i < 8; ++i) v.push_back(support::cube_vertices[i] + vec3{1, 1, 1});
        t.assign(support::cube_triangles.begin(), support::cube_triangles.end());
        for (const auto& f : support::cube_triangles) t.push_back({f[0] + 8, f[2] + 8, f[1] + 8});
    }
    [[nodiscard]] mesh3 view() const { return {v, t}; }
};
} // namespace

TEST_CASE("aabb_mesh: fixtures", "[aabb_mesh]") {
    CHECK(intersects(aabb3{{0.2, 0.2, 0.2}, {0.3, 0.3, 0.3}}, cube));
    CHECK(intersects(cube, aabb3{{-1, -1, -1}, {2, 2, 2}}));
    CHECK_FALSE(intersects(aabb3{{0.45, 0.45, 0.5}, {0.55, 0.55, 0.9}}, dented));
    CHECK(intersects(aabb3{{0.5, 0.5, 0.25}, {0.55, 0.55, 0.9}}, dented));
    CHECK_FALSE(intersects(aabb3{{0.5, 0.5, 0x1.0000000000001p-2}, {0.5, 0.5, 0.9}}, dented));
    CHECK_FALSE(intersects(aabb3{{2, 2, 2}, {-1, -1, -1}}, cube)); // inverted: empty
}
TEST_CASE("aabb_mesh: contains, fixtures", "[aabb_mesh]") {
    CHECK(contains(cube, aabb3{{0, 0, 0}, {1, 1, 1}})); // the solid itself
    CHECK(contains(cube, aabb3{{0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}}));
    CHECK(contains(cube, aabb3{{0, 0.25, 0}, {0.5, 0.75, 1}})); // touching three faces from inside
    CHECK_FALSE(contains(cube, aabb3{{0, 0, 0}, {1, 1, above1}}));
    CHECK_FALSE(contains(cube, aabb3{{-0x1p-60, 0, 0}, {0.5, 0.5, 0.5}}));
    CHECK_FALSE(contains(cube, aabb3{{0.5, 0.5, 0.5}, {1.5, 0.75, 0.75}})); // through a face
    CHECK(contains(dented, aabb3{{0, 0, 0}, {1, 1, 0.25}}));                // under the dent, up to its apex
    CHECK_FALSE(contains(dented, aabb3{{0, 0, 0}, {1, 1, 0x1.0000000000001p-2}}));
    CHECK_FALSE(contains(dented, aabb3{{0.4, 0.4, 0.5}, {0.6, 0.6, 0.6}})); // in the dent
    CHECK_FALSE(contains(dented, aabb3{{0, 0, 0}, {1, 1, 1}}));
    // the dent's floor is z = 1/4 + 3/2 max(|x - 1/2|, |y - 1/2|)
    CHECK(contains(dented, aabb3{{0, 0, 0}, {0.25, 1, 0.625}})); // touching the floor at (1/4, 1/2, 5/8)
    CHECK_FALSE(contains(dented, aabb3{{0, 0, 0}, {0.25, 1, 0x1.4000000000001p-1}}));
    CHECK(contains(dented, aabb3{{0, 0, 0.5}, {0.125, 0.125, 0.8125}})); // a corner on the floor
    CHECK_FALSE(contains(dented, aabb3{{0, 0, 0.5}, {0.125, 0.125, 0x1.a000000000001p-1}}));
    CHECK_FALSE(contains(dented, aabb3{{0, 0, 0.5}, {0.5, 0.5, 1}}));
    // flat boxes: a face, a rectangle across the dent, an edge, a point
    CHECK(contains(cube, aabb3{{0, 0, 1}, {1, 1, 1}}));
    CHECK_FALSE(contains(dented, aabb3{{0, 0, 1}, {1, 1, 1}}));
    CHECK(contains(dented, aabb3{{0, 0, 0.25}, {1, 1, 0.25}}));
    CHECK_FALSE(contains(dented, aabb3{{0, 0, 0.3}, {1, 1, 0.3}}));
    CHECK(contains(cube, aabb3{{0, 0, 0}, {1, 0, 0}}));
    CHECK_FALSE(contains(cube, aabb3{{0, 0, 0}, {above1, 0, 0}}));
    CHECK(contains(cube, aabb3{{1, 1, 1}, {1, 1, 1}}));
    CHECK(contains(dented, aabb3{{0.5, 0.5, 0.25}, {0.5, 0.5, 0.25}}));
    CHECK_FALSE(contains(dented, aabb3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}}));
    // tiers and bad input
    CHECK(contains<conservative>(cube, aabb3{{0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}}));
    CHECK_FALSE(contains<aggressive>(dented, aabb3{{0.4, 0.4, 0.5}, {0.6, 0.6, 0.6}}));
    CHECK(contains<approximate>(cube, aabb3{{0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}}));
    CHECK(classify_contains(cube, aabb3{{0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}}) == certainty::yes);
    CHECK_FALSE(contains(cube, aabb3{{0.75, 0.75, 0.75}, {0.25, 0.25, 0.25}})); // inverted: empty
    CHECK_FALSE(contains(cube, aabb3{{0.25, 0.25, std::nan("")}, {0.75, 0.75, 0.75}}));
    CHECK_FALSE(contains(cube, aabb3{{0.25, 0.25, 0.25}, {0.75, 0.75, INFINITY}}));
    CHECK_FALSE(contains(mesh3{}, aabb3{{0, 0, 0}, {1, 1, 1}}));
    const std::array<point3, 7> seven{support::cube_vertices[0], support::cube_vertices[1], support::cube_vertices[2],
                                      support::cube_vertices[3], support::cube_vertices[4], support::cube_vertices[5],
                                      support::cube_vertices[6]};
    CHECK_FALSE(contains(mesh3{seven, support::cube_triangles}, aabb3{{0.25, 0.25, 0.25}, {0.5, 0.5, 0.5}})); // an index out of range
}
TEST_CASE("aabb_mesh: contains on glued, hollow and overlapping surfaces", "[aabb_mesh]") {
    // two cubes face to face at z = 1: the shared square is covered twice (even), so the union is
    // solid across it, whatever the diagonals
    for (const bool other : {false, true}) {
        const two_cubes stack(0, 1, other);
        CHECK(contains(stack.view(), aabb3{{0, 0, 0}, {1, 1, 2}}));
        CHECK(contains(stack.view(), aabb3{{0.2, 0.2, 0.5}, {0.8, 0.8, 1.5}}));
        CHECK(contains(stack.view(), aabb3{{0, 0, 1}, {1, 1, 1}})); // the shared square
        CHECK_FALSE(contains(stack.view(), aabb3{{0, 0, 0}, {1, 1, 0x1.0000000000001p1}}));
        CHECK_FALSE(contains(stack.view(), aabb3{{0, 0, 0}, {above1, 1, 2}}));
    }
    // the upper cube moved by half along x: the square covered twice is [0.5, 1] x [0, 1]
    const two_cubes shifted(0.5, 1, false);
    CHECK(contains(shifted.view(), aabb3{{0.5, 0, 0.5}, {1, 1, 1.5}}));
    CHECK_FALSE(contains(shifted.view(), aabb3{{0.25, 0, 0.5}, {1, 1, 1.5}}));   // x < 0.5, z > 1 is outside
    CHECK_FALSE(contains(shifted.view(), aabb3{{0.5, 0, 0.5}, {1.25, 1, 1.5}})); // x > 1, z < 1 is outside
    CHECK(contains(shifted.view(), aabb3{{0.5, 0, 1}, {1, 1, 1}}));
    CHECK(contains(shifted.view(), aabb3{{0.25, 0, 1}, {1, 1, 1}})); // on the lower cube's top face, then on both
    // overlapping cubes (the common part has even parity: outside)
    const two_cubes overlap(0.5, 0.5, false);
    CHECK_FALSE(contains(overlap.view(), aabb3{{0.6, 0.2, 0.6}, {0.9, 0.8, 0.9}}));
    CHECK(contains(overlap.view(), aabb3{{0.1, 0.2, 0.1}, {0.4, 0.8, 0.4}}));
    CHECK(contains(overlap.view(), aabb3{{0.1, 0.2, 0.1}, {0.6, 0.8, 0.4}})); // below the common part
    CHECK_FALSE(contains(overlap.view(), aabb3{{0.1, 0.2, 0.1}, {0.6, 0.8, 0.6}}));
    // a cavity [1, 2]^3 in [0, 3]^3
    const hollow_cube hollow;
    CHECK_FALSE(contains(hollow.view(), aabb3{{0, 0, 0}, {3, 3, 3}}));
    CHECK_FALSE(contains(hollow.view(), aabb3{{0.5, 0.5, 0.5}, {2.5, 2.5, 2.5}})); // the cavity wholly inside the box
    CHECK(contains(hollow.view(), aabb3{{0, 0, 0}, {3, 3, 1}}));                   // up to the cavity's floor
    CHECK_FALSE(contains(hollow.view(), aabb3{{0, 0, 0}, {3, 3, 1.5}}));
    CHECK(contains(hollow.view(), aabb3{{0, 0, 0}, {1, 3, 3}}));
    CHECK_FALSE(contains(hollow.view(), aabb3{{1.25, 1.25, 1.25}, {1.75, 1.75, 1.75}})); // in the cavity
    CHECK_FALSE(contains(hollow.view(), aabb3{{1, 1, 1}, {2, 2, 2}}));
    CHECK(contains(hollow.view(), aabb3{{1, 1, 1}, {2, 2, 1}})); // the cavity's floor: on the surface
}
TEST_CASE("aabb_mesh: contains against the oracle, random and near-degenerate", "[aabb_mesh][oracle]") {
    support::mesh_store store;
    support::contains_oracle_cases(
        "aabb_mesh", support::cases(10000), approx_bound,
        [&](support::rng& r, bool near) -> std::optional<std::pair<mesh3, aabb3>> {
            const aabb3 b = near ? support::box_in_mesh_near(r, store) : support::box_in_mesh_random(r, store);
            bool fin = support::finite_shape(b);
            for (const auto& p : store.v) fin = fin && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
            if (!fin) return std::nullopt;
            return std::pair{store.view(), b};
        },
        [](const mesh3& m, const aabb3& b) { return support::box_in_mesh_truth(m, b); },
        [](const mesh3& m, const aabb3& b) { return support::shape_str(m) + " " + support::shape_str(b); });
}
TEST_CASE("aabb_mesh: contains in blocks glued, overlapping or nested, against the oracle", "[aabb_mesh][oracle]") {
    // contained although triangles reach into the box: coplanar ones whose coverage there is even
    const long glued = support::contains_in_store(
        "aabb_mesh contains, blocks glued, overlapping or nested", support::cases(4000), 37, approx_bound,
        [](support::rng& r, support::mesh_store& store) { return support::box_in_blocks(r, store); },
        [](const mesh3& m, const aabb3& b) { return support::box_in_mesh_truth(m, b); },
        [](const mesh3& m, const aabb3& b) {
            for (std::size_t j = 0; j < m.triangles.size(); ++j) {
                arith::exact_kernel k;
                if (detail::meets_interior(k, b, m.triangle(j)) && detail::solid_mesh::normal_axis(k, m.triangle(j)) >= 0) return true;
            }
            return false;
        });
    std::printf("[cases] aabb_mesh contains, blocks: %ld contained with triangles inside the box whose coverage is even\n", glued);
    CHECK(glued > 0);
}
TEST_CASE("aabb_mesh: contains, the box split in two, rewritten meshes and exact translations give the same answer", "[aabb_mesh]") {
    support::rng r(support::seed() + 41);
    support::mesh_store store, rewritten;
    long checked = 0, bad = 0, yes = 0;
    auto same = [&](bool x, bool e, const mesh3& m, const aabb3& b, const char* how) {
        ++checked;
        if (x != e && ++bad <= 5)
            std::printf("  aabb_mesh contains, %s differs: %s %s\n", how, support::shape_str(m).c_str(), support::shape_str(b).c_str());
    };
    for (long i = 0; i < support::cases(6000); ++i) {
        const int kind = static_cast<int>(i % 3);
        const aabb3 b = kind == 0 ? support::box_in_mesh_near(r, store)
                                  : (kind == 1 ? support::box_in_mesh_random(r, store) : support::box_in_blocks(r, store));
        const mesh3 m = store.view();
        const bool e = contains(m, b);
        yes += e;
        // split at a double strictly between the bounds of an axis that has one
        for (int axis = 0; axis < 3; ++axis) {
            const double lo = axis == 0 ? b.min.x : (axis == 1 ? b.min.y : b.min.z),
                         hi = axis == 0 ? b.max.x : (axis == 1 ? b.max.y : b.max.z);
            const double mid = lo + (hi - lo) * (r.uniform(0.125, 0.875));
            if (!(lo < mid && mid < hi)) continue;
            aabb3 b1 = b, b2 = b;
            (axis == 0 ? b1.max.x : (axis == 1 ? b1.max.y : b1.max.z)) = mid;
            (axis == 0 ? b2.min.x : (axis == 1 ? b2.min.y : b2.min.z)) = mid;
            same(contains(m, b1) && contains(m, b2), e, m, b, "split");
            break;
        }
        for (int how = 0; how < 2; ++how) { // every triangle rotated; every triangle reversed
            rewritten = store;
            for (auto& t : rewritten.t)
                t = how == 0 ? std::array<std::uint32_t, 3>{t[1], t[2], t[0]} : std::array<std::uint32_t, 3>{t[0], t[2], t[1]};
            same(contains(rewritten.view(), b), e, m, b, how == 0 ? "rotated" : "reversed");
        }
        const vec3 v{std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)), std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)),
                     std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20))};
        rewritten = store;
        bool exact_move = true;
        for (auto& p : rewritten.v) {
            const auto q = support::shifted(p, v);
            if (!q) exact_move = false;
            else p = *q;
        }
        const auto bt = support::translated(b, v);
        if (exact_move && bt) same(contains(rewritten.view(), *bt), e, m, b, "translated");
    }
    std::printf("[cases] aabb_mesh contains, split boxes, rewrites and exact translations: %ld checked (%ld contained), %ld differ\n",
                checked, yes, bad);
    CHECK(bad == 0);
    CHECK(yes > 0);
}
TEST_CASE("aabb_mesh: oracle, random and near-degenerate", "[aabb_mesh][oracle]") {
    support::mesh_oracle<aabb3>("aabb_mesh", support::cases(20000), approx_bound);
}
TEST_CASE("aabb_mesh: rewrites of either shape and exact translations give the same answer", "[aabb_mesh]") {
    support::mesh_symmetries<aabb3>("aabb_mesh", support::cases(20000));
}

} // namespace test_query_aabb_mesh
