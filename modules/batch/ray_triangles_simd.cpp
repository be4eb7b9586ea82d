// One ray against many triangles, in SIMD lanes: the kernels behind batch::intersects(ray3,
// triangles) (modules/batch/ray_triangles.cppm declares them). Google Highway compiles this file
// once per target (foreach_target.h re-includes it) and picks the best one the processor has at
// run time: AVX-512, AVX2, SSE4 or SSSE3, and a portable 128-bit emulation.
//
// Both kernels read the triangles as structure-of-arrays (nine arrays of n coordinates) and do in
// each lane, operation for operation, what the scalar query does, so that a lane's answer is the
// scalar answer bit for bit (IEEE arithmetic is the same in a lane as in a scalar register, and
// the library is built with -ffp-contract=off, so no product is fused into a sum here either):
// - watertight: the approximate tier, the watertight test of Woop, Benthin and Wald (JCGT 2(1),
//   2013) as modules/engines/triangle.cppm's ray_triangle_watertight writes it. 1 hit, 0 miss.
// - filter: the five signs of the filtered tiers' first decision (modules/engines/triangle.cppm's
//   linear_triangle: the normal against the direction, the three Pluecker edge values, the
//   origin's side) in the semi-static filter of modules/arith/filtered.cppm. 1 or 0 where all five
//   are proven, 2 where one is not (an edge, a vertex or the plane within the bound, a ray in the
//   plane, a degenerate triangle, a value out of the filter's range): the caller asks the scalar
//   query there. A block of 64 lanes is first tried against one static bound (below, at filter),
//   which costs the values alone; a vector it leaves open runs each lane's own bound, the scalar
//   filter's. Where a sign is proven either way the scalar filter proves it too, so the answers
//   agree in every tier.
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

// The nine coordinate arrays: a.x, a.y, a.z, b.x, ..., c.z.
struct soa {
    const double* c[9];
};

// Runs body(arrays, at, lane, count) over n lanes: `count` lanes from `lane` on, read at offset `at`
// of the arrays: whole vectors from the arrays themselves, the tail from a zero-padded copy on the
// stack (read at 0).
template <class Body>
HWY_INLINE void over_lanes(const soa& t, std::size_t n, const Body& body) {
    const D d;
    const std::size_t N = hn::Lanes(d);
    std::size_t i = 0;
    for (; i + N <= n; i += N) body(t, i, i, N);
    if (i == n) return;
    HWY_ALIGN double tail[9][HWY_MAX_BYTES / sizeof(double)] = {};
    soa padded{};
    for (int k = 0; k < 9; ++k) {
        std::memcpy(tail[k], t.c[k] + i, (n - i) * sizeof(double));
        padded.c[k] = tail[k];
    }
    body(padded, std::size_t{0}, i, n - i);
}

void watertight(const double* origin, const double* direction, const double* const* coords, std::size_t n, std::uint8_t* out) {
    // The ray's frame, once, as the scalar code finds it.
    const double dir[3] = {direction[0], direction[1], direction[2]};
    int kz = 0;
    if ((dir[1] < 0 ? -dir[1] : dir[1]) > (dir[kz] < 0 ? -dir[kz] : dir[kz])) kz = 1;
    if ((dir[2] < 0 ? -dir[2] : dir[2]) > (dir[kz] < 0 ? -dir[kz] : dir[kz])) kz = 2;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (dir[kz] < 0.0) {
        const int tmp = kx;
        kx = ky;
        ky = tmp;
    }
    if (!(dir[kz] != 0.0)) {
        std::memset(out, 0, n);
        return;
    }
    const D d;
    const V sx = hn::Set(d, dir[kx] / dir[kz]), sy = hn::Set(d, dir[ky] / dir[kz]), sz = hn::Set(d, 1.0 / dir[kz]);
    const V ox = hn::Set(d, origin[kx]), oy = hn::Set(d, origin[ky]), oz = hn::Set(d, origin[kz]);
    const V zero = hn::Zero(d);
    soa t{};
    for (int k = 0; k < 9; ++k) t.c[k] = coords[k];
    over_lanes(t, n, [&](const soa& s, std::size_t i, std::size_t lane, std::size_t count) {
        // a - o, b - o, c - o along the ray's frame (kx, ky, kz)
        auto rel = [&](int vertex, int axis, V o) { return hn::Sub(hn::LoadU(d, s.c[3 * vertex + axis] + i), o); };
        const V Ax = rel(0, kx, ox), Ay = rel(0, ky, oy), Az = rel(0, kz, oz);
        const V Bx = rel(1, kx, ox), By = rel(1, ky, oy), Bz = rel(1, kz, oz);
        const V Cx = rel(2, kx, ox), Cy = rel(2, ky, oy), Cz = rel(2, kz, oz);
        const V ax = hn::Sub(Ax, hn::Mul(sx, Az)), ay = hn::Sub(Ay, hn::Mul(sy, Az));
        const V bx = hn::Sub(Bx, hn::Mul(sx, Bz)), by = hn::Sub(By, hn::Mul(sy, Bz));
        const V cx = hn::Sub(Cx, hn::Mul(sx, Cz)), cy = hn::Sub(Cy, hn::Mul(sy, Cz));
        const V U = hn::Sub(hn::Mul(cx, by), hn::Mul(cy, bx));
        const V Vv = hn::Sub(hn::Mul(ax, cy), hn::Mul(ay, cx));
        const V W = hn::Sub(hn::Mul(bx, ay), hn::Mul(by, ax));
        const M negative = hn::Or(hn::Or(hn::Lt(U, zero), hn::Lt(Vv, zero)), hn::Lt(W, zero));
        const M positive = hn::Or(hn::Or(hn::Gt(U, zero), hn::Gt(Vv, zero)), hn::Gt(W, zero));
        const V det = hn::Add(hn::Add(U, Vv), W);
        const V az = hn::Mul(sz, Az), bz = hn::Mul(sz, Bz), cz = hn::Mul(sz, Cz);
        const V T = hn::Add(hn::Add(hn::Mul(U, az), hn::Mul(Vv, bz)), hn::Mul(W, cz));
        // A NaN det passes `!(det != 0)` in the scalar code, as it fails Eq here.
        const M behind = hn::Or(hn::And(hn::Lt(det, zero), hn::Gt(T, zero)), hn::And(hn::Gt(det, zero), hn::Lt(T, zero)));
        const M miss = hn::Or(hn::Or(hn::And(negative, positive), hn::Eq(det, zero)), behind);
        store_answers(d, hn::Not(miss), out + lane, count);
    });
}

// The five signs, over any number type T with +, - and * (fv: a value with its permanent; pv: the
// value alone; pp: a permanent alone, for the static bound), from the differences of inputs:
// ab = b - a, ac = c - a, oa = a - o, ob = b - o, oc = c - o and the direction d - 0. The
// expressions are those of the scalar filter, operation for operation (arith's cross, dot, det3).
template <class T>
struct vec {
    T x, y, z;
};
template <class T>
HWY_INLINE T dot(const vec<T>& a, const vec<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
HWY_INLINE vec<T> cross(const vec<T>& a, const vec<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
HWY_INLINE T det3(const vec<T>& a, const vec<T>& b, const vec<T>& c) {
    return a.x * (b.y * c.z - b.z * c.y) + a.y * (b.z * c.x - b.x * c.z) + a.z * (b.x * c.y - b.y * c.x);
}
template <class T>
struct five {
    T nd, wa, wb, wc, num;
};
template <class T>
HWY_INLINE five<T> five_signs(const vec<T>& ab, const vec<T>& ac, const vec<T>& oa, const vec<T>& ob, const vec<T>& oc, const vec<T>& dir) {
    const vec<T> normal = cross(ab, ac);
    return {dot(normal, dir), det3(dir, ob, oc), det3(dir, oc, oa), det3(dir, oa, ob), dot(normal, oa)};
}

// A value of the semi-static filter: v and its permanent p (modules/arith/filtered.cppm).
struct fv {
    V v, p;
};
HWY_INLINE fv operator-(fv a, fv b) { return {hn::Sub(a.v, b.v), hn::Add(a.p, b.p)}; }
HWY_INLINE fv operator+(fv a, fv b) { return {hn::Add(a.v, b.v), hn::Add(a.p, b.p)}; }
HWY_INLINE fv operator*(fv a, fv b) { return {hn::Mul(a.v, b.v), hn::Add(hn::Mul(a.p, b.p), hn::Set(D(), 0x1p-1020))}; }
// The value alone (the same operations on v as fv's).
struct pv {
    V v;
};
HWY_INLINE pv operator-(pv a, pv b) { return {hn::Sub(a.v, b.v)}; }
HWY_INLINE pv operator+(pv a, pv b) { return {hn::Add(a.v, b.v)}; }
HWY_INLINE pv operator*(pv a, pv b) { return {hn::Mul(a.v, b.v)}; }
// The permanent alone, in scalar double (the same operations on p as fv's).
struct pp {
    double p;
};
HWY_INLINE pp operator-(pp a, pp b) { return {a.p + b.p}; }
HWY_INLINE pp operator+(pp a, pp b) { return {a.p + b.p}; }
HWY_INLINE pp operator*(pp a, pp b) { return {a.p * b.p + 0x1p-1020}; }

// The lanes of one block: its differences of inputs, as fv (v and |v|), per vector.
struct lane_inputs {
    vec<fv> ab, ac, oa, ob, oc;
};
HWY_INLINE fv exact_difference(V a, V b) {
    const V v = hn::Sub(a, b);
    return {v, hn::Abs(v)};
}
HWY_INLINE lane_inputs inputs_at(D d, const soa& s, std::size_t i, const V* o) {
    V p[3][3];
    for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k) p[v][k] = hn::LoadU(d, s.c[3 * v + k] + i);
    auto diff = [&](int u, int v) {
        return vec<fv>{exact_difference(p[u][0], p[v][0]), exact_difference(p[u][1], p[v][1]), exact_difference(p[u][2], p[v][2])};
    };
    auto from_origin = [&](int u) {
        return vec<fv>{exact_difference(p[u][0], o[0]), exact_difference(p[u][1], o[1]), exact_difference(p[u][2], o[2])};
    };
    return {diff(1, 0), diff(2, 0), from_origin(0), from_origin(1), from_origin(2)};
}
HWY_INLINE vec<pv> values(const vec<fv>& a) { return {{a.x.v}, {a.y.v}, {a.z.v}}; }

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
void filter(const double* origin, const double* direction, const double* const* coords, std::size_t n, std::uint8_t* out) {
    const D d;
    const std::size_t N = hn::Lanes(d);
    // gamma_8 with the (1 + 2^-20) margin of filtered.cppm's error_bound: every sign below is of
    // eight operations (differences of inputs count one).
    constexpr double ku = 8 * (1.0 / 9007199254740992.0);
    constexpr double gamma = ku / (1.0 - ku) * (1.0 + 0x1p-20);
    const V g = hn::Set(d, gamma), trusted = hn::Set(d, 0x1p-900);
    // The direction as linear3's D: d - 0, a difference of inputs.
    const vec<fv> dir{exact_difference(hn::Set(d, direction[0]), hn::Zero(d)), exact_difference(hn::Set(d, direction[1]), hn::Zero(d)),
                      exact_difference(hn::Set(d, direction[2]), hn::Zero(d))};
    const vec<pv> dir_v = values(dir);
    auto abs_of = [](double x) { return x < 0 ? -x : x; };
    const vec<pp> dir_p{{abs_of(direction[0] - 0.0)}, {abs_of(direction[1] - 0.0)}, {abs_of(direction[2] - 0.0)}};
    const V o[3] = {hn::Set(d, origin[0]), hn::Set(d, origin[1]), hn::Set(d, origin[2])};
    constexpr std::size_t block = 64;
    HWY_ALIGN double tail[9][HWY_MAX_BYTES / sizeof(double)];
    for (std::size_t start = 0; start < n; start += block) {
        const std::size_t m = n - start < block ? n - start : block;
        const std::size_t full = m / N * N;
        soa whole{}, padded{};
        for (int k = 0; k < 9; ++k) whole.c[k] = coords[k] + start;
        if (full < m) {
            for (int k = 0; k < 9; ++k) {
                for (std::size_t j = 0; j < N; ++j) tail[k][j] = full + j < m ? whole.c[k][full + j] : 0.0;
                padded.c[k] = tail[k];
            }
        }
        auto inputs = [&](std::size_t i) { return i < full ? inputs_at(d, whole, i, o) : inputs_at(d, padded, 0, o); };
        // The block's largest |difference| of each kind and axis (a NaN counts as infinite).
        V most[15];
        for (V& x : most) x = hn::Zero(d);
        for (std::size_t i = 0; i < m; i += N) {
            const lane_inputs in = inputs(i);
            const vec<fv>* kinds[5] = {&in.ab, &in.ac, &in.oa, &in.ob, &in.oc};
            for (int k = 0; k < 5; ++k) {
                const fv* axis[3] = {&kinds[k]->x, &kinds[k]->y, &kinds[k]->z};
                for (int a = 0; a < 3; ++a) { most[3 * k + a] = max_counting_nan(d, most[3 * k + a], axis[a]->p); }
            }
        }
        vec<pp> largest[5];
        for (int k = 0; k < 5; ++k)
            largest[k] = {{hn::GetLane(hn::MaxOfLanes(d, most[3 * k]))},
                          {hn::GetLane(hn::MaxOfLanes(d, most[3 * k + 1]))},
                          {hn::GetLane(hn::MaxOfLanes(d, most[3 * k + 2]))}};
        const five<pp> permanent = five_signs(largest[0], largest[1], largest[2], largest[3], largest[4], dir_p);
        const double permanents[5] = {permanent.nd.p, permanent.wa.p, permanent.wb.p, permanent.wc.p, permanent.num.p};
        V bound[5];
        for (int k = 0; k < 5; ++k) {
            const double b = gamma * permanents[k];
            bound[k] = hn::Set(d, b < 0x1p-900 ? 0x1p-900 : b); // NaN: stays NaN, and nothing passes it
        }
        for (std::size_t i = 0; i < m; i += N) {
            const std::size_t count = m - i < N ? m - i : N;
            const lane_inputs in = inputs(i);
            const five<pv> v = five_signs(values(in.ab), values(in.ac), values(in.oa), values(in.ob), values(in.oc), dir_v);
            const V vs[5] = {v.nd.v, v.wa.v, v.wb.v, v.wc.v, v.num.v};
            auto positive = [&](int k) { return hn::Gt(vs[k], bound[k]); };
            auto negative = [&](int k) { return hn::Lt(vs[k], hn::Neg(bound[k])); };
            M all = hn::Or(positive(0), negative(0));
            for (int k = 1; k < 5; ++k) all = hn::And(all, hn::Or(positive(k), negative(k)));
            if (hn::AllTrue(d, hn::Or(all, hn::Not(hn::FirstN(d, count))))) { // the padded lanes do not count
                answer(d, positive, negative, out + start + i, count);
                continue;
            }
            // the lanes' own bounds
            const five<fv> f = five_signs(in.ab, in.ac, in.oa, in.ob, in.oc, dir);
            const fv fs[5] = {f.nd, f.wa, f.wb, f.wc, f.num};
            auto own_positive = [&](int k) { return hn::And(hn::Ge(fs[k].p, trusted), hn::Gt(fs[k].v, hn::Mul(g, fs[k].p))); };
            auto own_negative = [&](int k) { return hn::And(hn::Ge(fs[k].p, trusted), hn::Lt(fs[k].v, hn::Neg(hn::Mul(g, fs[k].p)))); };
            answer(d, own_positive, own_negative, out + start + i, count);
        }
    }
}

// The target this copy was compiled for.
const char* target() { return hwy::TargetName(HWY_TARGET); }

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace incidence::batch::simd {
HWY_EXPORT(watertight);
HWY_EXPORT(filter);
HWY_EXPORT(target);

// The entry points (declared extern "C++" in modules/batch/ray_triangles.cppm).
void ray_triangles_watertight(const double* origin, const double* direction, const double* const* coords, std::size_t n,
                              std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(watertight)(origin, direction, coords, n, out);
}
void ray_triangles_filter(const double* origin, const double* direction, const double* const* coords, std::size_t n, std::uint8_t* out) {
    HWY_DYNAMIC_DISPATCH(filter)(origin, direction, coords, n, out);
}
// The target the dispatch picks now (a test walks every target the processor has).
const char* target_name() { return HWY_DYNAMIC_DISPATCH(target)(); }
} // namespace incidence::batch::simd
#endif
