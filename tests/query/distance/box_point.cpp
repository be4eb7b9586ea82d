// squared_distance and max_squared_distance of a box and a point, in every tier, against exact
// squared distances over CGAL Epeck (testkit/oracle/cgal_oracle.cpp): the exact tier correctly
// rounded, the conservative and aggressive intervals containing the exact value, on 100,000 random
// pairs at every scale and a regression case.
#include <catch2/catch_test_macros.hpp>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/lp_shapes.hpp"
#include "testkit/flat_checks.hpp"
#include "testkit/ball_halfspace_checks.hpp"
#include "testkit/distance_checks.hpp"

namespace test_query_distance_box_point {

using namespace incidence;

// The regression of the architecture issue: squared_distance<conservative> of this point and box
// returned an interval whose upper end lay 9.7e-51 below the exact value. The class it stands for:
// s + e rounded to nearest (not upward), an error bound one operation short (gamma_4 for five
// roundings), at every magnitude; the new enclosure rounds every end outward.
TEST_CASE("squared_distance: the intervals contain the exact value (regression, and the class of it)", "[squared_distance][oracle]") {
    const point3 p{0x1.f4cdd89a78f92p-56, -0x1.52904e1d81808p-58, -0x1.39fa10a093536p-56};
    const aabb3 b{{-0x1.e462b26872b88p-60, -0x1.1e463e281f4b2p-57, -0x1.a2da2abed215ap-58},
                  {-0x1.bc1f6fb431cep-61, -0x1.0446bc0b5b806p-57, 0x1.ac2f56e46f9c6p-57}};
    double P[3], mn[3], mx[3];
    support::arr(p, P), support::arr(b.min, mn), support::arr(b.max, mx);
    const interval c = squared_distance<conservative>(b, p);
    CHECK(oracle::interval_contains_point_box_sqdist(P, mn, mx, false, c.lo, c.hi));
    CHECK(oracle::is_rounded_point_box_sqdist(P, mn, mx, false, squared_distance(b, p)));
    support::rng r(support::seed() + 78);
    long n = 0, bad = 0, not_rounded = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        support::transform tr = support::random_transform(r, false);
        auto q = [&](int k) { return support::random_coord(r, tr, k); };
        const point3 x{q(0), q(1), q(2)};
        const aabb3 box = support::ordered(aabb3{{q(0), q(1), q(2)}, {q(0), q(1), q(2)}});
        if (!is_finite(x) || !is_finite(box.min) || !is_finite(box.max)) continue;
        support::arr(x, P), support::arr(box.min, mn), support::arr(box.max, mx);
        for (bool far : {false, true}) {
            ++n;
            const interval v = far ? max_squared_distance<aggressive>(box, x) : squared_distance<conservative>(box, x);
            if (!oracle::interval_contains_point_box_sqdist(P, mn, mx, far, v.lo, v.hi) && ++bad <= 5)
                std::printf("  [%a, %a] misses the squared distance of %s to %s\n", v.lo, v.hi, support::str(x).c_str(),
                            (support::str(box.min) + support::str(box.max)).c_str());
            const double e = far ? max_squared_distance(box, x) : squared_distance(box, x);
            if (!oracle::is_rounded_point_box_sqdist(P, mn, mx, far, e)) ++not_rounded;
        }
    }
    std::printf("[cases] squared_distance intervals: %ld cases, %ld not enclosed, %ld exact not correctly rounded\n", n, bad, not_rounded);
    CHECK(bad == 0);
    CHECK(not_rounded == 0);
}

TEST_CASE("signed_distance: a box and a point, every tier against the exact QP and rows", "[signed_distance][oracle]") {
    const aabb3 b{{0, 0, 0}, {1, 2, 3}};
    CHECK(signed_distance(b, point3{3, 4, 4}) == 3.0);
    CHECK(signed_distance(point3{0.5, 0.25, 1}, b) == -0.25);
    CHECK(signed_distance(b, point3{1, 1, 1}) == 0.0);
    CHECK(signed_distance(aabb3{{0, 0, 0}, {0, 2, 3}}, point3{0, 1, 1}) == 0.0); // a flat box has no inside
    CHECK(std::isnan(signed_distance(aabb3{{1, 0, 0}, {0, 2, 3}}, point3{0, 1, 1})));
    // random boxes and points, half of them inside, and points on a face, an edge or a corner,
    // nudged by ulps, at every scale
    support::distance_oracle<aabb3>(
        "aabb_point distances", support::cases(10000), 79,
        [](support::rng& r, bool near) -> std::optional<std::pair<aabb3, point3>> {
            support::transform tr = support::random_transform(r, near, true);
            auto q = [&](int k) { return support::random_coord(r, tr, k); };
            const aabb3 box = support::ordered(aabb3{{q(0), q(1), q(2)}, {q(0), q(1), q(2)}});
            point3 x{q(0), q(1), q(2)};
            if (r.coin())
                x = {box.min.x + (box.max.x - box.min.x) * r.uniform(0, 1), box.min.y + (box.max.y - box.min.y) * r.uniform(0, 1),
                     box.min.z + (box.max.z - box.min.z) * r.uniform(0, 1)};
            if (near) { // on a face, an edge or a corner, then nudged
                const double lo[3] = {box.min.x, box.min.y, box.min.z}, hi[3] = {box.max.x, box.max.y, box.max.z};
                double c[3] = {x.x, x.y, x.z};
                for (int k = 0; k < 3; ++k)
                    if (r.coin()) c[k] = support::nudge(r.coin() ? lo[k] : hi[k], r.integer(-1, 1));
                x = {c[0], c[1], c[2]};
            }
            if (!is_finite(x) || !is_finite(box.min) || !is_finite(box.max)) return std::nullopt;
            return std::pair{box, x};
        },
        [](const aabb3& box) { return oracle::distance_solid{oracle::distance_solid::rows, {}, support::lp(box)}; },
        [](const aabb3& box) { return support::shape_str(box); });
}

TEST_CASE("obb_point: squared and signed distance, every tier against the exact QP and faces", "[signed_distance][oracle]") {
    // the box [0, 1] x [0, 2] x [0, 3] as an oriented box with permuted axes, and a skew one
    const obb3 b{{0.5, 1, 1.5}, {vec3{0, 1, 0}, vec3{0, 0, 1}, vec3{1, 0, 0}}, {1, 1.5, 0.5}};
    CHECK(signed_distance(b, point3{3, 4, 4}) == 3.0);
    CHECK(signed_distance(point3{0.5, 0.25, 1}, b) == -0.25);
    CHECK(signed_distance(b, point3{1, 1, 1}) == 0.0);
    CHECK(squared_distance(b, point3{4, 6, 1}) == 25.0);
    CHECK(squared_distance(b, point3{0.5, 0.25, 1}) == 0.0);
    const obb3 skew{{0, 0, 0}, {vec3{1, 0, 0}, vec3{1, 1, 0}, vec3{0, 0, 1}}, {1, 1, 1}}; // x - y in [-1, 1], y in [-1, 1]
    CHECK(signed_distance(skew, point3{0, 0, 3}) == 2.0);
    CHECK(signed_distance(skew, point3{0, 0, 0}) == static_cast<double>(-1.0L / std::sqrt(2.0L)));
    CHECK(signed_distance(obb3{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, 1, 0}}, point3{0.5, 0, 0}) == 0.0); // flat
    CHECK(std::isnan(signed_distance(obb3{{0, 0, 0}, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}, {1, -1, 1}}, point3{0, 0, 0})));
    support::distance_oracle<obb3>(
        "obb_point distances", support::cases(3000), 81,
        [](support::rng& r, bool near) -> std::optional<std::pair<obb3, point3>> {
            const auto c = near ? support::ball_near<obb3>(r) : support::ball_random<obb3>(r);
            if (!c) return std::nullopt;
            return std::pair{c->first, c->second.center};
        },
        [](const obb3& box) { return oracle::distance_solid{oracle::distance_solid::rows, {}, support::lp(box)}; },
        [](const obb3& box) { return support::shape_str(box); });
}

} // namespace test_query_distance_box_point
