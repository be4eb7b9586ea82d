// aabb3 x line3: the slab test over all t in every tier; CGAL Epeck oracle on 100,000 random and
// 100,000 near-degenerate cases (lines through a face, edge or corner point, in face planes,
// axis-parallel, flat boxes, ulp nudges, 2^+-500), and the reversed direction.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/box_linear_cases.hpp"

namespace test_query_aabb_line { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_line"); // stated in the catalog (modules/query/catalog.cppm)

std::string describe(const aabb3& b, const line3& l) {
    return "box " + support::str(b.min) + support::str(b.max) + " line " + support::str(l.origin) + " dir " + support::str(l.direction);
}
bool truth(const aabb3& b, const line3& l) {
    double p[3], d[3], mn[3], mx[3];
    arr(l.origin, p);
    arr(l.direction, d);
    arr(b.min, mn);
    arr(b.max, mx);
    return oracle::box_line(mn, mx, p, d);
}
bool skip(const aabb3&, const line3& l) { return l.direction == vec3{0, 0, 0}; }
std::pair<aabb3, line3> near_case(support::rng& r) {
    const auto c = support::box_linear_near(r);
    return {c.box, line3{c.point(0), c.direction()}};
}
std::pair<aabb3, line3> random_case(support::rng& r) {
    const auto c = support::box_linear_random(r);
    return {c.box, line3{c.point(0), c.direction()}};
}
} // namespace

TEST_CASE("aabb_line: fixtures (closed box, touching counts)", "[aabb_line]") {
    const aabb3 B{{0, 0, 0}, {1, 1, 1}};
    CHECK(intersects(B, line3{{-5, 0.5, 0.5}, {1, 0, 0}}));
    CHECK(intersects(B, line3{{5, 0.5, 0.5}, {1, 0, 0}})); // behind the origin counts
    CHECK(intersects(B, line3{{2, 1, 0}, {-1, -1, 0}}));   // touching the edge x = 1, y = 0
    CHECK_FALSE(intersects(B, line3{{2.0000000000000004, 1, 0}, {-1, -1, 0}}));
    CHECK(intersects(B, line3{{-1, 1, 1}, {1, 0, 0}})); // along an edge
    CHECK_FALSE(intersects(B, line3{{-1, 1.0000000000000002, 1}, {1, 0, 0}}));
    CHECK(intersects(line3{{3, 3, 3}, {1, 1, 1}}, B)); // reversed order, the diagonal
    CHECK(method::aabb_line_slab(B, line3{{5, 0.5, 0.5}, {1, 0, 0}}));
    // In the plane x = 0 of a face of [0,1]x[1,2]x[0,1], parallel to it, missing the box: y reaches 1
    // at t = 1 + 4 ulps, z leaves the box at t = 1. CGAL 5.5's do_intersect(Line_3, Iso_cuboid_3)
    // says yes here (its slab bound for x becomes 0/0); the rational slab oracle and the exact
    // tier say no.
    const line3 miss{{0, 0, -1}, {0, 0x1.ffffffffffffcp-1, 2}};
    CHECK_FALSE(intersects(aabb3{{0, 1, 0}, {1, 2, 1}}, miss));
    double mn[3] = {0, 1, 0}, mx[3] = {1, 2, 1}, o[3] = {0, 0, -1}, d[3] = {0, 0x1.ffffffffffffcp-1, 2};
    CHECK_FALSE(oracle::box_line(mn, mx, o, d));
    std::printf("[cases] aabb_line: CGAL Epick do_intersect(Line_3, Iso_cuboid_3) on the in-face-plane miss says %s\n",
                oracle::box_line_epick(mn, mx, o, d) ? "yes (wrong)" : "no");
}
TEST_CASE("aabb_line: oracle, random", "[aabb_line][oracle]") {
    support::run_oracle("aabb_line random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("aabb_line: oracle, near-degenerate", "[aabb_line][oracle]") {
    support::run_oracle("aabb_line near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}
TEST_CASE("aabb_line: the reversed direction gives the same answer", "[aabb_line]") {
    support::rng r(support::seed() + 43);
    long n = 0, bad = 0;
    for (long i = 0; i < support::cases(50000); ++i) {
        const auto [b, l] = (i % 2) ? near_case(r) : random_case(r);
        ++n;
        if (intersects(b, l) != intersects(b, line3{l.origin, vec3{-l.direction.x, -l.direction.y, -l.direction.z}})) ++bad;
    }
    std::printf("[cases] aabb_line reversed direction: %ld, %ld differ\n", n, bad);
    CHECK(bad == 0);
}

} // namespace test_query_aabb_line
