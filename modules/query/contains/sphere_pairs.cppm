// contains: sphere_pairs
module;
#include <array>
export module incidence.detail:contains.sphere_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.separating_axes;
import :engines.tetrahedron;
import :intersects.linear_pairs;
import :intersects.obb_pairs;
import :contains.obb_pairs;
import :engines.sphere;
import :engines.ball_obb;
import :intersects.sphere_pairs;
import :engines.kdop;
import :engines.halfspace_slabs;
import :engines.ball_halfspaces;
import :exactly;

export namespace incidence::detail {

// aabb3 against sphere3 (closed box, closed ball): intersects, contains(aabb3, sphere3) and
// contains(sphere3, aabb3).
// Semantics: touching counts; a box contains a ball it touches from inside. Unchecked negative
// radii act as |r| (as in point_sphere); inverted, infinite or NaN input meets and holds nothing.

// Is the ball inside the box?
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& b, const sphere3& s) {
    if (!ball::usable(b) || !ball::usable(s)) return false;
    const double r = ball::magnitude(s.radius);
    const double c[3] = {s.center.x, s.center.y, s.center.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    for (int i = 0; i < 3; ++i) {
        const double ci = c[i], lo = mn[i], hi = mx[i];
        if (k.sgn([=](auto L) { return L(ci) - L(r) - L(lo); }) == sign::negative) return false;
        if (k.sgn([=](auto L) { return L(hi) - L(ci) - L(r); }) == sign::negative) return false;
    }
    return true;
}

// Is the box inside the ball?
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& s, const aabb3& b) {
    if (!ball::usable(b) || !ball::usable(s)) return false;
    const double c[3] = {s.center.x, s.center.y, s.center.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    double far[3];
    for (int i = 0; i < 3; ++i) {
        const double ci = c[i], lo = mn[i], hi = mx[i];
        // min is at least as far from c as max iff c - min >= max - c
        far[i] = k.sgn([=](auto L) { return (L(ci) + L(ci)) - (L(lo) + L(hi)); }) != sign::negative ? lo : hi;
    }
    const double r = s.radius;
    return k.sgn([=](auto L) {
        auto g = [&](int i) { return L(far[i]) - L(c[i]); };
        const auto g0 = g(0), g1 = g(1), g2 = g(2);
        return L(r) * L(r) - (g0 * g0 + g1 * g1 + g2 * g2);
    }) != sign::negative;
}

// contains(obb3, sphere3) and contains(sphere3, obb3): a closed box (the parallelepiped its axes
// span, read exactly as given) and a closed ball.
// Semantics: a ball touching the box's faces from inside lies in it; a box whose corners touch the
// sphere from inside lies in the ball. Unchecked negative radii act as |r|; NaN, infinite or
// negative extents hold nothing and lie in nothing.

// Is the ball inside the box?
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& b, const sphere3& s) {
    if (!sat::well_formed(b) || !finite(b) || !ball::usable(s)) return false;
    if (s.radius == 0.0) return contains(k, b, s.center);
    const vec3 a[3] = {b.axes[0], b.axes[1], b.axes[2]};
    if (arith::is_zero(k, [=](auto L) { return arith::det3(arith::lift(L, a[0]), arith::lift(L, a[1]), arith::lift(L, a[2])); }))
        return false; // a flat box
    const point3 o = b.center, c = s.center;
    const double r = s.radius;
    for (unsigned i = 0; i < 3; ++i) {
        const vec3 ai = a[i], aj = a[(i + 1) % 3], ak = a[(i + 2) % 3];
        const double h = b.half_extents[i];
        auto room = [=](auto L) { // A_i = h_i |det| - |n_i . (c - o)|
            const auto n = arith::cross(arith::lift(L, aj), arith::lift(L, ak));
            return L(h) * sat::magnitude(arith::dot(n, arith::lift(L, ai))) -
                   L(1.0) * sat::magnitude(arith::dot(n, arith::lift(L, c) - arith::lift(L, o)));
        };
        if (k.sgn(room) == sign::negative) return false;
        if (k.sgn([=](auto L) {
                const auto n = arith::cross(arith::lift(L, aj), arith::lift(L, ak));
                const auto A = room(L);
                const auto one = L(1.0);
                return A * A - L(r) * L(r) * (one * one) * arith::dot(n, n);
            }) == sign::negative)
            return false;
    }
    return true;
}

// Is the box inside the ball?
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& s, const obb3& b) {
    if (!sat::well_formed(b) || !finite(b) || !ball::usable(s)) return false;
    const point3 c = s.center;
    const double r = s.radius;
    for (int m = 0; m < 8; ++m) {
        double f[3]; // the corner's signed extents
        for (unsigned j = 0; j < 3; ++j) f[j] = (m >> j & 1) ? b.half_extents[j] : -b.half_extents[j];
        if (k.sgn([=](auto L) {
                const auto one = L(1.0);
                const auto x = ball_obb::corner_less(L, b, f, c);
                return L(r) * L(r) * (one * one) - arith::dot(x, x);
            }) == sign::negative)
            return false;
    }
    return true;
}

// point3 against sphere3 (the closed ball).
// Semantics: the point intersects the ball iff |p - c| <= r (on the sphere counts).

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& s, const point3& p) {
    return intersects(k, p, s);
}

// sphere3 against sphere3 (closed balls).
// Semantics: intersects iff |c1 - c2| <= r1 + r2 (tangent balls intersect);
// contains(a, b) iff ball b lies inside ball a: r_a >= r_b and |ca - cb| <= r_a - r_b
// (internally tangent counts; equal balls contain each other). Unchecked negative radii act as
// |r|, as in every other pair of the ball.

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& a, const sphere3& b) {
    const double ra = ball::magnitude(a.radius), rb = ball::magnitude(b.radius);
    if (k.sgn([=](auto L) { return L(ra) - L(rb); }) == sign::negative) return false;
    return k.sgn([=](auto L) {
        const auto d = arith::lift(L, a.center) - arith::lift(L, b.center);
        const auto r = L(ra) - L(rb);
        return r * r - arith::dot(d, d);
    }) != sign::negative;
}

// contains(sphere3, segment3 | triangle3 | tetrahedron3): the ball is convex, so it holds the hull
// of the vertices iff it holds each vertex (|v - c|^2 <= r^2, degree 2). Semantics: a vertex on the
// sphere counts; unchecked negative radii act as |r|; a NaN or infinite number holds nothing.

// Every vertex finite and held (in(p)): a convex set holds their hull iff it holds each.
template <std::size_t N, class In>
[[nodiscard]] constexpr bool holds_vertices(const std::array<point3, N>& v, const In& in) {
    for (const point3& p : v)
        if (!finite(p) || !in(p)) return false;
    return true;
}
template <class K, std::size_t N>
[[nodiscard]] constexpr bool holds_all(K& k, const sphere3& s, const std::array<point3, N>& v) {
    return ball::usable(s) && holds_vertices(v, [&](point3 p) { return intersects(k, p, s); });
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& s, const segment3& g) {
    return holds_all(k, s, std::array{g.a, g.b});
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& s, const triangle3& t) {
    return holds_all(k, s, std::array{t.a, t.b, t.c});
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& s, const tetrahedron3& t) {
    return holds_all(k, s, std::array{t.a, t.b, t.c, t.d});
}

// contains(convex_polyhedron3 | frustum3 | kdop<K>, sphere3): the ball in every half-space
// (ball_halfspaces.cppm; semantics of intersects/sphere_pairs.cppm: a set touching the ball from
// inside holds it).

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& p, const sphere3& s) {
    if (!halfspaces::well_formed(p.planes.data(), p.count, convex_polyhedron3::capacity) || !ball::usable(s)) return false;
    return ball_rows::inside(k, p.planes.data(), p.count, s);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const sphere3& s) {
    if (!halfspaces::well_formed(f.planes.data(), 6, 6) || !ball::usable(s)) return false;
    return ball_rows::inside(k, f.planes.data(), 6, s);
}
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const sphere3& s) {
    if (!kdop_slabs::well_formed(b) || !ball::usable(s)) return false;
    const std::array<plane3, N> rows = kdop_slabs::halfspaces(b);
    return ball_rows::inside(k, rows.data(), N, s);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const aabb3&, const sphere3&);
extern template bool exactly<contains_body>(const sphere3&, const aabb3&);
extern template bool exactly<contains_body>(const obb3&, const sphere3&);
extern template bool exactly<contains_body>(const sphere3&, const obb3&);
extern template bool exactly<contains_body>(const sphere3&, const point3&);
extern template bool exactly<contains_body>(const sphere3&, const sphere3&);
extern template bool exactly<contains_body>(const sphere3&, const segment3&);
extern template bool exactly<contains_body>(const sphere3&, const triangle3&);
extern template bool exactly<contains_body>(const sphere3&, const tetrahedron3&);
extern template bool exactly<contains_body>(const convex_polyhedron3&, const sphere3&);
extern template bool exactly<contains_body>(const frustum3&, const sphere3&);
extern template bool exactly<contains_body>(const kdop<6>&, const sphere3&);
extern template bool exactly<contains_body>(const kdop<14>&, const sphere3&);
extern template bool exactly<contains_body>(const kdop<18>&, const sphere3&);
extern template bool exactly<contains_body>(const kdop<26>&, const sphere3&);
} // namespace incidence::detail
