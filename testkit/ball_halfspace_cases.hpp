// Cases for a ball against a half-space set (convex_polyhedron_sphere, frustum_sphere, kdop_sphere)
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
// Random: a set of polyhedron_random_set, a camera frustum or the k-DOP of a random cloud, and a
// ball centred within 1.5 of the set's middle with a radius up to 1, at one random scale.
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
inline incidence::sphere3 ball_touching(rng& r, const proto_rows& p) {
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

template <class P>
std::optional<std::pair<P, incidence::sphere3>> ball_near(rng& r) {
    using namespace incidence;
    const proto_rows p = near_rows<P>(r);
    const sphere3 b = ball_touching(r, p);
    transform tr = random_transform(r, true, true);
    const auto a = realise_rows<P>(p, tr);
    if (!a) return std::nullopt;
    const sphere3 s{moved(b.center, tr), tr.scale_only(b.radius)};
    if (!incidence::is_finite(s.center) || !std::isfinite(s.radius)) return std::nullopt;
    return std::pair{*a, s};
}

template <class P>
std::optional<std::pair<P, incidence::sphere3>> ball_random(rng& r) {
    using namespace incidence;
    transform tr = random_transform(r, false, true);
    std::optional<P> a;
    point3 mid;
    if constexpr (is_kdop<P>::value) {
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
