// kdop_of's two passes over the points in SIMD lanes (modules/bound/kdop_of.cppm declares them and
// gives each a block of points as x, y, z triples). Highway compiles this file once per target and
// dispatches at run time, as the batches do (modules/batch/ray_triangles_simd.cpp).
//
// A lane computes a point's sums exactly as the scalar code does (kdop_of.cppm's detail::dot_of:
// the direction's nonzero terms, +-x, +-y, +-z, added left to right; kdop_of.cppm checks at compile
// time that kdop<K>'s directions come in the order `sums` below takes) and its error bound
// ((|x| + |y|) + |z|) 2^-50 (detail::dot_error). Pass 1 returns each direction's rounded least
// and greatest sum over the block, the largest error bound and whether every number is finite;
// pass 2 returns the points whose rounded interval reaches past the other bound, those whose
// exact sum is needed. Source: Klosowski, Held, Mitchell, Sowizral and Zikan, "Efficient collision
// detection using bounding volume hierarchies of k-DOPs", IEEE TVCG 4(1), 1998, section 4.1.
#include <cstddef>
#include <cstdint>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "modules/bound/kdop_of_simd.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace incidence::bound::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using D = hn::ScalableTag<double>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

// The sums of kdop<K>'s directions in kdop.cppm's order, as detail::dot_of rounds them: the axes
// x, y, z; with Corners (K = 14, 26) (x + y) + z, (x - y) + z, (x + y) - z, (x - y) - z; with Edges
// (K = 18, 26) x + y, x + z, y + z, x - y, x - z, y - z (x - y is x + (-y) exactly as rounded).
template <bool Corners, bool Edges>
HWY_INLINE void sums(V x, V y, V z, V* v) {
    v[0] = x, v[1] = y, v[2] = z;
    unsigned k = 3;
    if constexpr (Corners) {
        const V xy = hn::Add(x, y), x_y = hn::Sub(x, y);
        v[k++] = hn::Add(xy, z), v[k++] = hn::Add(x_y, z), v[k++] = hn::Sub(xy, z), v[k++] = hn::Sub(x_y, z);
    }
    if constexpr (Edges) {
        v[k++] = hn::Add(x, y), v[k++] = hn::Add(x, z), v[k++] = hn::Add(y, z);
        v[k++] = hn::Sub(x, y), v[k++] = hn::Sub(x, z), v[k++] = hn::Sub(y, z);
    }
}
HWY_INLINE V error_of(D d, V x, V y, V z) { return hn::Mul(hn::Add(hn::Add(hn::Abs(x), hn::Abs(y)), hn::Abs(z)), hn::Set(d, 0x1p-50)); }

template <bool Corners, bool Edges>
HWY_INLINE bool extremes_of(const double* xyz, std::size_t n, double* lo, double* hi, double* widest) {
    constexpr unsigned m = 3 + (Corners ? 4 : 0) + (Edges ? 6 : 0);
    const D d;
    const std::size_t N = hn::Lanes(d);
    V mn[m], mx[m], v[m];
    for (unsigned k = 0; k < m; ++k) mn[k] = hn::Set(d, lo[k]), mx[k] = hn::Set(d, hi[k]);
    V wide = hn::Set(d, *widest);
    M finite = hn::FirstN(d, N);
    for (std::size_t i = 0; i < n; i += N) {
        V x, y, z;
        hn::LoadInterleaved3(d, xyz + 3 * i, x, y, z);
        finite = hn::And(finite, hn::And(hn::IsFinite(x), hn::And(hn::IsFinite(y), hn::IsFinite(z))));
        wide = hn::Max(wide, error_of(d, x, y, z));
        sums<Corners, Edges>(x, y, z, v);
        for (unsigned k = 0; k < m; ++k) mn[k] = hn::Min(mn[k], v[k]), mx[k] = hn::Max(mx[k], v[k]);
    }
    for (unsigned k = 0; k < m; ++k) lo[k] = hn::GetLane(hn::MinOfLanes(d, mn[k])), hi[k] = hn::GetLane(hn::MaxOfLanes(d, mx[k]));
    *widest = hn::GetLane(hn::MaxOfLanes(d, wide));
    return hn::AllTrue(d, finite);
}

template <bool Corners, bool Edges>
HWY_INLINE std::size_t candidates_of(const double* xyz, std::size_t n, std::size_t count, const double* min_upper, const double* max_lower,
                                     std::uint32_t* out) {
    constexpr unsigned m = 3 + (Corners ? 4 : 0) + (Edges ? 6 : 0);
    const D d;
    const std::size_t N = hn::Lanes(d);
    V lo[m], hi[m], v[m];
    for (unsigned k = 0; k < m; ++k) lo[k] = hn::Set(d, min_upper[k]), hi[k] = hn::Set(d, max_lower[k]);
    std::size_t found = 0;
    for (std::size_t i = 0; i < n; i += N) {
        V x, y, z;
        hn::LoadInterleaved3(d, xyz + 3 * i, x, y, z);
        const V err = error_of(d, x, y, z);
        sums<Corners, Edges>(x, y, z, v);
        M any = hn::Not(hn::FirstN(d, N));
        for (unsigned k = 0; k < m; ++k)
            any = hn::Or(any, hn::Or(hn::Not(hn::Gt(hn::Sub(v[k], err), lo[k])), hn::Not(hn::Lt(hn::Add(v[k], err), hi[k]))));
        if (hn::AllFalse(d, any)) continue;
        const V flags = hn::VecFromMask(d, any);
        for (std::size_t l = 0; l < N; ++l)
            if (i + l < count && hn::ExtractLane(flags, l) != 0.0) out[found++] = static_cast<std::uint32_t>(i + l);
    }
    return found;
}

// xyz: n points (n a multiple of 64) as x, y, z triples; k: 14, 18 or 26. lo, hi: each direction's
// least and greatest rounded sum folded in (K / 2 each); widest: the largest error bound folded in.
// false where some number is not finite (then the rest means nothing).
bool extremes(const double* xyz, std::size_t n, int k, double* lo, double* hi, double* widest) {
    if (k == 14) return extremes_of<true, false>(xyz, n, lo, hi, widest);
    if (k == 18) return extremes_of<false, true>(xyz, n, lo, hi, widest);
    return extremes_of<true, true>(xyz, n, lo, hi, widest);
}

// The points of the block (the first `count` real) whose rounded interval [v - err, v + err]
// reaches below min_upper or above max_lower in some direction: their indices in `out` (room for
// n), and their number.
std::size_t candidates(const double* xyz, std::size_t n, std::size_t count, int k, const double* min_upper, const double* max_lower,
                       std::uint32_t* out) {
    if (k == 14) return candidates_of<true, false>(xyz, n, count, min_upper, max_lower, out);
    if (k == 18) return candidates_of<false, true>(xyz, n, count, min_upper, max_lower, out);
    return candidates_of<true, true>(xyz, n, count, min_upper, max_lower, out);
}

} // namespace incidence::bound::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace incidence::bound::simd {
HWY_EXPORT(extremes);
HWY_EXPORT(candidates);

// The entry points (declared extern "C++" in modules/bound/kdop_of.cppm).
bool kdop_extremes(const double* xyz, std::size_t n, int k, double* lo, double* hi, double* widest) {
    return HWY_DYNAMIC_DISPATCH(extremes)(xyz, n, k, lo, hi, widest);
}
std::size_t kdop_candidates(const double* xyz, std::size_t n, std::size_t count, int k, const double* min_upper, const double* max_lower,
                            std::uint32_t* out) {
    return HWY_DYNAMIC_DISPATCH(candidates)(xyz, n, count, k, min_upper, max_lower, out);
}
} // namespace incidence::bound::simd
#endif
