// squared_distance and signed_distance of a point and a ball (sphere3) or a capsule: fixtures
// (outside, inside, at the centre, exactly on the sphere from a Pythagorean quadruple and one ulp
// off it, a capsule's ends and side, a negative radius, NaN), then every tier against the exact
// values over CGAL Epeck (testkit/oracle/cgal_distance.cpp: the core's squared distance, then
// sqrt(Q) - |r|) on 20,000 random and 20,000 near-degenerate cases each: balls through a point built
// from Pythagorean quadruples, kept, nudged by ulps or moved, and capsules touching a point at an
// end or along the side (testkit/capsule_cases.hpp); then a random exact-or-nudged scale
// 2^-500..2^500 and translation.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/capsule_checks.hpp"
#include "testkit/distance_checks.hpp"

namespace test_query_distance_ball_point {

using namespace incidence;

TEST_CASE("ball_point: fixtures", "[distance][ball_point]") {
    const sphere3 s{{1, 2, 3}, 3};
    CHECK(signed_distance(point3{1, 2, 8}, s) == 2.0);
    CHECK(squared_distance(point3{1, 2, 8}, s) == 4.0);
    CHECK(signed_distance(s, point3{1, 2, 3}) == -3.0); // the centre
    CHECK(squared_distance(s, point3{1, 2, 3}) == 0.0);
    CHECK(signed_distance(point3{2, 4, 5}, s) == 0.0); // (1, 2, 2): on the sphere
    CHECK(squared_distance(point3{2, 4, 5}, s) == 0.0);
    const double off = std::nextafter(5.0, 6.0);
    CHECK(signed_distance(point3{2, 4, off}, s) > 0.0);
    CHECK(signed_distance(point3{2, 4, std::nextafter(5.0, 4.0)}, s) < 0.0);
    CHECK(signed_distance(point3{1, 2, 8}, sphere3{{1, 2, 3}, -3}) == 2.0); // an unchecked negative radius acts as |r|
    CHECK(std::isnan(signed_distance(point3{NAN, 0, 0}, s)));
    CHECK(std::isnan(squared_distance(point3{0, 0, 0}, sphere3{{0, 0, 0}, INFINITY})));
    const interval c = signed_distance<conservative>(point3{1, 2, 8}, s);
    CHECK(c.lo <= 2.0);
    CHECK(c.hi >= 2.0);
    CHECK(signed_distance<approximate>(point3{1, 2, 8}, s) == 2.0);

    const capsule3 k{{0, 0, 0}, {4, 0, 0}, 1};
    CHECK(signed_distance(k, point3{2, 3, 0}) == 2.0);  // beside the segment
    CHECK(signed_distance(k, point3{7, 0, 4}) == 4.0);  // beyond b: |(3, 0, 4)| - 1
    CHECK(signed_distance(k, point3{-1, 0, 0}) == 0.0); // the end cap
    CHECK(signed_distance(k, point3{2, 0, 0.5}) == -0.5);
    CHECK(squared_distance(k, point3{7, 0, 4}) == 16.0);
    CHECK(squared_distance(point3{2, 0, 0.5}, k) == 0.0);
    CHECK(signed_distance(capsule3{{1, 1, 1}, {1, 1, 1}, 2}, point3{1, 1, 4}) == 1.0); // a = b: a ball
}

namespace {
// A ball through a point: p = c + k (a, b, e) with a^2 + b^2 + e^2 = d^2 and radius k d (exact),
// then the radius kept, nudged by ulps or scaled by 1 -+ 2^-40, or the point at the centre.
std::optional<std::pair<sphere3, point3>> ball_near(support::rng& r) {
    static constexpr int quads[][4] = {{1, 2, 2, 3},  {2, 3, 6, 7},   {1, 4, 8, 9},    {4, 4, 7, 9},   {2, 6, 9, 11},
                                       {6, 6, 7, 11}, {3, 4, 12, 13}, {2, 10, 11, 15}, {1, 12, 12, 17}};
    const auto& q = quads[r.integer(0, 8)];
    const double k = std::ldexp(static_cast<double>(r.integer(1, 9)), r.integer(-3, 3));
    double v[3] = {q[0] * k, q[1] * k, q[2] * k};
    for (double& x : v)
        if (r.coin()) x = -x;
    const point3 c = support::small_point(r);
    point3 p{c.x + v[0], c.y + v[1], c.z + v[2]};
    double rad = q[3] * k;
    switch (r.integer(0, 5)) {
    case 0: rad = support::nudge(rad, r.integer(-2, 2)); break;
    case 1: rad *= r.coin() ? 1 + 0x1p-40 : 1 - 0x1p-40; break;
    case 2: p = c; break;
    default: break;
    }
    support::transform tr = support::random_transform(r, true, true);
    const sphere3 s = support::realise(sphere3{c, rad}, tr);
    const point3 m = support::moved(p, tr);
    if (!is_finite(s.center) || !std::isfinite(s.radius) || !is_finite(m)) return std::nullopt;
    return std::pair{s, m};
}
std::optional<std::pair<sphere3, point3>> ball_random(support::rng& r) {
    support::transform tr = support::random_transform(r, false, true);
    auto u = [&] { return point3{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)}; };
    const sphere3 s = support::realise(sphere3{u(), r.uniform(0, 1)}, tr);
    const point3 p = support::moved(u(), tr);
    if (!is_finite(s.center) || !std::isfinite(s.radius) || !is_finite(p)) return std::nullopt;
    return std::pair{s, p};
}
oracle::distance_solid solid(const sphere3& s) {
    return {oracle::distance_solid::capsule, {s.center.x, s.center.y, s.center.z, s.center.x, s.center.y, s.center.z, s.radius}, {}};
}
oracle::distance_solid solid(const capsule3& c) {
    return {oracle::distance_solid::capsule, {c.a.x, c.a.y, c.a.z, c.b.x, c.b.y, c.b.z, c.radius}, {}};
}
} // namespace

TEST_CASE("ball_point: every tier against the exact distances over Epeck", "[distance][ball_point][oracle]") {
    support::distance_oracle<sphere3>(
        "point_sphere distances", support::cases(20000), 211,
        [](support::rng& r, bool near) { return near ? ball_near(r) : ball_random(r); }, [](const sphere3& s) { return solid(s); },
        [](const sphere3& s) { return support::shape_str(s); });
    support::distance_oracle<capsule3>(
        "capsule_point distances", support::cases(20000), 212,
        [](support::rng& r, bool near) { return near ? support::capsule_near<point3>(r) : support::capsule_random<point3>(r); },
        [](const capsule3& c) { return solid(c); }, [](const capsule3& c) { return support::shape_str(c); });
}

} // namespace test_query_distance_ball_point
