// The oracle and rewriting checks shared by the OBB pairs' tests. Include after check.hpp and
// obb_cases.hpp.
#pragma once
#include <string>
#include <vector>
#include "flat_checks.hpp"

namespace support {
inline std::string str(const incidence::obb3& b) { return shape_str(b); }
inline std::string str(const incidence::aabb3& b) { return "aabb " + str(b.min) + str(b.max); }
inline std::string str(const incidence::segment3& s) { return "segment " + str(s.a) + str(s.b); }
inline std::string str(const incidence::ray3& s) { return "ray " + str(s.origin) + str(s.direction); }
inline std::string str(const incidence::line3& s) { return "line " + str(s.origin) + str(s.direction); }
inline std::string str(const incidence::triangle3& t) { return "triangle " + str(t.a) + str(t.b) + str(t.c); }
inline std::string str(const incidence::tetrahedron3& t) { return "tetrahedron " + str(t.a) + str(t.b) + str(t.c) + str(t.d); }
inline std::string str(const incidence::plane3& p) { return "plane " + str(p.normal) + " " + hex(p.offset); }

// The oracle test of an OBB pair: `random` and `near` cases against the LP oracle, every tier's
// contract, then the same answers for the box rewritten (negated or rotated axes) and for the
// partner rewritten by `partner_variants(b)` (reversed segments, rotated triangles, ...).
template <class A, class B, class Near, class Random>
void run_obb_pair(const char* name, long n, double approx_bound, Near near, Random random) {
    auto truth = [](const A& a, const B& b) { return oracle::lp_intersect(lp(a), lp(b)); };
    auto skip = [](const A&, const B&) { return false; };
    auto describe = [](const A& a, const B& b) { return str(a) + " " + str(b); };
    const std::string r = std::string(name) + " random", d = std::string(name) + " near-degenerate";
    run_oracle(r.c_str(), n, approx_bound, random, truth, skip, describe);
    run_oracle(d.c_str(), n, approx_bound, near, truth, skip, describe);
}
template <class A, class B, class Near, class Random, class Variants>
void run_rewritten(const char* name, long n, Near near, Random random, Variants variants) {
    rng r(seed() + 97);
    long checked = 0, bad = 0;
    for (long i = 0; i < n; ++i) {
        const auto [a, b] = (i % 2) ? near(r) : random(r);
        const bool e = incidence::intersects(a, b);
        for (const auto& [a2, b2] : variants(a, b, r)) {
            ++checked;
            if (incidence::intersects(a2, b2) != e && ++bad <= 5)
                std::printf("  rewritten differs: %s %s\n", str(a).c_str(), str(b).c_str());
        }
    }
    std::printf("[cases] %s rewritten: %ld variants, %ld differ\n", name, checked, bad);
    CHECK(bad == 0);
}
} // namespace support
