// Error-free transforms, expansions, dyadic rounding and correct rounding, checked against
// independent arithmetic (long double where exact, Boost cpp_rational otherwise).
#include <catch2/catch_test_macros.hpp>
#include <boost/multiprecision/cpp_int.hpp>
#include <limits>
#include <utility>
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"

namespace test_arith_arith { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using rational = boost::multiprecision::cpp_rational;

namespace {
rational Q(double x) { return rational(x); }
// nearest-even check for x against the exact rational v
bool nearest(const rational& v, double x) {
    const rational d = abs(v - Q(x));
    for (double nb : {std::nextafter(x, INFINITY), std::nextafter(x, -INFINITY)}) {
        if (!std::isfinite(nb)) continue;
        const rational dn = abs(v - Q(nb));
        if (dn < d) return false;
        if (dn == d && (std::bit_cast<std::uint64_t>(x) & 1u)) return false;
    }
    return true;
}
double random_double(support::rng& r) {
    // raw bit patterns of finite doubles, biased towards interesting exponents
    for (;;) {
        const double x = std::bit_cast<double>(r.bits());
        if (std::isfinite(x)) return r.integer(0, 3) == 0 ? x : std::ldexp(r.uniform(-1, 1), r.integer(-60, 60));
    }
}
// The sign of det[p0 - p3; p1 - p3; p2 - p3] in rationals.
sign exact_orientation(const point3 (&p)[4]) {
    auto diff = [&](int k, int axis) {
        return Q(axis == 0 ? p[k].x : (axis == 1 ? p[k].y : p[k].z)) - Q(axis == 0 ? p[3].x : (axis == 1 ? p[3].y : p[3].z));
    };
    rational m[3][3];
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) m[k][j] = diff(k, j);
    const rational v = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return v > 0 ? sign::positive : (v < 0 ? sign::negative : sign::zero);
}
} // namespace

TEST_CASE("arith: two_sum, two_diff and two_product are error-free", "[arith]") {
    support::rng r(support::seed());
    long n = 0, bad = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        const double a = std::ldexp(r.uniform(-1, 1), r.integer(-400, 400)), b = std::ldexp(r.uniform(-1, 1), r.integer(-400, 400));
        const auto s = arith::two_sum(a, b);
        const auto d = arith::two_diff(a, b);
        const auto p = arith::two_product(a, b);
        ++n;
        if (Q(s.hi) + Q(s.lo) != Q(a) + Q(b) || Q(d.hi) + Q(d.lo) != Q(a) - Q(b) || Q(p.hi) + Q(p.lo) != Q(a) * Q(b)) ++bad;
        if (s.hi != a + b || p.hi != a * b) ++bad;
    }
    std::printf("[cases] error-free transforms: %ld, wrong %ld\n", n, bad);
    CHECK(bad == 0);
    static_assert(arith::two_product(0.1, 0.1).lo != 0.0);
}

TEST_CASE("arith: expansion arithmetic is exact", "[arith]") {
    support::rng r(support::seed() + 1);
    long bad = 0;
    for (long i = 0; i < support::cases(20000); ++i) {
        const double x[4] = {std::ldexp(r.uniform(-1, 1), r.integer(-100, 100)), std::ldexp(r.uniform(-1, 1), r.integer(-100, 100)),
                             std::ldexp(r.uniform(-1, 1), r.integer(-100, 100)), std::ldexp(r.uniform(-1, 1), r.integer(-100, 100))};
        using E = arith::expansion<1>;
        const auto e = (E(x[0]) - E(x[1])) * (E(x[2]) + E(x[3])) - E(x[0]) * E(x[2]);
        const rational want = (Q(x[0]) - Q(x[1])) * (Q(x[2]) + Q(x[3])) - Q(x[0]) * Q(x[2]);
        rational got = 0;
        for (int k = 0; k < e.n; ++k) got += Q(e.c[static_cast<unsigned>(k)]);
        if (got != want) ++bad;
        // nonoverlapping, increasing magnitude
        for (int k = 1; k < e.n; ++k)
            if (std::fabs(e.c[static_cast<unsigned>(k - 1)]) >= std::fabs(e.c[static_cast<unsigned>(k)])) ++bad;
    }
    CHECK(bad == 0);
}

TEST_CASE("arith: dyadic rounding and quotients are correctly rounded (subnormal to overflow)", "[arith]") {
    support::rng r(support::seed() + 2);
    long n = 0, bad = 0;
    for (long i = 0; i < support::cases(20000); ++i) {
        const double a = random_double(r), b = random_double(r), c = random_double(r);
        const auto s = arith::to_dyadic(a) * arith::to_dyadic(b) + arith::to_dyadic(c);
        const rational v = Q(a) * Q(b) + Q(c);
        const double got = arith::to_double(s);
        ++n;
        if (std::isfinite(got) ? !nearest(v, got) : abs(v) < Q(0x1.fffffffffffffp1023)) ++bad;
        if (b != 0.0) {
            const double q = arith::quotient(arith::to_dyadic(a) - arith::to_dyadic(c), arith::to_dyadic(b));
            const rational vq = (Q(a) - Q(c)) / Q(b);
            if (std::isfinite(q) && !nearest(vq, q)) ++bad;
        }
    }
    std::printf("[cases] dyadic rounding: %ld, wrong %ld\n", n, bad);
    CHECK(bad == 0);
    static_assert(arith::to_double(arith::to_dyadic(0x1p-1074) + arith::to_dyadic(0x1p-1074)) == 0x1p-1073);
}

TEST_CASE("arith: the filter never claims a wrong sign", "[arith]") {
    support::rng r(support::seed() + 3);
    long n = 0, wrong = 0, proven = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        const double x[4] = {random_double(r), random_double(r), random_double(r), random_double(r)};
        const auto f = [&](auto L) { return (L(x[0]) - L(x[1])) * (L(x[2]) - L(x[3])) - L(x[0]) * L(x[2]); };
        const int fs = arith::proven_sign(f(arith::lift_filter{}));
        const rational v = (Q(x[0]) - Q(x[1])) * (Q(x[2]) - Q(x[3])) - Q(x[0]) * Q(x[2]);
        const int t = v > 0 ? 1 : (v < 0 ? -1 : 0);
        ++n;
        if (fs != 0) {
            ++proven;
            if (fs != t) ++wrong;
        }
        bool valid = true;
        if (static_cast<int>(arith::exact_sign(f, valid)) != t) ++wrong;
    }
    std::printf("[cases] filter: %ld, proven %ld, wrong %ld\n", n, proven, wrong);
    CHECK(wrong == 0);
}

// The kernel of mesh and polygon3 pairs: a sign the filter cannot prove is settled by plain double
// with every operation exact, then double-double. orient3d of four exactly coplanar points of
// small dyadic coordinates (an exact zero the filter cannot prove), the last one nudged by up to
// two ulps in half the cases (a sign a few ulps from zero): every sign it calls certain is right,
// and it settles signs on which the plain filter kernel fails.
TEST_CASE("arith: the settling filter kernel settles exact zeros, never wrongly", "[arith]") {
    support::rng r(support::seed() + 5);
    long certain = 0, settled = 0, wrong = 0;
    for (long i = 0; i < support::cases(20000); ++i) {
        const double a = support::small(r), b = support::small(r), c = support::small(r);
        point3 p[4];
        for (auto& q : p) {
            const double x = support::small(r), y = support::small(r);
            q = {x, y, a * x + b * y + c}; // exact: products of small dyadics
        }
        if (r.coin()) p[3].z = support::nudge(p[3].z, r.integer(-2, 2));
        const auto f = [&p](auto L) {
            const auto o = arith::lift(L, p[3]);
            return arith::det3(arith::lift(L, p[0]) - o, arith::lift(L, p[1]) - o, arith::lift(L, p[2]) - o);
        };
        const sign want = exact_orientation(p);
        arith::settling_filter_kernel k;
        arith::filter_kernel plain;
        const sign s = k.sgn(f);
        (void)plain.sgn(f);
        if (k.failed()) continue;
        ++certain;
        if (s != want) ++wrong;
        if (plain.failed()) ++settled;
    }
    std::printf("[cases] settling filter kernel: %ld certain, %ld of them settled after the filter failed, wrong %ld\n", certain, settled,
                wrong);
    CHECK(wrong == 0);
    CHECK(settled > support::cases(20000) / 4);
}

// Zeros by structure (arith::zero_by_structure): orient3d of four points in one plane z = c (random
// doubles of exponents -300 to 300, so the products round and only the structure shows the zero,
// and no product overflows), the last
// point's z moved by up to two ulps in half the cases, and in a tenth of the cases one coordinate
// infinite or NaN. The filter kernel's structural_sgn is certain on every exact zero and never
// wrong; it never calls a sign certain with a non-finite input, where the exact kernel reports the
// input invalid.
TEST_CASE("arith: zeros by structure are proven exactly, never for a nonzero or non-finite value", "[arith]") {
    support::rng r(support::seed() + 6);
    long zeros = 0, proven_zeros = 0, certain = 0, wrong = 0, non_finite = 0, claimed_non_finite = 0;
    for (long i = 0; i < support::cases(20000); ++i) {
        auto coordinate = [&] { return std::ldexp(r.uniform(-1, 1), r.integer(-300, 300)); };
        const double c = coordinate();
        point3 p[4];
        for (auto& q : p) q = {coordinate(), coordinate(), c};
        if (r.coin()) p[3].z = support::nudge(p[3].z, r.integer(-2, 2));
        const bool bad = r.integer(0, 9) == 0;
        if (bad) {
            double* coords[3] = {&p[r.integer(0, 3)].x, &p[r.integer(0, 3)].y, &p[r.integer(0, 3)].z};
            *coords[r.integer(0, 2)] = r.coin() ? std::numeric_limits<double>::infinity() : std::numeric_limits<double>::quiet_NaN();
        }
        const auto f = [&p](auto L) {
            const auto o = arith::lift(L, p[3]);
            return arith::det3(arith::lift(L, p[0]) - o, arith::lift(L, p[1]) - o, arith::lift(L, p[2]) - o);
        };
        arith::filter_kernel k;
        const sign s = arith::sgn<arith::hint::structural>(k, f);
        arith::exact_kernel e;
        const sign x = e.sgn(f);
        if (bad) {
            ++non_finite;
            if (!k.failed()) ++claimed_non_finite;
            if (e.valid) ++claimed_non_finite;
            continue;
        }
        const sign want = exact_orientation(p);
        if (x != want) ++wrong;
        if (want == sign::zero) ++zeros;
        if (k.failed()) continue;
        ++certain;
        if (s != want) ++wrong;
        if (want == sign::zero) ++proven_zeros;
    }
    std::printf("[cases] zeros by structure: %ld certain, %ld exact zeros of which %ld proven by the filter kernel, wrong %ld; "
                "%ld non-finite, %ld claimed\n",
                certain, zeros, proven_zeros, wrong, non_finite, claimed_non_finite);
    CHECK(wrong == 0);
    CHECK(claimed_non_finite == 0);
    CHECK(non_finite > 0);
    // every unmoved case is an exact zero by structure (z - c = 0 in every row)
    CHECK(proven_zeros == zeros);
    CHECK(zeros > support::cases(20000) / 3);
    // the rule in constant evaluation too
    static_assert([] {
        arith::filter_kernel k;
        const point3 a{0.1, 0.3, 0.7}, b{0.2, -0.5, 0.7}, d{-0.9, 0.4, 0.7}, o{1.0 / 3.0, 0.6, 0.7};
        const sign s = arith::sgn<arith::hint::structural>(k, [=](auto L) {
            const auto O = arith::lift(L, o);
            return arith::det3(arith::lift(L, a) - O, arith::lift(L, b) - O, arith::lift(L, d) - O);
        });
        return s == sign::zero && !k.failed();
    }());
}

// Every degree up to dyadic_max_degree, with inputs anywhere in the finite range (subnormal to
// 2^1023): the terms then span up to 2098 d bits, which the dyadic fallback must hold whole. The
// first case of each degree is the widest: huge^d - tiny^d, positive.
template <int D>
long exact_sign_wrong(support::rng& r, long cases) {
    long wrong = 0;
    for (long i = 0; i < cases; ++i) {
        double x[3][D]; // three terms of D factors each: t0 - t1 + t2
        for (auto& t : x)
            for (double& v : t) v = random_double(r);
        if (i == 0)
            for (int k = 0; k < D; ++k) x[0][k] = 0x1.fffffffffffffp1023, x[1][k] = 0x1p-1074, x[2][k] = 0.0;
        const auto f = [&x](auto L) {
            return [&]<std::size_t... K>(std::index_sequence<K...>) {
                return (L(x[0][K]) * ...) - (L(x[1][K]) * ...) + (L(x[2][K]) * ...);
            }(std::make_index_sequence<D>{});
        };
        rational v = 0;
        for (int t = 0; t < 3; ++t) {
            rational p = 1;
            for (double c : x[t]) p *= Q(c);
            v += t == 1 ? -p : p;
        }
        const int want = v > 0 ? 1 : (v < 0 ? -1 : 0);
        bool valid = true;
        if (static_cast<int>(arith::exact_sign(f, valid)) != want || !valid) ++wrong;
    }
    return wrong;
}
TEST_CASE("arith: exact signs of degree 2 to 10 over the whole exponent range", "[arith]") {
    support::rng r(support::seed() + 5);
    const long each = support::cases(300);
    static_assert(arith::dyadic_max_degree == 10);
    const long wrong = exact_sign_wrong<2>(r, each) + exact_sign_wrong<3>(r, each) + exact_sign_wrong<4>(r, each) +
                       exact_sign_wrong<5>(r, each) + exact_sign_wrong<6>(r, each) + exact_sign_wrong<7>(r, each) +
                       exact_sign_wrong<8>(r, each) + exact_sign_wrong<9>(r, each) + exact_sign_wrong<10>(r, each);
    std::printf("[cases] exact signs, degree 2 to %d, full exponent range: %ld, wrong %ld\n", arith::dyadic_max_degree, 9 * each, wrong);
    CHECK(wrong == 0);
}

// A scene near 2^-500 or 2^500: orient3d of four points at 2^k times three lifted ones (degree
// 6, as the half-space signs mix unit normals with coordinates). Unscaled, the filter's permanent
// leaves its trusted range; scaled by filter_shift's power of two, it decides them, never wrongly.
TEST_CASE("arith: the scaled filter decides scenes far from scale 1, never wrongly", "[arith]") {
    support::rng r(support::seed() + 6);
    long n = 0, wrong = 0, proven = 0, unscaled = 0;
    for (long i = 0; i < support::cases(20000); ++i) {
        const int k = r.integer(0, 1) ? r.integer(-520, -310) : r.integer(340, 520);
        double x[12];
        for (double& v : x) v = std::ldexp(r.uniform(-1, 1), k);
        const auto f = [&x](auto L) {
            const auto one = L(1.0);
            auto p = [&](int j) { return arith::v3<decltype(L(0.0))>{L(x[3 * j]), L(x[3 * j + 1]), L(x[3 * j + 2])}; };
            return one * one * one * arith::det3(p(1) - p(0), p(2) - p(0), p(3) - p(0));
        };
        rational v;
        {
            auto q = [&](int j, int c) { return Q(x[3 * j + c]) - Q(x[c]); };
            v = q(1, 0) * (q(2, 1) * q(3, 2) - q(2, 2) * q(3, 1)) + q(1, 1) * (q(2, 2) * q(3, 0) - q(2, 0) * q(3, 2)) +
                q(1, 2) * (q(2, 0) * q(3, 1) - q(2, 1) * q(3, 0));
        }
        const int want = v > 0 ? 1 : (v < 0 ? -1 : 0);
        ++n;
        unscaled += arith::proven_sign(f(arith::lift_filter{})) != 0;
        const int shift = arith::filter_shift(f(arith::lift_range{}));
        if (shift == 0) continue;
        const int s = arith::scaled_filter_sign(f, shift);
        if (s != 0) {
            ++proven;
            if (s != want) ++wrong;
        }
        bool valid = true;
        if (static_cast<int>(arith::exact_sign(f, valid)) != want) ++wrong;
    }
    std::printf("[cases] scaled filter: %ld scenes at 2^-520..2^-310 and 2^340..2^520, proven unscaled %ld, scaled %ld, wrong %ld\n", n,
                unscaled, proven, wrong);
    CHECK(wrong == 0);
    CHECK(unscaled < n / 10);
    CHECK(proven > n * 9 / 10);
}

TEST_CASE("arith: correctly_round finds the nearest double of sqrt(2) and of 1/3", "[arith]") {
    using arith::dyadic;
    const auto two = arith::to_dyadic(2.0);
    const double s2 =
        arith::correctly_round([&](const dyadic& y) { return arith::sign_of(y) >= 0 && arith::sign_of(y * y - two) >= 0; },
                               [&](const dyadic& y) { return arith::sign_of(y) > 0 && arith::sign_of(y * y - two) > 0; }, 1.0);
    CHECK(s2 == std::sqrt(2.0));
    CHECK(arith::quotient(arith::to_dyadic(1.0), arith::to_dyadic(3.0)) == 1.0 / 3.0);
}

TEST_CASE("arith: the double-double filter never claims a wrong sign, near cancellation", "[arith]") {
    support::rng r(support::seed() + 4);
    long n = 0, wrong = 0, proven = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        // x0 x2 - x1 x3 with x0 x2 ~ x1 x3: near cancellation, a few ulps apart or exactly equal
        const double a = std::ldexp(r.uniform(0.5, 1), r.integer(-300, 300)), b = std::ldexp(r.uniform(0.5, 1), r.integer(-300, 300));
        const double x[4] = {a, support::nudge(a * b / b, r.integer(-3, 3)), support::nudge(b, r.integer(-2, 2)), b};
        const auto f = [&](auto L) { return L(x[0]) * L(x[2]) - L(x[1]) * L(x[3]) + (L(x[0]) - L(x[1])) * (L(x[2]) - L(x[3])); };
        const int fs = arith::proven_sign(f(arith::lift_filter_dd{}));
        const rational v = Q(x[0]) * Q(x[2]) - Q(x[1]) * Q(x[3]) + (Q(x[0]) - Q(x[1])) * (Q(x[2]) - Q(x[3]));
        const int t = v > 0 ? 1 : (v < 0 ? -1 : 0);
        ++n;
        if (fs != 0) {
            ++proven;
            if (fs != t) ++wrong;
        }
    }
    std::printf("[cases] double-double filter: %ld near-cancelling, proven %ld, wrong %ld\n", n, proven, wrong);
    CHECK(wrong == 0);
}

TEST_CASE("arith: a coordinate o + t d from t to twice double's precision is the nearest double where decided", "[arith]") {
    // t = P / S with P, S double-double products (value.cppm's near_quotient_of), o an input, d an
    // input (a ray) or a difference of inputs (a segment): the enclosure of t - (c0 + q) and the
    // rounding of o + t d (coordinate_near) against exact rationals, at scales 2^-500..2^500, with
    // o at t d's scale, cancelling it, or cancelling all but a small part of it.
    support::rng r(support::seed() + 5);
    long n = 0, decided = 0, wrong = 0, outside = 0;
    auto scaled = [&](int lo, int hi) { return std::ldexp(r.uniform(-1, 1), r.integer(lo, hi)); };
    for (long i = 0; i < support::cases(100000); ++i) {
        const int e = r.integer(-500, 500);
        const double p[4] = {scaled(e - 2, e + 2), scaled(-2, 2), scaled(e - 2, e + 2), scaled(-2, 2)};
        const double s[4] = {scaled(-2, 2), scaled(-2, 2), scaled(-2, 2), scaled(-2, 2)};
        const arith::lift_filter_dd L{};
        const auto P = L(p[0]) * L(p[1]) - L(p[2]) * L(p[3]);
        const auto S = L(s[0]) * L(s[1]) + L(s[2]) * L(s[3]);
        const rational Pq = Q(p[0]) * Q(p[1]) - Q(p[2]) * Q(p[3]), Sq = Q(s[0]) * Q(s[1]) + Q(s[2]) * Q(s[3]);
        if (Sq == 0) continue;
        const arith::near_quotient t = arith::near_quotient_of(P, S);
        if (!t.ok) continue;
        const rational tq = Pq / Sq;
        if (abs(tq - Q(t.c0) - Q(t.q)) > Q(t.delta)) ++outside;
        const bool segment = r.coin();
        const double d0 = scaled(-3, 3), d1 = segment ? d0 - scaled(-3 - r.integer(0, 40), -3) : 0.0;
        const rational dq = segment ? Q(d0) - Q(d1) : Q(d0);
        // o at t d's scale, or a few ulps from -t d (cancellation), or -t d plus a much smaller y
        const double td = static_cast<double>(tq * dq);
        const int kind = r.integer(0, 2);
        const double o =
            kind == 0 ? td * r.uniform(-2, 2) : support::nudge(kind == 1 ? -td : -td + std::ldexp(td, -r.integer(1, 60)), r.integer(-2, 2));
        const auto x = segment ? arith::coordinate_near(L(o), L(d0) - L(d1), t) : arith::coordinate_near(L(o), L(d0), t);
        ++n;
        if (!x) continue;
        ++decided;
        if (!nearest(Q(o) + tq * dq, *x)) ++wrong;
    }
    std::printf("[cases] coordinate from t: %ld, decided %ld, wrong %ld, t outside its enclosure %ld\n", n, decided, wrong, outside);
    CHECK(n > support::cases(100000) / 2);
    CHECK(outside == 0);
    CHECK(wrong == 0);
}

} // namespace test_arith_arith
