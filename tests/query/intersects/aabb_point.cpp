// aabb3 x point3 and the point-box squared distances: CGAL Epeck oracle for the test, and an
// exact rational check that the exact tier's distances are correctly rounded and that the
// conservative/aggressive intervals contain the exact value.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"

namespace test_query_aabb_point { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
std::string describe(const aabb3& b, const point3& p) {
    return "box " + support::str(b.min) + support::str(b.max) + " point " + support::str(p);
}
bool truth(const aabb3& b, const point3& p) {
    double a[3], mn[3], mx[3];
    arr(p, a);
    arr(b.min, mn);
    arr(b.max, mx);
    return oracle::point_in_box(a, mn, mx);
}
bool skip(const aabb3&, const point3&) { return false; }
std::pair<aabb3, point3> near_case(support::rng& r) {
    double lo[3], hi[3], p[3];
    for (int i = 0; i < 3; ++i) {
        lo[i] = support::small(r);
        hi[i] = lo[i] + r.integer(0, 6) * 0.5;
        const int w = r.integer(0, 2);
        p[i] = w == 0 ? lo[i] : (w == 1 ? hi[i] : lo[i] - 0.5);
    }
    support::transform tr = support::random_transform(r, true);
    aabb3 b{{tr.apply(lo[0], 0), tr.apply(lo[1], 1), tr.apply(lo[2], 2)}, {tr.apply(hi[0], 0), tr.apply(hi[1], 1), tr.apply(hi[2], 2)}};
    b = support::ordered(b);
    return {b, point3{tr.apply(p[0], 0), tr.apply(p[1], 1), tr.apply(p[2], 2)}};
}
std::pair<aabb3, point3> random_case(support::rng& r) {
    support::transform tr = support::random_transform(r, false);
    auto c = [&](int i) { return support::random_coord(r, tr, i); };
    double a[3] = {c(0), c(1), c(2)}, b[3] = {c(0), c(1), c(2)};
    for (int i = 0; i < 3; ++i)
        if (a[i] > b[i]) std::swap(a[i], b[i]);
    return {aabb3{{a[0], a[1], a[2]}, {b[0], b[1], b[2]}}, point3{c(0), c(1), c(2)}};
}
} // namespace

TEST_CASE("aabb_point: fixtures", "[aabb_point]") {
    const aabb3 B{{0, 0, 0}, {1, 2, 3}};
    CHECK(intersects(B, point3{1, 2, 3}));
    CHECK(intersects(point3{0, 1, 3}, B));
    CHECK_FALSE(intersects(B, point3{1, 2, 3.0000000000000004}));
    CHECK(contains(B, point3{0.5, 0.5, 0.5}));
    CHECK(squared_distance(B, point3{2, 3, 4}) == 3.0);
    CHECK(squared_distance(B, point3{0.5, 1, 1}) == 0.0);
    CHECK(max_squared_distance(B, point3{0, 0, 0}) == 14.0);
    const interval iv = squared_distance<conservative>(B, point3{2, 3, 4});
    CHECK(iv.contains(3.0));
}
TEST_CASE("aabb_point: oracle, random", "[aabb_point][oracle]") {
    support::run_oracle("aabb_point random", support::cases(100000), 0.0, random_case, truth, skip, describe);
}
TEST_CASE("aabb_point: oracle, near-degenerate", "[aabb_point][oracle]") {
    support::run_oracle("aabb_point near-degenerate", support::cases(100000), 0.0, near_case, truth, skip, describe);
}
TEST_CASE("aabb_point: distances are correctly rounded (exact) and enclosed (intervals)", "[aabb_point][oracle]") {
    support::rng r(support::seed() + 7);
    long n = 0, bad = 0, not_enclosed = 0, approx_bad = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        auto [b, p] = (i % 2) ? near_case(r) : random_case(r);
        double a[3], mn[3], mx[3];
        arr(p, a);
        arr(b.min, mn);
        arr(b.max, mx);
        for (bool far : {false, true}) {
            ++n;
            const double e = far ? max_squared_distance(b, p) : squared_distance(b, p);
            if (!oracle::is_rounded_point_box_sqdist(a, mn, mx, far, e) && std::isfinite(e) && ++bad <= 5)
                std::printf("  not correctly rounded (%s): %s -> %a\n", far ? "max" : "min", describe(b, p).c_str(), e);
            const interval c = far ? max_squared_distance<conservative>(b, p) : squared_distance<conservative>(b, p);
            if (std::isfinite(c.hi) && !(c.lo <= e && e <= c.hi)) ++not_enclosed;
            const double ap = far ? max_squared_distance<approximate>(b, p) : squared_distance<approximate>(b, p);
            // stated bound: |approx - exact| <= gamma_4 * exact + 4 * 2^-1074 (plus the exact value's own rounding)
            const double g4 = 4 * 0x1p-53 / (1 - 4 * 0x1p-53);
            if (std::isfinite(ap) && std::fabs(ap - e) > g4 * e * (1 + 0x1p-20) + 0x1p-1070 + std::fabs(e) * 0x1p-53) ++approx_bad;
        }
    }
    std::printf(
        "[cases] aabb_point distances: %ld; exact not correctly rounded %ld; intervals not enclosing %ld; approximate outside bound %ld\n",
        n, bad, not_enclosed, approx_bad);
    CHECK(bad == 0);
    CHECK(not_enclosed == 0);
    CHECK(approx_bad == 0);
}

} // namespace test_query_aabb_point
