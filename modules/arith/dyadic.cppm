// Exact dyadic rationals m * 2^e: the fallback that is exact over the whole finite binary64
// range (subnormals to 2^1024) and usable in constant evaluation. The magnitude is a fixed-
// capacity array of 64-bit limbs (no allocation). A product of d inputs has its bits between
// 2^(-1074 d) and 2^(1024 d), so a polynomial of degree d needs 2098 d bits plus carries when its
// inputs span the full exponent range: 336 limbs (21,504 bits) cover degree 10, the highest of any
// predicate here (the order of two crossings on a coplanar triangle's edges as seen from a vertex,
// contains(mesh, triangle)). Products use 128-bit intermediates;
// everything is plain integer arithmetic, so constexpr.
// Correct rounding back to binary64 (nearest, ties to even) lives here; quotients are rounded
// by exact bracketing (rounding.cppm), so no long division is needed.
// (Boost.Multiprecision's fixed-width cpp_int 1.74 was used first and tripped its own
// assertion `0 == borrow` in subtract_unsigned on operands of ~90 limbs in this build; this
// type replaces it. Boost's cpp_rational remains an independent oracle in tests/arith.)
// Source: Knuth, TAOCP vol. 2, section 4.3.1 (classical algorithms A, S, M).
module;
#include <array>
#include <bit>
#include <cstdint>
export module incidence.arith:dyadic;
import :eft;

export namespace incidence::arith {

inline constexpr int dyadic_limbs = 336;
inline constexpr int dyadic_max_degree = 10;
static_assert(2098 * dyadic_max_degree + 64 <= 64 * dyadic_limbs); // 64 bits of carries: up to 2^64 terms

struct dyadic {
    // Only w[0 .. n) is ever read: at run time the rest stays uninitialised and copies move only
    // the used limbs (a clear or copy of the whole capacity per operation cost more than the arithmetic).
    std::array<std::uint64_t, dyadic_limbs> w; // magnitude, little-endian limbs
    int n = 0;                                 // used limbs; w[n-1] != 0 unless n == 0
    bool neg = false;
    int e = 0; // value = (neg ? -1 : 1) * magnitude * 2^e

    // Constant evaluation forbids reading indeterminate values, so fill there only.
    constexpr dyadic() {
        if (__builtin_is_constant_evaluated()) w.fill(0);
    }
    constexpr dyadic(const dyadic& o) : n(o.n), neg(o.neg), e(o.e) {
        if (__builtin_is_constant_evaluated()) w.fill(0);
        for (int i = 0; i < n; ++i) w[static_cast<unsigned>(i)] = o.w[static_cast<unsigned>(i)];
    }
    constexpr dyadic& operator=(const dyadic& o) {
        if (this == &o) return *this;
        for (int i = 0; i < o.n; ++i) w[static_cast<unsigned>(i)] = o.w[static_cast<unsigned>(i)];
        n = o.n, neg = o.neg, e = o.e;
        return *this;
    }

    [[nodiscard]] constexpr bool is_zero() const { return n == 0; }
    [[nodiscard]] constexpr std::uint64_t limb(int i) const { return i < n ? w[static_cast<unsigned>(i)] : 0; }
};

using u128 = unsigned __int128;

constexpr void trim(dyadic& a) {
    while (a.n > 0 && a.w[static_cast<unsigned>(a.n - 1)] == 0) --a.n;
    if (a.n == 0) a.neg = false;
}

// Number of significant bits of the magnitude (0 for zero).
[[nodiscard]] constexpr int bit_length(const dyadic& a) {
    if (a.n == 0) return 0;
    return (a.n - 1) * 64 + (64 - std::countl_zero(a.w[static_cast<unsigned>(a.n - 1)]));
}

// magnitude << k (k >= 0)
[[nodiscard]] constexpr dyadic shifted_left(const dyadic& a, int k) {
    dyadic r;
    r.neg = a.neg;
    r.e = a.e - k;
    const int limbs = k / 64, bits = k % 64;
    const int top = a.n + limbs + 1 < dyadic_limbs ? a.n + limbs + 1 : dyadic_limbs;
    for (int i = 0; i < top; ++i) r.w[static_cast<unsigned>(i)] = 0;
    for (int i = a.n - 1; i >= 0; --i) {
        const std::uint64_t x = a.w[static_cast<unsigned>(i)];
        const int j = i + limbs;
        // Capacity is sized for every predicate of degree <= dyadic_max_degree (see top); beyond
        // it, bits are dropped rather than written out of bounds.
        if (bits == 0) {
            if (j < dyadic_limbs) r.w[static_cast<unsigned>(j)] = x;
        } else {
            if (j + 1 < dyadic_limbs) r.w[static_cast<unsigned>(j + 1)] |= x >> (64 - bits);
            if (j < dyadic_limbs) r.w[static_cast<unsigned>(j)] |= x << bits;
        }
    }
    r.n = top;
    trim(r);
    return r;
}

[[nodiscard]] constexpr int compare_magnitude(const dyadic& a, const dyadic& b) {
    if (a.n != b.n) return a.n < b.n ? -1 : 1;
    for (int i = a.n - 1; i >= 0; --i) {
        const auto x = a.w[static_cast<unsigned>(i)], y = b.w[static_cast<unsigned>(i)];
        if (x != y) return x < y ? -1 : 1;
    }
    return 0;
}

// |a| + |b| and |a| - |b| (|a| >= |b|), same exponent; sign of the result left to the caller.
[[nodiscard]] constexpr dyadic add_magnitude(const dyadic& a, const dyadic& b) {
    dyadic r;
    r.e = a.e;
    const int m = a.n > b.n ? a.n : b.n;
    std::uint64_t carry = 0;
    for (int i = 0; i < m; ++i) {
        const u128 s = u128{a.limb(i)} + b.limb(i) + carry;
        r.w[static_cast<unsigned>(i)] = static_cast<std::uint64_t>(s);
        carry = static_cast<std::uint64_t>(s >> 64);
    }
    r.n = m;
    if (carry != 0 && m < dyadic_limbs) r.w[static_cast<unsigned>(r.n++)] = carry;
    trim(r);
    return r;
}
[[nodiscard]] constexpr dyadic sub_magnitude(const dyadic& a, const dyadic& b) {
    dyadic r;
    r.e = a.e;
    std::uint64_t borrow = 0;
    for (int i = 0; i < a.n; ++i) {
        const std::uint64_t x = a.w[static_cast<unsigned>(i)], y = b.limb(i);
        const std::uint64_t d = x - y - borrow;
        borrow = (x < y || (x == y && borrow)) ? 1 : 0;
        r.w[static_cast<unsigned>(i)] = d;
    }
    r.n = a.n;
    trim(r);
    return r;
}

// Exact conversion; a non-finite input converts to 0 (callers check finiteness first).
[[nodiscard]] constexpr dyadic to_dyadic(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const int field = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
    dyadic d;
    if (field == 0x7ff) return d;
    int e = -1074;
    if (field != 0) {
        mant |= std::uint64_t{1} << 52;
        e = field - 1075;
    }
    if (mant == 0) return d;
    const int tz = std::countr_zero(mant); // strip trailing zeros: shorter alignment shifts
    d.w[0] = mant >> tz;
    d.n = 1;
    d.e = e + tz;
    d.neg = (bits >> 63) != 0;
    return d;
}

[[nodiscard]] constexpr dyadic abs(const dyadic& a) {
    dyadic r = a;
    r.neg = false;
    return r;
}
[[nodiscard]] constexpr dyadic operator-(const dyadic& a) {
    dyadic r = a;
    if (r.n != 0) r.neg = !r.neg;
    return r;
}

[[nodiscard]] constexpr dyadic operator+(const dyadic& a, const dyadic& b) {
    if (a.is_zero()) return b;
    if (b.is_zero()) return a;
    // Align to the smaller exponent.
    if (a.e > b.e) return shifted_left(a, a.e - b.e) + b;
    if (b.e > a.e) return a + shifted_left(b, b.e - a.e);
    if (a.neg == b.neg) {
        dyadic r = add_magnitude(a, b);
        r.neg = a.neg && r.n != 0;
        return r;
    }
    const int c = compare_magnitude(a, b);
    if (c == 0) return dyadic{};
    dyadic r = c > 0 ? sub_magnitude(a, b) : sub_magnitude(b, a);
    r.neg = c > 0 ? a.neg : b.neg;
    if (r.n == 0) r.neg = false;
    return r;
}
[[nodiscard]] constexpr dyadic operator-(const dyadic& a, const dyadic& b) { return a + (-b); }

[[nodiscard]] constexpr dyadic operator*(const dyadic& a, const dyadic& b) {
    if (a.is_zero() || b.is_zero()) return dyadic{};
    dyadic r;
    r.e = a.e + b.e;
    r.neg = a.neg != b.neg;
    const int top = a.n + b.n < dyadic_limbs ? a.n + b.n : dyadic_limbs;
    for (int i = 0; i < top; ++i) r.w[static_cast<unsigned>(i)] = 0;
    for (int i = 0; i < a.n; ++i) {
        std::uint64_t carry = 0;
        const u128 x = a.w[static_cast<unsigned>(i)];
        for (int j = 0; j < b.n; ++j) {
            const int k = i + j;
            if (k >= dyadic_limbs) break;
            const u128 t = x * b.w[static_cast<unsigned>(j)] + r.w[static_cast<unsigned>(k)] + carry;
            r.w[static_cast<unsigned>(k)] = static_cast<std::uint64_t>(t);
            carry = static_cast<std::uint64_t>(t >> 64);
        }
        if (i + b.n < dyadic_limbs) r.w[static_cast<unsigned>(i + b.n)] = carry;
    }
    r.n = top;
    trim(r);
    return r;
}

[[nodiscard]] constexpr int sign_of(const dyadic& a) { return a.n == 0 ? 0 : (a.neg ? -1 : 1); }

// Bit k of the magnitude.
[[nodiscard]] constexpr bool bit(const dyadic& a, int k) {
    if (k < 0 || k >= a.n * 64) return false;
    return ((a.w[static_cast<unsigned>(k / 64)] >> (k % 64)) & 1u) != 0;
}
// Any bit below position k set?
[[nodiscard]] constexpr bool any_below(const dyadic& a, int k) {
    for (int i = 0; i < a.n && i * 64 < k; ++i) {
        const int hi = (i + 1) * 64 <= k ? 64 : k - i * 64;
        const std::uint64_t mask = hi == 64 ? ~std::uint64_t{0} : ((std::uint64_t{1} << hi) - 1);
        if (a.w[static_cast<unsigned>(i)] & mask) return true;
    }
    return false;
}

// Nearest binary64 (ties to even); overflow gives an infinity.
[[nodiscard]] constexpr double to_double(const dyadic& a) {
    if (a.is_zero()) return 0.0;
    const int len = bit_length(a);
    const int lead = len - 1 + a.e;                          // exponent of the leading bit
    const int low = (lead - 52) > -1074 ? lead - 52 : -1074; // exponent of the last kept bit
    const int drop = low - a.e;                              // bits of the magnitude dropped
    std::uint64_t q = 0;
    for (int k = len - 1; k >= (drop > 0 ? drop : 0); --k) q = (q << 1) | (bit(a, k) ? 1u : 0u);
    if (drop < 0) q <<= -drop;
    int low_exp = low;
    if (drop > 0) {
        const bool half = bit(a, drop - 1);
        const bool rest = any_below(a, drop - 1);
        if (half && (rest || (q & 1u))) ++q;
    }
    if (q == (std::uint64_t{1} << 53)) {
        q >>= 1;
        ++low_exp;
    }
    std::uint64_t bits = 0;
    if (q >= (std::uint64_t{1} << 52)) {
        const int field = low_exp + 52 + 1023;
        bits = field >= 0x7ff ? std::uint64_t{0x7ff} << 52 : (static_cast<std::uint64_t>(field) << 52) | (q - (std::uint64_t{1} << 52));
    } else {
        bits = q; // subnormal
    }
    if (a.neg) bits |= std::uint64_t{1} << 63;
    return std::bit_cast<double>(bits);
}

} // namespace incidence::arith
