// The capsule pairs' fast path (modules/engines/certificate.cppm): a verdict it gives in any kernel
// is the exact QP's answer (CGAL's QP_solver over Gmpzf, testkit/capsule_checks.hpp's oracle) on
// the capsule tests' random and near-degenerate cases; the filter settles most random cases, and
// a tangent contact (no room between the guess and the truth) is left open, never answered.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"

namespace test_engines_certificate { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
namespace cert = incidence::detail::certificate;

template <class K, class B>
cert::verdict verdict_of(K& k, const capsule3& c, const B& b) {
    const double r = c.radius < 0 ? -c.radius : c.radius;
    if constexpr (std::is_same_v<B, aabb3>) return cert::segment_box(k, c.a, c.b, b, r);
    else if constexpr (std::is_same_v<B, obb3>) return cert::segment_obb(k, c.a, c.b, b, r);
    else return cert::segment_segment(k, c.a, c.b, b.a, b.b, detail::ball_flat::radii{r, b.radius < 0 ? -b.radius : b.radius});
}

template <class B>
void run(const char* name) {
    support::rng r(support::seed() + 53);
    long n = 0, declined = 0, filter_settled = 0, exact_settled = 0, wrong = 0, approx_settled = 0, approx_wrong = 0;
    for (long i = 0; i < support::cases(4000); ++i) {
        const bool near = i % 2 == 1;
        const auto p = near ? support::capsule_near<B>(r) : support::capsule_random<B>(r);
        if (!p) continue;
        const auto& [c, b] = *p;
        const auto [core, rb] = support::core_of(b);
        const std::optional<bool> known = oracle::qp_sets_within(support::lp(segment3{c.a, c.b}), core, c.radius, rb);
        if (!known) { // the QP declined (its solver reported an error)
            ++declined;
            continue;
        }
        const bool truth = *known;
        ++n;
        auto settles = [&](cert::verdict v, long& settled) {
            if (v == cert::verdict::open) return true;
            if (!near) ++settled;
            return (v == cert::verdict::meets) == truth;
        };
        arith::filter_kernel f;
        if (!settles(verdict_of(f, c, b), filter_settled)) {
            ++wrong;
            UNSCOPED_INFO(support::shape_str(c) + " " + support::shape_str(b));
        }
        CHECK(!f.failed()); // the fast path never fails a filter pass
        arith::exact_kernel e;
        if (!settles(verdict_of(e, c, b), exact_settled)) ++wrong;
        arith::approx_kernel a; // plain double: right wherever its signs are (the pair's bound)
        support_margin::margin_kernel m;
        (void)verdict_of(m, c, b);
        if (!settles(verdict_of(a, c, b), approx_settled) && m.min_rel > 0x1p-40) ++approx_wrong;
    }
    std::printf("[cases] certificate %s: %ld cases, random settled by the filter %ld, by exact signs %ld, by plain double %ld; "
                "wrong %ld, plain double wrong away from a tie %ld; %ld declined by the QP\n",
                name, n, filter_settled, exact_settled, approx_settled, wrong, approx_wrong, declined);
    CHECK(wrong == 0);
    CHECK(approx_wrong == 0);
    CHECK(declined * 100 <= n);    // at most 1% declined
    CHECK(filter_settled > n / 4); // a fast path: most random cases (half the cases) settled
}

TEST_CASE("certificate: a capsule against a capsule, a box, an oriented box: every verdict is the QP's", "[certificate][oracle]") {
    run<capsule3>("capsule_capsule");
    run<aabb3>("aabb_capsule");
    run<obb3>("capsule_obb");
}

TEST_CASE("certificate: tangent contacts are left open", "[certificate]") {
    // the capsule's surface through the box's edge (x, y) = (4, 4) at distance 5 (3-4-5), exactly
    const aabb3 box{{0, 0, 0}, {4, 4, 4}};
    const capsule3 c{{7, 8, -10}, {7, 8, 10}, 5};
    arith::filter_kernel f;
    CHECK(cert::segment_box(f, c.a, c.b, box, c.radius) == cert::verdict::open);
    arith::exact_kernel e;
    CHECK(cert::segment_box(e, c.a, c.b, box, c.radius) == cert::verdict::open);
    CHECK(intersects(box, c));
    CHECK_FALSE(intersects(box, capsule3{c.a, c.b, 0x1.3ffffffffffffp+2}));
    // two skew segments 5 apart with radii 2 and 3
    const capsule3 s{{0, 0, 0}, {10, 0, 0}, 2}, t{{5, -5, 5}, {5, 5, 5}, 3};
    CHECK(cert::segment_segment(f, s.a, s.b, t.a, t.b, detail::ball_flat::radii{2, 3}) == cert::verdict::open);
    CHECK(cert::segment_segment(f, s.a, s.b, t.a, t.b, detail::ball_flat::radii{2, 4}) == cert::verdict::meets);
    CHECK(cert::segment_segment(f, s.a, s.b, t.a, t.b, detail::ball_flat::radii{2, 2}) == cert::verdict::apart);
    // non-finite guesses (segments spanning 2^1023 and more) are left open, not answered
    const double big = 0x1.fffffffffffffp+1023;
    CHECK(cert::segment_segment(f, point3{-big, 0, 0}, point3{big, 0, 0}, point3{0, 1, 0}, point3{0, 2, 0}, 0.5) == cert::verdict::open);
}

} // namespace test_engines_certificate
