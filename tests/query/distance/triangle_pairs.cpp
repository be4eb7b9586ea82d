// squared_distance and distance between a triangle and a point, a segment, a ray, a line or a
// triangle: fixtures (the nearest points at a vertex, on an edge, inside the face; parallel sets;
// sets that meet; collinear triangles; NaN), then every tier of the five pairs, both argument
// orders, against the oracle (testkit/oracle/cgal_distance.cpp: CGAL's point-triangle distance
// over Epeck, the exact QP for the others): the exact tier correctly rounded, the intervals
// containing the exact value, the approximate tier within its stated bound
// (testkit/distance_checks.hpp). Cases as for the linear pairs (testkit/flat_cases.hpp): random
// shapes at scales 2^-500..2^500, the flat pairs' meeting, parallel and coplanar arrangements, and
// sets apart by a small dyadic offset, nudged by ulps, scaled and translated.
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

namespace test_query_distance_triangle_pairs {

using namespace incidence;

TEST_CASE("triangle_pairs distances: fixtures", "[distance][triangle_pairs]") {
    const triangle3 t{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
    CHECK(squared_distance(point3{1, 1, 3}, t) == 9.0);                  // above the face
    CHECK(distance(t, point3{-3, -4, 0}) == 5.0);                        // beyond the vertex at the origin
    CHECK(distance(point3{2, -3, 4}, t) == 5.0);                         // beyond the edge on the x axis
    CHECK(distance(point3{1, 1, 0}, t) == 0.0);                          // in it
    CHECK(distance(segment3{{1, 1, 2}, {1, 1, 5}}, t) == 2.0);           // an end point above the face
    CHECK(distance(segment3{{1, 1, 2}, {1, 1, -5}}, t) == 0.0);          // through it
    CHECK(distance(segment3{{-1, 4, -2}, {4, -1, -2}}, t) == 2.0);       // parallel, below the face
    CHECK(squared_distance(segment3{{2, -1, 1}, {2, -1, 5}}, t) == 2.0); // beside an edge
    CHECK(distance(ray3{{1, 1, 2}, {0, 0, 1}}, t) == 2.0);
    CHECK(distance(ray3{{1, 1, 2}, {0, 0, -1}}, t) == 0.0);
    CHECK(distance(line3{{-1, 4, 3}, {1, -1, 0}}, t) == 3.0);               // parallel to the face, across it
    CHECK(distance(line3{{10, 10, 10}, {0, 0, 1}}, t) == std::sqrt(128.0)); // the line x = y = 10 and the edge x + y = 4
    const triangle3 u{{0, 0, 3}, {4, 0, 3}, {0, 4, 3}};
    CHECK(distance(t, u) == 3.0);                                                       // parallel faces
    CHECK(distance(t, triangle3{{5, 5, -1}, {5, 5, 1}, {9, 9, 0}}) == std::sqrt(18.0)); // an edge against an edge
    CHECK(distance(t, triangle3{{1, 1, -1}, {1, 1, 1}, {9, 9, 0}}) == 0.0);             // crossing
    const triangle3 flat{{0, 0, 0}, {2, 0, 0}, {4, 0, 0}};                              // collinear: the segment from 0 to 4
    CHECK(distance(point3{3, 4, 0}, flat) == 4.0);
    CHECK(distance(segment3{{5, 0, 0}, {7, 0, 0}}, flat) == 1.0);
    CHECK(std::isnan(distance(t, point3{0, NAN, 0})));
    CHECK(std::isnan(squared_distance(triangle3{{0, 0, INFINITY}, {1, 0, 0}, {0, 1, 0}}, u)));
    const interval c = squared_distance<conservative>(segment3{{1, 1, 2}, {1, 1, 5}}, t);
    CHECK(c.lo <= 4.0);
    CHECK(c.hi >= 4.0);
}

template <class A>
void against_oracle(const char* name, std::uint64_t salt, long n) {
    support::rng r(support::seed() + salt);
    support::distance_tally t{name};
    for (long i = 0; i < 3 * n; ++i) {
        const auto [a, b] = i % 3 == 0   ? support::flat_random<A, triangle3>(r)
                            : i % 3 == 1 ? support::flat_near<A, triangle3>(r)
                                         : support::flat_apart<A, triangle3>(r);
        support::check_flat_distance_case(t, a, b);
    }
    t.report();
}

TEST_CASE("triangle_pairs distances: every tier against the oracle", "[distance][triangle_pairs][oracle]") {
    against_oracle<line3>("line_triangle", 321, support::cases(400));
    against_oracle<point3>("point_triangle", 322, support::cases(1500));
    against_oracle<ray3>("ray_triangle", 323, support::cases(400));
    against_oracle<segment3>("segment_triangle", 324, support::cases(400));
    against_oracle<triangle3>("triangle_triangle", 325, support::cases(400));
}

} // namespace test_query_distance_triangle_pairs
