// squared_distance and signed_distance of a point and a tetrahedron or a solid mesh: fixtures (the
// unit corner tetrahedron: inside, beyond a face, an edge and a vertex, on it; a flat tetrahedron;
// the box [0, 1] x [0, 2] x [0, 3] as a mesh, inside and outside; a malformed mesh; NaN), then
// every tier against the exact values (testkit/oracle/cgal_distance.cpp: the exact QP and the
// faces in rationals for a tetrahedron; CGAL's point-triangle distances over Epeck and the
// crossing parity for a mesh) on random and near-degenerate cases: tetrahedra with points at a face,
// an edge or a vertex along the normal cone, on the boundary or inside
// (testkit/ball_halfspace_cases.hpp), and star meshes with points at a vertex, an edge or a face
// point, near them, or at the inside centre (testkit/mesh_cases.hpp), at scales 2^-500..2^500.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/ball_halfspace_checks.hpp"
#include "testkit/mesh_checks.hpp"
#include "testkit/distance_checks.hpp"

namespace test_query_distance_triangles_point {

using namespace incidence;

TEST_CASE("triangles_point: fixtures", "[distance][triangles_point]") {
    const tetrahedron3 t{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}};
    CHECK(signed_distance(point3{1, 1, -3}, t) == 3.0);  // beyond the face z = 0
    CHECK(signed_distance(point3{-3, -4, 1}, t) == 5.0); // beyond the edge on the z axis
    CHECK(signed_distance(point3{5, -2, -2}, t) == 3.0); // beyond the vertex (4, 0, 0)
    CHECK(signed_distance(point3{1, 1, 0.5}, t) == -0.5);
    CHECK(signed_distance(t, point3{2, 0, 2}) == 0.0);
    CHECK(squared_distance(t, point3{5, -2, -2}) == 9.0);
    CHECK(squared_distance(t, point3{1, 1, 0.5}) == 0.0);
    CHECK(signed_distance(point3{1, 1, 3}, t) == static_cast<double>(1.0L / std::sqrt(3.0L))); // beyond the slanted face x + y + z = 4
    const tetrahedron3 flat{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}};
    CHECK(signed_distance(point3{1, 1, 0}, flat) == 0.0);
    CHECK(signed_distance(point3{1, 1, 2}, flat) == 2.0);
    CHECK(std::isnan(signed_distance(point3{1, 1, INFINITY}, t)));

    const std::array<point3, 8> v{point3{0, 0, 0}, {1, 0, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 3}, {1, 0, 3}, {1, 2, 3}, {0, 2, 3}};
    const std::array<std::array<std::uint32_t, 3>, 12> f{{{0, 2, 1},
                                                          {0, 3, 2},
                                                          {4, 5, 6},
                                                          {4, 6, 7},
                                                          {0, 1, 5},
                                                          {0, 5, 4},
                                                          {2, 3, 7},
                                                          {2, 7, 6},
                                                          {1, 2, 6},
                                                          {1, 6, 5},
                                                          {0, 4, 7},
                                                          {0, 7, 3}}};
    const mesh3 m = mesh3::make(v, f).value();
    CHECK(signed_distance(m, point3{0.5, 0.25, 1}) == -0.25);
    CHECK(signed_distance(m, point3{3, 4, 4}) == 3.0);
    CHECK(squared_distance(point3{3, 4, 4}, m) == 9.0);
    CHECK(signed_distance(m, point3{1, 1, 1}) == 0.0);
    const std::array<std::array<std::uint32_t, 3>, 1> out_of_range{{{0, 1, 9}}};
    CHECK(std::isnan(signed_distance(mesh3{v, out_of_range}, point3{0, 0, 0})));
}

TEST_CASE("triangles_point: every tier against the exact distances", "[distance][triangles_point][oracle]") {
    support::distance_oracle<tetrahedron3>(
        "point_tetrahedron distances", support::cases(5000), 231,
        [](support::rng& r, bool near) -> std::optional<std::pair<tetrahedron3, point3>> {
            const auto c = near ? support::ball_near<tetrahedron3>(r) : support::ball_random<tetrahedron3>(r);
            if (!c) return std::nullopt;
            return std::pair{c->first, c->second.center};
        },
        [](const tetrahedron3& t) {
            return oracle::distance_solid{oracle::distance_solid::tetrahedron,
                                          {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z, t.d.x, t.d.y, t.d.z},
                                          {}};
        },
        [](const tetrahedron3& t) { return support::shape_str(t); });

    // meshes: the store outlives each case's view
    support::rng r(support::seed() + 232);
    support::distance_tally tally{"mesh_point distances"};
    for (long i = 0; i < 2 * support::cases(1000); ++i) {
        support::mesh_store store;
        point3 p[2];
        if (i % 2 == 1) {
            const segment3 s = support::segment_in_mesh_near(r, store);
            p[0] = s.a, p[1] = s.b;
        } else {
            const auto at = support::random_mesh_and_box_points(r, store);
            p[0] = at(), p[1] = at();
        }
        const mesh3 m = store.view();
        const oracle::mesh_data data = support::mesh_data_of(m);
        oracle::distance_solid solid{oracle::distance_solid::mesh, {}, {}};
        solid.mesh_ptr = &data;
        for (const point3& x : p)
            if (is_finite(x) && detail::solid_mesh::well_formed(m)) support::check_distance_case(tally, m, x, solid, support::shape_str(m));
    }
    tally.report();
}

} // namespace test_query_distance_triangles_point
