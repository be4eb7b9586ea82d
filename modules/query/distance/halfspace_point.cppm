// distance: convex_polyhedron3, frustum3 and kdop<K> against point3: the squared distance and the
// signed distance from a point to a set of half-spaces n_i . x <= d_i (a k-DOP's slabs as its
// 2 x K/2 rows, read exactly).
// Semantics: the closed half-space set (possibly empty or unbounded; a zero normal is all of space
// when its offset is >= 0 and nothing otherwise). signed_distance: the distance to the set outside
// it, minus the distance to its boundary inside it (zero on the boundary); squared_distance: zero
// inside. An empty set: +infinity for both (no point is near); a set without a boundary (every row
// all of space): -infinity inside. A non-finite number, a count outside [0, capacity] or an empty
// k-DOP slab: NaN.
// Method (exact tiers): with e_i = n_i . p - d_i (degree 2), p is outside iff some e_i > 0. Then
// the projection's active set (engines/ball_halfspaces.cppm: one, two or three rows with
// independent normals whose KKT test holds, the set plain double names first; signs of degree <= 6)
// gives the squared distance P / S (degree 4 / 2, 6 / 4 or 8 / 6), correctly rounded as a
// quotient, and its square root as the larger root of S t^2 - P (engines/nearest_feature.cppm).
// Inside, the boundary's nearest point lies on the plane of the row with the largest
// e_i / |n_i| (every row's plane is at least as far as the boundary, convexity): rows ordered by
// sign(e_j^2 |n_i|^2 - e_i^2 |n_j|^2) (degree 6), and -|e_i| / |n_i| is the smaller root of
// |n_i|^2 t^2 - e_i^2.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.1 (closest points by Voronoi
// regions); Boyd and Vandenberghe, Convex Optimization (2004), sections 5.5.3 (KKT conditions) and
// 8.1 (projection onto a polyhedron, distance to its boundary).
// Approximate tier: the same signs and roots in plain double (rows compared by their quotients'
// values; where its signs refute every active set, within rounding of a tie, exact signs name one).
// Error bound: where no deciding sign lies within 2^-40 of its permanent (the yes/no
// pairs' measure: the active set or feature is then plain double's too), for inputs whose nonzero
// magnitudes lie in [2^-120, 2^120], |d~ - d| <= 2^-40 M + 2^-140 for the signed distance and 2^-40 M^2 + 2^-280 for the squared one, M
// the largest magnitude among the inputs' numbers (a row's |d_i| / max |n_i|); the absolute terms
// cover numerators that underflow where nearly equal inputs differ by ulps (tests/query/distance/halfspace_point.cpp, testkit/distance_checks.hpp).
module;
#include <array>
#include <type_traits>
export module incidence.detail:distance.halfspace_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.ball_halfspaces;
import :engines.halfspace_slabs;
import :engines.kdop;
import :engines.nearest_feature;
import :exactly;

export namespace incidence::detail {

namespace rows_distance {

// The signed (or squared) distance from p to the m rows (well formed: the caller checks).
template <class K>
[[nodiscard]] constexpr arith::value_t<K> of(K& k, const plane3* planes, int m, point3 p, bool squared) {
    if (!is_finite(p)) return arith::exact_value(k, __builtin_nan(""));
    const ball_rows::rows r(planes, m);
    constexpr double inf = __builtin_huge_val();
    if (r.empty) return arith::exact_value(k, inf);
    const ball_rows::sides s = ball_rows::sides_of(k, r, p);
    if (s.outside) {
        const ball_rows::found f = nearest::found_or_exactly(
            k,
            [&](auto& kernel) {
                if constexpr (std::is_same_v<std::remove_reference_t<decltype(kernel)>, K>) return ball_rows::nearest(kernel, r, p, s);
                else return ball_rows::nearest(kernel, r, p, ball_rows::sides_of(kernel, r, p));
            },
            [](const ball_rows::found& x) { return x.any; });
        if (!f.any) return arith::exact_value(k, inf); // the rows are empty
        return ball_rows::with_distance(r, p, f.set, [&](auto q) -> arith::value_t<K> {
            if (squared) return arith::value(k, q);
            return nearest::root_distance(k, q, false);
        });
    }
    if (squared) return arith::exact_value(k, 0.0);
    if (r.n == 0) return arith::exact_value(k, -inf);
    unsigned best = 0;
    for (unsigned j = 1; j < r.n; ++j) {
        const plane3 a = r[best], b = r[j];
        const auto depth = [=](const plane3& h) {
            return [=](auto L) {
                const auto e = ball_rows::excess(L, h, p);
                const auto n = arith::lift(L, h.normal);
                return arith::ratio{e * e, arith::dot(n, n)};
            };
        };
        if (nearest::compare_quotients(k, depth(b), depth(a)) == sign::negative) best = j;
    }
    const plane3 h = r[best];
    if (k.sgn([=](auto L) { return ball_rows::excess(L, h, p); }) == sign::zero) return arith::exact_value(k, 0.0);
    return nearest::root_distance(
        k,
        [=](auto L) {
            const auto e = ball_rows::excess(L, h, p);
            const auto n = arith::lift(L, h.normal);
            return arith::ratio{e * e, arith::dot(n, n)};
        },
        true);
}

template <class K, int N>
[[nodiscard]] constexpr arith::value_t<K> of(K& k, const kdop<N>& b, point3 p, bool squared) {
    if (!kdop_slabs::well_formed(b)) return arith::exact_value(k, __builtin_nan(""));
    const std::array<plane3, N> rows = kdop_slabs::halfspaces(b);
    return of(k, rows.data(), N, p, squared);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> of(K& k, const convex_polyhedron3& c, point3 p, bool squared) {
    if (!halfspaces::well_formed(c.planes.data(), c.count, convex_polyhedron3::capacity)) return arith::exact_value(k, __builtin_nan(""));
    return of(k, c.planes.data(), c.count, p, squared);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> of(K& k, const frustum3& f, point3 p, bool squared) {
    if (!halfspaces::well_formed(f.planes.data(), 6, 6)) return arith::exact_value(k, __builtin_nan(""));
    return of(k, f.planes.data(), 6, p, squared);
}

} // namespace rows_distance

template <class K>
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const convex_polyhedron3& c, const point3& p) {
    return rows_distance::of(k, c, p, true);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> signed_distance(K& k, const convex_polyhedron3& c, const point3& p) {
    return rows_distance::of(k, c, p, false);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const frustum3& f, const point3& p) {
    return rows_distance::of(k, f, p, true);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> signed_distance(K& k, const frustum3& f, const point3& p) {
    return rows_distance::of(k, f, p, false);
}
template <class K, int N>
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const kdop<N>& b, const point3& p) {
    return rows_distance::of(k, b, p, true);
}
template <class K, int N>
[[nodiscard]] constexpr arith::value_t<K> signed_distance(K& k, const kdop<N>& b, const point3& p) {
    return rows_distance::of(k, b, p, false);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template double exactly<nearest_body>(const convex_polyhedron3&, const point3&);
extern template double exactly<signed_body>(const convex_polyhedron3&, const point3&);
extern template double exactly<nearest_body>(const frustum3&, const point3&);
extern template double exactly<signed_body>(const frustum3&, const point3&);
extern template double exactly<nearest_body>(const kdop<6>&, const point3&);
extern template double exactly<signed_body>(const kdop<6>&, const point3&);
extern template double exactly<nearest_body>(const kdop<14>&, const point3&);
extern template double exactly<signed_body>(const kdop<14>&, const point3&);
extern template double exactly<nearest_body>(const kdop<18>&, const point3&);
extern template double exactly<signed_body>(const kdop<18>&, const point3&);
extern template double exactly<nearest_body>(const kdop<26>&, const point3&);
extern template double exactly<signed_body>(const kdop<26>&, const point3&);
} // namespace incidence::detail
