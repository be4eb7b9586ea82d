// distance: aabb3 and point3, the squared distance to the box's nearest and farthest point, and the
// signed distance.
// Semantics: the closed box (an inverted box, or a NaN or an infinite number: NaN).
// signed_distance: the distance to the box outside it, minus the distance to its boundary inside
// (zero on the boundary).
// Method: per axis, the gap to the nearer face when the point lies outside the slab (zero inside)
// for the nearest point, to the farther face for the farthest (the sign of 2 p - min - max,
// degree 1); the value is the sum of the squared gaps, a polynomial of degree 2 (arith::value:
// correctly rounded, enclosed or plain). Source: Ericson, Real-Time Collision Detection (2005),
// section 5.1.3 (SqDistPointAABB).
// The signed distance outside: the square root of that sum, the larger root of t^2 - sum
// (engines/nearest_feature.cppm), correctly rounded; inside: the largest of the six differences
// min_i - p_i and p_i - max_i (each <= 0), ordered by comparing differences (degree 1), and the
// difference correctly rounded.
// Approximate tier: each gap rounds once, each square once, two sums: |d~ - d| <= gamma_5 d + 2^-1070
// (Higham, Accuracy and Stability of Numerical Algorithms, 2002, section 3.1), for gaps whose squares
// do not overflow; the signed distance within 2^-50 (|d| + 2^-1000) outside (one more rounding for
// the square root), and the difference rounded once inside (tests/query/distance/box_point.cpp).
module;
#include <array>
#include <utility>
export module incidence.detail:distance.box_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.nearest_feature;
import :engines.ball_obb;
import :engines.separating_axes;
import :exactly;

export namespace incidence::detail {

enum class distance_kind : unsigned char { nearest, farthest };

[[nodiscard]] constexpr bool box_point_usable(const aabb3& b, const point3& p) {
    const double pc[3] = {p.x, p.y, p.z}, mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    bool ok = true;
    for (int i = 0; i < 3; ++i) ok = ok && is_finite(pc[i]) && is_finite(mn[i]) && is_finite(mx[i]) && mn[i] <= mx[i];
    return ok;
}

// The sum of the squared gaps, or, with `signed_root`, its square root.
template <class K>
[[nodiscard]] constexpr arith::value_t<K> box_squared_distance(K& k, const aabb3& b, const point3& p, distance_kind kind,
                                                               bool signed_root = false) {
    const double pc[3] = {p.x, p.y, p.z}, mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    if (!box_point_usable(b, p)) return arith::exact_value(k, __builtin_nan(""));
    // the gap per axis: from lo to hi (the square is what counts), lo = hi for a zero gap
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
        if (kind == distance_kind::nearest) {
            lo[i] = hi[i] = pc[i];
            if (arith::compare(k, pc[i], mn[i]) == sign::negative) lo[i] = mn[i];
            else if (arith::compare(k, pc[i], mx[i]) == sign::positive) hi[i] = mx[i];
        } else {
            const double m = mn[i], x = mx[i], c = pc[i];
            const bool to_min = k.sgn([=](auto L) { return (L(c) - L(m)) - (L(x) - L(c)); }) != sign::negative;
            lo[i] = to_min ? m : c;
            hi[i] = to_min ? c : x;
        }
    }
    const auto sum = [=](auto L) {
        const auto g0 = L(hi[0]) - L(lo[0]), g1 = L(hi[1]) - L(lo[1]), g2 = L(hi[2]) - L(lo[2]);
        return g0 * g0 + g1 * g1 + g2 * g2;
    };
    if (signed_root) return nearest::root_distance(k, [=](auto L) { return arith::ratio{sum(L), L(1.0) * L(1.0)}; }, false);
    return arith::value(k, sum);
}

template <class K>
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const aabb3& b, const point3& p) {
    return box_squared_distance(k, b, p, distance_kind::nearest);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> max_squared_distance(K& k, const aabb3& b, const point3& p) {
    return box_squared_distance(k, b, p, distance_kind::farthest);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> signed_distance(K& k, const aabb3& b, const point3& p) {
    if (!box_point_usable(b, p)) return arith::exact_value(k, __builtin_nan(""));
    const double pc[3] = {p.x, p.y, p.z}, mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    bool outside = false;
    for (int i = 0; i < 3; ++i) outside = outside || pc[i] < mn[i] || pc[i] > mx[i];
    if (outside) return box_squared_distance(k, b, p, distance_kind::nearest, true);
    // inside: the largest of min_i - p_i and p_i - max_i, as lo - hi
    double lo = mn[0], hi = pc[0];
    for (int i = 0; i < 3; ++i)
        for (const auto& [l, h] : {std::pair{mn[i], pc[i]}, std::pair{pc[i], mx[i]}}) {
            const double l0 = lo, h0 = hi;
            if (l == l0 && h == h0) continue;
            if (k.sgn([=](auto L) { return (L(l) - L(h)) - (L(l0) - L(h0)); }) == sign::positive) lo = l, hi = h;
        }
    if (lo == hi) return arith::exact_value(k, 0.0); // on the boundary
    return arith::value(k, [=](auto L) { return L(lo) - L(hi); });
}

// obb3 and point3: the squared distance and the signed distance.
// Semantics: the points o + A s, |s_j| <= h_j (A's columns the axes exactly as given, so the box may
// be skew, flat or a point); signed_distance as for the box above (a flat box has no inside). A NaN
// or infinite number or a negative extent: NaN.
// Method (exact tiers): the minimiser's active set of ball_obb.cppm (a corner, an edge, a face, or
// the inside; KKT signs of degree <= 8, the set plain double names first) gives the squared distance
// P / S outside (degree 4 / 2, 6 / 4, 8 / 6), correctly rounded as a quotient, and its square root
// as the larger root of S t^2 - P. Inside (det A != 0), the boundary's nearest point lies on the
// nearer face of the pair j whose (h_j |det A| - |n_j . (p - o)|) / |n_j| is least (n_j = a_k x a_l;
// compared squared, degree 16), and minus that distance is the smaller root of
// |n_j|^2 t^2 - (h_j |det A| - |n_j . (p - o)|)^2.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.1.4 (closest point on an OBB);
// Boyd and Vandenberghe, Convex Optimization (2004), section 5.5.3 (KKT conditions).
// Approximate tier: the same signs and roots in plain double (faces compared by their quotients'
// values; where its signs refute all 27 sets, within rounding of a tie, exact signs name one).
// Error bound: where no deciding sign lies within 2^-40 of its permanent (the yes/no
// pairs' measure: the active set or feature is then plain double's too), for inputs whose nonzero
// magnitudes lie in [2^-120, 2^120], |d~ - d| <= 2^-40 M + 2^-140 for the signed distance and 2^-40 M^2 + 2^-280 for the squared one, M
// the largest magnitude among the inputs' numbers (a row's |d_i| / max |n_i|); the absolute terms
// cover numerators that underflow where nearly equal inputs differ by ulps (tests/query/distance/box_point.cpp, testkit/distance_checks.hpp).
namespace obb_distance {

[[nodiscard]] constexpr bool usable(const obb3& b, const point3& p) {
    if (!is_finite(p) || !is_finite(b.center)) return false;
    for (unsigned j = 0; j < 3; ++j)
        if (!is_finite(b.axes[j]) || !is_finite(b.half_extents[j]) || !(b.half_extents[j] >= 0.0)) return false;
    return true;
}

template <class K>
[[nodiscard]] constexpr arith::value_t<K> of(K& k, const obb3& b, point3 p, bool squared) {
    if (!usable(b, p)) return arith::exact_value(k, __builtin_nan(""));
    const ball_obb::frame f{b.center, p, {b.axes[0], b.axes[1], b.axes[2]}, {b.half_extents[0], b.half_extents[1], b.half_extents[2]}, 0.0};
    const auto at = nearest::found_or_exactly(
                        k, [&](auto& kernel) { return ball_obb::minimiser(kernel, f); }, [](const auto& m) { return m.first; })
                        .second;
    if (at != ball_obb::active{})
        return ball_obb::with_distance(f, at, [&](auto q) -> arith::value_t<K> {
            if (k.sgn([=](auto L) { return q(L).num; }) == sign::zero) return arith::exact_value(k, 0.0); // on the box
            if (squared) return arith::value(k, q);
            return nearest::root_distance(k, q, false);
        });
    if (squared) return arith::exact_value(k, 0.0);
    // the inside: the face pair nearest p
    const auto face = [=](unsigned j) {
        const vec3 u = b.axes[(j + 1) % 3], v = b.axes[(j + 2) % 3], a0 = b.axes[0], a1 = b.axes[1], a2 = b.axes[2];
        const double h = b.half_extents[j];
        const point3 o = b.center;
        return [=](auto L) {
            const auto n = arith::cross(arith::lift(L, u), arith::lift(L, v));
            const auto d = arith::det3(arith::lift(L, a0), arith::lift(L, a1), arith::lift(L, a2));
            const auto room = L(h) * sat::magnitude(d) - L(1.0) * sat::magnitude(arith::dot(n, arith::lift(L, p) - arith::lift(L, o)));
            return arith::ratio{room * room, arith::dot(n, n)};
        };
    };
    const auto f0 = face(0), f1 = face(1), f2 = face(2);
    const auto less = [&](const auto& x, const auto& y) { return nearest::compare_quotients(k, x, y) == sign::negative; };
    const auto depth = [&](const auto& q) -> arith::value_t<K> {
        if (k.sgn([=](auto L) { return q(L).num; }) == sign::zero) return arith::exact_value(k, 0.0);
        return nearest::root_distance(k, q, true);
    };
    if (less(f1, f0)) return less(f2, f1) ? depth(f2) : depth(f1);
    return less(f2, f0) ? depth(f2) : depth(f0);
}

} // namespace obb_distance

template <class K>
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const obb3& b, const point3& p) {
    return obb_distance::of(k, b, p, true);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> signed_distance(K& k, const obb3& b, const point3& p) {
    return obb_distance::of(k, b, p, false);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template double exactly<nearest_body>(const aabb3&, const point3&);
extern template double exactly<farthest_body>(const aabb3&, const point3&);
extern template double exactly<signed_body>(const aabb3&, const point3&);
extern template double exactly<nearest_body>(const obb3&, const point3&);
extern template double exactly<signed_body>(const obb3&, const point3&);
} // namespace incidence::detail
