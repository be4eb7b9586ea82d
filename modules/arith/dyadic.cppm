// Exact dyadic rationals m * 2^e with a fixed-width Boost.Multiprecision integer mantissa:
// the fallback that is exact over the whole finite binary64 range (subnormals, 2^1023), and
// usable in constant evaluation. The mantissa width covers polynomials of degree 5 whose inputs
// span the full exponent range (5 * 2100 bits plus carries). Correct rounding back to binary64
// (round to nearest, ties to even) and correctly rounded quotients live here too.
module;
#include <bit>
#include <cstdint>
#include <boost/multiprecision/cpp_int.hpp>
export module incidence.arith:dyadic;
import :eft;

export namespace incidence::arith {

inline constexpr unsigned dyadic_bits = 11264;
using big_int = boost::multiprecision::number<
    boost::multiprecision::cpp_int_backend<dyadic_bits, dyadic_bits, boost::multiprecision::signed_magnitude,
                                           boost::multiprecision::unchecked, void>,
    boost::multiprecision::et_off>;

struct dyadic {
    big_int m; // value = m * 2^e
    int e = 0;
};

// Exact conversion; a non-finite input converts to 0 (callers check finiteness first).
[[nodiscard]] constexpr dyadic to_dyadic(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const int field = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
    if (field == 0x7ff) return {};
    int e = -1074;
    if (field != 0) {
        mant |= std::uint64_t{1} << 52;
        e = field - 1075;
    }
    if (mant == 0) return {};
    // Strip trailing zeros so alignment shifts stay short.
    const int tz = std::countr_zero(mant);
    mant >>= tz;
    e += tz;
    dyadic d{big_int(mant), e};
    if (bits >> 63) d.m = -d.m;
    return d;
}

[[nodiscard]] constexpr dyadic operator+(const dyadic& a, const dyadic& b) {
    if (a.m.is_zero()) return b;
    if (b.m.is_zero()) return a;
    if (a.e >= b.e) return {(a.m << static_cast<unsigned>(a.e - b.e)) + b.m, b.e};
    return {a.m + (b.m << static_cast<unsigned>(b.e - a.e)), a.e};
}
[[nodiscard]] constexpr dyadic operator-(const dyadic& a) { return {-a.m, a.e}; }
[[nodiscard]] constexpr dyadic operator-(const dyadic& a, const dyadic& b) { return a + (-b); }
[[nodiscard]] constexpr dyadic operator*(const dyadic& a, const dyadic& b) {
    if (a.m.is_zero() || b.m.is_zero()) return {};
    return {a.m * b.m, a.e + b.e};
}
[[nodiscard]] constexpr int sign_of(const dyadic& a) { return a.m.sign(); }

// Round mag * 2^e (+ a sticky "something nonzero below") to the nearest binary64, ties to even.
[[nodiscard]] constexpr double round_to_double(big_int mag, int e, bool sticky, bool negative) {
    if (mag.is_zero()) return negative ? -0.0 : 0.0;
    const int top = static_cast<int>(boost::multiprecision::msb(mag));
    const int lead = top + e;                              // exponent of the leading bit
    const int low = (lead - 52) > -1074 ? lead - 52 : -1074; // exponent of the last kept bit
    const int drop = low - e;
    std::uint64_t q = 0;
    int low_exp = low;
    if (drop <= 0) {
        q = static_cast<std::uint64_t>(mag << static_cast<unsigned>(-drop));
    } else {
        const big_int kept = mag >> static_cast<unsigned>(drop);
        const big_int rem = mag - (kept << static_cast<unsigned>(drop));
        const big_int half = big_int(1) << static_cast<unsigned>(drop - 1);
        q = static_cast<std::uint64_t>(kept);
        const bool up = rem > half || (rem == half && (sticky || (q & 1u)));
        if (up) ++q;
    }
    if (q == (std::uint64_t{1} << 53)) {
        q >>= 1;
        ++low_exp;
    }
    std::uint64_t bits = 0;
    if (q >= (std::uint64_t{1} << 52)) {
        const int field = low_exp + 52 + 1023;
        if (field >= 0x7ff) bits = std::uint64_t{0x7ff} << 52; // overflow: infinity
        else bits = (static_cast<std::uint64_t>(field) << 52) | (q - (std::uint64_t{1} << 52));
    } else {
        bits = q; // subnormal (low_exp == -1074)
    }
    if (negative) bits |= std::uint64_t{1} << 63;
    return std::bit_cast<double>(bits);
}

[[nodiscard]] constexpr double to_double(const dyadic& a) {
    const bool neg = a.m.sign() < 0;
    return round_to_double(neg ? big_int(-a.m) : a.m, a.e, false, neg);
}

// Correctly rounded n / d (d != 0).
[[nodiscard]] constexpr double quotient(const dyadic& n, const dyadic& d) {
    if (n.m.is_zero()) return 0.0;
    const bool neg = (n.m.sign() < 0) != (d.m.sign() < 0);
    big_int nm = n.m.sign() < 0 ? big_int(-n.m) : n.m;
    const big_int dm = d.m.sign() < 0 ? big_int(-d.m) : d.m;
    const int nb = static_cast<int>(boost::multiprecision::msb(nm));
    const int db = static_cast<int>(boost::multiprecision::msb(dm));
    int k = db - nb + 56;
    if (k < 0) k = 0;
    nm <<= static_cast<unsigned>(k);
    const big_int q = nm / dm;
    const big_int r = nm - q * dm;
    return round_to_double(q, n.e - d.e - k, !r.is_zero(), neg);
}

} // namespace incidence::arith
