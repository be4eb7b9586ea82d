// A capsule's core (segment ab) against a box, an oriented box or another segment, within R:
// closest points guessed in plain double, then settled by exact signs where the guess is good
// enough. The fast path of the capsule pairs; whatever it leaves open goes to the pair's full
// case analysis (capsule.cppm, capsule_obb.cppm), which decides every input.
// Method: with x(t) = a + t (b - a), t a double in [0, 1], and y a point of the other shape built
// from doubles inside its bounds (a box point clamped into [lo, hi]; o + sum s_j m_j with
// |s_j| <= h_j; c + u (d - c) with u in [0, 1]):
//   witness:    R^2 - |x(t) - y|^2 > 0 proves that they meet. x(t) - y = (a - y) 1 + t (b - a)
//               (degree 2; for an oriented box (a - o) 1 + t (b - a) - sum s_j m_j), so the sign
//               has degree 4.
//   separation: a direction v of doubles (the guess's x - y) with v . (e - f) > 0 and
//               (v . (e - f))^2 > R^2 |v|^2 for e each end of the segment and f the other shape's
//               support point in direction v (a box's corner by the signs of v's coordinates; a
//               segment's two ends; an oriented box's o + sum sigma_j h_j m_j with sigma_j the
//               proven sign of v . m_j, both signs where it is not proven) proves that every pair
//               of points lies farther than R apart (degree 4; for an oriented box, with v . (e - o)
//               times a lifted 1, degree 6).
// Each sign is hint::optional: a filter that cannot prove it leaves the case open and the pass is
// not failed. Both certificates hold for any doubles chosen, so the guess needs no error analysis.
// Skipped in constant evaluation (a guess at extreme scales may overflow there) and where a
// guessed double is not finite.
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.9 (closest points of two
// segments) and 5.1.3 (closest point on an AABB); the separating-direction certificate is the weak
// duality of the distance problem, Boyd and Vandenberghe, Convex Optimization (2004), section 8.2.
// Approximate tier: the same signs in plain double; its bound is the pair's (a deciding sign within
// 2^-40 of its permanent).
module;
#include <array>
#include <initializer_list>
export module incidence.detail:engines.certificate;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.ball_flat;

export namespace incidence::detail {

namespace certificate {

enum class verdict : unsigned char { open, meets, apart };

// The parameter t in [0, 1] of the point of segment pa + t d nearest to the box [lo, hi] (plain
// double): the sum of squared gaps is a convex piecewise quadratic in t, minimised on each piece
// between the parameters where a coordinate crosses a bound.
[[nodiscard]] constexpr double nearest_parameter(const double (&pa)[3], const double (&d)[3], const double (&lo)[3],
                                                 const double (&hi)[3]) {
    double ts[8] = {0.0, 1.0};
    int n = 2;
    for (unsigned j = 0; j < 3; ++j) {
        if (d[j] == 0.0) continue;
        for (const double bound : {lo[j], hi[j]}) {
            const double t = (bound - pa[j]) / d[j];
            if (t > 0.0 && t < 1.0) ts[n++] = t;
        }
    }
    for (int i = 1; i < n; ++i)
        for (int m = i; m > 0 && ts[m] < ts[m - 1]; --m) {
            const double s = ts[m];
            ts[m] = ts[m - 1];
            ts[m - 1] = s;
        }
    auto gaps = [&](double t) {
        double f = 0.0;
        for (unsigned j = 0; j < 3; ++j) {
            const double p = pa[j] + t * d[j];
            const double g = p < lo[j] ? lo[j] - p : (p > hi[j] ? p - hi[j] : 0.0);
            f += g * g;
        }
        return f;
    };
    double best_t = 0.0, best_f = gaps(0.0);
    for (int i = 0; i + 1 < n; ++i) {
        const double t0 = ts[i], t1 = ts[i + 1], mid = 0.5 * (t0 + t1);
        double num = 0.0, den = 0.0;
        for (unsigned j = 0; j < 3; ++j) {
            const double p = pa[j] + mid * d[j];
            if (p >= lo[j] && p <= hi[j]) continue;
            num += (pa[j] - (p < lo[j] ? lo[j] : hi[j])) * d[j];
            den += d[j] * d[j];
        }
        const double t = den > 0.0 ? clamp(-num / den, t0, t1) : mid;
        if (const double f = gaps(t); f < best_f) best_f = f, best_t = t;
    }
    return best_t;
}

// The parameters (s, t) of the closest points of segments a + s (b - a) and c + t (d - c), plain
// double (Ericson 5.1.9).
[[nodiscard]] constexpr std::array<double, 2> closest_parameters(point3 a, point3 b, point3 c, point3 d) {
    const vec3 d1 = b - a, d2 = d - c, w = a - c;
    const double aa = dot(d1, d1), ee = dot(d2, d2), f = dot(d2, w);
    if (aa == 0.0 && ee == 0.0) return {0.0, 0.0};
    if (aa == 0.0) return {0.0, clamp(f / ee, 0.0, 1.0)};
    const double cc = dot(d1, w);
    if (ee == 0.0) return {clamp(-cc / aa, 0.0, 1.0), 0.0};
    const double bb = dot(d1, d2), den = aa * ee - bb * bb;
    double s = den > 0.0 ? clamp((bb * f - cc * ee) / den, 0.0, 1.0) : 0.0;
    double t = (bb * s + f) / ee;
    if (t < 0.0) t = 0.0, s = clamp(-cc / aa, 0.0, 1.0);
    else if (t > 1.0) t = 1.0, s = clamp((bb - cc) / aa, 0.0, 1.0);
    return {s, t};
}

// Is R^2 - |g|^2 proven positive, with g(L) a difference of two points of degree 2?
template <class K, class R, class G>
[[nodiscard]] constexpr bool witness(K& k, R rad, const G& g) {
    return arith::sgn<arith::hint::optional>(k, [=](auto L) {
               const auto w = g(L);
               const auto one = L(1.0);
               return ball_flat::squared(L, rad) * (one * one) - arith::dot(w, w);
           }) == sign::positive;
}
// Are G > 0 and G^2 > R^2 |v|^2 proven (times a lifted 1 squared where G carries one)?
template <bool WithOne, class K, class R, class G>
[[nodiscard]] constexpr bool beyond(K& k, R rad, vec3 v, const G& gap) {
    if (arith::sgn<arith::hint::optional>(k, gap) != sign::positive) return false;
    return arith::sgn<arith::hint::optional>(k, [=](auto L) {
               const auto g = gap(L);
               const auto V = arith::lift(L, v);
               if constexpr (WithOne) {
                   const auto one = L(1.0);
                   return g * g - ball_flat::squared(L, rad) * arith::dot(V, V) * (one * one);
               } else {
                   return g * g - ball_flat::squared(L, rad) * arith::dot(V, V);
               }
           }) == sign::positive;
}

// (a - y) 1 + t (b - a)
template <class L>
[[nodiscard]] constexpr auto on_segment_less(L l, point3 a, point3 b, double t, point3 y) {
    const auto one = l(1.0);
    return arith::scaled(arith::lift(l, a) - arith::lift(l, y), one) + arith::scaled(arith::lift(l, b) - arith::lift(l, a), l(t));
}

[[nodiscard]] constexpr bool finite_all(std::initializer_list<double> xs) {
    for (const double x : xs)
        if (!is_finite(x)) return false;
    return true;
}

// Segment ab against the box [lo, hi] (finite, lo <= hi), within R.
template <class K, class R>
[[nodiscard]] constexpr verdict segment_box(K& k, point3 a, point3 b, const aabb3& box, R rad) {
    if (__builtin_is_constant_evaluated()) return verdict::open;
    const double pa[3] = {a.x, a.y, a.z}, d[3] = {b.x - a.x, b.y - a.y, b.z - a.z};
    const double lo[3] = {box.min.x, box.min.y, box.min.z}, hi[3] = {box.max.x, box.max.y, box.max.z};
    if (!finite_all({d[0], d[1], d[2]})) return verdict::open;
    const double t = nearest_parameter(pa, d, lo, hi);
    double x[3], y[3];
    for (unsigned j = 0; j < 3; ++j) x[j] = pa[j] + t * d[j], y[j] = clamp(x[j], lo[j], hi[j]);
    const point3 yp{y[0], y[1], y[2]};
    if (witness(k, rad, [=](auto L) { return on_segment_less(L, a, b, t, yp); })) return verdict::meets;
    const vec3 v{x[0] - y[0], x[1] - y[1], x[2] - y[2]};
    if (!is_finite(v) || (v.x == 0.0 && v.y == 0.0 && v.z == 0.0)) return verdict::open;
    const point3 c{v.x > 0.0 ? hi[0] : lo[0], v.y > 0.0 ? hi[1] : lo[1], v.z > 0.0 ? hi[2] : lo[2]};
    for (const point3 e : {a, b})
        if (!beyond<false>(k, rad, v, [=](auto L) { return arith::dot(arith::lift(L, v), arith::lift(L, e) - arith::lift(L, c)); }))
            return verdict::open;
    return verdict::apart;
}

// Segment ab against segment cd, within R.
template <class K, class R>
[[nodiscard]] constexpr verdict segment_segment(K& k, point3 a, point3 b, point3 c, point3 d, R rad) {
    if (__builtin_is_constant_evaluated()) return verdict::open;
    if (!is_finite(b - a) || !is_finite(d - c) || !is_finite(a - c)) return verdict::open;
    const auto [s, t] = closest_parameters(a, b, c, d);
    if (!finite_all({s, t})) return verdict::open;
    if (witness(k, rad,
                [=](auto L) { return on_segment_less(L, a, b, s, c) - arith::scaled(arith::lift(L, d) - arith::lift(L, c), L(t)); }))
        return verdict::meets;
    const vec3 v = (a + (b - a) * s) - (c + (d - c) * t);
    if (!is_finite(v) || (v.x == 0.0 && v.y == 0.0 && v.z == 0.0)) return verdict::open;
    for (const point3 e : {a, b})
        for (const point3 f : {c, d})
            if (!beyond<false>(k, rad, v, [=](auto L) { return arith::dot(arith::lift(L, v), arith::lift(L, e) - arith::lift(L, f)); }))
                return verdict::open;
    return verdict::apart;
}

// Segment ab against the oriented box (finite, extents >= 0), within R.
template <class K, class R>
[[nodiscard]] constexpr verdict segment_obb(K& k, point3 a, point3 b, const obb3& box, R rad) {
    if (__builtin_is_constant_evaluated()) return verdict::open;
    const point3 o = box.center;
    const vec3 m[3] = {box.axes[0], box.axes[1], box.axes[2]};
    const double h[3] = {box.half_extents[0], box.half_extents[1], box.half_extents[2]};
    // the segment in the box's coordinates (near orthonormal axes for a checked box: a guess)
    double la[3], d[3], lo[3], hi[3];
    for (unsigned j = 0; j < 3; ++j) {
        const double mm = dot(m[j], m[j]);
        la[j] = mm > 0.0 ? dot(m[j], a - o) / mm : 0.0;
        d[j] = (mm > 0.0 ? dot(m[j], b - o) / mm : 0.0) - la[j];
        lo[j] = -h[j], hi[j] = h[j];
    }
    if (!finite_all({la[0], la[1], la[2], d[0], d[1], d[2]})) return verdict::open;
    const double t = nearest_parameter(la, d, lo, hi);
    double s[3];
    for (unsigned j = 0; j < 3; ++j) s[j] = clamp(la[j] + t * d[j], lo[j], hi[j]);
    if (witness(k, rad, [=](auto L) {
            return on_segment_less(L, a, b, t, o) - arith::scaled(arith::lift(L, m[0]), L(s[0])) -
                   arith::scaled(arith::lift(L, m[1]), L(s[1])) - arith::scaled(arith::lift(L, m[2]), L(s[2]));
        }))
        return verdict::meets;
    const vec3 v = (a + (b - a) * t) - (o + m[0] * s[0] + m[1] * s[1] + m[2] * s[2]);
    if (!is_finite(v) || (v.x == 0.0 && v.y == 0.0 && v.z == 0.0)) return verdict::open;
    // sigma_j: the proven sign of v . m_j; 0 where not proven (both signs are then tried)
    int sigma[3];
    for (unsigned j = 0; j < 3; ++j) {
        const vec3 mj = m[j];
        const sign sj = arith::sgn<arith::hint::optional>(k, [=](auto L) { return arith::dot(arith::lift(L, v), arith::lift(L, mj)); });
        sigma[j] = sj == sign::positive ? 1 : (sj == sign::negative ? -1 : 0);
    }
    for (int choice = 0; choice < 8; ++choice) {
        double f[3]; // sigma_j h_j
        bool repeated = false;
        for (unsigned j = 0; j < 3; ++j) {
            const int bit = (choice >> j) & 1;
            if (sigma[j] != 0 && bit) repeated = true;
            f[j] = (sigma[j] != 0 ? sigma[j] : (bit ? -1 : 1)) * h[j];
        }
        if (repeated) continue;
        for (const point3 e : {a, b})
            if (!beyond<true>(k, rad, v, [=](auto L) {
                    const auto V = arith::lift(L, v);
                    return arith::dot(V, arith::lift(L, e) - arith::lift(L, o)) * L(1.0) - L(f[0]) * arith::dot(V, arith::lift(L, m[0])) -
                           L(f[1]) * arith::dot(V, arith::lift(L, m[1])) - L(f[2]) * arith::dot(V, arith::lift(L, m[2]));
                }))
                return verdict::open;
    }
    return verdict::apart;
}

} // namespace certificate

} // namespace incidence::detail
