// kdop_of<K>: the tightest k-DOP of a point set: per direction d, [min, max] of dot(d, p)
// over the points, rounded outward to the nearest doubles (the sums of up to three coordinates
// are evaluated exactly only for the candidates a rounded pass cannot rule out).
// Source: Klosowski, Held, Mitchell, Sowizral and Zikan, "Efficient collision detection using
// bounding volume hierarchies of k-DOPs", IEEE TVCG 4(1), 1998, section 4.1.
module;
#include <array>
#include <span>
#include <vector>
export module incidence.bound:kdop_of;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :outward;
import :aabb_of;

export namespace incidence::bound {

namespace detail {
// dot(d, p) rounded; two additions err by at most 2u(1+u) sum |terms| (u = 2^-53), and adding or
// subtracting the bound itself rounds by about u sum more: 2^-50 (|x|+|y|+|z|) covers both, for
// every direction (d in {-1, 0, 1}^3). Sums of subnormals are exact.
// The zero terms are left out (a direction's are known where the loops below unroll): adding a zero
// changes no sum but the sign of a zero one.
[[nodiscard]] constexpr double dot_of(direction3 d, point3 p) {
    const double x = d.x * p.x, y = d.y * p.y, z = d.z * p.z; // the products are exact
    if (d.z == 0) return d.y == 0 ? x : (d.x == 0 ? y : x + y);
    if (d.y == 0) return d.x == 0 ? z : x + z;
    return d.x == 0 ? y + z : (x + y) + z;
}
[[nodiscard]] constexpr double dot_error(point3 p) {
    return ((p.x < 0 ? -p.x : p.x) + (p.y < 0 ? -p.y : p.y) + (p.z < 0 ? -p.z : p.z)) * 0x1p-50;
}
[[nodiscard]] constexpr arith::dyadic exact_dot(direction3 d, point3 p) {
    return arith::to_dyadic(d.x * p.x) + arith::to_dyadic(d.y * p.y) + arith::to_dyadic(d.z * p.z);
}
} // namespace detail

template <int K>
[[nodiscard]] constexpr result<kdop<K>> kdop_of(std::span<const point3> points) {
    if (points.empty()) return error{errc::empty_input};
    kdop<K> out{};
    if constexpr (K == 6) { // the axes alone: no sum, the box's bounds exactly
        const result<aabb3> box = aabb_of(points);
        if (!box) return box.error();
        const aabb3 b = box.value();
        out.min = {b.min.x, b.min.y, b.min.z}, out.max = {b.max.x, b.max.y, b.max.z};
        return out;
    }
    constexpr auto dirs = kdop<K>::directions();
    constexpr unsigned m = K / 2;
    // Pass 1, every direction per point (each point read once): the rounded minimum and maximum,
    // and the largest point's error bound (widest); then an upper bound of each exact minimum (the
    // rounded least sum's point q: fl(v_q + widest) >= fl(v_q + err_q) >= its exact sum, rounding
    // being monotone) and a lower bound of each exact maximum.
    std::array<double, m> min_upper, max_lower;
    min_upper.fill(__builtin_huge_val()), max_lower.fill(-__builtin_huge_val());
    double widest = 0.0;
    for (const point3& p : points) {
        if (!is_finite(p)) return error{errc::not_finite};
        const double e = detail::dot_error(p);
        widest = e > widest ? e : widest;
#pragma clang loop unroll(full)
        for (unsigned i = 0; i < m; ++i) {
            const double v = detail::dot_of(dirs[i], p);
            min_upper[i] = v < min_upper[i] ? v : min_upper[i];
            max_lower[i] = v > max_lower[i] ? v : max_lower[i];
        }
    }
    for (unsigned i = 0; i < m; ++i) min_upper[i] = min_upper[i] + widest, max_lower[i] = max_lower[i] - widest;
    // Pass 2: the points whose rounded interval reaches past the other bound (usually one per
    // side), then their exact sums.
    std::vector<std::size_t> candidates;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const point3 p = points[k];
        bool any = false;
        const double err = detail::dot_error(p);
#pragma clang loop unroll(full)
        for (unsigned i = 0; i < m; ++i) {
            const double v = detail::dot_of(dirs[i], p);
            any |= !(v - err > min_upper[i]) || !(v + err < max_lower[i]);
        }
        if (any) candidates.push_back(k);
    }
    std::array<bool, m> have_lo{}, have_hi{};
    std::array<arith::dyadic, m> lo, hi;
    for (const std::size_t k : candidates)
        for (unsigned i = 0; i < m; ++i) {
            const point3 p = points[k];
            const double v = detail::dot_of(dirs[i], p), err = detail::dot_error(p);
            const bool lo_candidate = !(v - err > min_upper[i]), hi_candidate = !(v + err < max_lower[i]);
            if (!lo_candidate && !hi_candidate) continue;
            const arith::dyadic x = detail::exact_dot(dirs[i], p);
            if (lo_candidate && (!have_lo[i] || arith::sign_of(x - lo[i]) < 0)) lo[i] = x, have_lo[i] = true;
            if (hi_candidate && (!have_hi[i] || arith::sign_of(x - hi[i]) > 0)) hi[i] = x, have_hi[i] = true;
        }
    for (unsigned i = 0; i < m; ++i) {
        out.min[i] = round_down(lo[i]);
        out.max[i] = round_up(hi[i]);
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
