// Cases and checks for a ball or a capsule against a polygon3 or a solid mesh3 (polygon_sphere,
// capsule_polygon, mesh_sphere, capsule_mesh; the checks are in ball_view_checks.hpp, and the
// benchmarks use the cases too). Include after testing.hpp, the CGAL oracle header, lp_shapes.hpp,
// flat_shapes.hpp, mesh_cases.hpp, polygon3_cases.hpp and capsule_cases.hpp.
//
// Near-degenerate, a polygon: polygon3_near's star polygon with holes in a small integer plane and
// a point X of it (a vertex, an edge's midpoint or quarter point, the centre: in the hole or inside,
// or between the rings); rows through X along the plane's two normals and across the edge there
// in the plane (both ways: a star polygon is not convex), and a ball touching them at X
// (ball_touching of ball_halfspace_cases.hpp: centre X + t w, radius t |w|, exact where |w| is an
// integer, else rounded; kept, nudged, moved, halved, doubled or zero; one time in eight centred
// at X or X - t w). Then one random exact scale 2^-500..2^500 for the polygon (no translation: a
// rounded one would bend its plane) and the same scale for the ball, nudged by ulps half of the
// time. A mesh: a star mesh of mesh_cases.hpp (closed, not convex) and a point X of its surface
// (a vertex, an edge's midpoint, a face point), rows along the face's two normals and across its
// edge, a ball touching them at X; then one random exact-or-nudged scale and translation for both.
// A capsule grows from the ball to c + v (capsule_touching: v . w >= 0, zero one time in six; v in
// the polygon's plane or the face's plane one time in three: parallel to it).
// Random: a star polygon of polygon3_random's kind, or a small star mesh about a random point of
// [-1, 1]^3; a ball about the polygon's first vertex (within 1/2) or a random point of [-1, 1]^3,
// radius up to 1/2; a capsule from there along a vector in [-1/2, 1/2]^3; one random scale.
// The oracle is ball_view_truth.hpp's.
#pragma once
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include "ball_view_truth.hpp"

namespace support {

// The stores a case's polygon or mesh views.
struct view_store {
    polygon3_store polygon;
    mesh_store mesh;
};

inline bool finite_mesh(const mesh_store& m) {
    for (const auto& p : m.v)
        if (!incidence::is_finite(p)) return false;
    return true;
}
template <class Round>
bool finite_round(const Round& x) {
    if constexpr (std::is_same_v<Round, incidence::sphere3>) return is_finite(x.center) && std::isfinite(x.radius);
    else return is_finite(x.a) && is_finite(x.b) && std::isfinite(x.radius);
}

// Rows through X along n, -n, m and -m.
inline proto_rows rows_across(incidence::point3 X, incidence::vec3 n, incidence::vec3 m) {
    proto_rows rows;
    rows.spots = {X};
    for (const incidence::vec3 u : {n, n * -1.0, m, m * -1.0}) add_row(rows, u, X);
    return rows;
}
// A ball touching the rows (ball_touching), or a capsule grown from one (capsule_touching) whose
// second end lies along `flat` (a vector of the touched plane: parallel to it) one time in three.
template <class Round>
Round round_touching(rng& r, const proto_rows& rows, incidence::vec3 flat) {
    if constexpr (std::is_same_v<Round, incidence::sphere3>) {
        return ball_touching(r, rows);
    } else {
        incidence::capsule3 c = capsule_touching(r, rows);
        if (r.integer(0, 2) == 0) c.b = c.a + flat * (r.integer(1, 4) * 0.25);
        return c;
    }
}

// A random ball about c (radius up to 1/2) or capsule from c along a vector of [-1/2, 1/2]^3
// (radius up to `reach`).
template <class Round>
Round random_round(rng& r, incidence::point3 c, double reach) {
    using namespace incidence;
    if constexpr (std::is_same_v<Round, sphere3>) return {c, r.uniform(0, 0.5)};
    else return {c, c + vec3{r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5)}, r.uniform(0, reach)};
}
// The polygon scaled by one random power of two (no translation: a rounded one would bend its
// plane) and the ball or capsule with it, nudged by ulps when asked; std::nullopt when the polygon
// is not made or a number overflowed.
template <class Round>
std::optional<Round> with_polygon(rng& r, view_store& s, const Round& round, bool nudged) {
    transform tr = random_transform(r, false, true);
    tr.t[0] = tr.t[1] = tr.t[2] = 0;
    scale_polygon(s.polygon, tr);
    if (!s.polygon.finish()) return std::nullopt;
    tr.nudged = nudged;
    const Round out = realise(round, tr);
    if (!finite_round(out)) return std::nullopt;
    return out;
}
// The mesh and the ball or capsule under one random scale and translation, nudged when asked.
template <class Round>
std::optional<Round> with_mesh(rng& r, view_store& s, const Round& round, bool nudged) {
    transform tr = random_transform(r, nudged, true);
    realise_mesh(s.mesh, tr);
    const Round out = realise(round, tr);
    if (!finite_round(out) || !finite_mesh(s.mesh)) return std::nullopt;
    return out;
}

// A ball or a capsule near a polygon (the polygon in s.polygon); std::nullopt when a shape could not
// be made or overflowed.
template <class Round>
std::optional<Round> round_near_polygon(rng& r, view_store& s) {
    using namespace incidence;
    const point2 centre{small(r), small(r)};
    const int n = r.integer(1, 3);
    polygon_store flat;
    star_polygon(r, n, centre, 1.0, flat);
    vec2 along2{1, 0};
    const int where = r.integer(0, 7);
    const point2 X2 = where == 0 ? centre : (where == 1 ? centre + vec2{0.375 * n, 0.0} : ring_point(r, flat, along2));
    const plane_frame f = small_frame(r);
    embed(flat, f, s.polygon);
    const point3 X = f.at(X2);
    const vec3 N = f.normal(), edge = f.along(along2);
    const Round round = round_touching<Round>(r, rows_across(X, N, cross(N, edge)), r.coin() ? edge : f.along(small_dir2(r)));
    return with_polygon(r, s, round, r.coin());
}
template <class Round>
std::optional<Round> round_random_polygon(rng& r, view_store& s) {
    using namespace incidence;
    auto grid = [&] { return std::ldexp(double(r.integer(-(1 << 20), 1 << 20)), -20); };
    polygon_store flat;
    star_polygon(r, r.integer(1, 3), point2{grid(), grid()}, 0.125, flat);
    embed(flat, small_frame(r, false), s.polygon);
    const point3 c = s.polygon.v[0] + vec3{r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5)};
    return with_polygon(r, s, random_round<Round>(r, c, 0.5), false);
}

// A ball or a capsule near a star mesh (the mesh in s.mesh).
template <class Round>
std::optional<Round> round_near_mesh(rng& r, view_store& s) {
    using namespace incidence;
    star_mesh(r, r.integer(1, 2), point3{0, 0, 0}, 1.0, s.mesh);
    const auto& t = s.mesh.t[static_cast<std::size_t>(r.integer(0, static_cast<int>(s.mesh.t.size()) - 1))];
    const point3 a = s.mesh.v[t[0]], b = s.mesh.v[t[1]], c = s.mesh.v[t[2]];
    point3 X = a;
    switch (r.integer(0, 2)) {
    case 0: break;
    case 1: X = a + (b - a) * 0.5; break;
    default: X = a + (b - a) * 0.25 + (c - a) * 0.25; break;
    }
    const vec3 N = cross(b - a, c - a);
    const Round round = round_touching<Round>(r, rows_across(X, N, cross(N, b - a)), r.coin() ? b - a : c - a);
    return with_mesh(r, s, round, r.coin());
}
template <class Round>
std::optional<Round> round_random_mesh(rng& r, view_store& s) {
    using namespace incidence;
    star_mesh(r, 1, point3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}, 0.125, s.mesh);
    const point3 c{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
    return with_mesh(r, s, random_round<Round>(r, c, 0.25), false);
}

} // namespace support
