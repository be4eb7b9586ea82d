// Values in every tier (docs/DESIGN.md, "Values"). A number a query returns (a ray parameter, a
// coordinate of a hit point, a barycentric, a squared distance) is a quotient P / S of two
// polynomials in the inputs, written once as a generic lambda f(L) -> ratio{P, S} (or f(L) -> P for
// a polynomial), lifted like a predicate (kernel.cppm). The kernel a query body runs in decides
// what the number becomes:
//   plain      approx_kernel           P / S in plain double;
//   enclosure  the filter kernels      an interval that contains the exact P / S: P and S with the
//                                      filter's rigorous bounds (filtered.cppm), divided with
//                                      outward rounding;
//   rounded    exact_kernel, and the   P / S correctly rounded to nearest (ties to even): P and S in
//              exact tier's filter     the double-double filter (filtered_dd.cppm), a candidate c near
//              pass (rounding_kernel)  P / S, and c is the answer when the signs of P - m S at the
//                                      two midpoints m next to c are proven (Ziv's rounding test,
//                                      IEEE Trans. Computers 40(4), 1991); otherwise every operation
//                                      exact in double, then exact dyadic bracketing.
// The midpoint test: the nearest double to x is c iff pred-mid(c) < x < succ-mid(c) (Muller et al.,
// Handbook of Floating-Point Arithmetic, 2018, section 2.2); each midpoint is the double-double
// c + h with h half a gap, exact, so P - m S composes in the double-double filter with a proven
// bound, and a tie (x on a midpoint) is left to the exact stage, which rounds it to even.
module;
#include <optional>
#include <type_traits>
#include <utility>
export module incidence.arith:value;
import incidence.core;
import :eft;
import :filtered;
import :filtered_dd;
import :dyadic;
import :rounding;
import :kernel;

export namespace incidence::arith {

template <class P, class S>
struct ratio {
    P num;
    S den;
};
template <class P, class S>
ratio(P, S) -> ratio<P, S>;

template <class T>
inline constexpr bool is_ratio = false;
template <class P, class S>
inline constexpr bool is_ratio<ratio<P, S>> = true;

// A polynomial value read as P / 1 (the 1 lifted, so it has the lift's number type).
template <class L, class E>
[[nodiscard]] constexpr auto as_ratio(L l, const E& e) {
    if constexpr (is_ratio<E>) return e;
    else return ratio{e, l(1.0)};
}
template <class F, class L>
[[nodiscard]] constexpr auto ratio_of(const F& f, L l) {
    return as_ratio(l, f(l));
}

// What a kernel's values are (kernel.cppm declares value_mode): a kernel without a mode of its own
// (a test's observing kernel) computes plain values.
template <class K>
[[nodiscard]] consteval value_mode value_mode_of() {
    if constexpr (requires { K::values; }) return K::values;
    else return value_mode::plain;
}
template <class K>
inline constexpr bool encloses = value_mode_of<K>() == value_mode::enclosure;
template <class K>
using value_t = std::conditional_t<encloses<K>, interval, double>;
template <class K>
using point_value_t = std::conditional_t<encloses<K>, interval3, point3>;
template <class K>
using vec_value_t = std::conditional_t<encloses<K>, interval3, vec3>;

// Whether kernel k has left a sign open already. Its values are then discarded (the caller runs the
// whole query again in the exact kernel), so a rounded value is not worth its exact stages: those
// can cost tens of microseconds, on a quadratic whose roots the open sign may have assumed when it
// has none (a ray just missing a ball). The rounded modes below then return plain double.
// Run time only: in constant evaluation a plain value may divide by zero or take a NaN, which is
// ill-formed there.
template <class K>
[[nodiscard]] constexpr bool values_discarded(const K& k) {
    if constexpr (requires { k.failed(); }) return !__builtin_is_constant_evaluated() && k.failed();
    else return false;
}

// --- intervals, rounded outward ----------------------------------------------------------------
// Every operation below returns an interval that contains every exact result for operands in its
// operand intervals: each end point is computed in round-to-nearest (error <= half an ulp, or
// 2^-1075 when subnormal) and moved one double outward.
[[nodiscard]] constexpr interval outward(double lo, double hi) { return {next_down(lo), next_up(hi)}; }
[[nodiscard]] constexpr interval point_interval(double x) { return {x, x}; }
inline constexpr interval whole_line{-__builtin_huge_val(), __builtin_huge_val()};
[[nodiscard]] constexpr double min_of(double a, double b) { return b < a ? b : a; }
[[nodiscard]] constexpr double max_of(double a, double b) { return a < b ? b : a; }
[[nodiscard]] constexpr interval add(interval a, interval b) { return outward(a.lo + b.lo, a.hi + b.hi); }
[[nodiscard]] constexpr interval negate(interval a) { return {-a.hi, -a.lo}; }
[[nodiscard]] constexpr interval sub(interval a, interval b) { return add(a, negate(b)); }
[[nodiscard]] constexpr interval mul(interval a, interval b) {
    if ((a.lo == 0.0 && a.hi == 0.0) || (b.lo == 0.0 && b.hi == 0.0)) return {0.0, 0.0}; // 0 * inf
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    double lo = p[0], hi = p[0];
    for (double x : p) {
        if (x != x) return whole_line; // 0 * inf of an unbounded operand
        lo = min_of(lo, x);
        hi = max_of(hi, x);
    }
    return outward(lo, hi);
}
// a / b; the whole line when b contains 0 (a parameter whose denominator is not proven nonzero).
[[nodiscard]] constexpr interval divide(interval a, interval b) {
    if (!(b.lo > 0.0 || b.hi < 0.0)) return whole_line;
    const double p[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
    double lo = p[0], hi = p[0];
    for (double x : p) {
        if (x != x) return whole_line;
        lo = min_of(lo, x);
        hi = max_of(hi, x);
    }
    return outward(lo, hi);
}
// sqrt of the non-negative part (sqrt is correctly rounded in IEEE arithmetic).
[[nodiscard]] constexpr interval square_root(interval a) {
    const double lo = a.lo > 0.0 ? next_down(sqrt(a.lo)) : 0.0;
    return {lo > 0.0 ? lo : 0.0, a.hi > 0.0 ? next_up(sqrt(a.hi)) : 0.0};
}
[[nodiscard]] constexpr interval max_of(interval a, interval b) { return {max_of(a.lo, b.lo), max_of(a.hi, b.hi)}; }
[[nodiscard]] constexpr interval min_of(interval a, interval b) { return {min_of(a.lo, b.lo), min_of(a.hi, b.hi)}; }
[[nodiscard]] constexpr interval hull(interval a, interval b) { return {min_of(a.lo, b.lo), max_of(a.hi, b.hi)}; }
[[nodiscard]] constexpr interval intersected(interval a, interval b) { return {max_of(a.lo, b.lo), min_of(a.hi, b.hi)}; }

// The enclosure of a filtered value: |v - x| <= error_bound (filtered.cppm, invariant I1, for every
// finite permanent: a product's permanent carries 2^-1020 for its own underflow), plus 2^-1074 for
// the rounding of the bound itself where it is subnormal; an infinite or NaN permanent (an
// overflow) encloses nothing, so the whole line.
template <int K>
[[nodiscard]] constexpr interval enclose(filtered<K> a) {
    if (!(a.p <= 0x1.fffffffffffffp1023) || a.v != a.v) return whole_line;
    const double e = error_bound(a) + 0x1p-1074;
    return outward(a.v - e, a.v + e);
}

// --- rounded: the double-double fast path --------------------------------------------------------
// A double-double constant lifted into the filter exactly: c + h, |h| <= u |c|.
[[nodiscard]] constexpr filtered_dd<0> lift_filtered_dd(double c, double h) { return {c, h, abs(c) + abs(h)}; }

// The nearest double to x (ties to even), given cmp(c, h) = sign(x - (c + h)) at the midpoints
// c + h next to a candidate c (h half a gap: exact), and a guess near x: zero when x is that
// midpoint (a tie: the even neighbour), nothing when cmp cannot tell. nullopt when it cannot, or the
// candidate leaves [2^-1021, 2^1023) in magnitude (half a gap is then not a double, or the next
// double is infinite), or it moves more than seven times.
[[nodiscard]] constexpr double even_of(double a, double b) { return (__builtin_bit_cast(unsigned long long, a) & 1u) != 0 ? b : a; }
// round_at_midpoints_with takes at(c) -> side(h) = sign(x - (c + h)), so that the two midpoints of
// one candidate share what side() keeps.
template <class At>
[[nodiscard]] constexpr std::optional<double> round_at_midpoints_with(double guess, const At& at) {
    double c = guess;
    for (int step = 0; step < 8; ++step) {
        if (!(abs(c) >= 0x1p-1021 && abs(c) < 0x1p1023)) return std::nullopt;
        const double up = next_up(c), down = next_down(c);
        const auto side = at(c);
        const std::optional<sign> above = side((up - c) * 0.5); // x - (c + half the gap above)
        if (!above) return std::nullopt;
        if (*above == sign::zero) return even_of(c, up);
        if (*above == sign::positive) {
            c = up;
            continue;
        }
        const std::optional<sign> below = side((down - c) * 0.5);
        if (!below) return std::nullopt;
        if (*below == sign::zero) return even_of(c, down);
        if (*below == sign::negative) {
            c = down;
            continue;
        }
        return c;
    }
    return std::nullopt;
}
template <class Cmp>
[[nodiscard]] constexpr std::optional<double> round_at_midpoints(double guess, const Cmp& cmp) {
    return round_at_midpoints_with(guess, [&](double c) { return [&cmp, c](double h) { return cmp(c, h); }; });
}
// The double-double filter's sign as such a comparison: nothing where it proves none (a tie included).
template <int K>
[[nodiscard]] constexpr std::optional<sign> dd_side(const filtered_dd<K>& x) {
    if (const int s = proven_sign(x); s != 0) return to_sign(s);
    return std::nullopt;
}
// A comparison's sign times a proven sign s (nothing stays nothing).
[[nodiscard]] constexpr std::optional<sign> times(std::optional<sign> a, sign s) {
    if (a) return *a * s;
    return std::nullopt;
}

// h x for h a power of two: exact in every part (the filter trusts no permanent below 2^-800, so a
// part that underflows errs by less than 2^-1075, far inside the bound's slack), the bound scaled.
template <int K>
[[nodiscard]] constexpr filtered_dd<K> scaled(const filtered_dd<K>& x, double h) {
    return {x.hi * h, x.lo * h, x.p * abs(h)};
}

// Half the smaller gap around c (a power of two), or 0 where |c| is outside [2^-1021, 2^1023).
[[nodiscard]] constexpr double half_gap(double c) {
    if (!(abs(c) >= 0x1p-1021 && abs(c) < 0x1p1023)) return 0.0;
    return (abs(c) - next_down(abs(c))) * 0.5;
}
// Whether P / S surely rounds to c, from R = P - c S (r): |R| < h |S|, h half the smaller gap
// around c (a power of two), puts P / S strictly between the midpoints next to c. In double:
// |R| <= |r.hi| (1 + u) + e_R and |S| >= |s.hi| (1 - u) - e_S, the factors 1 +- 2^-20 covering
// each operation's rounding; h times a number above 2^-900 is exact. A tie (|R| = h |S|) is not
// decided here.
template <int A, int B>
[[nodiscard]] constexpr bool surely_rounds_to(const filtered_dd<A>& r, const filtered_dd<B>& s, double c) {
    const double h = half_gap(c);
    const double s_min = h * (abs(s.hi) * (1.0 - 0x1p-20) - dd_error(s));
    const double r_max = (abs(r.hi) * (1.0 + 0x1p-20) + dd_error(r)) * (1.0 + 0x1p-20);
    return s_min > 0x1p-900 && r_max < s_min;
}
// A polynomial's value x = hi + lo (+- e) rounds to hi when |lo| + e < h, h as above.
template <int K>
[[nodiscard]] constexpr bool surely_rounds_to_hi(const filtered_dd<K>& x) {
    return (abs(x.lo) + dd_error(x)) * (1.0 + 0x1p-20) < half_gap(x.hi);
}

// P / S correctly rounded from the double-double filter's P and S, or nullopt (S not proven
// nonzero, a value near a midpoint, a magnitude out of the filter's range). First the quotient of
// the leading parts c0, then c0 corrected by the residual R0 = P - c0 S (P / S to about twice
// double's precision, rounded), each decided by surely_rounds_to on its own residual; otherwise the
// midpoint test around the corrected candidate, both midpoints of a candidate c sharing
// R = P - c S: sign(P - (c + h) S) = sign(R - h S), h S exact.
template <int A, int B>
[[nodiscard]] constexpr std::optional<double> rounded_quotient(const filtered_dd<A>& p, const filtered_dd<B>& s) {
    const double c0 = p.hi / s.hi;
    const auto r0 = p - lift_filtered_dd(c0) * s;
    if (surely_rounds_to(r0, s, c0)) return c0;
    const double c = c0 + r0.hi / s.hi;
    // c - c0 is exact where c and c0 are within a factor 2 of each other (Sterbenz)
    if (c != c0 && ((c0 > 0.0 && c > 0.0) || (c0 < 0.0 && c < 0.0)) && abs(c) <= 2.0 * abs(c0) && abs(c0) <= 2.0 * abs(c))
        if (surely_rounds_to(r0 - lift_filtered_dd(c - c0) * s, s, c)) return c;
    const std::optional<sign> ss = dd_side(s);
    if (!ss) return std::nullopt;
    const sign sign_s = *ss;
    return round_at_midpoints_with(is_finite(c) ? c : c0, [&](double m) __attribute__((always_inline)) {
        return [r = p - lift_filtered_dd(m) * s, &s, sign_s](double h)
                   __attribute__((always_inline)) { return times(dd_side(r - scaled(s, h)), sign_s); };
    });
}
// A polynomial's value rounded from its double-double filter value: hi, or the quotient's test on
// P / 1.
template <int K>
[[nodiscard]] constexpr std::optional<double> rounded_polynomial(const filtered_dd<K>& x) {
    if (surely_rounds_to_hi(x)) return x.hi;
    return rounded_quotient(x, lift_filtered_dd(1.0));
}

template <class F>
[[nodiscard]] constexpr double plain_value(const F& f) {
    const auto r = ratio_of(f, lift_double{});
    return r.num / r.den;
}

// Whether a ratio's numerator has the degree of its denominator (a parameter), so that P 1 - m S is
// homogeneous with m and the 1 lifted (for a coordinate, P is one degree higher: P - m S).
template <class F>
inline constexpr bool same_degree = [] {
    using R = decltype(ratio_of(std::declval<const F&>(), lift_degree{}));
    return decltype(R::num)::hi == decltype(R::den)::hi;
}();

// The exact stages, out of line. An exact zero first (arith's exact sign of P: its structural,
// exact-double, double-double, expansion and dyadic stages), then the midpoint test on exact signs of
// P - m S, then, for a result below the normal range or beyond the largest double, dyadic
// bracketing (rounding.cppm).
template <class F>
[[nodiscard, gnu::noinline]] constexpr double rounded_value_exactly(F f, double guess) {
    bool valid = true;
    const sign ss = exact_sign([=](auto L) { return ratio_of(f, L).den; }, valid);
    if (!valid || ss == sign::zero) return __builtin_nan("");
    if (exact_sign([=](auto L) { return ratio_of(f, L).num; }, valid) == sign::zero) return 0.0;
    if (!is_finite(guess) || guess == 0.0) guess = plain_value(f);
    if (is_finite(guess) && guess != 0.0)
        if (const auto v = round_at_midpoints(guess, [&](double c, double h) {
                const sign d = exact_sign(
                    [=](auto L) {
                        const auto r = ratio_of(f, L);
                        if constexpr (same_degree<F>) return r.num * L(1.0) - (L(c) + L(h)) * r.den;
                        else return r.num - (L(c) + L(h)) * r.den;
                    },
                    valid);
                return std::optional<sign>(d * ss);
            }))
            return *v;
    const auto d = ratio_of(f, lift_dyadic{});
    return quotient(d.num, d.den);
}

// The value f rounded from x, f's double-double filter value (a ratio or a polynomial) already
// evaluated, perhaps in one evaluation that several values share: the fast path's answer where its
// test decides, else f's exact stages. Run time only (the filter's NaN and infinities).
// A value that is zero by structure (coplanar or axis-aligned inputs: kernel.cppm's
// zero_by_structure, sound here as a zero filter value implies finite inputs) is 0 with no exact
// stage: no error bound proves a zero.
template <class F, class X>
[[nodiscard]] constexpr double rounded_from(const F& f, const X& x) {
    if constexpr (is_ratio<X>) {
        if (x.num.hi == 0.0 && dd_side(x.den) && zero_by_structure([&](auto L) { return ratio_of(f, L).num; })) return 0.0;
        if (const auto v = rounded_quotient(x.num, x.den)) return *v;
        return rounded_value_exactly(f, x.num.hi / x.den.hi);
    } else {
        if (x.hi == 0.0 && zero_by_structure(f)) return 0.0;
        if (const auto v = rounded_polynomial(x)) return *v;
        return rounded_value_exactly(f, x.hi);
    }
}
template <class F>
[[nodiscard]] constexpr double rounded_value(const F& f) {
    if (__builtin_is_constant_evaluated()) return rounded_value_exactly(f, 0.0);
    return rounded_from(f, f(lift_filter_dd{}));
}

// --- one value, in the kernel's mode ---------------------------------------------------------------
template <class F>
[[nodiscard]] constexpr interval enclosed_value(const F& f) {
    const auto r = ratio_of(f, lift_filter{});
    return divide(enclose(r.num), enclose(r.den));
}

// The value f (a ratio or a polynomial) as kernel K computes values.
template <class K, class F>
[[nodiscard]] constexpr value_t<K> value(K& k, const F& f) {
    if constexpr (value_mode_of<K>() == value_mode::enclosure) return enclosed_value(f);
    else if constexpr (value_mode_of<K>() == value_mode::rounded) return values_discarded(k) ? plain_value(f) : rounded_value(f);
    else return plain_value(f);
}
// An exact double (a bound of the parameter's domain, an input coordinate) as a value of K.
template <class K>
[[nodiscard]] constexpr value_t<K> exact_value(K&, double x) {
    if constexpr (encloses<K>) return point_interval(x);
    else return x;
}
template <class K>
[[nodiscard]] constexpr point_value_t<K> exact_point(K&, point3 p) {
    if constexpr (encloses<K>) return interval3{point_interval(p.x), point_interval(p.y), point_interval(p.z)};
    else return p;
}

// The point a + t b of a parameter t = P / S (f(L) -> ratio{P, S}) on the line a(L) + t b(L)
// (lifted points and vectors: b = q - a exactly for a segment), each coordinate
// (a_i S + P b_i) / S from one evaluation of P and S. Plain: a + fl(P / S) b, as a user would write it.
// value_and_point gives t and the point together, from that one evaluation.
template <class K>
struct value_with_point {
    value_t<K> t;
    point_value_t<K> point;
};

// Coordinate pick(a + t b) correctly rounded, as its own ratio (a_i S + P b_i) / S.
template <class K, class F, class A, class B, class Pick>
[[nodiscard]] constexpr double rounded_coordinate(K& k, const F& f, const A& a, const B& b, Pick pick) {
    return value(k, [=](auto L) {
        const auto q = ratio_of(f, L);
        return ratio{pick(a(L)) * q.den + q.num * pick(b(L)), q.den};
    });
}
inline constexpr auto pick_x = [](const auto& v) { return v.x; };
inline constexpr auto pick_y = [](const auto& v) { return v.y; };
inline constexpr auto pick_z = [](const auto& v) { return v.z; };

// The rounded point; at run time from the double-double filter's P and S (r, when given) where its
// midpoint tests decide, by the exact stages for the other coordinates.
template <class K, class F, class A, class B>
[[nodiscard]] constexpr point3 rounded_point(K& k, const F& f, const A& a, const B& b) {
    return point3{rounded_coordinate(k, f, a, b, pick_x), rounded_coordinate(k, f, a, b, pick_y), rounded_coordinate(k, f, a, b, pick_z)};
}
// t = P / S to about twice double's precision, c0 + q with |t - (c0 + q)| <= delta, from the
// double-double P and S: c0 = P.hi / S.hi and q = R.hi / S.hi for R = P - c0 S, so that
// t - (c0 + q) = R / S - R.hi / S.hi, which is at most (dR + |q| (1 + u) dS) / (|S.hi| - dS) +
// u |q| with dR = u |R.hi| + e_R and dS = u |S.hi| + e_S (|lo| <= u |hi|, e the filter's bounds),
// plus 2^-1073 for a q that underflows; each rounding in double covered by factors 1 +- 2^-20.
// ok is false where S is not proven away from 0 or a number is not finite.
struct near_quotient {
    double c0 = 0.0, q = 0.0, delta = 0.0;
    bool ok = false;
};
template <int A, int B>
[[nodiscard]] constexpr near_quotient near_quotient_of(const filtered_dd<A>& p, const filtered_dd<B>& s) {
    const double s_min = abs(s.hi) * (1.0 - 0x1p-20) - dd_error(s);
    if (!(s_min > 0x1p-900)) return {};
    const double c0 = p.hi / s.hi;
    const auto r = p - lift_filtered_dd(c0) * s;
    const double q = r.hi / s.hi;
    const double d_r = abs(r.hi) * 0x1p-52 + dd_error(r);
    const double d_s = abs(s.hi) * 0x1p-52 + dd_error(s);
    const double delta = ((d_r + abs(q) * (1.0 + 0x1p-50) * d_s) / s_min + abs(q) * 0x1p-52 + 0x1p-1073) * (1.0 + 0x1p-20);
    if (!(is_finite(c0) && is_finite(q) && is_finite(delta))) return {};
    return {c0, q, delta, true};
}
// The filter's bound on x, or 0 where x is exact by construction: an input or a double-double
// constant (K = 0), or a value whose permanent is 0 (every term a zero: exactly 0).
template <int K>
[[nodiscard]] constexpr double exact_error(const filtered_dd<K>& x) {
    if (K == 0 || x.p == 0.0) return 0.0;
    return dd_error(x);
}
// The coordinate x = o + t d (o, d the double-double filter's values of the point's coordinate and
// the direction's, with their bounds) correctly rounded, from t = c0 + q +- delta: o + c0 d to
// double-double by two_product and two_sum (exact where the product neither underflows nor
// overflows), the rest in double, x = g + gl +- E with E the sum of: delta |d|, the dropped
// q d.lo, u times the low terms' magnitudes for each of the five roundings there, the bounds of o
// and d (d's times |t|), and 2^-1020 for a low product that underflows. x rounds to g when
// |gl| + E is below half the smaller gap around g. nullopt where that does not decide.
template <int A, int B>
[[nodiscard]] constexpr std::optional<double> coordinate_near(const filtered_dd<A>& o, const filtered_dd<B>& d, const near_quotient& t) {
    if (!(abs(t.c0) < 0x1p995 && abs(d.hi) < 0x1p995)) return std::nullopt; // Dekker's split
    const auto p = two_product(t.c0, d.hi);
    if (!(t.c0 == 0.0 || d.hi == 0.0 || (abs(p.hi) >= 0x1p-900 && abs(p.hi) <= 0x1p995))) return std::nullopt;
    const auto sh = two_sum(o.hi, p.hi);
    const double a = t.c0 * d.lo, b = t.q * d.hi;
    const double low = ((sh.lo + p.lo) + (o.lo + a)) + b;
    const auto g = two_sum(sh.hi, low);
    const double magnitude = abs(sh.lo) + abs(p.lo) + abs(o.lo) + abs(a) + abs(b);
    const double t_max = abs(t.c0) + abs(t.q) + t.delta;
    const double e =
        (t.delta * (abs(d.hi) + abs(d.lo)) + abs(t.q) * abs(d.lo) + magnitude * 0x1p-50 + exact_error(o) + t_max * exact_error(d)) *
            (1.0 + 0x1p-20) +
        0x1p-1020;
    if ((abs(g.lo) + e) * (1.0 + 0x1p-20) < half_gap(g.hi)) return g.hi;
    return std::nullopt;
}

template <class K, class F, class A, class B, class R>
[[nodiscard]] constexpr point3 rounded_point(K& k, const F& f, const A& a, const B& b, const R& r, const near_quotient& t) {
    const auto o = a(lift_filter_dd{});
    const auto d = b(lift_filter_dd{});
    auto coordinate = [&](const auto& oi, const auto& di, auto pick) {
        if (t.ok)
            if (const auto v = coordinate_near(oi, di, t)) return *v;
        if (const auto v = rounded_quotient(oi * r.den + r.num * di, r.den)) return *v;
        return rounded_coordinate(k, f, a, b, pick);
    };
    return point3{coordinate(o.x, d.x, pick_x), coordinate(o.y, d.y, pick_y), coordinate(o.z, d.z, pick_z)};
}
template <class K, class F, class A, class B, class R>
[[nodiscard]] constexpr point3 rounded_point(K& k, const F& f, const A& a, const B& b, const R& r) {
    return rounded_point(k, f, a, b, r, near_quotient_of(r.num, r.den));
}

// Both rounded, at run time, from r, the double-double filter's ratio of f: t itself as the
// coordinate 0 + t 1, from the same near quotient as the point.
template <class K, class F, class A, class B, class R>
[[nodiscard]] constexpr value_with_point<K> rounded_value_and_point(K& k, const F& f, const A& a, const B& b, const R& r) {
    const near_quotient q = near_quotient_of(r.num, r.den);
    std::optional<double> t;
    if (q.ok) t = coordinate_near(lift_filtered_dd(0.0), lift_filtered_dd(1.0), q);
    return {t ? *t : rounded_from(f, r), rounded_point(k, f, a, b, r, q)};
}
// The point a + t b in plain double.
template <class A, class B>
[[nodiscard]] constexpr point3 plain_point_at(double t, const A& a, const B& b) {
    const auto o = a(lift_double{});
    const auto d = b(lift_double{});
    return point3{o.x + t * d.x, o.y + t * d.y, o.z + t * d.z};
}
template <class K, class F, class A, class B>
[[nodiscard]] constexpr value_with_point<K> value_and_point(K& k, const F& f, const A& a, const B& b) {
    constexpr value_mode mode = value_mode_of<K>();
    if constexpr (mode == value_mode::plain) {
        const double t = plain_value(f);
        return {t, plain_point_at(t, a, b)};
    } else if constexpr (mode == value_mode::enclosure) {
        const auto r = ratio_of(f, lift_filter{});
        const auto o = a(lift_filter{});
        const auto d = b(lift_filter{});
        const interval s = enclose(r.den);
        return {divide(enclose(r.num), s),
                interval3{divide(enclose(o.x * r.den + r.num * d.x), s), divide(enclose(o.y * r.den + r.num * d.y), s),
                          divide(enclose(o.z * r.den + r.num * d.z), s)}};
    } else {
        if (values_discarded(k)) {
            const double t = plain_value(f);
            return {t, plain_point_at(t, a, b)};
        }
        if (__builtin_is_constant_evaluated()) return {rounded_value(f), rounded_point(k, f, a, b)};
        return rounded_value_and_point(k, f, a, b, ratio_of(f, lift_filter_dd{}));
    }
}
template <class K, class F, class A, class B>
[[nodiscard]] constexpr point_value_t<K> point_at(K& k, const F& f, const A& a, const B& b) {
    if constexpr (value_mode_of<K>() == value_mode::rounded) {
        if (values_discarded(k)) return plain_point_at(plain_value(f), a, b);
        if (__builtin_is_constant_evaluated()) return rounded_point(k, f, a, b);
        return rounded_point(k, f, a, b, ratio_of(f, lift_filter_dd{}));
    }
    return value_and_point(k, f, a, b).point;
}

// --- roots of a quadratic --------------------------------------------------------------------------
// The roots t1 <= t2 of a t^2 + 2 b t + c, for a > 0 and b^2 - a c >= 0 (a caller that has proven
// both), each coefficient a polynomial in the inputs: f(L) -> quadratic{a, b, c}. A parameter where
// a line meets a sphere is one (a = d . d, b = m . d, c = m . m - r^2). Rounded, t is bracketed by
// the signs of q^2 f(p / q) = a p^2 + 2 b p q + c q^2 and of a p + b q (which side of the vertex
// -b / a the point p / q lies on) at the two midpoints around a candidate; enclosed, by interval
// arithmetic on the enclosures of a, b, c and b^2 - a c, with the root written so that nothing
// cancels (t1 = c / (-b + sqrt(disc)) when b < 0, (-b - sqrt(disc)) / a when b > 0).
template <class A, class B, class C>
struct quadratic {
    A a;
    B b;
    C c;
};
template <class A, class B, class C>
quadratic(A, B, C) -> quadratic<A, B, C>;
enum class root : unsigned char { smaller, larger };

// sign(t - y) for the root t of f, from the signs of f(y) (times q^2) and of the vertex test a y + b
// (times q) at y = p / q, q > 0: zero when t = y; nothing when a needed sign is not proven.
[[nodiscard]] constexpr std::optional<sign> root_side(root r, std::optional<sign> f, std::optional<sign> v) {
    if (!f || !v) return std::nullopt;
    const sign fs = *f, vs = *v;
    if (r == root::smaller) {
        if (fs == sign::negative) return sign::negative;
        if (fs == sign::positive) return vs == sign::negative ? sign::positive : sign::negative;
        return vs != sign::positive ? sign::zero : sign::negative;
    }
    if (fs == sign::negative) return sign::positive;
    if (fs == sign::positive) return vs == sign::negative ? sign::positive : sign::negative;
    return vs != sign::negative ? sign::zero : sign::positive;
}
// The two polynomials of that test: q^2 f(p / q) and q (a p / q + b).
template <class Q, class P, class D>
[[nodiscard]] constexpr auto root_f(const Q& e, const P& p, const D& q) {
    return e.a * p * p + (e.b * p * q + e.b * p * q) + e.c * q * q;
}
template <class Q, class P, class D>
[[nodiscard]] constexpr auto root_v(const Q& e, const P& p, const D& q) {
    return e.a * p + e.b * q;
}

// The root in plain double, written so that nothing cancels; from a discriminant b b - a c
// computed by the caller, or in double.
[[nodiscard]] constexpr double root_of(root r, double a, double b, double c, double disc) {
    const double s = sqrt(disc > 0.0 ? disc : 0.0);
    if (b < 0.0) return r == root::smaller ? c / (-b + s) : (-b + s) / a;
    return r == root::smaller ? (-b - s) / a : c / (-b - s);
}
[[nodiscard]] constexpr double plain_root(root r, double a, double b, double c) { return root_of(r, a, b, c, b * b - a * c); }
[[nodiscard]] constexpr interval enclosed_root(root r, interval a, interval b, interval c, interval disc) {
    const interval s = square_root(disc);
    if (b.hi < 0.0) return r == root::smaller ? divide(c, add(negate(b), s)) : divide(add(negate(b), s), a);
    if (b.lo > 0.0) return r == root::smaller ? divide(sub(negate(b), s), a) : divide(c, sub(negate(b), s));
    return r == root::smaller ? divide(sub(negate(b), s), a) : divide(add(negate(b), s), a);
}
template <class F>
[[nodiscard]] constexpr interval enclosed_root_of(const F& f, root r) {
    const auto q = f(lift_filter{});
    return enclosed_root(r, enclose(q.a), enclose(q.b), enclose(q.c), enclose(q.b * q.b - q.a * q.c));
}

// sign(t - y) by exact signs (kernel.cppm's exact_sign) for y = p(L) / q(L), q > 0.
template <class F, class P, class D>
[[nodiscard]] constexpr sign exact_root_side(const F& f, root r, const P& p, const D& q) {
    bool valid = true;
    const sign fs = exact_sign([=](auto L) { return root_f(f(L), p(L), q(L)); }, valid);
    const sign vs = exact_sign([=](auto L) { return root_v(f(L), p(L), q(L)); }, valid);
    return *root_side(r, fs, vs);
}
// The exact stages: the midpoint test on exact signs, then dyadic bracketing for a result below the
// normal range or beyond the largest double.
template <class F>
[[nodiscard, gnu::noinline]] constexpr double rounded_root_exactly(F f, root r, double guess) {
    if (is_finite(guess) && guess != 0.0)
        if (const auto v = round_at_midpoints(guess, [&](double c, double h) {
                return std::optional<sign>(exact_root_side(f, r, [=](auto L) { return L(c) + L(h); }, [](auto L) { return L(1.0); }));
            }))
            return *v;
    const auto q = f(lift_dyadic{});
    const dyadic one = to_dyadic(1.0);
    auto side = [&](const dyadic& y) { return *root_side(r, to_sign(sign_of(root_f(q, y, one))), to_sign(sign_of(root_v(q, y, one)))); };
    return correctly_round([&](const dyadic& y) { return side(y) != sign::positive; },
                           [&](const dyadic& y) { return side(y) == sign::negative; }, is_finite(guess) ? guess : 0.0);
}
// One Newton step from g on the double-double coefficients: the root to about twice the
// precision of g, as g - delta (delta small beside g): the guess for a coordinate a_i + t b_i that
// cancels, where the rounded t alone is not near enough.
template <class Q>
[[nodiscard]] constexpr double newton_step(const Q& q, double g) {
    const filtered_dd<0> x = lift_filtered_dd(g), one = lift_filtered_dd(1.0);
    const auto f = root_f(q, x, one);
    const auto fp = root_v(q, x, one); // f'(g) / 2
    const double d = fp.hi + fp.hi;
    if (!(abs(d) > 0.0)) return 0.0;
    const double delta = (f.hi + f.lo) / d;
    return is_finite(delta) ? delta : 0.0;
}
// Whether root r of g(p) = a p^2 + 2 b p w + c w^2 (w > 0 fixed) lies strictly within p0 -+ h, from
// G0 = g(p0) and G1 = a p0 + b w (half the slope there): g(p0 +- h) = G0 +- 2 h G1 + a h^2. With
// a > 0, g is positive outside its roots and negative between them, so g(p0 - h) > 0 > g(p0 + h)
// puts the smaller root, and only it, inside (and - then + the larger): G1 < 0 (> 0) and
// |G0 + a h^2| < 2 h |G1|. In double with the filter's bounds, each rounding covered by 1 +- 2^-20
// and 2^-1020 (normal) for an a h^2 that underflows; h a power of two, so 2 h times a number
// above 2^-900 is exact. One evaluation of g for both midpoints, where the midpoint test takes two.
template <class Q, int A, int B>
[[nodiscard]] constexpr bool root_surely_within(const Q& q, root r, const filtered_dd<A>& g0, const filtered_dd<B>& g1, double h) {
    if ((g1.hi < 0.0) != (r == root::smaller)) return false;
    const double a_max = abs(q.a.hi) * (1.0 + 0x1p-20) + dd_error(q.a);
    const double left = (abs(g0.hi) * (1.0 + 0x1p-20) + dd_error(g0) + (a_max * h * h * (1.0 + 0x1p-20) + 0x1p-1020)) * (1.0 + 0x1p-20);
    const double right = 2.0 * h * (abs(g1.hi) * (1.0 - 0x1p-20) - dd_error(g1));
    return right > 0x1p-900 && left < right;
}
// Whether the root is surely c (rounded to nearest), as root_surely_within at p0 = c, w = 1.
template <class Q>
[[nodiscard]] constexpr bool root_surely_rounds_to(const Q& q, root r, double c) {
    const double h = half_gap(c);
    if (h == 0.0) return false;
    const filtered_dd<0> x = lift_filtered_dd(c), one = lift_filtered_dd(1.0);
    return root_surely_within(q, r, root_f(q, x, one), root_v(q, x, one), h);
}

// The guess: the root in double and one Newton step; where that is not surely it, the root from
// the double-double coefficients and discriminant. Near a double root (a ray tangent to a ball)
// the discriminant in double is mostly rounding error, and its square root moves the root by
// about 2^-26 of its size, too far for the midpoint tests below (a Newton step only halves that
// error at a double root); in double-double it moves it by an ulp or two.
template <class F>
[[nodiscard]] constexpr double rounded_root(const F& f, root r) {
    const auto qd = f(lift_double{});
    double guess = plain_root(r, qd.a, qd.b, qd.c);
    if (!__builtin_is_constant_evaluated()) {
        const auto q = f(lift_filter_dd{});
        const filtered_dd<0> one = lift_filtered_dd(1.0);
        if (is_finite(guess)) guess -= newton_step(q, guess);
        if (root_surely_rounds_to(q, r, guess)) return guess;
        const auto disc = q.b * q.b - q.a * q.c;
        if (const double g = root_of(r, q.a.hi, q.b.hi, q.c.hi, disc.hi + disc.lo); is_finite(g)) {
            guess = g - newton_step(q, g);
            if (root_surely_rounds_to(q, r, guess)) return guess;
        }
        if (const auto v = round_at_midpoints(guess, [&](double c, double h) {
                const auto m = lift_filtered_dd(c, h);
                return root_side(r, dd_side(root_f(q, m, one)), dd_side(root_v(q, m, one)));
            }))
            return *v;
    }
    return rounded_root_exactly(f, r, guess);
}

// The root as kernel K computes values.
template <class F>
[[nodiscard]] constexpr double plain_root_of(const F& f, root r) {
    const auto q = f(lift_double{});
    return plain_root(r, q.a, q.b, q.c);
}
template <class K, class F>
[[nodiscard]] constexpr value_t<K> root_value(K& k, const F& f, root r) {
    if constexpr (value_mode_of<K>() == value_mode::enclosure) return enclosed_root_of(f, r);
    else if constexpr (value_mode_of<K>() == value_mode::rounded) return values_discarded(k) ? plain_root_of(f, r) : rounded_root(f, r);
    else return plain_root_of(f, r);
}

// A coordinate a_i + t b_i at the root, by exact signs, then dyadic bracketing.
template <class F, class A, class B>
[[nodiscard, gnu::noinline]] constexpr double rounded_root_coordinate(F f, root r, A ai, B bi, sign sb, double guess) {
    const bool up = sb == sign::positive;
    if (is_finite(guess) && guess != 0.0)
        if (const auto v = round_at_midpoints(guess, [&](double c, double h) {
                const sign s = up ? exact_root_side(
                                        f, r, [=](auto L) { return (L(c) + L(h)) - ai(L); }, [=](auto L) { return bi(L); })
                                  : exact_root_side(f, r, [=](auto L) { return ai(L) - (L(c) + L(h)); }, [=](auto L) { return -bi(L); });
                return std::optional<sign>(sb * s);
            }))
            return *v;
    const auto q = f(lift_dyadic{});
    const dyadic a = ai(lift_dyadic{}), d = bi(lift_dyadic{});
    auto side = [&](const dyadic& y) {
        const dyadic p = up ? y - a : a - y, w = up ? d : -d;
        return sb * *root_side(r, to_sign(sign_of(root_f(q, p, w))), to_sign(sign_of(root_v(q, p, w))));
    };
    return correctly_round([&](const dyadic& y) { return side(y) != sign::positive; },
                           [&](const dyadic& y) { return side(y) == sign::negative; }, is_finite(guess) ? guess : 0.0);
}

// The point a + t b at the root t (a(L), b(L) lifted points and vectors, as in point_at; each b_i
// an input or the difference of two inputs, whose sign in double is exact): each
// coordinate a_i + t b_i is on the side of a midpoint m that t is of y = (m - a_i) / b_i (times the
// sign of b_i), so it is bracketed as the root is, with p = +-(m - a_i) and q = |b_i|.
template <class K, class F, class A, class B>
[[nodiscard]] constexpr value_with_point<K> value_and_point_at_root(K& k, const F& f, root r, const A& a, const B& b) {
    constexpr value_mode mode = value_mode_of<K>();
    if constexpr (mode == value_mode::plain) {
        const double t = plain_root_of(f, r);
        return {t, plain_point_at(t, a, b)};
    } else if constexpr (mode == value_mode::enclosure) {
        const interval t = enclosed_root_of(f, r);
        const auto o = a(lift_filter{});
        const auto d = b(lift_filter{});
        auto coordinate = [&](const auto& oi, const auto& di) { return add(enclose(oi), mul(t, enclose(di))); };
        return {t, interval3{coordinate(o.x, d.x), coordinate(o.y, d.y), coordinate(o.z, d.z)}};
    } else {
        if (values_discarded(k)) {
            const double t = plain_root_of(f, r);
            return {t, plain_point_at(t, a, b)};
        }
        // the rounded t and one Newton step give t to about twice double's precision, and so a guess
        // for each coordinate that stays within an ulp where a_i + t b_i cancels
        const double t = rounded_root(f, r);
        bool run_time = !__builtin_is_constant_evaluated(); // not const: a const bool would be a constant
        const auto q = run_time ? f(lift_filter_dd{}) : decltype(f(lift_filter_dd{})){};
        const auto ad = run_time ? a(lift_filter_dd{}) : decltype(a(lift_filter_dd{})){};
        const auto bd = run_time ? b(lift_filter_dd{}) : decltype(b(lift_filter_dd{})){};
        const double delta = run_time ? newton_step(q, t) : 0.0;
        auto coordinate = [&](auto pick) -> double {
            const double bi = pick(b(lift_double{}));
            const sign sb = sign_of_double(bi);
            if (sb == sign::zero) return pick(a(lift_double{})); // b_i == 0: the coordinate is a_i, an input
            double guess = pick(a(lift_double{})) + t * bi;
            // sign(a_i + t b_i - m) = sign(b_i) sign(t - y), y = p / q = sign(b_i) (m - a_i) / |b_i|
            if (run_time) {
                const auto ai = pick(ad);
                const auto di = pick(bd);
                const auto g = ai + lift_filtered_dd(t, -delta) * di;
                guess = g.hi + g.lo;
                if (const double h = half_gap(guess); h != 0.0) { // both midpoints from one evaluation
                    const auto c = lift_filtered_dd(guess);
                    const auto p0 = sb == sign::positive ? c - ai : ai - c;
                    const auto w = sb == sign::positive ? di : -di;
                    if (root_surely_within(q, r, root_f(q, p0, w), root_v(q, p0, w), h)) return guess;
                }
                const auto v = round_at_midpoints(guess, [&](double c, double h) {
                    const auto m = lift_filtered_dd(c, h);
                    const auto s = sb == sign::positive ? root_side(r, dd_side(root_f(q, m - ai, di)), dd_side(root_v(q, m - ai, di)))
                                                        : root_side(r, dd_side(root_f(q, ai - m, -di)), dd_side(root_v(q, ai - m, -di)));
                    return times(s, sb);
                });
                if (v) return *v;
            }
            return rounded_root_coordinate(f, r, [=](auto L) { return pick(a(L)); }, [=](auto L) { return pick(b(L)); }, sb, guess);
        };
        return {t, point3{coordinate(pick_x), coordinate(pick_y), coordinate(pick_z)}};
    }
}

} // namespace incidence::arith
