// Checks for the distances from a point to a solid (squared_distance, signed_distance), every tier
// against the exact values of the CGAL oracle (testkit/oracle/cgal_distance.cpp): the exact tier
// correctly rounded, the conservative and aggressive intervals containing the exact value, the
// approximate tier within its stated bound. Include after testing.hpp, the CGAL oracle header and
// the case headers of the shapes (the generators are the pairs' own: a point where a ball's centre
// or a capsule's end would be).
//
// The approximate tier's bound, stated in the distance tables' heads: |d~ - d| <= 2^-40 M + 2^-140
// for the signed distance and 2^-40 M^2 + 2^-280 for the squared one, M the largest magnitude among
// the point's and the solid's numbers (a half-space's |d_i| / max |n_i|), for inputs whose nonzero
// magnitudes lie in [2^-120, 2^120] (beyond, the quotients' numerators, of degree up to 8, leave
// double's range; the absolute term covers those that underflow where the differences of nearly
// equal inputs are tiny); a case whose point the approximate tier places on the wrong side of the
// boundary counts as an error like any other. The bound holds where no deciding sign of the query
// lies within 2^-40 of its permanent (testing.hpp's margin_kernel on the same body): there plain
// double takes the exact tier's active set or feature. Cases nearer a decision are counted apart
// (near_decision) and not held to it, as the yes/no pairs' approximate tiers are not.
#pragma once
#include <catch2/catch_test_macros.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace support {

// The numbers that size a solid: its coordinates and radius.
struct magnitudes {
    double largest = 0, smallest = INFINITY; // nonzero magnitudes
    void add(double x) {
        const double a = std::fabs(x);
        if (a == 0) return;
        largest = std::max(largest, a), smallest = std::min(smallest, a);
    }
    void add(incidence::point3 p) { add(p.x), add(p.y), add(p.z); }
    void add_row(const incidence::plane3& h) {
        const double n = std::max({std::fabs(h.normal.x), std::fabs(h.normal.y), std::fabs(h.normal.z)});
        add(h.normal.x), add(h.normal.y), add(h.normal.z);
        if (n > 0) add(h.offset / n);
    }
};
inline void add_numbers(magnitudes& m, const incidence::sphere3& s) { m.add(s.center), m.add(s.radius); }
inline void add_numbers(magnitudes& m, const incidence::capsule3& c) { m.add(c.a), m.add(c.b), m.add(c.radius); }
inline void add_numbers(magnitudes& m, const incidence::aabb3& b) { m.add(b.min), m.add(b.max); }
inline void add_numbers(magnitudes& m, const incidence::obb3& b) {
    m.add(b.center);
    for (unsigned j = 0; j < 3; ++j) m.add(incidence::point3{0, 0, 0} + b.axes[j] * b.half_extents[j]);
}
inline void add_numbers(magnitudes& m, const incidence::tetrahedron3& t) { m.add(t.a), m.add(t.b), m.add(t.c), m.add(t.d); }
inline void add_numbers(magnitudes& m, const incidence::mesh3& x) {
    for (const auto& v : x.vertices) m.add(v);
}
inline void add_numbers(magnitudes& m, const incidence::convex_polyhedron3& c) {
    for (int i = 0; i < c.count; ++i) m.add_row(c.planes[static_cast<unsigned>(i)]);
}
inline void add_numbers(magnitudes& m, const incidence::frustum3& f) {
    for (const auto& h : f.planes) m.add_row(h);
}
template <int K>
void add_numbers(magnitudes& m, const incidence::kdop<K>& b) {
    const auto rows = incidence::detail::kdop_slabs::halfspaces(b);
    for (const auto& h : rows) m.add_row(h);
}

struct distance_tally {
    std::string name;
    long cases = 0, declined = 0, not_rounded = 0, not_enclosed = 0, over_bound = 0, bounded = 0, inside = 0, printed = 0;
    long near_decision = 0, near_decision_over = 0; // in range, a deciding sign within 2^-40: not held to the bound
    double worst = 0;                               // the approximate tier's largest error over its bound's scale
    void report() const {
        std::printf("[cases] %s: %ld values (%ld inside), %ld declined by the oracle, %ld exact not correctly rounded, %ld intervals "
                    "missing the value, %ld approximate over the bound of %ld in its range (worst %.3g M; %ld more near a decision, %ld "
                    "of them over)\n",
                    name.c_str(), cases, inside, declined, not_rounded, not_enclosed, over_bound, bounded, worst, near_decision,
                    near_decision_over);
        CHECK(not_rounded == 0);
        CHECK(not_enclosed == 0);
        CHECK(over_bound == 0);
        CHECK(declined * 100 <= cases); // the oracle may decline at most 1% of the cases
    }
};

// The range where a case is held to the approximate bound: the nonzero magnitudes in
// [2^-120, 2^120] (in_range_at_all) and no deciding sign within `margin` of its permanent (clear).
struct bound_scope {
    double largest = 0;
    bool in_range_at_all = false, clear = false;
    double margin = 0x1p-40, relative = 0x1p-40; // the bound: relative M (M^2 squared) + 2^-140 (2^-280)
};
// The scope of a case of magnitudes m whose deciding signs' least relative margin is min_rel.
inline bound_scope scope_of(const magnitudes& m, double min_rel, double margin = 0x1p-40, double relative = 0x1p-40) {
    bound_scope b;
    b.margin = margin, b.relative = relative, b.largest = m.largest;
    b.clear = min_rel >= margin;
    b.in_range_at_all = m.largest <= 0x1p120 && m.smallest >= 0x1p-120;
    return b;
}

// One value in every tier (x exact, c and a the intervals, ap approximate) against the oracle's
// check k of them.
inline void tally_value(distance_tally& t, const bound_scope& b, bool squared, const oracle::distance_check& k, double x,
                        incidence::interval c, incidence::interval a, double ap, const std::string& what) {
    ++t.cases;
    if (!k.known) {
        ++t.declined;
        return;
    }
    const bool in_range = b.in_range_at_all && b.clear;
    const double scale = squared ? b.largest * b.largest : b.largest;
    const bool beyond = !(k.error <= b.relative * scale + (squared ? 0x1p-280 : 0x1p-140));
    const bool over = in_range && beyond;
    if (b.in_range_at_all && !b.clear) ++t.near_decision, t.near_decision_over += beyond;
    t.bounded += in_range;
    if (in_range && scale > 0) t.worst = std::max(t.worst, k.error / scale);
    const bool bad = !k.rounded || !k.enclosed || over;
    t.not_rounded += !k.rounded, t.not_enclosed += !k.enclosed, t.over_bound += over;
    if (bad && ++t.printed <= 5)
        std::printf("  %s %s of %s: exact %a, [%a, %a] and [%a, %a], approximate %a; oracle %a (rounded %d, enclosed %d, error %.3g)\n",
                    t.name.c_str(), squared ? "squared" : "unsquared", what.c_str(), x, c.lo, c.hi, a.lo, a.hi, ap, k.value, k.rounded,
                    k.enclosed, k.error);
}

// One case: both distances of p and s in every tier against the oracle.
template <class S>
void check_distance_case(distance_tally& t, const S& s, incidence::point3 p, const oracle::distance_solid& solid, const std::string& what) {
    using namespace incidence;
    magnitudes m;
    add_numbers(m, s);
    m.add(p);
    // the smallest relative margin among the exact path's deciding signs
    support_margin::margin_kernel mk;
    if constexpr (requires { detail::signed_distance(mk, s, p); }) (void)detail::signed_distance(mk, s, p);
    else (void)detail::signed_distance(mk, p, s);
    const bound_scope b = scope_of(m, mk.min_rel);
    for (const bool squared : {false, true}) {
        const double x = squared ? squared_distance(s, p) : signed_distance(s, p);
        const interval c = squared ? squared_distance<conservative>(s, p) : signed_distance<conservative>(s, p);
        const interval a = squared ? squared_distance<aggressive>(s, p) : signed_distance<aggressive>(s, p);
        const double ap = squared ? squared_distance<approximate>(s, p) : signed_distance<approximate>(s, p);
        const auto k = oracle::check_distance(solid, {p.x, p.y, p.z}, squared, x, std::max(c.lo, a.lo), std::min(c.hi, a.hi), ap);
        t.inside += !squared && k.known && k.sign < 0;
        tally_value(t, b, squared, k, x, c, a, ap, what + " and " + str(p));
    }
}

// One case of two points, segments, rays, lines or triangles: distance and squared_distance in
// every tier, both argument orders, against the oracle (oracle::check_flat_distance: CGAL's, or the
// exact QP). The bound's scope: margin 2^-20, relative 2^-30 (modules/query/distance/linear_pairs.cppm).
template <class A, class B>
void check_flat_distance_case(distance_tally& t, const A& a, const B& b) {
    using namespace incidence;
    magnitudes m;
    for (const auto& f : {to_flat(a), to_flat(b)}) {
        const int n = f.kind == oracle::flat::point ? 3 : f.kind == oracle::flat::triangle ? 9 : 6;
        for (int i = 0; i < n; ++i) m.add(f.v[i]);
    }
    support_margin::margin_kernel mk;
    if constexpr (requires { detail::distance(mk, a, b); }) (void)detail::distance(mk, a, b);
    else (void)detail::distance(mk, b, a);
    const bound_scope s = scope_of(m, mk.min_rel, 0x1p-20, 0x1p-30);
    for (const bool squared : {false, true}) {
        const double x = squared ? squared_distance(a, b) : distance(a, b);
        const interval c = squared ? squared_distance<conservative>(a, b) : distance<conservative>(a, b);
        const interval g = squared ? squared_distance<aggressive>(a, b) : distance<aggressive>(a, b);
        const double ap = squared ? squared_distance<approximate>(a, b) : distance<approximate>(a, b);
        // the other order gives the same values, bit for bit
        const double xr = squared ? squared_distance(b, a) : distance(b, a);
        const double apr = squared ? squared_distance<approximate>(b, a) : distance<approximate>(b, a);
        CHECK(std::memcmp(&x, &xr, sizeof x) == 0);
        CHECK(std::memcmp(&ap, &apr, sizeof ap) == 0);
        const auto k = oracle::check_flat_distance(to_flat(a), to_flat(b), squared, x, std::max(c.lo, g.lo), std::min(c.hi, g.hi), ap);
        tally_value(t, s, squared, k, x, c, g, ap, str(a) + " and " + str(b));
    }
}

// n random and n near-degenerate cases from gen(rng, near) -> optional<pair<S, point3>>.
template <class S, class Gen, class Solid, class Str>
void distance_oracle(const std::string& name, long n, std::uint64_t salt, Gen gen, Solid solid_of, Str str_of) {
    rng r(seed() + salt);
    distance_tally t{name};
    for (long i = 0; i < 2 * n; ++i) {
        const auto c = gen(r, i % 2 == 1);
        if (!c) continue;
        const auto& [s, p] = *c;
        check_distance_case(t, s, p, solid_of(s), str_of(s));
    }
    t.report();
}

} // namespace support
