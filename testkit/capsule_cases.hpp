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

} // namespace support
