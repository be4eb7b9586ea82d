// ray3 x sphere3 (ball): every tier against the CGAL Epeck oracle (exact squared distance of
// the ray to the centre against r^2) on 100,000 random and 100,000 near-degenerate cases:
// tangent rays, rays through exact surface points, origins exactly on the sphere; plus the
// exact tier's correctly rounded first-hit parameter.
#include <catch2/catch_test_macros.hpp>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/sphere_points.hpp"

namespace test_query_ray_sphere { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("ray_sphere"); // stated in the catalog (modules/query/catalog.cppm)

std::string describe(const ray3& r, const sphere3& s) {
    return "ray " + support::str(r.origin) + " dir " + support::str(r.direction) + " ball " + support::str(s.center) + " r " +
           support::hex(s.radius);
}
bool truth(const ray3& r, const sphere3& s) {
    double o[3], d[3], c[3];
    arr(r.origin, o);
    arr(r.direction, d);
    arr(s.center, c);
    return oracle::ray_ball(o, d, c, s.radius);
}
bool skip(const ray3& r, const sphere3&) { return r.direction == vec3{0, 0, 0}; }

std::pair<ray3, sphere3> near_case(support::rng& r) {
    using support::small;
    const double C[3] = {small(r), small(r), small(r)};
    const auto q = support::pythagorean(r);
    const double k = r.integer(1, 4);
    const double on[3] = {C[0] + k * q.x, C[1] + k * q.y, C[2] + k * q.z}; // exactly on the sphere
    double O[3], D[3];
    const int kind = r.integer(0, 2);
    if (kind == 0) { // tangent: move along a direction perpendicular to (q.x, q.y, q.z)
        const double t[3] = {q.y, -q.x, 0.0};
        const double m = r.integer(1, 3);
        for (int i = 0; i < 3; ++i) {
            O[i] = on[i] - m * t[i];
            D[i] = t[i];
        }
        if (q.x == 0 && q.y == 0) {
            O[0] = on[0] - m;
            O[1] = on[1];
            O[2] = on[2];
            D[0] = 1;
            D[1] = 0;
            D[2] = 0;
        }
    } else if (kind == 1) { // aimed at an exact surface point
        for (int i = 0; i < 3; ++i) {
            O[i] = small(r) * 3;
            D[i] = on[i] - O[i];
        }
    } else { // origin on the sphere
        for (int i = 0; i < 3; ++i) {
            O[i] = on[i];
            D[i] = small(r);
        }
    }
    if (r.integer(0, 7) == 0)
        for (double& di : D) di = -di;
    support::transform tr = support::random_transform(r, true);
    return {ray3{{tr.apply(O[0], 0), tr.apply(O[1], 1), tr.apply(O[2], 2)}, {tr.dir(D[0]), tr.dir(D[1]), tr.dir(D[2])}},
            sphere3{{tr.apply(C[0], 0), tr.apply(C[1], 1), tr.apply(C[2], 2)}, tr.scale_only(k * q.w)}};
}
std::pair<ray3, sphere3> random_case(support::rng& r) {
    support::transform tr = support::random_transform(r, false);
    auto c = [&](int i) { return support::random_coord(r, tr, i); };
    return {ray3{{c(0), c(1), c(2)}, {tr.scale_only(r.uniform(-1, 1)), tr.scale_only(r.uniform(-1, 1)), tr.scale_only(r.uniform(-1, 1))}},
            sphere3{{c(0), c(1), c(2)}, tr.scale_only(r.uniform(0, 0.7))}};
}
} // namespace

TEST_CASE("ray_sphere: fixtures (solid ball, tangent counts)", "[ray_sphere]") {
    const sphere3 S{{0, 0, 0}, 1};
    CHECK(intersects(ray3{{-5, 0, 0}, {1, 0, 0}}, S));
    CHECK(intersects(ray3{{-5, 1, 0}, {1, 0, 0}}, S)); // tangent
    CHECK_FALSE(intersects(ray3{{-5, 1.0000000001, 0}, {1, 0, 0}}, S));
    CHECK_FALSE(intersects(ray3{{-5, 0, 0}, {-1, 0, 0}}, S));
    CHECK(intersects(ray3{{0, 0, 0}, {-1, 0, 0}}, S)); // origin inside
    CHECK(intersects(ray3{{1, 0, 0}, {1, 0, 0}}, S));  // origin on the surface, leaving
    const auto h = intersection(ray3{{-5, 0, 0}, {2, 0, 0}}, S);
    REQUIRE(h);
    CHECK(h->t_enter == 2.0);
    CHECK(h->t_exit == 3.0);
    CHECK(h->point == point3{-1, 0, 0});
    const auto tangent = intersection(ray3{{-5, 1, 0}, {1, 0, 0}}, S);
    REQUIRE(tangent);
    CHECK(tangent->t_enter == 5.0);
    CHECK(tangent->t_exit == 5.0);
    CHECK(tangent->point == point3{0, 1, 0});
    CHECK(intersection(ray3{{0.5, 0, 0}, {1, 0, 0}}, S)->t_enter == 0.0);
    CHECK(intersection(ray3{{0.5, 0, 0}, {1, 0, 0}}, S)->t_exit == 0.5);
}
TEST_CASE("ray_sphere: oracle, random", "[ray_sphere][oracle]") {
    support::run_oracle("ray_sphere random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("ray_sphere: oracle, near-degenerate", "[ray_sphere][oracle]") {
    support::run_oracle("ray_sphere near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}
TEST_CASE("ray_sphere: exact first hit is correctly rounded; algebraic method against the oracle", "[ray_sphere]") {
    support::rng r(support::seed() + 5);
    long checked = 0, bad = 0, algebraic_wrong = 0, algebraic_outside = 0;
    for (long i = 0; i < support::cases(20000); ++i) {
        auto [ray, s] = (i % 2) ? near_case(r) : random_case(r);
        if (skip(ray, s)) continue;
        const bool t = truth(ray, s);
        if (method::ray_sphere_algebraic(ray, s).has_value() != t) {
            ++algebraic_wrong;
            support_margin::margin_kernel mk;
            (void)detail::intersects(mk, ray, s);
            if (mk.min_rel > approx_bound) ++algebraic_outside;
        }
        const auto h = intersection(ray, s);
        if (!h) continue;
        double o[3], d[3], c[3];
        arr(ray.origin, o);
        arr(ray.direction, d);
        arr(s.center, c);
        ++checked;
        if (!oracle::is_rounded_ray_ball_t(o, d, c, s.radius, h->t_enter) && ++bad <= 5)
            std::printf("  t %a not correctly rounded: %s\n", h->t_enter, describe(ray, s).c_str());
    }
    std::printf("[cases] ray_sphere exact t: %ld hits checked, %ld not correctly rounded; algebraic method wrong %ld, outside bound %ld\n",
                checked, bad, algebraic_wrong, algebraic_outside);
    CHECK(bad == 0);
    CHECK(algebraic_outside == 0);
}

} // namespace test_query_ray_sphere
