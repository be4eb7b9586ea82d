// aabb3 x aabb3: intersects and contains against CGAL Epeck (Iso_cuboid_3), and the "two boxes
// cover a third" exercise against an independent oracle: every cell of the arrangement of all
// box planes inside c (breakpoints and the open intervals between them, handled symbolically so
// no midpoint is ever rounded) must lie in a or in b.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include <algorithm>
#include <vector>

namespace test_query_aabb_aabb { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
std::string describe(const aabb3& a, const aabb3& b) {
    return "box " + support::str(a.min) + support::str(a.max) + " box " + support::str(b.min) + support::str(b.max);
}
bool truth(const aabb3& a, const aabb3& b) {
    double a0[3], a1[3], b0[3], b1[3];
    arr(a.min, a0);
    arr(a.max, a1);
    arr(b.min, b0);
    arr(b.max, b1);
    return oracle::box_box(a0, a1, b0, b1);
}
bool skip(const aabb3&, const aabb3&) { return false; }
aabb3 box_from(support::rng& r, support::transform& tr, bool nice) {
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
        lo[i] = nice ? r.integer(-4, 4) * 0.5 : r.uniform(-1, 1);
        hi[i] = lo[i] + (nice ? r.integer(0, 6) * 0.5 : r.uniform(0, 1));
    }
    aabb3 b{{tr.apply(lo[0], 0), tr.apply(lo[1], 1), tr.apply(lo[2], 2)}, {tr.apply(hi[0], 0), tr.apply(hi[1], 1), tr.apply(hi[2], 2)}};
    b = support::ordered(b);
    return b;
}
std::pair<aabb3, aabb3> near_case(support::rng& r) {
    support::transform tr = support::random_transform(r, true);
    return {box_from(r, tr, true), box_from(r, tr, true)};
}
std::pair<aabb3, aabb3> random_case(support::rng& r) {
    support::transform tr = support::random_transform(r, false);
    return {box_from(r, tr, false), box_from(r, tr, false)};
}

// Independent cover oracle over the arrangement of breakpoints.
struct sample {
    double lo, hi;
}; // lo == hi: a breakpoint; lo < hi: the open cell (lo, hi)
bool in(const sample& s, double mn, double mx) { return mn <= s.lo && s.hi <= mx; }
bool covers_oracle(const aabb3& a, const aabb3& b, const aabb3& c) {
    double amn[3], amx[3], bmn[3], bmx[3], cmn[3], cmx[3];
    arr(a.min, amn);
    arr(a.max, amx);
    arr(b.min, bmn);
    arr(b.max, bmx);
    arr(c.min, cmn);
    arr(c.max, cmx);
    std::vector<sample> axis[3];
    for (int i = 0; i < 3; ++i) {
        std::vector<double> v{cmn[i], cmx[i]};
        for (double x : {amn[i], amx[i], bmn[i], bmx[i]})
            if (cmn[i] <= x && x <= cmx[i]) v.push_back(x);
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end()), v.end());
        for (std::size_t k = 0; k < v.size(); ++k) {
            axis[i].push_back({v[k], v[k]});
            if (k + 1 < v.size()) axis[i].push_back({v[k], v[k + 1]});
        }
    }
    for (const auto& x : axis[0])
        for (const auto& y : axis[1])
            for (const auto& z : axis[2]) {
                const bool ina = in(x, amn[0], amx[0]) && in(y, amn[1], amx[1]) && in(z, amn[2], amx[2]);
                const bool inb = in(x, bmn[0], bmx[0]) && in(y, bmn[1], bmx[1]) && in(z, bmn[2], bmx[2]);
                if (!ina && !inb) return false;
            }
    return true;
}
} // namespace

TEST_CASE("aabb_aabb: fixtures", "[aabb_aabb]") {
    const aabb3 A{{0, 0, 0}, {1, 1, 1}};
    CHECK(intersects(A, aabb3{{1, 1, 1}, {2, 2, 2}})); // corner touch
    CHECK(intersects(A, aabb3{{1, 0, 0}, {2, 1, 1}})); // face touch
    CHECK_FALSE(intersects(A, aabb3{{1.0000000000000002, 0, 0}, {2, 1, 1}}));
    CHECK(contains(A, A));
    CHECK(contains(A, aabb3{{0, 0, 0}, {1, 0, 0}})); // a flat box on an edge
    CHECK_FALSE(contains(A, aabb3{{0, 0, 0}, {1, 1, 1.0000000000000002}}));
    // the cover exercise
    CHECK(covers(aabb3{{0, 0, 0}, {1, 1, 1}}, aabb3{{1, 0, 0}, {2, 1, 1}}, aabb3{{0, 0, 0}, {2, 1, 1}}));
    CHECK_FALSE(covers(aabb3{{0, 0, 0}, {1, 1, 1}}, aabb3{{1.0000000000000002, 0, 0}, {2, 1, 1}}, aabb3{{0, 0, 0}, {2, 1, 1}}));
    CHECK(covers(aabb3{{0, 0, 0}, {2, 1, 1}}, aabb3{{5, 5, 5}, {6, 6, 6}}, aabb3{{0, 0, 0}, {1, 1, 1}}));
    CHECK_FALSE(covers(aabb3{{0, 0, 0}, {1, 1, 1}}, aabb3{{0, 0, 0}, {1, 1, 1}}, aabb3{{0, 0, 0}, {1, 1, 2}}));
}
TEST_CASE("aabb_aabb: oracle, random", "[aabb_aabb][oracle]") {
    support::run_oracle("aabb_aabb random", support::cases(100000), 0.0, random_case, truth, skip, describe);
}
TEST_CASE("aabb_aabb: oracle, near-degenerate", "[aabb_aabb][oracle]") {
    support::run_oracle("aabb_aabb near-degenerate", support::cases(100000), 0.0, near_case, truth, skip, describe);
}
TEST_CASE("aabb_aabb: contains in every tier against the oracle", "[aabb_aabb][oracle]") {
    support::rng r(support::seed() + 8);
    long n = 0, wrong = 0;
    for (long i = 0; i < support::cases(200000); ++i) {
        auto [a, b] = (i % 2) ? near_case(r) : random_case(r);
        double a0[3], a1[3], b0[3], b1[3];
        arr(a.min, a0);
        arr(a.max, a1);
        arr(b.min, b0);
        arr(b.max, b1);
        const bool t = oracle::box_contains_box(a0, a1, b0, b1);
        ++n;
        if (contains<exact>(a, b) != t || contains<conservative>(a, b) != t || contains<aggressive>(a, b) != t ||
            contains<approximate>(a, b) != t || (classify_contains(a, b) == certainty::yes) != t)
            ++wrong;
    }
    std::printf("[cases] aabb_aabb contains: %ld cases, %ld wrong in some tier\n", n, wrong);
    CHECK(wrong == 0);
}
TEST_CASE("aabb_aabb: covers against the independent arrangement oracle", "[aabb_aabb][oracle]") {
    support::rng r(support::seed() + 9);
    long n = 0, wrong = 0, yes = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        support::transform tr = support::random_transform(r, (i % 2) == 0);
        const bool nice = (i % 4) < 3;
        const aabb3 a = box_from(r, tr, nice), b = box_from(r, tr, nice);
        // c from pieces of a and b, so that covering happens often
        aabb3 c = box_from(r, tr, nice);
        if (r.coin()) {
            c.min = a.min;
            c.max = point3{std::max(a.max.x, b.max.x), a.max.y, a.max.z};
        }
        if (c.min.x > c.max.x) std::swap(c.min.x, c.max.x);
        ++n;
        const bool t = covers_oracle(a, b, c);
        yes += t;
        if (covers(a, b, c) != t && ++wrong <= 5)
            std::printf("  covers wrong: %s c %s%s\n", describe(a, b).c_str(), support::str(c.min).c_str(), support::str(c.max).c_str());
        if (covers(b, a, c) != t) ++wrong;
    }
    std::printf("[cases] aabb_aabb covers: %ld cases (%ld covered), %ld wrong\n", n, yes, wrong);
    CHECK(wrong == 0);
}

} // namespace test_query_aabb_aabb
