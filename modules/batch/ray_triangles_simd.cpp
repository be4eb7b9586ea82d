// One ray against many triangles, and many rays against one triangle, in SIMD lanes: the kernels
// behind batch::intersects(ray3, triangles) and batch::intersects(rays, triangle3)
// (modules/batch/ray_triangles.cppm declares them). Google Highway compiles this file once per
// target (foreach_target.h re-includes it) and picks the best one the processor has at run time:
// AVX-512, AVX2, SSE4 or SSSE3, and a portable 128-bit emulation.
//
// The kernels read the many shapes as structure-of-arrays (lanes-inl.h's fields: nine arrays of n
// coordinates for triangles, six for rays; the one shape broadcast) and do in each lane, operation
// for operation, what the scalar query does, so that a lane's answer is the scalar answer bit for
// bit (IEEE arithmetic is the same in a lane as in a scalar register, and the library is built
// with -ffp-contract=off, so no product is fused into a sum here either):
// - watertight: the approximate tier, the watertight test of Woop, Benthin and Wald (JCGT 2(1),
//   2013) as modules/engines/triangle.cppm's ray_triangle_watertight writes it. 1 hit, 0 miss.
//   One ray: its frame (the axis permutation and shear) once; many rays: each lane's own, by
//   selecting components lane by lane. And the same in float lanes for triangles kept in floats
//   (batch::triangles_soa_f): the approximate tier there, with its own bound (ray_triangles.cppm).
// - filter: the five signs of the filtered tiers' first decision (modules/engines/triangle.cppm's
//   linear_triangle: the normal against the direction, the three Pluecker edge values, the
//   origin's side) in the semi-static filter of modules/arith/filtered.cppm. 1 or 0 where all five
//   are proven, 2 where one is not (an edge, a vertex or the plane within the bound, a ray in the
//   plane, a degenerate triangle, a value out of the filter's range): the caller asks the scalar
//   query there. A block of 64 lanes is first tried against one static bound (below, at
//   filter_fields), which costs the values alone; a vector it leaves open runs each lane's own
//   bound, the scalar filter's. Where a sign is proven either way the scalar filter proves it too,
//   so the answers agree in every tier.
#include <cstddef>
#include <cstdint>
#include <cstring>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "modules/batch/ray_triangles_simd.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep
#include <hwy/highway.h>
#include "modules/batch/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace incidence::batch::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The fields of a ray-triangle lane: the triangle's a.x, a.y, a.z, b.x, ..., c.z (0..8), the ray's
// origin (9..11) and direction (12..14); the one ray's or the one triangle's broadcast.
HWY_INLINE fields ray_triangle_fields(const double* const* ray, bool rays, const double* const* triangle, bool triangles) {
    fields f{{}, {}, 15};
    for (int k = 0; k < 9; ++k) f.p[k] = triangle[k], f.per_lane[k] = triangles;
    for (int k = 0; k < 6; ++k) f.p[9 + k] = ray[k], f.per_lane[9 + k] = rays;
    return f;
}

// The watertight test's miss in lanes (doubles, or floats for float packets), from the vertices
// relative to the origin in the ray's frame (x, y, z = kx, ky, kz) and the shear s: the scalar
// code's operations in its order.
template <class DT>
struct sheared {
    hn::Vec<DT> sx, sy, sz;
};
template <bool Fused = false, class DT, class VT = hn::Vec<DT>>
HWY_INLINE hn::Mask<DT> watertight_miss(DT d, const sheared<DT>& s, const VT* A, const VT* B, const VT* C) {
    const VT zero = hn::Zero(d);
    auto minus_product = [](VT x, VT a, VT b) { // x - a b
        if constexpr (Fused) return hn::NegMulAdd(a, b, x);
        else return hn::Sub(x, hn::Mul(a, b));
    };
    const VT ax = minus_product(A[0], s.sx, A[2]), ay = minus_product(A[1], s.sy, A[2]);
    const VT bx = minus_product(B[0], s.sx, B[2]), by = minus_product(B[1], s.sy, B[2]);
    const VT cx = minus_product(C[0], s.sx, C[2]), cy = minus_product(C[1], s.sy, C[2]);
    const VT U = minus_product(hn::Mul(cx, by), cy, bx);
    const VT Vv = minus_product(hn::Mul(ax, cy), ay, cx);
    const VT W = minus_product(hn::Mul(bx, ay), by, ax);
    const auto negative = hn::Or(hn::Or(hn::Lt(U, zero), hn::Lt(Vv, zero)), hn::Lt(W, zero));
    const auto positive = hn::Or(hn::Or(hn::Gt(U, zero), hn::Gt(Vv, zero)), hn::Gt(W, zero));
    const VT det = hn::Add(hn::Add(U, Vv), W);
    const VT az = hn::Mul(s.sz, A[2]), bz = hn::Mul(s.sz, B[2]), cz = hn::Mul(s.sz, C[2]);
    VT T;
    if constexpr (Fused) T = hn::MulAdd(W, cz, hn::MulAdd(Vv, bz, hn::Mul(U, az)));
    else T = hn::Add(hn::Add(hn::Mul(U, az), hn::Mul(Vv, bz)), hn::Mul(W, cz));
    // A NaN det passes `!(det != 0)` in the scalar code, as it fails Eq here.
    const auto behind = hn::Or(hn::And(hn::Lt(det, zero), hn::Gt(T, zero)), hn::And(hn::Gt(det, zero), hn::Lt(T, zero)));
    return hn::Or(hn::Or(hn::And(negative, positive), hn::Eq(det, zero)), behind);
}

// The ray's frame as the scalar code finds it: kz the axis of the largest |d_k| (the first of
// equals), kx and ky the next two cyclically, swapped where d_kz < 0.
template <class T>
HWY_INLINE void ray_frame(const T* dir, int* axis) {
    int kz = 0;
    if ((dir[1] < 0 ? -dir[1] : dir[1]) > (dir[kz] < 0 ? -dir[kz] : dir[kz])) kz = 1;
    if ((dir[2] < 0 ? -dir[2] : dir[2]) > (dir[kz] < 0 ? -dir[kz] : dir[kz])) kz = 2;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (dir[kz] < 0) {
        const int tmp = kx;
        kx = ky;
        ky = tmp;
    }
    axis[0] = kx, axis[1] = ky, axis[2] = kz;
}

// One ray in its frame, broadcast: the axes (kx, ky, kz), the shear and the origin's coordinates
// along them; false where d_kz is zero (or NaN: `!(d_kz != 0)`), where the scalar code answers no.
template <class DT>
struct ray_in_frame {
    int axis[3];
    sheared<DT> shear;
    hn::Vec<DT> o[3];
};
template <class DT, class T>
HWY_INLINE bool frame_of(DT d, const T* origin, const T* direction, ray_in_frame<DT>& f) {
    const T dir[3] = {direction[0], direction[1], direction[2]};
    ray_frame(dir, f.axis);
    const int kx = f.axis[0], ky = f.axis[1], kz = f.axis[2];
    if (!(dir[kz] != T(0))) return false;
    f.shear = {hn::Set(d, dir[kx] / dir[kz]), hn::Set(d, dir[ky] / dir[kz]), hn::Set(d, T(1) / dir[kz])};
    for (int k = 0; k < 3; ++k) f.o[k] = hn::Set(d, origin[f.axis[k]]);
    return true;
}

// One ray against n triangles: the ray's frame once, as the scalar code finds it.
void watertight(const double* origin, const double* direction, const double* const* coords, std::size_t n, std::uint8_t* out) {
    const D d;
    ray_in_frame<D> f;
    if (!frame_of(d, origin, direction, f)) {
        std::memset(out, 0, n);
        return;
    }
    const int* axis = f.axis;
    const V* o = f.o;
    const sheared<D>& shear = f.shear;
    const double* ray[6] = {origin, origin + 1, origin + 2, direction, direction + 1, direction + 2};
    over_fields(d, ray_triangle_fields(ray, false, coords, true), n,
                [&](const fields& f, std::size_t i, std::size_t lane, std::size_t count) {
                    V rel[3][3]; // a - o, b - o, c - o along the ray's frame
                    for (int v = 0; v < 3; ++v)
                        for (int k = 0; k < 3; ++k) rel[v][k] = hn::Sub(f.at(d, 3 * v + axis[k], i), o[k]);
                    store_answers(d, hn::Not(watertight_miss(d, shear, rel[0], rel[1], rel[2])), out + lane, count);
                });
}

// n rays against one triangle: each lane finds its ray's frame as the scalar code does (kz the
// axis of the largest |d_k|, the first of equals; kx, ky the next two cyclically, swapped where
// d_kz < 0), by selecting components lane by lane.
void watertight_rays(const double* const* rays, const double* const* triangle, std::size_t n, std::uint8_t* out) {
    const D d;
    const V zero = hn::Zero(d);
    over_fields(d, ray_triangle_fields(rays, true, triangle, false), n,
                [&](const fields& f, std::size_t i, std::size_t lane, std::size_t count) {
                    const V dir[3] = {f.at(d, 12, i), f.at(d, 13, i), f.at(d, 14, i)};
                    const M y_larger = hn::Gt(hn::Abs(dir[1]), hn::Abs(dir[0]));
                    const M z2 = hn::Gt(hn::Abs(dir[2]), hn::IfThenElse(y_larger, hn::Abs(dir[1]), hn::Abs(dir[0])));
                    const M z1 = hn::AndNot(z2, y_larger), z0 = hn::AndNot(z2, hn::Not(y_larger));
                    // component kz, and kx, ky before the swap (kz = 0: 1, 2; kz = 1: 2, 0; kz = 2: 0, 1)
                    auto pick_z = [&](const V* v) { return hn::IfThenElse(z0, v[0], hn::IfThenElse(z1, v[1], v[2])); };
                    auto pick_x = [&](const V* v) { return hn::IfThenElse(z0, v[1], hn::IfThenElse(z1, v[2], v[0])); };
                    auto pick_y = [&](const V* v) { return hn::IfThenElse(z0, v[2], hn::IfThenElse(z1, v[0], v[1])); };
                    const V dz = pick_z(dir);
                    const M swap = hn::Lt(dz, zero);
                    auto frame = [&](const V* v, V* out3) {
                        const V x = pick_x(v), y = pick_y(v);
                        out3[0] = hn::IfThenElse(swap, y, x);
                        out3[1] = hn::IfThenElse(swap, x, y);
                        out3[2] = pick_z(v);
                    };
                    V df[3];
                    frame(dir, df);
                    const sheared<D> shear{hn::Div(df[0], df[2]), hn::Div(df[1], df[2]), hn::Div(hn::Set(d, 1.0), df[2])};
                    V rel[3][3];
                    for (int v = 0; v < 3; ++v) {
                        const V r[3] = {hn::Sub(f.at(d, 3 * v, i), f.at(d, 9, i)), hn::Sub(f.at(d, 3 * v + 1, i), f.at(d, 10, i)),
                                        hn::Sub(f.at(d, 3 * v + 2, i), f.at(d, 11, i))};
                        frame(r, rel[v]);
                    }
                    // a zero d_kz: the scalar answers no at once (`!(d_kz != 0)`, which a NaN passes: so Eq, not
                    // Highway's Ne, which is ordered on some targets and unordered on others)
                    const M miss = hn::Or(hn::Eq(dz, zero), watertight_miss(d, shear, rel[0], rel[1], rel[2]));
                    store_answers(d, hn::Not(miss), out + lane, count);
                });
}

// One ray against n triangles in float lanes (floats throughout: the ray's frame as above, the
// shear in float, the vertices relative to the origin rounded once to float; products fused into
// sums where the target has FMA: this tier is held to its bound, not to the scalar's bits). 1 hit,
// 0 miss.
using DF = hn::ScalableTag<float>;
void watertight_float(const float* origin, const float* direction, const float* const* coords, std::size_t n, std::uint8_t* out) {
    static_assert(HWY_MAX_BYTES / sizeof(float) <= 16, "two bytes of mask bits per vector");
    const DF d;
    ray_in_frame<DF> f;
    if (!frame_of(d, origin, direction, f)) {
        std::memset(out, 0, n);
        return;
    }
    const int* axis = f.axis;
    const hn::Vec<DF>* o = f.o;
    const sheared<DF>& shear = f.shear;
    auto lanes = [&](const float* const* p, std::size_t i, std::uint8_t* o8, std::size_t count) {
        hn::Vec<DF> rel[3][3]; // a - o, b - o, c - o along the ray's frame
        for (int v = 0; v < 3; ++v)
            for (int k = 0; k < 3; ++k) rel[v][k] = hn::Sub(hn::LoadU(d, p[3 * v + axis[k]] + i), o[k]);
        std::uint8_t bits[2] = {};
        hn::StoreMaskBits(d, hn::Not(watertight_miss<true>(d, shear, rel[0], rel[1], rel[2])), bits);
        store_bytes(byte_per_bit(bits[0]), o8, count < 8 ? count : 8);
        if (count > 8) store_bytes(byte_per_bit(bits[1]), o8 + 8, count - 8);
    };
    const std::size_t N = hn::Lanes(d);
    std::size_t i = 0;
    for (; i + N <= n; i += N) lanes(coords, i, out + i, N);
    if (i == n) return;
    HWY_ALIGN float tail[9][HWY_MAX_BYTES / sizeof(float)] = {};
    const float* padded[9];
    for (int k = 0; k < 9; ++k) {
        std::memcpy(tail[k], coords[k] + i, (n - i) * sizeof(float));
        padded[k] = tail[k];
    }
    lanes(padded, 0, out + i, n - i);
}

// The five signs (fv: a value with its permanent; pv: the value alone; pp: a permanent alone, for
// the static bound; lanes-inl.h), from the differences of inputs: ab = b - a, ac = c - a,
// oa = a - o, ob = b - o, oc = c - o and the direction d - 0. The expressions are those of the
// scalar filter, operation for operation (arith's cross, dot, det3).
template <class T>
struct five {
    T nd, wa, wb, wc, num;
};
template <class T>
HWY_INLINE five<T> five_signs(const vec<T>& ab, const vec<T>& ac, const vec<T>& oa, const vec<T>& ob, const vec<T>& oc, const vec<T>& dir) {
    const vec<T> normal = cross(ab, ac);
    return {dot(normal, dir), det3(dir, ob, oc), det3(dir, oc, oa), det3(dir, oa, ob), dot(normal, oa)};
}

// The lanes' differences of inputs, as fv (v and |v|): the triangle's edges, its vertices from the
// origin, and the direction as linear3's D (d - 0).
struct lane_inputs {
    vec<fv> ab, ac, oa, ob, oc, dir;
};
HWY_INLINE lane_inputs inputs_at(D d, const fields& f, std::size_t i) {
    V p[5][3]; // a, b, c, origin, direction
    for (int v = 0; v < 5; ++v)
        for (int k = 0; k < 3; ++k) p[v][k] = f.at(d, 3 * v + k, i);
    auto diff = [&](int u, int v) {
        return vec<fv>{exact_difference(p[u][0], p[v][0]), exact_difference(p[u][1], p[v][1]), exact_difference(p[u][2], p[v][2])};
    };
    const V zero = hn::Zero(d);
    const vec<fv> dir{exact_difference(p[4][0], zero), exact_difference(p[4][1], zero), exact_difference(p[4][2], zero)};
    return {diff(1, 0), diff(2, 0), diff(0, 3), diff(1, 3), diff(2, 3), dir};
}

// Answers from the five signs, where every sign is proven: a hit iff every edge value and the
// origin's side have the sign of n.d. positive(x) / negative(x): proven so (against the lane's
// own bound, or the block's static one).
template <class Pos, class Neg>
HWY_INLINE void answer(D d, const Pos& positive, const Neg& negative, std::uint8_t* out, std::size_t count) {
    const M up = positive(0), down = negative(0);
    auto with_nd = [&](int k) { return hn::Or(hn::And(up, positive(k)), hn::And(down, negative(k))); };
    auto proven = [&](int k) { return hn::Or(positive(k), negative(k)); };
    const M decided = hn::And(hn::Or(up, down), hn::And(hn::And(proven(1), proven(2)), hn::And(proven(3), proven(4))));
    const M yes = hn::And(hn::And(with_nd(1), with_nd(2)), hn::And(with_nd(3), with_nd(4)));
    store_answers(d, hn::And(decided, yes), hn::Not(decided), out, count);
}

// The filter in blocks of 64 lanes. First a static bound per block (modelling no more than the
// block needs): the permanents of the five signs evaluated, by the same operations, on the
// block's largest |difference| of each kind and axis. Rounding to nearest is monotone, so each
// lane's computed permanent is at most the block's, and so is its bound gamma_8 p; a value above
// the block's bound (and above 2^-900, since |v| <= p) is proven by the lane's own filter too.
// A vector with a lane the static bound leaves open runs the lane's own bound (the values again
// with their permanents); a lane that leaves open goes to the scalar query. A NaN anywhere in a
// block makes its static bound infinite (no NaN can hide a larger difference from the maxima).
void filter_fields(D d, const fields& all, std::size_t n, std::uint8_t* out) {
    constexpr double gamma = gamma_of(8); // every sign below is of eight operations (differences of inputs count one)
    constexpr std::size_t block = 64;
    for (std::size_t start = 0; start < n; start += block) {
        const std::size_t m = n - start < block ? n - start : block;
        const fields f = from(all, start);
        // The block's largest |difference| of each kind and axis (a NaN counts as infinite).
        V most[6][3];
        for (auto& row : most)
            for (V& x : row) x = hn::Zero(d);
        over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t, std::size_t) {
            const lane_inputs in = inputs_at(d, g, i);
            const vec<fv>* kinds[6] = {&in.ab, &in.ac, &in.oa, &in.ob, &in.oc, &in.dir};
            for (int k = 0; k < 6; ++k) {
                most[k][0] = max_counting_nan(d, most[k][0], kinds[k]->x.p);
                most[k][1] = max_counting_nan(d, most[k][1], kinds[k]->y.p);
                most[k][2] = max_counting_nan(d, most[k][2], kinds[k]->z.p);
            }
        });
        vec<pp> largest[6];
        for (int k = 0; k < 6; ++k)
            largest[k] = {{hn::GetLane(hn::MaxOfLanes(d, most[k][0]))},
                          {hn::GetLane(hn::MaxOfLanes(d, most[k][1]))},
                          {hn::GetLane(hn::MaxOfLanes(d, most[k][2]))}};
        const five<pp> permanent = five_signs(largest[0], largest[1], largest[2], largest[3], largest[4], largest[5]);
        const double permanents[5] = {permanent.nd.p, permanent.wa.p, permanent.wb.p, permanent.wc.p, permanent.num.p};
        V bound[5];
        for (int k = 0; k < 5; ++k) bound[k] = static_bound(d, gamma, permanents[k]);
        over_fields(d, f, m, [&](const fields& g, std::size_t i, std::size_t lane, std::size_t count) {
            const lane_inputs in = inputs_at(d, g, i);
            const five<pv> v = five_signs(values(in.ab), values(in.ac), values(in.oa), values(in.ob), values(in.oc), values(in.dir));
            const V vs[5] = {v.nd.v, v.wa.v, v.wb.v, v.wc.v, v.num.v};
            auto positive = [&](int k) { return hn::Gt(vs[k], bound[k]); };
            auto negative = [&](int k) { return hn::Lt(vs[k], hn::Neg(bound[k])); };
            M all_proven = hn::Or(positive(0), negative(0));
            for (int k = 1; k < 5; ++k) all_proven = hn::And(all_proven, hn::Or(positive(k), negative(k)));
            if (hn::AllTrue(d, hn::Or(all_proven, hn::Not(hn::FirstN(d, count))))) { // the padded lanes do not count
                answer(d, positive, negative, out + start + lane, count);
                return;
            }
            // the lanes' own bounds
            const five<fv> fs5 = five_signs(in.ab, in.ac, in.oa, in.ob, in.oc, in.dir);
            const fv fs[5] = {fs5.nd, fs5.wa, fs5.wb, fs5.wc, fs5.num};
            answer(
                d, [&](int k) { return own_positive(d, gamma, fs[k]); }, [&](int k) { return own_negative(d, gamma, fs[k]); },
                out + start + lane, count);
        });
    }
}
// One ray against n triangles.
void filter(const double* origin, const double* direction, const double* const* coords, std::size_t n, std::uint8_t* out) {
    const double* ray[6] = {origin, origin + 1, origin + 2, direction, direction + 1, direction + 2};
    filter_fields(D(), ray_triangle_fields(ray, false, coords, true), n, out);
}
// n rays against one triangle.
void filter_rays(const double* const* rays, const double* const* triangle, std::size_t n, std::uint8_t* out) {
    filter_fields(D(), ray_triangle_fields(rays, true, triangle, false), n, out);
}

// The target this copy was compiled for.
const char* target() { return hwy::TargetName(HWY_TARGET); }

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace incidence::batch::simd {
HWY_EXPORT(watertight);
HWY_EXPORT(filter);
HWY_EXPORT(watertight_rays);
HWY_EXPORT(filter_rays);
HWY_EXPORT(watertight_float);
HWY_EXPORT(target);

// The entry points (declared extern "C++" in modules/batch/ray_triangles.cppm).
void ray_triangles_watertight(const double* origin, const double* direction, const double* const* coords, std::size_t n,
                              std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(watertight)(origin, direction, coords, n, out);
}
void ray_triangles_filter(const double* origin, const double* direction, const double* const* coords, std::size_t n, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(filter)(origin, direction, coords, n, out);
}
void rays_triangle_watertight(const double* const* rays, const double* const* triangle, std::size_t n, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(watertight_rays)(rays, triangle, n, out);
}
void rays_triangle_filter(const double* const* rays, const double* const* triangle, std::size_t n, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(filter_rays)(rays, triangle, n, out);
}
void ray_triangles_watertight_float(const float* origin, const float* direction, const float* const* coords, std::size_t n,
                                    std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(watertight_float)(origin, direction, coords, n, out);
}
// The target the dispatch picks now (a test walks every target the processor has).
const char* target_name() { return HWY_DYNAMIC_DISPATCH(target)(); }
} // namespace incidence::batch::simd
#endif
