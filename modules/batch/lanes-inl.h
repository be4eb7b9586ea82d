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

} // namespace incidence::batch::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif
