// Cases for the mesh pairs: closed, non-convex, embedded test meshes and the oracle's view of
// them. Include after flat_cases.hpp.
//
// A star mesh: the surface grid of the cube [-n, n]^3 (n x n squares per face, each split along a
// random diagonal, outward oriented), every grid point d pushed along its ray from the centre to
// centre + r d with r in {1/2, 1, 3/2} (dyadic, so exact): non-convex, and embedded, since each
// triangle projects from the centre onto the same patch of the sphere as its cube triangle.
// Near-degenerate: the other shape placed at a point X of the surface (a vertex, an edge's
// midpoint or a point inside a triangle) as in flat_cases.hpp (through X, along a triangle's edge
// in its plane, or along a random direction), or at the centre (inside); then one random
// exact-or-nudged scale and translation for both. Random: a mesh around a random centre in
// [-1, 1]^3 of size about 1/2 and a random shape of flat_cases.hpp, at a random scale. A
// half-space set (convex_polyhedron3, frustum3, kdop<K>) near X: the supporting planes or the
// k-DOP of a small dyadic cloud around X (X one of its points), or the integer frustum shrunk 16
// times with its own boundary point at X; at the centre it lies inside the mesh, where only a
// point of it decides. Random: the sets of polyhedron_cases.hpp and kdop_cases.hpp.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>
#include "obb_cases.hpp"
#include "polyhedron_cases.hpp"

namespace support {

struct mesh_store {
    std::vector<incidence::point3> v;
    std::vector<std::array<std::uint32_t, 3>> t;
    [[nodiscard]] incidence::mesh3 view() const { return {v, t}; }
};
inline oracle::mesh_data mesh_data_of(const incidence::mesh3& m) {
    oracle::mesh_data d;
    for (const auto& p : m.vertices) d.v.push_back({p.x, p.y, p.z});
    for (const auto& t : m.triangles) d.t.push_back({t[0], t[1], t[2]});
    return d;
}

// The star mesh of grid size n around `centre` (in units of `unit`), in small coordinates.
inline void star_mesh(rng& r, int n, incidence::point3 centre, double unit, mesh_store& m) {
    m.v.clear();
    m.t.clear();
    std::map<std::array<int, 3>, std::uint32_t> index;
    auto vertex = [&](std::array<int, 3> g) {
        const auto [it, added] = index.try_emplace(g, static_cast<std::uint32_t>(m.v.size()));
        if (added) {
            static constexpr double radii[] = {0.5, 1.0, 1.5};
            const double k = radii[r.integer(0, 2)] * unit;
            m.v.push_back({centre.x + k * g[0], centre.y + k * g[1], centre.z + k * g[2]});
        }
        return it->second;
    };
    for (int a = 0; a < 3; ++a)
        for (int s = -1; s <= 1; s += 2) {
            const int u = (a + 1) % 3, w = (a + 2) % 3;
            for (int i = -n; i < n; ++i)
                for (int j = -n; j < n; ++j) {
                    auto at = [&](int di, int dj) {
                        std::array<int, 3> g{};
                        g[static_cast<unsigned>(a)] = s * n, g[static_cast<unsigned>(u)] = i + di, g[static_cast<unsigned>(w)] = j + dj;
                        return vertex(g);
                    };
                    const std::uint32_t p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
                    std::array<std::uint32_t, 3> t1{p00, p10, p11}, t2{p00, p11, p01};
                    if (r.coin()) t1 = {p00, p10, p01}, t2 = {p10, p11, p01};
                    if (s < 0) std::swap(t1[1], t1[2]), std::swap(t2[1], t2[2]); // outward
                    m.t.push_back(t1);
                    m.t.push_back(t2);
                }
        }
}
inline void realise_mesh(mesh_store& m, transform& tr) {
    for (auto& p : m.v) p = moved(p, tr);
}
// A point of the surface: a vertex, an edge's midpoint, or a point inside a triangle; `along`
// gets an edge direction of that triangle.
inline incidence::point3 surface_point(rng& r, const mesh_store& m, incidence::vec3& along) {
    const auto& t = m.t[static_cast<std::size_t>(r.integer(0, static_cast<int>(m.t.size()) - 1))];
    const incidence::point3 a = m.v[t[0]], b = m.v[t[1]], c = m.v[t[2]];
    along = r.coin() ? b - a : c - b;
    switch (r.integer(0, 2)) {
    case 0: return a;
    case 1: return a + (b - a) * 0.5;
    default: return a + (b - a) * 0.25 + (c - a) * 0.25;
    }
}

template <class B>
struct is_set_for_mesh : std::bool_constant<is_halfspace_shape<B>::value || is_kdop<B>::value> {};
// A k-DOP that could not be built (bounds out of range): an empty one.
template <class B>
B kdop_or_empty(const std::optional<B>& b) {
    if (b) return *b;
    B e{};
    e.min[0] = 1, e.max[0] = 0;
    return e;
}
template <class B>
B halfspace_set_at(rng& r, incidence::point3 X, transform& tr) {
    using namespace incidence;
    std::vector<point3> pts{X};
    for (int i = r.integer(3, 7); i > 0; --i)
        pts.push_back(X + vec3{r.integer(-4, 4) * 0.0625, r.integer(-4, 4) * 0.0625, r.integer(-4, 4) * 0.0625});
    if constexpr (std::is_same_v<B, frustum3>) {
        halfspace_set h = frustum_near_set(r);
        for (auto& p : h.planes) p.x = X + (p.x - h.X) * 0.0625;
        return realise_frustum(h, tr);
    } else if constexpr (std::is_same_v<B, convex_polyhedron3>) {
        halfspace_set h;
        for (int i = r.integer(4, 12); i > 0; --i) {
            const vec3 n = small_normal(r);
            h.planes.push_back({n, extreme(pts, n)});
        }
        return realise_polyhedron(h, tr);
    } else {
        for (auto& p : pts) p = moved(p, tr);
        return kdop_or_empty<B>(kdop_around<B::slabs * 2>(pts));
    }
}

// Every case: the mesh in `store` (and a second one in `other` for mesh against mesh), the
// other shape returned (for a mesh, its view of `other`).
template <class B>
B mesh_near(rng& r, mesh_store& store, mesh_store& other) {
    using namespace incidence;
    const point3 centre = small_point(r);
    star_mesh(r, r.integer(1, 2), centre, 1.0, store);
    vec3 along{};
    const bool at_centre = r.integer(0, 4) == 0;
    const point3 X = at_centre ? centre : surface_point(r, store, along);
    const vec3 d = at_centre || r.coin() ? small_dir(r) : along;
    transform tr = random_transform(r, true, true);
    if constexpr (std::is_same_v<B, mesh3>) {
        star_mesh(r, 1, point3{0, 0, 0}, 1.0, other);
        vec3 unused{};
        const point3 Y = surface_point(r, other, unused);
        for (auto& p : other.v) p = p + (X - Y); // the other mesh's surface point Y at X (exact: small numbers)
        realise_mesh(store, tr);
        realise_mesh(other, tr);
        return other.view();
    } else if constexpr (std::is_same_v<B, obb3>) {
        obb3 o = near_obb(r);
        const point3 q = boundary_point(r, o);
        o.center = o.center + (X - q);
        realise_mesh(store, tr);
        return moved(tr, o);
    } else if constexpr (is_set_for_mesh<B>::value) {
        const B b = halfspace_set_at<B>(r, X, tr);
        realise_mesh(store, tr);
        return b;
    } else {
        const auto b = place<B>(r, X, d, r.coin());
        realise_mesh(store, tr);
        return realise(b, tr);
    }
}
template <class B>
B mesh_random(rng& r, mesh_store& store, mesh_store& other) {
    using namespace incidence;
    const point3 centre{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
    star_mesh(r, r.integer(1, 2), centre, 0.25, store);
    transform tr = random_transform(r, false, true);
    realise_mesh(store, tr);
    if constexpr (std::is_same_v<B, mesh3>) {
        star_mesh(r, 1, point3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}, 0.25, other);
        realise_mesh(other, tr);
        return other.view();
    } else if constexpr (std::is_same_v<B, obb3>) {
        return random_obb(r, tr);
    } else if constexpr (std::is_same_v<B, convex_polyhedron3>) {
        return realise_polyhedron(polyhedron_random_set(r), tr);
    } else if constexpr (std::is_same_v<B, frustum3>) {
        const auto f = camera_frustum(r, tr);
        return f ? *f : frustum3{};
    } else if constexpr (is_kdop<B>::value) {
        std::vector<point3> pts = random_cloud(r);
        for (auto& p : pts) p = moved(p, tr);
        return kdop_or_empty<B>(kdop_around<B::slabs * 2>(pts));
    } else {
        const auto b = random_shape<B>(r, false, 0.0);
        return realise(b, tr);
    }
}

// A star mesh of grid size 1 or 2 about a small centre, and a point X of its surface with a step
// `along` an edge of X's triangle (surface_point): what the near-degenerate generators start from.
struct star_near {
    incidence::point3 centre, X;
    incidence::vec3 along;
};
inline star_near star_mesh_near(rng& r, mesh_store& store) {
    star_near n{small_point(r), {}, {}};
    star_mesh(r, r.integer(1, 2), n.centre, 1.0, store);
    n.X = surface_point(r, store, n.along);
    return n;
}
// A star mesh (support/mesh_cases.hpp, star-shaped about its centre) and a segment from the
// centre to a surface point X (inside, touching), from X along a triangle's edge in its plane,
// between two surface points, or from halfway to X to a little short of or past X; the far end
// nudged by ulps or not; then one exact-or-nudged scale 2^-500..2^500 and translation.
inline incidence::segment3 segment_in_mesh_near(rng& r, mesh_store& store) {
    using namespace incidence;
    const auto [centre, X, along] = star_mesh_near(r, store);
    vec3 unused{};
    segment3 s{};
    switch (r.integer(0, 3)) {
    case 0: s = {centre, X}; break;
    case 1: s = {X, X + along * (r.integer(-4, 4) * 0.25)}; break;
    case 2: s = {X, surface_point(r, store, unused)}; break;
    default: s = {centre + (X - centre) * 0.5, X + (X - centre) * (r.integer(-2, 2) * 0.125)}; break;
    }
    if (r.coin()) s.b = {nudge(s.b.x, r.integer(-2, 2)), nudge(s.b.y, r.integer(-2, 2)), nudge(s.b.z, r.integer(-2, 2))};
    if (r.coin()) std::swap(s.a, s.b);
    transform tr = random_transform(r, r.integer(0, 3) == 0, true);
    realise_mesh(store, tr);
    return realise(s, tr);
}
// A random star mesh in store (mesh_random), and a function drawing points of its vertices' box.
inline auto random_mesh_and_box_points(rng& r, mesh_store& store) {
    using namespace incidence;
    mesh_store other;
    (void)mesh_random<point3>(r, store, other);
    const aabb3 box = incidence::detail::solid_mesh::bounds(store.view());
    return [&r, box] {
        return point3{box.min.x + (box.max.x - box.min.x) * r.uniform(0, 1), box.min.y + (box.max.y - box.min.y) * r.uniform(0, 1),
                      box.min.z + (box.max.z - box.min.z) * r.uniform(0, 1)};
    };
}
// A random star mesh and a segment between two points of its vertices' box, or an eighth of one.
inline incidence::segment3 segment_in_mesh_random(rng& r, mesh_store& store) {
    using namespace incidence;
    const auto at = random_mesh_and_box_points(r, store);
    const point3 a = at(), b = at();
    if (r.coin()) return {a, b};
    return {a, a + (b - a) * 0.125}; // a short one: more of them inside
}
// The oracle's answer to contains(m, s) (tests/oracle/cgal_mesh.cpp; std::runtime_error when it
// finds no clean parity segment).
inline bool segment_in_mesh_truth(const incidence::mesh3& m, const incidence::segment3& s) {
    return oracle::mesh_contains_segment(mesh_data_of(m), {s.a.x, s.a.y, s.a.z}, {s.b.x, s.b.y, s.b.z});
}
// A star mesh and a triangle touching its surface: the centre and two surface points; three
// surface points; a surface point, a step along a triangle's edge and the centre; or one of the
// mesh's own triangles (on the surface), with a vertex pulled towards the centre or pushed out
// by a quarter, or its third vertex moved to the centre; vertices nudged by ulps or not, the
// order rotated or reversed; then one exact-or-nudged scale 2^-500..2^500 and translation.
inline incidence::triangle3 triangle_in_mesh_near(rng& r, mesh_store& store) {
    using namespace incidence;
    const auto [centre, X, along] = star_mesh_near(r, store);
    vec3 unused{};
    triangle3 t{};
    switch (r.integer(0, 3)) {
    case 0: t = {centre, X, surface_point(r, store, unused)}; break;
    case 1: t = {X, surface_point(r, store, unused), surface_point(r, store, unused)}; break;
    case 2: t = {X, X + along * (r.integer(-4, 4) * 0.25), centre}; break;
    default: {
        const auto& f = store.t[static_cast<std::size_t>(r.integer(0, static_cast<int>(store.t.size()) - 1))];
        t = {store.v[f[0]], store.v[f[1]], store.v[f[2]]};
        switch (r.integer(0, 3)) {
        case 0: break;
        case 1: t.c = t.c + (centre - t.c) * 0.25; break;
        case 2: t.c = t.c + (t.c - centre) * 0.25; break;
        default: t.c = centre; break;
        }
    }
    }
    if (r.coin()) t.c = {nudge(t.c.x, r.integer(-2, 2)), nudge(t.c.y, r.integer(-2, 2)), nudge(t.c.z, r.integer(-2, 2))};
    for (int i = r.integer(0, 2); i > 0; --i) t = {t.b, t.c, t.a};
    if (r.coin()) std::swap(t.b, t.c);
    transform tr = random_transform(r, r.integer(0, 3) == 0, true);
    realise_mesh(store, tr);
    return realise(t, tr);
}
// A random star mesh and a triangle of three points of its vertices' box, or an eighth of one.
inline incidence::triangle3 triangle_in_mesh_random(rng& r, mesh_store& store) {
    using namespace incidence;
    const auto at = random_mesh_and_box_points(r, store);
    const point3 a = at(), b = at(), c = at();
    if (r.coin()) return {a, b, c};
    return {a, a + (b - a) * 0.125, a + (c - a) * 0.125}; // a small one: more of them inside
}
// The triangles of `more` added to `into` as one surface (its vertices after into's).
inline void append_mesh(mesh_store& into, const mesh_store& more) {
    const auto base = static_cast<std::uint32_t>(into.v.size());
    into.v.insert(into.v.end(), more.v.begin(), more.v.end());
    for (const auto& f : more.t) into.t.push_back({f[0] + base, f[1] + base, f[2] + base});
}
// Two star meshes, the second's centre a few quarters off the first's, kept as one unchecked
// surface that crosses itself (their common part has even parity), and a triangle on or near
// either's surface (one of its triangles, possibly with a vertex moved, or surface points of both):
// lines of the other surface then cross the covering triangle's edges.
inline incidence::triangle3 triangle_in_crossed_meshes(rng& r, mesh_store& store) {
    using namespace incidence;
    const point3 centre = small_point(r);
    const point3 other_centre = centre + vec3{r.integer(-3, 3) * 0.25, r.integer(-3, 3) * 0.25, r.integer(-3, 3) * 0.25};
    mesh_store a, b;
    star_mesh(r, 1, centre, 1.0, a);
    star_mesh(r, 1, other_centre, 1.0, b);
    vec3 unused{};
    triangle3 t{};
    if (r.coin()) {
        const mesh_store& from = r.coin() ? a : b;
        const auto& f = from.t[static_cast<std::size_t>(r.integer(0, static_cast<int>(from.t.size()) - 1))];
        t = {from.v[f[0]], from.v[f[1]], from.v[f[2]]};
        if (r.coin()) t.c = r.coin() ? t.c + (centre - t.c) * 0.25 : surface_point(r, r.coin() ? a : b, unused);
    } else {
        t = {surface_point(r, a, unused), surface_point(r, b, unused), r.coin() ? centre : surface_point(r, r.coin() ? a : b, unused)};
    }
    store = a;
    append_mesh(store, b);
    for (int i = r.integer(0, 2); i > 0; --i) t = {t.b, t.c, t.a};
    transform tr = random_transform(r, false, true);
    realise_mesh(store, tr);
    return realise(t, tr);
}
// A box against a star mesh: spanned by the centre and a surface point X; with a corner at X and
// the other a few eighths away; around a mesh triangle, stretched along an axis in which it is
// flat to the centre's coordinate (a face on the surface, from inside or outside); around the
// centre; or from halfway to X to a little short of or past X. Sometimes made flat along an axis
// (a rectangle, through contains(mesh, triangle)), a corner nudged by ulps; then one
// exact-or-nudged scale 2^-500..2^500 and translation.
inline incidence::aabb3 box_in_mesh_near(rng& r, mesh_store& store) {
    using namespace incidence;
    const auto [centre, X, along] = star_mesh_near(r, store);
    auto eighths = [&r] { return vec3{r.integer(-4, 4) * 0.125, r.integer(-4, 4) * 0.125, r.integer(-4, 4) * 0.125}; };
    aabb3 b{};
    switch (r.integer(0, 4)) {
    case 0: b = ordered(aabb3{centre, X}); break;
    case 1: b = ordered(aabb3{X, X + eighths()}); break;
    case 2: {
        const auto& f = store.t[static_cast<std::size_t>(r.integer(0, static_cast<int>(store.t.size()) - 1))];
        const point3 v[3] = {store.v[f[0]], store.v[f[1]], store.v[f[2]]};
        b = incidence::detail::solid_mesh::bounds(v, 3);
        const int axis = r.integer(0, 2);
        double* lo = axis == 0 ? &b.min.x : (axis == 1 ? &b.min.y : &b.min.z);
        double* hi = axis == 0 ? &b.max.x : (axis == 1 ? &b.max.y : &b.max.z);
        const double c = axis == 0 ? centre.x : (axis == 1 ? centre.y : centre.z);
        if (*lo == *hi) {
            if (r.integer(0, 3) == 0) *(c < *lo ? hi : lo) = *lo + (*lo - c); // outward
            else *(c < *lo ? lo : hi) = c;                                    // inward
        }
        break;
    }
    case 3: {
        const vec3 h{r.integer(1, 4) * 0.125, r.integer(1, 4) * 0.125, r.integer(1, 4) * 0.125};
        b = aabb3{centre - h, centre + h};
        break;
    }
    default: b = ordered(aabb3{centre + (X - centre) * 0.5, X + (X - centre) * (r.integer(-2, 2) * 0.125)}); break;
    }
    if (r.integer(0, 7) == 0) {
        switch (r.integer(0, 2)) {
        case 0: b.max.x = b.min.x; break;
        case 1: b.max.y = b.min.y; break;
        default: b.max.z = b.min.z; break;
        }
    }
    if (r.coin()) b.max = {nudge(b.max.x, r.integer(-2, 2)), nudge(b.max.y, r.integer(-2, 2)), nudge(b.max.z, r.integer(-2, 2))};
    transform tr = random_transform(r, r.integer(0, 3) == 0, true);
    realise_mesh(store, tr);
    return realise(ordered(b), tr);
}
// A random star mesh and the box of two points of its vertices' box, or an eighth of it.
inline incidence::aabb3 box_in_mesh_random(rng& r, mesh_store& store) {
    using namespace incidence;
    const auto at = random_mesh_and_box_points(r, store);
    const point3 a = at(), b = at();
    if (r.coin()) return ordered(aabb3{a, b});
    return ordered(aabb3{a, a + (b - a) * 0.125}); // a small one: more of them inside
}
// The closed surface of the block lo + [0, size] (integer units of `unit`), each face a grid of
// unit squares split along random diagonals: many coplanar triangles side by side; outward, or
// inward (`inward`: a nested shell, whose inside has even parity, a cavity).
inline void block_mesh(rng& r, std::array<int, 3> lo, std::array<int, 3> size, bool inward, mesh_store& m) {
    std::map<std::array<int, 3>, std::uint32_t> index;
    auto vertex = [&](std::array<int, 3> g) {
        const auto [it, added] = index.try_emplace(g, static_cast<std::uint32_t>(m.v.size()));
        if (added) m.v.push_back({double(lo[0] + g[0]), double(lo[1] + g[1]), double(lo[2] + g[2])});
        return it->second;
    };
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
            const int u = (a + 1) % 3, w = (a + 2) % 3;
            for (int i = 0; i < size[static_cast<unsigned>(u)]; ++i)
                for (int j = 0; j < size[static_cast<unsigned>(w)]; ++j) {
                    auto at = [&](int di, int dj) {
                        std::array<int, 3> g{};
                        g[static_cast<unsigned>(a)] = side * size[static_cast<unsigned>(a)], g[static_cast<unsigned>(u)] = i + di,
                        g[static_cast<unsigned>(w)] = j + dj;
                        return vertex(g);
                    };
                    const std::uint32_t p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
                    std::array<std::uint32_t, 3> t1{p00, p10, p11}, t2{p00, p11, p01};
                    if (r.coin()) t1 = {p00, p10, p01}, t2 = {p10, p11, p01};
                    if ((side == 0) != inward) std::swap(t1[1], t1[2]), std::swap(t2[1], t2[2]);
                    m.t.push_back(t1);
                    m.t.push_back(t2);
                }
        }
}
// Blocks of integer size 1 to 3 kept as one unchecked surface in `store`: a second block beside
// the first (sharing a whole face or part of a face plane, so coplanar triangles of both cover one
// area twice, which has even parity: the union is solid across it), overlapping it (their common
// part has even parity), or nested inside it as an inward shell (a cavity). The first block is
// [0, s1]; the return value is its extent s1.
inline std::array<int, 3> glued_blocks(rng& r, mesh_store& store) {
    store.v.clear();
    store.t.clear();
    const int how = r.integer(0, 3); // 0, 1 beside; 2 overlapping; 3 nested
    const std::array<int, 3> s1 =
        how == 3 ? std::array<int, 3>{3, 3, 3} : std::array<int, 3>{r.integer(1, 3), r.integer(1, 3), r.integer(1, 3)};
    block_mesh(r, {0, 0, 0}, s1, false, store);
    std::array<int, 3> lo2{}, s2{r.integer(1, 3), r.integer(1, 3), r.integer(1, 3)};
    for (unsigned k = 0; k < 3; ++k) lo2[k] = r.integer(-1, s1[k] - 1);
    const auto axis = static_cast<unsigned>(r.integer(0, 2));
    if (how == 0) // continuing the first block along an axis: the union is a block
        for (unsigned k = 0; k < 3; ++k)
            if (k != axis) lo2[k] = 0, s2[k] = s1[k];
    if (how <= 1) lo2[axis] = s1[axis];            // face to face
    if (how == 3) lo2 = {1, 1, 1}, s2 = {1, 1, 1}; // the middle unit cube
    block_mesh(r, lo2, s2, how == 3, store);
    return s1;
}
// A point of half-integer coordinates within the box b.
inline incidence::point3 half_point(rng& r, const incidence::aabb3& b) {
    auto half = [&r](double lo, double hi) { return lo + r.integer(0, static_cast<int>(2 * (hi - lo))) * 0.5; };
    return {half(b.min.x, b.max.x), half(b.min.y, b.max.y), half(b.min.z, b.max.z)};
}
// glued_blocks and a box of half-integer corners within their bounds, often the first block's own
// box or the union's; sometimes flat along an axis; then a scale 2^-500..2^500 and translation,
// exact or nudged.
inline incidence::aabb3 box_in_blocks(rng& r, mesh_store& store) {
    using namespace incidence;
    const std::array<int, 3> s1 = glued_blocks(r, store);
    aabb3 b{};
    const aabb3 all = incidence::detail::solid_mesh::bounds(store.view());
    switch (r.integer(0, 3)) {
    case 0: b = aabb3{{0, 0, 0}, {double(s1[0]), double(s1[1]), double(s1[2])}}; break;
    case 1: b = all; break;
    default: b = ordered(aabb3{half_point(r, all), half_point(r, all)}); break;
    }
    if (r.integer(0, 7) == 0) b.max.x = b.min.x;
    transform tr = random_transform(r, r.integer(0, 3) == 0, true);
    realise_mesh(store, tr);
    return realise(b, tr);
}
// glued_blocks and a triangle of half-integer vertices within their bounds, often in a coordinate
// plane (across the glued faces, or on them); then a scale and translation, exact or nudged.
inline incidence::triangle3 triangle_in_blocks(rng& r, mesh_store& store) {
    using namespace incidence;
    (void)glued_blocks(r, store);
    const aabb3 all = incidence::detail::solid_mesh::bounds(store.view());
    triangle3 t{half_point(r, all), half_point(r, all), half_point(r, all)};
    if (r.coin()) { // in a plane x = const, y = const or z = const
        const int axis = r.integer(0, 2);
        const double c = axis == 0 ? t.a.x : (axis == 1 ? t.a.y : t.a.z);
        for (point3* p : {&t.b, &t.c}) (axis == 0 ? p->x : (axis == 1 ? p->y : p->z)) = c;
    }
    transform tr = random_transform(r, r.integer(0, 3) == 0, true);
    realise_mesh(store, tr);
    return realise(t, tr);
}
// The oracle's answer to contains(m, b) (tests/oracle/cgal_mesh_box.cpp; std::runtime_error when it
// finds no clean parity segment).
inline bool box_in_mesh_truth(const incidence::mesh3& m, const incidence::aabb3& b) {
    return oracle::mesh_contains_box(mesh_data_of(m), {b.min.x, b.min.y, b.min.z}, {b.max.x, b.max.y, b.max.z});
}
// The oracle's answer to contains(m, t) (tests/oracle/cgal_mesh.cpp; std::runtime_error when it
// finds no clean parity segment).
inline bool triangle_in_mesh_truth(const incidence::mesh3& m, const incidence::triangle3& t) {
    return oracle::mesh_contains_triangle(mesh_data_of(m), {t.a.x, t.a.y, t.a.z}, {t.b.x, t.b.y, t.b.z}, {t.c.x, t.c.y, t.c.z});
}
// The oracle's answer (tests/oracle/cgal_mesh.cpp).
template <class B>
bool mesh_truth(const incidence::mesh3& m, const B& b) {
    using namespace incidence;
    const auto md = mesh_data_of(m);
    if constexpr (std::is_same_v<B, mesh3>) return oracle::mesh_mesh_intersect(md, mesh_data_of(b));
    else if constexpr (std::is_same_v<B, obb3>) return oracle::mesh_intersect(md, lp(b), {b.center.x, b.center.y, b.center.z});
    else if constexpr (is_set_for_mesh<B>::value) return oracle::mesh_intersect(md, lp(b)); // an exact point of b from the LP
    else return oracle::mesh_intersect(md, to_flat(b));
}

} // namespace support
