// The checks of the half-space pairs (convex_polyhedron3 and frustum3 against a point, segment,
// ray or line): the exact LP oracle on random and near-degenerate cases, rewrites and exact
// translations, and contains. Include after polyhedron_cases.hpp and check.hpp.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace support {

// n random and n near-degenerate cases of P against B, each against the exact LP.
template <class P, class B>
void halfspace_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + (std::is_same_v<P, frustum3> ? 17u : 0u));
    for (int near = 0; near < 2; ++near) {
        tally t{name + (near ? " near-degenerate" : " random")};
        long skipped = 0, yes = 0, held = 0;
        for (long i = 0; i < n; ++i) {
            const auto c = near ? halfspace_near<P, B>(r) : halfspace_random<P, B>(r);
            std::optional<bool> truth;
            if (c && finite_shape(c->second)) truth = oracle::lp_intersect_verified(lp(c->first), lp(c->second));
            if (!truth) {
                ++skipped;
                continue;
            } // overflowed, or the LP's certificate check declined
            yes += *truth;
            check_pair(t, c->first, c->second, *truth, approx_bound, [&] { return shape_str(c->first) + " " + shape_str(c->second); });
            held += held_whole(c->first, c->second, *truth);
        }
        std::printf("[cases] %s: %ld of %ld meet; %ld generated cases skipped (not finite, or the oracle declined)\n", t.name.c_str(), yes,
                    t.n, skipped);
        t.print();
        require_contracts(t);
        CHECK(yes > 0);
        CHECK(yes < t.n);
        if constexpr (std::is_same_v<B, tetrahedron3> || std::is_same_v<B, obb3>) {
            print_held_whole(t.name, held);
            if (near) CHECK(held > 0);
        }
    }
}

// The same answer for the other argument order, the same sets written differently (both shapes)
// and exact translations of both.
template <class P, class B>
void halfspace_symmetries(const std::string& name, long n) {
    using namespace incidence;
    rng r(seed() + 71 + (std::is_same_v<P, frustum3> ? 17u : 0u));
    long checked = 0, bad = 0, yes = 0;
    for (long i = 0; i < n; ++i) {
        const auto c = (i % 2) ? halfspace_near<P, B>(r) : halfspace_random<P, B>(r);
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
        for (const auto& a2 : same_set(a)) same(intersects(a2, b));
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

// contains(P, B) for B = point3, segment3, triangle3, tetrahedron3 or aabb3 against the LP (each vertex in the half-spaces), on
// near-degenerate, random and inside cases: n of each.
template <class P, class B>
void halfspace_contains_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + 37 + (std::is_same_v<P, frustum3> ? 17u : 0u));
    tally t{name + " contains"};
    long yes = 0;
    for (long i = 0; i < 3 * n; ++i) {
        std::optional<std::pair<P, B>> c;
        if (i % 3 == 2) {
            if constexpr (std::is_same_v<B, triangle3> || std::is_same_v<B, tetrahedron3>) c = halfspace_inside_case<P, B>(r);
            else if (const auto s = halfspace_inside_case<P>(r)) {
                if constexpr (std::is_same_v<B, segment3>) c = s;
                else if constexpr (std::is_same_v<B, aabb3>) c = std::pair{s->first, ordered(aabb3{s->second.a, s->second.b})};
                else if constexpr (std::is_same_v<B, obb3>) c = std::pair{s->first, obb_between(r, s->second)};
                else c = std::pair{s->first, s->second.b};
            }
        } else c = i % 3 ? halfspace_near<P, B>(r) : halfspace_random<P, B>(r);
        if (!c || !finite_shape(c->second)) continue;
        const auto& [a, b] = *c;
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

} // namespace support
