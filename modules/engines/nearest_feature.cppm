// The nearest feature (a vertex, an edge or a face) of a segment, a triangle or a set of triangles
// to a point, its squared distance as a quotient of polynomials, and the distances a point's
// distance queries return from it: the engine of distance/ball_point, distance/triangles_point and
// distance/halfspace_point.
// Semantics: a closed segment (a = b: a point) and a closed triangle (a collinear one: its three
// edges as segments).
// Method (exact tiers): a feature's squared distance to p is P / S with S > 0 (no lifted 1s pad
// the degrees: the exact stages' expansions of the roots below would outgrow their types):
//   vertex v:          P = |p - v|^2, S = 1 (degree 2 over 0);
//   edge uv:           P = |(v - u) x (p - u)|^2, S = |v - u|^2 (Lagrange's identity; 4 over 2);
//   face abc:          P = (n . (p - a))^2, S = |n|^2, n = (b - a) x (c - a) (6 over 4).
// The segment's feature: with d = b - a and w = p - a, d . w <= 0: a; d . w >= |d|^2: b; else
// the edge (degree 2). The triangle's: Ericson's Voronoi-region walk (section 5.1.5,
// ClosestPtPointTriangle) on exact signs: the six dot products d1..d6 (degree 2) and the three
// region determinants va, vb, vc (degree 4); with n = 0 (a collinear triangle) the nearest of its
// three edges' features. Two features are ordered by sign(P1 S2 - P2 S1) (degree <= 10); a feature
// met twice (a vertex or an edge that neighbouring triangles share) is recognised by its points,
// so no tie between them is ever asked of a sign.
// A distance from P / S and a radius r >= 0 is a root of a quadratic whose coefficients are
// polynomials, which arith::root_value rounds correctly (the enclosures and plain values are taken
// from P and S directly, below):
//   sqrt(P / S):              the larger root of S t^2 - P;
//   -sqrt(P / S):             the smaller root of the same;
//   sqrt(P / S) - r:          the larger root of S t^2 + 2 S r t + (S r^2 - P);
//   (sqrt(P / S) - r)^2 (the squared distance to a ball from outside, sqrt(P / S) >= r): the
//                             smaller root of S^2 t^2 - 2 S (P + r^2 S) t + (P - r^2 S)^2
//                             (its roots are (sqrt(P / S) -+ r)^2).
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.2 (closest point on a
// segment) and 5.1.5 (on a triangle); Muller et al., Handbook of Floating-Point Arithmetic (2018),
// section 2.2 (rounding by the signs at the midpoints, arith/value.cppm).
// Approximate tier: the same walk in plain double, then sqrt(P / S) (less r) directly
// (modules/query/distance/*.cppm state each bound).
module;
#include <cstddef>
#include <type_traits>
export module incidence.detail:engines.nearest_feature;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence::detail {

namespace nearest {

// search(k), a search for the nearest feature or active set that reports whether it found one
// (settled(result)); where k's signs refute every candidate (plain double's, within rounding of a
// tie), the same search on exact signs, which name one.
template <class K, class Search, class Settled>
[[nodiscard]] constexpr auto found_or_exactly(K& k, Search search, Settled settled) {
    auto result = search(k);
    if constexpr (!std::is_same_v<K, arith::exact_kernel>)
        if (!settled(result)) {
            arith::exact_kernel e;
            result = search(e);
        }
    return result;
}

enum class kind : unsigned char { vertex, edge, face };

// A feature: a vertex a, an edge ab or a face abc.
struct feature {
    kind what = kind::vertex;
    point3 a{}, b{}, c{};
};

// f(q) for q(L) -> ratio{P, S}, the squared distance from p to feature x, a vertex or an edge (one
// type of q per kind).
template <class F>
constexpr decltype(auto) with_segment_distance(const feature& x, point3 p, F&& f) {
    if (x.what == kind::vertex) {
        const point3 a = x.a;
        return f([=](auto L) {
            const auto w = arith::lift(L, p) - arith::lift(L, a);
            return arith::ratio{arith::dot(w, w), L(1.0)};
        });
    }
    const point3 a = x.a, b = x.b;
    return f([=](auto L) {
        const auto d = arith::lift(L, b) - arith::lift(L, a), w = arith::lift(L, p) - arith::lift(L, a);
        const auto c = arith::cross(d, w);
        return arith::ratio{arith::dot(c, c), arith::dot(d, d)};
    });
}
// The same for any feature.
template <class F>
constexpr decltype(auto) with_distance(const feature& x, point3 p, F&& f) {
    if (x.what != kind::face) return with_segment_distance(x, p, f);
    const point3 a = x.a, b = x.b, c = x.c;
    return f([=](auto L) {
        const auto A = arith::lift(L, a);
        const auto n = arith::cross(arith::lift(L, b) - A, arith::lift(L, c) - A);
        const auto t = arith::dot(n, arith::lift(L, p) - A);
        return arith::ratio{t * t, arith::dot(n, n)};
    });
}

// sign(dist(x)^2 - dist(y)^2) from p; zero for the same feature.
[[nodiscard]] constexpr bool same(const feature& x, const feature& y) {
    if (x.what != y.what) return false;
    switch (x.what) {
    case kind::vertex: return x.a == y.a;
    case kind::edge: return (x.a == y.a && x.b == y.b) || (x.a == y.b && x.b == y.a);
    default: return x.a == y.a && x.b == y.b && x.c == y.c;
    }
}
// sign(P1 / S1 - P2 / S2) for two quotients (S > 0): the kernel's sign of P1 S2 - P2 S1; in plain
// double the quotients themselves are compared, since the products (degree up to 10) leave double's
// range long before the distances do.
template <class K, class Q1, class Q2>
[[nodiscard]] constexpr sign compare_quotients(K& k, const Q1& qx, const Q2& qy) {
    if constexpr (std::is_same_v<K, arith::approx_kernel>) {
        const auto u = qx(arith::lift_double{});
        const auto v = qy(arith::lift_double{});
        const double a = u.num / u.den, b = v.num / v.den;
        return a < b ? sign::negative : (b < a ? sign::positive : sign::zero);
    } else {
        return k.sgn([=](auto L) {
            const auto u = qx(L);
            const auto v = qy(L);
            return u.num * v.den - v.num * u.den;
        });
    }
}
template <class K>
[[nodiscard]] constexpr sign closer(K& k, point3 p, const feature& x, const feature& y) {
    if (same(x, y)) return sign::zero;
    return with_distance(x, p, [&](auto qx) { return with_distance(y, p, [&](auto qy) { return compare_quotients(k, qx, qy); }); });
}

// The segment ab's feature nearest p.
template <class K>
[[nodiscard]] constexpr feature of_segment(K& k, point3 a, point3 b, point3 p) {
    if (a == b) return {kind::vertex, a};
    const auto along = [=](auto L) { return arith::dot(arith::lift(L, b) - arith::lift(L, a), arith::lift(L, p) - arith::lift(L, a)); };
    if (k.sgn(along) != sign::positive) return {kind::vertex, a};
    if (k.sgn([=](auto L) {
            const auto d = arith::lift(L, b) - arith::lift(L, a);
            return arith::dot(d, d) - along(L);
        }) != sign::positive)
        return {kind::vertex, b};
    return {kind::edge, a, b};
}

// The nearer of two features (the first on a tie).
template <class K>
[[nodiscard]] constexpr feature nearer(K& k, point3 p, const feature& x, const feature& y) {
    return closer(k, p, y, x) == sign::negative ? y : x;
}

// The triangle abc's feature nearest p.
template <class K>
[[nodiscard]] constexpr feature of_triangle(K& k, const triangle3& t, point3 p) {
    const point3 a = t.a, b = t.b, c = t.c;
    if (arith::is_zero<arith::hint::often_zero>(k, [=](auto L) {
            const auto A = arith::lift(L, a);
            const auto n = arith::cross(arith::lift(L, b) - A, arith::lift(L, c) - A);
            return arith::dot(n, n);
        })) {
        const feature x = nearer(k, p, of_segment(k, a, b, p), of_segment(k, b, c, p));
        return nearer(k, p, x, of_segment(k, c, a, p));
    }
    // d(u, v, w, z) = (v - u) . (z - w), the dot products of Ericson's walk
    const auto dd = [](point3 u, point3 v, point3 w, point3 z) {
        return [=](auto L) { return arith::dot(arith::lift(L, v) - arith::lift(L, u), arith::lift(L, z) - arith::lift(L, w)); };
    };
    const auto d1 = dd(a, b, a, p), d2 = dd(a, c, a, p), d3 = dd(a, b, b, p), d4 = dd(a, c, b, p), d5 = dd(a, b, c, p), d6 = dd(a, c, c, p);
    const auto s = [&](auto f) { return k.sgn(f); };
    const sign s1 = s(d1), s2 = s(d2);
    if (s1 != sign::positive && s2 != sign::positive) return {kind::vertex, a};
    const sign s3 = s(d3), s43 = s([=](auto L) { return d4(L) - d3(L); });
    if (s3 != sign::negative && s43 != sign::positive) return {kind::vertex, b};
    if (s1 != sign::negative && s3 != sign::positive && s([=](auto L) { return d1(L) * d4(L) - d3(L) * d2(L); }) != sign::positive)
        return {kind::edge, a, b};
    const sign s6 = s(d6), s56 = s([=](auto L) { return d5(L) - d6(L); });
    if (s6 != sign::negative && s56 != sign::positive) return {kind::vertex, c};
    if (s2 != sign::negative && s6 != sign::positive && s([=](auto L) { return d5(L) * d2(L) - d1(L) * d6(L); }) != sign::positive)
        return {kind::edge, a, c};
    if (s43 != sign::negative && s56 != sign::negative && s([=](auto L) { return d3(L) * d6(L) - d5(L) * d4(L); }) != sign::positive)
        return {kind::edge, b, c};
    return {kind::face, a, b, c};
}

// The nearest feature of n triangles tri(i) to p (n > 0).
template <class K, class Tri>
[[nodiscard]] constexpr feature of_triangles(K& k, point3 p, std::size_t n, const Tri& tri) {
    feature best = of_triangle(k, tri(0), p);
    for (std::size_t i = 1; i < n; ++i) best = nearer(k, p, best, of_triangle(k, tri(i), p));
    return best;
}

// sign(P): zero iff p lies on the feature.
template <class K>
[[nodiscard]] constexpr sign distance_sign(K& k, const feature& x, point3 p) {
    if (x.what == kind::vertex) return x.a == p ? sign::zero : sign::positive;
    return with_distance(x, p, [&](auto q) { return k.sgn([=](auto L) { return q(L).num; }); });
}

// The distances from P / S (q) in kernel k's values. Rounded: a root of the quadratics above
// (arith::root_value). Enclosed and plain: from P and S directly (sqrt(P / S), then - r, then
// squared, each rounded outward or once), since the quadratics' discriminants cancel (for the
// ball, b^2 - a c = S P is computed as S^2 r^2 - S (S r^2 - P)).
template <class K>
inline constexpr bool direct_values = arith::value_mode_of<K>() != arith::value_mode::rounded;

template <class Q>
[[nodiscard]] constexpr interval enclosed_root_distance(const Q& q) {
    const auto x = q(arith::lift_filter{});
    return arith::square_root(arith::divide(arith::enclose(x.num), arith::enclose(x.den)));
}
template <class Q>
[[nodiscard]] constexpr double plain_root_distance(const Q& q) {
    const auto x = q(arith::lift_double{});
    const double v = x.num / x.den; // may round below zero where P cancels
    return arith::sqrt(v > 0.0 ? v : 0.0);
}

// sqrt(P / S) or -sqrt(P / S).
template <class K, class Q>
[[nodiscard]] constexpr arith::value_t<K> root_distance(K& k, const Q& q, bool negative) {
    if constexpr (arith::encloses<K>) {
        const interval u = enclosed_root_distance(q);
        return negative ? arith::negate(u) : u;
    } else {
        if (direct_values<K> || arith::values_discarded(k)) {
            const double u = plain_root_distance(q);
            return negative ? -u : u;
        }
        return arith::root_value(
            k,
            [=](auto L) {
                const auto x = q(L);
                return arith::quadratic{x.den, L(0.0) * x.den, -x.num};
            },
            negative ? arith::root::smaller : arith::root::larger);
    }
}
// sqrt(P / S) - r, r >= 0.
template <class K, class Q>
[[nodiscard]] constexpr arith::value_t<K> ball_distance(K& k, const Q& q, double r) {
    if constexpr (arith::encloses<K>) {
        return arith::sub(enclosed_root_distance(q), arith::point_interval(r));
    } else {
        if (direct_values<K> || arith::values_discarded(k)) return plain_root_distance(q) - r;
        return arith::root_value(
            k,
            [=](auto L) {
                const auto x = q(L);
                const auto R = L(r);
                return arith::quadratic{x.den, x.den * R, x.den * (R * R) - x.num};
            },
            arith::root::larger);
    }
}
// (sqrt(P / S) - r)^2 for sqrt(P / S) > r >= 0.
template <class K, class Q>
[[nodiscard]] constexpr arith::value_t<K> ball_squared_distance(K& k, const Q& q, double r) {
    if constexpr (arith::encloses<K>) {
        const interval u = arith::sub(enclosed_root_distance(q), arith::point_interval(r));
        const interval v{u.lo > 0.0 ? u.lo : 0.0, u.hi > 0.0 ? u.hi : 0.0};
        return arith::mul(v, v);
    } else {
        if (direct_values<K> || arith::values_discarded(k)) {
            const double u = plain_root_distance(q) - r;
            return u * u;
        }
        return arith::root_value(
            k,
            [=](auto L) {
                const auto x = q(L);
                const auto R = L(r);
                const auto rs = (R * R) * x.den;
                const auto gap = x.num - rs;
                return arith::quadratic{x.den * x.den, -(x.den * (x.num + rs)), gap * gap};
            },
            arith::root::smaller);
    }
}

} // namespace nearest

} // namespace incidence::detail
