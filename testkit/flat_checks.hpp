// The checks every flat pair's test runs (tests/query/<pair>.cpp for the pairs among points,
// lines, rays, segments, planes and triangles): the CGAL Epeck oracle with every tier contract,
// and the same answer for rewritten shapes and exact translations. Include after check.hpp.
#pragma once
#include <string>
#include "flat_cases.hpp"

namespace support {

// --- descriptions ----------------------------------------------------------------------------
inline std::string shape_str(const incidence::point3& p) { return "point " + str(p); }
inline std::string shape_str(const incidence::segment3& s) { return "segment " + str(s.a) + str(s.b); }
inline std::string shape_str(const incidence::ray3& r) { return "ray " + str(r.origin) + str(r.direction); }
inline std::string shape_str(const incidence::line3& l) { return "line " + str(l.origin) + str(l.direction); }
inline std::string shape_str(const incidence::plane3& p) { return "plane " + str(p.normal) + " " + hex(p.offset); }
inline std::string str(incidence::point2 q) { return "(" + hex(q.x) + "," + hex(q.y) + ")"; }
inline std::string str(incidence::vec2 q) { return "(" + hex(q.x) + "," + hex(q.y) + ")"; }
inline std::string shape_str(const incidence::point2& p) { return "point2 " + str(p); }
inline std::string shape_str(const incidence::segment2& s) { return "segment2 " + str(s.a) + str(s.b); }
inline std::string shape_str(const incidence::ray2& r) { return "ray2 " + str(r.origin) + str(r.direction); }
inline std::string shape_str(const incidence::line2& l) { return "line2 " + str(l.origin) + str(l.direction); }
inline std::string shape_str(const incidence::triangle3& t) { return "triangle " + str(t.a) + str(t.b) + str(t.c); }
inline std::string shape_str(const incidence::tetrahedron3& t) { return "tetrahedron " + str(t.a) + str(t.b) + str(t.c) + str(t.d); }
inline std::string shape_str(const incidence::aabb3& b) { return "aabb " + str(b.min) + str(b.max); }
inline std::string shape_str(const incidence::obb3& b) {
    return "obb c" + str(b.center) + " a" + str(b.axes[0]) + str(b.axes[1]) + str(b.axes[2]) + " h(" + hex(b.half_extents[0]) + "," +
           hex(b.half_extents[1]) + "," + hex(b.half_extents[2]) + ")";
}

// --- the checks every flat pair runs ---------------------------------------------------------
// The oracle on `n` random and `n` near-degenerate cases, with every tier contract.
template <class A, class B>
void flat_oracle(const std::string& name, long n, double approx_bound) {
    auto describe = [](const A& a, const B& b) { return shape_str(a) + " " + shape_str(b); };
    // an offset n . x that overflowed (random shapes far out at 2^500): outside the oracle's domain
    auto skip = [](const A& a, const B& b) {
        const auto fa = to_flat(a), fb = to_flat(b);
        for (double x : fa.v)
            if (!std::isfinite(x)) return true;
        for (double x : fb.v)
            if (!std::isfinite(x)) return true;
        return false;
    };
    auto truth = [](const A& a, const B& b) { return flat_truth(a, b); };
    run_oracle((name + " random").c_str(), n, approx_bound, [](rng& r) { return flat_random<A, B>(r); }, truth, skip, describe);
    run_oracle((name + " near-degenerate").c_str(), n, approx_bound, [](rng& r) { return flat_near<A, B>(r); }, truth, skip, describe);
}

// contains(a, b) against the oracle (every vertex of b in a) on `n` random, `n` near-degenerate
// and `n` inside cases (inside_case: b's vertices inside a, on its boundary or just outside), with every tier contract; the approximate tier's misses must lie within `approx_bound`.
template <class A, class B>
void flat_contains_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + 31);
    tally t{name + " contains"};
    long yes = 0;
    for (long i = 0; i < 3 * n; ++i) {
        const auto [a, b] = i % 3 == 2 ? inside_case<A, B>(r) : (i % 3 ? flat_near<A, B>(r) : flat_random<A, B>(r));
        const bool truth = flat_contains_truth(a, b);
        yes += truth;
        check_contains(t, a, b, truth, approx_bound, [&] { return shape_str(a) + " " + shape_str(b); });
    }
    t.print();
    std::printf("[cases] %s contains: %ld of %ld contained\n", name.c_str(), yes, t.n);
    require_contracts(t);
    CHECK(yes > 0);
}

// The same answer for every rewrite of either shape and for exact translations of both.
template <class A, class B>
void flat_symmetries(const std::string& name, long n) {
    using namespace incidence;
    rng r(seed() + 71);
    long checked = 0, bad = 0, yes = 0;
    for (long i = 0; i < n; ++i) {
        const auto [a, b] = (i % 2) ? flat_near<A, B>(r) : flat_random<A, B>(r);
        const bool e = intersects(a, b);
        yes += e;
        auto same = [&](bool x) {
            ++checked;
            if (x != e && ++bad <= 5) std::printf("  %s differs: %s %s\n", name.c_str(), shape_str(a).c_str(), shape_str(b).c_str());
        };
        for (const auto& a2 : same_set(a)) same(intersects(a2, b));
        for (const auto& b2 : same_set(b)) same(intersects(a, b2));
        const vec3 v{std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)), std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)),
                     std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20))};
        const auto at = translated(a, v);
        const auto bt = translated(b, v);
        if (at && bt) same(intersects(*at, *bt));
    }
    std::printf("[cases] %s rewrites and exact translations: %ld checked (%ld pairs intersect), %ld differ\n", name.c_str(), checked, yes,
                bad);
    CHECK(bad == 0);
    CHECK(yes > 0);
}

} // namespace support
