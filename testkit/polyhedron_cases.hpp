// Cases for the half-space pairs: convex_polyhedron3 and frustum3 against a point, segment, ray
// or line. Include after flat_cases.hpp.
//
// Near-degenerate convex polyhedron: 4 to 12 supporting half-spaces of a cloud of 4 to 8 small
// dyadic points, each normal of small integers (components in -3..3) and each plane through the
// cloud's extreme point along it (so the cloud touches every face); one in eight has only 1 to 3
// half-spaces (unbounded), one in eight gains the opposite half-space of its first face, flush
// (the set is then flat: that face) or a quarter beyond (empty). The other shape is placed as in
// flat_cases.hpp at X, one plane's extreme point (or the cloud's first point), along a random
// direction or along that plane. Near-degenerate frustum: an axis-aligned view volume of small
// integer normals (side slopes q / p with p in {1, 2, 4}, so its corners are dyadic), eye and
// distances small dyadics, and X a corner, an edge midpoint, a face centre, a point inside or the
// eye. Then one random exact-or-nudged scale 2^-500..2^500 and translation for both shapes, each
// plane moved as its normal and a point on it (flat_cases.hpp's plane_proto).
// Random: the supporting half-spaces of random normals around a cloud of 4 to 8 random points
// within 0.6 of a centre in [-0.5, 0.5]^3, or a camera frustum (frustum3::from_camera: eye in [-1, 1]^3, any
// view direction, fov 0.3 to 2.5, aspect 0.5 to 2, near 0.05 to 0.5, far up to 3.5 beyond),
// against a random shape of flat_cases.hpp, at one random scale.
// A frustum partner: near-degenerate, the first reflected through X or another moved to X, a third
// of the time then moved out along the face; random, a second camera frustum.
// A k-DOP partner (kdop_cases.hpp): near-degenerate, the k-DOP of a small dyadic cloud at X on the
// outer side of the face there (X one of its points two times in three, else the cloud starts a
// quarter out), moved by the same transform; random, the k-DOP of 4 to 8 random points within
// 0.4 of a centre in [-0.6, 0.6]^3.
#pragma once
#include "kdop_cases.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace support {

inline std::string plane_str(const incidence::plane3& p) {
    return "[(" + hex(p.normal.x) + "," + hex(p.normal.y) + "," + hex(p.normal.z) + ") " + hex(p.offset) + "]";
}
inline std::string shape_str(const incidence::convex_polyhedron3& c) {
    std::string s = "convex_polyhedron3 (" + std::to_string(c.count) + ")";
    for (int i = 0; i < c.count && i < incidence::convex_polyhedron3::capacity; ++i)
        s += " " + plane_str(c.planes[static_cast<unsigned>(i)]);
    return s;
}
inline std::string shape_str(const incidence::frustum3& f) {
    std::string s = "frustum3";
    for (const auto& p : f.planes) s += " " + plane_str(p);
    return s;
}
inline bool finite_shape(const incidence::convex_polyhedron3& c) {
    for (int i = 0; i < c.count; ++i) {
        const auto& p = c.planes[static_cast<unsigned>(i)];
        if (!std::isfinite(p.offset) || !std::isfinite(p.normal.x) || !std::isfinite(p.normal.y) || !std::isfinite(p.normal.z))
            return false;
    }
    return true;
}
inline bool finite_shape(const incidence::frustum3& f) {
    for (const auto& p : f.planes)
        if (!std::isfinite(p.offset) || !std::isfinite(p.normal.x) || !std::isfinite(p.normal.y) || !std::isfinite(p.normal.z))
            return false;
    return true;
}

// The same set written differently: planes in reverse order, one plane scaled by 2 (normal and
// offset), one plane repeated (a polyhedron with room for it).
inline std::vector<incidence::convex_polyhedron3> same_set(const incidence::convex_polyhedron3& c) {
    std::vector<incidence::convex_polyhedron3> v(2, c);
    std::reverse(v[0].planes.begin(), v[0].planes.begin() + c.count);
    if (c.count > 0) {
        auto& p = v[1].planes[0];
        const incidence::plane3 q{p.normal * 2.0, p.offset * 2.0};
        if (std::isfinite(q.offset) && std::isfinite(q.normal.x) && std::isfinite(q.normal.y) && std::isfinite(q.normal.z)) p = q;
    }
    if (c.count > 0 && c.count < incidence::convex_polyhedron3::capacity) {
        v.push_back(c);
        v.back().planes[static_cast<unsigned>(c.count)] = c.planes[static_cast<unsigned>(c.count - 1)];
        ++v.back().count;
    }
    return v;
}
inline std::vector<incidence::frustum3> same_set(const incidence::frustum3& f) {
    std::vector<incidence::frustum3> v(2, f);
    std::reverse(v[0].planes.begin(), v[0].planes.end());
    std::swap(v[1].planes[0], v[1].planes[5]);
    std::swap(v[1].planes[2], v[1].planes[3]);
    return v;
}
inline std::optional<incidence::convex_polyhedron3> translated(const incidence::convex_polyhedron3& c, incidence::vec3 v) {
    incidence::convex_polyhedron3 d = c;
    for (int i = 0; i < c.count; ++i) {
        const auto p = translated(c.planes[static_cast<unsigned>(i)], v);
        if (!p) return std::nullopt;
        d.planes[static_cast<unsigned>(i)] = *p;
    }
    return d;
}
inline std::optional<incidence::frustum3> translated(const incidence::frustum3& f, incidence::vec3 v) {
    incidence::frustum3 d = f;
    for (unsigned i = 0; i < 6; ++i) {
        const auto p = translated(f.planes[i], v);
        if (!p) return std::nullopt;
        d.planes[i] = *p;
    }
    return d;
}

// A small integer normal (components in -3..3, not all zero).
inline incidence::vec3 small_normal(rng& r) {
    for (;;) {
        const incidence::vec3 n{double(r.integer(-3, 3)), double(r.integer(-3, 3)), double(r.integer(-3, 3))};
        if (!(n.x == 0 && n.y == 0 && n.z == 0)) return n;
    }
}
inline incidence::point3 extreme(const std::vector<incidence::point3>& pts, incidence::vec3 n) {
    incidence::point3 x = pts[0];
    for (const auto& p : pts)
        if (dot(n, p - incidence::point3{0, 0, 0}) > dot(n, x - incidence::point3{0, 0, 0})) x = p;
    return x;
}

// Half-spaces kept as protos (a normal and a point on the plane) until the transform moves them.
struct halfspace_set {
    std::vector<plane_proto> planes;
    incidence::point3 X;                  // where the other shape is placed
    incidence::vec3 face{};               // the normal of a face through X (zero: none)
    std::vector<incidence::point3> spots; // points of the set in small dyadics, most on its boundary (balls touch there)
};
inline incidence::convex_polyhedron3 realise_polyhedron(const halfspace_set& h, transform& tr) {
    incidence::convex_polyhedron3 c{};
    c.count = static_cast<int>(h.planes.size());
    for (std::size_t i = 0; i < h.planes.size(); ++i) c.planes[i] = realise(h.planes[i], tr);
    return c;
}
inline incidence::frustum3 realise_frustum(const halfspace_set& h, transform& tr) {
    incidence::frustum3 f{};
    for (std::size_t i = 0; i < 6; ++i) f.planes[i] = realise(h.planes[i], tr);
    return f;
}

// The set as P: a frustum (six planes) or a polyhedron.
template <class P>
P realise_as(const halfspace_set& h, transform& tr) {
    if constexpr (std::is_same_v<P, incidence::frustum3>) return realise_frustum(h, tr);
    else return realise_polyhedron(h, tr);
}

inline halfspace_set polyhedron_near_set(rng& r) {
    using namespace incidence;
    const point3 c = small_point(r);
    std::vector<point3> pts;
    for (int i = r.integer(4, 8); i > 0; --i)
        pts.push_back({c.x + r.integer(-8, 8) * 0.25, c.y + r.integer(-8, 8) * 0.25, c.z + r.integer(-8, 8) * 0.25});
    halfspace_set h;
    const int m = r.integer(0, 7) == 0 ? r.integer(1, 3) : r.integer(4, 12);
    for (int i = 0; i < m; ++i) {
        const vec3 n = small_normal(r);
        h.planes.push_back({n, extreme(pts, n)});
    }
    if (r.integer(0, 7) == 0) { // the opposite of the first face: flush (a flat set) or beyond (empty)
        const plane_proto f = h.planes[0];
        h.planes.push_back({-f.n, r.coin() ? f.x : f.x + f.n * 0.25});
    }
    const auto s = static_cast<std::size_t>(r.integer(0, m - 1));
    h.X = r.integer(0, 5) == 0 ? pts[0] : h.planes[s].x;
    h.face = h.planes[s].n;
    h.spots = pts;
    return h;
}
inline halfspace_set polyhedron_random_set(rng& r) {
    using namespace incidence;
    const point3 c{r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5)};
    std::vector<point3> pts;
    for (int i = r.integer(4, 8); i > 0; --i)
        pts.push_back({c.x + r.uniform(-0.6, 0.6), c.y + r.uniform(-0.6, 0.6), c.z + r.uniform(-0.6, 0.6)});
    halfspace_set h;
    const int m = r.integer(0, 7) == 0 ? r.integer(1, 3) : r.integer(4, 12);
    for (int i = 0; i < m; ++i) {
        const vec3 n{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
        h.planes.push_back({n, extreme(pts, n)});
    }
    h.X = c;
    return h;
}
// An axis-aligned frustum of small integers: view axis f = +-e_k, the other two axes r and u
// with random signs, side slopes q / p, eye E, near and far distances.
inline halfspace_set frustum_near_set(rng& r) {
    using namespace incidence;
    const int k = r.integer(0, 2);
    vec3 ax[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    auto sgn = [&] { return r.coin() ? 1.0 : -1.0; };
    const vec3 f = ax[k] * sgn(), rt = ax[(k + 1) % 3] * sgn(), up = ax[(k + 2) % 3] * sgn();
    const point3 E = small_point(r);
    static constexpr double ps[] = {1, 2, 4};
    double q[4], p[4];
    for (int i = 0; i < 4; ++i) q[i] = r.integer(1, 3), p[i] = ps[r.integer(0, 2)];
    const double zn = r.integer(1, 4) * 0.25, zf = zn + r.integer(1, 8) * 0.5;
    halfspace_set h;
    h.planes = {{-f, E + f * zn},           {f, E + f * zf},          {-rt * p[0] - f * q[0], E}, {rt * p[1] - f * q[1], E},
                {-up * p[2] - f * q[2], E}, {up * p[3] - f * q[3], E}};
    // the corner at depth z, left or right, bottom or top (dyadic: q z / p with p a power of 2)
    auto corner = [&](double z, bool right, bool top) {
        const double x = right ? q[1] * z / p[1] : -q[0] * z / p[0], y = top ? q[3] * z / p[3] : -q[2] * z / p[2];
        return E + f * z + rt * x + up * y;
    };
    auto mid = [](point3 a, point3 b) { return point3{(a.x + b.x) * 0.5, (a.y + b.y) * 0.5, (a.z + b.z) * 0.5}; };
    const double z = r.coin() ? zn : zf;
    const point3 a = corner(z, r.coin(), r.coin()), b = corner(z, r.coin(), r.coin());
    switch (r.integer(0, 5)) {
    case 0:
        h.X = a;
        h.face = r.coin() ? h.planes[z == zn ? 0u : 1u].n : h.planes[2].n;
        break; // a corner
    case 1:
        h.X = mid(a, corner(z == zn ? zf : zn, true, true));
        h.face = h.planes[3].n;
        break; // on or near a side face
    case 2:
        h.X = mid(a, b);
        h.face = h.planes[z == zn ? 0u : 1u].n;
        break;                                                                  // an edge or the near/far face
    case 3: h.X = mid(corner(zn, false, false), corner(zf, true, true)); break; // inside
    case 4:
        h.X = E;
        h.face = h.planes[2].n;
        break; // the eye, apex of the sides
    default:
        h.X = mid(corner(z, false, true), corner(z, true, true));
        h.face = h.planes[5].n;
        break; // a near or far edge
    }
    for (const double d : {zn, zf}) // the corners, the near and far faces' centres and edge midpoints
        for (int i = 0; i < 4; ++i) {
            const point3 c = corner(d, i & 1, i & 2);
            h.spots.push_back(c);
            h.spots.push_back(mid(c, corner(d, !(i & 1), !(i & 2))));
            h.spots.push_back(mid(c, corner(d, !(i & 1), i & 2)));
        }
    return h;
}

// A polyhedron at X for a second half-space set: 4 to 12 supporting half-spaces of a small dyadic
// cloud that contains X and lies on the outer side of f (when f is not zero), and two times in
// three the half-space beyond that face through X (-f . x <= -f . X), so the two sets meet at most
// in the face's plane.
inline halfspace_set polyhedron_near_at(rng& r, incidence::point3 X, incidence::vec3 f) {
    using namespace incidence;
    std::vector<point3> pts{X};
    for (int i = r.integer(3, 7); i > 0; --i) {
        vec3 w{r.integer(-8, 8) * 0.25, r.integer(-8, 8) * 0.25, r.integer(-8, 8) * 0.25};
        if (dot(f, w) < 0) w = -w;
        pts.push_back(X + w);
    }
    halfspace_set h;
    for (int i = r.integer(4, 12); i > 0; --i) {
        const vec3 n = small_normal(r);
        h.planes.push_back({n, extreme(pts, n)});
    }
    if (!(f.x == 0 && f.y == 0 && f.z == 0) && r.integer(0, 2) != 0) h.planes.push_back({-f, X});
    h.X = X;
    h.face = -f;
    return h;
}

template <class P>
struct is_halfspace_shape : std::bool_constant<std::is_same_v<P, incidence::convex_polyhedron3> || std::is_same_v<P, incidence::frustum3>> {
};

// P (convex_polyhedron3 or frustum3) against B, near-degenerate.
template <class P, class B>
std::optional<std::pair<P, B>> halfspace_near(rng& r) {
    using namespace incidence;
    const halfspace_set h = std::is_same_v<P, frustum3> ? frustum_near_set(r) : polyhedron_near_set(r);
    if constexpr (std::is_same_v<B, convex_polyhedron3>) { // a second polyhedron at X, beyond the face
        const halfspace_set h2 = polyhedron_near_at(r, h.X, h.face);
        transform tr = random_transform(r, true, true);
        const P a = realise_as<P>(h, tr);
        const convex_polyhedron3 b = realise_polyhedron(h2, tr);
        if (!finite_shape(a) || !finite_shape(b)) return std::nullopt;
        return std::pair{a, b};
    } else if constexpr (std::is_same_v<B, frustum3>) {
        // a second frustum at X: the first reflected through X (it touches the first within the
        // plane of a face through X, or at X) or another one moved so that its X is here; a third
        // of the time then moved a quarter or 2^-20 out along the face
        halfspace_set h2 = h;
        if (r.coin()) {
            for (auto& p : h2.planes) p = {-p.n, h.X + (h.X - p.x)};
        } else {
            h2 = frustum_near_set(r);
            const vec3 v = h.X - h2.X;
            for (auto& p : h2.planes) p.x = p.x + v;
        }
        if (r.integer(0, 2) == 0) {
            const vec3 v = h.face * (r.coin() ? 0.25 : 0x1p-20);
            for (auto& p : h2.planes) p.x = p.x + v;
        }
        transform tr = random_transform(r, true, true);
        const P a = realise_as<P>(h, tr);
        const frustum3 b = realise_frustum(h2, tr);
        if (!finite_shape(a) || !finite_shape(b)) return std::nullopt;
        return std::pair{a, b};
    } else if constexpr (is_kdop<B>::value) { // the k-DOP of a cloud at X, on or beyond the face
        std::vector<point3> pts;
        const bool at_x = r.integer(0, 2) != 0;
        for (int i = r.integer(3, 7); i > 0; --i) {
            vec3 w{r.integer(-8, 8) * 0.25, r.integer(-8, 8) * 0.25, r.integer(-8, 8) * 0.25};
            if (dot(h.face, w) < 0) w = -w;
            pts.push_back(h.X + w + (at_x ? vec3{0, 0, 0} : h.face * 0.25));
        }
        if (at_x) pts.push_back(h.X);
        transform tr = random_transform(r, true, true);
        const P a = realise_as<P>(h, tr);
        for (auto& p : pts) p = moved(p, tr);
        const auto b = kdop_around<B::slabs * 2>(pts);
        if (!b || !finite_shape(a)) return std::nullopt;
        return std::pair{a, *b};
    } else {
        vec3 d = small_dir(r);
        const bool has_face = !(h.face.x == 0 && h.face.y == 0 && h.face.z == 0);
        if (has_face && r.coin()) { // along the face
            d = cross(h.face, d);
            if (d.x == 0 && d.y == 0 && d.z == 0) d = cross(h.face, vec3{1, 2, 3});
        }
        auto b = place<B>(r, h.X, d, r.coin());
        if constexpr (std::is_same_v<B, plane3>) // a face's own plane through X, either orientation: touching
            if (has_face && r.integer(0, 2) == 0) b = {r.coin() ? h.face : -h.face, h.X};
        if constexpr (std::is_same_v<B, tetrahedron3>)
            if (has_face && r.integer(0, 2) == 0) b = tetrahedron_around(r, h.X, h.face);
        transform tr = random_transform(r, true, true);
        const P a = realise_as<P>(h, tr);
        const B bb = realise(b, tr);
        if (!finite_shape(a)) return std::nullopt;
        return std::pair{a, bb};
    }
}
// A random camera frustum (frustum3::from_camera), its eye in [-1, 1]^3 moved by tr.
inline std::optional<incidence::frustum3> camera_frustum(rng& r, transform& tr) {
    using namespace incidence;
    const point3 eye{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
    const vec3 fw{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}, up{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
    const double zn = r.uniform(0.05, 0.5), zf = zn + r.uniform(0.5, 3.0);
    const auto f =
        frustum3::from_camera(moved(eye, tr), fw, up, r.uniform(0.3, 2.5), r.uniform(0.5, 2.0), tr.scale_only(zn), tr.scale_only(zf));
    if (!f.has_value()) return std::nullopt;
    return f.value();
}
template <class P, class B>
std::optional<std::pair<P, B>> halfspace_random(rng& r) {
    using namespace incidence;
    const auto b = [&] {
        if constexpr (std::is_same_v<B, convex_polyhedron3>) return polyhedron_random_set(r);
        else if constexpr (is_kdop<B>::value) return random_cloud(r);
        else if constexpr (std::is_same_v<B, frustum3>) return 0; // drawn below, once the transform is known
        else return random_shape<B>(r, false, 0.0);
    }();
    transform tr = random_transform(r, false, true);
    P a;
    if constexpr (std::is_same_v<P, frustum3>) {
        const auto f = camera_frustum(r, tr);
        if (!f) return std::nullopt;
        a = *f;
    } else {
        a = realise_polyhedron(polyhedron_random_set(r), tr);
    }
    B bb;
    if constexpr (std::is_same_v<B, convex_polyhedron3>) bb = realise_polyhedron(b, tr);
    else if constexpr (std::is_same_v<B, frustum3>) {
        const auto f = camera_frustum(r, tr);
        if (!f) return std::nullopt;
        bb = *f;
    } else if constexpr (is_kdop<B>::value) {
        std::vector<point3> pts = b;
        for (auto& p : pts) p = moved(p, tr);
        const auto kd = kdop_around<B::slabs * 2>(pts);
        if (!kd) return std::nullopt;
        bb = *kd;
    } else bb = realise(b, tr);
    if (!finite_shape(a) || !finite_shape(bb)) return std::nullopt;
    return std::pair{a, bb};
}

// contains(P, segment3 | triangle3 | tetrahedron3) cases: a segment (or triangle, or tetrahedron)
// between points of the near-degenerate set's boundary or inside (the extreme points and X), then
// its last vertex nudged by one ulp or not.
template <class P, class S = incidence::segment3>
std::optional<std::pair<P, S>> halfspace_inside_case(rng& r) {
    using namespace incidence;
    const halfspace_set h = std::is_same_v<P, frustum3> ? frustum_near_set(r) : polyhedron_near_set(r);
    std::vector<point3> on{h.X};
    for (const auto& p : h.planes) on.push_back(p.x);
    auto pick = [&] { return on[static_cast<std::size_t>(r.integer(0, static_cast<int>(on.size()) - 1))]; };
    S s;
    if constexpr (std::is_same_v<S, tetrahedron3>) {
        const point3 a = pick(), b = pick(), c = pick();
        s = {a, b, c, pick()};
    } else if constexpr (std::is_same_v<S, triangle3>) {
        const point3 a = pick(), b = pick();
        s = {a, b, pick()};
    } else {
        const point3 a = pick();
        s = {a, pick()};
    }
    transform tr = random_transform(r, r.coin(), true);
    const P a = realise_as<P>(h, tr);
    s = realise(s, tr);
    if constexpr (std::is_same_v<S, tetrahedron3>) {
        if (r.coin()) s.d.x = std::nextafter(s.d.x, r.coin() ? 1e308 : -1e308);
    } else if constexpr (std::is_same_v<S, triangle3>) {
        if (r.coin()) s.c.x = std::nextafter(s.c.x, r.coin() ? 1e308 : -1e308);
    } else if (r.coin()) s.b.x = std::nextafter(s.b.x, r.coin() ? 1e308 : -1e308);
    if (!finite_shape(a)) return std::nullopt;
    return std::pair{a, s};
}

} // namespace support
