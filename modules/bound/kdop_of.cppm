// kdop_of<K>: the tightest k-DOP of a point set: per direction d, [min, max] of dot(d, p)
// over the points, rounded outward to the nearest doubles. Two rounded passes (in SIMD lanes,
// kdop_of_simd.cpp, outside constant evaluation) find the few points whose sum could be an
// extreme; only those are compared exactly, and only the extremes' exact sums are formed.
// Source: Klosowski, Held, Mitchell, Sowizral and Zikan, "Efficient collision detection using
// bounding volume hierarchies of k-DOPs", IEEE TVCG 4(1), 1998, section 4.1.
module;
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>
export module incidence.bound:kdop_of;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :outward;
import :aabb_of;

// The two passes in SIMD lanes (kdop_of_simd.cpp): a block of n points (n a multiple of 64) as x,
// y, z triples, the first `count` real; k: 14, 18 or 26.
extern "C++" {
namespace incidence::bound::simd {
// Folds each direction's least and greatest rounded sum into lo and hi and the largest error bound
// into widest; false where some number is not finite.
bool kdop_extremes(const double* xyz, std::size_t n, int k, double* lo, double* hi, double* widest);
// The real points whose rounded interval reaches past the other bound: their indices in out, and
// their number.
std::size_t kdop_candidates(const double* xyz, std::size_t n, std::size_t count, int k, const double* min_upper, const double* max_lower,
                            std::uint32_t* out);
} // namespace incidence::bound::simd
}

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
[[nodiscard]] constexpr bool is_axis(direction3 d) { return (d.x != 0) + (d.y != 0) + (d.z != 0) == 1; }
// Is dot(d, p) < dot(d, q), exactly? Equal terms (the points of a flat face, thousands on a
// machined part) give equal sums without the exact sign.
[[nodiscard]] constexpr bool sum_below(direction3 d, point3 p, point3 q) {
    const double px = d.x * p.x, py = d.y * p.y, pz = d.z * p.z, qx = d.x * q.x, qy = d.y * q.y, qz = d.z * q.z;
    if (px == qx && py == qy && pz == qz) return false;
    bool valid = true;
    return arith::exact_sign([=](auto L) { return (L(px) + L(py) + L(pz)) - (L(qx) + L(qy) + L(qz)); }, valid) == sign::negative;
}
// Do kdop<K>'s directions come as kdop_of_simd.cpp's sums take them: the axes, then with K = 14 or
// 26 the corners (1, 1, 1), (1, -1, 1), (1, 1, -1), (1, -1, -1), then with K = 18 or 26 the edges
// (1, 1, 0), (1, 0, 1), (0, 1, 1), (1, -1, 0), (1, 0, -1), (0, 1, -1)?
template <int K>
[[nodiscard]] consteval bool in_lane_order() {
    constexpr direction3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    constexpr direction3 corners[4] = {{1, 1, 1}, {1, -1, 1}, {1, 1, -1}, {1, -1, -1}};
    constexpr direction3 edges[6] = {{1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, -1, 0}, {1, 0, -1}, {0, 1, -1}};
    direction3 want[13]{};
    unsigned n = 0;
    for (const direction3& d : axes) want[n++] = d;
    if (K == 14 || K == 26)
        for (const direction3& d : corners) want[n++] = d;
    if (K == 18 || K == 26)
        for (const direction3& d : edges) want[n++] = d;
    const auto dirs = kdop<K>::directions();
    if (n != dirs.size()) return false;
    for (unsigned i = 0; i < n; ++i)
        if (dirs[i].x != want[i].x || dirs[i].y != want[i].y || dirs[i].z != want[i].z) return false;
    return true;
}
// A block of up to block_points points from `start` on as x, y, z triples, the rest of the block
// filled with the first of them (a repeated point changes no extreme); the number of real ones.
inline constexpr std::size_t block_points = 64;
inline std::size_t fill_block(double (&block)[3 * block_points], std::span<const point3> points, std::size_t start) {
    static_assert(sizeof(point3) == 3 * sizeof(double));
    const std::size_t count = points.size() - start < block_points ? points.size() - start : block_points;
    std::memcpy(block, points.data() + start, count * sizeof(point3));
    for (std::size_t j = count; j < block_points; ++j) std::memcpy(block + 3 * j, points.data() + start, sizeof(point3));
    return count;
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
    std::vector<std::size_t> candidates;
    // After pass 1: an axis's rounded extremes are exact (no sum), so they are the bounds, and no
    // point is a candidate for them; every other direction's widened by the largest error bound.
    const auto widen = [&] {
        for (unsigned i = 0; i < m; ++i)
            if (detail::is_axis(dirs[i]))
                out.min[i] = min_upper[i], out.max[i] = max_lower[i], min_upper[i] = -__builtin_huge_val(),
                max_lower[i] = __builtin_huge_val();
            else min_upper[i] = min_upper[i] + widest, max_lower[i] = max_lower[i] - widest;
    };
    if (!std::is_constant_evaluated()) { // both passes in SIMD lanes, a block of points at a time
        static_assert(detail::in_lane_order<K>(), "kdop_of_simd.cpp's sums take the directions in this order");
        // pass 1 keeps each block's extremes and largest error bound (2 m + 1 numbers): pass 2 skips
        // a block whose least sum less its largest bound lies above every upper bound of a minimum
        // and whose greatest plus it below every lower bound of a maximum (then so does each of
        // its points' interval, rounding being monotone)
        double block[3 * detail::block_points];
        const std::size_t blocks = (points.size() + detail::block_points - 1) / detail::block_points;
        std::vector<double> seen(blocks * (2 * m + 1));
        for (std::size_t b = 0; b < blocks; ++b) {
            (void)detail::fill_block(block, points, b * detail::block_points);
            double* lo = seen.data() + b * (2 * m + 1);
            double* hi = lo + m;
            for (unsigned i = 0; i < m; ++i) lo[i] = __builtin_huge_val(), hi[i] = -__builtin_huge_val();
            hi[m] = 0.0;
            if (!simd::kdop_extremes(block, detail::block_points, K, lo, hi, hi + m)) return error{errc::not_finite};
            for (unsigned i = 0; i < m; ++i)
                min_upper[i] = lo[i] < min_upper[i] ? lo[i] : min_upper[i], max_lower[i] = hi[i] > max_lower[i] ? hi[i] : max_lower[i];
            widest = hi[m] > widest ? hi[m] : widest;
        }
        widen();
        std::uint32_t found[detail::block_points];
        for (std::size_t b = 0; b < blocks; ++b) {
            const double* lo = seen.data() + b * (2 * m + 1);
            const double* hi = lo + m;
            bool open = false;
            for (unsigned i = 0; i < m; ++i) open |= !(lo[i] - hi[m] > min_upper[i]) || !(hi[i] + hi[m] < max_lower[i]);
            if (!open) continue;
            const std::size_t start = b * detail::block_points, count = detail::fill_block(block, points, start);
            const std::size_t f = simd::kdop_candidates(block, detail::block_points, count, K, min_upper.data(), max_lower.data(), found);
            for (std::size_t j = 0; j < f; ++j) candidates.push_back(start + found[j]);
        }
    } else {
        for (const point3& p : points) {
            if (!is_finite(p)) return error{errc::not_finite};
            const double e = detail::dot_error(p);
            widest = e > widest ? e : widest;
            for (unsigned i = 0; i < m; ++i) {
                const double v = detail::dot_of(dirs[i], p);
                min_upper[i] = v < min_upper[i] ? v : min_upper[i];
                max_lower[i] = v > max_lower[i] ? v : max_lower[i];
            }
        }
        widen();
        // Pass 2: the points whose rounded interval reaches past the other bound (usually one per
        // side), then their exact sums.
        for (std::size_t k = 0; k < points.size(); ++k) {
            const point3 p = points[k];
            bool any = false;
            const double err = detail::dot_error(p);
            for (unsigned i = 0; i < m; ++i) {
                const double v = detail::dot_of(dirs[i], p);
                any |= !(v - err > min_upper[i]) || !(v + err < max_lower[i]);
            }
            if (any) candidates.push_back(k);
        }
    }
    // The exact stage: per direction and side the candidate of the least (greatest) exact sum, each
    // compared with the best so far by the exact sign of their difference (a tie, commonest on flat
    // faces, is an exact zero in double), then the best's exact sum rounded outward.
    constexpr std::size_t none = ~std::size_t{0};
    std::array<std::size_t, m> lo_at, hi_at;
    lo_at.fill(none), hi_at.fill(none);
    for (const std::size_t k : candidates)
        for (unsigned i = 0; i < m; ++i) {
            if (detail::is_axis(dirs[i])) continue;
            const point3 p = points[k];
            const double v = detail::dot_of(dirs[i], p), err = detail::dot_error(p);
            if (!(v - err > min_upper[i]) && (lo_at[i] == none || detail::sum_below(dirs[i], p, points[lo_at[i]]))) lo_at[i] = k;
            if (!(v + err < max_lower[i]) && (hi_at[i] == none || detail::sum_below(dirs[i], points[hi_at[i]], p))) hi_at[i] = k;
        }
    for (unsigned i = 0; i < m; ++i) {
        if (detail::is_axis(dirs[i])) continue;
        out.min[i] = round_down(detail::exact_dot(dirs[i], points[lo_at[i]]));
        out.max[i] = round_up(detail::exact_dot(dirs[i], points[hi_at[i]]));
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
