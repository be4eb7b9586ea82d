// Correct rounding of a real number known only through exact comparisons.
// Given le(y) == (x <= y) and lt(y) == (x < y) for dyadic y, returns the binary64 nearest to
// x, ties to even: bisection over the ordered bit patterns of binary64, started from a guess.
// Source: the midpoint test of Muller et al., Handbook of Floating-Point Arithmetic (2018),
// section 2.2 (rounding functions and midpoints).
module;
#include <bit>
#include <cstdint>
export module incidence.arith:rounding;
import incidence.core;
import :eft;
import :dyadic;

export namespace incidence::arith {

// Monotone map from finite doubles to integers (order-preserving; -0 and +0 share 0).
[[nodiscard]] constexpr std::int64_t order_key(double x) {
    const auto b = std::bit_cast<std::uint64_t>(x);
    const auto mag = static_cast<std::int64_t>(b & ~(std::uint64_t{1} << 63));
    return (b >> 63) ? -mag : mag;
}
[[nodiscard]] constexpr double from_order_key(std::int64_t k) {
    if (k >= 0) return std::bit_cast<double>(static_cast<std::uint64_t>(k));
    return std::bit_cast<double>(static_cast<std::uint64_t>(-k) | (std::uint64_t{1} << 63));
}
inline constexpr std::int64_t max_finite_key = 0x7fefffffffffffff;

// The midpoint between the doubles with keys k and k + 1, exactly (k + 1 <= max key).
[[nodiscard]] constexpr dyadic midpoint_above(std::int64_t k) {
    dyadic m = to_dyadic(from_order_key(k)) + to_dyadic(from_order_key(k + 1));
    m.e -= 1;
    return m;
}

template <class Le, class Lt>
[[nodiscard]] constexpr double correctly_round(Le le, Lt lt, double guess) {
    // Find the smallest key k with x <= midpoint_above(k): then x lies in
    // [midpoint_above(k - 1), midpoint_above(k)] and the nearest double has key k.
    auto ok = [&](std::int64_t k) { return k >= max_finite_key || le(midpoint_above(k)); };
    std::int64_t lo = -max_finite_key - 1; // ok(lo) treated false (sentinel below everything)
    std::int64_t hi = max_finite_key;      // ok(hi) true (x beyond the last midpoint rounds to max/inf)
    if (is_finite(guess)) {
        const std::int64_t g = order_key(guess);
        const std::int64_t a = g - 4 > -max_finite_key ? g - 4 : -max_finite_key;
        const std::int64_t b = g + 4 < max_finite_key ? g + 4 : max_finite_key;
        if (!ok(a)) lo = a;
        if (ok(b)) hi = b;
    }
    // hi - lo can exceed INT64_MAX (the key range spans 2^64): take the difference unsigned.
    while (static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo) > 1) {
        const std::int64_t mid = lo + static_cast<std::int64_t>((static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo)) / 2);
        if (ok(mid)) hi = mid;
        else lo = mid;
    }
    std::int64_t k = hi;
    if (k >= max_finite_key) {
        // Beyond the largest finite double's upper midpoint: overflow to infinity.
        dyadic top = to_dyadic(from_order_key(max_finite_key));
        dyadic half_ulp = to_dyadic(0x1p970);
        if (!lt(top + half_ulp)) return __builtin_huge_val();
        return from_order_key(max_finite_key);
    }
    if (k <= -max_finite_key) {
        dyadic bottom = to_dyadic(from_order_key(-max_finite_key));
        dyadic half_ulp = to_dyadic(0x1p970);
        if (le(bottom - half_ulp)) return -__builtin_huge_val();
    }
    // Tie: x exactly at the midpoint above k -> pick the even one of k, k + 1.
    if (k < max_finite_key && !lt(midpoint_above(k))) {
        const double a = from_order_key(k), b = from_order_key(k + 1);
        return (std::bit_cast<std::uint64_t>(a) & 1u) ? b : a;
    }
    return from_order_key(k);
}

// Correctly rounded n / d (d != 0), by bracketing: n/d <= y  <=>  sign(d) (n - y d) <= 0.
[[nodiscard]] constexpr double quotient(const dyadic& n, const dyadic& d) {
    const int sd = sign_of(d);
    auto le = [&](const dyadic& y) { return sign_of(n - y * d) * sd <= 0; };
    auto lt = [&](const dyadic& y) { return sign_of(n - y * d) * sd < 0; };
    const double nd = to_double(n), dd = to_double(d);
    double guess = 0.0;
    if (is_finite(nd) && is_finite(dd) && dd != 0.0 && nd != 0.0) {
        const int k = exponent_of(nd) - exponent_of(dd);
        if (k > -1000 && k < 1000) guess = nd / dd;
    }
    return correctly_round(le, lt, guess);
}

} // namespace incidence::arith
