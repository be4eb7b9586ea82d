// Configurations on and near each family's decision boundary, for the audit's stability curves
// and its independent recomputation test. Include after `import incidence;`.
//
// For every family (A, B) of incidence::catalog, `near_boundary<A, B>::touching(rng)` builds an
// *exactly* touching pair from small integers and dyadic fractions (|x| <= 2^10), so every
// coordinate is exact. The audit then moves it:
//   setting: add an offset from the origin (exact: integers) and scale by 2^e (exact);
//   level k: translate the second shape by 2^-k * 2^10 along a random unit vector, rounded
//            (so the pair is about 2^-k of the object size from touching, on either side);
//   ulp j:   move one coordinate of either shape by j ulps, up or down.
// A family without a specialisation here does not compile: the audit covers every family.
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <type_traits>
#include <utility>
#include "rng.hpp"

namespace audit {

using namespace incidence;

// A stream per (seed, family, level, setting): the recomputation test regenerates any of them.
inline std::uint64_t stream(std::uint64_t seed, unsigned family, int level, unsigned setting) {
    std::uint64_t h = seed * 0x9E3779B97F4A7C15ull;
    for (std::uint64_t v : {std::uint64_t(family), std::uint64_t(level + 1000), std::uint64_t(setting)}) {
        h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        h *= 0xBF58476D1CE4E5B9ull;
    }
    return h;
}

inline constexpr double base_size = 1024.0; // the objects' size, in the units before scaling

// --- per-shape moves -------------------------------------------------------------------------
inline point3 moved(point3 p, vec3 v) { return p + v; }
inline sphere3 moved(sphere3 s, vec3 v) { return {s.center + v, s.radius}; }
inline capsule3 moved(capsule3 c, vec3 v) { return {c.a + v, c.b + v, c.radius}; }
inline aabb3 moved(aabb3 b, vec3 v) { return {b.min + v, b.max + v}; }
inline ray3 moved(ray3 r, vec3 v) { return {r.origin + v, r.direction}; }
inline segment3 moved(segment3 s, vec3 v) { return {s.a + v, s.b + v}; }
inline line3 moved(line3 l, vec3 v) { return {l.origin + v, l.direction}; }
inline plane3 moved(plane3 p, vec3 v) { return {p.normal, p.offset + dot(p.normal, v)}; }
inline triangle3 moved(triangle3 t, vec3 v) { return {t.a + v, t.b + v, t.c + v}; }
inline obb3 moved(obb3 b, vec3 v) { return {b.center + v, b.axes, b.half_extents}; }
inline tetrahedron3 moved(tetrahedron3 t, vec3 v) { return {t.a + v, t.b + v, t.c + v, t.d + v}; }
// The plane's shapes move by (v.x, v.y).
inline point2 moved(point2 p, vec3 v) { return {p.x + v.x, p.y + v.y}; }
inline segment2 moved(segment2 s, vec3 v) { return {moved(s.a, v), moved(s.b, v)}; }
inline ray2 moved(ray2 r, vec3 v) { return {moved(r.origin, v), r.direction}; }
inline line2 moved(line2 l, vec3 v) { return {moved(l.origin, v), l.direction}; }
inline circle2 moved(circle2 c, vec3 v) { return {moved(c.center, v), c.radius}; }

// Every shape is an aggregate of doubles: scaling and ulp moves act on its fields.
template <class S>
using fields = std::array<double, sizeof(S) / sizeof(double)>;

template <class S>
S scaled(const S& s, int e) {
    auto f = std::bit_cast<fields<S>>(s);
    for (double& x : f) x = std::ldexp(x, e);
    return std::bit_cast<S>(f);
}
inline plane3 scaled(const plane3& p, int e) { return {p.normal, std::ldexp(p.offset, e)}; } // n . (2^e x) = 2^e offset
inline obb3 scaled(const obb3& b, int e) { // the axes are directions: only the centre and extents scale
    return {scaled(b.center, e),
            b.axes,
            {std::ldexp(b.half_extents[0], e), std::ldexp(b.half_extents[1], e), std::ldexp(b.half_extents[2], e)}};
}
inline aabb3 tidy(aabb3 b) { // a nudge may swap a flat box's bounds
    if (b.min.x > b.max.x) std::swap(b.min.x, b.max.x);
    if (b.min.y > b.max.y) std::swap(b.min.y, b.max.y);
    if (b.min.z > b.max.z) std::swap(b.min.z, b.max.z);
    return b;
}
inline obb3 tidy(obb3 b) { // a nudge may make a zero extent negative
    for (double& h : b.half_extents) h = std::fabs(h);
    return b;
}
// A k-DOP moves by shifting every bound by d_i . v (rounded: the moved k-DOP is the one its
// bounds say).
inline kdop<14> moved(kdop<14> b, vec3 v) {
    const auto d = kdop<14>::directions();
    for (unsigned i = 0; i < d.size(); ++i) {
        const double dv = d[i].x * v.x + d[i].y * v.y + d[i].z * v.z;
        b.min[i] += dv, b.max[i] += dv;
    }
    return b;
}
inline kdop<14> tidy(kdop<14> b) { // a nudge may invert a flat slab
    for (unsigned i = 0; i < b.min.size(); ++i)
        if (b.min[i] > b.max[i]) std::swap(b.min[i], b.max[i]);
    return b;
}
template <class S>
S tidy(const S& s) {
    return s;
}

template <class S>
S nudged(const S& s, int ulps, rng& r) {
    auto f = std::bit_cast<fields<S>>(s);
    double& x = f[static_cast<std::size_t>(r.integer(0, static_cast<int>(f.size()) - 1))];
    const double to = r.coin() ? INFINITY : -INFINITY;
    for (int i = 0; i < ulps; ++i) x = std::nextafter(x, to);
    return tidy(std::bit_cast<S>(f));
}

inline vec3 random_unit(rng& r) {
    for (;;) {
        const vec3 v{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
        const double l2 = dot(v, v);
        if (l2 > 0.01 && l2 <= 1.0) return v * (1.0 / std::sqrt(l2));
    }
}
inline point3 int_point(rng& r, int lim = 512) {
    return {double(r.integer(-lim, lim)), double(r.integer(-lim, lim)), double(r.integer(-lim, lim))};
}
// a^2 + b^2 + c^2 = d^2, with random signs and order: an exact point on a sphere of radius d.
inline std::pair<vec3, double> pythagorean(rng& r) {
    static constexpr int q[][4] = {{1, 2, 2, 3},  {2, 3, 6, 7},   {1, 4, 8, 9},    {4, 4, 7, 9},    {2, 6, 9, 11},
                                   {6, 6, 7, 11}, {3, 4, 12, 13}, {2, 10, 11, 15}, {1, 12, 12, 17}, {8, 9, 12, 17}};
    const auto& e = q[r.integer(0, 9)];
    double v[3] = {double(e[0]), double(e[1]), double(e[2])};
    for (int i = 2; i > 0; --i) std::swap(v[i], v[r.integer(0, i)]);
    for (double& x : v) x = r.coin() ? x : -x;
    return {vec3{v[0], v[1], v[2]}, double(e[3])};
}
inline vec3 int_vec(rng& r, int lim) {
    for (;;) {
        const vec3 v{double(r.integer(-lim, lim)), double(r.integer(-lim, lim)), double(r.integer(-lim, lim))};
        if (v.x != 0 || v.y != 0 || v.z != 0) return v;
    }
}
inline triangle3 int_triangle(rng& r) {
    for (;;) {
        const point3 a = int_point(r, 400);
        const triangle3 t{a, a + int_vec(r, 400), a + int_vec(r, 400)};
        const vec3 n = cross(t.b - t.a, t.c - t.a);
        if (dot(n, n) > 1e4) return t;
    }
}
// A point of the closed triangle's boundary: a vertex, or an edge point at a quarter step.
inline point3 boundary_point(const triangle3& t, rng& r) {
    const point3 v[3] = {t.a, t.b, t.c};
    const int i = r.integer(0, 2);
    const point3 p = v[i], q = v[(i + 1) % 3];
    const double s = r.integer(0, 4) * 0.25;
    return p + (q - p) * s;
}

template <class A, class B>
struct near_boundary; // specialised per family below

template <>
struct near_boundary<point3, sphere3> {
    static std::pair<point3, sphere3> touching(rng& r) {
        const point3 c = int_point(r);
        const auto [u, d] = pythagorean(r);
        const double m = r.integer(1, 30);
        return {c + u * m, sphere3{c, d * m}};
    }
};
template <>
struct near_boundary<sphere3, sphere3> {
    static std::pair<sphere3, sphere3> touching(rng& r) {
        const point3 c = int_point(r);
        const auto [u, d] = pythagorean(r);
        const double m = r.integer(2, 30), r1 = r.integer(1, int(d * m) - 1);
        return {sphere3{c, r1}, sphere3{c + u * m, d * m - r1}};
    }
};
// A box and a ball touching at a face, an edge or a corner: the ball's centre beyond the box's
// nearest point q by a Pythagorean offset u m of length d m (its radius), u pointing away from the
// box on the axes where q is on a face (a zero component: q inside the slab).
template <>
struct near_boundary<aabb3, sphere3> {
    static std::pair<aabb3, sphere3> touching(rng& r) {
        const point3 lo = int_point(r);
        const aabb3 b{lo, lo + vec3{double(r.integer(1, 400)), double(r.integer(1, 400)), double(r.integer(1, 400))}};
        auto [u, d] = pythagorean(r);
        const double m = r.integer(1, 20);
        const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
        double uc[3] = {u.x, u.y, u.z}, q[3];
        for (int i = 0; i < 3; ++i) q[i] = uc[i] > 0 ? mx[i] : (uc[i] < 0 ? mn[i] : std::floor((mn[i] + mx[i]) / 2));
        return {b, sphere3{point3{q[0] + uc[0] * m, q[1] + uc[1] * m, q[2] + uc[2] * m}, d * m}};
    }
};
template <>
struct near_boundary<aabb3, point3> {
    static std::pair<aabb3, point3> touching(rng& r) {
        const point3 lo = int_point(r);
        const aabb3 b{lo, lo + vec3{double(r.integer(1, 400)), double(r.integer(1, 400)), double(r.integer(1, 400))}};
        double p[3];
        const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
        const int on = r.integer(0, 2); // at least this axis on a face; others on a face w.p. 1/3
        for (int i = 0; i < 3; ++i) {
            const int how = i == on ? r.integer(0, 1) : r.integer(0, 2);
            p[i] = how == 0 ? mn[i] : (how == 1 ? mx[i] : mn[i] + std::floor((mx[i] - mn[i]) * r.uniform(0, 1)));
        }
        return {b, point3{p[0], p[1], p[2]}};
    }
};
template <>
struct near_boundary<aabb3, aabb3> {
    static std::pair<aabb3, aabb3> touching(rng& r) {
        const auto [a, p] = near_boundary<aabb3, point3>::touching(r);
        // A second box with p as a corner, lying outside a on the touching axes.
        const double mn[3] = {a.min.x, a.min.y, a.min.z}, mx[3] = {a.max.x, a.max.y, a.max.z}, q[3] = {p.x, p.y, p.z};
        double lo[3], hi[3];
        for (int i = 0; i < 3; ++i) {
            const double e = r.integer(1, 300);
            const bool up = q[i] == mx[i] ? true : (q[i] == mn[i] ? false : r.coin());
            lo[i] = up ? q[i] : q[i] - e;
            hi[i] = up ? q[i] + e : q[i];
        }
        return {a, aabb3{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}};
    }
};
template <>
struct near_boundary<ray3, sphere3> {
    static std::pair<ray3, sphere3> touching(rng& r) {
        const point3 c = int_point(r);
        const auto [u, d] = pythagorean(r);
        const double m = r.integer(1, 30);
        const point3 p = c + u * m; // on the sphere
        vec3 w = cross(u, int_vec(r, 8));
        if (w.x == 0 && w.y == 0 && w.z == 0) w = cross(u, vec3{1, 0, 0}) + cross(u, vec3{0, 1, 0});
        const double t = r.integer(1, 6);
        return {ray3{p - w * t, w}, sphere3{c, d * m}}; // tangent at p
    }
};
template <>
struct near_boundary<aabb3, ray3> {
    static std::pair<aabb3, ray3> touching(rng& r) {
        for (;;) {
            const auto [b, p] = near_boundary<aabb3, point3>::touching(r);
            // Through a boundary point p from outside: the ray grazes an edge/corner or enters.
            const point3 o = p + int_vec(r, 600);
            if (o.x >= b.min.x && o.x <= b.max.x && o.y >= b.min.y && o.y <= b.max.y && o.z >= b.min.z && o.z <= b.max.z) continue;
            return {b, ray3{o, p - o}};
        }
    }
};
template <>
struct near_boundary<aabb3, segment3> {
    static std::pair<aabb3, segment3> touching(rng& r) { // ends on the boundary, or passes through it
        const auto [b, ray] = near_boundary<aabb3, ray3>::touching(r);
        const double f = r.integer(2, 4) * 0.5; // 1: ends at the boundary point
        return {b, segment3{ray.origin, ray.origin + ray.direction * f}};
    }
};
template <>
struct near_boundary<aabb3, line3> {
    static std::pair<aabb3, line3> touching(rng& r) { // the ray's line: the origin is outside the box
        const auto [b, ray] = near_boundary<aabb3, ray3>::touching(r);
        return {b, line3{ray.origin, ray.direction}};
    }
};
// Planes n . p = offset through the shape's vertex that is extreme along -n: the shape lies on
// the plane's positive side and touches it at a vertex, an edge or a face (ties).
template <>
struct near_boundary<aabb3, plane3> {
    static std::pair<aabb3, plane3> touching(rng& r) {
        const auto [b, p] = near_boundary<aabb3, point3>::touching(r);
        const vec3 n = int_vec(r, 6);
        const point3 lo{n.x >= 0 ? b.min.x : b.max.x, n.y >= 0 ? b.min.y : b.max.y, n.z >= 0 ? b.min.z : b.max.z};
        return {b, plane3{n, dot(n, lo - point3{0, 0, 0})}};
    }
};
template <>
struct near_boundary<plane3, segment3> {
    static std::pair<plane3, segment3> touching(rng& r) {
        const point3 a = int_point(r, 400);
        const point3 b = a + int_vec(r, 400);
        vec3 n = int_vec(r, 6);
        if (dot(n, b - a) < 0) n = n * -1.0;
        return {plane3{n, dot(n, a - point3{0, 0, 0})}, r.coin() ? segment3{a, b} : segment3{b, a}};
    }
};
template <>
struct near_boundary<plane3, triangle3> {
    static std::pair<plane3, triangle3> touching(rng& r) {
        const triangle3 t = int_triangle(r);
        const vec3 n = int_vec(r, 6);
        const point3 v[3] = {t.a, t.b, t.c};
        point3 lo = v[0];
        for (const point3& q : v)
            if (dot(n, q - lo) < 0) lo = q;
        return {plane3{n, dot(n, lo - point3{0, 0, 0})}, t};
    }
};
template <>
struct near_boundary<ray3, triangle3> {
    static std::pair<ray3, triangle3> touching(rng& r) {
        const triangle3 t = int_triangle(r);
        const point3 p = boundary_point(t, r), o = p + int_vec(r, 600);
        return {ray3{o, p - o}, t};
    }
};
template <>
struct near_boundary<segment3, triangle3> {
    static std::pair<segment3, triangle3> touching(rng& r) {
        const triangle3 t = int_triangle(r);
        const point3 p = boundary_point(t, r), o = p + int_vec(r, 600);
        const double f = r.integer(1, 3) * 0.5 + 0.5; // ends on the edge, or passes through it
        return {segment3{o, o + (p - o) * f}, t};
    }
};
template <>
struct near_boundary<aabb3, triangle3> {
    // A triangle outside the box touching it at a boundary point p: at a vertex, or along an edge
    // lying in the plane of a face through p; the rest of the triangle beyond that face.
    static std::pair<aabb3, triangle3> touching(rng& r) {
        const auto [b, p] = near_boundary<aabb3, point3>::touching(r);
        const double q[3] = {p.x, p.y, p.z}, mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
        int axis = 0;
        while (q[axis] != mn[axis] && q[axis] != mx[axis]) ++axis;
        const double out = q[axis] == mx[axis] ? 1.0 : -1.0;
        auto away = [&](bool in_plane) { // a vector pointing out of the face (or lying in its plane)
            double v[3] = {double(r.integer(-300, 300)), double(r.integer(-300, 300)), double(r.integer(-300, 300))};
            v[axis] = in_plane ? 0.0 : out * double(r.integer(1, 300));
            return vec3{v[0], v[1], v[2]};
        };
        for (;;) {
            triangle3 t;
            if (r.coin()) t = triangle3{p, p + away(false), p + away(false)};
            else {
                const vec3 w = away(true);
                t = triangle3{p + w, p - w * double(r.integer(1, 3)), p + away(false)};
            }
            const vec3 n = cross(t.b - t.a, t.c - t.a);
            if (dot(n, n) > 1e4) return {b, t};
        }
    }
};
template <>
struct near_boundary<triangle3, triangle3> {
    static std::pair<triangle3, triangle3> touching(rng& r) {
        const triangle3 t = int_triangle(r);
        const point3 p = boundary_point(t, r);
        for (;;) {
            const triangle3 u{p, p + int_vec(r, 400), p + int_vec(r, 400)};
            const vec3 n = cross(u.b - u.a, u.c - u.a);
            if (dot(n, n) > 1e4) return r.coin() ? std::pair{t, u} : std::pair{u, t};
        }
    }
};

// A box whose corners are exact: integer centre and extents, and a frame that is a signed
// permutation of the unit axes, possibly turned by the exactly orthogonal dyadic near-rotation
// (1, e, 0), (-e, 1, 0), (0, 0, 1 + e^2), |e| <= 2^-11. p is a corner, edge or face point of its boundary and
// o = sum s_i a_i points out of the box there.
struct obb_touch {
    obb3 box;
    point3 p;
    vec3 o;
};
inline obb_touch touching_obb(rng& r) {
    std::array<vec3, 3> a{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
    if (r.coin()) {
        // e <= 2^-11 keeps the frame within obb3::make's 1e-6 of orthonormal, as the
        // alternatives (Gottschalk's test) assume
        const double e = std::ldexp(1.0, -r.integer(11, 13)) * (r.coin() ? 1 : -1);
        a = {vec3{1, e, 0}, vec3{-e, 1, 0}, vec3{0, 0, 1 + e * e}};
    }
    for (int i = 2; i > 0; --i) std::swap(a[static_cast<unsigned>(i)], a[static_cast<unsigned>(r.integer(0, i))]);
    const bool swap_xz = r.coin(); // one coordinate permutation for the whole frame
    for (auto& v : a) {
        double c[3] = {v.x, v.y, v.z};
        if (swap_xz) std::swap(c[0], c[2]);
        v = r.coin() ? vec3{c[0], c[1], c[2]} : vec3{-c[0], -c[1], -c[2]};
    }
    obb_touch t{obb3{int_point(r, 256), a, {double(r.integer(1, 256)), double(r.integer(1, 256)), double(r.integer(1, 256))}}, {}, {}};
    t.p = t.box.center;
    for (unsigned i = 0; i < 3; ++i) {
        const double s = r.integer(0, 3) == 0 ? 0.0 : (r.coin() ? 1.0 : -1.0);
        t.p = t.p + a[i] * (s * t.box.half_extents[i]);
        t.o = t.o + a[i] * (s == 0.0 ? 0.0 : s);
    }
    if (t.o.x == 0 && t.o.y == 0 && t.o.z == 0) t.o = a[0]; // the centre was picked: use a face
    if (t.o.x == a[0].x && t.o.y == a[0].y && t.o.z == a[0].z) t.p = t.box.center + a[0] * t.box.half_extents[0];
    return t;
}
// touching_obb's box moved so that its boundary point lies at p with its centre on the outer side
// of the plane through p with outward normal o (reflected through p when it was not; exact: the
// offsets are integers and dyadics): touching at p at least, or overlapping along the face.
inline obb3 obb_beyond(rng& r, point3 p, vec3 o) {
    const auto b = touching_obb(r);
    const vec3 in = b.box.center - b.p;
    obb3 box = b.box;
    box.center = p + (dot(in, o) < 0 ? in * -1.0 : in);
    return box;
}
template <>
struct near_boundary<obb3, point3> {
    static std::pair<obb3, point3> touching(rng& r) {
        const auto t = touching_obb(r);
        return {t.box, t.p};
    }
};
template <>
struct near_boundary<obb3, sphere3> {
    static std::pair<obb3, sphere3> touching(rng& r) { // centred out along o from p, its radius the distance (rounded)
        const auto t = touching_obb(r);
        const double k = r.integer(1, 60);
        return {t.box, sphere3{t.p + t.o * k, k * std::sqrt(dot(t.o, t.o))}};
    }
};
// A ball touching a flat shape or a tetrahedron at x: centred at x + k w for w in the shape's normal
// cone at x, its radius k |w| (rounded unless |w| is an integer). A capsule grown from that centre
// along v with v . w >= 0 keeps the ball's distance (the shape lies in w . (y - x) <= 0).
inline sphere3 ball_at(rng& r, point3 x, vec3 w) {
    const double k = r.integer(1, 40);
    return sphere3{x + w * k, k * std::sqrt(dot(w, w))};
}
inline capsule3 capsule_at(rng& r, point3 x, vec3 w) {
    const sphere3 b = ball_at(r, x, w);
    vec3 v = r.integer(0, 3) == 0 ? vec3{0, 0, 0} : int_vec(r, 40);
    if (dot(v, w) < 0) v = v * -1.0;
    return capsule3{b.center, b.center + v, b.radius};
}
inline vec3 across(rng& r, vec3 d) { // a nonzero vector perpendicular to d
    for (;;) {
        const vec3 w = cross(d, int_vec(r, 8));
        if (w.x != 0 || w.y != 0 || w.z != 0) return w;
    }
}
// A shape, a point x of it and a direction w in its normal cone at x.
template <class S>
struct contact {
    S shape;
    point3 x;
    vec3 w;
};
inline contact<segment3> segment_contact(rng& r) { // at an end (w leaning away) or inside
    const point3 a = int_point(r, 400);
    const vec3 d = int_vec(r, 400);
    const segment3 s{a, a + d};
    const int at = r.integer(0, 2);
    if (at == 2) return {s, a + d * (r.integer(1, 3) * 0.25), across(r, d)};
    const vec3 out = at == 0 ? d * -1.0 : d;
    return {s, at == 0 ? s.a : s.b, across(r, d) * double(r.integer(0, 2)) + out * double(r.integer(1, 2))};
}
inline contact<line3> line_contact(rng& r) {
    const line3 l{int_point(r, 400), int_vec(r, 400)};
    return {l, l.origin + l.direction * double(r.integer(-3, 3)), across(r, l.direction)};
}
inline contact<plane3> plane_contact(rng& r) {
    const vec3 n = int_vec(r, 12);
    const point3 x = int_point(r, 400);
    return {plane3{n, dot(n, x - point3{0, 0, 0})}, x, r.coin() ? n : n * -1.0};
}
inline contact<triangle3> triangle_contact(rng& r) { // at a vertex, an edge point or inside, off either side
    const triangle3 t = int_triangle(r);
    const point3 v[3] = {t.a, t.b, t.c};
    const vec3 n = cross(t.b - t.a, t.c - t.a);
    const auto out = [&](int i) { return cross(v[(i + 1) % 3] - v[i], n); }; // edge i's outward normal in the plane
    const int i = r.integer(0, 2), where = r.integer(0, 2);
    vec3 w = n * double(r.integer(-2, 2));
    point3 x = v[i];
    if (where == 0) w = w + (out(i) + out((i + 2) % 3)) * double(r.integer(0, 1)); // the vertex v[i]
    else if (where == 1) x = v[i] + (v[(i + 1) % 3] - v[i]) * (r.integer(1, 3) * 0.25), w = w + out(i) * double(r.integer(0, 1));
    else x = point3{(t.a.x + t.b.x + 2 * t.c.x) / 4, (t.a.y + t.b.y + 2 * t.c.y) / 4, (t.a.z + t.b.z + 2 * t.c.z) / 4};
    if (w.x == 0 && w.y == 0 && w.z == 0) w = n;
    return {t, x, w};
}
inline contact<tetrahedron3> tetrahedron_contact(rng& r) { // at a face point, an edge point or a vertex
    for (;;) {
        const point3 a = int_point(r, 400);
        const tetrahedron3 t{a, a + int_vec(r, 400), a + int_vec(r, 400), a + int_vec(r, 400)};
        const point3 v[4] = {t.a, t.b, t.c, t.d};
        if (dot(cross(v[1] - v[0], v[2] - v[0]), v[3] - v[0]) == 0) continue;
        const auto outward = [&](int skip) { // the face without v[skip]: its normal, away from v[skip]
            const point3 p = v[(skip + 1) % 4], q = v[(skip + 2) % 4], s = v[(skip + 3) % 4];
            const vec3 m = cross(q - p, s - p);
            return dot(m, v[skip] - p) > 0 ? m * -1.0 : m;
        };
        const int i = r.integer(0, 3), j = (i + 1 + r.integer(0, 2)) % 4, where = r.integer(0, 2);
        if (where == 0) { // a point of the face without v[i]
            const point3 p = v[(i + 1) % 4], q = v[(i + 2) % 4], s = v[(i + 3) % 4];
            return {t, point3{(p.x + q.x + 2 * s.x) / 4, (p.y + q.y + 2 * s.y) / 4, (p.z + q.z + 2 * s.z) / 4}, outward(i)};
        }
        vec3 w{0, 0, 0};
        point3 x = v[i];
        if (where == 1) { // the edge v[i] v[j]: the two faces through it
            x = v[i] + (v[j] - v[i]) * (r.integer(1, 3) * 0.25);
            for (int f = 0; f < 4; ++f)
                if (f != i && f != j) w = w + outward(f) * double(r.integer(1, 2));
        } else { // the vertex v[i]: its three faces
            for (int f = 0; f < 4; ++f)
                if (f != i) w = w + outward(f) * double(r.integer(1, 2));
        }
        return {t, x, w};
    }
}
inline contact<point3> point_contact(rng& r) {
    const point3 p = int_point(r, 400);
    return {p, p, int_vec(r, 12)};
}
inline contact<aabb3> box_contact(rng& r) { // at a face, an edge or a corner, w pointing away on those axes
    const point3 lo = int_point(r);
    const aabb3 b{lo, lo + vec3{double(r.integer(1, 400)), double(r.integer(1, 400)), double(r.integer(1, 400))}};
    const vec3 u = int_vec(r, 6);
    const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z}, uc[3] = {u.x, u.y, u.z};
    double q[3];
    for (int i = 0; i < 3; ++i) q[i] = uc[i] > 0 ? mx[i] : (uc[i] < 0 ? mn[i] : std::floor((mn[i] + mx[i]) / 2));
    return {b, point3{q[0], q[1], q[2]}, u};
}
template <class S, class F>
struct ball_contact { // near_boundary for S and a ball, from F's contact
    static std::pair<S, sphere3> touching(rng& r) {
        const auto c = F{}(r);
        return {c.shape, ball_at(r, c.x, c.w)};
    }
};
struct segment_contact_f {
    contact<segment3> operator()(rng& r) const { return segment_contact(r); }
};
struct line_contact_f {
    contact<line3> operator()(rng& r) const { return line_contact(r); }
};
struct plane_contact_f {
    contact<plane3> operator()(rng& r) const { return plane_contact(r); }
};
struct triangle_contact_f {
    contact<triangle3> operator()(rng& r) const { return triangle_contact(r); }
};
struct tetrahedron_contact_f {
    contact<tetrahedron3> operator()(rng& r) const { return tetrahedron_contact(r); }
};
template <>
struct near_boundary<segment3, sphere3> : ball_contact<segment3, segment_contact_f> {};
template <>
struct near_boundary<line3, sphere3> : ball_contact<line3, line_contact_f> {};
template <>
struct near_boundary<plane3, sphere3> : ball_contact<plane3, plane_contact_f> {};
template <>
struct near_boundary<sphere3, triangle3> {
    static std::pair<sphere3, triangle3> touching(rng& r) {
        const auto c = triangle_contact(r);
        return {ball_at(r, c.x, c.w), c.shape};
    }
};
template <>
struct near_boundary<sphere3, tetrahedron3> {
    static std::pair<sphere3, tetrahedron3> touching(rng& r) {
        const auto c = tetrahedron_contact(r);
        return {ball_at(r, c.x, c.w), c.shape};
    }
};
// A capsule grown from a ball touching the partner (capsule_at); a ball or capsule partner: the
// point or segment where it touched with half the radius, the capsule the other half (exact).
template <class B>
struct near_boundary<capsule3, B> {
    static std::pair<capsule3, B> touching(rng& r) {
        if constexpr (std::is_same_v<B, sphere3> || std::is_same_v<B, capsule3>) {
            const auto c = [&] {
                if constexpr (std::is_same_v<B, sphere3>) return point_contact(r);
                else return segment_contact(r);
            }();
            capsule3 k = capsule_at(r, c.x, c.w);
            k.radius *= 0.5;
            if constexpr (std::is_same_v<B, sphere3>) return {k, sphere3{c.shape, k.radius}};
            else return {k, capsule3{c.shape.a, c.shape.b, k.radius}};
        } else if constexpr (std::is_same_v<B, ray3>) { // along a touched segment, beyond its end
            const auto c = segment_contact(r);
            return {capsule_at(r, c.x, c.w), ray3{c.shape.a, c.shape.b - c.shape.a}};
        } else {
            const auto c = [&] {
                if constexpr (std::is_same_v<B, point3>) return point_contact(r);
                else if constexpr (std::is_same_v<B, segment3>) return segment_contact(r);
                else if constexpr (std::is_same_v<B, line3>) return line_contact(r);
                else if constexpr (std::is_same_v<B, plane3>) return plane_contact(r);
                else if constexpr (std::is_same_v<B, triangle3>) return triangle_contact(r);
                else return tetrahedron_contact(r);
            }();
            return {capsule_at(r, c.x, c.w), c.shape};
        }
    }
};
template <>
struct near_boundary<aabb3, capsule3> {
    static std::pair<aabb3, capsule3> touching(rng& r) {
        const auto c = box_contact(r);
        return {c.shape, capsule_at(r, c.x, c.w)};
    }
};
template <>
struct near_boundary<capsule3, obb3> {
    static std::pair<capsule3, obb3> touching(rng& r) { // grown from a ball touching at p along o
        const auto t = touching_obb(r);
        return {capsule_at(r, t.p, t.o), t.box};
    }
};
template <>
struct near_boundary<aabb3, obb3> {
    static std::pair<aabb3, obb3> touching(rng& r) { // the box in the octant of o at p
        const auto t = touching_obb(r);
        const vec3 w{double(r.integer(1, 256)), double(r.integer(1, 256)), double(r.integer(1, 256))};
        const point3 q{t.p.x + (t.o.x >= 0 ? w.x : -w.x), t.p.y + (t.o.y >= 0 ? w.y : -w.y), t.p.z + (t.o.z >= 0 ? w.z : -w.z)};
        return {tidy(aabb3{t.p, q}), t.box};
    }
};
template <>
struct near_boundary<obb3, obb3> {
    static std::pair<obb3, obb3> touching(rng& r) { // a box of the same frame, corner to corner beyond p
        const auto t = touching_obb(r);
        obb3 b{t.p, t.box.axes, {double(r.integer(1, 256)), double(r.integer(1, 256)), double(r.integer(1, 256))}};
        for (unsigned i = 0; i < 3; ++i) {
            const double s = dot(t.o, t.box.axes[i]) > 0 ? 1.0 : (dot(t.o, t.box.axes[i]) < 0 ? -1.0 : 0.0);
            b.center = b.center + t.box.axes[i] * (s * b.half_extents[i]);
        }
        return r.coin() ? std::pair{t.box, b} : std::pair{b, t.box};
    }
};
template <>
struct near_boundary<obb3, segment3> {
    static std::pair<obb3, segment3> touching(rng& r) { // from p outwards
        const auto t = touching_obb(r);
        const point3 q = t.p + t.o * double(r.integer(1, 200)) + int_vec(r, 40);
        return {t.box, r.coin() ? segment3{t.p, q} : segment3{q, t.p}};
    }
};
template <>
struct near_boundary<obb3, ray3> {
    static std::pair<obb3, ray3> touching(rng& r) { // aimed at p from outside
        const auto t = touching_obb(r);
        const point3 o = t.p + t.o * double(r.integer(1, 200)) + int_vec(r, 40);
        return {t.box, ray3{o, t.p - o}};
    }
};
template <>
struct near_boundary<line3, obb3> {
    static std::pair<line3, obb3> touching(rng& r) { // through p, across the outward direction
        const auto t = touching_obb(r);
        vec3 d = cross(t.o, int_vec(r, 8));
        if (d.x == 0 && d.y == 0 && d.z == 0) d = t.o;
        return {line3{t.p, d}, t.box};
    }
};
template <>
struct near_boundary<obb3, triangle3> {
    static std::pair<obb3, triangle3> touching(rng& r) { // a vertex at p, the rest outwards
        const auto t = touching_obb(r);
        for (;;) {
            const triangle3 u{t.p, t.p + t.o * double(r.integer(1, 200)) + int_vec(r, 100),
                              t.p + t.o * double(r.integer(1, 200)) + int_vec(r, 100)};
            const vec3 n = cross(u.b - u.a, u.c - u.a);
            if (dot(n, n) > 1e4) return {t.box, u};
        }
    }
};
template <>
struct near_boundary<obb3, plane3> {
    static std::pair<obb3, plane3> touching(rng& r) { // the supporting plane at p, normal o
        const auto t = touching_obb(r);
        return {t.box, plane3{t.o, dot(t.o, t.p - point3{0, 0, 0})}};
    }
};

// The flat pairs (points, lines, rays, segments, planes, triangles): both shapes through one
// integer point X, each with X on its own boundary (a segment's end, a ray's origin or a point it
// is aimed at, a line through it, a plane through it, a triangle's vertex or edge point), so the
// pair touches exactly at X; a move of 2^-k takes them apart (or, for a plane, across).
// A tetrahedron has X at a vertex, an edge point or a face point (a box: at a corner, an edge or
// face point), so the other shape passes through its boundary there.
template <class S>
concept flat_shape = std::is_same_v<S, point3> || std::is_same_v<S, segment3> || std::is_same_v<S, ray3> || std::is_same_v<S, line3> ||
                     std::is_same_v<S, plane3> || std::is_same_v<S, triangle3> || std::is_same_v<S, tetrahedron3>;
inline tetrahedron3 int_tetrahedron(rng& r) {
    for (;;) {
        const point3 a = int_point(r, 400);
        const tetrahedron3 t{a, a + int_vec(r, 400), a + int_vec(r, 400), a + int_vec(r, 400)};
        if (std::fabs(dot(cross(t.b - t.a, t.c - t.a), t.d - t.a)) > 1e6) return t;
    }
}
inline point3 boundary_point(const tetrahedron3& t, rng& r) {
    const triangle3 f = t.face(r.integer(0, 3));
    const int w = r.integer(0, 2);
    if (w == 0) return boundary_point(f, r);                    // a vertex or an edge point
    return f.a + (f.b - f.a) * 0.25 + (f.c - f.a) * (w * 0.25); // inside the face
}
template <class S>
S through(rng& r, point3 X) {
    const vec3 d = int_vec(r, 300);
    if constexpr (std::is_same_v<S, point3>) return X;
    else if constexpr (std::is_same_v<S, segment3>) return r.coin() ? segment3{X, X + d} : segment3{X + d, X};
    else if constexpr (std::is_same_v<S, ray3>) return r.coin() ? ray3{X, d} : ray3{X - d, d};
    else if constexpr (std::is_same_v<S, line3>) return line3{X - d * double(r.integer(0, 3)), d};
    else if constexpr (std::is_same_v<S, plane3>) {
        const vec3 n = int_vec(r, 6);
        return plane3{n, dot(n, X - point3{0, 0, 0})};
    } else if constexpr (std::is_same_v<S, tetrahedron3>) {
        const tetrahedron3 t = int_tetrahedron(r);
        return moved(t, X - boundary_point(t, r));
    } else {
        const triangle3 t = int_triangle(r);
        return moved(t, X - boundary_point(t, r));
    }
}
// In the plane: the same, through one integer point X.
template <class S>
concept flat2_shape = std::is_same_v<S, point2> || std::is_same_v<S, segment2> || std::is_same_v<S, ray2> || std::is_same_v<S, line2>;
template <class S>
S through2(rng& r, point2 X) {
    vec2 d{double(r.integer(-300, 300)), double(r.integer(-300, 300))};
    if (d.x == 0 && d.y == 0) d = {1, 0};
    if constexpr (std::is_same_v<S, point2>) return X;
    else if constexpr (std::is_same_v<S, segment2>) return r.coin() ? segment2{X, X + d} : segment2{X + d, X};
    else if constexpr (std::is_same_v<S, ray2>) return r.coin() ? ray2{X, d} : ray2{X - d, d};
    else return line2{X - double(r.integer(0, 3)) * d, d};
}
template <class A, class B>
requires(flat2_shape<A> && flat2_shape<B>)
struct near_boundary<A, B> {
    static std::pair<A, B> touching(rng& r) {
        const point2 X{double(r.integer(-400, 400)), double(r.integer(-400, 400))};
        const A a = through2<A>(r, X);
        return {a, through2<B>(r, X)};
    }
};
// A disk touching b at X from across it: centre X + k w and radius 5k for a 3-4-5 step w (exact);
// a partner disk on the other side, of radius 5 k2 around X - k2 w; a segment, ray or line along w
// turned, through X.
template <class B>
requires(flat2_shape<B> || std::is_same_v<B, circle2>)
struct near_boundary<circle2, B> {
    static std::pair<circle2, B> touching(rng& r) {
        const point2 X{double(r.integer(-400, 400)), double(r.integer(-400, 400))};
        double x = 3, y = 4;
        if (r.coin()) std::swap(x, y);
        const vec2 w{r.coin() ? -x : x, r.coin() ? -y : y}, d{-w.y, w.x};
        const double k = r.integer(1, 60);
        const circle2 c{X + k * w, 5 * k};
        if constexpr (std::is_same_v<B, circle2>) {
            const double k2 = r.integer(0, 60);
            return {c, circle2{X - k2 * w, 5 * k2}};
        } else if constexpr (std::is_same_v<B, point2>) {
            return {c, X};
        } else {
            const double before = r.integer(1, 4), after = r.integer(1, 4);
            if constexpr (std::is_same_v<B, segment2>) return {c, segment2{X - before * d, X + after * d}};
            else if constexpr (std::is_same_v<B, ray2>) return {c, ray2{X - before * d, d}};
            else return {c, line2{X - before * d, d}};
        }
    }
};
template <class A, class B>
requires(flat_shape<A> && flat_shape<B>)
struct near_boundary<A, B> {
    static std::pair<A, B> touching(rng& r) {
        const point3 X = int_point(r, 400);
        const A a = through<A>(r, X);
        return {a, through<B>(r, X)};
    }
};

template <>
struct near_boundary<aabb3, tetrahedron3> {
    static std::pair<aabb3, tetrahedron3> touching(rng& r) {
        const auto [b, p] = near_boundary<aabb3, point3>::touching(r);
        const tetrahedron3 t = int_tetrahedron(r);
        return {b, moved(t, p - boundary_point(t, r))};
    }
};
template <>
struct near_boundary<obb3, tetrahedron3> {
    static std::pair<obb3, tetrahedron3> touching(rng& r) {
        const auto [b, p] = near_boundary<obb3, point3>::touching(r);
        const tetrahedron3 t = int_tetrahedron(r);
        return {b, moved(t, p - boundary_point(t, r))};
    }
};

// The k-DOP pairs (K = 14 stands for every K): the 14-DOP of a few integer points, so every bound
// is exact and attained; p the cloud's extreme point along one direction d_s (on that face) and
// d_s the outward direction there.
inline double dot_dir(direction3 d, vec3 v) { return d.x * v.x + d.y * v.y + d.z * v.z; }
inline kdop<14> kdop_of_points(const point3* pts, int n) {
    const auto d = kdop<14>::directions();
    kdop<14> b{};
    for (unsigned i = 0; i < d.size(); ++i) {
        b.min[i] = b.max[i] = dot_dir(d[i], pts[0] - point3{0, 0, 0});
        for (int j = 1; j < n; ++j) {
            const double v = dot_dir(d[i], pts[j] - point3{0, 0, 0}); // exact: small integers
            b.min[i] = std::min(b.min[i], v), b.max[i] = std::max(b.max[i], v);
        }
    }
    return b;
}
struct kdop_touch {
    kdop<14> box;
    point3 p;
    direction3 ds;
    vec3 o; // d_s as a vector
};
inline kdop_touch touching_kdop(rng& r) {
    const point3 c = int_point(r, 400);
    point3 pts[8];
    const int n = r.integer(4, 8);
    for (int i = 0; i < n; ++i) pts[i] = c + int_vec(r, 300);
    const direction3 ds = kdop<14>::directions()[static_cast<unsigned>(r.integer(0, 6))];
    point3 X = pts[0];
    for (int i = 1; i < n; ++i)
        if (dot_dir(ds, pts[i] - X) > 0) X = pts[i];
    return {kdop_of_points(pts, n), X, ds, vec3{double(ds.x), double(ds.y), double(ds.z)}};
}
// An integer vector w with d_s . w >= 0 (outwards or along the face).
inline vec3 outward(rng& r, const kdop_touch& t, int lim) {
    const vec3 w = int_vec(r, lim);
    return dot_dir(t.ds, w) < 0 ? w * -1.0 : w;
}
template <>
struct near_boundary<kdop<14>, point3> {
    static std::pair<kdop<14>, point3> touching(rng& r) {
        const auto t = touching_kdop(r);
        return {t.box, t.p};
    }
};
template <>
struct near_boundary<kdop<14>, segment3> {
    static std::pair<kdop<14>, segment3> touching(rng& r) { // from p outwards
        const auto t = touching_kdop(r);
        const point3 q = t.p + t.o * double(r.integer(1, 200)) + outward(r, t, 40);
        return {t.box, r.coin() ? segment3{t.p, q} : segment3{q, t.p}};
    }
};
template <>
struct near_boundary<kdop<14>, ray3> {
    static std::pair<kdop<14>, ray3> touching(rng& r) { // aimed at p from outside
        const auto t = touching_kdop(r);
        const point3 o = t.p + t.o * double(r.integer(1, 200)) + outward(r, t, 40);
        return {t.box, ray3{o, t.p - o}};
    }
};
template <>
struct near_boundary<kdop<14>, line3> {
    static std::pair<kdop<14>, line3> touching(rng& r) { // through p, in the face's plane
        const auto t = touching_kdop(r);
        vec3 d = cross(t.o, int_vec(r, 8));
        if (d.x == 0 && d.y == 0 && d.z == 0) d = cross(t.o, vec3{1, 2, 3});
        return {t.box, line3{t.p, d}};
    }
};
template <>
struct near_boundary<kdop<14>, plane3> {
    static std::pair<kdop<14>, plane3> touching(rng& r) { // the face's plane through p, either orientation
        const auto t = touching_kdop(r);
        const vec3 n = t.o * (r.coin() ? double(r.integer(1, 3)) : -double(r.integer(1, 3)));
        return {t.box, plane3{n, dot(n, t.p - point3{0, 0, 0})}};
    }
};
template <>
struct near_boundary<kdop<14>, kdop<14>> {
    static std::pair<kdop<14>, kdop<14>> touching(rng& r) { // a cloud from p outwards, p included
        const auto t = touching_kdop(r);
        point3 q[8];
        const int n = r.integer(3, 8);
        q[0] = t.p;
        for (int i = 1; i < n; ++i) q[i] = t.p + outward(r, t, 300);
        return {t.box, kdop_of_points(q, n)};
    }
};
template <>
struct near_boundary<kdop<14>, triangle3> {
    static std::pair<kdop<14>, triangle3> touching(rng& r) { // a corner at p, the others outwards
        const auto t = touching_kdop(r);
        return {t.box, triangle3{t.p, t.p + outward(r, t, 300), t.p + outward(r, t, 300)}};
    }
};
template <>
struct near_boundary<kdop<14>, tetrahedron3> {
    static std::pair<kdop<14>, tetrahedron3> touching(rng& r) { // a vertex at p, the others outwards
        const auto t = touching_kdop(r);
        return {t.box, tetrahedron3{t.p, t.p + outward(r, t, 300), t.p + outward(r, t, 300), t.p + outward(r, t, 300)}};
    }
};
template <>
struct near_boundary<kdop<14>, obb3> {
    static std::pair<kdop<14>, obb3> touching(rng& r) { // a box with a corner, an edge or face point at p, outwards
        const auto t = touching_kdop(r);
        return {t.box, obb_beyond(r, t.p, t.o)};
    }
};
template <>
struct near_boundary<kdop<14>, sphere3> {
    static std::pair<kdop<14>, sphere3> touching(rng& r) { // centred out along d_s, its radius the distance (rounded)
        const auto t = touching_kdop(r);
        const double k = r.integer(1, 200);
        return {t.box, sphere3{t.p + t.o * k, k * std::sqrt(dot(t.o, t.o))}};
    }
};
template <>
struct near_boundary<aabb3, kdop<14>> {
    static std::pair<aabb3, kdop<14>> touching(rng& r) { // a box with its corner at p, outwards
        const auto t = touching_kdop(r);
        const double s[3] = {double(t.ds.x), double(t.ds.y), double(t.ds.z)};
        double lo[3] = {t.p.x, t.p.y, t.p.z}, hi[3] = {t.p.x, t.p.y, t.p.z};
        for (int i = 0; i < 3; ++i) {
            const double e = r.integer(1, 300);
            const bool up = s[i] > 0 || (s[i] == 0 && r.coin());
            (up ? hi[i] : lo[i]) += up ? e : -e;
        }
        return {aabb3{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}, t.box};
    }
};

// The half-space pairs: planes with small integer normals (components in -3..3) through the
// extreme points of a few integer points along them, so every offset is exact and attained
// (convex_polyhedron3); or an axis-aligned frustum of integer slopes q / p (p in {1, 2, 4}) with
// its eye and clip distances multiples of 4, so its corners are integers (frustum3). p is a
// boundary point (an extreme point, a corner or an edge midpoint) and o the outward normal of a
// face through it. A plane moves by offset + n . v (rounded: the moved shape is the one its planes
// say) and scales by 2^e in its offset alone.
inline convex_polyhedron3 moved(convex_polyhedron3 c, vec3 v) {
    for (int i = 0; i < c.count; ++i) c.planes[static_cast<unsigned>(i)] = moved(c.planes[static_cast<unsigned>(i)], v);
    return c;
}
inline frustum3 moved(frustum3 f, vec3 v) {
    for (auto& p : f.planes) p = moved(p, v);
    return f;
}
inline convex_polyhedron3 scaled(convex_polyhedron3 c, int e) {
    for (int i = 0; i < c.count; ++i) c.planes[static_cast<unsigned>(i)] = scaled(c.planes[static_cast<unsigned>(i)], e);
    return c;
}
inline frustum3 scaled(frustum3 f, int e) {
    for (auto& p : f.planes) p = scaled(p, e);
    return f;
}
inline convex_polyhedron3 nudged(convex_polyhedron3 c, int ulps, rng& r) { // one number of one live plane
    auto& p = c.planes[static_cast<unsigned>(r.integer(0, c.count - 1))];
    p = nudged(p, ulps, r);
    return c;
}
template <class P>
struct halfspace_touch {
    P shape;
    point3 p;
    vec3 o;
};
inline halfspace_touch<convex_polyhedron3> touching_polyhedron(rng& r) {
    const point3 c = int_point(r, 400);
    point3 pts[8];
    const int n = r.integer(4, 8);
    for (int i = 0; i < n; ++i) pts[i] = c + int_vec(r, 300);
    convex_polyhedron3 h{};
    h.count = r.integer(4, 12);
    for (int i = 0; i < h.count; ++i) {
        vec3 d = int_vec(r, 3);
        if (d.x == 0 && d.y == 0 && d.z == 0) d = vec3{0, 0, 1};
        point3 X = pts[0];
        for (int j = 1; j < n; ++j)
            if (dot(d, pts[j] - X) > 0) X = pts[j];
        h.planes[static_cast<unsigned>(i)] = plane3{d, dot(d, X - point3{0, 0, 0})}; // exact: small integers
    }
    const auto s = static_cast<unsigned>(r.integer(0, h.count - 1));
    point3 X = pts[0];
    for (int j = 1; j < n; ++j)
        if (dot(h.planes[s].normal, pts[j] - X) > 0) X = pts[j];
    return {h, X, h.planes[s].normal};
}
inline halfspace_touch<frustum3> touching_frustum(rng& r) {
    const int k = r.integer(0, 2);
    const vec3 ax[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    auto sgn = [&] { return r.coin() ? 1.0 : -1.0; };
    const vec3 f = ax[k] * sgn(), rt = ax[(k + 1) % 3] * sgn(), up = ax[(k + 2) % 3] * sgn();
    const point3 E = int_point(r, 400);
    static constexpr double ps[] = {1, 2, 4};
    double q[4], p[4];
    for (int i = 0; i < 4; ++i) q[i] = r.integer(1, 3), p[i] = ps[r.integer(0, 2)];
    const double zn = 4.0 * r.integer(1, 30), zf = zn + 4.0 * r.integer(1, 60);
    const vec3 e = E - point3{0, 0, 0};
    auto through = [&](vec3 n, point3 x) { return plane3{n, dot(n, x - point3{0, 0, 0})}; };
    const frustum3 fr{{through(-f, E + f * zn), through(f, E + f * zf), plane3{-rt * p[0] - f * q[0], dot(-rt * p[0] - f * q[0], e)},
                       plane3{rt * p[1] - f * q[1], dot(rt * p[1] - f * q[1], e)},
                       plane3{-up * p[2] - f * q[2], dot(-up * p[2] - f * q[2], e)},
                       plane3{up * p[3] - f * q[3], dot(up * p[3] - f * q[3], e)}}};
    const double z = r.coin() ? zn : zf;
    const bool right = r.coin(), top = r.coin();
    const point3 corner = E + f * z + rt * (right ? q[1] * z / p[1] : -q[0] * z / p[0]) + up * (top ? q[3] * z / p[3] : -q[2] * z / p[2]);
    const unsigned face = r.integer(0, 1) == 0 ? (z == zn ? 0u : 1u) : (right ? 3u : 2u);
    return {fr, corner, fr.planes[face].normal};
}
template <class P>
halfspace_touch<P> touching_halfspaces(rng& r) {
    if constexpr (std::is_same_v<P, frustum3>) return touching_frustum(r);
    else return touching_polyhedron(r);
}
// An integer vector w with o . w >= 0 (outwards or along the face).
inline vec3 outward(rng& r, vec3 o, int lim) {
    const vec3 w = int_vec(r, lim);
    return dot(o, w) < 0 ? w * -1.0 : w;
}
template <class P, class B>
requires(std::is_same_v<P, convex_polyhedron3> || std::is_same_v<P, frustum3>)
struct near_boundary<P, B> {
    static std::pair<P, B> touching(rng& r) {
        const auto t = touching_halfspaces<P>(r);
        if constexpr (std::is_same_v<B, point3>) return {t.shape, t.p};
        else if constexpr (std::is_same_v<B, segment3>) { // from p outwards
            const point3 q = t.p + t.o * double(r.integer(1, 60)) + outward(r, t.o, 40);
            return {t.shape, r.coin() ? segment3{t.p, q} : segment3{q, t.p}};
        } else if constexpr (std::is_same_v<B, ray3>) { // aimed at p from outside
            const point3 o = t.p + t.o * double(r.integer(1, 60)) + outward(r, t.o, 40);
            return {t.shape, ray3{o, t.p - o}};
        } else if constexpr (std::is_same_v<B, aabb3>) { // corner p, every point on the face or outside it
            auto side = [&](double o) { return (o > 0 ? 1.0 : (o < 0 ? -1.0 : (r.coin() ? 1.0 : -1.0))) * double(r.integer(1, 40)); };
            const point3 q = t.p + vec3{side(t.o.x), side(t.o.y), side(t.o.z)};
            return {t.shape, aabb3{{std::min(t.p.x, q.x), std::min(t.p.y, q.y), std::min(t.p.z, q.z)},
                                   {std::max(t.p.x, q.x), std::max(t.p.y, q.y), std::max(t.p.z, q.z)}}};
        } else if constexpr (std::is_same_v<B, convex_polyhedron3>) {
            // the supporting planes of an integer cloud from p outwards (p included), and two times
            // in three the face's opposite half-space through p: touching at p at least
            point3 pts[8];
            const int n = r.integer(3, 8);
            pts[0] = t.p;
            for (int i = 1; i < n; ++i) pts[i] = t.p + outward(r, t.o, 300);
            convex_polyhedron3 q{};
            q.count = r.integer(4, 10);
            for (int i = 0; i < q.count; ++i) {
                const vec3 d = int_vec(r, 3);
                double top = dot(d, pts[0] - point3{0, 0, 0});
                for (int j = 1; j < n; ++j) top = std::max(top, dot(d, pts[j] - point3{0, 0, 0})); // exact: integers
                q.planes[static_cast<unsigned>(i)] = plane3{d, top};
            }
            if (r.integer(0, 2) != 0) q.planes[static_cast<unsigned>(q.count++)] = plane3{-t.o, -dot(t.o, t.p - point3{0, 0, 0})};
            return {t.shape, q};
        } else if constexpr (std::is_same_v<B, triangle3>) { // a corner at p, the others outwards
            return {t.shape, triangle3{t.p, t.p + outward(r, t.o, 300), t.p + outward(r, t.o, 300)}};
        } else if constexpr (std::is_same_v<B, obb3>) { // a box with a corner, an edge or face point at p, outwards
            return {t.shape, obb_beyond(r, t.p, t.o)};
        } else if constexpr (std::is_same_v<B, tetrahedron3>) { // a vertex at p, the others outwards
            return {t.shape, tetrahedron3{t.p, t.p + outward(r, t.o, 300), t.p + outward(r, t.o, 300), t.p + outward(r, t.o, 300)}};
        } else if constexpr (std::is_same_v<B, frustum3> && std::is_same_v<P, frustum3>) {
            // the frustum reflected through its corner p (x -> 2p - x, exact: integers): the two
            // touch at p only
            frustum3 g = t.shape;
            for (auto& h : g.planes) h = plane3{h.normal * -1.0, h.offset - 2 * dot(h.normal, t.p - point3{0, 0, 0})};
            return {t.shape, g};
        } else if constexpr (std::is_same_v<B, kdop<14>>) {
            // the 14-DOP of an integer cloud from p outwards, p included two times in three (else
            // the cloud starts one step out): touching at p, or whether the slabs reach the face
            point3 pts[8];
            const int n = r.integer(3, 8);
            pts[0] = r.integer(0, 2) != 0 ? t.p : t.p + t.o + outward(r, t.o, 2);
            for (int i = 1; i < n; ++i) pts[i] = t.p + outward(r, t.o, 300);
            return {t.shape, kdop_of_points(pts, n)};
        } else if constexpr (std::is_same_v<B, plane3>) { // the face's plane through p, either orientation
            const vec3 n = t.o * (r.coin() ? double(r.integer(1, 3)) : -double(r.integer(1, 3)));
            return {t.shape, plane3{n, dot(n, t.p - point3{0, 0, 0})}};
        } else if constexpr (std::is_same_v<B, sphere3>) { // centred out along the face normal, its radius the distance (rounded)
            const double k = r.integer(1, 60);
            return {t.shape, sphere3{t.p + t.o * k, k * std::sqrt(dot(t.o, t.o))}};
        } else { // through p, in the face's plane
            vec3 d = cross(t.o, int_vec(r, 8));
            if (d.x == 0 && d.y == 0 && d.z == 0) d = cross(t.o, vec3{1, 2, 3});
            return {t.shape, line3{t.p, d}};
        }
    }
};
// A capsule grown from a ball touching a half-space set or a k-DOP at p along its face's normal
// (capsule_at): the capsule first, as in the catalog.
template <class P>
requires(std::is_same_v<P, convex_polyhedron3> || std::is_same_v<P, frustum3>)
struct near_boundary<capsule3, P> {
    static std::pair<capsule3, P> touching(rng& r) {
        const auto t = touching_halfspaces<P>(r);
        return {capsule_at(r, t.p, t.o), t.shape};
    }
};
template <>
struct near_boundary<capsule3, kdop<14>> {
    static std::pair<capsule3, kdop<14>> touching(rng& r) {
        const auto t = touching_kdop(r);
        return {capsule_at(r, t.p, t.o), t.box};
    }
};
template <>
struct near_boundary<convex_polyhedron3, frustum3> { // the polyhedron first, as in the catalog
    static std::pair<convex_polyhedron3, frustum3> touching(rng& r) {
        const auto [f, c] = near_boundary<frustum3, convex_polyhedron3>::touching(r);
        return {c, f};
    }
};
template <class P>
requires(std::is_same_v<P, convex_polyhedron3> || std::is_same_v<P, frustum3>)
struct near_boundary<aabb3, P> { // the box first, as in the catalog
    static std::pair<aabb3, P> touching(rng& r) {
        const auto [p, b] = near_boundary<P, aabb3>::touching(r);
        return {b, p};
    }
};

// The coordinate settings: offset from the origin (in object sizes) and scale 2^e.
struct setting {
    double offset; // added to every point, before scaling (exact: an integer)
    int scale_exp;
};
inline constexpr setting settings[] = {{0, 0}, {0, -300}, {0, 300}, {1 << 20, 0}, {1 << 20, -300}, {1 << 20, 300}};
inline constexpr unsigned setting_count = sizeof(settings) / sizeof(settings[0]);
inline constexpr int separation_levels = 61; // k = 0..60
inline constexpr int ulp_levels = 9;         // j = 0..8
// level index: 0..60 separation 2^-k, 61..69 ulp perturbation j = index - 61
inline constexpr int level_count = separation_levels + ulp_levels;

// One case of family (A, B) at a level and setting.
template <class A, class B>
std::pair<A, B> make_case(rng& r, int level, const setting& s) {
    auto [a, b] = near_boundary<A, B>::touching(r);
    const vec3 off{s.offset * base_size, -s.offset * base_size, s.offset * base_size};
    a = moved(a, off);
    b = moved(b, off);
    if (level < separation_levels) {
        b = tidy(moved(b, random_unit(r) * std::ldexp(base_size, -level)));
    } else {
        const int j = level - separation_levels;
        if (r.coin()) a = nudged(a, j, r);
        else b = nudged(b, j, r);
    }
    return {scaled(a, s.scale_exp), scaled(b, s.scale_exp)};
}

} // namespace audit
