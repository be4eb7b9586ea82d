// Cases and checks for the 3D polygon pairs (tests/query/<pair>.cpp with polygon3): planar star
// polygons with holes in space, the oracle's triangulation of them, and the checks every such
// pair runs (polygon3_checks.hpp). Include after flat_cases.hpp and mesh_cases.hpp.
//
// A polygon: a star polygon of polygon_cases.hpp (non-convex, half of them with a hole) in the
// plane o + u e1 + v e2 of a small dyadic o and small integer e1, e2 (a third of the time two unit
// axes), so every vertex is exact and the vertices are exactly coplanar; then a random scale
// 2^-500..2^500 (exact, no translation: a rounded translation would bend the plane).
// Near-degenerate: the other shape placed at a point X of the polygon (a vertex, an edge's
// midpoint or quarter point, the centre: in the hole or inside, or between the rings) along the
// edge there, along a direction in the plane, or along any direction, as in flat_cases.hpp; a
// plane or a triangle in the polygon's own plane a third of the time; a second polygon with a ring
// point at X, in the same plane half of the time; a k-DOP, frustum or convex polyhedron of a small
// cloud at X (mesh_cases.hpp's halfspace_set_at); a star mesh with a surface point at X. The other
// shape takes the same scale, nudged by a few ulps half of the time.
// Random: a star polygon of size about 1/2 around a random centre (coordinates on a 2^-20 grid) in
// a random small integer plane, and a random shape of flat_cases.hpp (a small set or mesh about a
// random point; a point half of the time on the polygon's plane, at a random grid point of it), at
// one random scale.
// The oracle (tests/oracle/cgal_polygon.cpp): the polygon's CGAL constrained triangulation, each
// triangle against the other shape by the flat, LP or mesh oracle.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>
#include "polygon_cases.hpp"

namespace support {

struct polygon3_store {
    std::vector<incidence::point3> v;
    std::vector<std::uint32_t> ends;
    incidence::polygon3 g{};
    [[nodiscard]] incidence::polygon3 view() const { return {v, ends, g.plane_vertices, g.axis}; }
    // make() on the vertices: false when it refuses them
    bool finish() {
        const auto m = incidence::polygon3::make(v, ends);
        if (!m.has_value()) return false;
        g = m.value();
        return true;
    }
};
inline oracle::polygon3_data polygon3_data_of(const incidence::polygon3& g) {
    oracle::polygon3_data d;
    for (const auto& p : g.vertices) d.v.push_back({p.x, p.y, p.z});
    if (g.ring_ends.empty()) d.ring_ends.push_back(static_cast<unsigned>(g.vertices.size()));
    for (auto e : g.ring_ends) d.ring_ends.push_back(e);
    d.axis = g.axis;
    return d;
}
// The plane o + u e1 + v e2.
struct plane_frame {
    incidence::point3 o;
    incidence::vec3 e1, e2;
    [[nodiscard]] incidence::point3 at(incidence::point2 p) const { return o + e1 * p.x + e2 * p.y; }
    [[nodiscard]] incidence::vec3 along(incidence::vec2 d) const { return e1 * d.x + e2 * d.y; }
    [[nodiscard]] incidence::vec3 normal() const { return cross(e1, e2); }
};
inline plane_frame small_frame(rng& r, bool small_origin = true) {
    using incidence::vec3;
    plane_frame f{small_origin ? small_point(r) : incidence::point3{0, 0, 0}, {}, {}};
    if (r.integer(0, 2) == 0) {
        const vec3 unit[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        const int a = r.integer(0, 2), b = (a + r.integer(1, 2)) % 3;
        f.e1 = unit[a] * (r.coin() ? 1.0 : -1.0), f.e2 = unit[b];
        return f;
    }
    for (;;) {
        f.e1 = {double(r.integer(-2, 2)), double(r.integer(-2, 2)), double(r.integer(-2, 2))};
        f.e2 = {double(r.integer(-2, 2)), double(r.integer(-2, 2)), double(r.integer(-2, 2))};
        const vec3 n = f.normal();
        if (!(n.x == 0 && n.y == 0 && n.z == 0)) return f;
    }
}
inline void embed(const polygon_store& flat, const plane_frame& f, polygon3_store& out) {
    out.v.clear();
    for (const auto& p : flat.v) out.v.push_back(f.at(p));
    out.ends = flat.ends;
}
// A point of a ring of the 3D polygon (a vertex, an edge's midpoint or quarter point), with the
// direction of that edge.
inline incidence::point3 ring_point3(rng& r, const polygon3_store& g, incidence::vec3& along) {
    polygon_store flat; // the same rings, for ring_point's choice
    for (const auto& p : g.v) flat.v.push_back({p.x, p.y});
    flat.ends = g.ends;
    const incidence::polygon2 view = flat.view();
    const std::size_t ring = static_cast<std::size_t>(r.integer(0, static_cast<int>(view.rings()) - 1));
    const std::size_t b = view.ring_begin(ring), e = view.ring_end(ring);
    const std::size_t j = b + static_cast<std::size_t>(r.integer(0, static_cast<int>(e - b) - 1));
    const incidence::point3 a = g.v[j], c = g.v[incidence::polygon2::next(j, b, e)];
    along = c - a;
    switch (r.integer(0, 2)) {
    case 0: return a;
    case 1: return a + (c - a) * 0.5;
    default: return a + (c - a) * 0.25;
    }
}
inline void scale_polygon(polygon3_store& g, const transform& tr) {
    for (auto& p : g.v) p = {std::ldexp(p.x, tr.k), std::ldexp(p.y, tr.k), std::ldexp(p.z, tr.k)};
}

// Every case: the polygon in `store`; the other shape returned (a second polygon or a mesh are
// views of `other` or `mesh`). std::nullopt when a shape could not be made (it overflowed).
template <class B>
std::optional<B> polygon3_near(rng& r, polygon3_store& store, polygon3_store& other, mesh_store& mesh) {
    using namespace incidence;
    const point2 centre{small(r), small(r)};
    const int n = r.integer(1, 3);
    polygon_store flat;
    star_polygon(r, n, centre, 1.0, flat);
    vec2 along2{};
    const int where = r.integer(0, 7);
    const point2 X2 = where == 0 ? centre : (where == 1 ? centre + vec2{0.375 * n, 0.0} : ring_point(r, flat, along2));
    const plane_frame f = small_frame(r);
    embed(flat, f, store);
    const point3 X = f.at(X2);
    const int how = r.integer(0, 2);
    const vec3 d = how == 0 ? f.along(where < 2 ? small_dir2(r) : along2) : (how == 1 ? f.along(small_dir2(r)) : small_dir(r));
    transform tr = random_transform(r, false, true);
    tr.t[0] = tr.t[1] = tr.t[2] = 0;
    transform partner = tr;
    partner.nudged = r.coin();
    scale_polygon(store, tr);
    if (!store.finish()) return std::nullopt;
    if constexpr (std::is_same_v<B, polygon3>) {
        polygon_store flat2;
        star_polygon(r, 1, point2{0, 0}, 1.0, flat2);
        embed(flat2, r.coin() ? plane_frame{{0, 0, 0}, f.e1, f.e2} : small_frame(r, false), other);
        vec3 unused{};
        const point3 Y = ring_point3(r, other, unused);
        for (auto& p : other.v) p = p + (X - Y); // its ring point Y at X (exact: small numbers)
        scale_polygon(other, tr);
        if (!other.finish()) return std::nullopt;
        return other.g;
    } else if constexpr (std::is_same_v<B, mesh3>) {
        mesh_store m;
        star_mesh(r, r.integer(1, 2), point3{0, 0, 0}, 1.0, m);
        vec3 unused{};
        const point3 S = r.integer(0, 4) == 0 ? point3{0.25, 0, 0} : surface_point(r, m, unused);
        for (auto& p : m.v) p = p + (X - S);
        realise_mesh(m, partner);
        mesh = m;
        return mesh.view();
    } else if constexpr (is_set_for_mesh<B>::value) {
        return halfspace_set_at<B>(r, X, partner);
    } else {
        auto b = place<B>(r, X, d, r.coin());
        if constexpr (std::is_same_v<B, plane3>) // the polygon's own plane through X, either orientation
            if (r.integer(0, 2) == 0) b = {r.coin() ? f.normal() : -f.normal(), X};
        if constexpr (std::is_same_v<B, triangle3>) // a triangle in the polygon's plane
            if (r.integer(0, 2) == 0) b = {X, X + f.along(small_dir2(r)), X + f.along(small_dir2(r))};
        return realise(b, partner);
    }
}
template <class B>
std::optional<B> polygon3_random(rng& r, polygon3_store& store, polygon3_store& other, mesh_store& mesh) {
    using namespace incidence;
    auto grid = [&] { return std::ldexp(double(r.integer(-(1 << 20), 1 << 20)), -20); };
    polygon_store flat;
    star_polygon(r, r.integer(1, 3), point2{grid(), grid()}, 0.125, flat);
    const plane_frame f = small_frame(r, false);
    embed(flat, f, store);
    transform tr = random_transform(r, false, true);
    tr.t[0] = tr.t[1] = tr.t[2] = 0;
    scale_polygon(store, tr);
    if (!store.finish()) return std::nullopt;
    if constexpr (std::is_same_v<B, polygon3>) {
        polygon_store flat2;
        star_polygon(r, r.integer(1, 2), point2{grid(), grid()}, 0.125, flat2);
        embed(flat2, small_frame(r, false), other);
        scale_polygon(other, tr);
        if (!other.finish()) return std::nullopt;
        return other.g;
    } else if constexpr (std::is_same_v<B, mesh3>) {
        mesh_store m;
        star_mesh(r, 1, point3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}, 0.125, m);
        realise_mesh(m, tr);
        mesh = m;
        return mesh.view();
    } else if constexpr (is_set_for_mesh<B>::value) {
        return halfspace_set_at<B>(r, point3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}, tr);
    } else if constexpr (std::is_same_v<B, point3>) { // half of them in the polygon's plane (a random grid point of it)
        if (r.coin()) {
            const point3 p = f.at(point2{grid(), grid()});
            return point3{std::ldexp(p.x, tr.k), std::ldexp(p.y, tr.k), std::ldexp(p.z, tr.k)};
        }
        return realise(random_shape<B>(r, false, 0.0), tr);
    } else {
        return realise(random_shape<B>(r, false, 0.0), tr);
    }
}

// For contains(polygon3, segment3 | triangle3): points_in_star's polygon (polygon_cases.hpp) in
// a small plane (small_frame), and its points in that plane (exact); then one exact scale
// 2^-500..2^500, the points nudged by ulps a quarter of the time (off the plane, most of them).
// Random: a star polygon of polygon3_random's kind and points of its plane (a random point of the
// flat polygon's box, or an eighth of the way to another), at one scale.
// std::nullopt when the polygon could not be made or a point overflowed.
inline std::optional<std::array<incidence::point3, 3>> points_in_polygon3(rng& r, polygon3_store& store, bool near) {
    using namespace incidence;
    polygon_store flat;
    std::array<point2, 3> p2{};
    plane_frame f{};
    if (near) {
        p2 = points_in_star(r, flat);
        f = small_frame(r);
    } else {
        auto grid = [&] { return std::ldexp(double(r.integer(-(1 << 20), 1 << 20)), -20); };
        star_polygon(r, r.integer(1, 3), point2{grid(), grid()}, 0.125, flat);
        f = small_frame(r, false);
        const auto box = detail::polygon2d::bounds(flat.view());
        auto at = [&] {
            const double u = box.min.x + (box.max.x - box.min.x) * r.uniform(0, 1),
                         v = box.min.y + (box.max.y - box.min.y) * r.uniform(0, 1);
            return point2{std::ldexp(std::round(std::ldexp(u, 24)), -24),
                          std::ldexp(std::round(std::ldexp(v, 24)), -24)}; // exact in the plane
        };
        p2 = {at(), at(), at()};
        if (r.coin()) p2[1] = p2[0] + 0.125 * (p2[1] - p2[0]), p2[2] = p2[0] + 0.125 * (p2[2] - p2[0]);
    }
    embed(flat, f, store);
    transform tr = random_transform(r, false, true);
    tr.t[0] = tr.t[1] = tr.t[2] = 0;
    scale_polygon(store, tr);
    if (!store.finish()) return std::nullopt;
    std::array<point3, 3> out{};
    for (int i = 0; i < 3; ++i) {
        const point3 q = f.at(p2[static_cast<std::size_t>(i)]);
        out[static_cast<std::size_t>(i)] = {std::ldexp(q.x, tr.k), std::ldexp(q.y, tr.k), std::ldexp(q.z, tr.k)};
        if (r.integer(0, 3) == 0) {
            point3& o = out[static_cast<std::size_t>(i)];
            o = {nudge(o.x, r.integer(-2, 2)), nudge(o.y, r.integer(-2, 2)), nudge(o.z, r.integer(-2, 2))};
        }
    }
    for (const auto& q : out)
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) return std::nullopt;
    return out;
}
inline bool segment_in_polygon3_truth(const incidence::polygon3& g, const incidence::segment3& s) {
    return oracle::polygon3_contains_segment(polygon3_data_of(g), {s.a.x, s.a.y, s.a.z}, {s.b.x, s.b.y, s.b.z});
}
inline bool triangle_in_polygon3_truth(const incidence::polygon3& g, const incidence::triangle3& t) {
    return oracle::polygon3_contains_triangle(polygon3_data_of(g), {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z});
}

// The oracle: some triangle of the polygon's CGAL triangulation meets b.
template <class B>
bool polygon3_truth(const incidence::polygon3& g, const B& b) {
    using namespace incidence;
    const auto tris = oracle::polygon3_triangles(polygon3_data_of(g));
    auto tri = [](const std::array<double, 9>& t) { return triangle3{{t[0], t[1], t[2]}, {t[3], t[4], t[5]}, {t[6], t[7], t[8]}}; };
    std::vector<std::array<double, 9>> other;
    std::optional<oracle::mesh_data> md;
    if constexpr (std::is_same_v<B, obb3> || is_set_for_mesh<B>::value) { // the triangles as one soup, through the LP
        oracle::mesh_data soup;
        for (const auto& t : tris) {
            const auto n = static_cast<std::uint32_t>(soup.v.size());
            soup.v.push_back({t[0], t[1], t[2]}), soup.v.push_back({t[3], t[4], t[5]}), soup.v.push_back({t[6], t[7], t[8]});
            soup.t.push_back({n, n + 1, n + 2});
        }
        return oracle::any_triangle_meets(soup, lp(b));
    }
    if constexpr (std::is_same_v<B, polygon3>) other = oracle::polygon3_triangles(polygon3_data_of(b));
    if constexpr (std::is_same_v<B, mesh3>) md = mesh_data_of(b);
    for (const auto& t : tris) {
        const triangle3 T = tri(t);
        if constexpr (std::is_same_v<B, polygon3>) {
            for (const auto& u : other)
                if (oracle::flat_intersect(to_flat(T), to_flat(tri(u)))) return true;
        } else if constexpr (std::is_same_v<B, mesh3>) {
            if (oracle::mesh_intersect(*md, to_flat(T))) return true;
        } else if constexpr (!std::is_same_v<B, obb3> && !is_set_for_mesh<B>::value) {
            if (oracle::flat_intersect(to_flat(T), to_flat(b))) return true;
        }
    }
    return false;
}

template <class B>
bool finite_partner(const B& b) {
    if constexpr (std::is_same_v<B, incidence::polygon3> || std::is_same_v<B, incidence::mesh3>) return true;
    else return finite_shape(b);
}
} // namespace support
