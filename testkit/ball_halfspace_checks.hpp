// The checks of a ball against a half-space set (convex_polyhedron_sphere, frustum_sphere,
// kdop_sphere), an oriented box (obb_sphere) or a flat shape or tetrahedron (segment_, line_,
// plane_sphere, sphere_triangle, sphere_tetrahedron) on ball_halfspace_cases.hpp's cases. Oracle:
// the exact squared distance from the centre to the set (CGAL's QP over Gmpzf,
// oracle::qp_ball_meets) against r^2, and for the flat shapes CGAL's do_intersect(Sphere_3, X) over
// Epeck besides (the two must agree); contains: the ball in every row, in rationals
// (oracle::ball_in_rows). Include after testing.hpp, check.hpp and the CGAL
// oracle header.
#pragma once
#include <cstdio>
#include <string>
#include "ball_halfspace_cases.hpp"
#include "flat_checks.hpp"

namespace support {

// Every tier against an exact oracle (truth_of(a, b): std::nullopt where it declines) on n random
// and n near-degenerate cases of gen(r, near) (std::nullopt: not finite, skipped; describe(a, b)
// names a case in a failure); the oracle may
// decline at most 1% of them (counted); both answers and tangent cases the filter leaves open
// occur.
template <class Gen, class Truth, class Describe>
void qp_oracle_run(const std::string& name, long n, double approx_bound, rng& r, Gen gen, Truth truth_of, Describe describe) {
    using namespace incidence;
    for (int near = 0; near < 2; ++near) {
        tally t{name + (near ? " near-degenerate" : " random")};
        long not_finite = 0, declined = 0, yes = 0, open = 0;
        for (long i = 0; i < n; ++i) {
            const auto c = gen(r, near != 0);
            if (!c) {
                ++not_finite;
                continue;
            }
            const auto& [a, b] = *c;
            const std::optional<bool> truth = truth_of(a, b);
            if (!truth) {
                ++declined;
                continue;
            }
            yes += *truth;
            open += classify(a, b) == certainty::uncertain;
            check_pair(t, a, b, *truth, approx_bound, [&] { return describe(a, b); });
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

// The ball against P: the exact QP, and for the flat shapes CGAL's squared distance over Epeck,
// which must agree with it.
template <class P>
void ball_halfspace_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + 29);
    long oracles_differ = 0;
    qp_oracle_run(
        name, n, approx_bound, r, [](rng& g, bool near) { return near ? ball_near<P>(g) : ball_random<P>(g); },
        [&](const P& a, const sphere3& s) {
            const auto truth = oracle::qp_ball_meets(lp(a), a3(s.center), s.radius);
            if constexpr (flat_ball_shape<P>)
                if (truth) oracles_differ += oracle::ball_flat(to_flat(a), a3(s.center), s.radius) != *truth;
            return truth;
        },
        [](const P& a, const sphere3& s) { return shape_str(a) + " " + shape_str(s); });
    std::printf("[cases] %s: the two oracles differ on %ld cases\n", name.c_str(), oracles_differ);
    CHECK(oracles_differ == 0);
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
