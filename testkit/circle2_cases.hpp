// Cases and checks for a circle2 (the closed disk) against a point2, circle2, segment2, ray2, line2
// or polygon2 (the families circle2_point2, circle2_circle2, circle2_segment2, circle2_ray2,
// circle2_line2, circle2_polygon2), contains(circle2, point2 | segment2 | circle2 | polygon2) and
// contains(polygon2, circle2).
// Oracle: CGAL's squared distance from the centre over Epeck with the shape embedded in the plane
// z = 0 (oracle::ball_flat), exact rationals for two disks and for a point (oracle::ball_ball,
// ball_contains_ball, point_in_ball), and for a polygon its set holding the centre (CGAL
// Polygon_2 over Epeck, oracle::polygon_intersect) or an edge within the radius.
// The checks are in circle2_checks.hpp. Include after testing.hpp and the CGAL oracle header.
//
// Near-degenerate: the shape in small dyadics, a point X of it (a segment's end or a point inside,
// a ray's origin or a point along it, a line's point, a ring point of a star polygon or its centre,
// the partner disk's boundary point) and a direction w in its normal cone at X (across the shape,
// or beyond an end; an axis or Pythagorean w one time in two, so that |w| is exact); the disk
// centred at X + k w with radius k |w| (exact where |w| is, else rounded), kept, nudged by ulps,
// halved or doubled; centred at X one time in eight. Then one random exact-or-nudged scale
// 2^-500..2^500 and translation for both. Random: flat_cases.hpp's random_shape2, a random star
// polygon (polygon_cases.hpp) or disk, and a disk of centre in [-1.5, 1.5]^2 and radius up to 1/2,
// at one random scale.
// contains: a disk of radius 5m around a small integer centre and vertices on its circle ((3m, 4m)
// away) or inside; a star polygon whose farthest vertex gives the radius (rounded); a disk inside
// another, touching it from inside ((3q, 4q) away, radius 5m - 5q), halved or grown by an ulp.
// contains(polygon2, circle2): a disk inside a star polygon, its radius the distance to the nearest
// edge (disk_in_star).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include "flat_cases.hpp"
#include "flat_shapes.hpp"
#include "lp_shapes.hpp"
#include "polygon_cases.hpp"

namespace support {

inline incidence::circle2 realise(const incidence::circle2& c, transform& tr) { return {moved(c.center, tr), tr.scale_only(c.radius)}; }

// The plane's shapes in z = 0, for the 3D oracles.
inline incidence::point3 in_space(incidence::point2 p) { return {p.x, p.y, 0.0}; }
inline incidence::vec3 in_space(incidence::vec2 v) { return {v.x, v.y, 0.0}; }
inline std::array<double, 3> a3(incidence::point2 p) { return {p.x, p.y, 0.0}; }
inline oracle::flat flat_of(const incidence::point2& p) { return to_flat(in_space(p)); }
inline oracle::flat flat_of(const incidence::segment2& s) { return to_flat(incidence::segment3{in_space(s.a), in_space(s.b)}); }
inline oracle::flat flat_of(const incidence::ray2& r) { return to_flat(incidence::ray3{in_space(r.origin), in_space(r.direction)}); }
inline oracle::flat flat_of(const incidence::line2& l) { return to_flat(incidence::line3{in_space(l.origin), in_space(l.direction)}); }

// Calls f(a, b) for every edge of every ring.
template <class F>
void each_edge(const incidence::polygon2& g, const F& f) {
    for (std::size_t ring = 0; ring < g.rings(); ++ring) {
        const std::size_t b = g.ring_begin(ring), e = g.ring_end(ring);
        for (std::size_t j = b; j < e; ++j) f(g.vertices[j], g.vertices[incidence::polygon2::next(j, b, e)]);
    }
}

// Does the disk meet b?
template <class B>
bool disk_truth(const incidence::circle2& c, const B& b) {
    using namespace incidence;
    const double r = std::fabs(c.radius);
    const auto C = a3(c.center);
    if constexpr (std::is_same_v<B, circle2>) {
        const auto E = a3(b.center);
        return oracle::ball_ball(C.data(), r, E.data(), std::fabs(b.radius));
    } else if constexpr (std::is_same_v<B, point2>) {
        const auto P = a3(b);
        return oracle::point_in_ball(P.data(), C.data(), r);
    } else if constexpr (std::is_same_v<B, polygon2>) {
        if (oracle::polygon_intersect(polygon_data_of(b), oracle::flat2{oracle::flat2::point, {c.center.x, c.center.y}})) return true;
        bool near = false;
        each_edge(b, [&](point2 p, point2 q) { near = near || oracle::ball_flat(flat_of(segment2{p, q}), C, r); });
        return near;
    } else {
        return oracle::ball_flat(flat_of(b), C, r);
    }
}
// Is the disk in the polygon's set (simple rings that do not meet, as the generators' star polygons
// and make() give)? A zero radius: its centre in the set; else the centre in it and no edge
// strictly within the radius (CGAL's squared distance over Epeck): such an edge has the outside
// on one side of it, within the disk.
inline bool polygon_holds_disk_truth(const incidence::polygon2& g, const incidence::circle2& c) {
    using namespace incidence;
    if (!oracle::polygon_intersect(polygon_data_of(g), oracle::flat2{oracle::flat2::point, {c.center.x, c.center.y}})) return false;
    const double r = std::fabs(c.radius);
    bool near = false;
    if (r > 0.0) each_edge(g, [&](point2 p, point2 q) { near = near || oracle::segment_in_open_ball(a3(p), a3(q), a3(c.center), r); });
    return !near;
}
// Is b in the disk? Its vertices (a disk: the centres within the difference of the radii).
template <class B>
bool disk_holds_truth(const incidence::circle2& c, const B& b) {
    using namespace incidence;
    if constexpr (std::is_same_v<B, circle2>) {
        const auto C = a3(c.center), E = a3(b.center);
        return oracle::ball_contains_ball(C.data(), std::fabs(c.radius), E.data(), std::fabs(b.radius));
    } else if constexpr (std::is_same_v<B, segment2>) {
        return disk_truth(c, b.a) && disk_truth(c, b.b);
    } else if constexpr (std::is_same_v<B, polygon2>) {
        for (const point2 p : b.vertices)
            if (!disk_truth(c, p)) return false;
        return true;
    } else {
        return disk_truth(c, b);
    }
}

// w with |w| exact one time in two (an axis or a Pythagorean direction, its length in len), else a
// small integer vector (len rounded).
inline incidence::vec2 disk_dir(rng& r, double& len) {
    if (r.coin()) {
        static constexpr double legs[3][2] = {{1, 0}, {3, 4}, {5, 12}};
        static constexpr double lengths[3] = {1, 5, 13};
        const int i = r.integer(0, 2);
        double x = legs[i][0], y = legs[i][1];
        if (r.coin()) std::swap(x, y);
        len = lengths[i];
        return {r.coin() ? -x : x, r.coin() ? -y : y};
    }
    const incidence::vec2 d = small_dir2(r);
    len = std::sqrt(d.x * d.x + d.y * d.y);
    return d;
}
inline incidence::vec2 turned(incidence::vec2 d) { return {-d.y, d.x}; }
// The disk touching at X from w (|w| = len): centre X + k w, radius k len, kept one time in two,
// else nudged by ulps, halved or doubled; centred at X one time in eight.
inline incidence::circle2 disk_at(rng& r, incidence::point2 X, incidence::vec2 w, double len) {
    if (r.integer(0, 7) == 0) return {X, r.integer(0, 4) * 0.25};
    const double k = r.integer(1, 4) * 0.25;
    double rad = k * len;
    switch (r.integer(0, 5)) {
    case 0: rad = nudge(rad, r.integer(-3, 3)); break;
    case 1: rad *= 0.5; break;
    case 2: rad *= 2.0; break;
    default: break;
    }
    return {X + k * w, rad};
}

// A case: the disk and b (a polygon2 views `store`).
template <class B>
std::optional<std::pair<incidence::circle2, B>> disk_near(rng& r, polygon_store& store) {
    using namespace incidence;
    const point2 A{small(r), small(r)};
    double len = 1.0;
    const vec2 d = disk_dir(r, len); // the shape's direction, or the partner's
    B b{};
    circle2 c{};
    if constexpr (std::is_same_v<B, point2>) {
        b = A;
        c = disk_at(r, A, d, len);
    } else if constexpr (std::is_same_v<B, circle2>) { // the partner around A, touched at A + k2 d
        const double k2 = r.integer(0, 4) * 0.25;
        b = circle2{A, k2 * len};
        c = disk_at(r, A + k2 * d, d, len);
    } else if constexpr (std::is_same_v<B, polygon2>) {
        const int n = r.integer(1, 3);
        star_polygon(r, n, A, 1.0, store);
        vec2 along{};
        const int where = r.integer(0, 7);
        const point2 X = where == 0 ? A : (where == 1 ? A + vec2{0.375 * n, 0.0} : ring_point(r, store, along));
        double wl = 1.0;
        vec2 w{};
        if (where < 2 || r.integer(0, 3) == 0) {
            w = disk_dir(r, wl);
        } else { // across the ring's edge at X, either side
            w = r.coin() ? turned(along) : -turned(along);
            wl = std::sqrt(dot(w, w));
        }
        c = disk_at(r, X, w, wl);
        b = store.view();
    } else { // a segment, ray or line along d through A, touched across it or beyond an end
        const double k = r.integer(1, 4);
        if constexpr (std::is_same_v<B, segment2>) b = segment2{A, A + k * d};
        else if constexpr (std::is_same_v<B, ray2>) b = ray2{A, d};
        else b = line2{A, d};
        const bool beyond = !std::is_same_v<B, line2> && r.coin();
        if (beyond) { // beyond A: away from the shape, straight or at a slant
            const bool straight = r.coin();
            const vec2 w = straight ? -d : -d + (r.integer(-2, 2) * 0.5) * turned(d);
            c = disk_at(r, A, w, straight ? len : std::sqrt(dot(w, w)));
        } else { // across, at a point along it (a segment's inside)
            const double t = std::is_same_v<B, segment2> ? k * r.integer(0, 4) * 0.25 : r.integer(-2, 4) * 0.5;
            c = disk_at(r, A + t * d, r.coin() ? turned(d) : -turned(d), len);
        }
    }
    transform tr = random_transform(r, true, true);
    const circle2 m = realise(c, tr);
    if constexpr (std::is_same_v<B, polygon2>) {
        realise_polygon(store, tr);
        b = store.view();
    } else {
        b = realise(b, tr);
    }
    if (!is_finite(m.center) || !std::isfinite(m.radius)) return std::nullopt;
    if constexpr (std::is_same_v<B, polygon2>) {
        for (const point2 p : store.v)
            if (!is_finite(p)) return std::nullopt;
    } else if constexpr (std::is_same_v<B, circle2>) {
        if (!is_finite(b.center) || !std::isfinite(b.radius)) return std::nullopt;
    } else if constexpr (std::is_same_v<B, point2>) {
        if (!is_finite(b)) return std::nullopt;
    } else if constexpr (std::is_same_v<B, segment2>) {
        if (!is_finite(b.a) || !is_finite(b.b)) return std::nullopt;
    } else {
        if (!is_finite(b.origin) || !is_finite(b.direction)) return std::nullopt;
    }
    return std::pair{m, b};
}
template <class B>
std::optional<std::pair<incidence::circle2, B>> disk_random(rng& r, polygon_store& store) {
    using namespace incidence;
    transform tr = random_transform(r, false, true);
    B b{};
    if constexpr (std::is_same_v<B, circle2>) {
        b = realise(circle2{{r.uniform(-1, 1), r.uniform(-1, 1)}, r.uniform(0, 0.5)}, tr);
    } else if constexpr (std::is_same_v<B, polygon2>) {
        star_polygon(r, r.integer(1, 3), point2{r.uniform(-1, 1), r.uniform(-1, 1)}, 0.125, store);
        realise_polygon(store, tr);
        b = store.view();
    } else {
        b = realise(random_shape2<B>(r), tr);
    }
    const circle2 c = realise(circle2{{r.uniform(-1.5, 1.5), r.uniform(-1.5, 1.5)}, r.uniform(0, 0.5)}, tr);
    if (!is_finite(c.center) || !std::isfinite(c.radius)) return std::nullopt;
    return std::pair{c, b};
}

// contains(circle2, B): a disk of radius 5m around a small integer centre holding B's vertices (on
// its circle, (3m, 4m) away, one time in two, else inside), or another disk touching it from
// inside, or a star polygon; then one random exact-or-nudged scale and translation.
template <class B>
std::pair<incidence::circle2, B> disk_holding(rng& r, polygon_store& store) {
    using namespace incidence;
    const point2 C{double(r.integer(-16, 16)), double(r.integer(-16, 16))};
    const double m = r.integer(1, 8);
    const auto on_circle = [&] {
        double x = 3 * m, y = 4 * m;
        if (r.coin()) std::swap(x, y);
        return C + vec2{r.coin() ? -x : x, r.coin() ? -y : y};
    };
    const auto inside = [&] { return C + vec2{r.integer(-7, 7) * m * 0.25, r.integer(-7, 7) * m * 0.25}; };
    const auto vertex = [&] { return r.coin() ? on_circle() : inside(); };
    circle2 c{C, 5 * m};
    B b{};
    if constexpr (std::is_same_v<B, point2>) {
        b = vertex();
    } else if constexpr (std::is_same_v<B, segment2>) {
        b = segment2{vertex(), vertex()};
    } else if constexpr (std::is_same_v<B, circle2>) {
        const double q = m * r.integer(0, 4) * 0.25;
        double rb = 5 * m - 5 * q;
        const int how = r.integer(0, 3);
        if (how == 0) rb *= 0.5;
        else if (how == 1) rb = nudge(rb, 1);
        double x = 3 * q, y = 4 * q;
        if (r.coin()) std::swap(x, y);
        b = circle2{C + vec2{r.coin() ? -x : x, r.coin() ? -y : y}, rb};
    } else { // a star polygon around C; the radius its farthest vertex's distance, rounded, or a little more
        star_polygon(r, r.integer(1, 3), C, m * 0.5, store);
        double far = 0.0;
        for (const point2 p : store.v) far = std::fmax(far, (p.x - C.x) * (p.x - C.x) + (p.y - C.y) * (p.y - C.y));
        c.radius = std::sqrt(far) * (r.coin() ? 1.0 : 1.0625);
        b = store.view();
    }
    transform tr = random_transform(r, true, true);
    if constexpr (std::is_same_v<B, polygon2>) {
        realise_polygon(store, tr);
        b = store.view();
    } else {
        b = realise(b, tr);
    }
    return {realise(c, tr), b};
}
// contains(polygon2, circle2): a star polygon (a hole half of the time) in small coordinates and a
// disk around a point inside it (between the rings, or a ring point moved towards there) whose
// radius is its distance from the nearest edge (in double, rounded), kept, nudged by ulps, halved
// or grown by 1/16; one time in eight a ring point with radius 0. Then one random exact-or-nudged
// scale and translation; `store` holds the polygon.
inline incidence::circle2 disk_in_star(rng& r, polygon_store& store) {
    using namespace incidence;
    const point2 centre{small(r), small(r)};
    const int n = r.integer(1, 3);
    star_polygon(r, n, centre, 1.0, store);
    vec2 along{};
    const point2 X = ring_point(r, store, along);
    circle2 c{X, 0.0};
    if (r.integer(0, 7) != 0) {
        const point2 P = centre + vec2{0.375 * n, 0.0}; // between the rings
        c.center = r.coin() ? P : X + (r.integer(1, 4) * 0.0625) * (P - X);
        double nearest = 1e300;
        each_edge(store.view(), [&](point2 p, point2 q) { // the squared distance in double
            const vec2 d = q - p, m = c.center - p;
            const double t = std::clamp(dot(m, d) / dot(d, d), 0.0, 1.0);
            const vec2 e = m - t * d;
            nearest = std::fmin(nearest, dot(e, e));
        });
        c.radius = std::sqrt(nearest);
        switch (r.integer(0, 7)) {
        case 0: c.radius = nudge(c.radius, r.integer(-3, 3)); break;
        case 1: c.radius *= 1.0625; break;
        case 2:
        case 3:
        case 4: c.radius *= 0.5; break;
        default: break;
        }
    }
    transform tr = random_transform(r, true, true);
    realise_polygon(store, tr);
    return realise(c, tr);
}

template <class B>
std::pair<incidence::circle2, B> disk_random_around(rng& r, polygon_store& store) {
    for (;;)
        if (const auto c = disk_random<B>(r, store)) return *c;
}
} // namespace support
