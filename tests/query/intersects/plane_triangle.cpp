// plane3 x triangle3: CGAL Epeck oracle on 100,000 random and 100,000 near-degenerate cases (planes
// through the vertex extreme along -n, touching at a vertex or an edge, or through another vertex;
// exact scales and nudged translations), vertex order and the flipped plane.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/plane_cases.hpp"

namespace test_query_plane_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("plane_triangle"); // stated in the catalog (modules/query/catalog.cppm)

std::string describe(const plane3& p, const triangle3& t) {
    return "plane " + support::str(p.normal) + " " + support::hex(p.offset) + " tri " + support::str(t.a) + support::str(t.b) +
           support::str(t.c);
}
bool truth(const plane3& p, const triangle3& t) {
    double n[3], a[3], b[3], c[3];
    arr(p.normal, n);
    arr(t.a, a);
    arr(t.b, b);
    arr(t.c, c);
    return oracle::plane_triangle(n, p.offset, a, b, c);
}
bool skip(const plane3& p, const triangle3& t) {
    double a[3], b[3], c[3];
    arr(t.a, a);
    arr(t.b, b);
    arr(t.c, c);
    return p.normal == vec3{0, 0, 0} || oracle::triangle_is_degenerate(a, b, c);
}
std::pair<plane3, triangle3> near_case(support::rng& r) {
    std::vector<point3> v;
    for (int i = 0; i < 3; ++i) v.push_back({support::small(r), support::small(r), support::small(r)});
    if (r.integer(0, 3) == 0) v[2] = v[0] + (v[1] - v[0]) * 0.5 + vec3{0, 0, 1}; // an edge may lie flat in the plane
    const auto pc = support::plane_near(r, v);
    return {pc.plane, triangle3{pc.v[0], pc.v[1], pc.v[2]}};
}
std::pair<plane3, triangle3> random_case(support::rng& r) {
    const auto pc = support::plane_random(r, 3);
    return {pc.plane, triangle3{pc.v[0], pc.v[1], pc.v[2]}};
}
} // namespace

TEST_CASE("plane_triangle: fixtures", "[plane_triangle]") {
    const plane3 P{{0, 0, 1}, 1};
    CHECK(intersects(P, triangle3{{0, 0, 0}, {1, 0, 2}, {0, 1, 0}}));
    CHECK(intersects(P, triangle3{{0, 0, 1}, {1, 0, 2}, {0, 1, 2}})); // a vertex on the plane
    CHECK_FALSE(intersects(P, triangle3{{0, 0, 1.0000000000000002}, {1, 0, 2}, {0, 1, 2}}));
    CHECK(intersects(triangle3{{0, 0, 1}, {1, 0, 1}, {0, 1, 3}}, P)); // an edge in the plane, reversed order
    CHECK(intersects(P, triangle3{{0, 0, 1}, {1, 0, 1}, {0, 1, 1}})); // lying in the plane
}
TEST_CASE("plane_triangle: oracle, random", "[plane_triangle][oracle]") {
    support::run_oracle("plane_triangle random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("plane_triangle: oracle, near-degenerate", "[plane_triangle][oracle]") {
    support::run_oracle("plane_triangle near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}
TEST_CASE("plane_triangle: vertex order and the flipped plane give the same answer", "[plane_triangle]") {
    support::rng r(support::seed() + 59);
    long n = 0, bad = 0;
    for (long i = 0; i < support::cases(50000); ++i) {
        const auto [p, t] = (i % 2) ? near_case(r) : random_case(r);
        const bool e = intersects(p, t);
        n += 3;
        if (intersects(p, triangle3{t.b, t.c, t.a}) != e) ++bad;
        if (intersects(p, triangle3{t.c, t.b, t.a}) != e) ++bad;
        if (intersects(plane3{p.normal * -1.0, -p.offset}, t) != e) ++bad;
    }
    std::printf("[cases] plane_triangle symmetries: %ld, %ld differ\n", n, bad);
    CHECK(bad == 0);
}

} // namespace test_query_plane_triangle
