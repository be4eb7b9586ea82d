// kdop_of<K>: the tightest k-DOP of a point set: per direction d, [min, max] of dot(d, p)
// over the points, rounded outward to the nearest doubles (the sums of up to three coordinates
// are evaluated exactly only for the candidates a rounded pass cannot rule out).
// Source: Klosowski, Held, Mitchell, Sowizral and Zikan, "Efficient collision detection using
// bounding volume hierarchies of k-DOPs", IEEE TVCG 4(1), 1998, section 4.1.
module;
#include <array>
#include <span>
export module incidence.bound:kdop_of;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :outward;

export namespace incidence::bound {

namespace detail {
// dot(d, p) rounded, and a bound on its rounding error (two additions: <= 2u(1+u) sum |terms|).
struct rounded_dot {
    double v, err;
};
[[nodiscard]] constexpr rounded_dot dot_of(direction3 d, point3 p) {
    const double x = d.x * p.x, y = d.y * p.y, z = d.z * p.z; // exact: d in {-1, 0, 1}
    const double ax = x < 0 ? -x : x, ay = y < 0 ? -y : y, az = z < 0 ? -z : z;
    return {(x + y) + z, (ax + ay + az) * 0x1.8p-52};
}
[[nodiscard]] constexpr arith::dyadic exact_dot(direction3 d, point3 p) {
    return arith::to_dyadic(d.x * p.x) + arith::to_dyadic(d.y * p.y) + arith::to_dyadic(d.z * p.z);
}
} // namespace detail

template <int K>
[[nodiscard]] constexpr result<kdop<K>> kdop_of(std::span<const point3> points) {
    if (points.empty()) return error{errc::empty_input};
    for (const point3& p : points)
        if (!is_finite(p)) return error{errc::not_finite};
    kdop<K> out{};
    const auto dirs = kdop<K>::directions();
    for (unsigned i = 0; i < dirs.size(); ++i) {
        const direction3 d = dirs[i];
        double min_upper = __builtin_huge_val(), max_lower = -__builtin_huge_val();
        for (const point3& p : points) {
            const auto r = detail::dot_of(d, p);
            if (r.v + r.err < min_upper) min_upper = r.v + r.err;
            if (r.v - r.err > max_lower) max_lower = r.v - r.err;
        }
        // Exact extremes among the points whose rounded interval reaches past the other bound.
        bool have_lo = false, have_hi = false;
        arith::dyadic lo, hi;
        for (const point3& p : points) {
            const auto r = detail::dot_of(d, p);
            const bool lo_candidate = !(r.v - r.err > min_upper), hi_candidate = !(r.v + r.err < max_lower);
            if (!lo_candidate && !hi_candidate) continue;
            const arith::dyadic x = detail::exact_dot(d, p);
            if (lo_candidate && (!have_lo || arith::sign_of(x - lo) < 0)) lo = x, have_lo = true;
            if (hi_candidate && (!have_hi || arith::sign_of(x - hi) > 0)) hi = x, have_hi = true;
        }
        out.min[i] = round_down(lo);
        out.max[i] = round_up(hi);
        if (!is_finite(out.min[i]) || !is_finite(out.max[i])) return error{errc::out_of_range};
    }
    return out;
}

// Is p in the k-DOP (closed)? Exact (each product d * coordinate is exact: d in {-1, 0, 1}).
template <int K>
[[nodiscard]] constexpr bool contains(const kdop<K>& k, point3 p) {
    const auto dirs = kdop<K>::directions();
    for (unsigned i = 0; i < dirs.size(); ++i) {
        const double x = dirs[i].x * p.x, y = dirs[i].y * p.y, z = dirs[i].z * p.z, lo = k.min[i], hi = k.max[i];
        bool valid = true;
        if (arith::exact_sign([=](auto L) { return L(x) + L(y) + L(z) - L(lo); }, valid) == sign::negative) return false;
        if (arith::exact_sign([=](auto L) { return L(hi) - (L(x) + L(y) + L(z)); }, valid) == sign::negative) return false;
        if (!valid) return false;
    }
    return true;
}

} // namespace incidence::bound
