// plane3 x segment3: CGAL Epeck oracle on 100,000 random and 100,000 near-degenerate cases (planes
// through an end point with the segment on one side or crossing, exact scales and nudged
// translations), reversed end points and the flipped plane.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/plane_cases.hpp"

namespace test_query_plane_segment { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("plane_segment"); // stated in the catalog (modules/query/catalog.cppm)

std::string describe(const plane3& p, const segment3& s) {
    return "plane " + support::str(p.normal) + " " + support::hex(p.offset) + " segment " + support::str(s.a) + support::str(s.b);
}
bool truth(const plane3& p, const segment3& s) {
    double n[3], a[3], b[3];
    arr(p.normal, n);
    arr(s.a, a);
    arr(s.b, b);
    return oracle::plane_segment(n, p.offset, a, b);
}
bool skip(const plane3& p, const segment3&) { return p.normal == vec3{0, 0, 0}; }
std::pair<plane3, segment3> near_case(support::rng& r) {
    const point3 a{support::small(r), support::small(r), support::small(r)}, b{support::small(r), support::small(r), support::small(r)};
    const auto pc = support::plane_near(r, {a, b});
    return {pc.plane, segment3{pc.v[0], pc.v[1]}};
}
std::pair<plane3, segment3> random_case(support::rng& r) {
    const auto pc = support::plane_random(r, 2);
    return {pc.plane, segment3{pc.v[0], pc.v[1]}};
}
} // namespace

TEST_CASE("plane_segment: fixtures", "[plane_segment]") {
    const plane3 P{{0, 0, 1}, 1};
    CHECK(intersects(P, segment3{{0, 0, 0}, {0, 0, 2}}));
    CHECK(intersects(P, segment3{{0, 0, 0}, {5, 5, 1}})); // ends on the plane
    CHECK_FALSE(intersects(P, segment3{{0, 0, 0}, {5, 5, 0.9999999999999999}}));
    CHECK(intersects(segment3{{1, 2, 1}, {3, 4, 1}}, P)); // in the plane, reversed order
    CHECK(intersects(P, segment3{{0, 0, 1}, {0, 0, 1}})); // a point segment on it
}
TEST_CASE("plane_segment: oracle, random", "[plane_segment][oracle]") {
    support::run_oracle("plane_segment random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("plane_segment: oracle, near-degenerate", "[plane_segment][oracle]") {
    support::run_oracle("plane_segment near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}
TEST_CASE("plane_segment: reversed end points and the flipped plane give the same answer", "[plane_segment]") {
    support::rng r(support::seed() + 53);
    long n = 0, bad = 0;
    for (long i = 0; i < support::cases(50000); ++i) {
        const auto [p, s] = (i % 2) ? near_case(r) : random_case(r);
        const bool e = intersects(p, s);
        n += 2;
        if (intersects(p, segment3{s.b, s.a}) != e) ++bad;
        if (intersects(plane3{p.normal * -1.0, -p.offset}, s) != e) ++bad;
    }
    std::printf("[cases] plane_segment symmetries: %ld, %ld differ\n", n, bad);
    CHECK(bad == 0);
}

} // namespace test_query_plane_segment
