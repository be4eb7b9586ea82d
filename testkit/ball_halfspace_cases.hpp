// Cases for a ball against a half-space set (convex_polyhedron_sphere, frustum_sphere, kdop_sphere),
// against an oriented box (obb_sphere: its six face rows, read as a box) and against a flat shape or
// a tetrahedron (segment_, line_, plane_sphere, sphere_triangle, sphere_tetrahedron: flat_rows).
// Include after testing.hpp and the CGAL oracle header.
//
// Near-degenerate: the set in small dyadics (polyhedron_near_set and frustum_near_set of
// polyhedron_cases.hpp; for a k-DOP, the k-DOP of a cloud of 4 to 8 small dyadic points), a point X
// of it (a spot: a cloud point, a corner, a face centre or an edge midpoint), the rows tight at X,
// and a direction w in their normal cone (a combination of up to three of their normals with
// weights 1 to 4, one of integer length where there is one), so the set's point nearest
// c = X + t w is X and the distance is t |w|. The radius is
// that distance when |w|^2 is a perfect square (exact tangency, at a face, an edge or a vertex),
// else the distance rounded; then kept, nudged by 1 or 2 ulps, moved by a relative 2^-40..2^-10
// either way, halved or doubled. One time in eight the centre is X itself or X - t w (inside,
// tangent from within when one row is tight). Then one random exact-or-nudged scale 2^-500..2^500
// and translation for both shapes.
// An oriented box: near_obb's (small dyadic centre and extents, zero extents too; signed
// permutation, near-rotation or small-integer skew frames), its six face rows (outward normals
// a_k x a_l, exact) and its 27 spots (corners, edge midpoints, face centres, centre).
// Random: a set of polyhedron_random_set, a camera frustum or the k-DOP of a random cloud, and a
// ball centred within 1.5 of the set's middle with a radius up to 1, at one random scale; a box of
// random_obb with a ball of random_point and a radius up to 3/4.
// The checks are in ball_halfspace_checks.hpp.
#pragma once
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>
#include "lp_shapes.hpp"
#include "flat_cases.hpp"
#include "polyhedron_cases.hpp"

namespace support {

inline std::string shape_str(const incidence::sphere3& s) {
    return "sphere (" + hex(s.center.x) + "," + hex(s.center.y) + "," + hex(s.center.z) + ") " + hex(s.radius);
}

// The rows of a set in small dyadics: a normal and a point on each plane.
struct proto_rows {
    std::vector<plane_proto> rows;
    std::vector<incidence::point3> spots;
    std::vector<incidence::point3> cloud; // a k-DOP's points
};

// An oriented box's face rows and spots (small dyadics: exact).
inline proto_rows box_rows(const incidence::obb3& b) {
    using namespace incidence;
    proto_rows out;
    const auto& a = b.axes;
    const double det = dot(a[0], cross(a[1], a[2]));
    for (unsigned j = 0; j < 3; ++j) {
        const vec3 n = cross(a[(j + 1) % 3], a[(j + 2) % 3]) * (det < 0 ? -1.0 : 1.0);
        for (const double s : {1.0, -1.0}) out.rows.push_back({n * s, b.center + a[j] * (s * b.half_extents[j])});
    }
    for (int code = 0; code < 27; ++code) {
        const int s[3] = {code % 3 - 1, code / 3 % 3 - 1, code / 9 - 1};
        point3 x = b.center;
        for (unsigned j = 0; j < 3; ++j) x = x + a[j] * (s[j] * b.half_extents[j]);
        out.spots.push_back(x);
    }
    return out;
}

template <class P>
proto_rows near_rows(rng& r) {
    using namespace incidence;
    proto_rows out;
    if constexpr (is_kdop<P>::value) {
        const point3 c = small_point(r);
        for (int i = r.integer(4, 8); i > 0; --i)
            out.cloud.push_back({c.x + r.integer(-8, 8) * 0.25, c.y + r.integer(-8, 8) * 0.25, c.z + r.integer(-8, 8) * 0.25});
        for (const auto d : P::directions()) {
            const vec3 n{double(d.x), double(d.y), double(d.z)};
            out.rows.push_back({n, extreme(out.cloud, n)});
            out.rows.push_back({-n, extreme(out.cloud, -n)});
        }
        out.spots = out.cloud;
    } else {
        const halfspace_set h = std::is_same_v<P, frustum3> ? frustum_near_set(r) : polyhedron_near_set(r);
        out.rows = h.planes;
        out.spots = h.spots;
    }
    return out;
}

// The set of the rows, moved by tr (a k-DOP: the k-DOP of its moved cloud).
template <class P>
std::optional<P> realise_rows(const proto_rows& p, transform& tr) {
    using namespace incidence;
    if constexpr (is_kdop<P>::value) {
        std::vector<point3> pts = p.cloud;
        for (auto& x : pts) x = moved(x, tr);
        return kdop_around<P::slabs * 2>(pts);
    } else {
        halfspace_set h;
        h.planes = p.rows;
        const P a = realise_as<P>(h, tr);
        if (!finite_shape(a)) return std::nullopt;
        return a;
    }
}

// A ball at a spot of the rows, in their small coordinates (before the transform).
// (*dir: the direction w from X to the centre, for a capsule that grows away from it.)
inline incidence::sphere3 ball_touching(rng& r, const proto_rows& p, incidence::vec3* dir = nullptr) {
    using namespace incidence;
    const point3 X = p.spots[static_cast<std::size_t>(r.integer(0, static_cast<int>(p.spots.size()) - 1))];
    std::vector<vec3> tight; // the rows tight at X (small dyadics: exact), some of them
    for (const auto& row : p.rows)
        if (dot(row.n, X - row.x) == 0 && r.integer(0, 2) != 0) tight.push_back(row.n);
    if (tight.size() > 3) tight.resize(3);
    // their combination with weights 1..4, one whose length is an integer if there is one (exact tangency)
    vec3 w{0, 0, 0};
    const int start = r.integer(0, 63);
    for (int m = 0; m < 64; ++m) {
        const int code = (start + m) % 64;
        vec3 u{0, 0, 0};
        for (std::size_t j = 0; j < tight.size(); ++j) u = u + tight[j] * double(1 + (code >> (2 * j)) % 4);
        if (m == 0) w = u;
        const double len = std::sqrt(dot(u, u));
        if (len == std::floor(len)) {
            w = u;
            break;
        }
    }
    if (dir) *dir = w;
    const double t = std::ldexp(double(r.integer(1, 8)), -2);
    double radius = t * std::sqrt(dot(w, w)); // exact when |w|^2 is a square
    point3 c = X + w * t;
    const int inside = r.integer(0, 7);
    if (inside == 0) c = X;
    else if (inside == 1) c = X - w * t;
    switch (r.integer(0, 6)) {
    case 0:
    case 1: break;
    case 2: radius = nudge(radius, r.coin() ? r.integer(1, 2) : -r.integer(1, 2)); break;
    case 3: radius *= 1 + std::ldexp(r.coin() ? 1.0 : -1.0, -r.integer(10, 40)); break;
    case 4: radius *= 0.5; break;
    case 5: radius *= 2; break;
    default: radius = 0; break;
    }
    return {c, radius};
}

// A flat shape or a tetrahedron in small dyadics as rows whose normal cone at each spot is the
// shape's: a segment or a line the two perpendicular pairs of rows through it (and a row beyond
// each end), a plane its two sides, a triangle its plane's two sides and its three edges' outward
// rows in the plane, a tetrahedron its four outward faces. Spots: vertices, edge points, face
// points.
template <class S>
struct flat_shape_rows {
    typename proto_of<S>::type shape;
    proto_rows rows;
};
inline void add_row(proto_rows& p, incidence::vec3 n, incidence::point3 x) { p.rows.push_back({n, x}); }
inline void add_across(proto_rows& p, incidence::vec3 d, incidence::point3 x) {
    using namespace incidence;
    vec3 u = cross(d, vec3{1, 0, 0});
    if (u.x == 0 && u.y == 0 && u.z == 0) u = cross(d, vec3{0, 1, 0});
    const vec3 w = cross(d, u);
    for (const vec3 n : {u, u * -1.0, w, w * -1.0}) add_row(p, n, x);
}
inline incidence::point3 mix(incidence::point3 a, incidence::point3 b, double t) { return a + (b - a) * t; }
template <class S>
flat_shape_rows<S> flat_rows(rng& r) {
    using namespace incidence;
    flat_shape_rows<S> f;
    proto_rows& p = f.rows;
    if constexpr (std::is_same_v<S, segment3>) {
        const point3 a = small_point(r);
        const point3 b = a + small_dir(r);
        f.shape = segment3{a, b};
        add_across(p, b - a, a);
        add_row(p, a - b, a);
        add_row(p, b - a, b);
        p.spots = {a, b, mix(a, b, 0.5), mix(a, b, 0.25)};
    } else if constexpr (std::is_same_v<S, line3>) {
        const point3 o = small_point(r);
        const vec3 d = small_dir(r);
        f.shape = line3{o, d};
        add_across(p, d, o);
        p.spots = {o, o + d, o - d * 2.0};
    } else if constexpr (std::is_same_v<S, plane3>) {
        const vec3 n = small_dir(r);
        const point3 x = small_point(r);
        f.shape = plane_proto{n, x};
        add_row(p, n, x);
        add_row(p, n * -1.0, x);
        p.spots = {x};
    } else if constexpr (std::is_same_v<S, triangle3>) {
        for (;;) {
            const point3 a = small_point(r), b = a + small_dir(r), c = a + small_dir(r);
            const vec3 n = cross(b - a, c - a);
            if (n.x == 0 && n.y == 0 && n.z == 0) continue;
            f.shape = triangle3{a, b, c};
            add_row(p, n, a);
            add_row(p, n * -1.0, a);
            const point3 v[3] = {a, b, c};
            for (int i = 0; i < 3; ++i) {
                add_row(p, cross(v[(i + 1) % 3] - v[i], n), v[i]);
                p.spots.push_back(v[i]);
                p.spots.push_back(mix(v[i], v[(i + 1) % 3], 0.5));
            }
            p.spots.push_back(mix(mix(a, b, 0.5), c, 0.5));
            break;
        }
    } else { // a tetrahedron
        for (;;) {
            const point3 a = small_point(r);
            const point3 v[4] = {a, a + small_dir(r), a + small_dir(r), a + small_dir(r)};
            if (dot(cross(v[1] - v[0], v[2] - v[0]), v[3] - v[0]) == 0) continue;
            f.shape = tetrahedron3{v[0], v[1], v[2], v[3]};
            for (int i = 0; i < 4; ++i) {
                const point3 x = v[(i + 1) % 4], y = v[(i + 2) % 4], z = v[(i + 3) % 4];
                const vec3 m = cross(y - x, z - x);
                add_row(p, dot(m, v[i] - x) > 0 ? m * -1.0 : m, x);
                p.spots.push_back(v[i]);
                p.spots.push_back(mix(v[i], v[(i + 1) % 4], 0.5));
                p.spots.push_back(mix(mix(x, y, 0.5), z, 0.5));
            }
            break;
        }
    }
    return f;
}
template <class S>
inline constexpr bool flat_ball_shape =
    std::is_same_v<S, incidence::segment3> || std::is_same_v<S, incidence::line3> || std::is_same_v<S, incidence::plane3> ||
    std::is_same_v<S, incidence::triangle3> || std::is_same_v<S, incidence::tetrahedron3>;

template <class P>
std::optional<std::pair<P, incidence::sphere3>> ball_near(rng& r) {
    using namespace incidence;
    if constexpr (flat_ball_shape<P>) {
        const auto f = flat_rows<P>(r);
        const sphere3 b = ball_touching(r, f.rows);
        transform tr = random_transform(r, true, true);
        const P a = realise(f.shape, tr);
        const sphere3 t{moved(b.center, tr), tr.scale_only(b.radius)};
        if (!finite_shape(a) || !incidence::is_finite(t.center) || !std::isfinite(t.radius)) return std::nullopt;
        return std::pair{a, t};
    } else if constexpr (std::is_same_v<P, obb3>) {
        const obb3 b = near_obb(r);
        const sphere3 s = ball_touching(r, box_rows(b));
        const transform tr = random_transform(r, true, true);
        const obb3 m = moved(tr, b);
        const sphere3 t{moved(tr, s.center), tr.scale_only(s.radius)};
        if (!finite_shape(m) || !incidence::is_finite(t.center) || !std::isfinite(t.radius)) return std::nullopt;
        return std::pair{m, t};
    } else {
        const proto_rows p = near_rows<P>(r);
        const sphere3 b = ball_touching(r, p);
        transform tr = random_transform(r, true, true);
        const auto a = realise_rows<P>(p, tr);
        if (!a) return std::nullopt;
        const sphere3 s{moved(b.center, tr), tr.scale_only(b.radius)};
        if (!incidence::is_finite(s.center) || !std::isfinite(s.radius)) return std::nullopt;
        return std::pair{*a, s};
    }
}

template <class P>
std::optional<std::pair<P, incidence::sphere3>> ball_random(rng& r) {
    using namespace incidence;
    transform tr = random_transform(r, false, true);
    std::optional<P> a;
    point3 mid;
    if constexpr (flat_ball_shape<P>) {
        const P b = realise(random_shape<P>(r, false, 0.0), tr);
        const sphere3 s{moved(point3{r.uniform(-1.5, 1.5), r.uniform(-1.5, 1.5), r.uniform(-1.5, 1.5)}, tr),
                        tr.scale_only(r.uniform(0, 0.75))};
        if (!finite_shape(b) || !incidence::is_finite(s.center) || !std::isfinite(s.radius)) return std::nullopt;
        return std::pair{b, s};
    } else if constexpr (std::is_same_v<P, obb3>) {
        const obb3 b = random_obb(r, tr);
        const sphere3 s{random_point(r, tr), tr.scale_only(r.uniform(0, 0.75))};
        if (!finite_shape(b) || !incidence::is_finite(s.center) || !std::isfinite(s.radius)) return std::nullopt;
        return std::pair{b, s};
    } else if constexpr (is_kdop<P>::value) {
        std::vector<point3> pts = random_cloud(r);
        mid = pts[0];
        for (auto& x : pts) x = moved(x, tr);
        a = kdop_around<P::slabs * 2>(pts);
    } else if constexpr (std::is_same_v<P, frustum3>) {
        a = camera_frustum(r, tr);
        mid = point3{0, 0, 0};
    } else {
        const halfspace_set h = polyhedron_random_set(r);
        mid = h.X;
        a = realise_polyhedron(h, tr);
    }
    if (!a) return std::nullopt;
    const point3 c{mid.x + r.uniform(-1.5, 1.5), mid.y + r.uniform(-1.5, 1.5), mid.z + r.uniform(-1.5, 1.5)};
    const sphere3 s{moved(c, tr), tr.scale_only(r.uniform(0, 1))};
    if (!incidence::is_finite(s.center) || !std::isfinite(s.radius)) return std::nullopt;
    return std::pair{*a, s};
}

} // namespace support
