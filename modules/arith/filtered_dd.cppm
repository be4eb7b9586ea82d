// The second filter stage: double-double values with a rigorous u^2-scale error bound. It decides
// almost every configuration that is a few ulps off a decision boundary, leaving only (nearly)
// exact zeros to the expansion stage.
//
// Derivation (u = 2^-53; Dekker's two_product and Knuth's two_sum are exact without underflow):
// a value is (hi, lo) with |lo| <= u |hi|, plus a permanent p and a compile-time count K with
//   (I1) |hi + lo - x| <= e_K p,  e_K = 8 K u^2     (I2) |hi + lo| <= p.
// * input or difference of inputs: two_diff is exact, K = 0, p = |hi| + |lo|.
// * sum: s = two_sum(a.hi, b.hi) (exact); t = (a.lo + b.lo) + s.lo in double errs by at most
//   u (|a.lo| + |b.lo|) + u (1 + u)(|a.lo| + |b.lo| + |s.lo|) <= 3.01 u^2 (pa + pb); two_sum(s.hi, t)
//   renormalises exactly. So e_{max(Ka,Kb)+1} (pa + pb) covers it, with p = fl(pa + pb).
// * product: two_product(a.hi, b.hi) is exact; the cross terms a.hi b.lo + a.lo b.hi err by
//   <= 3.01 u^2 |a.hi b.hi|, the dropped a.lo b.lo is <= u^2 |a.hi b.hi|, adding them to the low
//   part errs by <= 3.01 u^2 |a.hi b.hi|: < 8 u^2 pa pb. Propagation as in filtered.cppm gives
//   e_{Ka+Kb+1}, with p = fl(pa pb) + 2^-960: e_1 2^-960 > 2^-1063 covers the absolute error
//   (<= 3 * 2^-1075) of the products that underflow.
// Trust only 2^-800 <= p <= 2^900 (no underflow of e_K p, no overflow in Dekker's split); the
// final bound is inflated by (1 + 2^-20) for the rounding of p (fewer than 2^30 operations).
module;
// INCIDENCE_DD_INLINE: the double-double filter's operations and vector algebra are always inlined
// in an optimised build (bench/NOTES.md: values that share parts then share them). The sanitizer
// build (-O0, INCIDENCE_UNFORCED_INLINE) leaves them to the compiler: forced inlining at -O0 only
// multiplies the code (the exact value instances took 74 s to compile there, the values fuzzer 93 s).
#ifdef INCIDENCE_UNFORCED_INLINE
#define INCIDENCE_DD_INLINE
#else
#define INCIDENCE_DD_INLINE gnu::always_inline
#endif
export module incidence.arith:filtered_dd;
import :eft;
import :filtered; // unit_roundoff

export namespace incidence::arith {

template <int K>
struct filtered_dd {
    static constexpr int ops = K;
    double hi, lo, p;
};

inline constexpr double dd_infinity = __builtin_huge_val();

template <int A, int B>
[[nodiscard]] constexpr bool dd_poisoned(const filtered_dd<A>& a, const filtered_dd<B>& b) {
    // In constant evaluation NaN is ill-formed: stop before Dekker's split could overflow.
    return __builtin_is_constant_evaluated() && !(a.p < 0x1p900 && b.p < 0x1p900);
}

[[nodiscard]] constexpr filtered_dd<0> lift_filtered_dd(double x) { return {x, 0.0, abs(x)}; }

template <int A, int B>
[[nodiscard, INCIDENCE_DD_INLINE]] constexpr auto operator+(const filtered_dd<A>& a, const filtered_dd<B>& b) {
    constexpr int K = (A > B ? A : B) + 1;
    if (dd_poisoned(a, b)) return filtered_dd<K>{0.0, 0.0, dd_infinity};
    const auto s = two_sum(a.hi, b.hi);
    const double t = (a.lo + b.lo) + s.lo;
    const auto r = two_sum(s.hi, t);
    if constexpr (A == 0 && B == 0) {
        if (a.lo == 0.0 && b.lo == 0.0) return filtered_dd<K>{r.hi, r.lo, abs(r.hi) + abs(r.lo)}; // exact
    }
    return filtered_dd<K>{r.hi, r.lo, a.p + b.p};
}
template <int A>
[[nodiscard, INCIDENCE_DD_INLINE]] constexpr filtered_dd<A> operator-(const filtered_dd<A>& a) {
    return {-a.hi, -a.lo, a.p};
}
// |x|: a normalised double-double has the sign of its leading part; the bound carries over.
template <int A>
[[nodiscard]] constexpr filtered_dd<A> abs(const filtered_dd<A>& a) {
    return a.hi < 0.0 ? -a : a;
}
template <int A, int B>
[[nodiscard, INCIDENCE_DD_INLINE]] constexpr auto operator-(const filtered_dd<A>& a, const filtered_dd<B>& b) {
    if constexpr (A == 0 && B == 0) {
        // Difference of two inputs: exact.
        if (a.lo == 0.0 && b.lo == 0.0) {
            const auto d = two_diff(a.hi, b.hi);
            return filtered_dd<1>{d.hi, d.lo, abs(d.hi) + abs(d.lo)};
        }
    }
    return a + (-b);
}
template <int A, int B>
[[nodiscard, INCIDENCE_DD_INLINE]] constexpr filtered_dd<A + B + 1> operator*(const filtered_dd<A>& a, const filtered_dd<B>& b) {
    if (dd_poisoned(a, b)) return {0.0, 0.0, dd_infinity};
    const auto p = two_product(a.hi, b.hi);
    const double cross = a.hi * b.lo + a.lo * b.hi;
    const auto r = two_sum(p.hi, p.lo + cross);
    return {r.hi, r.lo, a.p * b.p + 0x1p-960};
}

// A bound on |hi + lo - x| (I1), inflated as proven_sign's; infinite where the bound is not trusted.
template <int K>
[[nodiscard]] constexpr double dd_error(const filtered_dd<K>& a) {
    if (!(a.p >= 0x1p-800 && a.p <= 0x1p900)) return dd_infinity;
    constexpr double e = 8.0 * (K + 1) * unit_roundoff * unit_roundoff * (1.0 + 0x1p-20);
    return e * a.p;
}

// +1 / -1 when the sign is proven, 0 otherwise.
template <int K>
[[nodiscard]] constexpr int proven_sign(const filtered_dd<K>& a) {
    if (!(a.p >= 0x1p-800 && a.p <= 0x1p900)) return 0;
    constexpr double e = 8.0 * (K + 1) * unit_roundoff * unit_roundoff * (1.0 + 0x1p-20);
    const double bound = e * a.p;
    // |lo| <= u |hi|, so hi (1 - 2u) > bound proves hi + lo > x - ... > 0.
    const double m = a.hi * (1.0 - 2.0 * unit_roundoff);
    if (m > bound) return 1;
    if (m < -bound) return -1;
    return 0;
}

} // namespace incidence::arith
