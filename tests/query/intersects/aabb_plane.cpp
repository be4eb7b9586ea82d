// aabb3 x plane3: CGAL Epeck oracle on 100,000 random and 100,000 near-degenerate cases (planes
// through the box's extreme corner along -n, touching a corner, an edge or a face, or through
// another corner; flat boxes; exact scales and nudged translations), and the flipped plane.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/plane_cases.hpp"

namespace test_query_aabb_plane { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_plane"); // stated in the catalog (modules/query/catalog.cppm)

std::string describe(const aabb3& b, const plane3& p) {
    return "box " + support::str(b.min) + support::str(b.max) + " plane " + support::str(p.normal) + " " + support::hex(p.offset);
}
bool truth(const aabb3& b, const plane3& p) {
    double mn[3], mx[3], n[3];
    arr(b.min, mn);
    arr(b.max, mx);
    arr(p.normal, n);
    return oracle::box_plane(mn, mx, n, p.offset);
}
bool skip(const aabb3&, const plane3& p) { return p.normal == vec3{0, 0, 0}; }
std::pair<aabb3, plane3> near_case(support::rng& r) {
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) lo[i] = support::small(r), hi[i] = lo[i] + r.integer(0, 8) * 0.5;
    std::vector<point3> corners;
    for (int c = 0; c < 8; ++c) corners.push_back({c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]});
    const auto pc = support::plane_near(r, corners);
    return {support::ordered(aabb3{pc.v[0], pc.v[7]}), pc.plane};
}
std::pair<aabb3, plane3> random_case(support::rng& r) {
    const auto pc = support::plane_random(r, 2);
    return {support::ordered(aabb3{pc.v[0], pc.v[1]}), pc.plane};
}
} // namespace

TEST_CASE("aabb_plane: fixtures", "[aabb_plane]") {
    const aabb3 B{{0, 0, 0}, {1, 1, 1}};
    CHECK(intersects(B, plane3{{1, 1, 1}, 1.5}));
    CHECK(intersects(B, plane3{{1, 1, 1}, 3})); // touching the corner (1,1,1)
    CHECK_FALSE(intersects(B, plane3{{1, 1, 1}, 3.0000000000000004}));
    CHECK(intersects(B, plane3{{0, 0, 1}, 0}));  // the bottom face
    CHECK(intersects(plane3{{1, -1, 0}, 1}, B)); // reversed order, the edge x = 1, y = 0
    CHECK_FALSE(intersects(B, plane3{{1, -1, 0}, 1.0000000000000002}));
    CHECK(intersects(B, plane3{{0, 0, 0}, 0}));       // zero normal, offset 0: everything
    CHECK_FALSE(intersects(B, plane3{{0, 0, 0}, 1})); // zero normal: nothing
}
TEST_CASE("aabb_plane: oracle, random", "[aabb_plane][oracle]") {
    support::run_oracle("aabb_plane random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("aabb_plane: oracle, near-degenerate", "[aabb_plane][oracle]") {
    support::run_oracle("aabb_plane near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}
TEST_CASE("aabb_plane: the flipped plane (-n, -offset) gives the same answer", "[aabb_plane]") {
    support::rng r(support::seed() + 47);
    long n = 0, bad = 0;
    for (long i = 0; i < support::cases(50000); ++i) {
        const auto [b, p] = (i % 2) ? near_case(r) : random_case(r);
        ++n;
        if (intersects(b, p) != intersects(b, plane3{p.normal * -1.0, -p.offset})) ++bad;
    }
    std::printf("[cases] aabb_plane flipped: %ld, %ld differ\n", n, bad);
    CHECK(bad == 0);
}

} // namespace test_query_aabb_plane
