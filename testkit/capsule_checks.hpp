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
        name + " (the other around capsule)", n, approx_bound, capsule_random_in<X>, capsule_inside<X>, false,
        [](const X& x, const capsule3& c) { return holds_capsule(x, c); },
        [](const X& x, const capsule3& c) { return shape_str(x) + " " + shape_str(c); });
}
// The fixtures of a capsule against x, the box [0, 10]^3 as a half-space set (capsule_frustum,
// capsule_kdop, capsule_convex_polyhedron): a capsule parallel above a face, along an edge, its
// middle nearest an edge and nearest a corner (Pythagorean), a ball at a corner, each touching and
// one ulp short, one inside, a NaN radius; then contains: a capsule touching two faces from
// inside and one ulp too wide, a ball touching all six faces, an end outside.
template <class X>
void capsule_box_set_fixtures(const X& x) {
    using namespace incidence;
    CHECK(intersects(capsule3{{-5, 5, 13}, {15, 5, 13}, 3}, x)); // parallel above the top face
    CHECK_FALSE(intersects(capsule3{{-5, 5, 13}, {15, 5, 13}, 0x1.7ffffffffffffp1}, x));
    CHECK(intersects(x, capsule3{{-5, 13, 14}, {15, 13, 14}, 5})); // along the edge y = z = 10: 3-4-5
    CHECK_FALSE(intersects(x, capsule3{{-5, 13, 14}, {15, 13, 14}, 0x1.3ffffffffffffp2}));
    CHECK(intersects(capsule3{{5, 5, 20}, {21, 5, 8}, 5}, x)); // its middle nearest the edge x = z = 10: (3, 0, 4) away
    CHECK_FALSE(intersects(capsule3{{5, 5, 20}, {21, 5, 8}, 0x1.3ffffffffffffp2}, x));
    CHECK(intersects(x, capsule3{{9, 13, 12}, {13, 11, 12}, 3})); // its middle nearest the corner (10, 10, 10): (1, 2, 2) away
    CHECK_FALSE(intersects(x, capsule3{{9, 13, 12}, {13, 11, 12}, 0x1.7ffffffffffffp1}));
    CHECK(intersects(capsule3{{12, 12, 11}, {12, 12, 11}, 3}, x)); // a ball at the corner (10, 10, 10): 2-2-1
    CHECK_FALSE(intersects(capsule3{{12, 12, 11}, {12, 12, 11}, 0x1.7ffffffffffffp1}, x));
    CHECK(intersects(capsule3{{1, 1, 1}, {2, 2, 2}, 0}, x)); // inside
    CHECK_FALSE(intersects(capsule3{{1, 1, 1}, {2, 2, 2}, __builtin_nan("")}, x));
    CHECK(contains(x, capsule3{{3, 5, 5}, {7, 5, 5}, 3})); // touching x = 0 and x = 10 from inside
    CHECK_FALSE(contains(x, capsule3{{3, 5, 5}, {7, 5, 5}, 0x1.8000000000001p1}));
    CHECK(contains(x, capsule3{{5, 5, 5}, {5, 5, 5}, 5}));        // a ball touching all six faces
    CHECK_FALSE(contains(x, capsule3{{5, 5, 5}, {11, 5, 5}, 1})); // an end outside
}

template <class S>
void sphere_contains(const std::string& name, long n, double approx_bound) {
    using namespace incidence;
    contains_oracle<sphere3, S>(name + " (sphere around the other)", n, approx_bound, sphere_random_around<S>, sphere_holding<S>, false,
                                nullptr, [](const sphere3& s, const S& x) { return shape_str(s) + " " + shape_str(x); });
}

} // namespace support
