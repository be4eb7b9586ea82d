// Cases for a capsule against a shape (capsule_point, capsule_sphere, capsule_capsule,
// capsule_segment, capsule_ray, capsule_line, capsule_plane, capsule_triangle,
// capsule_tetrahedron, aabb_capsule, capsule_obb, capsule_convex_polyhedron, capsule_frustum, capsule_kdop);
// the checks are in capsule_checks.hpp. Include after testing.hpp and the CGAL oracle header.
// A half-space set or a k-DOP: near_rows' set (ball_halfspace_cases.hpp) and a capsule grown from a
// ball touching it (capsule_touching), as below; random: ball_random's set and ball, grown to a
// capsule along a vector of up to twice the radius, with half the radius.
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

// A capsule grown from a ball touching the rows (ball_touching, along w in their normal cone at the
// spot): from c to c + v with v . w >= 0 (a small dyadic v, zero one time in six), so that its
// segment keeps the ball's distance.
inline incidence::capsule3 capsule_touching(rng& r, const proto_rows& rows) {
    using namespace incidence;
    vec3 w{0, 0, 0};
    const sphere3 ball = ball_touching(r, rows, &w);
    vec3 v = small_dir(r) * 0.5;
    if (dot(v, w) < 0) v = v * -1.0;
    if (r.integer(0, 5) == 0) v = vec3{0, 0, 0};
    return {ball.center, ball.center + v, ball.radius};
}

template <class B>
std::optional<std::pair<incidence::capsule3, B>> capsule_near_shape(rng& r) {
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
    } else if constexpr (std::is_same_v<B, obb3>) { // near_obb's frames: signed permutations, near rotations, skew
        const obb3 b = near_obb(r);
        rows = box_rows(b);
        partner = b;
    } else {
        const auto f = flat_rows<B>(r);
        rows = f.rows;
        partner = f.shape;
    }
    capsule3 c = capsule_touching(r, rows);
    if (halves) {
        const double whole = c.radius;
        c.radius = whole * 0.5;
        if constexpr (std::is_same_v<B, sphere3> || std::is_same_v<B, capsule3>) partner.radius = whole * 0.5;
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
std::optional<std::pair<incidence::capsule3, B>> capsule_near(rng& r) {
    using namespace incidence;
    if constexpr (is_halfspace_shape<B>::value || is_kdop<B>::value) { // near_rows' set, as ball_near
        const proto_rows p = near_rows<B>(r);
        const capsule3 c = capsule_touching(r, p);
        transform tr = random_transform(r, true, true);
        const auto b = realise_rows<B>(p, tr);
        const capsule3 m = realise(c, tr);
        if (!b || !is_finite(m.a) || !is_finite(m.b) || !std::isfinite(m.radius)) return std::nullopt;
        return std::pair{m, *b};
    } else {
        return capsule_near_shape<B>(r);
    }
}
template <class B>
std::optional<std::pair<incidence::capsule3, B>> capsule_random_shape(rng& r) {
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
template <class B>
std::optional<std::pair<incidence::capsule3, B>> capsule_random(rng& r) {
    using namespace incidence;
    if constexpr (is_halfspace_shape<B>::value || is_kdop<B>::value) { // ball_random's set and ball, grown
        const auto c = ball_random<B>(r);
        if (!c) return std::nullopt;
        const sphere3 s = c->second;
        const vec3 v{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
        const capsule3 k{s.center, s.center + v * (2 * s.radius), s.radius * 0.5};
        if (!is_finite(k.b)) return std::nullopt;
        return std::pair{k, c->first};
    } else {
        return capsule_random_shape<B>(r);
    }
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
    } else if constexpr (std::is_same_v<S, obb3>) {
        // the box along the segment, across it either the coordinate axes or a frame turned about
        // the segment by (0.6, 0.8) rounded, with extents (3m, 4m) (every corner on the cylinder, or
        // within rounding of it) or (0, 5m), or half those (inside) one time in two
        const double k = r.coin() ? 0.5 : 1.0;
        const bool turned = r.coin();
        const vec3 p = turned ? across(0.6, 0.8) : across(1, 0), q = turned ? across(-0.8, 0.6) : across(0, 1);
        const bool flat = r.integer(0, 5) == 0;
        const double hu = flat ? 0.0 : 3 * m * k, hw = (flat ? 5 : 4) * m * k;
        const obb3 b{a + along(len * 0.5), {along(1), p, q}, {len * 0.5, hu, hw}};
        return {realise(c, tr), realise(b, tr)};
    } else if constexpr (std::is_same_v<S, sphere3> || std::is_same_v<S, capsule3>) {
        // balls 5q from the segment (across by (3q, 4q) at a point of it, or beyond an end by 3q and
        // across by 4q) of radius 5m - 5q: touching from inside; halved one time in four, grown by
        // an ulp one time in four. A capsule: two such centres, the same radius.
        const double q = m * r.integer(0, 4) * 0.25;
        const double u = (r.coin() ? 3 : -3) * q, w = (r.coin() ? 4 : -4) * q;
        auto centre = [&] {
            return r.coin() ? a + along(r.integer(0, 8) * len / 8) + across(u, w)
                            : a + along(r.coin() ? -3 * q : len + 3 * q) + across(0, w);
        };
        double rs = 5 * m - 5 * q;
        tr.nudged = r.integer(0, 2) == 0; // touching stays touching two times in three
        const int how = r.integer(0, 3);
        if (how == 0) rs *= 0.5;
        else if (how == 1) rs = nudge(rs, 1);
        if constexpr (std::is_same_v<S, sphere3>) return {realise(c, tr), realise(sphere3{centre(), rs}, tr)};
        else return {realise(c, tr), realise(capsule3{centre(), centre(), rs}, tr)};
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
    using namespace incidence;
    if constexpr (std::is_same_v<X, obb3>) {
        const auto [x, s] = obb_holding_ball(r);
        return {x, capsule_from(r, s)};
    } else if constexpr (std::is_same_v<X, aabb3>) {
        const auto [x, s] = aabb_holding_ball(r);
        return {x, capsule_from(r, s)};
    } else if constexpr (std::is_same_v<X, sphere3>) { // sphere_holding's ball around a capsule: two ends, radius to touch
        const auto [x, s] = sphere_holding<segment3>(r);
        const double room = std::fmax(std::sqrt(dot(s.a - x.center, s.a - x.center)), std::sqrt(dot(s.b - x.center, s.b - x.center)));
        return {x, capsule3{s.a, s.b, std::fmax(0.0, x.radius - room) * (r.coin() ? 1.0 : 0.5)}};
    } else { // a half-space set (near_rows): from the middle of its spots (points of the set) to a spot or halfway
        for (;;) {
            const proto_rows p = near_rows<X>(r);
            vec3 sum{0, 0, 0};
            for (const point3 x : p.spots) sum = sum + (x - point3{0, 0, 0});
            const point3 m = point3{0, 0, 0} + sum * (1.0 / double(p.spots.size()));
            const point3 s = p.spots[static_cast<std::size_t>(r.integer(0, static_cast<int>(p.spots.size()) - 1))];
            const vec3 d = s - m;
            const double radius = r.integer(0, 2) == 0 ? 0.0 : std::sqrt(dot(d, d)) * 0.0625; // zero: touching at s
            const capsule3 c{m, r.coin() ? s : m + d * 0.5, radius};
            transform tr = random_transform(r, true, true);
            const auto x = realise_rows<X>(p, tr);
            const capsule3 k = realise(c, tr);
            if (x && is_finite(k.a) && is_finite(k.b) && std::isfinite(k.radius)) return {*x, k};
        }
    }
}
// The random counterparts of capsule_inside.
template <class X>
std::pair<X, incidence::capsule3> capsule_random_in(rng& r) {
    using namespace incidence;
    if constexpr (std::is_same_v<X, aabb3> || std::is_same_v<X, obb3>) {
        return capsule_random_inside<X>(r);
    } else if constexpr (std::is_same_v<X, sphere3>) {
        const auto [c, s] = capsule_random_around<sphere3>(r);
        return {s, c};
    } else {
        for (;;)
            if (const auto c = ball_random<X>(r)) return {c->first, capsule_from(r, c->second)};
    }
}
// The truths: every vertex within r of the capsule's segment (CGAL's squared distance over Epeck,
// oracle::ball_flat); a box around both end balls (contain_cases.hpp's contains_truth).
// A ball in X: the rows in rationals for a half-space set (oracle::ball_in_rows), the ball in a
// ball, the centre within the difference of the radii of a capsule's segment (over Epeck,
// oracle::flat_holds_ball), else contain_cases.hpp's contains_truth.
template <class X>
bool holds_ball(const X& x, const incidence::sphere3& s) {
    if constexpr (is_halfspace_shape<X>::value || is_kdop<X>::value) {
        return oracle::ball_in_rows(lp(x), a3(s.center), s.radius);
    } else if constexpr (std::is_same_v<X, incidence::sphere3>) {
        const double c1[3] = {x.center.x, x.center.y, x.center.z}, c2[3] = {s.center.x, s.center.y, s.center.z};
        return oracle::ball_contains_ball(c1, std::fabs(x.radius), c2, std::fabs(s.radius));
    } else if constexpr (std::is_same_v<X, incidence::capsule3>) {
        return oracle::flat_holds_ball(to_flat(incidence::segment3{x.a, x.b}), a3(s.center), x.radius, s.radius);
    } else {
        return contains_truth(x, s);
    }
}
template <class S>
bool capsule_holds(const incidence::capsule3& c, const S& s) {
    if constexpr (std::is_same_v<S, incidence::sphere3>) {
        return holds_ball(c, s);
    } else if constexpr (std::is_same_v<S, incidence::capsule3>) {
        const double r = std::fabs(s.radius);
        return holds_ball(c, incidence::sphere3{s.a, r}) && holds_ball(c, incidence::sphere3{s.b, r});
    } else if constexpr (std::is_same_v<S, incidence::obb3>) {
        double o[3], axes[9];
        box_arrays(s, o, axes);
        return oracle::box_in_capsule(o, axes, s.half_extents.data(), a3(c.a).data(), a3(c.b).data(), c.radius);
    } else {
        for (const auto& p : vertices(s))
            if (!oracle::ball_flat(to_flat(incidence::segment3{c.a, c.b}), a3(p), c.radius)) return false;
        return true;
    }
}
template <class X>
bool holds_capsule(const X& x, const incidence::capsule3& c) {
    const double r = std::fabs(c.radius);
    return holds_ball(x, incidence::sphere3{c.a, r}) && holds_ball(x, incidence::sphere3{c.b, r});
}

} // namespace support
