// Cases for the pairs among points, lines, rays, segments, planes, triangles, tetrahedra and
// boxes (the tests'
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
//             triangles in one plane);
//   apart     (flat_apart, for distances) the second shape placed at X plus a small dyadic offset.
// Random: coordinates in [-1, 1] at a random scale 2^-500..2^500, half of them in one plane
// z = c (every shape but a tetrahedron, so pairs of lines can meet; a box then has a face in
// it), unnudged.
#pragma once
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include "flat_shapes.hpp"
#include "obb_cases.hpp"

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
inline incidence::triangle3 realise(const incidence::triangle3& t, transform& tr) {
    return {moved(t.a, tr), moved(t.b, tr), moved(t.c, tr)};
}
inline incidence::tetrahedron3 realise(const incidence::tetrahedron3& t, transform& tr) {
    return {moved(t.a, tr), moved(t.b, tr), moved(t.c, tr), moved(t.d, tr)};
}
inline incidence::aabb3 realise(const incidence::aabb3& b, transform& tr) {
    return ordered(incidence::aabb3{moved(b.min, tr), moved(b.max, tr)});
}
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
    case 0: s = {X, X + f * d}; break;               // starts at X
    case 1: s = {X - f * d, X + g * d}; break;       // passes through X
    case 2: s = {X + f * d, X + (f + g) * d}; break; // X just before its start
    default: s = {X, X}; break;                      // a point
    }
    return r.coin() ? s : Seg{s.b, s.a};
}
template <class Ray, class P, class V>
Ray ray_at(rng& r, P X, V d) {
    switch (r.integer(0, 3)) {
    case 0: return {X, d};               // origin at X
    case 1: return {X - step(r) * d, d}; // X ahead
    case 2: return {X + step(r) * d, d}; // X behind
    default: return {X, V{}};            // a point
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

// A tetrahedron a, a + e1, a + e2, a + e3 with X = a + w1 e1 + w2 e2 + w3 e3 at a vertex, an edge
// point, a face point, inside, or just outside; e1 = d and e2 in a face with it when `contain`;
// one in twelve is coplanar (e3 in the plane of e1 and e2).
inline incidence::tetrahedron3 tetrahedron_at(rng& r, incidence::point3 X, incidence::vec3 d, bool contain) {
    using incidence::vec3;
    const vec3 e1 = contain || r.coin() ? d : small_dir(r), e2 = small_dir(r);
    vec3 e3 = small_dir(r);
    if (r.integer(0, 11) == 0) e3 = r.coin() ? e1 + e2 : e1 * 2.0 - e2 * 0.5;
    static constexpr double w[][3] = {{0, 0, 0},         {1, 0, 0},          {0.5, 0, 0},     {0.5, 0.5, 0},    {0.25, 0.25, 0},
                                      {0.25, 0.25, 0.5}, {0.25, 0.25, 0.25}, {-0.25, 0.5, 0}, {0.5, 0.5, 0.25}, {0.75, 0.5, 0}};
    const auto& c = w[r.integer(0, 9)];
    const incidence::point3 a = X - e1 * c[0] - e2 * c[1] - e3 * c[2];
    incidence::point3 v[4] = {a, a + e1, a + e2, a + e3};
    for (int i = 3; i > 0; --i) std::swap(v[i], v[r.integer(0, i)]); // any vertex order
    return {v[0], v[1], v[2], v[3]};
}
// A large tetrahedron with a face in the plane through X normal to f (a set's outward normal at
// its boundary point X), moved out or in by 2^-20 or not, its apex deep on the set's side (so that
// it may hold the set whole: no face of it meets the set, and a vertex of the set decides) or
// outside.
inline incidence::tetrahedron3 tetrahedron_around(rng& r, incidence::point3 X, incidence::vec3 f) {
    using incidence::vec3;
    vec3 u = cross(f, vec3{1, 2, 3});
    if (u.x == 0 && u.y == 0 && u.z == 0) u = cross(f, vec3{3, 1, 2});
    const vec3 w = cross(f, u);
    static constexpr double moves[] = {0x1p-20, 0, -0x1p-20};
    const incidence::point3 c = X + f * moves[r.integer(0, 2)];
    return {c + u * 64, c - u * 32 + w * 64, c - u * 32 - w * 64, X + f * (r.integer(0, 3) == 0 ? 256.0 : -256.0)};
}
// A box with X at a corner, an edge or face point, inside, or just outside; flat boxes (zero
// width on an axis) included.
inline incidence::aabb3 box_at(rng& r, incidence::point3 X) {
    const double x[3] = {X.x, X.y, X.z};
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
        const double w = r.integer(0, 4) * 0.5;
        static constexpr double s[] = {-1, 1, -1, 1, 0, 0.5, -1.5, 1.5};
        const double c = x[i] - s[r.integer(0, 7)] * w;
        lo[i] = c - w, hi[i] = c + w;
    }
    return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
}

// An oriented box (obb_cases.hpp's near box: small dyadic centre and extents, zero extents
// included, a permuted, near-rotation or skew frame) moved so that a corner, an edge or face
// point of its boundary (sometimes a quarter off it) is X.
inline incidence::obb3 obb_at(rng& r, incidence::point3 X) {
    incidence::obb3 b = near_obb(r);
    const incidence::point3 q = boundary_point(r, b);
    b.center = {b.center.x + (X.x - q.x), b.center.y + (X.y - q.y), b.center.z + (X.z - q.z)};
    return b;
}
// A box about the segment s for contains cases: centred at its midpoint (rounded), a permuted,
// near-rotation or skew frame, each extent zero or a quarter, an eighth or a sixteenth of the
// segment's largest coordinate difference (so between boundary points of a convex set it lies
// inside, pokes out or touches).
inline incidence::obb3 obb_between(rng& r, const incidence::segment3& s) {
    const double w = std::fmax(std::fabs(s.b.x - s.a.x), std::fmax(std::fabs(s.b.y - s.a.y), std::fabs(s.b.z - s.a.z)));
    incidence::obb3 b{{0.5 * s.a.x + 0.5 * s.b.x, 0.5 * s.a.y + 0.5 * s.b.y, 0.5 * s.a.z + 0.5 * s.b.z}, near_frame(r), {}};
    for (double& h : b.half_extents) h = r.integer(0, 3) == 0 ? 0.0 : std::ldexp(w, -r.integer(2, 4));
    return b;
}
inline incidence::obb3 realise(const incidence::obb3& b, transform& tr) {
    incidence::obb3 o = b;
    o.center = moved(b.center, tr);
    for (double& h : o.half_extents) h = tr.scale_only(h);
    return o;
}

template <class S>
typename proto_of<S>::type place(rng& r, incidence::point3 X, incidence::vec3 d, bool contain) {
    using namespace incidence;
    if constexpr (std::is_same_v<S, point3>) return shape_at(r, X, d, contain);
    else if constexpr (std::is_same_v<S, segment3>) return segment_at<segment3>(r, X, d);
    else if constexpr (std::is_same_v<S, ray3>) return ray_at<ray3>(r, X, d);
    else if constexpr (std::is_same_v<S, line3>) return line_at<line3>(r, X, d);
    else if constexpr (std::is_same_v<S, plane3>) return plane_at(r, X, d, contain);
    else if constexpr (std::is_same_v<S, tetrahedron3>) return tetrahedron_at(r, X, d, contain);
    else if constexpr (std::is_same_v<S, aabb3>) return box_at(r, X);
    else if constexpr (std::is_same_v<S, obb3>) return obb_at(r, X);
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

// Apart: a placed at X, b at X + h, h a small dyadic vector (zero for 1 in 729 cases), each along
// its own or a common direction, so that the nearest points fall exactly on an end, inside, or
// along a parallel stretch; then moved (the distance tests' third arrangement).
template <class A, class B>
std::pair<A, B> flat_apart(rng& r, bool any_scale = true) {
    using namespace incidence;
    const point3 X = small_point(r);
    const vec3 h{r.integer(-4, 4) * 0.25, r.integer(-4, 4) * 0.25, r.integer(-4, 4) * 0.25};
    const vec3 d = small_dir(r);
    const auto a = place<A>(r, X, d, r.coin());
    const auto b = place<B>(r, X + h, r.coin() ? d : small_dir(r), r.coin());
    transform tr = random_transform(r, true, any_scale);
    return {realise(a, tr), realise(b, tr)};
}

// Random shapes; every point and direction in the plane z = c for half of the cases.
template <class S>
typename proto_of<S>::type random_shape(rng& r, bool in_plane, double c) {
    using namespace incidence;
    auto p = [&] { return point3{r.uniform(-1, 1), r.uniform(-1, 1), in_plane ? c : r.uniform(-1, 1)}; };
    auto v = [&] { return vec3{r.uniform(-1, 1), r.uniform(-1, 1), in_plane ? 0.0 : r.uniform(-1, 1)}; };
    if constexpr (std::is_same_v<S, point3>) return p();
    else if constexpr (std::is_same_v<S, obb3>)
        return obb3{p(), random_frame(r), {r.uniform(0, 0.5), r.uniform(0, 0.5), r.uniform(0, 0.5)}};
    else if constexpr (std::is_same_v<S, segment3>) return segment3{p(), p()};
    else if constexpr (std::is_same_v<S, ray3>) return ray3{p(), v()};
    else if constexpr (std::is_same_v<S, line3>) return line3{p(), v()};
    else if constexpr (std::is_same_v<S, plane3>)
        return plane_proto{in_plane && r.coin() ? vec3{0, 0, 1} : v() + vec3{0, 0, r.uniform(-1, 1)}, p()};
    else if constexpr (std::is_same_v<S, tetrahedron3>) { // in general position: faces in a common plane are the near cases
        auto q = [&] { return point3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}; };
        const point3 q0 = q(), q1 = q(), q2 = q();
        return tetrahedron3{q0, q1, q2, q()};
    } else if constexpr (std::is_same_v<S, aabb3>) { // in the plane: a face in it
        const point3 a = p(), b = p();
        return aabb3{{std::min(a.x, b.x), std::min(a.y, b.y), in_plane ? a.z : std::min(a.z, b.z)},
                     {std::max(a.x, b.x), std::max(a.y, b.y), in_plane ? a.z + r.uniform(0, 1) : std::max(a.z, b.z)}};
    } else return triangle3{p(), p(), p()};
}
// in_plane: every case in one plane z = c (true), none (false), or half of them (unset).
template <class A, class B>
std::pair<A, B> flat_random(rng& r, bool any_scale = true, std::optional<bool> in_plane_cases = std::nullopt) {
    if constexpr (flat2_shape<A>) {
        const A a = random_shape2<A>(r);
        const B b = random_shape2<B>(r);
        transform tr = random_transform(r, false, any_scale);
        return {realise(a, tr), realise(b, tr)};
    } else {
        const bool coin = r.coin();
        const bool in_plane = in_plane_cases.value_or(coin);
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
inline std::vector<incidence::line3> same_set(const incidence::line3& l) {
    return {{l.origin, l.direction * -1.0}, {l.origin, l.direction * 2.0}};
}
inline std::vector<incidence::plane3> same_set(const incidence::plane3& p) {
    return {{p.normal * -1.0, -p.offset}, {p.normal * 2.0, p.offset * 2.0}};
}
inline std::vector<incidence::triangle3> same_set(const incidence::triangle3& t) { return {{t.b, t.c, t.a}, {t.a, t.c, t.b}}; }
inline std::vector<incidence::tetrahedron3> same_set(const incidence::tetrahedron3& t) {
    return {{t.b, t.c, t.d, t.a}, {t.a, t.c, t.b, t.d}};
}
inline std::vector<incidence::aabb3> same_set(const incidence::aabb3& b) { return {b}; }
inline std::vector<incidence::obb3> same_set(const incidence::obb3& b) { return {rewritten(b, 0), rewritten(b, 1)}; }
inline std::vector<incidence::point2> same_set(const incidence::point2& p) { return {p}; }
inline std::vector<incidence::segment2> same_set(const incidence::segment2& s) { return {{s.b, s.a}}; }
inline std::vector<incidence::ray2> same_set(const incidence::ray2& r) { return {{r.origin, 2.0 * r.direction}}; }
inline std::vector<incidence::line2> same_set(const incidence::line2& l) {
    return {{l.origin, -1.0 * l.direction}, {l.origin, 2.0 * l.direction}};
}

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
inline std::optional<incidence::tetrahedron3> translated(const incidence::tetrahedron3& t, incidence::vec3 v) {
    const auto a = shifted(t.a, v), b = shifted(t.b, v), c = shifted(t.c, v), d = shifted(t.d, v);
    if (a && b && c && d) return incidence::tetrahedron3{*a, *b, *c, *d};
    return std::nullopt;
}
inline std::optional<incidence::aabb3> translated(const incidence::aabb3& b, incidence::vec3 v) {
    const auto lo = shifted(b.min, v), hi = shifted(b.max, v);
    if (lo && hi) return incidence::aabb3{*lo, *hi};
    return std::nullopt;
}
inline std::optional<incidence::obb3> translated(const incidence::obb3& b, incidence::vec3 v) {
    if (const auto c = shifted(b.center, v)) return incidence::obb3{*c, b.axes, b.half_extents};
    return std::nullopt;
}
inline bool finite_shape(const incidence::obb3& b) {
    for (double x : {b.center.x, b.center.y, b.center.z, b.half_extents[0], b.half_extents[1], b.half_extents[2]})
        if (!std::isfinite(x)) return false;
    for (const auto& a : b.axes)
        if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(a.z)) return false;
    return true;
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

// --- containment cases ----------------------------------------------------------------------
// The outer shape a and an inner shape b whose vertices are points of a: exact combinations of
// a's vertices with weights in quarters (mostly inside or on a face, an edge or a vertex; one
// in eight with a weight of -1/4, just outside), then one scale and translation, nudged in half
// of the cases.
// A box inside a tetrahedron uses a corner tetrahedron (o, o + s e_x, o + s e_y, o + s e_z in
// a signed axis order), where box corners can lie exactly on the slanted face.
inline incidence::point3 combination(rng& r, const incidence::point3* v, int n) {
    int w[4] = {0, 0, 0, 0}, left = 4;
    for (int i = 0; i + 1 < n; ++i) {
        w[i] = r.integer(0, left);
        left -= w[i];
    }
    w[n - 1] = left;
    if (r.integer(0, 7) == 0) { // move a quarter from one weight to another: outside when it was 0
        const int i = r.integer(0, n - 1), j = (i + r.integer(1, n - 1)) % n;
        w[i] -= 1, w[j] += 1;
    }
    incidence::point3 p{0, 0, 0};
    for (int i = 0; i < n; ++i) p = p + (v[i] - incidence::point3{0, 0, 0}) * (w[i] * 0.25);
    return p;
}
template <class A, class B>
std::pair<A, B> inside_case(rng& r) {
    using namespace incidence;
    tetrahedron3 t;
    aabb3 box;
    if constexpr (std::is_same_v<A, tetrahedron3> && std::is_same_v<B, aabb3>) {
        const point3 o = small_point(r);
        const double s = r.integer(1, 8);
        const double g[3] = {r.coin() ? s : -s, r.coin() ? s : -s, r.coin() ? s : -s};
        t = {o, o + vec3{g[0], 0, 0}, o + vec3{0, g[1], 0}, o + vec3{0, 0, g[2]}};
        // the box from o towards the tetrahedron, widths w_i with sum w_i / s about 1
        double lo[3], hi[3];
        int left = 4;
        for (int i = 0; i < 3; ++i) {
            const int q = i == 2 ? left + (r.integer(0, 5) == 0 ? 1 : 0) : r.integer(0, left);
            left -= q;
            const double w = q * 0.25 * s, from = (i == 0 ? o.x : (i == 1 ? o.y : o.z));
            lo[i] = g[i] > 0 ? from : from - w;
            hi[i] = g[i] > 0 ? from + w : from;
        }
        box = {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
        transform tr = random_transform(r, r.coin(), true);
        return {realise(t, tr), realise(box, tr)};
    } else {
        point3 v[4];
        int n = 4;
        if constexpr (std::is_same_v<A, aabb3>) {
            box = box_at(r, small_point(r));
            for (int i = 0; i < 4; ++i)
                v[i] = point3{(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y, i == 3 ? box.max.z : box.min.z};
        } else {
            t = tetrahedron_at(r, small_point(r), small_dir(r), false);
            v[0] = t.a, v[1] = t.b, v[2] = t.c, v[3] = t.d;
        }
        auto in = [&] {
            if constexpr (std::is_same_v<A, aabb3>) { // a corner, edge or face point, inside, or a quarter out
                const double lo[3] = {box.min.x, box.min.y, box.min.z}, hi[3] = {box.max.x, box.max.y, box.max.z};
                double c[3];
                for (int k = 0; k < 3; ++k) {
                    const int q = r.integer(0, 4);
                    c[k] = lo[k] + (hi[k] - lo[k]) * q * 0.25;
                    if (r.integer(0, 15) == 0) c[k] += r.coin() ? 0.25 : -0.25;
                }
                return point3{c[0], c[1], c[2]};
            } else {
                return combination(r, v, n);
            }
        };
        B b;
        if constexpr (std::is_same_v<B, point3>) b = in();
        else if constexpr (std::is_same_v<B, segment3>) b = {in(), in()};
        else if constexpr (std::is_same_v<B, triangle3>) b = {in(), in(), in()};
        else b = tetrahedron3{in(), in(), in(), in()};
        transform tr = random_transform(r, r.coin(), true); // half of them exactly on the boundary
        if constexpr (std::is_same_v<A, aabb3>) return {realise(box, tr), realise(b, tr)};
        else return {realise(t, tr), realise(b, tr)};
    }
}

} // namespace support
