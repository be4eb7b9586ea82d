// aabb3 x triangle3: fixtures and the CGAL Epeck oracle on 100,000 random and 100,000
// near-degenerate cases (a triangle touching the box at a corner, an edge point or a face point,
// with an edge in a face plane, its plane through a box corner or edge, flat boxes, and a random
// exact-or-nudged scale and translation), plus box-axis symmetries and vertex order.
// contains(aabb, triangle) against CGAL Epeck (each vertex in the Iso_cuboid_3) on 10,000 random
// and 10,000 cases inside, on the boundary from inside or just beyond it.
#include <catch2/catch_test_macros.hpp>
#include <array>
#include <cmath>
#include "testkit/oracle/cgal_oracle.hpp"
import incidence;
import incidence.detail;
#include "testkit/testing.hpp"
#include "testkit/check.hpp"
#include "testkit/obb_cases.hpp"
#include "testkit/contain_checks.hpp"

namespace test_query_aabb_triangle { // this file's names, apart from the files compiled with it (tests/CMakeLists.txt)

using namespace incidence;
using support::arr;

namespace {
const double approx_bound = catalog::approximate_bound("aabb_triangle"); // stated in the catalog (modules/query/catalog.cppm)

std::string describe(const aabb3& b, const triangle3& t) {
    return "box " + support::str(b.min) + support::str(b.max) + " tri " + support::str(t.a) + support::str(t.b) + support::str(t.c);
}
bool truth(const aabb3& b, const triangle3& t) {
    double mn[3], mx[3], a[3], c[3], d[3];
    arr(b.min, mn);
    arr(b.max, mx);
    arr(t.a, a);
    arr(t.b, c);
    arr(t.c, d);
    return oracle::box_triangle(mn, mx, a, c, d);
}
bool skip(const aabb3&, const triangle3& t) {
    double a[3], c[3], d[3];
    arr(t.a, a);
    arr(t.b, c);
    arr(t.c, d);
    return oracle::triangle_is_degenerate(a, c, d);
}

std::pair<aabb3, triangle3> near_case(support::rng& r) {
    using support::small;
    double mn[3], mx[3];
    for (int i = 0; i < 3; ++i) {
        mn[i] = small(r);
        const int flat = r.integer(0, 5); // a flat box along this axis, 1 in 6
        mx[i] = flat == 0 ? mn[i] : mn[i] + r.integer(1, 8) * (r.coin() ? 1.0 : 0.5);
    }
    // a boundary point: each coordinate at min, max, or (for one axis at least not) in between
    double p[3];
    const int on = r.integer(0, 2);
    for (int i = 0; i < 3; ++i) {
        const int how = i == on ? r.integer(0, 1) : r.integer(0, 2);
        p[i] = how == 0 ? mn[i] : (how == 1 ? mx[i] : mn[i] + (mx[i] - mn[i]) * r.integer(0, 4) * 0.25);
    }
    const double out = p[on] == mx[on] ? 1.0 : -1.0;
    auto vec = [&](bool in_plane, bool outward) {
        std::array<double, 3> v{small(r), small(r), small(r)};
        if (in_plane) v[on] = 0;
        else if (outward) v[on] = out * (r.integer(1, 8) + (r.coin() ? 0.0 : 0.25));
        return v;
    };
    double T[3][3];
    const int kind = r.integer(0, 4);
    auto set = [&](int k, const double* base, const std::array<double, 3>& v, double f) {
        for (int i = 0; i < 3; ++i) T[k][i] = base[i] + f * v[i];
    };
    const std::array<double, 3> zero{0, 0, 0};
    if (kind == 0) { // a vertex on the boundary, the rest beyond the face
        set(0, p, zero, 0);
        const auto u = vec(false, true), w = vec(false, true);
        set(1, p, u, 1), set(2, p, w, 1);
    } else if (kind == 1) { // an edge in the face plane, the third vertex beyond it
        const auto w = vec(true, false), u = vec(false, true);
        set(0, p, w, 1), set(1, p, w, -0.5 * r.integer(1, 4)), set(2, p, u, 1);
    } else if (kind == 2) { // the triangle's plane through the boundary point, leaning on it
        const auto w = vec(true, false), u = vec(false, r.coin());
        set(0, p, w, 1), set(1, p, u, 1);
        for (int i = 0; i < 3; ++i) T[2][i] = p[i] - (T[0][i] - p[i]) * 0.5 - (T[1][i] - p[i]) * 0.25;
    } else if (kind == 3) { // a random triangle with a vertex at the boundary point
        set(0, p, zero, 0);
        const auto u = vec(false, false), w = vec(false, false);
        set(1, p, u, 1), set(2, p, w, 1);
    } else { // small random triangle near the box
        for (auto& v : T)
            for (int i = 0; i < 3; ++i) v[i] = p[i] + small(r) * 0.25;
    }
    support::transform tr = support::random_transform(r, true);
    auto P = [&](const double* v) { return point3{tr.apply(v[0], 0), tr.apply(v[1], 1), tr.apply(v[2], 2)}; };
    support::transform exact = tr;
    exact.nudged = false;
    const aabb3 b = support::ordered(aabb3{{exact.apply(mn[0], 0), exact.apply(mn[1], 1), exact.apply(mn[2], 2)},
                                           {exact.apply(mx[0], 0), exact.apply(mx[1], 1), exact.apply(mx[2], 2)}});
    return {b, triangle3{P(T[0]), P(T[1]), P(T[2])}};
}
std::pair<aabb3, triangle3> random_case(support::rng& r) {
    support::transform tr = support::random_transform(r, false);
    auto p = [&] { return point3{support::random_coord(r, tr, 0), support::random_coord(r, tr, 1), support::random_coord(r, tr, 2)}; };
    const aabb3 b = support::ordered(aabb3{p(), p()});
    return {b, triangle3{p(), p(), p()}};
}
} // namespace

TEST_CASE("aabb_triangle: fixtures", "[aabb_triangle]") {
    const aabb3 B{{0, 0, 0}, {1, 1, 1}};
    CHECK(intersects(B, triangle3{{0.5, 0.5, 0.5}, {3, 0, 0}, {0, 3, 0}}));     // a vertex inside
    CHECK(intersects(B, triangle3{{-1, -1, 0.5}, {3, -1, 0.5}, {-1, 3, 0.5}})); // slicing through
    CHECK(intersects(B, triangle3{{1, 1, 1}, {2, 1, 1}, {1, 2, 2}}));           // touching the corner
    CHECK_FALSE(intersects(B, triangle3{{1, 1, std::nextafter(1.0, 2.0)}, {2, 1, 2}, {1, 2, 2}}));
    CHECK(intersects(B, triangle3{{1.5, 0.5, 1}, {0.5, 1.5, 1}, {2, 2, 3}})); // an edge through the top face's corner
    CHECK_FALSE(intersects(B, triangle3{{1.5, 0.5, 1}, {0.5, std::nextafter(1.5, 2.0), 1}, {2, 2, 3}}));
    CHECK(intersects(B, triangle3{{1.5, 0, 0}, {0, 1.5, 0}, {0, 0, 1.5}})); // plane cutting the corner region
    CHECK(intersects(B, triangle3{{2, 0, 0}, {0, 2, 0}, {0, 0, 2}}));       // plane x+y+z=2 meets the box
    CHECK(intersects(B, triangle3{{3, 0, 0}, {0, 3, 0}, {0, 0, 3}}));       // plane x+y+z=3 touches corner (1,1,1)
    CHECK_FALSE(intersects(B, triangle3{{3, 0, std::nextafter(0.0, 1.0)}, {0, 3, std::nextafter(0.0, 1.0)}, {0, 0, 3.0000000000000004}}));
    CHECK_FALSE(intersects(B, triangle3{{2, 0, 0}, {3, 0, 0}, {2, 1, 0}}));              // beside the box
    CHECK_FALSE(intersects(B, triangle3{{1.5, -1, 0.5}, {3, 0.5, 0.5}, {1.5, 2, 0.5}})); // only an edge axis separates
    // flat boxes: a rectangle, a segment, a point
    CHECK(intersects(aabb3{{0, 0, 0}, {1, 1, 0}}, triangle3{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0}}));
    CHECK(intersects(aabb3{{0, 0, 0}, {1, 0, 0}}, triangle3{{0.5, -1, -1}, {0.5, 1, -1}, {0.5, 0, 1}}));
    CHECK(intersects(aabb3{{0.25, 0.25, 0}, {0.25, 0.25, 0}}, triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    CHECK_FALSE(intersects(aabb3{{0.75, 0.75, 0}, {0.75, 0.75, 0}}, triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    CHECK_FALSE(intersects(aabb3{{2, 0, 0}, {1, 1, 1}}, triangle3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})); // inverted box
    CHECK(method::aabb_triangle_sat(B, triangle3{{0.5, 0.5, 0.5}, {3, 0, 0}, {0, 3, 0}}));
    CHECK_FALSE(method::aabb_triangle_sat(B, triangle3{{2, 0, 0}, {3, 0, 0}, {2, 1, 0}}));
}
TEST_CASE("aabb_triangle: oracle, random", "[aabb_triangle][oracle]") {
    support::run_oracle("aabb_triangle random", support::cases(100000), approx_bound, random_case, truth, skip, describe);
}
TEST_CASE("aabb_triangle: oracle, near-degenerate", "[aabb_triangle][oracle]") {
    support::run_oracle("aabb_triangle near-degenerate", support::cases(100000), approx_bound, near_case, truth, skip, describe);
}
TEST_CASE("aabb_triangle: vertex order, axis permutations and mirror images give the same answer", "[aabb_triangle]") {
    support::rng r(support::seed() + 37);
    long n = 0, bad = 0;
    auto perm = [](point3 p, int s) { // one of the 6 axis permutations, then a mirror by the sign bits
        const double c[3] = {p.x, p.y, p.z};
        static constexpr int P[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
        const auto& q = P[s % 6];
        point3 o{c[q[0]], c[q[1]], c[q[2]]};
        if (s & 8) o.x = -o.x;
        if (s & 16) o.y = -o.y;
        if (s & 32) o.z = -o.z;
        return o;
    };
    for (long i = 0; i < support::cases(20000); ++i) {
        auto [b, t] = near_case(r);
        const bool e = intersects(b, t);
        for (const triangle3& t2 : {triangle3{t.b, t.c, t.a}, triangle3{t.c, t.b, t.a}}) {
            ++n;
            if (intersects(b, t2) != e) ++bad;
        }
        const int s = r.integer(0, 63);
        const aabb3 b2 = support::ordered(aabb3{perm(b.min, s), perm(b.max, s)});
        ++n;
        if (intersects(b2, triangle3{perm(t.a, s), perm(t.b, s), perm(t.c, s)}) != e) ++bad;
    }
    std::printf("[cases] aabb_triangle symmetries: %ld, %ld differ\n", n, bad);
    CHECK(bad == 0);
}

// A collinear triangle is the segment between its two extreme vertices along an axis on which they
// differ (coordinate comparisons, exact), or a point: the oracle's segment test.
bool collinear_truth(const aabb3& b, const triangle3& t) {
    const point3 v[3] = {t.a, t.b, t.c};
    int lo = 0, hi = 0;
    for (int k = 0; k < 3 && lo == hi; ++k) {
        auto c = [&](int i) { return k == 0 ? v[i].x : (k == 1 ? v[i].y : v[i].z); };
        for (int i = 1; i < 3; ++i) {
            if (c(i) < c(lo)) lo = i;
            if (c(i) > c(hi)) hi = i;
        }
    }
    double mn[3], mx[3], p[3], q[3];
    arr(b.min, mn);
    arr(b.max, mx);
    arr(v[lo], p);
    arr(v[hi], q);
    return oracle::box_segment(mn, mx, p, q);
}
TEST_CASE("aabb_triangle: the rounded axes never decide against the oracle", "[aabb_triangle][oracle]") {
    // Random cases at every scale and at scale 1, near-degenerate cases (flat boxes included, which
    // the stage must leave alone), the integer grid {-2..2}^3 (exact touching on every kind of
    // axis) and a few non-finite coordinates.
    support::rng r(support::seed() + 11), one(support::seed() + 12);
    one.at_scale_one = true;
    long n = 0, decided = 0, one_n = 0, one_decided = 0, wrong = 0;
    for (long i = 0; i < support::cases(100000); ++i) {
        const int kind = int(i % 4);
        auto [b, t] = kind == 0   ? random_case(r)
                      : kind == 1 ? random_case(one)
                      : kind == 2 ? near_case(r)
                                  : [&] {
                                        auto g = [&] { return double(r.integer(-2, 2)); };
                                        auto p = [&] { return point3{g(), g(), g()}; };
                                        return std::pair{support::ordered(aabb3{p(), p()}), triangle3{p(), p(), p()}};
                                    }();
        if (r.integer(0, 199) == 0) t.b.z = r.coin() ? std::nan("") : (r.coin() ? 1.0 : -1.0) * INFINITY;
        const point3 v[3] = {t.a, t.b, t.c};
        const certainty fast = detail::box_triangle::rounded_axes_decide(b, v);
        ++n;
        one_n += kind == 1;
        if (fast == certainty::uncertain) continue;
        ++decided;
        one_decided += kind == 1;
        if (!(std::isfinite(t.b.z))) { // no shape: never a yes (the exact tier says no)
            wrong += fast == certainty::yes;
            continue;
        }
        if ((fast == certainty::yes) != (skip(b, t) ? collinear_truth(b, t) : truth(b, t))) {
            if (++wrong <= 5) std::printf("  rounded axes wrong: %s\n", describe(b, t).c_str());
        }
    }
    std::printf("[cases] aabb_triangle rounded axes: %ld cases, %ld decided (%ld of %ld random at scale 1), wrong %ld\n", n, decided,
                one_decided, one_n, wrong);
    CHECK(wrong == 0);
    CHECK(one_decided > one_n * 9 / 10);
}
TEST_CASE("aabb_triangle: contains(aabb, triangle)", "[aabb_triangle][oracle]") {
    support::contains_oracle<aabb3, triangle3>(
        "aabb_triangle (aabb around triangle)", support::cases(10000), approx_bound,
        [](support::rng& r) {
            const auto tr = support::random_transform(r, false);
            return std::pair{support::random_aabb(r, tr),
                             triangle3{support::random_point(r, tr), support::random_point(r, tr), support::random_point(r, tr)}};
        },
        support::aabb_holding<triangle3>, true);
}

} // namespace test_query_aabb_triangle
