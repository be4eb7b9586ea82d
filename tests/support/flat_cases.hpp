// Cases for the pairs among points, lines, rays, segments, planes and triangles (the tests'
// checks are in flat_checks.hpp). Include after testing.hpp and the CGAL oracle header.
//
// Near-degenerate: both shapes are built in small dyadic coordinates around one point X, in one
// of three arrangements, then moved by one random exact-or-nudged scale and translation:
//   meet      each shape has X at a chosen place: a segment's end, its interior, or just past its
//             end; a ray's origin, a point ahead of it, or behind it; a line through it; a
//             triangle's vertex, an edge point, an interior point or a point just outside; a plane
//             through it; so touching, crossing and near-missing pairs;
//   parallel  both along one direction d (or -d, 2d): collinear with overlapping, touching or
//             separated ranges, or side by side in a plane; a plane containing d;
//   coplanar  the second shape lies in the first one's plane (a line in a triangle's plane, two
//             triangles in one plane).
// Random: coordinates in [-1, 1] at a random scale 2^-500..2^500, half of them in one plane
// z = c (every shape, so pairs of lines can meet), unnudged.
#pragma once
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include "flat_shapes.hpp"

namespace support {

// --- shapes in small coordinates, then moved -------------------------------------------------
// A plane is kept as its normal and a point on it until the transform has moved that point.
struct plane_proto {
    incidence::vec3 n;
    incidence::point3 x;
};
template <class S>
struct proto_of {
    using type = S;
};
template <>
struct proto_of<incidence::plane3> {
    using type = plane_proto;
};

inline incidence::point3 moved(const incidence::point3& p, transform& tr) { return {tr.apply(p.x, 0), tr.apply(p.y, 1), tr.apply(p.z, 2)}; }
inline incidence::vec3 moved_dir(const incidence::vec3& d, transform& tr) { return {tr.dir(d.x), tr.dir(d.y), tr.dir(d.z)}; }
inline incidence::point3 realise(const incidence::point3& p, transform& tr) { return moved(p, tr); }
inline incidence::segment3 realise(const incidence::segment3& s, transform& tr) { return {moved(s.a, tr), moved(s.b, tr)}; }
inline incidence::ray3 realise(const incidence::ray3& r, transform& tr) { return {moved(r.origin, tr), moved_dir(r.direction, tr)}; }
inline incidence::line3 realise(const incidence::line3& l, transform& tr) { return {moved(l.origin, tr), moved_dir(l.direction, tr)}; }
inline incidence::triangle3 realise(const incidence::triangle3& t, transform& tr) { return {moved(t.a, tr), moved(t.b, tr), moved(t.c, tr)}; }
inline incidence::plane3 realise(const plane_proto& p, transform& tr) {
    const incidence::point3 x = moved(p.x, tr);
    transform unscaled = tr; // a normal is not scaled with the coordinates (n . x would overflow)
    unscaled.k = 0;
    const incidence::vec3 n = moved_dir(p.n, unscaled); // a nudged normal tilts the plane slightly
    return {n, n.x * x.x + n.y * x.y + n.z * x.z};
}

inline incidence::vec3 small_dir(rng& r) {
    for (;;) {
        const incidence::vec3 d{double(r.integer(-4, 4)), double(r.integer(-4, 4)), double(r.integer(-4, 4))};
        if (!(d.x == 0 && d.y == 0 && d.z == 0)) return d;
    }
}
inline incidence::point3 small_point(rng& r) { return {small(r), small(r), small(r)}; }
inline double step(rng& r) { return r.integer(1, 8) * 0.25; }

// The shape of type S with X at a random place of its own (its end, interior or just past it),
// running along d (a plane: containing d when `contain`, else with a random normal).
inline incidence::point3 shape_at(rng&, incidence::point3 X, incidence::vec3, bool) { return X; }
// (templates over the dimension: Seg, Ray and Line are segment3/ray3/line3 or their 2D kinds)
template <class Seg, class P, class V>
Seg segment_at(rng& r, P X, V d) {
    const double f = step(r), g = step(r);
    Seg s;
    switch (r.integer(0, 3)) {
    case 0: s = {X, X + f * d}; break;             // starts at X
    case 1: s = {X - f * d, X + g * d}; break;     // passes through X
    case 2: s = {X + f * d, X + (f + g) * d}; break; // X just before its start
    default: s = {X, X}; break;                    // a point
    }
    return r.coin() ? s : Seg{s.b, s.a};
}
template <class Ray, class P, class V>
Ray ray_at(rng& r, P X, V d) {
    switch (r.integer(0, 3)) {
    case 0: return {X, d};                  // origin at X
    case 1: return {X - step(r) * d, d};    // X ahead
    case 2: return {X + step(r) * d, d};    // X behind
    default: return {X, V{}};               // a point
    }
}
template <class Line, class P, class V>
Line line_at(rng& r, P X, V d) {
    if (r.integer(0, 7) == 0) return {X, V{}}; // a point
    return {X - step(r) * d, d};
}
inline plane_proto plane_at(rng& r, incidence::point3 X, incidence::vec3 d, bool contain) {
    incidence::vec3 n = small_dir(r);
    if (contain) {
        n = cross(d, n);
        if (n.x == 0 && n.y == 0 && n.z == 0) n = cross(d, incidence::vec3{1, 2, 3});
    }
    return {n, X};
}
inline incidence::triangle3 triangle_at(rng& r, incidence::point3 X, incidence::vec3 d) {
    // vertices a, b, c with X = a + s (b - a) + u (c - a) at a vertex, an edge, inside or outside
    const incidence::vec3 e1 = r.coin() ? d : small_dir(r), e2 = small_dir(r);
    static constexpr double su[][2] = {{0, 0}, {0.5, 0}, {0.25, 0.25}, {0.5, 0.5}, {1, 0}, {0.75, 0.5}, {-0.25, 0.5}};
    const auto& w = su[r.integer(0, 6)];
    const incidence::point3 a = X - e1 * w[0] - e2 * w[1];
    const incidence::triangle3 t{a, a + e1, a + e2};
    switch (r.integer(0, 2)) {
    case 0: return t;
    case 1: return {t.b, t.c, t.a};
    default: return {t.a, t.c, t.b};
    }
}

template <class S>
typename proto_of<S>::type place(rng& r, incidence::point3 X, incidence::vec3 d, bool contain) {
    using namespace incidence;
    if constexpr (std::is_same_v<S, point3>) return shape_at(r, X, d, contain);
    else if constexpr (std::is_same_v<S, segment3>) return segment_at<segment3>(r, X, d);
    else if constexpr (std::is_same_v<S, ray3>) return ray_at<ray3>(r, X, d);
    else if constexpr (std::is_same_v<S, line3>) return line_at<line3>(r, X, d);
    else if constexpr (std::is_same_v<S, plane3>) return plane_at(r, X, d, contain);
    else return triangle_at(r, X, d);
}

// --- in the plane: the same arrangements (meet at X, parallel or collinear) --------------------
inline incidence::point2 moved(const incidence::point2& p, transform& tr) { return {tr.apply(p.x, 0), tr.apply(p.y, 1)}; }
inline incidence::vec2 moved_dir(const incidence::vec2& d, transform& tr) { return {tr.dir(d.x), tr.dir(d.y)}; }
inline incidence::point2 realise(const incidence::point2& p, transform& tr) { return moved(p, tr); }
inline incidence::segment2 realise(const incidence::segment2& s, transform& tr) { return {moved(s.a, tr), moved(s.b, tr)}; }
inline incidence::ray2 realise(const incidence::ray2& r, transform& tr) { return {moved(r.origin, tr), moved_dir(r.direction, tr)}; }
inline incidence::line2 realise(const incidence::line2& l, transform& tr) { return {moved(l.origin, tr), moved_dir(l.direction, tr)}; }
inline incidence::vec2 small_dir2(rng& r) {
    for (;;) {
        const incidence::vec2 d{double(r.integer(-4, 4)), double(r.integer(-4, 4))};
        if (!(d.x == 0 && d.y == 0)) return d;
    }
}
template <class S>
S place2(rng& r, incidence::point2 X, incidence::vec2 d) {
    using namespace incidence;
    if constexpr (std::is_same_v<S, point2>) return X;
    else if constexpr (std::is_same_v<S, segment2>) return segment_at<segment2>(r, X, d);
    else if constexpr (std::is_same_v<S, ray2>) return ray_at<ray2>(r, X, d);
    else return line_at<line2>(r, X, d);
}
template <class A, class B>
std::pair<A, B> flat_near2(rng& r, bool any_scale) {
    using namespace incidence;
    const point2 X{small(r), small(r)};
    const vec2 d = small_dir2(r);
    const A a = place2<A>(r, X, d);
    B b;
    if (r.coin()) { // meet at X
        b = place2<B>(r, X, r.integer(0, 3) == 0 ? d : small_dir2(r));
    } else { // parallel: along d (or -d, 2d), on a's line or beside it
        const double k = r.integer(0, 2) == 0 ? -1.0 : (r.coin() ? 1.0 : 2.0);
        const vec2 side = r.coin() ? vec2{0, 0} : (r.integer(1, 2) * 0.25) * vec2{-d.y, d.x};
        b = place2<B>(r, X + (r.integer(-6, 6) * 0.25) * d + side, k * d);
    }
    transform tr = random_transform(r, true, any_scale);
    return {realise(a, tr), realise(b, tr)};
}
template <class S>
S random_shape2(rng& r) {
    using namespace incidence;
    auto p = [&] { return point2{r.uniform(-1, 1), r.uniform(-1, 1)}; };
    auto v = [&] { return vec2{r.uniform(-1, 1), r.uniform(-1, 1)}; };
    if constexpr (std::is_same_v<S, point2>) return p();
    else if constexpr (std::is_same_v<S, segment2>) return segment2{p(), p()};
    else if constexpr (std::is_same_v<S, ray2>) return ray2{p(), v()};
    else return line2{p(), v()};
}

// any_scale false: scale 1, no far translation (the benchmarks' sets).
template <class A, class B>
std::pair<A, B> flat_near(rng& r, bool any_scale = true) {
    using namespace incidence;
    if constexpr (flat2_shape<A>) return flat_near2<A, B>(r, any_scale);
    else {
    const point3 X = small_point(r);
    const vec3 d = small_dir(r);
    typename proto_of<A>::type a{};
    typename proto_of<B>::type b{};
    switch (r.integer(0, 2)) {
    case 0: // meet at X, each along its own direction
        a = place<A>(r, X, d, false);
        b = place<B>(r, X, r.integer(0, 3) == 0 ? d : small_dir(r), false);
        break;
    case 1: { // parallel: b along d (or -d, 2d), collinear or beside a in a common plane
        a = place<A>(r, X, d, true);
        const double k = r.integer(0, 2) == 0 ? -1.0 : (r.coin() ? 1.0 : 2.0);
        const vec3 side = r.coin() ? vec3{0, 0, 0} : cross(d, small_dir(r)) * (r.integer(1, 2) * 0.25);
        b = place<B>(r, X + d * (r.integer(-6, 6) * 0.25) + side, d * k, true);
        if constexpr (std::is_same_v<A, plane3> && std::is_same_v<B, plane3>) b.n = a.n * k; // parallel planes
        break;
    }
    default: { // coplanar: b at another point of a plane through X that contains d
        const vec3 e = small_dir(r);
        a = place<A>(r, X, d, true);
        b = place<B>(r, X + d * (r.integer(-4, 4) * 0.25) + e * (r.integer(-4, 4) * 0.25), r.coin() ? e : d + e, true);
        break;
    }
    }
    transform tr = random_transform(r, true, any_scale);
    return {realise(a, tr), realise(b, tr)};
    }
}

// Random shapes; every point and direction in the plane z = c for half of the cases.
template <class S>
typename proto_of<S>::type random_shape(rng& r, bool in_plane, double c) {
    using namespace incidence;
    auto p = [&] { return point3{r.uniform(-1, 1), r.uniform(-1, 1), in_plane ? c : r.uniform(-1, 1)}; };
    auto v = [&] { return vec3{r.uniform(-1, 1), r.uniform(-1, 1), in_plane ? 0.0 : r.uniform(-1, 1)}; };
    if constexpr (std::is_same_v<S, point3>) return p();
    else if constexpr (std::is_same_v<S, segment3>) return segment3{p(), p()};
    else if constexpr (std::is_same_v<S, ray3>) return ray3{p(), v()};
    else if constexpr (std::is_same_v<S, line3>) return line3{p(), v()};
    else if constexpr (std::is_same_v<S, plane3>) return plane_proto{in_plane && r.coin() ? vec3{0, 0, 1} : v() + vec3{0, 0, r.uniform(-1, 1)}, p()};
    else return triangle3{p(), p(), p()};
}
template <class A, class B>
std::pair<A, B> flat_random(rng& r, bool any_scale = true) {
    if constexpr (flat2_shape<A>) {
        const A a = random_shape2<A>(r);
        const B b = random_shape2<B>(r);
        transform tr = random_transform(r, false, any_scale);
        return {realise(a, tr), realise(b, tr)};
    } else {
        const bool in_plane = r.coin();
        const double c = r.uniform(-1, 1);
        const auto a = random_shape<A>(r, in_plane, c);
        const auto b = random_shape<B>(r, in_plane, c);
        transform tr = random_transform(r, false, any_scale);
        return {realise(a, tr), realise(b, tr)};
    }
}

// --- shapes that are the same point set ------------------------------------------------------
// Exact rewrites (reversed, rotated, negated, doubled), used to check that the answer depends on
// the point set alone.
inline std::vector<incidence::point3> same_set(const incidence::point3& p) { return {p}; }
inline std::vector<incidence::segment3> same_set(const incidence::segment3& s) { return {{s.b, s.a}}; }
inline std::vector<incidence::ray3> same_set(const incidence::ray3& r) { return {{r.origin, r.direction * 2.0}}; }
inline std::vector<incidence::line3> same_set(const incidence::line3& l) { return {{l.origin, l.direction * -1.0}, {l.origin, l.direction * 2.0}}; }
inline std::vector<incidence::plane3> same_set(const incidence::plane3& p) { return {{p.normal * -1.0, -p.offset}, {p.normal * 2.0, p.offset * 2.0}}; }
inline std::vector<incidence::triangle3> same_set(const incidence::triangle3& t) { return {{t.b, t.c, t.a}, {t.a, t.c, t.b}}; }
inline std::vector<incidence::point2> same_set(const incidence::point2& p) { return {p}; }
inline std::vector<incidence::segment2> same_set(const incidence::segment2& s) { return {{s.b, s.a}}; }
inline std::vector<incidence::ray2> same_set(const incidence::ray2& r) { return {{r.origin, 2.0 * r.direction}}; }
inline std::vector<incidence::line2> same_set(const incidence::line2& l) { return {{l.origin, -1.0 * l.direction}, {l.origin, 2.0 * l.direction}}; }

// Translated by v (a plane's offset moves by n . v); std::nullopt unless every coordinate
// moved exactly.
inline bool exact_add(double x, double v, double& out) {
    out = x + v;
    return out - v == x && out - x == v;
}
inline std::optional<incidence::point3> shifted(const incidence::point3& p, incidence::vec3 v) {
    incidence::point3 q;
    if (exact_add(p.x, v.x, q.x) && exact_add(p.y, v.y, q.y) && exact_add(p.z, v.z, q.z)) return q;
    return std::nullopt;
}
inline std::optional<incidence::point3> translated(const incidence::point3& p, incidence::vec3 v) { return shifted(p, v); }
inline std::optional<incidence::segment3> translated(const incidence::segment3& s, incidence::vec3 v) {
    const auto a = shifted(s.a, v), b = shifted(s.b, v);
    if (a && b) return incidence::segment3{*a, *b};
    return std::nullopt;
}
inline std::optional<incidence::ray3> translated(const incidence::ray3& r, incidence::vec3 v) {
    if (const auto o = shifted(r.origin, v)) return incidence::ray3{*o, r.direction};
    return std::nullopt;
}
inline std::optional<incidence::line3> translated(const incidence::line3& l, incidence::vec3 v) {
    if (const auto o = shifted(l.origin, v)) return incidence::line3{*o, l.direction};
    return std::nullopt;
}
inline std::optional<incidence::triangle3> translated(const incidence::triangle3& t, incidence::vec3 v) {
    const auto a = shifted(t.a, v), b = shifted(t.b, v), c = shifted(t.c, v);
    if (a && b && c) return incidence::triangle3{*a, *b, *c};
    return std::nullopt;
}
// In the plane: by (v.x, v.y).
inline std::optional<incidence::point2> translated(const incidence::point2& p, incidence::vec3 v) {
    incidence::point2 q;
    if (exact_add(p.x, v.x, q.x) && exact_add(p.y, v.y, q.y)) return q;
    return std::nullopt;
}
inline std::optional<incidence::segment2> translated(const incidence::segment2& s, incidence::vec3 v) {
    const auto a = translated(s.a, v), b = translated(s.b, v);
    if (a && b) return incidence::segment2{*a, *b};
    return std::nullopt;
}
inline std::optional<incidence::ray2> translated(const incidence::ray2& r, incidence::vec3 v) {
    if (const auto o = translated(r.origin, v)) return incidence::ray2{*o, r.direction};
    return std::nullopt;
}
inline std::optional<incidence::line2> translated(const incidence::line2& l, incidence::vec3 v) {
    if (const auto o = translated(l.origin, v)) return incidence::line2{*o, l.direction};
    return std::nullopt;
}
inline std::optional<incidence::plane3> translated(const incidence::plane3& p, incidence::vec3 v) {
    // offset + n . v, exact when each product and sum is
    const double terms[3] = {p.normal.x * v.x, p.normal.y * v.y, p.normal.z * v.z};
    const double comps[3][2] = {{p.normal.x, v.x}, {p.normal.y, v.y}, {p.normal.z, v.z}};
    double o = p.offset;
    for (int i = 0; i < 3; ++i) {
        if (std::fma(comps[i][0], comps[i][1], -terms[i]) != 0.0) return std::nullopt;
        double next;
        if (!exact_add(o, terms[i], next)) return std::nullopt;
        o = next;
    }
    return incidence::plane3{p.normal, o};
}

} // namespace support
