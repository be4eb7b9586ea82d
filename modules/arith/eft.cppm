// Error-free transforms on binary64, all constexpr (no std::fma, which is not constexpr).
// Source: Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
// Predicates", DCG 18 (1997), sections 2.2-2.5; Dekker (1971) and Veltkamp splitting.
// Valid for round-to-nearest-even without overflow; two_product is exact only while the low
// part a*b - fl(a*b) is representable, i.e. |a*b| >= 2^-969 (callers guarantee the range).
module;
#include <bit>
#include <cstdint>
export module incidence.arith:eft;

export namespace incidence::arith {

struct two_double {
    double hi; // fl(result)
    double lo; // exact rounding error: hi + lo == exact result
};

[[nodiscard]] constexpr double abs(double x) { return __builtin_fabs(x); }

// Dekker's Fast-Two-Sum; requires |a| >= |b| (or a == 0).
[[nodiscard]] constexpr two_double fast_two_sum(double a, double b) {
    const double x = a + b;
    const double bvirt = x - a;
    return {x, b - bvirt};
}

// Knuth's Two-Sum: no precondition on magnitudes.
[[nodiscard]] constexpr two_double two_sum(double a, double b) {
    const double x = a + b;
    const double bvirt = x - a;
    const double avirt = x - bvirt;
    const double bround = b - bvirt;
    const double around = a - avirt;
    return {x, around + bround};
}

[[nodiscard]] constexpr two_double two_diff(double a, double b) {
    const double x = a - b;
    const double bvirt = a - x;
    const double avirt = x + bvirt;
    const double bround = bvirt - b;
    const double around = a - avirt;
    return {x, around + bround};
}

// Veltkamp split into two 26-bit halves (Shewchuk's Split); |a| < 2^996 so c does not overflow.
[[nodiscard]] constexpr two_double split(double a) {
    constexpr double splitter = 134217729.0; // 2^27 + 1
    const double c = splitter * a;
    const double abig = c - a;
    const double ahi = c - abig;
    return {ahi, a - ahi};
}

// Dekker's Two-Product by splitting (constexpr, unlike std::fma).
[[nodiscard]] constexpr two_double two_product(double a, double b) {
    const double x = a * b;
    const auto [ahi, alo] = split(a);
    const auto [bhi, blo] = split(b);
    const double err1 = x - (ahi * bhi);
    const double err2 = err1 - (alo * bhi);
    const double err3 = err2 - (ahi * blo);
    return {x, (alo * blo) - err3};
}

// Binary exponent of a finite nonzero double: floor(log2 |x|), subnormals included.
[[nodiscard]] constexpr int exponent_of(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const int field = static_cast<int>((bits >> 52) & 0x7ff);
    if (field != 0) return field - 1023;
    std::uint64_t m = bits & ((std::uint64_t{1} << 52) - 1);
    return (63 - std::countl_zero(m)) - 1074;
}

// x * 2^k, exact when the result is a normal number or an exactly representable subnormal.
[[nodiscard]] constexpr double scale_by_power_of_two(double x, int k) {
    double f = 1.0;
    double step = k >= 0 ? 2.0 : 0.5;
    int n = k >= 0 ? k : -k;
    // Multiply in chunks of at most 2^512 so the factor itself never overflows/underflows.
    while (n > 0) {
        const int chunk = n > 512 ? 512 : n;
        f = 1.0;
        double s = step;
        for (int i = chunk; i > 0; i >>= 1) {
            if (i & 1) f *= s;
            s *= s;
        }
        x *= f;
        n -= chunk;
    }
    return x;
}

// Square root usable in constant evaluation (Newton from a power-of-two start, monotone
// convergence), the hardware instruction at run time. Only used for starting guesses and the
// approximate tier, never for a decision of the exact tier.
[[nodiscard]] constexpr double sqrt(double x) {
    if (!__builtin_is_constant_evaluated()) return __builtin_sqrt(x);
    if (!(x > 0.0) || !(x < __builtin_huge_val())) return x == 0.0 ? 0.0 : (x > 0.0 ? x : 0.0);
    double y = scale_by_power_of_two(1.0, (exponent_of(x) + 1) / 2 + 1); // y >= sqrt(x)
    for (int i = 0; i < 200; ++i) {
        const double z = 0.5 * (y + x / y);
        if (!(z < y)) break;
        y = z;
    }
    return y;
}

[[nodiscard]] constexpr double next_up(double x) {
    if (x != x || x == __builtin_huge_val()) return x;
    if (x == 0.0) return std::bit_cast<double>(std::uint64_t{1});
    auto b = std::bit_cast<std::uint64_t>(x);
    b = x > 0.0 ? b + 1 : b - 1;
    return std::bit_cast<double>(b);
}
[[nodiscard]] constexpr double next_down(double x) { return -next_up(-x); }

} // namespace incidence::arith
