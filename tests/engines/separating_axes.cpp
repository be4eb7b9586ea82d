// The separating-axis engine behind the OBB pairs (modules/query/separating_axes.cppm): the
// box-box fast pass against the general path on the OBB tests' cases, both kernels; flat and
// dependent-axis configurations that need the extra axes, against the exact LP oracle.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/obb_cases.hpp"

namespace test_query_separating_axes { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
namespace sat = incidence::detail::sat;

TEST_CASE("separating_axes: the box-box fast pass agrees with the general path", "[separating_axes]") {
    support::rng r(support::seed() + 7);
    long decided = 0, bad = 0, n = 0;
    for (long i = 0; i < support::cases(20000); ++i) {
        const auto [a, b] = (i % 2) ? support::obb_case<obb3, obb3>::near(r) : support::obb_case<obb3, obb3>::random(r);
        const auto za = sat::zonotope_of(a), zb = sat::zonotope_of(b);
        arith::filter_kernel f;
        const certainty fast = sat::box_box_fast(f, za, zb);
        arith::exact_kernel e;
        const bool general = detail::intersects(e, a, b); // exact: the LP-checked answer of tests/query/obb_obb.cpp
        ++n;
        if (fast != certainty::uncertain) {
            ++decided;
            if ((fast == certainty::yes) != general) ++bad;
        }
        arith::approx_kernel k; // in the order the approximate tier takes (its rounding depends on it)
        const certainty approx = detail::obb_before(a, b) ? sat::box_box_fast(k, za, zb) : sat::box_box_fast(k, zb, za);
        if (approx != certainty::uncertain && (approx == certainty::yes) != intersects<approximate>(a, b)) ++bad;
    }
    std::printf("[cases] separating_axes fast pass: %ld cases, %ld decided by the filter pass, %ld differ\n", n, decided, bad);
    CHECK(decided > n / 4);
    CHECK(bad == 0);
}

// The box pass with the bounds from the inputs' maxima alone (sat::box_box_bounded_pass): every
// answer it gives is the exact one, at scale 1, at scales up to 2^150 and down to 2^-400 (where
// the values underflow and only the absolute term of the bound stands between them and a wrong
// sign).
TEST_CASE("separating_axes: the bounds from the inputs' maxima decide only what is true", "[separating_axes]") {
    support::rng r(support::seed() + 11);
    long n = 0, decided = 0, bad = 0, tiny_decided = 0;
    auto scaled = [](obb3 b, int k) {
        b.center = point3{std::ldexp(b.center.x, k), std::ldexp(b.center.y, k), std::ldexp(b.center.z, k)};
        for (double& h : b.half_extents) h = std::ldexp(h, k);
        return b;
    };
    for (long i = 0; i < support::cases(20000); ++i) {
        auto [a, b] = (i % 2) ? support::obb_case<obb3, obb3>::near(r, false) : support::obb_case<obb3, obb3>::random(r, false);
        const int k = i % 5 == 0 ? r.integer(-400, -300) : i % 5 == 1 ? r.integer(100, 150) : 0;
        a = scaled(a, k), b = scaled(b, k);
        const bool truth = oracle::lp_intersect(support::lp(a), support::lp(b));
        ++n;
        if (const certainty r1 = sat::box_box_bounded_pass(a, b); r1 != certainty::uncertain) {
            ++decided;
            if ((r1 == certainty::yes) != truth) ++bad;
            if (k < -299) ++tiny_decided;
        }
    }
    std::printf("[cases] separating_axes maxima bounds: %ld cases, %ld decided (%ld at 2^-400..2^-300), %ld wrong\n", n, decided,
                tiny_decided, bad);
    CHECK(bad == 0);
    CHECK(decided > n / 3);

    // The same pass with every sign taken as computed (no bound) is wrong on some near-degenerate
    // case: searched among fixed-seed cases whose signs the filter cannot all prove, and confirmed
    // by the oracle. The bounded pass leaves that case undecided or answers it right.
    support::rng q(20261126);
    long tries = 0;
    bool found = false;
    while (!found && tries < 100000) {
        ++tries;
        const auto [a, b] = support::obb_case<obb3, obb3>::near(q, false);
        const certainty r0 = sat::box_box_pass(arith::lift_filter{}, a, b, [](const auto& v, sat::box_axis_kind) {
            return v.v > 0 ? 1 : v.v < 0 ? -1 : 0;
        });
        const certainty rf =
            sat::box_box_pass(arith::lift_filter{}, a, b, [](const auto& v, sat::box_axis_kind) { return arith::proven_sign(v); });
        if (r0 == certainty::uncertain || rf != certainty::uncertain) continue;
        const bool truth = oracle::lp_intersect(support::lp(a), support::lp(b));
        if ((r0 == certainty::yes) == truth) continue;
        found = true;
        const certainty r1 = sat::box_box_bounded_pass(a, b);
        CHECK((r1 == certainty::uncertain || (r1 == certainty::yes) == truth));
    }
    std::printf("[cases] separating_axes: the pass without a bound is wrong on near-degenerate case %ld of a fixed sequence\n", tries);
    CHECK(found);
}

TEST_CASE("separating_axes: configurations that need the extra axes", "[separating_axes]") {
    const std::array<vec3, 3> I{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
    const std::array<vec3, 3> R{vec3{1, 1, 0}, vec3{-1, 1, 0}, vec3{0, 0, 1}};
    const std::array<vec3, 3> dependent{vec3{1, 0, 0}, vec3{1, 0, 0}, vec3{0, 1, 0}}; // a flat parallelepiped
    const obb3 cases[][2] = {
        {obb3{{0, 0, 0}, I, {1, 1, 0}}, obb3{{3, 0, 0}, R, {0.75, 0.75, 0}}},        // coplanar rectangles, apart
        {obb3{{0, 0, 0}, I, {1, 1, 0}}, obb3{{2.5, 0, 0}, R, {0.75, 0.75, 0}}},      // coplanar rectangles, touching
        {obb3{{0, 0, 0}, I, {1, 0, 0}}, obb3{{3, 0, 0}, I, {1, 0, 0}}},              // collinear segments, apart
        {obb3{{0, 0, 0}, I, {1, 0, 0}}, obb3{{2, 0, 0}, I, {1, 0, 0}}},              // collinear segments, touching
        {obb3{{0, 0, 0}, I, {1, 0, 0}}, obb3{{0, 1, 0}, I, {1, 0, 0}}},              // parallel segments
        {obb3{{0, 0, 0}, I, {0, 0, 0}}, obb3{{0, 0, 1e-300}, I, {0, 0, 0}}},         // two points
        {obb3{{0, 0, 0}, dependent, {1, 1, 1}}, obb3{{0, 0, 0.5}, I, {1, 1, 0.25}}}, // dependent axes
        {obb3{{0, 0, 0}, dependent, {1, 1, 1}}, obb3{{0, 3, 0}, I, {1, 1, 1}}},
    };
    for (const auto& c : cases) {
        const bool truth = oracle::lp_intersect(support::lp(c[0]), support::lp(c[1]));
        CHECK(intersects(c[0], c[1]) == truth);
        CHECK(intersects(c[1], c[0]) == truth);
        CHECK(intersects(c[0], c[1].center) == oracle::lp_intersect(support::lp(c[0]), support::lp(c[1].center)));
    }
}

} // namespace test_query_separating_axes
