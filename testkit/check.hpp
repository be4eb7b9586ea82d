// The tier-contract check shared by every oracle test. Include after testing.hpp.
#pragma once
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace support {

// Every tier contract held over the cases tallied in t.
inline void require_contracts(const tally& t) {
    CHECK(t.exact_wrong == 0);
    CHECK(t.symmetry_wrong == 0);
    CHECK(t.conservative_violations == 0);
    CHECK(t.aggressive_violations == 0);
    CHECK(t.classify_wrong == 0);
    CHECK(t.approx_outside_bound == 0);
}

// One case of a canonical pair (a, b) whose true answer is `truth` (from the oracle).
// Checks: exact == truth; both argument orders agree; conservative never misses a true yes;
// aggressive never reports a false yes; classify is never wrong; approximate is wrong only
// within its stated relative margin `bound` (measured by margin_kernel on the same body).
template <class A, class B>
void check_pair(tally& t, const A& a, const B& b, bool truth, double bound, const std::function<std::string()>& describe) {
    using namespace incidence;
    ++t.n;
    const bool e = intersects<exact>(a, b);
    if (e != truth) {
        if (++t.exact_wrong <= 5) std::printf("  exact disagrees (truth %d): %s\n", truth, describe().c_str());
    }
    if (intersects<exact>(b, a) != e || intersects<approximate>(b, a) != intersects<approximate>(a, b)) ++t.symmetry_wrong;
    if (truth && !intersects<conservative>(a, b)) {
        if (++t.conservative_violations <= 5) std::printf("  conservative misses: %s\n", describe().c_str());
    }
    if (!truth && intersects<aggressive>(a, b)) {
        if (++t.aggressive_violations <= 5) std::printf("  aggressive false yes: %s\n", describe().c_str());
    }
    const certainty c = classify(a, b);
    if (c == certainty::uncertain) ++t.uncertain;
    else if ((c == certainty::yes) != truth) ++t.classify_wrong;
    if (intersects<approximate>(a, b) != truth) {
        ++t.approx_wrong;
        support_margin::margin_kernel mk;
        if constexpr (requires { detail::intersects(mk, a, b); }) (void)detail::intersects(mk, a, b);
        else (void)detail::intersects(mk, b, a); // the pair is written in the other order
        if (mk.min_rel > bound) {
            if (++t.approx_outside_bound <= 5) std::printf("  approximate wrong at margin %g: %s\n", mk.min_rel, describe().c_str());
        }
    }
}

} // namespace support

namespace support {

inline std::string str(incidence::point3 q) { return "(" + hex(q.x) + "," + hex(q.y) + "," + hex(q.z) + ")"; }
inline std::string str(incidence::vec3 q) { return "(" + hex(q.x) + "," + hex(q.y) + "," + hex(q.z) + ")"; }

// Run n generated cases of a canonical pair against the oracle and require every contract.
// gen(rng) -> std::pair<A, B>; truth(a, b) -> bool (oracle); skip(a, b) -> bool (outside the
// oracle's preconditions); describe(a, b) -> std::string.
template <class Gen, class Truth, class Skip, class Describe>
tally run_oracle(const char* name, long n, double bound, Gen gen, Truth truth, Skip skip, Describe describe) {
    rng r(seed());
    tally t{name};
    long skipped = 0;
    for (long i = 0; i < n; ++i) {
        auto [a, b] = gen(r);
        if (skip(a, b)) {
            ++skipped;
            continue;
        }
        check_pair(t, a, b, truth(a, b), bound, [&] { return describe(a, b); });
    }
    std::printf("[cases] %s: seed %llu, %ld generated cases skipped (oracle precondition)\n", name, static_cast<unsigned long long>(seed()),
                skipped);
    t.print();
    require_contracts(t);
    return t;
}

// Checks the values of exact hits: n cases alternating the near-degenerate and the random
// generator; check(a, b) returns std::nullopt when there is no hit, else whether its values are
// right (correctly rounded against the oracle).
template <class Near, class Random, class Check, class Describe>
void run_values(const char* name, long n, std::uint64_t seed_offset, Near near, Random random, Check check, Describe describe) {
    rng r(seed() + seed_offset);
    long checked = 0, bad = 0;
    for (long i = 0; i < n; ++i) {
        auto [a, b] = (i % 2) ? near(r) : random(r);
        const std::optional<bool> ok = check(a, b);
        if (!ok) continue;
        ++checked;
        if (!*ok && ++bad <= 5) std::printf("  wrong hit values: %s\n", describe(a, b).c_str());
    }
    std::printf("[cases] %s: %ld hits checked, %ld wrong\n", name, checked, bad);
    CHECK(bad == 0);
}

// One contains(a, b) case whose true answer is `truth`: exact == truth; conservative never
// misses a true yes; aggressive never reports a false yes; classify_contains is never wrong;
// approximate is wrong only within its stated relative margin `bound`.
template <class A, class B>
void check_contains(tally& t, const A& a, const B& b, bool truth, double bound, const std::function<std::string()>& describe) {
    using namespace incidence;
    ++t.n;
    auto say = [&](const char* what, long& count) {
        if (++count <= 5) std::printf("  contains: %s: %s\n", what, describe().c_str());
    };
    if (contains<exact>(a, b) != truth)
        say(truth ? "exact disagrees (truth: contained)" : "exact disagrees (truth: not contained)", t.exact_wrong);
    if (truth && !contains<conservative>(a, b)) say("conservative misses", t.conservative_violations);
    if (!truth && contains<aggressive>(a, b)) say("aggressive false yes", t.aggressive_violations);
    const certainty c = classify_contains(a, b);
    if (c == certainty::uncertain) ++t.uncertain;
    else if ((c == certainty::yes) != truth) say("classify wrong", t.classify_wrong);
    if (contains<approximate>(a, b) != truth) {
        ++t.approx_wrong;
        support_margin::margin_kernel mk;
        (void)detail::contains(mk, a, b);
        if (mk.min_rel > bound) say("approximate wrong outside its bound", t.approx_outside_bound);
    }
}

// contains(a, b) on `n` random and `n` near-degenerate cases of gen(rng, near) (an optional pair;
// std::nullopt: declined), against truth(a, b) (std::runtime_error: the oracle declined), with
// every tier contract; both answers must occur, "contained" in at least a twentieth of them.
template <class Gen, class Truth, class Describe>
void contains_oracle_cases(const std::string& name, long n, double approx_bound, Gen gen, Truth truth_of, Describe describe) {
    rng r(seed() + 29);
    for (int near = 0; near < 2; ++near) {
        tally t{name + (near ? " contains near-degenerate" : " contains random")};
        long yes = 0, skipped = 0;
        for (long i = 0; i < n; ++i) {
            const auto c = gen(r, near == 1);
            if (!c) {
                ++skipped;
                continue;
            }
            const auto& [a, b] = *c;
            bool truth = false;
            try {
                truth = truth_of(a, b);
            } catch (const std::runtime_error&) {
                ++skipped;
                continue;
            }
            yes += truth;
            check_contains(t, a, b, truth, approx_bound, [&] { return describe(a, b); });
        }
        t.print();
        std::printf("[cases] %s: %ld contained, %ld skipped (declined or not finite)\n", t.name.c_str(), yes, skipped);
        require_contracts(t);
        CHECK(yes > t.n / 20);
        CHECK(yes < t.n);
    }
}

} // namespace support
