// Checks for the k-DOP linear pairs (tests/query/kdop_<shape>.cpp: a point, segment,
// ray or line against kdop<K>, K = 6, 14, 18, 26): the LP oracle (the k-DOP as its slabs
// lo <= d . x <= hi, exact) with every tier contract, and the same answer for rewritten partners
// and exact translations of both. Include after check.hpp, flat_checks.hpp and lp_shapes.hpp; cases in kdop_cases.hpp.
#pragma once
#include <string>
#include <type_traits>
#include <vector>
#include "kdop_cases.hpp"

namespace support {

template <int K, class B>
void kdop_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + static_cast<std::uint64_t>(K));
    for (int near = 0; near < 2; ++near) {
        tally t{name + " " + std::to_string(K) + "-dop" + (near ? " near-degenerate" : " random")};
        long skipped = 0, held = 0;
        for (long i = 0; i < n; ++i) {
            const auto c = near ? kdop_near<K, B>(r) : kdop_random<K, B>(r);
            bool ok = c.has_value();
            std::optional<bool> truth;
            if (ok) {
                ok = finite_shape(c->second);
                if (ok) truth = oracle::lp_intersect_verified(lp(c->first), lp(c->second));
            }
            if (!truth) {
                ++skipped;
                continue;
            } // overflowed, or the LP's certificate check declined
            check_pair(t, c->first, c->second, *truth, approx_bound, [&] { return shape_str(c->first) + " " + shape_str(c->second); });
            held += held_whole(c->first, c->second, *truth);
        }
        std::printf("[cases] %s: %ld generated cases skipped (not finite, or the oracle declined)\n", t.name.c_str(), skipped);
        t.print();
        require_contracts(t);
        if constexpr (std::is_same_v<B, tetrahedron3> || std::is_same_v<B, obb3>) {
            print_held_whole(t.name, held);
            if (near) CHECK(held > 0);
        }
    }
}

template <int K, class B>
void kdop_symmetries(const std::string& name, long n) {
    using namespace incidence;
    rng r(seed() + 71 + static_cast<std::uint64_t>(K));
    long checked = 0, bad = 0, yes = 0;
    for (long i = 0; i < n; ++i) {
        const auto c = (i % 2) ? kdop_near<K, B>(r) : kdop_random<K, B>(r);
        if (!c) continue;
        const auto& [a, b] = *c;
        const bool e = intersects(a, b);
        yes += e;
        auto same = [&](bool x) {
            ++checked;
            if (x != e && ++bad <= 5) std::printf("  %s differs: %s %s\n", name.c_str(), shape_str(a).c_str(), shape_str(b).c_str());
        };
        same(intersects(b, a));
        for (const auto& b2 : same_set(b)) same(intersects(a, b2));
        const vec3 v{std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)), std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20)),
                     std::ldexp(double(r.integer(-64, 64)), r.integer(-4, 20))};
        const auto at = translated(a, v);
        const auto bt = translated(b, v);
        if (at && bt) same(intersects(*at, *bt));
    }
    std::printf("[cases] %s %d-dop rewrites and exact translations: %ld checked (%ld pairs intersect), %ld differ\n", name.c_str(), K,
                checked, yes, bad);
    CHECK(bad == 0);
    CHECK(yes > 0);
}

// contains(kdop, B) for B = aabb3, segment3, triangle3 or tetrahedron3 against the LP oracle (B's vertices each in the
// k-DOP's slabs): every tier contract, on near-degenerate, random and inside cases.
template <int K, class B>
void kdop_contains_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + 37 + static_cast<std::uint64_t>(K));
    tally t{name + " " + std::to_string(K) + "-dop contains"};
    long yes = 0;
    for (long i = 0; i < 3 * n; ++i) {
        const auto c = i % 3 == 2 ? kdop_inside_case<K, B>(r) : (i % 3 ? kdop_near<K, B>(r) : kdop_random<K, B>(r));
        if (!c || !finite_shape(c->second)) continue;
        const auto& [a, b] = *c;
        if constexpr (std::is_same_v<B, aabb3>)
            if (!(b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z)) continue;
        const bool truth = contained_truth(a, b);
        yes += truth;
        check_contains(t, a, b, truth, approx_bound, [&] { return shape_str(a) + " " + shape_str(b); });
    }
    t.print();
    std::printf("[cases] %s: %ld of %ld contained\n", t.name.c_str(), yes, t.n);
    require_contracts(t);
    CHECK(yes > 0);
    CHECK(yes < t.n);
}

// The oracle test and the rewrites for every K = 6, 14, 18, 26 against one shape B
// (tests/query/kdop_<shape>.cpp, aabb_kdop.cpp): n random and n near-degenerate cases per K.
template <class B>
void kdop_oracle_every_k(const std::string& name, long n, double approx_bound) {
    kdop_oracle<6, B>(name, n, approx_bound);
    kdop_oracle<14, B>(name, n, approx_bound);
    kdop_oracle<18, B>(name, n, approx_bound);
    kdop_oracle<26, B>(name, n, approx_bound);
}
template <class B>
void kdop_symmetries_every_k(const std::string& name, long n) {
    kdop_symmetries<6, B>(name, n);
    kdop_symmetries<14, B>(name, n);
    kdop_symmetries<18, B>(name, n);
    kdop_symmetries<26, B>(name, n);
}

} // namespace support
