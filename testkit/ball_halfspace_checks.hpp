// The checks of a ball against a half-space set (convex_polyhedron_sphere, frustum_sphere,
// kdop_sphere) on ball_halfspace_cases.hpp's cases. Oracle: the exact squared distance from the
// centre to the set (CGAL's QP over Gmpzf, oracle::qp_ball_meets) against r^2; contains: the ball in
// every row, in rationals (oracle::ball_in_rows). Include after testing.hpp, check.hpp and the CGAL
// oracle header.
#pragma once
#include <cstdio>
#include <string>
#include "ball_halfspace_cases.hpp"

namespace support {

// Every tier against the exact QP on n random and n near-degenerate cases; the oracle may decline
// at most 1% of them (counted); both answers and tangent cases the filter leaves open occur.
template <class P>
void ball_halfspace_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + 29);
    for (int near = 0; near < 2; ++near) {
        tally t{name + (near ? " near-degenerate" : " random")};
        long not_finite = 0, declined = 0, yes = 0, open = 0;
        for (long i = 0; i < n; ++i) {
            const auto c = near ? ball_near<P>(r) : ball_random<P>(r);
            if (!c) {
                ++not_finite;
                continue;
            }
            const auto& [a, s] = *c;
            const auto truth = oracle::qp_ball_meets(lp(a), a3(s.center), s.radius);
            if (!truth) {
                ++declined;
                continue;
            }
            yes += *truth;
            open += classify(a, s) == certainty::uncertain;
            check_pair(t, a, s, *truth, approx_bound, [&] { return shape_str(a) + " " + shape_str(s); });
        }
        std::printf("[cases] %s: %ld of %ld meet, %ld left open by the filter; skipped: %ld not finite, %ld declined by the oracle\n",
                    t.name.c_str(), yes, t.n, open, not_finite, declined);
        t.print();
        require_contracts(t);
        CHECK(yes > 0);
        CHECK(yes < t.n);
        CHECK(declined * 100 <= n);
        if (near) CHECK(open > 0);
    }
}

// contains(P, ball) against the rows in rationals, on the same cases.
template <class P>
void ball_halfspace_contains(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + 31);
    tally t{name + " contains"};
    long yes = 0;
    for (long i = 0; i < 2 * n; ++i) {
        const auto c = i % 2 ? ball_near<P>(r) : ball_random<P>(r);
        if (!c) continue;
        const auto& [a, s] = *c;
        const bool truth = oracle::ball_in_rows(lp(a), a3(s.center), s.radius);
        yes += truth;
        check_contains(t, a, s, truth, approx_bound, [&] { return shape_str(a) + " " + shape_str(s); });
    }
    t.print();
    std::printf("[cases] %s: %ld of %ld contained\n", t.name.c_str(), yes, t.n);
    require_contracts(t);
    CHECK(yes > 0);
    CHECK(yes < t.n);
}

} // namespace support
