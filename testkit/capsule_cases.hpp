// Cases for a capsule against a shape (capsule_point, capsule_sphere, capsule_capsule,
// capsule_segment, capsule_ray, capsule_line, capsule_plane, capsule_triangle,
// capsule_tetrahedron, aabb_capsule); the checks are in capsule_checks.hpp. Include after
// testing.hpp and the CGAL oracle header.
//
// Near-degenerate: the partner in small dyadics as rows whose normal cone at each spot is its own
// (flat_rows of ball_halfspace_cases.hpp; a box its six face rows; a point or a ball the six axis
// rows, so any direction), a ball touching it at a spot (ball_touching: centre c = X + t w with w
// in the normal cone at X, radius t |w|, exact where |w| is an integer, else rounded; kept, nudged,
// moved, halved, doubled or zero; the centre at X or inside one time in eight), grown into a capsule
// from c to c + v with v . w >= 0 (a small dyadic v, zero one time in six: a ball), so that its
// segment keeps the ball's distance. A ball or capsule partner takes half the radius (the
// partner's centre or segment where the ball touched) and the capsule the other half. Then one
// random exact-or-nudged scale 2^-500..2^500 and translation for both.
// Random: the partner of random_shape (a ball or a capsule: centre or ends in [-1, 1]^3, radius up
// to 1/2), a capsule from a point within 1.5 of the origin along a vector in [-1, 1]^3, radius up to
// 1/2, at one random scale.
#pragma once
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include "ball_halfspace_cases.hpp"
#include "contain_cases.hpp"
#include "flat_shapes.hpp"

namespace support {

inline std::string shape_str(const incidence::capsule3& c) {
    const auto pt = [](incidence::point3 p) { return "(" + hex(p.x) + "," + hex(p.y) + "," + hex(p.z) + ")"; };
    return "capsule " + pt(c.a) + " " + pt(c.b) + " " + hex(c.radius);
}

// The partner's core as the QP oracle's convex set, and its radius.
inline std::pair<oracle::convex_set, double> core_of(const incidence::sphere3& s) { return {lp(s.center), s.radius}; }
inline std::pair<oracle::convex_set, double> core_of(const incidence::capsule3& c) { return {lp(incidence::segment3{c.a, c.b}), c.radius}; }
template <class B>
std::pair<oracle::convex_set, double> core_of(const B& b) {
    return {lp(b), 0.0};
}

inline incidence::capsule3 realise(const incidence::capsule3& c, transform& tr) {
    return {moved(c.a, tr), moved(c.b, tr), tr.scale_only(c.radius)};
}
inline incidence::sphere3 realise(const incidence::sphere3& s, transform& tr) { return {moved(s.center, tr), tr.scale_only(s.radius)}; }

// Rows through x along the six axis directions: every direction is in their normal cone at x.
inline proto_rows axis_rows(incidence::point3 x) {
    using namespace incidence;
    proto_rows p;
    for (const vec3 n : {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}})
        for (const double s : {1.0, -1.0}) add_row(p, n * s, x);
    p.spots = {x};
    return p;
}

template <class B>
std::optional<std::pair<incidence::capsule3, B>> capsule_near(rng& r) {
    using namespace incidence;
    proto_rows rows;
    typename proto_of<B>::type partner{};
    bool halves = false; // a ball or a capsule partner: half the radius each
    if constexpr (std::is_same_v<B, point3> || std::is_same_v<B, sphere3>) {
        const point3 x = small_point(r);
        rows = axis_rows(x);
        if constexpr (std::is_same_v<B, point3>) partner = x;
        else partner = sphere3{x, 0.0}, halves = true;
    } else if constexpr (std::is_same_v<B, capsule3> || std::is_same_v<B, ray3>) {
        const auto f = flat_rows<segment3>(r); // a ray: its origin and a point along it
        rows = f.rows;
        if constexpr (std::is_same_v<B, capsule3>) partner = capsule3{f.shape.a, f.shape.b, 0.0}, halves = true;
        else partner = ray3{f.shape.a, f.shape.b - f.shape.a};
    } else if constexpr (std::is_same_v<B, aabb3>) {
        const obb3 b{small_point(r),
                     {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}},
                     {r.integer(0, 8) * 0.5, r.integer(0, 8) * 0.5, r.integer(0, 8) * 0.5}};
        rows = box_rows(b);
        const vec3 h{b.half_extents[0], b.half_extents[1], b.half_extents[2]};
        partner = aabb3{b.center - h, b.center + h};
    } else {
        const auto f = flat_rows<B>(r);
        rows = f.rows;
        partner = f.shape;
    }
    vec3 w{0, 0, 0};
    const sphere3 ball = ball_touching(r, rows, &w);
    vec3 v = small_dir(r) * 0.5;
    if (dot(v, w) < 0) v = v * -1.0;
    if (r.integer(0, 5) == 0) v = vec3{0, 0, 0};
    capsule3 c{ball.center, ball.center + v, ball.radius};
    if (halves) {
        c.radius = ball.radius * 0.5;
        if constexpr (std::is_same_v<B, sphere3> || std::is_same_v<B, capsule3>) partner.radius = ball.radius * 0.5;
    }
    transform tr = random_transform(r, true, true);
    const capsule3 m = realise(c, tr);
    const B b = realise(partner, tr);
    if (!is_finite(m.a) || !is_finite(m.b) || !std::isfinite(m.radius)) return std::nullopt;
    if constexpr (std::is_same_v<B, sphere3>) {
        if (!is_finite(b.center) || !std::isfinite(b.radius)) return std::nullopt;
    } else if constexpr (std::is_same_v<B, capsule3>) {
        if (!is_finite(b.a) || !is_finite(b.b) || !std::isfinite(b.radius)) return std::nullopt;
    } else if (!finite_shape(b)) {
        return std::nullopt;
    }
    return std::pair{m, b};
}

template <class B>
std::optional<std::pair<incidence::capsule3, B>> capsule_random(rng& r) {
    using namespace incidence;
    transform tr = random_transform(r, false, true);
    auto p = [&] { return point3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}; };
    B b;
    if constexpr (std::is_same_v<B, sphere3>) b = realise(sphere3{p(), r.uniform(0, 0.5)}, tr);
    else if constexpr (std::is_same_v<B, capsule3>) b = realise(capsule3{p(), p(), r.uniform(0, 0.5)}, tr);
    else b = realise(random_shape<B>(r, false, 0.0), tr);
    const point3 a{r.uniform(-1.5, 1.5), r.uniform(-1.5, 1.5), r.uniform(-1.5, 1.5)};
    const capsule3 c = realise(capsule3{a, a + vec3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}, r.uniform(0, 0.5)}, tr);
    if (!is_finite(c.a) || !is_finite(c.b) || !std::isfinite(c.radius)) return std::nullopt;
    const auto [core, rb] = core_of(b);
    (void)core;
    if (!std::isfinite(rb)) return std::nullopt;
    if constexpr (!std::is_same_v<B, sphere3> && !std::is_same_v<B, capsule3>)
        if (!finite_shape(b)) return std::nullopt;
    return std::pair{c, b};
}

// --- containment -------------------------------------------------------------------------------
// S from its first vertices (a point, a segment, a triangle or a tetrahedron).
template <class S>
S from_points(const std::array<incidence::point3, 4>& p) {
    using namespace incidence;
    if constexpr (std::is_same_v<S, point3>) return p[0];
    else if constexpr (std::is_same_v<S, segment3>) return segment3{p[0], p[1]};
    else if constexpr (std::is_same_v<S, triangle3>) return triangle3{p[0], p[1], p[2]};
    else return tetrahedron3{p[0], p[1], p[2], p[3]};
}
// (3m, 4m, 0) with its coordinates permuted and signed: length 5m, exactly.
inline incidence::vec3 five(rng& r, double m) {
    double c[3] = {3 * m * (r.coin() ? 1 : -1), 4 * m * (r.coin() ? 1 : -1), 0};
    for (int i = 2; i > 0; --i) std::swap(c[i], c[r.integer(0, i)]);
    return {c[0], c[1], c[2]};
}
// A ball of radius 5m around a small integer centre holding S: vertices within 5m/2 of the centre
// on each axis, one of them on the sphere one time in two; then one random exact-or-nudged scale
// and translation.
template <class S>
std::pair<incidence::sphere3, S> sphere_holding(rng& r) {
    using namespace incidence;
    const point3 c{double(r.integer(-16, 16)), double(r.integer(-16, 16)), double(r.integer(-16, 16))};
    const double m = r.integer(1, 8);
    std::array<point3, 4> p;
    for (auto& x : p) x = c + vec3{r.integer(-10, 10) * m * 0.25, r.integer(-10, 10) * m * 0.25, r.integer(-10, 10) * m * 0.25};
    if (r.coin()) p[static_cast<unsigned>(r.integer(0, 3))] = c + five(r, m);
    transform tr = random_transform(r, true, true);
    return {realise(sphere3{c, 5 * m}, tr), realise(from_points<S>(p), tr)};
}
// A capsule along a coordinate axis (length 1..8, radius 5m) holding S: vertices on its segment
// moved across by up to half the radius, one of them on the boundary one time in two (across by
// (3m, 4m), or beyond an end by 3m and across by 4m); a box spans the segment and +-3m, +-4m
// across (every corner on the cylinder), or +-3m/2 and +-4m (inside). Then one random
// exact-or-nudged scale and translation.
template <class S>
std::pair<incidence::capsule3, S> capsule_holding(rng& r) {
    using namespace incidence;
    const int axis = r.integer(0, 2);
    const auto along = [&](double t) {
        vec3 v{0, 0, 0};
        (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = t;
        return v;
    };
    const auto across = [&](double u, double w) { // in the other two coordinates
        return axis == 0 ? vec3{0, u, w} : axis == 1 ? vec3{w, 0, u} : vec3{u, w, 0};
    };
    const point3 a{double(r.integer(-16, 16)), double(r.integer(-16, 16)), double(r.integer(-16, 16))};
    const double len = r.integer(1, 8), m = r.integer(1, 4);
    const capsule3 c{a, a + along(len), 5 * m};
    transform tr = random_transform(r, true, true);
    if constexpr (std::is_same_v<S, aabb3>) {
        const double u = 3 * m * (r.integer(0, 3) == 0 ? 1.0 : 0.5), w = 4 * m; // on the cylinder one time in four
        const point3 lo = a + across(-u, -w), hi = a + along(len) + across(u, w);
        return {realise(c, tr), realise(aabb3{lo, hi}, tr)};
    } else {
        std::array<point3, 4> p;
        for (auto& x : p) x = a + along(r.integer(0, 8) * len / 8) + across(r.integer(-5, 5) * m * 0.5, r.integer(-5, 5) * m * 0.25);
        if (r.coin()) { // on the boundary: beyond an end (5m from it) or across the middle
            const double u = (r.coin() ? 3 : -3) * m, w = (r.coin() ? 4 : -4) * m;
            const point3 edge = r.coin() ? a + along(r.coin() ? -3 * m : len + 3 * m) + across(0, w) : a + along(len / 2) + across(u, w);
            p[static_cast<unsigned>(r.integer(0, 3))] = edge;
        }
        return {realise(c, tr), realise(from_points<S>(p), tr)};
    }
}
// X holding a capsule: a capsule around a ball X holds (obb_holding_ball, aabb_holding_ball, or a
// frustum with a ball touching one of its planes from either side, ball_near), its second end
// moved by a small vector one time in two (then its radius halved).
inline incidence::capsule3 capsule_from(rng& r, const incidence::sphere3& s) {
    using namespace incidence;
    if (r.coin()) return {s.center, s.center, s.radius};
    const double k = s.radius * 0.125;
    return {s.center, s.center + vec3{r.integer(-2, 2) * k, r.integer(-2, 2) * k, r.integer(-2, 2) * k}, s.radius * 0.5};
}

// The random counterparts: a random ball or capsule and a random shape (ball_random, capsule_random).
template <class S>
std::pair<incidence::sphere3, S> sphere_random_around(rng& r) {
    for (;;)
        if (const auto c = ball_random<S>(r)) return {c->second, c->first};
}
template <class S>
std::pair<incidence::capsule3, S> capsule_random_around(rng& r) {
    for (;;)
        if (const auto c = capsule_random<S>(r)) return *c;
}
template <class X>
std::pair<X, incidence::capsule3> capsule_random_inside(rng& r) {
    for (;;)
        if (const auto c = capsule_random<X>(r)) return {c->second, c->first};
}
template <class X>
std::pair<X, incidence::capsule3> capsule_inside(rng& r) {
    if constexpr (std::is_same_v<X, incidence::obb3>) {
        const auto [x, s] = obb_holding_ball(r);
        return {x, capsule_from(r, s)};
    } else {
        const auto [x, s] = aabb_holding_ball(r);
        return {x, capsule_from(r, s)};
    }
}
// The truths: every vertex within r of the capsule's segment (CGAL's squared distance over Epeck,
// oracle::ball_flat); a box around both end balls (contain_cases.hpp's contains_truth).
template <class S>
bool capsule_holds(const incidence::capsule3& c, const S& s) {
    for (const auto& p : vertices(s))
        if (!oracle::ball_flat(to_flat(incidence::segment3{c.a, c.b}), a3(p), c.radius)) return false;
    return true;
}
template <class X>
bool holds_capsule(const X& x, const incidence::capsule3& c) {
    const double r = std::fabs(c.radius);
    return contains_truth(x, incidence::sphere3{c.a, r}) && contains_truth(x, incidence::sphere3{c.b, r});
}

} // namespace support
