// The batches' shared per-target helpers, for the SIMD kernels (*_simd.cpp): Highway's pattern for
// a header that foreach_target.h compiles once per target (the guard toggles with each target).
#if defined(INCIDENCE_BATCH_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef INCIDENCE_BATCH_LANES_INL_H_
#undef INCIDENCE_BATCH_LANES_INL_H_
#else
#define INCIDENCE_BATCH_LANES_INL_H_
#endif

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace incidence::batch::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The batches' lanes: doubles, as many as the target's vectors hold.
using D = hn::ScalableTag<double>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

// Lane i's bit of `bits` as byte i of a little-endian word (0 or 1): the byte replicated into
// every byte, bit i kept in byte i, each nonzero byte then carried into its top bit (no carry
// crosses a byte: 0x80 + 0x7f < 0x100) and shifted down.
HWY_INLINE std::uint64_t byte_per_bit(unsigned bits) {
    const std::uint64_t x = (bits * 0x0101010101010101ULL) & 0x8040201008040201ULL;
    return ((x + 0x7f7f7f7f7f7f7f7fULL) >> 7) & 0x0101010101010101ULL;
}

// Writes the first `count` bytes of `word` (count <= 8), with one store for a whole vector.
HWY_INLINE void store_bytes(std::uint64_t word, std::uint8_t* out, std::size_t count) {
    switch (count) {
    case 8: std::memcpy(out, &word, 8); break;
    case 4: std::memcpy(out, &word, 4); break;
    case 2: std::memcpy(out, &word, 2); break;
    default:
        for (std::size_t i = 0; i < count; ++i) out[i] = static_cast<std::uint8_t>(word >> (8 * i));
    }
}

// Stores `count` (at most 8) lanes of double masks: 2 where `open` is set, else 1 where `yes` is,
// else 0 (the batches' answers; 2 is a lane the filter left to the scalar query).
HWY_INLINE void store_answers(D d, M yes, M open, std::uint8_t* out, std::size_t count) {
    static_assert(HWY_MAX_BYTES / sizeof(double) <= 8, "one byte of mask bits per vector");
    static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "byte i of the word is lane i");
    std::uint8_t y = 0, o = 0;
    hn::StoreMaskBits(d, yes, &y);
    hn::StoreMaskBits(d, open, &o);
    store_bytes(byte_per_bit(y & ~o & 0xffu) | (byte_per_bit(o) << 1), out, count);
}
// The same where no lane is open: 1 where `yes` is set, else 0.
HWY_INLINE void store_answers(D d, M yes, std::uint8_t* out, std::size_t count) {
    std::uint8_t y = 0;
    hn::StoreMaskBits(d, yes, &y);
    store_bytes(byte_per_bit(y), out, count);
}

// The largest lane of x, a NaN lane counting as infinite (a static bound must not lose a larger
// value to a NaN, which Max would drop or propagate depending on the operand order).
HWY_INLINE V max_counting_nan(D d, V most, V x) { return hn::Max(most, hn::IfThenElse(hn::Eq(x, x), x, hn::Set(d, __builtin_huge_val()))); }

// A kernel's inputs as fields: the one shape's are one value each, broadcast to every lane; the
// many shapes' are arrays, one value per lane.
// Up to fifteen fields: field k is *p[k] in every lane (per_lane[k] false) or p[k][i] in lane i.
struct fields {
    const double* p[15];
    bool per_lane[15];
    int count;
    // The vector of field k from lane i on.
    HWY_INLINE V at(D d, int k, std::size_t i) const { return per_lane[k] ? hn::LoadU(d, p[k] + i) : hn::Set(d, *p[k]); }
};

// An oriented box in lanes: fields 0..2 its centre, 3 + 3 j + k axis j's component k, 12..14 its
// half extents; load_obb reads the first `count` lanes from lane i and says which lanes are usable:
// every number passes ok(x) and no half extent is negative or NaN.
struct lanes_obb {
    V c[3], a[3][3], h[3];
};
// Runs body(f, i, lane, count) over n lanes of f, read at i: whole vectors in place, the tail from
// a zero-padded copy of the per-lane fields (read at 0).
template <class Body>
HWY_INLINE void over_fields(D d, const fields& f, std::size_t n, const Body& body) {
    const std::size_t N = hn::Lanes(d);
    std::size_t i = 0;
    for (; i + N <= n; i += N) body(f, i, i, N);
    if (i == n) return;
    HWY_ALIGN double tail[15][HWY_MAX_BYTES / sizeof(double)] = {};
    fields padded = f;
    for (int k = 0; k < f.count; ++k)
        if (f.per_lane[k]) {
            std::memcpy(tail[k], f.p[k] + i, (n - i) * sizeof(double));
            padded.p[k] = tail[k];
        }
    body(padded, std::size_t{0}, i, n - i);
}
template <class Ok>
HWY_INLINE M load_obb(D d, const fields& g, std::size_t i, std::size_t count, lanes_obb& b, const Ok& ok) {
    M usable = hn::FirstN(d, count);
    for (int k = 0; k < 3; ++k) {
        b.c[k] = g.at(d, k, i), b.h[k] = g.at(d, 12 + k, i);
        usable = hn::And(usable, hn::And(ok(b.c[k]), hn::And(ok(b.h[k]), hn::Ge(b.h[k], hn::Zero(d)))));
        for (int j = 0; j < 3; ++j) {
            b.a[j][k] = g.at(d, 3 + 3 * j + k, i);
            usable = hn::And(usable, ok(b.a[j][k]));
        }
    }
    return usable;
}
// The fields from lane `start` on.
HWY_INLINE fields from(const fields& f, std::size_t start) {
    fields g = f;
    for (int k = 0; k < f.count; ++k)
        if (f.per_lane[k]) g.p[k] += start;
    return g;
}

// The scalar filter's arithmetic in lanes (modules/arith/filtered.cppm), for kernels that must prove
// exactly the signs the scalar filter proves: a three-vector over any number type with +, - and *,
// and arith's cross, dot and det3 operation for operation (the library is built with
// -ffp-contract=off: no product is fused into a sum).
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

// A difference of two inputs (or an input, b = 0): its permanent is |v| (filtered.cppm's K = 1 case).
HWY_INLINE fv exact_difference(V a, V b) {
    const V v = hn::Sub(a, b);
    return {v, hn::Abs(v)};
}
HWY_INLINE vec<pv> values(const vec<fv>& a) { return {{a.x.v}, {a.y.v}, {a.z.v}}; }

// gamma_K with filtered.cppm's (1 + 2^-20) margin: the bound factor of a sign of K operations.
constexpr double gamma_of(int k) {
    const double ku = k * (1.0 / 9007199254740992.0);
    return ku / (1.0 - ku) * (1.0 + 0x1p-20);
}
// A block's static bound gamma p (p: the permanent computed from the block's largest inputs),
// raised to 2^-900: a value above it has |v| > 2^-900, so its own permanent (>= |v|) is trusted
// too. A NaN p stays NaN, and nothing passes it.
HWY_INLINE V static_bound(D d, double gamma, double p) {
    const double b = gamma * p;
    return hn::Set(d, b < 0x1p-900 ? 0x1p-900 : b);
}
// Proven positive / negative against the lane's own bound, as filtered.cppm's proven_sign.
HWY_INLINE M own_positive(D d, double gamma, fv x) {
    return hn::And(hn::Ge(x.p, hn::Set(d, 0x1p-900)), hn::Gt(x.v, hn::Mul(hn::Set(d, gamma), x.p)));
}
HWY_INLINE M own_negative(D d, double gamma, fv x) {
    return hn::And(hn::Ge(x.p, hn::Set(d, 0x1p-900)), hn::Lt(x.v, hn::Neg(hn::Mul(hn::Set(d, gamma), x.p))));
}

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif
