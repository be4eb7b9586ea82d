// aabb3 x segment3: the slab test on [0, 1] in every tier; CGAL Epeck oracle on 100,000 random and
// 100,000 near-degenerate cases (segments ending exactly on a face, edge or corner or passing
// through it, segments in face planes, axis-parallel, flat boxes, ulp nudges, 2^+-500), and
// reversed end points.
// contains(aabb, segment) against CGAL Epeck (each vertex in the Iso_cuboid_3) on 10,000 random and
// 10,000 cases inside, on the boundary from inside or just beyond it.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/contain_checks.hpp"
#include "testkit/box_linear_cases.hpp"

namespace test_query_aabb_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_segment"); // stated in the catalog (modules/query/catalog.cppm)

std::string describe(const aabb3& b, const segment3& s) {
    return "box " + support::str(b.min) + support::str(b.max) + " segment " + support::str(s.a) + support::str(s.b);
}
bool truth(const aabb3& b, const segment3& s) {
    double p[3], q[3], mn[3], mx[3];
    arr(s.a, p);
    arr(s.b, q);
    arr(b.min, mn);
    arr(b.max, mx);
    return oracle::box_segment(mn, mx, p, q);
}
bool skip(const aabb3&, const segment3&) { return false; }
std::pair<aabb3, segment3> near_case(support::rng& r) {
    const auto c = support::box_linear_near(r);
    const double f = r.integer(1, 4) * 0.5; // 1: ends at the boundary point
    return {c.box, segment3{c.point(0), c.point(f)}};
}
std::pair<aabb3, segment3> random_case(support::rng& r) {
    const auto c = support::box_linear_random(r);
    return {c.box, segment3{c.point(0), c.point(1)}};
}
} // namespace

TEST_CASE("aabb_segment: fixtures (closed box, touching counts)", "[aabb_segment]") {
    const aabb3 B{{0, 0, 0}, {1, 1, 1}};
    CHECK(intersects(B, segment3{{-1, 0.5, 0.5}, {0.5, 0.5, 0.5}}));
    CHECK(intersects(B, segment3{{-1, 0.5, 0.5}, {0, 0.5, 0.5}}));                // ends on a face
    CHECK_FALSE(intersects(B, segment3{{-1, 0.5, 0.5}, {-0x1p-1074, 0.5, 0.5}})); // one subnormal short
    CHECK(intersects(B, segment3{{2, 1, 0}, {0, -1, 0}}));                        // touching the edge x = 1, y = 0
    CHECK_FALSE(intersects(B, segment3{{2.0000000000000004, 1, 0}, {0, -1.0000000000000002, 0}}));
    CHECK(intersects(B, segment3{{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}})); // a point segment inside
    CHECK_FALSE(intersects(B, segment3{{2, 2, 2}, {3, 3, 3}}));       // on the diagonal's line, beyond
    CHECK(intersects(segment3{{3, 3, 3}, {1, 1, 1}}, B));             // reversed order, at the corner
    CHECK(method::aabb_segment_slab(B, segment3{{-1, 0.5, 0.5}, {0.5, 0.5, 0.5}}));
}
TEST_CASE("aabb_segment: oracle, random", "[aabb_segment][oracle]") {
    support::run_oracle("aabb_segment random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("aabb_segment: oracle, near-degenerate", "[aabb_segment][oracle]") {
    support::run_oracle("aabb_segment near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}
TEST_CASE("aabb_segment: reversed end points give the same answer", "[aabb_segment]") {
    support::rng r(support::seed() + 41);
    long n = 0, bad = 0;
    for (long i = 0; i < support::cases(50000); ++i) {
        const auto [b, s] = (i % 2) ? near_case(r) : random_case(r);
        ++n;
        if (intersects(b, s) != intersects(b, segment3{s.b, s.a})) ++bad;
    }
    std::printf("[cases] aabb_segment reversed: %ld, %ld differ\n", n, bad);
    CHECK(bad == 0);
}

TEST_CASE("aabb_segment: contains(aabb, segment)", "[aabb_segment][oracle]") {
    support::contains_oracle<aabb3, segment3>(
        "aabb_segment (aabb around segment)", support::cases(10000), approx_bound,
        [](support::rng& r) {
            const auto tr = support::random_transform(r, false);
            return std::pair{support::random_aabb(r, tr), segment3{support::random_point(r, tr), support::random_point(r, tr)}};
        },
        support::aabb_holding<segment3>, true);
}

} // namespace test_query_aabb_segment
