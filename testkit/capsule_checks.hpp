// The checks of a capsule against a shape on capsule_cases.hpp's cases. Oracle: the exact minimum of
// |x - y|^2 over the capsule's segment and the partner's core (its centre, its segment or itself),
// CGAL's QP over Gmpzf, against (r1 + r2)^2 (oracle::qp_sets_within). Include after testing.hpp,
// check.hpp and the CGAL oracle header.
#pragma once
#include <cstdio>
#include <string>
#include "capsule_cases.hpp"
#include "ball_halfspace_checks.hpp"
#include "flat_checks.hpp"

namespace support {

// Every tier against the exact QP between the cores (ball_halfspace_checks.hpp's qp_oracle_run).
template <class B>
void capsule_oracle(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    rng r(seed() + 37);
    qp_oracle_run(
        name, n, approx_bound, r, [](rng& g, bool near) { return near ? capsule_near<B>(g) : capsule_random<B>(g); },
        [](const capsule3& a, const B& b) {
            const auto [core, rb] = core_of(b);
            return oracle::qp_sets_within(lp(segment3{a.a, a.b}), core, a.radius, rb);
        },
        [](const capsule3& a, const B& b) { return shape_str(a) + " " + shape_str(b); });
}

} // namespace support
