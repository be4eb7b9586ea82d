// distance: a triangle against a point, a segment, a ray, a line and a triangle (line_triangle,
// point_triangle, ray_triangle, segment_triangle, triangle_triangle): the squared distance between
// their nearest points, and the distance.
// Semantics: closed triangles (a collinear one: its hull, a segment or a point) and the linear sets
// of engines/linear.cppm. A NaN or an infinite number: NaN.
// Method (exact tiers): sets that meet (the yes/no bodies, query/intersects/triangle_pairs.cppm) are
// at distance 0. Otherwise the nearest points of two convex sets that do not meet can be taken with
// one of them at a vertex or on an edge of its set: where both lie inside (a triangle's face, a
// linear set's interior), the segment joining them is normal to both, so the sets are parallel and
// the nearest points slide together until one reaches an edge or an end. The candidates:
//   a point (a linear set's end points, a ray's origin, a line's origin; a triangle's vertices)
//     against the other triangle: the triangle's feature nearest it (Ericson's region walk,
//     engines/nearest_feature.cppm; signs of degree <= 4) and its squared distance P / S (a vertex
//     2 over 0, an edge 4 over 2, the face 6 over 4);
//   each edge of the triangle against the linear set, and against each edge of the other
//     triangle: the segment pairs' nearest candidate (distance/linear_pairs.cppm; a free
//     minimiser 6 over 4);
// the least of them by exact comparisons of quotients (degree <= 10); the same pair of points met
// twice (a vertex and an edge's end point, an edge's line from two sides) is recognised by its
// points, so no tie between them is asked of a sign.
// The distance: sqrt(P / S), the larger root of S t^2 - P (engines/nearest_feature.cppm),
// correctly rounded; the squared distance: P / S correctly rounded.
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.5 (closest point on a
// triangle), 5.1.9 (of two segments) and 5.1.10 (of a segment and a triangle: the candidates).
// Approximate tier: the same walk, candidates and quotients in plain double. Error bound as for the
// linear pairs: where no deciding sign lies within 2^-20 of its permanent, for inputs whose nonzero
// magnitudes lie in [2^-120, 2^120], |d~ - d| <= 2^-30 M + 2^-140 for the distance and
// 2^-30 M^2 + 2^-280 for the squared one, M the largest magnitude among the inputs' numbers
// (tests/query/distance/triangle_pairs.cpp).
module;
#include <type_traits>
export module incidence.detail:distance.triangle_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.nearest_feature;
import :engines.triangle;
import :intersects.triangle_pairs;
import :distance.linear_pairs;
import :exactly;

export namespace incidence::detail {

namespace triangle_distance {

// A candidate: point p against a triangle's feature f, or a pair of linear sets' points (c).
struct candidate {
    bool on_triangle = false;
    nearest::feature f{};
    point3 p{};
    linear_distance::candidate c{};
};

template <class F>
constexpr decltype(auto) with_quotient(const candidate& u, F&& f) {
    if (u.on_triangle) return nearest::with_distance(u.f, u.p, f);
    return linear_distance::with_quotient(u.c, f);
}

[[nodiscard]] constexpr bool same_points(point3 a, point3 b, point3 c, point3 d) { return (a == c && b == d) || (a == d && b == c); }
// u (a point against a feature) and v (linear sets' points) name the same pair of points.
[[nodiscard]] constexpr bool same_mixed(const candidate& u, const candidate& v) {
    if (u.f.what == nearest::kind::vertex && v.c.what == linear_distance::kind::points) return same_points(u.p, u.f.a, v.c.p, v.c.x.o);
    if (u.f.what == nearest::kind::edge && v.c.what == linear_distance::kind::point_line && v.c.x.kind == extent::segment)
        return u.p == v.c.p && same_points(u.f.a, u.f.b, v.c.x.o, v.c.x.q);
    return false;
}
[[nodiscard]] constexpr bool same(const candidate& u, const candidate& v) {
    if (u.on_triangle && v.on_triangle) return u.p == v.p && nearest::same(u.f, v.f);
    if (!u.on_triangle && !v.on_triangle) return linear_distance::same(u.c, v.c);
    return u.on_triangle ? same_mixed(u, v) : same_mixed(v, u);
}

using linear_distance::nearer;

template <class K>
[[nodiscard]] constexpr candidate point_against(K& k, point3 p, const triangle3& t) {
    return {true, nearest::of_triangle(k, t, p), p, {}};
}
[[nodiscard]] constexpr linear3 edge(const triangle3& t, int i) {
    const point3 v[3] = {t.a, t.b, t.c};
    return as_linear(segment3{v[i], v[(i + 1) % 3]});
}
template <class K>
[[nodiscard]] constexpr candidate edges_against(K& k, const linear3& a, const linear3& b) {
    return {false, {}, {}, linear_distance::nearest_of(k, a, b)};
}

// The candidate holding the nearest points of x and t, which do not meet.
template <class K>
[[nodiscard]] constexpr candidate nearest_of(K& k, const linear3& x, const triangle3& t) {
    candidate best = point_against(k, x.o, t);
    if (x.is_point()) return best;
    if (x.bounded_above()) best = nearer(k, best, point_against(k, x.q, t));
    for (int i = 0; i < 3; ++i) best = nearer(k, best, edges_against(k, edge(t, i), x));
    return best;
}
template <class K>
[[nodiscard]] constexpr candidate nearest_of(K& k, const triangle3& s, const triangle3& t) {
    candidate best = point_against(k, s.a, t);
    best = nearer(k, best, point_against(k, s.b, t));
    best = nearer(k, best, point_against(k, s.c, t));
    best = nearer(k, best, point_against(k, t.a, s));
    best = nearer(k, best, point_against(k, t.b, s));
    best = nearer(k, best, point_against(k, t.c, s));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) best = nearer(k, best, edges_against(k, edge(s, i), edge(t, j)));
    return best;
}

template <class K>
[[nodiscard]] constexpr arith::value_t<K> value(K& k, const candidate& c, bool root) {
    return with_quotient(c, [&](auto q) -> arith::value_t<K> {
        if (root) return nearest::root_distance(k, q, false);
        return arith::value(k, q);
    });
}

template <class K, class A>
[[nodiscard]] constexpr arith::value_t<K> of(K& k, const A& a, const triangle3& t, bool root) {
    if (!finite(a) || !finite(t)) return arith::exact_value(k, __builtin_nan(""));
    if (detail::intersects(k, a, t)) return arith::exact_value(k, 0.0);
    if constexpr (std::is_same_v<A, triangle3>) return value(k, before(t, a) ? nearest_of(k, t, a) : nearest_of(k, a, t), root);
    else return value(k, nearest_of(k, as_linear(a), t), root);
}

} // namespace triangle_distance

template <class K, class A>
requires(linear_distance::linear_part<A> || std::is_same_v<A, triangle3>)
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const A& a, const triangle3& t) {
    return triangle_distance::of(k, a, t, false);
}
template <class K, class A>
requires(linear_distance::linear_part<A> || std::is_same_v<A, triangle3>)
[[nodiscard]] constexpr arith::value_t<K> distance(K& k, const A& a, const triangle3& t) {
    return triangle_distance::of(k, a, t, true);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template double exactly<nearest_body>(const line3&, const triangle3&);
extern template double exactly<nearest_body>(const point3&, const triangle3&);
extern template double exactly<nearest_body>(const ray3&, const triangle3&);
extern template double exactly<nearest_body>(const segment3&, const triangle3&);
extern template double exactly<nearest_body>(const triangle3&, const triangle3&);
extern template double exactly<euclidean_body>(const line3&, const triangle3&);
extern template double exactly<euclidean_body>(const point3&, const triangle3&);
extern template double exactly<euclidean_body>(const ray3&, const triangle3&);
extern template double exactly<euclidean_body>(const segment3&, const triangle3&);
extern template double exactly<euclidean_body>(const triangle3&, const triangle3&);
} // namespace incidence::detail
