// orient2d, orient3d, incircle, insphere: fixtures with Shewchuk's conventions, and CGAL Epeck
// on random and near-degenerate inputs (coplanar / cocircular / cospherical constructions nudged
// by ulps, scaled by 2^-500..2^500 and translated), including the subnormal range where a
// classic adaptive filter's bound underflows.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/sphere_points.hpp"

namespace test_predicates_orient { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
int s(sign x) { return static_cast<int>(x); }

struct pred_tally {
    const char* name;
    long n = 0, wrong = 0, approx_wrong = 0;
    void report() const {
        std::printf("[cases] %s: %ld cases; exact disagreements %ld; approximate (plain double) wrong %ld\n", name, n, wrong, approx_wrong);
        CHECK(wrong == 0);
    }
};

point3 gen_point(support::transform& tr, const double* base) { return {tr.apply(base[0], 0), tr.apply(base[1], 1), tr.apply(base[2], 2)}; }
} // namespace

TEST_CASE("predicates: fixtures with Shewchuk's sign conventions", "[predicates]") {
    CHECK(orient2d(point2{0, 0}, point2{1, 0}, point2{0, 1}) == sign::positive); // counterclockwise
    CHECK(orient2d(point2{0, 0}, point2{0, 1}, point2{1, 0}) == sign::negative);
    CHECK(orient2d(point2{0, 0}, point2{1, 1}, point2{2, 2}) == sign::zero);
    // d below the plane of a, b, c (ccw seen from above): positive
    CHECK(orient3d(point3{0, 0, 0}, point3{1, 0, 0}, point3{0, 1, 0}, point3{0, 0, -1}) == sign::positive);
    CHECK(orient3d(point3{0, 0, 0}, point3{1, 0, 0}, point3{0, 1, 0}, point3{0, 0, 1}) == sign::negative);
    CHECK(orient3d(point3{0, 0, 0}, point3{1, 0, 0}, point3{0, 1, 0}, point3{5, 7, 0}) == sign::zero);
    CHECK(incircle(point2{0, 0}, point2{1, 0}, point2{0, 1}, point2{0.5, 0.5}) == sign::positive);
    CHECK(incircle(point2{0, 0}, point2{1, 0}, point2{0, 1}, point2{1, 1}) == sign::zero);
    CHECK(incircle(point2{0, 0}, point2{1, 0}, point2{0, 1}, point2{2, 2}) == sign::negative);
    const point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, -1}; // orient3d(a,b,c,d) > 0
    CHECK(insphere(a, b, c, d, point3{0.1, 0.1, -0.1}) == sign::positive);
    CHECK(insphere(a, b, c, d, point3{1, 1, 0}) == sign::zero);
    CHECK(insphere(a, b, c, d, point3{3, 3, 3}) == sign::negative);
    // the subnormal case where a classic filter's error bound underflows
    constexpr double tiny = 0x1p-1074;
    CHECK(orient3d(point3{0, 0, 0}, point3{tiny, 0, 0}, point3{0, tiny, 0}, point3{0, 0, -tiny}) == sign::positive);
    CHECK(orient2d(point2{tiny, tiny}, point2{2 * tiny, 2 * tiny}, point2{3 * tiny, 3 * tiny}) == sign::zero);
    // the largest finite coordinates: the filter's products overflow, the exact path decides
    constexpr double huge = 0x1.fffffffffffffp1023;
    CHECK(orient2d(point2{-huge, -huge}, point2{huge, -huge}, point2{0, huge}) == sign::positive);
}

TEST_CASE("predicates: oracle, random and near-degenerate", "[predicates][oracle]") {
    support::rng r(support::seed());
    const long n = support::cases(100000);
    pred_tally o2{"orient2d random+near-degenerate"}, o3{"orient3d random+near-degenerate"}, ic{"incircle random+near-degenerate"},
        is{"insphere random+near-degenerate"};
    for (long i = 0; i < n; ++i) {
        const bool near = i % 2 == 1;
        support::transform tr = support::random_transform(r, near);
        double A[3], B[3], C[3], D[3], E[3];
        for (int k = 0; k < 3; ++k) {
            A[k] = near ? support::small(r) : r.uniform(-1, 1);
            B[k] = near ? support::small(r) : r.uniform(-1, 1);
            C[k] = near ? support::small(r) : r.uniform(-1, 1);
        }
        const double u = r.integer(-4, 4) * 0.5, v = r.integer(-4, 4) * 0.5;
        for (int k = 0; k < 3; ++k) {
            D[k] = near ? A[k] + u * (B[k] - A[k]) + v * (C[k] - A[k]) : r.uniform(-1, 1); // coplanar / collinear
            E[k] = r.uniform(-1, 1);
        }
        if (near) { // cospherical: five points on a sphere from Pythagorean quadruples
            const double ctr[3] = {support::small(r), support::small(r), support::small(r)};
            double* pts[5] = {A, B, C, D, E};
            const double k = r.integer(1, 3);
            for (double* p : pts) {
                const auto q = support::pythagorean(r);
                if (q.w != 9) continue; // same radius: quadruples with w = 9 only
                p[0] = ctr[0] + k * q.x;
                p[1] = ctr[1] + k * q.y;
                p[2] = ctr[2] + k * q.z;
            }
        }
        const point3 a = gen_point(tr, A), b = gen_point(tr, B), c = gen_point(tr, C), d = gen_point(tr, D), e = gen_point(tr, E);
        double pa[3], pb[3], pc[3], pd[3], pe[3];
        arr(a, pa);
        arr(b, pb);
        arr(c, pc);
        arr(d, pd);
        arr(e, pe);
        {
            ++o3.n;
            const int t = oracle::orient3d(pa, pb, pc, pd);
            if (s(orient3d(a, b, c, d)) != t && ++o3.wrong <= 5)
                std::printf("  orient3d: %s %s %s %s\n", support::str(a).c_str(), support::str(b).c_str(), support::str(c).c_str(),
                            support::str(d).c_str());
            if (s(orient3d<approximate>(a, b, c, d)) != t) ++o3.approx_wrong;
        }
        {
            ++o2.n;
            const point2 a2{a.x, a.y}, b2{b.x, b.y}, c2{c.x, c.y}, d2{d.x, d.y};
            const int t = oracle::orient2d(pa, pb, pd);
            if (s(orient2d(a2, b2, d2)) != t) ++o2.wrong;
            if (s(orient2d<approximate>(a2, b2, d2)) != t) ++o2.approx_wrong;
            ++ic.n;
            const int ti = oracle::incircle(pa, pb, pc, pd);
            if (s(incircle(a2, b2, c2, d2)) != ti) ++ic.wrong;
            if (s(incircle<approximate>(a2, b2, c2, d2)) != ti) ++ic.approx_wrong;
        }
        if (i % 4 == 0 || near) {
            ++is.n;
            const int t = oracle::insphere(pa, pb, pc, pd, pe);
            if (s(insphere(a, b, c, d, e)) != t && ++is.wrong <= 5) std::printf("  insphere mismatch\n");
            if (s(insphere<approximate>(a, b, c, d, e)) != t) ++is.approx_wrong;
        }
    }
    o2.report();
    o3.report();
    ic.report();
    is.report();
}

TEST_CASE("predicates: subnormal and near-underflow orient3d (the classic filter's blind spot)", "[predicates][oracle]") {
    support::rng r(support::seed() + 10);
    long n = 0, wrong = 0;
    for (long i = 0; i < support::cases(65536); ++i) {
        // tiny integer multiples of 2^-1074, nudged: many exactly coplanar
        double p[4][3];
        for (auto& q : p)
            for (double& x : q) x = r.integer(-8, 8) * 0x1p-1074;
        for (int k = 0; k < 3; ++k) p[3][k] = p[0][k] + (p[1][k] - p[0][k]) + (p[2][k] - p[0][k]);
        if (r.coin()) p[3][r.integer(0, 2)] += 0x1p-1074 * r.integer(-1, 1);
        ++n;
        const int t = oracle::orient3d(p[0], p[1], p[2], p[3]);
        const sign e = orient3d(point3{p[0][0], p[0][1], p[0][2]}, point3{p[1][0], p[1][1], p[1][2]}, point3{p[2][0], p[2][1], p[2][2]},
                                point3{p[3][0], p[3][1], p[3][2]});
        if (s(e) != t) ++wrong;
    }
    std::printf("[cases] orient3d subnormal: %ld cases, %ld exact disagreements\n", n, wrong);
    CHECK(wrong == 0);
}

} // namespace test_predicates_orient
