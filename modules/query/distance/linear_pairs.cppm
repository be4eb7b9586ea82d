// distance: points, segments, rays and lines against each other (line_line, line_point, line_ray,
// line_segment, point_point, point_ray, point_segment, ray_ray, ray_segment, segment_segment): the
// squared distance between their nearest points, and the distance.
// Semantics: closed sets as in engines/linear.cppm (a segment with equal end points, a ray or a
// line with a zero direction: its one point). A NaN or an infinite number: NaN.
// Method (exact tiers): sets that meet (engines/linear.cppm's signs) are at distance 0. Otherwise,
// with x = O1 + s D1 and y = O2 + t D2 (D = b - a taken exactly for a segment), w = O1 - O2,
// a = D1 . D1, b = D1 . D2, c = D1 . w, e = D2 . D2, f = D2 . w and n = D1 x D2 (|n|^2 = a e - b^2):
//   n != 0 and the free minimiser s = (b f - c e) / |n|^2, t = (a f - b c) / |n|^2 strictly inside
//     both parameter ranges (s > 0 for a ray or a segment, s < 1 for a segment; each a sign of
//     degree 4): the squared distance is (n . w)^2 / |n|^2 (degree 6 over 4);
//   otherwise the minimum of a convex function outside its free minimiser (or along a whole line,
//     n = 0) is reached where a parameter is at an end of its range: the least of each end point (a
//     segment's two, a ray's origin, a point; the first set's origin when it is a line, any of its
//     points) against the other set,
//     a point against a segment, ray or line as in engines/nearest_feature.cppm: the end point
//     nearest, P = |p - v|^2 (degree 2 over 0), or the line, |D x (p - O)|^2 / |D|^2 (4 over 2).
//     Candidates are compared as quotients (degree <= 6); the same pair of points met twice is
//     recognised by its points, and for parallel lines a point-line candidate is the least at once
//     (every point of one line is as far from the other), so no tie is asked of a sign there.
// The distance: sqrt(P / S), the larger root of S t^2 - P (engines/nearest_feature.cppm),
// correctly rounded; the squared distance: P / S correctly rounded.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.1.9 (closest points of two
// segments), with its clamping replaced by the exact comparison of the candidates.
// Approximate tier: the same signs and quotients in plain double (candidates compared by their
// quotients' values). Error bound: where no deciding sign lies within 2^-20 of its permanent (near
// parallel lines the free minimiser's quotient loses about 2^-52 / sin(angle) of its size), for
// inputs whose nonzero magnitudes lie in [2^-120, 2^120], |d~ - d| <= 2^-30 M + 2^-140 for the
// distance and 2^-30 M^2 + 2^-280 for the squared one, M the largest magnitude among the inputs'
// numbers (tests/query/distance/linear_pairs.cpp).
module;
#include <type_traits>
export module incidence.detail:distance.linear_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.nearest_feature;
import :exactly;

export namespace incidence::detail {

namespace linear_distance {

// A candidate pair of nearest points: two points (p and x.o), a point and a linear set's line (p
// and x), or the two sets' lines (x and y).
enum class kind : unsigned char { points, point_line, lines };
struct candidate {
    kind what = kind::points;
    point3 p{};
    linear3 x{}, y{};
};

// f(q) for q(L) -> ratio{P, S}, the candidate's squared distance (one type of q per kind).
template <class F>
constexpr decltype(auto) with_quotient(const candidate& c, F&& f) {
    const linear3 x = c.x, y = c.y;
    const point3 p = c.p;
    if (c.what == kind::points)
        return f([=](auto L) {
            const auto w = arith::lift(L, p) - x.O(L);
            return arith::ratio{arith::dot(w, w), L(1.0)};
        });
    if (c.what == kind::point_line)
        return f([=](auto L) {
            const auto d = x.D(L);
            const auto u = arith::cross(d, arith::lift(L, p) - x.O(L));
            return arith::ratio{arith::dot(u, u), arith::dot(d, d)};
        });
    return f([=](auto L) {
        const auto n = arith::cross(x.D(L), y.D(L));
        const auto t = arith::dot(n, x.O(L) - y.O(L));
        return arith::ratio{t * t, arith::dot(n, n)};
    });
}

// The same pair of nearest points (so no sign need prove their tie).
[[nodiscard]] constexpr bool same(const candidate& u, const candidate& v) {
    if (u.what != v.what) return false;
    const auto same_set = [](const linear3& a, const linear3& b) { return a.o == b.o && a.q == b.q && a.d == b.d && a.kind == b.kind; };
    if (u.what == kind::points) return (u.p == v.p && u.x.o == v.x.o) || (u.p == v.x.o && u.x.o == v.p);
    if (u.what == kind::point_line) return u.p == v.p && same_set(u.x, v.x);
    return same_set(u.x, v.x) && same_set(u.y, v.y);
}

// The nearer of two candidates (the first on a tie); of this table's or another's (C with its own
// same(u, v) and with_quotient(c, f), found by their namespace).
template <class K, class C>
[[nodiscard]] constexpr C nearer(K& k, const C& u, const C& v) {
    if (same(u, v)) return u;
    const sign s =
        with_quotient(u, [&](auto qu) { return with_quotient(v, [&](auto qv) { return nearest::compare_quotients(k, qv, qu); }); });
    return s == sign::negative ? v : u;
}

// Point p against the linear set x: its end point or its line, whichever holds p's nearest point.
template <class K>
[[nodiscard]] constexpr candidate point_against(K& k, point3 p, const linear3& x) {
    if (x.is_point()) return {kind::points, p, x};
    const auto along = [=](auto L) { return arith::dot(x.D(L), arith::lift(L, p) - x.O(L)); };
    if (x.bounded_below() && k.sgn(along) != sign::positive) return {kind::points, p, x};
    if (x.bounded_above() && k.sgn([=](auto L) {
            const auto d = x.D(L);
            return arith::dot(d, d) - along(L);
        }) != sign::positive)
        return {kind::points, p, as_linear(x.q)};
    return {kind::point_line, p, x};
}

// The candidate holding the nearest points of x and y, which do not meet.
template <class K>
[[nodiscard]] constexpr candidate nearest_of(K& k, const linear3& x, const linear3& y) {
    // a point is parallel to everything (no sign asked: its direction is zero by its numbers)
    const bool parallel = x.is_point() || y.is_point() || arith::is_zero<arith::hint::often_zero>(k, [=](auto L) {
                              const auto n = arith::cross(x.D(L), y.D(L));
                              return arith::dot(n, n);
                          });
    if (!parallel) {
        // the free minimiser's numerators: s |n|^2 = b f - c e, t |n|^2 = a f - b c
        const auto sn = [=](auto L) {
            const auto d1 = x.D(L), d2 = y.D(L), w = x.O(L) - y.O(L);
            return arith::dot(d1, d2) * arith::dot(d2, w) - arith::dot(d1, w) * arith::dot(d2, d2);
        };
        const auto tn = [=](auto L) {
            const auto d1 = x.D(L), d2 = y.D(L), w = x.O(L) - y.O(L);
            return arith::dot(d1, d1) * arith::dot(d2, w) - arith::dot(d1, d2) * arith::dot(d1, w);
        };
        const auto nn = [=](auto L) {
            const auto n = arith::cross(x.D(L), y.D(L));
            return arith::dot(n, n);
        };
        const auto inside = [&](const linear3& z, const auto& num) {
            if (z.bounded_below() && k.sgn(num) != sign::positive) return false;
            return !z.bounded_above() || k.sgn([=](auto L) { return nn(L) - num(L); }) == sign::positive;
        };
        if (inside(x, sn) && inside(y, tn)) return {kind::lines, {}, x, y};
    }
    // an end point of one against the other (a line's origin where both are lines)
    candidate c[4];
    int m = 0;
    c[m++] = point_against(k, x.o, y);
    if (x.bounded_above() && !x.is_point()) c[m++] = point_against(k, x.q, y);
    if (y.bounded_below() || y.is_point()) c[m++] = point_against(k, y.o, x);
    if (y.bounded_above() && !y.is_point()) c[m++] = point_against(k, y.q, x);
    // parallel lines: a point's distance to the other line is the lines' distance, a lower bound
    // of every candidate, so a candidate of that kind is the least
    if (parallel)
        for (int i = 0; i < m; ++i)
            if (c[i].what == kind::point_line) return c[i];
    candidate best = c[0];
    for (int i = 1; i < m; ++i) best = nearer(k, best, c[i]);
    return best;
}

[[nodiscard]] constexpr bool usable(const linear3& x) { return finite(x.o) && finite(x.q) && finite(x.d); }

// The squared distance of x and y (P / S) or, with `root`, the distance.
template <class K>
[[nodiscard]] constexpr arith::value_t<K> of(K& k, const linear3& x, const linear3& y, bool root) {
    if (!usable(x) || !usable(y)) return arith::exact_value(k, __builtin_nan(""));
    if (linear_linear(k, x, y)) return arith::exact_value(k, 0.0);
    return with_quotient(nearest_of(k, x, y), [&](auto q) -> arith::value_t<K> {
        if (root) return nearest::root_distance(k, q, false);
        return arith::value(k, q);
    });
}

// The pairs the table answers, in the catalog's order of their names (and the triangle after them).
template <class A>
concept linear_part = std::is_same_v<A, point3> || std::is_same_v<A, segment3> || std::is_same_v<A, ray3> || std::is_same_v<A, line3>;
template <class A>
inline constexpr int rank = std::is_same_v<A, line3>      ? 0
                            : std::is_same_v<A, point3>   ? 1
                            : std::is_same_v<A, ray3>     ? 2
                            : std::is_same_v<A, segment3> ? 3
                                                          : 4; // triangle3 (distance/triangle_pairs.cppm)

// Two sets of one kind in a fixed order of their numbers, so that every tier (plain double too)
// gives both argument orders the same value.
template <class K, class A, class B>
[[nodiscard]] constexpr arith::value_t<K> ordered(K& k, const A& a, const B& b, bool root) {
    if constexpr (std::is_same_v<A, B>)
        if (before(b, a)) return of(k, as_linear(b), as_linear(a), root);
    return of(k, as_linear(a), as_linear(b), root);
}

} // namespace linear_distance

template <class K, linear_distance::linear_part A, linear_distance::linear_part B>
requires(linear_distance::rank<A> <= linear_distance::rank<B>)
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const A& a, const B& b) {
    return linear_distance::ordered(k, a, b, false);
}
template <class K, linear_distance::linear_part A, linear_distance::linear_part B>
requires(linear_distance::rank<A> <= linear_distance::rank<B>)
[[nodiscard]] constexpr arith::value_t<K> distance(K& k, const A& a, const B& b) {
    return linear_distance::ordered(k, a, b, true);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template double exactly<nearest_body>(const line3&, const line3&);
extern template double exactly<nearest_body>(const line3&, const point3&);
extern template double exactly<nearest_body>(const line3&, const ray3&);
extern template double exactly<nearest_body>(const line3&, const segment3&);
extern template double exactly<nearest_body>(const point3&, const point3&);
extern template double exactly<nearest_body>(const point3&, const ray3&);
extern template double exactly<nearest_body>(const point3&, const segment3&);
extern template double exactly<nearest_body>(const ray3&, const ray3&);
extern template double exactly<nearest_body>(const ray3&, const segment3&);
extern template double exactly<nearest_body>(const segment3&, const segment3&);
extern template double exactly<euclidean_body>(const line3&, const line3&);
extern template double exactly<euclidean_body>(const line3&, const point3&);
extern template double exactly<euclidean_body>(const line3&, const ray3&);
extern template double exactly<euclidean_body>(const line3&, const segment3&);
extern template double exactly<euclidean_body>(const point3&, const point3&);
extern template double exactly<euclidean_body>(const point3&, const ray3&);
extern template double exactly<euclidean_body>(const point3&, const segment3&);
extern template double exactly<euclidean_body>(const ray3&, const ray3&);
extern template double exactly<euclidean_body>(const ray3&, const segment3&);
extern template double exactly<euclidean_body>(const segment3&, const segment3&);
} // namespace incidence::detail
