// A double that carries a rigorous bound on its own rounding error: the semi-static filter.
//
// Derivation (standard model fl(a op b) = (a op b)(1 + d), |d| <= u = 2^-53, plus an
// absolute error |eta| <= 2^-1075 for a product that underflows; sums are exact when subnormal).
// Each value carries v (computed), p (a "permanent") and a compile-time count K, with
//   (I1) |v - x| <= gamma_K * p      (x: the exact value, gamma_K = K u / (1 - K u))
//   (I2) |v| <= p
// * input:               v = x, p = |x|, K = 0.
// * difference of inputs: v = fl(a - b), p = |v|, K = 1      (|fl(y) - y| <= u |fl(y)| under RN).
// * sum/difference:      p = fl(pa + pb), K = max(Ka, Kb) + 1:
//     |v - x| <= gamma_Ka pa + gamma_Kb pb + u (pa + pb) <= gamma_{max+1} (pa + pb).
// * product:             p = fl(fl(pa pb) + c), c = 2^-1020, K = Ka + Kb + 1:
//     |va vb - xa xb| <= |va||vb - xb| + |xb||va - xa| <= (gamma_Ka + gamma_Kb + gamma_Ka gamma_Kb) pa pb
//     and the rounding adds u |va vb| + eta; gamma_{Ka+Kb+1} c >= u c = 2^-1073 > eta covers eta.
// Rounding of p itself loses at most a factor (1 - u) per operation; the final bound is inflated
// by (1 + 2^-20), valid for expressions of fewer than 2^30 operations. A permanent below 2^-900
// is not trusted (gamma * p could round in the subnormal range): the filter says "uncertain".
// This also keeps every operand of the fast path normal (a subnormal operand costs a microcode
// assist of ~100 cycles on x86). Overflow makes p infinite or NaN, so the bound test fails too:
// the filter never claims a sign it cannot prove, at any input magnitude.
export module incidence.arith:filtered;
import :eft;

export namespace incidence::arith {

inline constexpr double unit_roundoff = 1.0 / 9007199254740992.0; // 2^-53

template <int K>
struct filtered {
    static constexpr int ops = K;
    double v;
    double p;
};

[[nodiscard]] constexpr filtered<0> lift_filtered(double x) { return {x, abs(x)}; }

// In constant evaluation an operation that yields NaN (inf - inf, 0 * inf) is ill-formed, so an
// overflowed operand short-circuits to the "unbounded" value {0, inf}; at run time the IEEE
// result (inf or NaN) is just as conclusive, since the bound test then fails.
inline constexpr double infinity = __builtin_huge_val();
template <int A, int B>
[[nodiscard]] constexpr bool poisoned(filtered<A> a, filtered<B> b) {
    return __builtin_is_constant_evaluated() && !(a.p < infinity && b.p < infinity);
}

template <int A, int B>
[[nodiscard]] constexpr auto operator+(filtered<A> a, filtered<B> b) {
    if (poisoned(a, b)) return filtered<(A > B ? A : B) + 1>{0.0, infinity};
    const double v = a.v + b.v;
    if constexpr (A == 0 && B == 0) return filtered<1>{v, abs(v)};
    else return filtered<(A > B ? A : B) + 1>{v, a.p + b.p};
}
template <int A, int B>
[[nodiscard]] constexpr auto operator-(filtered<A> a, filtered<B> b) {
    if (poisoned(a, b)) return filtered<(A > B ? A : B) + 1>{0.0, infinity};
    const double v = a.v - b.v;
    if constexpr (A == 0 && B == 0) return filtered<1>{v, abs(v)};
    else return filtered<(A > B ? A : B) + 1>{v, a.p + b.p};
}
template <int A>
[[nodiscard]] constexpr filtered<A> operator-(filtered<A> a) {
    return {-a.v, a.p};
}
template <int A, int B>
[[nodiscard]] constexpr filtered<A + B + 1> operator*(filtered<A> a, filtered<B> b) {
    if (poisoned(a, b)) return {0.0, infinity};
    return {a.v * b.v, a.p * b.p + 0x1p-1020};
}

// |x|: the bound carries over unchanged, since | |v| - |x| | <= |v - x| and | |v| | <= p.
template <int A>
[[nodiscard]] constexpr filtered<A> abs(filtered<A> a) {
    return {abs(a.v), a.p};
}
template <int K>
[[nodiscard]] constexpr double error_bound(filtered<K> a) {
    constexpr double ku = K * unit_roundoff;
    constexpr double gamma = ku / (1.0 - ku) * (1.0 + 0x1p-20);
    return gamma * a.p;
}

// Whether a nonzero value is proven: |v| against the bound in one test, for a caller that only
// asks whether the value is zero (proven_sign's two tests branch on the sign, which on random
// inputs is mispredicted half the time).
template <int K>
[[nodiscard]] constexpr bool proven_nonzero(filtered<K> a) {
    return a.p >= 0x1p-900 && abs(a.v) > error_bound(a);
}

// +1 / -1 when the sign is proven, 0 when the filter cannot decide.
template <int K>
[[nodiscard]] constexpr int proven_sign(filtered<K> a) {
    if (!(a.p >= 0x1p-900)) return 0; // tiny, zero or NaN permanent: not trusted
    const double b = error_bound(a);
    if (a.v > b) return 1;
    if (a.v < -b) return -1;
    return 0;
}

} // namespace incidence::arith
