// squared_distance and signed_distance of a point and a set of half-spaces (convex_polyhedron3,
// frustum3, the k-DOPs): fixtures (the integer box as a 6-DOP and as planes: outside a face, an
// edge and a corner, inside nearer one face, on the boundary; the empty set; a set with no rows;
// NaN), then every tier against the exact values (testkit/oracle/cgal_distance.cpp: CGAL's exact QP
// outside, the rows in rationals inside) on random sets with points around them and near-degenerate
// sets with points at a face, an edge or a vertex, along the normal cone, on the boundary or inside
// (testkit/ball_halfspace_cases.hpp: the ball's centre is the point), at scales 2^-500..2^500.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/ball_halfspace_checks.hpp"
#include "testkit/distance_checks.hpp"

namespace test_query_distance_halfspace_point {

using namespace incidence;

namespace {
// The box [0, 1] x [0, 2] x [0, 3] as six planes.
convex_polyhedron3 box_planes() {
    convex_polyhedron3 c{};
    const plane3 rows[6] = {{{1, 0, 0}, 1}, {{-1, 0, 0}, 0}, {{0, 1, 0}, 2}, {{0, -1, 0}, 0}, {{0, 0, 1}, 3}, {{0, 0, -1}, 0}};
    for (int i = 0; i < 6; ++i) c.planes[static_cast<unsigned>(i)] = rows[i];
    c.count = 6;
    return c;
}
} // namespace

TEST_CASE("halfspace_point: fixtures", "[distance][halfspace_point]") {
    const convex_polyhedron3 c = box_planes();
    const kdop<6> k = kdop<6>::make({0, 0, 0}, {1, 2, 3}).value();
    for (const auto& [p, d] : {std::pair{point3{3, 1, 1}, 2.0}, std::pair{point3{4, 6, 1}, 5.0}, std::pair{point3{3, 4, 4}, 3.0},
                               std::pair{point3{0.5, 0.25, 1}, -0.25}, std::pair{point3{1, 1, 1}, 0.0}}) {
        CHECK(signed_distance(c, p) == d);
        CHECK(signed_distance(p, k) == d);
        CHECK(squared_distance(c, p) == (d > 0 ? d * d : 0.0));
        const interval v = signed_distance<conservative>(k, p);
        CHECK(v.lo <= d);
        CHECK(v.hi >= d);
    }
    // the plane 2x + y = 2 beyond the corner (1, 0): the edge's distance from (2, 1, 1) is 3 / sqrt(5)
    convex_polyhedron3 cut = c;
    cut.planes[6] = {{2, 1, 0}, 2};
    cut.count = 7;
    CHECK(signed_distance(cut, point3{0, 0, 1}) == 0.0);
    CHECK(signed_distance(cut, point3{2, 1, 1}) == static_cast<double>(3.0L / std::sqrt(5.0L)));
    convex_polyhedron3 empty = c;
    empty.planes[0] = {{1, 0, 0}, -1}; // x <= -1 and x >= 0
    CHECK(signed_distance(empty, point3{0, 0, 0}) == INFINITY);
    CHECK(squared_distance(empty, point3{0, 0, 0}) == INFINITY);
    convex_polyhedron3 all{};
    all.count = 0;
    CHECK(signed_distance(all, point3{0, 0, 0}) == -INFINITY);
    CHECK(squared_distance(all, point3{0, 0, 0}) == 0.0);
    CHECK(std::isnan(signed_distance(c, point3{0, NAN, 0})));
    convex_polyhedron3 bad = c;
    bad.count = 99;
    CHECK(std::isnan(signed_distance(bad, point3{0, 0, 0})));
}

namespace {
template <class P>
void distances(const std::string& name, long n, std::uint64_t salt) {
    support::distance_oracle<P>(
        name, n, salt,
        [](support::rng& r, bool near) -> std::optional<std::pair<P, point3>> {
            const auto c = near ? support::ball_near<P>(r) : support::ball_random<P>(r);
            if (!c) return std::nullopt;
            return std::pair{c->first, c->second.center};
        },
        [](const P& a) { return oracle::distance_solid{oracle::distance_solid::rows, {}, support::lp(a)}; },
        [](const P& a) { return support::shape_str(a); });
}
} // namespace

TEST_CASE("halfspace_point: every tier against the exact QP and rows", "[distance][halfspace_point][oracle]") {
    distances<convex_polyhedron3>("convex_polyhedron_point distances", support::cases(3000), 221);
    distances<frustum3>("frustum_point distances", support::cases(3000), 222);
    distances<kdop<6>>("kdop_point distances (6)", support::cases(1500), 223);
    distances<kdop<14>>("kdop_point distances (14)", support::cases(1500), 224);
    distances<kdop<18>>("kdop_point distances (18)", support::cases(1500), 225);
    distances<kdop<26>>("kdop_point distances (26)", support::cases(1500), 226);
}

} // namespace test_query_distance_halfspace_point
