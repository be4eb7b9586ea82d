// The checks every 3D polygon pair's test runs (tests/query/<pair>.cpp with polygon3): the
// triangulation oracle with every tier contract, and the same answer for rewritten shapes and
// exact translations. Include after check.hpp, flat_checks.hpp, mesh_checks.hpp and
// polygon3_cases.hpp.
#pragma once
#include <cstdio>
#include <string>
#include <type_traits>

namespace support {

inline std::string shape_str(const incidence::polygon3& g) {
    std::string s = "polygon3 " + std::to_string(g.vertices.size()) + " vertices";
    for (const auto& p : g.vertices) s += " " + str(p);
    s += ", ring ends";
    for (auto e : g.ring_ends) s += " " + std::to_string(e);
    return s + ", axis " + std::to_string(g.axis);
}

template <class B>
std::string partner_str(const B& b) {
    if constexpr (std::is_same_v<B, incidence::plane3>) return "plane " + str(b.normal) + " " + hex(b.offset);
    else return shape_str(b);
}

// n random and n near-degenerate cases of the polygon against B, each against the oracle, with
// every tier contract (both argument orders).
template <class B>
void polygon3_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + 53);
    for (int near = 0; near < 2; ++near) {
        tally t{name + (near ? " near-degenerate" : " random")};
        long skipped = 0, yes = 0;
        for (long i = 0; i < n; ++i) {
            polygon3_store store, other;
            mesh_store mesh;
            const auto b = near ? polygon3_near<B>(r, store, other, mesh) : polygon3_random<B>(r, store, other, mesh);
            if (!b || !finite_partner(*b)) {
                ++skipped;
                continue;
            }
            const bool truth = polygon3_truth(store.g, *b);
            yes += truth;
            auto describe = [&] { return shape_str(store.g) + " " + partner_str(*b); };
            if constexpr (canonical_pair<polygon3, B>) check_pair(t, store.g, *b, truth, approx_bound, describe);
            else check_pair(t, *b, store.g, truth, approx_bound, describe);
        }
        std::printf("[cases] %s: %ld of %ld meet; %ld generated cases skipped (a shape not made or not finite)\n", t.name.c_str(), yes, t.n,
                    skipped);
        t.print();
        require_contracts(t);
        CHECK(yes > 0);
        CHECK(yes < t.n);
    }
}

// The same answer for the polygon rewritten (each ring starting at its next vertex; every ring
// reversed), the partner rewritten (same_set), and both translated exactly.
template <class B>
void polygon3_symmetries(const std::string& name, long n) {
    using namespace incidence;
    rng r(seed() + 59);
    long checked = 0, bad = 0, yes = 0;
    for (long i = 0; i < n; ++i) {
        polygon3_store store, other;
        mesh_store mesh;
        const auto b = (i % 2) ? polygon3_near<B>(r, store, other, mesh) : polygon3_random<B>(r, store, other, mesh);
        if (!b || !finite_partner(*b)) continue;
        const bool e = intersects(store.g, *b);
        yes += e;
        auto same = [&](bool x) {
            ++checked;
            if (x != e && ++bad <= 5)
                std::printf("  %s differs: %s %s\n", name.c_str(), shape_str(store.g).c_str(), partner_str(*b).c_str());
        };
        for (int how = 0; how < 2; ++how) { // rotated rings, reversed rings
            polygon3_store w;
            w.ends = store.ends;
            for (std::size_t k = 0; k < store.g.rings(); ++k) {
                const std::size_t lo = store.g.ring_begin(k), hi = store.g.ring_end(k);
                for (std::size_t j = lo; j < hi; ++j)
                    w.v.push_back(how == 0 ? store.v[j + 1 == hi ? lo : j + 1] : store.v[hi - 1 - (j - lo)]);
            }
            if (w.finish()) same(intersects(w.g, *b));
        }
        if constexpr (!std::is_same_v<B, polygon3> && !std::is_same_v<B, mesh3>)
            for (const auto& b2 : same_set(*b)) same(intersects(store.g, b2));
        const vec3 v{std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)), std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)),
                     std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20))};
        polygon3_store moved_store;
        moved_store.ends = store.ends;
        bool exact = true;
        for (const auto& p : store.v) {
            const auto q = shifted(p, v);
            if (!q) {
                exact = false;
                break;
            }
            moved_store.v.push_back(*q);
        }
        if constexpr (!std::is_same_v<B, polygon3> && !std::is_same_v<B, mesh3>) {
            const auto bt = translated(*b, v);
            if (exact && bt && moved_store.finish()) same(intersects(moved_store.g, *bt));
        }
    }
    std::printf("[cases] %s rewrites and exact translations: %ld checked (%ld pairs intersect), %ld differ\n", name.c_str(), checked, yes,
                bad);
    CHECK(bad == 0);
    CHECK(yes > 0);
}

} // namespace support
