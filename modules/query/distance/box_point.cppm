// distance: aabb3 and point3, the squared distance to the box's nearest and farthest point.
// Semantics: the closed box (an inverted box, or a NaN or an infinite number: NaN).
// Method: per axis, the gap to the nearer face when the point lies outside the slab (zero inside)
// for the nearest point, to the farther face for the farthest (the sign of 2 p - min - max,
// degree 1); the value is the sum of the squared gaps, a polynomial of degree 2 (arith::value:
// correctly rounded, enclosed or plain). Source: Ericson, Real-Time Collision Detection (2005),
// section 5.1.3 (SqDistPointAABB).
// Approximate tier: each gap rounds once, each square once, two sums: |d~ - d| <= gamma_5 d + 2^-1070
// (Higham, Accuracy and Stability of Numerical Algorithms, 2002, section 3.1), for gaps whose squares
// do not overflow (tests/query/distance/box_point.cpp).
export module incidence.detail:distance.box_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :exactly;

export namespace incidence::detail {

enum class distance_kind : unsigned char { nearest, farthest };

template <class K>
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const aabb3& b, const point3& p, distance_kind kind) {
    const double pc[3] = {p.x, p.y, p.z}, mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    bool ok = true;
    for (int i = 0; i < 3; ++i) ok = ok && is_finite(pc[i]) && is_finite(mn[i]) && is_finite(mx[i]) && mn[i] <= mx[i];
    if (!ok) return arith::exact_value(k, __builtin_nan(""));
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
    return arith::value(k, [=](auto L) {
        const auto g0 = L(hi[0]) - L(lo[0]), g1 = L(hi[1]) - L(lo[1]), g2 = L(hi[2]) - L(lo[2]);
        return g0 * g0 + g1 * g1 + g2 * g2;
    });
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template double exactly<nearest_body>(const aabb3&, const point3&);
extern template double exactly<farthest_body>(const aabb3&, const point3&);
} // namespace incidence::detail
