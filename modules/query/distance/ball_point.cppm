// distance: point3 and sphere3, capsule3 and point3: the squared distance and the signed distance
// from a point to a ball or a capsule (a point or a segment swept by a ball).
// Semantics: the closed ball |x - c| <= |r| and the closed capsule (the points within |r| of the
// closed segment ab; a = b is a ball); an unchecked negative radius acts as |r|, as in every pair
// of the ball. signed_distance: |p - core| - |r|, positive outside, negative inside, zero on the
// boundary; squared_distance: the square of the positive part (zero inside). A NaN or an infinite
// number: NaN.
// Method (exact tiers): the core's feature nearest p (the centre; the segment's end or its inside,
// engines/nearest_feature.cppm, degree 2), its squared distance P / S, then the side
// sign(P - r^2 S) (degree 6): zero gives 0 exactly; otherwise the distance is a root of a quadratic
// in polynomials of degree <= 12 (nearest_feature.cppm), rounded correctly by arith::root_value.
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.2 (closest point on a
// segment) and 4.5.1 (capsules as swept spheres).
// Approximate tier: the same feature, sqrt(P / S) - |r| and its square in plain double.
// Error bound: where no deciding sign lies within 2^-40 of its permanent (the yes/no
// pairs' measure: the active set or feature is then plain double's too), for inputs whose nonzero
// magnitudes lie in [2^-120, 2^120], |d~ - d| <= 2^-40 M + 2^-140 for the signed distance and 2^-40 M^2 + 2^-280 for the squared one, M
// the largest magnitude among the inputs' numbers (a row's |d_i| / max |n_i|); the absolute terms
// cover numerators that underflow where nearly equal inputs differ by ulps (tests/query/distance/ball_point.cpp, testkit/distance_checks.hpp).
module;
export module incidence.detail:distance.ball_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.nearest_feature;
import :exactly;

export namespace incidence::detail {

namespace ball_distance {

[[nodiscard]] constexpr bool usable(point3 p, point3 a, point3 b, double r) {
    return is_finite(p) && is_finite(a) && is_finite(b) && is_finite(r);
}

// The signed (or squared) distance from p to the points within |r| of segment ab.
template <class K>
[[nodiscard]] constexpr arith::value_t<K> of(K& k, point3 p, point3 a, point3 b, double r, bool squared) {
    if (!usable(p, a, b, r)) return arith::exact_value(k, __builtin_nan(""));
    const double rad = r < 0.0 ? -r : r;
    const nearest::feature x = nearest::of_segment(k, a, b, p);
    return nearest::with_segment_distance(x, p, [&](auto q) -> arith::value_t<K> {
        const sign side = k.sgn([=](auto L) {
            const auto v = q(L);
            return v.num - L(rad) * L(rad) * v.den;
        });
        if (side == sign::zero || (squared && side == sign::negative)) return arith::exact_value(k, 0.0);
        if (squared) return nearest::ball_squared_distance(k, q, rad);
        return nearest::ball_distance(k, q, rad);
    });
}

} // namespace ball_distance

template <class K>
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const point3& p, const sphere3& s) {
    return ball_distance::of(k, p, s.center, s.center, s.radius, true);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> signed_distance(K& k, const point3& p, const sphere3& s) {
    return ball_distance::of(k, p, s.center, s.center, s.radius, false);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const capsule3& c, const point3& p) {
    return ball_distance::of(k, p, c.a, c.b, c.radius, true);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> signed_distance(K& k, const capsule3& c, const point3& p) {
    return ball_distance::of(k, p, c.a, c.b, c.radius, false);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template double exactly<nearest_body>(const point3&, const sphere3&);
extern template double exactly<signed_body>(const point3&, const sphere3&);
extern template double exactly<nearest_body>(const capsule3&, const point3&);
extern template double exactly<signed_body>(const capsule3&, const point3&);
} // namespace incidence::detail
