// sphere3 x sphere3 (balls): intersects and contains against CGAL Epeck (exact squared
// distances) on 100,000 random and 100,000 near-degenerate cases (externally and internally
// tangent balls built exactly, nudged by ulps, scaled and translated).
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/sphere_points.hpp"

namespace test_query_sphere_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("sphere_sphere"); // stated in the catalog (modules/query/catalog.cppm)
std::string describe(const sphere3& a, const sphere3& b) {
    return "ball " + support::str(a.center) + " r " + support::hex(a.radius) + " ball " + support::str(b.center) + " r " +
           support::hex(b.radius);
}
bool truth(const sphere3& a, const sphere3& b) {
    double c1[3], c2[3];
    arr(a.center, c1);
    arr(b.center, c2);
    return oracle::ball_ball(c1, a.radius, c2, b.radius);
}
bool skip(const sphere3&, const sphere3&) { return false; }
std::pair<sphere3, sphere3> near_case(support::rng& r) {
    const double C[3] = {support::small(r), support::small(r), support::small(r)};
    const auto q = support::pythagorean(r);
    const double k = r.integer(1, 4);
    const double r1 = r.integer(0, 3 * static_cast<int>(k * q.w));
    const double dist = k * q.w;
    // external tangency: r1 + r2 = dist; internal: r1 - r2 = dist
    const bool internal = r.coin();
    const double r2 = internal ? r1 + dist : dist - r1;
    support::transform tr = support::random_transform(r, true);
    const sphere3 a{{tr.apply(C[0], 0), tr.apply(C[1], 1), tr.apply(C[2], 2)}, tr.dir(r1)};
    const sphere3 b{{tr.apply(C[0] + k * q.x, 0), tr.apply(C[1] + k * q.y, 1), tr.apply(C[2] + k * q.z, 2)}, tr.dir(r2 < 0 ? -r2 : r2)};
    return {a, b};
}
std::pair<sphere3, sphere3> random_case(support::rng& r) {
    support::transform tr = support::random_transform(r, false);
    auto c = [&](int i) { return support::random_coord(r, tr, i); };
    return {sphere3{{c(0), c(1), c(2)}, tr.scale_only(r.uniform(0, 1))}, sphere3{{c(0), c(1), c(2)}, tr.scale_only(r.uniform(0, 1))}};
}
} // namespace

TEST_CASE("sphere_sphere: fixtures", "[sphere_sphere]") {
    CHECK(intersects(sphere3{{0, 0, 0}, 1}, sphere3{{2, 0, 0}, 1})); // tangent
    CHECK_FALSE(intersects(sphere3{{0, 0, 0}, 1}, sphere3{{2.000000000000001, 0, 0}, 1}));
    CHECK(contains(sphere3{{0, 0, 0}, 3}, sphere3{{1, 2, 2}, 0})); // internally tangent point
    CHECK(contains(sphere3{{0, 0, 0}, 4}, sphere3{{1, 2, 2}, 1})); // internally tangent
    CHECK_FALSE(contains(sphere3{{0, 0, 0}, 4}, sphere3{{1, 2, 2}, 1.0000000000000002}));
    CHECK(contains(sphere3{{0, 0, 0}, 1}, sphere3{{0, 0, 0}, 1})); // equal balls
    // unchecked negative radii act as |r|, as in every other pair of the ball
    CHECK(intersects(sphere3{{0, 0, 0}, -1}, sphere3{{1.5, 0, 0}, 1}));
    CHECK(contains(sphere3{{0, 0, 0}, -2}, sphere3{{0.5, 0, 0}, 1}));
    CHECK(contains(sphere3{{0, 0, 0}, 2}, sphere3{{0.5, 0, 0}, -1}));
    CHECK_FALSE(contains(sphere3{{0, 0, 0}, 1}, sphere3{{0, 0, 0}, -2}));
}
TEST_CASE("sphere_sphere: oracle, random", "[sphere_sphere][oracle]") {
    support::run_oracle("sphere_sphere random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("sphere_sphere: oracle, near-degenerate", "[sphere_sphere][oracle]") {
    support::run_oracle("sphere_sphere near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}
TEST_CASE("sphere_sphere: contains, every tier against the oracle", "[sphere_sphere][oracle]") {
    support::rng r(support::seed() + 6);
    support::tally t{"sphere_sphere contains"};
    for (long i = 0; i < support::cases(200000); ++i) {
        auto [a, b] = (i % 2) ? near_case(r) : random_case(r);
        if (r.coin()) std::swap(a, b);
        double c1[3], c2[3];
        arr(a.center, c1);
        arr(b.center, c2);
        const bool truth_ = oracle::ball_contains_ball(c1, a.radius, c2, b.radius);
        ++t.n;
        if (contains<exact>(a, b) != truth_ && ++t.exact_wrong <= 5) std::printf("  %s\n", describe(a, b).c_str());
        if (truth_ && !contains<conservative>(a, b)) ++t.conservative_violations;
        if (!truth_ && contains<aggressive>(a, b)) ++t.aggressive_violations;
        const certainty c = classify_contains(a, b);
        if (c == certainty::uncertain) ++t.uncertain;
        else if ((c == certainty::yes) != truth_) ++t.classify_wrong;
        if (contains<approximate>(a, b) != truth_) {
            ++t.approx_wrong;
            support_margin::margin_kernel mk;
            (void)detail::contains(mk, a, b);
            if (mk.min_rel > approx_bound) ++t.approx_outside_bound;
        }
    }
    t.print();
    CHECK(t.exact_wrong == 0);
    CHECK(t.conservative_violations == 0);
    CHECK(t.aggressive_violations == 0);
    CHECK(t.classify_wrong == 0);
    CHECK(t.approx_outside_bound == 0);
}

} // namespace test_query_sphere_sphere
