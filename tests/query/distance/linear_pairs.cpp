// squared_distance and distance between points, segments, rays and lines: fixtures (skew, crossing,
// parallel and collinear sets, nearest points at an end or inside, degenerate sets, NaN), then every
// tier of the ten pairs, both argument orders, against CGAL's squared_distance over Epeck
// (testkit/oracle/cgal_distance.cpp): the exact tier correctly rounded, the intervals containing
// the exact value, the approximate tier within its stated bound (testkit/distance_checks.hpp). Cases:
// random shapes (testkit/flat_cases.hpp, scales 2^-500..2^500, half of them in one plane) and
// near-degenerate ones: the flat pairs' meeting, parallel and coplanar arrangements, and sets placed
// apart by a small dyadic offset, so that the nearest points fall exactly on an end, inside, or on
// a parallel stretch, nudged by ulps, scaled and translated.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/flat_cases.hpp"
#include "testkit/obb_check.hpp"
#include "testkit/distance_checks.hpp"

namespace test_query_distance_linear_pairs {

using namespace incidence;

TEST_CASE("linear_pairs distances: fixtures", "[distance][linear_pairs]") {
    CHECK(distance(point3{0, 0, 0}, point3{3, 4, 0}) == 5.0);
    CHECK(squared_distance(point3{0, 1, 0}, segment3{{-1, 0, 0}, {1, 0, 0}}) == 1.0);
    CHECK(squared_distance(point3{3, 4, 0}, segment3{{-1, 0, 0}, {0, 0, 0}}) == 25.0); // beyond the end
    CHECK(squared_distance(segment3{{0, 0, 0}, {1, 0, 0}}, segment3{{0, 1, 1}, {0, 1, 2}}) == 2.0);
    CHECK(distance(segment3{{-1, 0, 0}, {1, 0, 0}}, segment3{{0, -1, 2}, {0, 1, 2}}) == 2.0);   // inside both
    CHECK(distance(segment3{{0, 0, 0}, {2, 0, 0}}, segment3{{1, 1, 0}, {3, 1, 0}}) == 1.0);     // parallel
    CHECK(distance(segment3{{0, 0, 0}, {1, 0, 0}}, segment3{{3, 0, 0}, {4, 0, 0}}) == 2.0);     // collinear, apart
    CHECK(distance(segment3{{-1, -1, 0}, {1, 1, 0}}, segment3{{-1, 1, 0}, {1, -1, 0}}) == 0.0); // crossing
    CHECK(squared_distance(ray3{{0, 0, 0}, {1, 0, 0}}, ray3{{-1, 1, 0}, {-1, 0, 0}}) == 2.0);
    CHECK(squared_distance(ray3{{0, 0, 0}, {1, 0, 0}}, ray3{{-1, 1, 0}, {1, 0, 0}}) == 1.0); // parallel, overlapping
    CHECK(distance(line3{{-1, 0, 0}, {1, 0, 0}}, line3{{0, -1, 2}, {0, 1, 0}}) == 2.0);
    CHECK(distance(line3{{0, 0, 0}, {1, 0, 0}}, line3{{5, 1, 0}, {-2, 0, 0}}) == 1.0);
    CHECK(squared_distance(line3{{0, 0, 0}, {1, 1, 1}}, point3{1, 0, 0}) == 2.0 / 3.0);
    CHECK(squared_distance(point3{1, 0, 0}, line3{{0, 0, 0}, {1, 1, 1}}) == 2.0 / 3.0);
    CHECK(distance(line3{{0, 0, 0}, {0, 0, 0}}, point3{0, 3, 4}) == 5.0); // a zero direction: a point
    CHECK(distance(segment3{{1, 1, 1}, {1, 1, 1}}, ray3{{0, 0, 0}, {0, 0, -1}}) == std::sqrt(3.0));
    CHECK(squared_distance(ray3{{0, 0, 0}, {0, 1, 0}}, segment3{{1, -3, 0}, {1, -2, 0}}) == 5.0);
    CHECK(distance(line3{{3, 4, 7}, {0, 0, 0}}, line3{{0, 0, 0}, {0, 0, 1}}) == 5.0); // a point against a line
    CHECK(distance(line3{{0, 0, 0}, {0, 0, 1}}, line3{{3, 4, 7}, {0, 0, 0}}) == 5.0);
    // a segment ahead of a ray's origin on its line, pointing back: they meet (CGAL 5.5's
    // squared_distance(Ray_3, Segment_3) says 4 here; the oracle cuts the ray to a segment)
    CHECK(distance(ray3{{0, 0, 0}, {0, 0, 1}}, segment3{{0, 0, 3}, {0, 0, 2}}) == 0.0);
    CHECK(distance(ray3{{0, 0, 4}, {0, 0, 1}}, segment3{{0, 0, 3}, {0, 0, 2}}) == 1.0);
    CHECK(std::isnan(distance(segment3{{0, 0, 0}, {1, 0, NAN}}, point3{0, 0, 0})));
    CHECK(std::isnan(squared_distance(line3{{0, 0, 0}, {INFINITY, 0, 0}}, line3{{0, 0, 0}, {0, 1, 0}})));
    // the intervals hold the exact value; the approximate tier agrees here
    const segment3 s{{0, 0, 0}, {1, 1, 0}}, t{{0, 1, 1}, {1, 0, 1}};
    const interval c = squared_distance<conservative>(s, t), a = squared_distance<aggressive>(t, s);
    CHECK(c.lo <= 1.0);
    CHECK(c.hi >= 1.0);
    CHECK(a.lo <= 1.0);
    CHECK(a.hi >= 1.0);
    CHECK(squared_distance<approximate>(s, t) == 1.0);
    // a point's distance to a solid: zero inside, the signed distance outside
    const aabb3 box{{0, 0, 0}, {1, 1, 1}};
    CHECK(distance(box, point3{0.5, 0.5, 0.5}) == 0.0);
    CHECK(distance(point3{4, 5, 1}, box) == 5.0);
    CHECK(distance<conservative>(box, point3{0.5, 0.5, 0.5}).hi == 0.0);
}

template <class A, class B>
void against_oracle(const char* name, std::uint64_t salt) {
    support::rng r(support::seed() + salt);
    support::distance_tally t{name};
    const long n = support::cases(1500);
    for (long i = 0; i < 3 * n; ++i) {
        const auto [a, b] = i % 3 == 0   ? support::flat_random<A, B>(r)
                            : i % 3 == 1 ? support::flat_near<A, B>(r)
                                         : support::flat_apart<A, B>(r);
        support::check_flat_distance_case(t, a, b);
    }
    t.report();
}

TEST_CASE("linear_pairs distances: every tier against CGAL's", "[distance][linear_pairs][oracle]") {
    against_oracle<line3, line3>("line_line", 301);
    against_oracle<line3, point3>("line_point", 302);
    against_oracle<line3, ray3>("line_ray", 303);
    against_oracle<line3, segment3>("line_segment", 304);
    against_oracle<point3, point3>("point_point", 305);
    against_oracle<point3, ray3>("point_ray", 306);
    against_oracle<point3, segment3>("point_segment", 307);
    against_oracle<ray3, ray3>("ray_ray", 308);
    against_oracle<ray3, segment3>("ray_segment", 309);
    against_oracle<segment3, segment3>("segment_segment", 310);
}

} // namespace test_query_distance_linear_pairs
