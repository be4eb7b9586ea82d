// Shared test support. Include after `import incidence;`.
// - rng with a printed seed (INCIDENCE_SEED overrides), case counts scaled by INCIDENCE_CASES_SCALE
//   (the sanitizer build runs a tenth of the release build's cases);
// - generators: random coordinates at scales 2^-500..2^500, translations far from the origin,
//   and nudges of 0..4 ulps applied to configurations built exactly on a decision boundary;
// - margin_kernel: re-runs a query body and records how close each deciding polynomial was to
//   zero relative to its permanent, which is the approximate tier's stated error measure;
// - tally: counts, printed as one "[cases]" line per test.
#pragma once
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include "rng.hpp"

namespace support {

inline std::uint64_t seed() {
    if (const char* s = std::getenv("INCIDENCE_SEED")) return std::strtoull(s, nullptr, 10);
    return 20261122;
}
inline long cases(long n) {
    double scale = 1.0;
    if (const char* s = std::getenv("INCIDENCE_CASES_SCALE")) scale = std::strtod(s, nullptr);
    const long m = static_cast<long>(static_cast<double>(n) * scale);
    return m < 100 ? 100 : m;
}

using rng = audit::rng; // seeded, shared with the audit

inline double nudge(double x, int ulps) {
    for (; ulps > 0; --ulps) x = std::nextafter(x, INFINITY);
    for (; ulps < 0; ++ulps) x = std::nextafter(x, -INFINITY);
    return x;
}

// A transform applied to every coordinate of a case: scale by 2^k (exact), translate by t
// (rounded: it moves exact boundary cases slightly off, which is part of the test), then
// nudge by 0..4 ulps with probability 1/2 per coordinate.
struct transform {
    int k = 0;
    double t[3] = {0, 0, 0};
    bool nudged = true;
    rng* r = nullptr;
    double apply(double x, int axis) const {
        double y = std::ldexp(x, k) + t[axis];
        if (nudged && r->coin()) y = nudge(y, r->integer(-4, 4));
        return y;
    }
    double scale_only(double x) const { return std::ldexp(x, k); } // for radii and directions
    double dir(double x) const {
        double y = std::ldexp(x, k);
        if (nudged && r->coin()) y = nudge(y, r->integer(-4, 4));
        return y;
    }
};
// any_scale false: scale 1 and no far translation (the benchmarks' sets, at the size of the others).
inline transform random_transform(rng& r, bool nudged, bool any_scale = true) {
    transform tr;
    tr.r = &r;
    tr.nudged = nudged;
    if (r.at_scale_one) any_scale = false;
    const int pick = r.integer(0, 9);
    tr.k = pick < 4 || !any_scale ? 0 : r.integer(-500, 500);
    if (r.integer(0, 3) == 0 && any_scale) {
        const int far = r.integer(1, 30);
        for (double& ti : tr.t) ti = std::ldexp(r.uniform(-1, 1), tr.k + far);
    }
    return tr;
}

// A coordinate for bad-input tests: one time in three a special value (NaN, infinities, the
// largest and near-largest magnitudes, subnormals, the smallest normal, zero, +-1), else uniform in
// [-1, 1].
inline double special_or_uniform(rng& r) {
    const double specials[] = {std::numeric_limits<double>::quiet_NaN(),
                               std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(),
                               0x1p1020,
                               -0x1.fffffffffffffp1023,
                               0x1p-1074,
                               -0x1p-1060,
                               0x1p-1022,
                               0.0,
                               1.0,
                               -1.0};
    return r.integer(0, 2) == 0 ? specials[r.integer(0, 10)] : r.uniform(-1, 1);
}

// Small integer or dyadic coordinates, so boundary constructions are exact before transforming.
inline double small(rng& r) { return r.integer(-16, 16) + (r.coin() ? 0.0 : r.integer(0, 3) * 0.25); }
inline double random_coord(rng& r, const transform& tr, int axis) { return tr.apply(r.uniform(-1, 1), axis); }

struct tally {
    std::string name;
    long n = 0, exact_wrong = 0, conservative_violations = 0, aggressive_violations = 0, classify_wrong = 0, approx_wrong = 0,
         approx_outside_bound = 0, symmetry_wrong = 0, uncertain = 0;
    void print() const {
        std::printf("[cases] %s: %ld cases; exact disagreements %ld; conservative violations %ld; aggressive "
                    "violations %ld; classify wrong %ld (uncertain %ld); approximate wrong %ld, outside its "
                    "bound %ld; argument-order mismatches %ld\n",
                    name.c_str(), n, exact_wrong, conservative_violations, aggressive_violations, classify_wrong, uncertain, approx_wrong,
                    approx_outside_bound, symmetry_wrong);
        std::fflush(stdout);
    }
};

// The box spanned by two corners in any order (nudged flat boxes may come out inverted).
inline incidence::aabb3 ordered(incidence::aabb3 b) {
    if (b.min.x > b.max.x) std::swap(b.min.x, b.max.x);
    if (b.min.y > b.max.y) std::swap(b.min.y, b.max.y);
    if (b.min.z > b.max.z) std::swap(b.min.z, b.max.z);
    return b;
}
inline std::string hex(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", x);
    return buf;
}
// A point's or vector's coordinates into a double[3] (the oracle's arrays).
inline void arr(incidence::point3 p, double* o) {
    o[0] = p.x;
    o[1] = p.y;
    o[2] = p.z;
}
inline void arr(incidence::vec3 p, double* o) {
    o[0] = p.x;
    o[1] = p.y;
    o[2] = p.z;
}

} // namespace support

// margin_kernel: the exact sign, plus min over deciding polynomials of |value| / permanent,
// where the permanent sums the absolute values of the monomials (differences count |a| + |b|,
// so it measures distance to the boundary relative to the coordinates' magnitude).
namespace support_margin {
// The approximate tier's stated domain: every nonzero input of magnitude in [2^-500, 2^500]
// (outside it plain double may overflow, e.g. 1/d for a subnormal d). Out-of-domain cases
// count as "at the boundary" (relative margin 0).
struct mnum {
    double v, p;
    bool in_domain;
};
constexpr mnum operator+(mnum a, mnum b) { return {a.v + b.v, a.p + b.p, a.in_domain && b.in_domain}; }
constexpr mnum operator-(mnum a, mnum b) { return {a.v - b.v, a.p + b.p, a.in_domain && b.in_domain}; }
constexpr mnum operator-(mnum a) { return {-a.v, a.p, a.in_domain}; }
constexpr mnum operator*(mnum a, mnum b) { return {a.v * b.v, a.p * b.p, a.in_domain && b.in_domain}; }
constexpr mnum abs(mnum a) { return {std::fabs(a.v), a.p, a.in_domain}; }
struct lift_margin {
    mnum operator()(double x) const {
        const double m = std::fabs(x);
        return {x, m, x == 0.0 || (m >= 0x1p-500 && m <= 0x1p500)};
    }
};
struct margin_kernel {
    double min_rel = INFINITY;
    bool valid = true;
    template <class F>
    incidence::sign sgn(F f) {
        const mnum m = f(lift_margin{});
        // Outside [2^-900, 2^900] plain double under- or overflows: outside the approximate
        // tier's stated domain, counted as "at the boundary" (relative margin 0).
        const bool in_domain = m.in_domain && m.p >= 0x1p-900 && m.p <= 0x1p900;
        const double rel = in_domain ? std::fabs(m.v) / m.p : 0.0;
        if (!(rel >= min_rel)) min_rel = rel;
        return incidence::arith::exact_sign(f, valid);
    }
    void observe_compare(double a, double b) {
        (void)sgn([=](auto L) { return L(a) - L(b); });
    }
};

} // namespace support_margin
