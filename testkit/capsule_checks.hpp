// The checks of a capsule against a shape on capsule_cases.hpp's cases. Oracle: the exact minimum of
// |x - y|^2 over the capsule's segment and the partner's core (its centre, its segment or itself),
// CGAL's QP over Gmpzf, against (r1 + r2)^2 (oracle::qp_sets_within). Include after testing.hpp,
// check.hpp and the CGAL oracle header.
#pragma once
#include <cstdio>
#include <string>
#include "capsule_cases.hpp"
#include "ball_halfspace_checks.hpp"
#include "contain_checks.hpp"
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

// contains: the capsule around a shape, a box around the capsule, the ball around a segment, a
// triangle or a tetrahedron (capsule_cases.hpp's generators and truths) through contain_checks.hpp's
// contains_oracle: n random and n holding cases.
template <class S>
void capsule_contains(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    contains_oracle<capsule3, S>(
        name + " (capsule around the other)", n, approx_bound, capsule_random_around<S>, capsule_holding<S>, false,
        [](const capsule3& c, const S& s) { return capsule_holds(c, s); },
        [](const capsule3& c, const S& s) { return shape_str(c) + " " + shape_str(s); });
}
template <class X>
void capsule_contained(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    contains_oracle<X, capsule3>(
        name + " (the other around capsule)", n, approx_bound, capsule_random_inside<X>, capsule_inside<X>, false,
        [](const X& x, const capsule3& c) { return holds_capsule(x, c); },
        [](const X& x, const capsule3& c) { return shape_str(x) + " " + shape_str(c); });
}
template <class S>
void sphere_contains(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    contains_oracle<sphere3, S>(name + " (sphere around the other)", n, approx_bound, sphere_random_around<S>, sphere_holding<S>, false,
                                nullptr, [](const sphere3& s, const S& x) { return shape_str(s) + " " + shape_str(x); });
}

} // namespace support
