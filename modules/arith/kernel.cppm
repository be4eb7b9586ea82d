// One predicate, four tiers. A predicate is written once as a generic lambda
//     [=](auto L) { ... return polynomial(L(x0), L(x1), ...); }
// that lifts its double inputs with L and returns a polynomial expression in them. Each
// *kernel* evaluates it with a different number type and turns the result into a sign:
//   approx_kernel  plain double                      (tier approximate)
//   filter_kernel  filtered<K> (rigorous error bound) (classify; conservative/aggressive)
//   exact_kernel   filter, then (out of line) the filter on power-of-two-scaled inputs, plain
//                  double with every operation exact, double-double, expansions in a safe
//                  exponent window, dyadic big integers
// A query body is a template over the kernel, so the *same* decision logic runs in every tier
// (incidence.query's decide_pair: the filter kernel first, the exact kernel only when it failed).
//
// Rule for predicate polynomials: homogeneous in their inputs (every input has degree 1,
// no literal constants), so scaling all inputs by 2^s keeps the sign: the scaled filter stage and
// the expansions' exponent window rely on it, and the range probe checks it.
// A constant that balances degrees is lifted like an input (L(1.0)), so it scales with them.
// abs(x) of a subexpression is allowed: every number type knows or bounds its sign, and
// |x| keeps both the degree and the filters' error bounds.
module;
// INCIDENCE_DD_INLINE, defined as in filtered_dd.cppm (a module cannot export a macro), for the
// double-double overloads of the vector algebra below.
#ifdef INCIDENCE_UNFORCED_INLINE
#define INCIDENCE_DD_INLINE
#else
#define INCIDENCE_DD_INLINE gnu::always_inline
#endif
#include <type_traits>
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
export module incidence.arith:kernel;
import incidence.core;
import :eft;
import :expansion;
import :filtered;
import :filtered_dd;
import :dyadic;

export namespace incidence::arith {

// What a kernel makes of a query's values (value.cppm): plain double, an enclosing interval, or
// the correctly rounded double.
enum class value_mode : unsigned char { plain, enclosure, rounded };

// --- generic small vector algebra over any number type --------------------------------------
template <class T>
struct v3 {
    T x, y, z;
};
template <class T>
struct v2 {
    T x, y;
};
template <class L>
[[nodiscard]] constexpr auto lift(L l, point3 p) {
    return v3<decltype(l(0.0))>{l(p.x), l(p.y), l(p.z)};
}
template <class L>
[[nodiscard]] constexpr auto lift(L l, vec3 p) {
    return v3<decltype(l(0.0))>{l(p.x), l(p.y), l(p.z)};
}
template <class L>
[[nodiscard]] constexpr auto lift(L l, point2 p) {
    return v2<decltype(l(0.0))>{l(p.x), l(p.y)};
}
template <class L>
[[nodiscard]] constexpr auto lift(L l, vec2 p) {
    return v2<decltype(l(0.0))>{l(p.x), l(p.y)};
}

template <class A, class B>
[[nodiscard]] constexpr auto operator-(const v3<A>& a, const v3<B>& b) {
    return v3<decltype(a.x - b.x)>{a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class A, class B>
[[nodiscard]] constexpr auto operator+(const v3<A>& a, const v3<B>& b) {
    return v3<decltype(a.x + b.x)>{a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class A, class B>
[[nodiscard]] constexpr auto dot(const v3<A>& a, const v3<B>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class A, class B>
[[nodiscard]] constexpr auto cross(const v3<A>& a, const v3<B>& b) {
    using T = decltype(a.y * b.z - a.z * b.y);
    return v3<T>{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// The vector a times the scalar s.
template <class A, class S>
[[nodiscard]] constexpr auto scaled(const v3<A>& a, const S& s) {
    return v3<decltype(a.x * s)>{a.x * s, a.y * s, a.z * s};
}
// det[a; b; c] = a . (b x c)
template <class A, class B, class C>
[[nodiscard]] constexpr auto det3(const v3<A>& a, const v3<B>& b, const v3<C>& c) {
    return a.x * (b.y * c.z - b.z * c.y) + a.y * (b.z * c.x - b.x * c.z) + a.z * (b.x * c.y - b.y * c.x);
}
// The same over the double-double filter, always inlined: a value's parts in that filter are
// composed of these, and once inlined into one function, several values share them
// (intersection/linear_pairs.cppm's rounded_triangle_values). Only there: inlining them for every
// number type made the yes/no filter's bodies slower (bench/NOTES.md).
template <int A, int B>
[[nodiscard, INCIDENCE_DD_INLINE]] constexpr auto operator-(const v3<filtered_dd<A>>& a, const v3<filtered_dd<B>>& b) {
    return v3<decltype(a.x - b.x)>{a.x - b.x, a.y - b.y, a.z - b.z};
}
template <int A, int B>
[[nodiscard, INCIDENCE_DD_INLINE]] constexpr auto dot(const v3<filtered_dd<A>>& a, const v3<filtered_dd<B>>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <int A, int B>
[[nodiscard, INCIDENCE_DD_INLINE]] constexpr auto cross(const v3<filtered_dd<A>>& a, const v3<filtered_dd<B>>& b) {
    using T = decltype(a.y * b.z - a.z * b.y);
    return v3<T>{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <int A, int B, int C>
[[nodiscard, INCIDENCE_DD_INLINE]] constexpr auto det3(const v3<filtered_dd<A>>& a, const v3<filtered_dd<B>>& b,
                                                       const v3<filtered_dd<C>>& c) {
    return a.x * (b.y * c.z - b.z * c.y) + a.y * (b.z * c.x - b.x * c.z) + a.z * (b.x * c.y - b.y * c.x);
}
template <int A, int B>
[[nodiscard, INCIDENCE_DD_INLINE]] constexpr auto cross(const v2<filtered_dd<A>>& a, const v2<filtered_dd<B>>& b) {
    return a.x * b.y - a.y * b.x;
}
template <class A, class B>
[[nodiscard]] constexpr auto operator-(const v2<A>& a, const v2<B>& b) {
    return v2<decltype(a.x - b.x)>{a.x - b.x, a.y - b.y};
}
template <class A, class B>
[[nodiscard]] constexpr auto dot(const v2<A>& a, const v2<B>& b) {
    return a.x * b.x + a.y * b.y;
}
template <class A, class B>
[[nodiscard]] constexpr auto cross(const v2<A>& a, const v2<B>& b) {
    return a.x * b.y - a.y * b.x;
}

// --- lifts -----------------------------------------------------------------------------------
struct lift_double {
    [[nodiscard]] constexpr double operator()(double x) const { return x; }
};
struct lift_filter {
    [[nodiscard]] constexpr filtered<0> operator()(double x) const { return lift_filtered(x); }
};
struct lift_filter_dd {
    [[nodiscard]] constexpr filtered_dd<0> operator()(double x) const { return lift_filtered_dd(x); }
};
struct lift_expansion {
    int shift = 0; // inputs are scaled by 2^shift (exact inside the safe window)
    [[nodiscard]] constexpr expansion<1> operator()(double x) const {
        return expansion<1>(shift == 0 ? x : scale_by_power_of_two(x, shift));
    }
};
// Plain double evaluation that also reports whether every operation was exact (its rounding
// error, by two_sum/two_diff/two_product, is zero, with no overflow and no underflow). When it
// was, the double result is the exact value: this settles exactly touching inputs (a shared
// vertex, small integers) whose zero the filter cannot prove, before any expansion.
struct exact_double {
    double v;
    bool exact;
    bool finite = true; // no NaN or infinite input below this node
};
// Once an operation is inexact the value no longer matters: {0, false}, computing nothing that
// could overflow (constant evaluation refuses a NaN). An exact zero factor still makes a product
// exactly zero, whatever the other factor's rounding, as long as that factor's inputs are finite
// (its true value is then a finite real): coplanar inputs (equal z, zero z-components) make many
// terms exactly zero while their other factors round.
[[nodiscard, gnu::always_inline]] constexpr exact_double operator+(exact_double a, exact_double b) {
    const bool fin = a.finite && b.finite;
    if (!a.exact || !b.exact || !(abs(a.v) < 0x1p1021 && abs(b.v) < 0x1p1021)) return {0.0, false, fin};
    const auto s = two_sum(a.v, b.v);
    return {s.hi, s.lo == 0.0, fin};
}
[[nodiscard, gnu::always_inline]] constexpr exact_double operator-(exact_double a) { return {-a.v, a.exact, a.finite}; }
[[nodiscard, gnu::always_inline]] constexpr exact_double operator-(exact_double a, exact_double b) { return a + (-b); }
[[nodiscard, gnu::always_inline]] constexpr exact_double abs(exact_double a) { return {abs(a.v), a.exact, a.finite}; }
[[nodiscard, gnu::always_inline]] constexpr exact_double operator*(exact_double a, exact_double b) {
    const bool fin = a.finite && b.finite;
    if (fin && ((a.exact && a.v == 0.0) || (b.exact && b.v == 0.0))) return {0.0, true, true};
    if (!a.exact || !b.exact) return {0.0, false, fin};
    const int e = exponent_of(a.v) + exponent_of(b.v); // |a b| in [2^e, 2^(e+2))
    if (e > 1020 || e < -968 || !(abs(a.v) < 0x1p995 && abs(b.v) < 0x1p995)) return {0.0, false, true};
    const auto p = two_product(a.v, b.v);
    return {p.hi, p.lo == 0.0, true};
}
struct lift_exact_double {
    [[nodiscard]] constexpr exact_double operator()(double x) const {
        const bool fin = abs(x) <= 0x1.fffffffffffffp1023;
        return {x, fin, fin};
    }
};
// Zeros by structure: a node is exactly zero (for finite inputs) when it is a zero input, a
// difference of two equal inputs (a sum of two opposite ones), a sum or difference of two such
// zeros, or a product with such a factor. Coplanar and axis-aligned inputs (equal coordinates, zero
// direction components) make whole terms zero this way, which no error bound can prove; a zero by
// cancellation of nonzero terms is not seen (exact_double settles those it can). Only compares:
// much cheaper than exact_double's error-free operations.
struct zero_input {
    double x;
};
struct zero_node {
    bool z;
};
template <class T>
concept zero_operand = std::is_same_v<T, zero_input> || std::is_same_v<T, zero_node>;
[[nodiscard, gnu::always_inline]] constexpr bool is_zero_node(zero_input a) { return a.x == 0.0; }
[[nodiscard, gnu::always_inline]] constexpr bool is_zero_node(zero_node a) { return a.z; }
[[nodiscard, gnu::always_inline]] constexpr zero_node operator-(zero_input a, zero_input b) { return {a.x == b.x}; }
[[nodiscard, gnu::always_inline]] constexpr zero_node operator+(zero_input a, zero_input b) { return {a.x == -b.x}; }
template <zero_operand A, zero_operand B>
[[nodiscard, gnu::always_inline]] constexpr zero_node operator+(A a, B b) {
    return {is_zero_node(a) && is_zero_node(b)};
}
template <zero_operand A, zero_operand B>
[[nodiscard, gnu::always_inline]] constexpr zero_node operator-(A a, B b) {
    return {is_zero_node(a) && is_zero_node(b)};
}
template <zero_operand A, zero_operand B>
[[nodiscard, gnu::always_inline]] constexpr zero_node operator*(A a, B b) {
    return {is_zero_node(a) || is_zero_node(b)};
}
[[nodiscard, gnu::always_inline]] constexpr zero_input operator-(zero_input a) { return {-a.x}; }
[[nodiscard, gnu::always_inline]] constexpr zero_node operator-(zero_node a) { return a; }
[[nodiscard, gnu::always_inline]] constexpr zero_input abs(zero_input a) { return {abs(a.x)}; }
[[nodiscard, gnu::always_inline]] constexpr zero_node abs(zero_node a) { return a; }
struct lift_zero {
    [[nodiscard]] constexpr zero_input operator()(double x) const { return {x}; }
};
// Whether f is zero by structure. Sound only where its inputs are finite (finite_zero below).
template <class F>
[[nodiscard, gnu::always_inline]] constexpr bool zero_by_structure(const F& f) {
    return is_zero_node(f(lift_zero{}));
}

struct lift_dyadic {
    [[nodiscard]] constexpr dyadic operator()(double x) const { return to_dyadic(x); }
};

// Range probe: the polynomial's degree range and the exponent range of its nonzero inputs, and
// for the scaled filter stage hi, with the node's permanent below 2^hi (each sum counted as if
// nothing cancelled, so it can only overestimate). Its operations are always inlined: it runs on
// every sign the filter leaves open, and an out-of-line call per node cost more than the probe.
inline constexpr int probe_zero = -(1 << 24); // hi of an exact zero
struct range_probe {
    int dmin = 1, dmax = 1;
    int emin = 1 << 20, emax = -(1 << 20);
    bool finite = true;
    int hi = probe_zero;
};
[[nodiscard, gnu::always_inline]] constexpr range_probe merge_range(range_probe a, range_probe b) {
    return {a.dmin, a.dmax, a.emin < b.emin ? a.emin : b.emin, a.emax > b.emax ? a.emax : b.emax, a.finite && b.finite, 0};
}
[[nodiscard, gnu::always_inline]] constexpr range_probe operator+(range_probe a, range_probe b) {
    auto r = merge_range(a, b);
    r.dmin = a.dmin < b.dmin ? a.dmin : b.dmin;
    r.dmax = a.dmax > b.dmax ? a.dmax : b.dmax;
    r.hi = (a.hi > b.hi ? a.hi : b.hi) + 1; // an exact zero's hi stays far below every other
    return r;
}
[[nodiscard, gnu::always_inline]] constexpr range_probe operator-(range_probe a, range_probe b) { return a + b; }
[[nodiscard, gnu::always_inline]] constexpr range_probe operator-(range_probe a) { return a; }
[[nodiscard, gnu::always_inline]] constexpr range_probe abs(range_probe a) { return a; }
[[nodiscard, gnu::always_inline]] constexpr range_probe operator*(range_probe a, range_probe b) {
    auto r = merge_range(a, b);
    r.dmin = a.dmin + b.dmin;
    r.dmax = a.dmax + b.dmax;
    r.hi = a.hi <= probe_zero || b.hi <= probe_zero ? probe_zero : a.hi + b.hi;
    return r;
}
struct lift_range {
    [[nodiscard]] constexpr range_probe operator()(double x) const {
        range_probe r;
        if (!is_finite(x)) r.finite = false;
        else if (x != 0.0) {
            r.emin = r.emax = exponent_of(x);
            r.hi = r.emin + 1;
        }
        return r;
    }
};

// Degree probe at compile time: the least and greatest degree of a predicate's terms, in its type
// (degree_span<Lo, Hi>), so a kernel can ask whether a predicate is homogeneous without running it.
template <int Lo, int Hi>
struct degree_span {
    static constexpr int lo = Lo, hi = Hi;
};
template <int A, int B, int C, int D>
[[nodiscard]] constexpr degree_span<(A < C ? A : C), (B > D ? B : D)> operator+(degree_span<A, B>, degree_span<C, D>) {
    return {};
}
template <int A, int B, int C, int D>
[[nodiscard]] constexpr degree_span<(A < C ? A : C), (B > D ? B : D)> operator-(degree_span<A, B>, degree_span<C, D>) {
    return {};
}
template <int A, int B, int C, int D>
[[nodiscard]] constexpr degree_span<A + C, B + D> operator*(degree_span<A, B>, degree_span<C, D>) {
    return {};
}
template <int A, int B>
[[nodiscard]] constexpr degree_span<A, B> operator-(degree_span<A, B>) {
    return {};
}
template <int A, int B>
[[nodiscard]] constexpr degree_span<A, B> abs(degree_span<A, B>) {
    return {};
}
struct lift_degree {
    [[nodiscard]] constexpr degree_span<1, 1> operator()(double) const { return {}; }
};
// Whether every term of the predicate f has the same degree in its lifted inputs.
template <class F, class D = decltype(std::declval<const F&>()(lift_degree{}))>
inline constexpr bool homogeneous = D::lo == D::hi;

// Inputs times 2^shift, exact by the caller's choice of shift (no overflow, no result below the
// normal range), then lifted as Lift lifts them.
template <class Lift>
struct lift_scaled {
    double factor; // 2^shift, |shift| <= 1022
    [[nodiscard]] constexpr auto operator()(double x) const { return Lift{}(x * factor); }
};
[[nodiscard]] constexpr double power_of_two(int k) { // -1022 <= k <= 1023
    return __builtin_bit_cast(double, static_cast<std::uint64_t>(k + 1023) << 52);
}

// --- exact sign ------------------------------------------------------------------------------
[[nodiscard]] constexpr sign to_sign(int s) { return s > 0 ? sign::positive : (s < 0 ? sign::negative : sign::zero); }
[[nodiscard]] constexpr sign sign_of_double(double v) { return v > 0.0 ? sign::positive : (v < 0.0 ? sign::negative : sign::zero); }

// The scaled filter stage. Where the permanent's estimate lies outside the filter's trusted range
// (below 2^-850, or above 2^1000: a scene near 2^-500 or 2^500, or a high degree), the power of
// two s that brings it near 1, within the bounds that keep every scaled input normal and finite,
// so the scaling is exact; 0 where the range is fine, or no such s exists, or the polynomial is
// not homogeneous. An intermediate that still overflows only makes the filter fail: its bound
// test never passes on an infinite or NaN permanent.
[[nodiscard]] constexpr int filter_shift(const range_probe& r) {
    if (r.dmin != r.dmax || r.hi <= probe_zero + (1 << 20) || (r.hi >= -850 && r.hi <= 1000)) return 0;
    int s = r.hi < 0 ? (-r.hi) / r.dmax : -((r.hi + r.dmax - 1) / r.dmax); // floor(-hi / d)
    if (s > 1022 - r.emax) s = 1022 - r.emax;
    if (s < -1022 - r.emin || s < -1022 || s > 1022) return 0;
    return s;
}
// A homogeneous polynomial of degree d keeps its sign when every input is scaled by 2^s:
// P(2^s x) = 2^(d s) P(x). The filter on the scaled inputs: +1 / -1 when proven, 0 otherwise.
template <class F>
[[nodiscard]] constexpr int scaled_filter_sign(const F& f, int shift) {
    return proven_sign(f(lift_scaled<lift_filter>{power_of_two(shift)}));
}

// Whether a filtered value's permanent lies where scaling the inputs cannot help: the filter
// failed because the value is near zero for its magnitude, not because the error bound under- or
// overflowed.
[[nodiscard]] constexpr bool in_trusted_range(double permanent) { return permanent >= 0x1p-850 && permanent <= 0x1p1000; }
template <int K>
[[nodiscard]] constexpr bool in_trusted_range(filtered<K> v) {
    return in_trusted_range(v.p);
}

// Whether the filter's value is zero, which says that every input it read was finite, so that a
// zero by structure (zero_by_structure) is an exact zero there: an infinite or NaN input makes
// every value computed from it infinite or NaN (inf + -inf and 0 * inf are NaN, and no operation
// turns either into a finite number). In constant evaluation an overflowed operand gives the value
// 0 with an infinite permanent instead (filtered.cppm's poisoned), so there the permanent must be
// finite too.
template <int K>
[[nodiscard]] constexpr bool finite_zero(filtered<K> v) {
    return v.v == 0.0 && (!__builtin_is_constant_evaluated() || v.p < infinity);
}

// Largest expansion capacity evaluated on the stack; larger predicates go to the dyadic path.
inline constexpr int max_expansion_capacity = 2048;

// Stages 2 and 3 live in their own (never inlined) function: their expansion and dyadic
// temporaries make a large stack frame, which must not be paid for when the filter decides.
// The predicate is passed by value (predicates capture their inputs by value): nothing of the
// fast path escapes to memory, so the filter runs on registers without store-forwarding stalls.
template <class F>
[[nodiscard, gnu::noinline]] constexpr sign exact_sign_fallback(F f, bool& valid, bool in_range, bool rounded_zero);

// Exact sign of a generic polynomial predicate at the exact values of its inputs.
// `valid` is cleared for non-finite inputs (their sign is then reported as zero).
template <class F>
[[nodiscard, gnu::always_inline]] constexpr sign exact_sign(const F& f, bool& valid) {
    // Stage 1: semi-static filter.
    const auto v = f(lift_filter{});
    if (const int s = proven_sign(v); s != 0) return to_sign(s);
    return exact_sign_fallback(f, valid, in_trusted_range(v), finite_zero(v));
}

template <class F>
[[nodiscard, gnu::noinline]] constexpr sign exact_sign_fallback(F f, bool& valid, bool in_range, bool rounded_zero) {
    // Stage 1a: a zero by structure, then every operation exact in double (exactly touching
    // inputs: an exact zero, which no filter can prove, is the commonest reason to be here). Only
    // where the filter's value, the same expression in plain double, is zero (rounded_zero, from
    // finite_zero, which also vouches for the inputs' finiteness): where this stage succeeds,
    // that value is the exact one, so it can settle a zero only there; a nonzero sign it would
    // settle, the stages below settle as well (skipping it is always sound, never wrong).
    if (rounded_zero) {
        if (zero_by_structure(f)) return sign::zero;
        if (const exact_double x = f(lift_exact_double{}); x.exact) return sign_of_double(x.v);
    }
    // Stage 1b, where the filter's permanent left its trusted range (in_range false): the filter
    // on inputs scaled by a power of two (scaled_filter_sign). Then 1c: the double-double filter,
    // which decides configurations a few ulps off the boundary (on the inputs scaled as in 1b, or
    // as they are).
    int shift = 0;
    range_probe r;
    if (!in_range) {
        r = f(lift_range{});
        if (r.finite) shift = filter_shift(r);
        if (shift != 0)
            if (const int s = scaled_filter_sign(f, shift); s != 0) return to_sign(s);
    }
    if (const int s = proven_sign(f(lift_scaled<lift_filter_dd>{power_of_two(shift)})); s != 0) return to_sign(s);
    if (in_range) r = f(lift_range{});
    if (!r.finite) {
        valid = false;
        return sign::zero;
    }
    if (r.emax < r.emin) return sign::zero; // every input is zero
    // Stage 2: expansions, when every intermediate stays clear of underflow and overflow.
    // A d-fold product of components of exponent >= emin - 106 stays >= d (emin - 106), which
    // must be >= -1000; the largest sum stays below d (emax + 1) + 7 <= 1000 (64 terms at most).
    using X = decltype(f(lift_expansion{}));
    if constexpr (X::capacity <= max_expansion_capacity) {
        if (r.dmin == r.dmax) {
            const int d = r.dmax;
            const int lo = 108 - 1000 / d; // 2 of margin for the integer halving below
            const int hi = 1000 / d - 7;
            if (r.emax - r.emin <= hi - lo - 2) {
                const int centre = (lo + hi) / 2 - (r.emin + r.emax) / 2;
                return to_sign(f(lift_expansion{centre}).sign());
            }
        }
    }
    // Stage 3: dyadic big integers, exact over the whole finite range.
    return to_sign(sign_of(f(lift_dyadic{})));
}

// --- kernels ---------------------------------------------------------------------------------
struct approx_kernel {
    static constexpr value_mode values = value_mode::plain;
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign sgn(const F& f) {
        return sign_of_double(f(lift_double{}));
    }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr bool zero(const F& f) {
        return !(abs(f(lift_double{})) > 0.0);
    } // NaN: zero, as sgn
};

// The exact fallback's two cheap stages for a sign the filter could not prove, on the inputs times
// factor (a power of two that keeps every input exact; 1 for the inputs as they are): plain double
// with every operation exact (an exact zero, from coplanar or axis-aligned inputs, is the
// commonest reason; tried only where the filter's value on the same inputs, rounded_zero, is zero,
// as in exact_sign_fallback), then double-double. The sign, or nothing when neither settles it.
template <class F>
[[nodiscard, gnu::noinline]] constexpr std::optional<sign> settle_cheaply(F f, double factor, bool rounded_zero) {
    if (rounded_zero)
        if (const exact_double x = f(lift_scaled<lift_exact_double>{factor}); x.exact) return sign_of_double(x.v);
    if (const int s = proven_sign(f(lift_scaled<lift_filter_dd>{factor})); s != 0) return to_sign(s);
    return std::nullopt;
}
struct filter_kernel {
    static constexpr value_mode values = value_mode::enclosure;
    // The permanent of the last sign the filter could not prove (0 or more, or NaN), -1 while
    // every sign is proven. One store where a flag took one, so the certain path is unchanged;
    // it tells whether scaling the inputs could help (in_trusted_range).
    double unproven = -1.0;
    // some sign could not be proven: the query's answer is uncertain
    [[nodiscard]] constexpr bool failed() const { return !(unproven < 0.0); }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign sgn(const F& f) {
        const auto v = f(lift_filter{});
        const int s = proven_sign(v);
        if (s == 0) unproven = v.p;
        return to_sign(s);
    }
    // sgn(f) == sign::zero, with one test instead of two (proven_nonzero): true when not proven nonzero.
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr bool zero(const F& f) {
        const auto v = f(lift_filter{});
        if (proven_nonzero(v)) return false;
        unproven = v.p;
        return true;
    }
    // The filter, then the two cheap exact stages (settle_cheaply) before the sign counts as
    // unproven: for signs that are often exactly zero (settling_filter_kernel, and single signs
    // such as aabb_convex_polyhedron's dependent normals).
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign settled_sgn(const F& f) {
        const auto v = f(lift_filter{});
        if (const int s = proven_sign(v); s != 0) return to_sign(s);
        if (const auto s = settle_cheaply(f, 1.0, finite_zero(v))) return *s;
        unproven = v.p;
        return sign::zero;
    }
    // sgn and zero for a sign that coplanar or axis-aligned inputs make zero by structure: the
    // filter, then in place (a few compares, only where the rounded value is zero) the structure,
    // before the sign counts as unproven. Nothing more: a sign near zero but not zero by structure
    // is left to the exact pass, as by sgn.
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign structural_sgn(const F& f) {
        const auto v = f(lift_filter{});
        const int s = proven_sign(v);
        if (s == 0 && !(finite_zero(v) && zero_by_structure(f))) unproven = v.p;
        return to_sign(s);
    }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr bool structural_zero(const F& f) {
        const auto v = f(lift_filter{});
        if (proven_nonzero(v)) return false;
        if (!(finite_zero(v) && zero_by_structure(f))) unproven = v.p;
        return true;
    }
    // A sign for a check whose failure decides nothing (a candidate witness point): zero when the
    // filter cannot prove it, and the query's certainty is untouched.
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign probe(const F& f) {
        return to_sign(proven_sign(f(lift_filter{})));
    }
    // The filter, then the whole exact fallback in place (decided): for a sign that is often
    // exactly zero where the cheap stages cannot settle it, and whose failure would send the whole
    // query to the exact kernel's run, which would compute the same exact sign again.
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign decided_sgn(const F& f) {
        bool valid = true;
        const sign s = exact_sign(f, valid);
        if (!valid) unproven = 0.0; // a non-finite input: the exact kernel's run reports it
        return s;
    }
};

// Whether a query body is in a filter pass at run time (a kernel derived from filter_kernel,
// outside constant evaluation): where a rounded stage with proven error bounds may decide before
// the signs (aabb_ray's slab parameters, aabb_triangle's and aabb_tetrahedron's separating axes).
// Not in plain double, whose own answer is its tier's; not in a kernel that observes the signs;
// not in the exact kernel, which runs only after a filter pass failed, where the stage, on the
// same input, had decided nothing; not in constant evaluation, which refuses the NaN and
// infinities such a stage can make.
template <class K>
[[nodiscard, gnu::always_inline]] constexpr bool rounded_stage_applies() {
    return std::is_base_of_v<filter_kernel, K> && !__builtin_is_constant_evaluated();
}

// The filter kernel of a pair with a mesh or a 3D polygon (incidence.query's filter_passes): a
// sign the filter cannot prove goes to the two cheap exact stages (settle_cheaply) before the
// query is called uncertain. Their signs repeat shared vertices, and a partner often lies in the
// polygon's plane, so exact zeros are common there, and settling each where it arises costs less
// than a second run of the whole (long) query in the exact kernel. For the other pairs it
// measured slower: their filter pass is short, and the extra call changes how their bodies inline.
struct settling_filter_kernel : filter_kernel {
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign sgn(const F& f) {
        return settled_sgn(f);
    }
    // Every sign here is settled (exact_double settles a zero by structure too).
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign structural_sgn(const F& f) {
        return sgn(f);
    }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr bool structural_zero(const F& f) {
        return zero(f);
    }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr bool zero(const F& f) {
        const auto v = f(lift_filter{});
        if (proven_nonzero(v)) return false;
        if (const auto s = settle_cheaply(f, 1.0, finite_zero(v))) return *s == sign::zero;
        unproven = v.p;
        return true;
    }
};

// The exact tier's filter pass for a query with values: the signs of filter kernel Base, the values
// correctly rounded (value.cppm); a sign it cannot prove sends the query to the exact kernel, as in
// a yes/no query.
template <class Base>
struct rounding_kernel : Base {
    static constexpr value_mode values = value_mode::rounded;
};

// The filter on every input times one power of two, for a whole query whose scene lies far from
// scale 1 (near 2^-500 or 2^500 the filter's permanents leave its trusted range, whatever the
// configuration). A homogeneous predicate of degree d only changes by the factor 2^(d s), so its
// sign is kept, provided every scaled input is exact. An input that would fall below the normal
// range is lifted as NaN, which makes the value and its permanent NaN and the sign unproven (an
// overflow leaves an infinite or NaN permanent by itself). A predicate that is not homogeneous is
// filtered on its inputs as they are. Used where the shapes cannot be scaled by value (views of
// vertices), at run time only (constant evaluation refuses NaN).
struct lift_scaled_filter {
    double factor; // 2^s, |s| <= 1022
    [[nodiscard, gnu::always_inline]] constexpr filtered<0> operator()(double x) const {
        const double y = x * factor;
        return lift_filtered(abs(y) < 0x1p-1022 && x != 0.0 ? __builtin_nan("") : y);
    }
};
struct scaled_filter_kernel {
    static constexpr value_mode values = value_mode::enclosure;
    double factor;          // 2^s
    double unproven = -1.0; // as in filter_kernel
    [[nodiscard]] constexpr bool failed() const { return !(unproven < 0.0); }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr std::optional<sign> proven(const F& f) const { // nothing: not proven
        if constexpr (homogeneous<F>) {
            const auto v = f(lift_scaled_filter{factor});
            if (const int s = proven_sign(v); s != 0) return to_sign(s);
            // not where a NaN permanent says an input was not exact
            if (v.p == v.p) return settle_cheaply(f, factor, finite_zero(v));
            return std::nullopt;
        } else {
            if (const int s = proven_sign(f(lift_filter{})); s != 0) return to_sign(s);
            return std::nullopt;
        }
    }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign sgn(const F& f) {
        if (const auto s = proven(f)) return *s;
        unproven = 0.0;
        return sign::zero;
    }
    // A check whose failure decides nothing: only a proven nonzero sign counts.
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign probe(const F& f) {
        return proven(f).value_or(sign::zero);
    }
};

// A probe's second chance, out of line: the scaled filter, where the permanent left the filter's
// trusted range (zero where it cannot help or cannot prove the sign).
template <class F>
[[nodiscard, gnu::noinline]] constexpr int scaled_probe(F f) {
    const range_probe r = f(lift_range{});
    if (!r.finite) return 0;
    const int shift = filter_shift(r);
    return shift != 0 ? scaled_filter_sign(f, shift) : 0;
}

struct exact_kernel {
    static constexpr value_mode values = value_mode::rounded;
    bool valid = true; // false when a predicate saw a NaN or infinite input
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign sgn(const F& f) {
        return exact_sign(f, valid);
    }
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr bool zero(const F& f) {
        const auto v = f(lift_filter{});
        if (proven_nonzero(v)) return false;
        return exact_sign_fallback(f, valid, in_trusted_range(v), finite_zero(v)) == sign::zero;
    }
    // A check whose failure decides nothing (see probe below) needs no exact sign: the filter,
    // and the scaled filter where the scene's scale defeated it.
    template <class F>
    [[nodiscard, gnu::always_inline]] constexpr sign probe(const F& f) {
        const auto v = f(lift_filter{});
        if (const int s = proven_sign(v); s != 0) return to_sign(s);
        if (in_trusted_range(v)) return sign::zero; // near its boundary: unknown
        return to_sign(scaled_probe(f));
    }
};

// Whether K's signs evaluate their expression on lift_filter first (the filter kernels, and the
// exact kernel's stage 1): where a body may lift a shared subexpression into the filter once
// (lifted_once).
template <class K>
[[nodiscard]] consteval bool lifts_filter() {
    return std::is_base_of_v<filter_kernel, K> || std::is_same_v<K, exact_kernel>;
}
// A subexpression f(L) that many signs of one body share, lifted into the filter once: called with
// lift_filter it returns the value kept at construction (when lifts_filter<K>(): the same value
// each call would compute, so the signs are unchanged), with any other lift it evaluates f.
template <class K, class F>
struct lifted_once {
    F f;
    decltype((*static_cast<const F*>(nullptr))(lift_filter{})) kept{};
    constexpr explicit lifted_once(const F& g) : f(g) {
        if constexpr (lifts_filter<K>()) kept = f(lift_filter{});
    }
    template <class L>
    [[nodiscard]] constexpr decltype(auto) operator()(L l) const {
        if constexpr (std::is_same_v<L, lift_filter>) return (kept);
        else return f(l);
    }
};

// Whether a query body is the exact kernel's pass at run time: a rounded stage cannot decide there
// (the filter pass before it, on the same input, could not), but what it found clear may still
// spare exact signs (aabb_triangle's axes that clearly overlap).
template <class K>
[[nodiscard, gnu::always_inline]] constexpr bool exact_pass_at_run_time() {
    return std::is_same_v<K, exact_kernel> && !__builtin_is_constant_evaluated();
}

// What a call site knows about a sign that the kernel cannot see in the expression. A call site
// says it with sgn<hint::...>(k, f) or is_zero<hint::...>(k, f); plain k.sgn(f) is hint::none.
// A hint never changes a sign that is returned as proven: it only decides where the filter kernels
// spend the work on a sign they cannot prove at once (docs/DESIGN.md, "Signs").
enum class hint : unsigned char {
    // A sign like any other: the filter, and a sign it cannot prove fails the pass (the query is
    // then uncertain, or runs again in the exact kernel).
    none,
    // A check whose failure decides nothing (a candidate witness point, a tentative direction):
    // zero when the kernel cannot prove the sign cheaply, and the pass is not failed. Only a
    // nonzero result may be relied on.
    optional,
    // Often exactly zero by structure (coplanar inputs in one plane z = c: equal coordinates, zero
    // direction components): the filter kernels prove such a zero in place (a few compares, only
    // where the rounded value is zero) instead of failing the pass; the exact kernel's fallback
    // tries the structure first anyway.
    structural,
    // A low-degree sign that decides which candidate points exist (a determinant of normals, a
    // component of a cross product) and is often exactly zero or nearly (a camera frustum's side
    // and near planes are dependent; k-DOP directions give exact zeros): the filter kernels try the
    // exact fallback's two cheap stages (plain double with every operation exact, then
    // double-double) before failing the pass.
    often_zero,
    // Often exactly zero at a point that decides the query (a fourth plane through a guessed
    // vertex: a k-DOP's corner where several of its planes meet a data point): every kernel
    // computes the exact sign in place, rather than fail a pass after which the exact kernel's run
    // of the whole query would compute it again among every other sign.
    decisive,
};

// k's sign of f under what the call site knows (hint above).
template <hint H = hint::none, class K, class F>
[[nodiscard, gnu::always_inline]] constexpr sign sgn(K& k, const F& f) {
    constexpr bool filtering = std::is_base_of_v<filter_kernel, K>;
    if constexpr (H == hint::none) {
        return k.sgn(f);
    } else if constexpr (H == hint::optional) {
        if constexpr (requires { k.probe(f); }) return k.probe(f);
        else return k.sgn(f);
    } else if constexpr (H == hint::structural && filtering) {
        return k.structural_sgn(f);
    } else if constexpr (H == hint::often_zero && filtering) {
        return k.settled_sgn(f);
    } else if constexpr (H == hint::decisive && filtering) {
        return k.decided_sgn(f);
    } else if constexpr (H == hint::structural) {
        return k.sgn(f);
    } else { // often_zero or decisive outside a filter kernel: a cheap proof first, then the sign
        const sign s = sgn<hint::optional>(k, f);
        if (s != sign::zero) return s;
        return k.sgn(f);
    }
}

// sgn<H>(k, f) == sign::zero, through k's one-test form where it has one (zero(f): a random nonzero
// sign then costs no mispredicted branch); a kernel that observes signs is asked for the sign.
template <hint H = hint::none, class K, class F>
[[nodiscard, gnu::always_inline]] constexpr bool is_zero(K& k, const F& f) {
    if constexpr (H == hint::structural && std::is_base_of_v<filter_kernel, K>) return k.structural_zero(f);
    else if constexpr (H != hint::none && H != hint::structural) return sgn<H>(k, f) == sign::zero;
    else if constexpr (requires { k.zero(f); }) return k.zero(f);
    else return k.sgn(f) == sign::zero;
}

// sign(a - b) for two doubles, exactly, by comparison. A kernel that observes decisions (the tests'
// margin kernel) sees it through observe_compare; the others pay nothing.
template <class K>
[[nodiscard, gnu::always_inline]] constexpr sign compare(K& k, double a, double b) {
    if constexpr (requires { k.observe_compare(a, b); }) k.observe_compare(a, b);
    return a > b ? sign::positive : (a < b ? sign::negative : sign::zero);
}

} // namespace incidence::arith
