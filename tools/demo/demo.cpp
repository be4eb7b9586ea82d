// incidence-demo: for each query family, the four tiers' answers on touching and nearly
// touching cases next to the true answer (CGAL Epeck), then a small speed table measured in this
// run (median of 7 repetitions, ns per test) on random and near-degenerate inputs.
#include "testkit/oracle/cgal_oracle.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>
import incidence;

using namespace incidence;

namespace {
const char* yn(bool b) { return b ? "yes" : "no"; }
const char* cert(certainty c) { return c == certainty::yes ? "yes" : (c == certainty::no ? "no" : "uncertain"); }
void arr(point3 p, double* o) {
    o[0] = p.x;
    o[1] = p.y;
    o[2] = p.z;
}
void arr(vec3 p, double* o) {
    o[0] = p.x;
    o[1] = p.y;
    o[2] = p.z;
}

int mismatches = 0;
template <class A, class B>
void row(const char* what, const A& a, const B& b, bool truth) {
    const bool e = intersects<exact>(a, b), c = intersects<conservative>(a, b), g = intersects<aggressive>(a, b),
               x = intersects<approximate>(a, b);
    if (e != truth) ++mismatches;
    std::printf("  %-46s %-6s %-12s %-11s %-12s %-10s %s\n", what, yn(truth), yn(e), yn(c), yn(g), yn(x), cert(classify(a, b)));
}
void header(const char* family) {
    std::printf("\n%s\n  %-46s %-6s %-12s %-11s %-12s %-10s %s\n", family, "case", "true", "exact", "conservative", "aggressive", "approx",
                "classify");
}

double median_ns(const std::function<long()>& run, long n) {
    std::vector<double> t;
    for (int rep = 0; rep < 7; ++rep) {
        const auto t0 = std::chrono::steady_clock::now();
        volatile long sink = run();
        (void)sink;
        const auto t1 = std::chrono::steady_clock::now();
        t.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / static_cast<double>(n));
    }
    std::sort(t.begin(), t.end());
    return t[3];
}
} // namespace

int main() {
    std::printf("incidence demo: tiers on touching and near-touching cases (true answer from CGAL Epeck)\n");
    const double up = std::nextafter(1.0, 2.0), dn = std::nextafter(1.0, 0.0);
    {
        header("ray x triangle (closed triangle; approximate = watertight, Woop-Benthin-Wald 2013)");
        const triangle3 T{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        auto truth = [&](const ray3& r) {
            double o[3], d[3], a[3], b[3], c[3];
            arr(r.origin, o);
            arr(r.direction, d);
            arr(T.a, a);
            arr(T.b, b);
            arr(T.c, c);
            return oracle::ray_triangle(o, d, a, b, c);
        };
        const ray3 cases[] = {{{0.5, 0, 1}, {0, 0, -1}},   {{1, 0, 1}, {0, 0, -1}},
                              {{0.5, 0.5, 1}, {0, 0, -1}}, {{0.5, std::nextafter(0.5, 1.0), 1}, {0, 0, -1}},
                              {{-1, 0.5, 0}, {1, 0, 0}},   {{0.1, 0.2, 0.3}, {-0.3, 0.1, -0.9}}};
        const char* names[] = {"through the middle of an edge",     "through a vertex",
                               "through the hypotenuse (0.5, 0.5)", "one ulp outside the hypotenuse",
                               "coplanar, crossing the triangle",   "0.1/0.2/0.3 coordinates"};
        for (int i = 0; i < 6; ++i) row(names[i], cases[i], T, truth(cases[i]));
    }
    {
        header("ray x aabb (closed box; approximate = slab method)");
        const aabb3 B{{0, 0, 0}, {1, 1, 1}};
        auto truth = [&](const ray3& r) {
            double o[3], d[3], mn[3], mx[3];
            arr(r.origin, o);
            arr(r.direction, d);
            arr(B.min, mn);
            arr(B.max, mx);
            return oracle::ray_box(o, d, mn, mx);
        };
        const ray3 cases[] = {{{-1, 1, 0.5}, {1, 0, 0}},
                              {{-1, 1, 1}, {1, 0, 0}},
                              {{2, 1, 0}, {-1, -1, 0}},
                              {{std::nextafter(2.0, 3.0), 1, 0}, {-1, -1, 0}},
                              {{-1, up, 0.5}, {1, 0, 0}}};
        const char* names[] = {"along a face", "along an edge", "touching an edge only", "one ulp beside that edge",
                               "one ulp above the top face"};
        for (int i = 0; i < 5; ++i) row(names[i], B, cases[i], truth(cases[i]));
    }
    {
        header("ray x sphere (solid ball; approximate = geometric method, RTR4 22.6.2)");
        const sphere3 S{{0, 0, 0}, 1};
        auto truth = [&](const ray3& r) {
            double o[3], d[3], c[3];
            arr(r.origin, o);
            arr(r.direction, d);
            arr(S.center, c);
            return oracle::ray_ball(o, d, c, S.radius);
        };
        const ray3 cases[] = {{{-5, 1, 0}, {1, 0, 0}}, {{-5, up, 0}, {1, 0, 0}}, {{-5, dn, 0}, {1, 0, 0}}, {{1, 0, 0}, {1, 0, 0}}};
        const char* names[] = {"tangent at (0, 1, 0)", "one ulp outside the tangent", "one ulp inside the tangent",
                               "origin on the sphere, leaving"};
        for (int i = 0; i < 4; ++i) row(names[i], cases[i], S, truth(cases[i]));
    }
    {
        header("sphere x sphere, point x sphere, aabb x aabb");
        auto bb = [](const sphere3& a, const sphere3& b) {
            double c1[3], c2[3];
            arr(a.center, c1);
            arr(b.center, c2);
            return oracle::ball_ball(c1, a.radius, c2, b.radius);
        };
        const sphere3 a{{0, 0, 0}, 1}, b{{2, 0, 0}, 1}, c{{std::nextafter(2.0, 3.0), 0, 0}, 1};
        const sphere3 d{{0.1, 0.2, 0.3}, 0.5}, e{{0.6, 0.2, 0.3}, 0.0};
        row("tangent balls", a, b, bb(a, b));
        row("one ulp apart", a, c, bb(a, c));
        row("0.1 + 0.5 = 0.6 touching (inexact decimals)", d, e, bb(d, e));
        const point3 p{1, 2, 2};
        const sphere3 s3{{0, 0, 0}, 3};
        double pa[3], ca[3];
        arr(p, pa);
        arr(s3.center, ca);
        row("point (1,2,2) on the sphere of radius 3", p, s3, oracle::point_in_ball(pa, ca, 3));
        const aabb3 b1{{0, 0, 0}, {1, 1, 1}}, b2{{1, 1, 1}, {2, 2, 2}};
        row("boxes touching at a corner", b1, b2, true);
    }
    std::printf("\nexact tier disagreements with CGAL Epeck above: %d\n", mismatches);

    // Speed: ns per test, median of 7 runs over 4096 cases.
    std::mt19937_64 g(20261122);
    std::uniform_real_distribution<double> u(-1, 1);
    const int n = 4096;
    std::vector<ray3> rays(n), near_rays(n);
    std::vector<triangle3> tris(n), near_tris(n);
    std::vector<aabb3> boxes(n);
    for (int i = 0; i < n; ++i) {
        const point3 a{u(g), u(g), u(g)}, b{u(g), u(g), u(g)}, c{u(g), u(g), u(g)}, o{u(g), u(g), u(g)};
        tris[i] = {a, b, c};
        rays[i] = {o, vec3{a.x - o.x + u(g) * 0.3, a.y - o.y + u(g) * 0.3, a.z - o.z + u(g) * 0.3}};
        point3 lo{u(g), u(g), u(g)}, hi{u(g), u(g), u(g)};
        boxes[i] = {{std::min(lo.x, hi.x), std::min(lo.y, hi.y), std::min(lo.z, hi.z)},
                    {std::max(lo.x, hi.x), std::max(lo.y, hi.y), std::max(lo.z, hi.z)}};
        // near-degenerate: aimed exactly at the midpoint of an edge of a triangle with dyadic vertices
        const point3 A{std::round(a.x * 8) / 8, std::round(a.y * 8) / 8, std::round(a.z * 8) / 8};
        const point3 B{std::round(b.x * 8) / 8, std::round(b.y * 8) / 8, std::round(b.z * 8) / 8};
        const point3 C{std::round(c.x * 8) / 8 + 0.0625, std::round(c.y * 8) / 8, std::round(c.z * 8) / 8};
        const point3 O{std::round(o.x * 8) / 8 + 2, std::round(o.y * 8) / 8, std::round(o.z * 8) / 8};
        near_tris[i] = {A, B, C};
        near_rays[i] = {O, point3{(A.x + B.x) / 2, (A.y + B.y) / 2, (A.z + B.z) / 2} - O};
    }
    std::printf("\nspeed, ns per test (median of 7 runs over %d cases, this machine, this run)\n", n);
    std::printf("  %-34s %10s %14s %12s %12s %12s\n", "query / inputs", "exact", "conservative", "aggressive", "approximate", "CGAL Epick");
    auto line = [&](const char* name, auto&& xs, auto&& ys, auto&& epick) {
        auto t = [&](auto tier) {
            return median_ns(
                [&] {
                    long s = 0;
                    for (int i = 0; i < n; ++i) s += intersects<decltype(tier)>(xs[i], ys[i]);
                    return s;
                },
                n);
        };
        const double ep = median_ns(
            [&] {
                long s = 0;
                for (int i = 0; i < n; ++i) s += epick(xs[i], ys[i]);
                return s;
            },
            n);
        std::printf("  %-34s %10.1f %14.1f %12.1f %12.1f %12.1f\n", name, t(exact{}), t(conservative{}), t(aggressive{}), t(approximate{}),
                    ep);
    };
    auto epick_rt = [](const ray3& r, const triangle3& t) {
        double o[3], d[3], a[3], b[3], c[3];
        arr(r.origin, o);
        arr(r.direction, d);
        arr(t.a, a);
        arr(t.b, b);
        arr(t.c, c);
        return oracle::ray_triangle_epick(o, d, a, b, c);
    };
    auto epick_rb = [](const aabb3& b, const ray3& r) {
        double o[3], d[3], mn[3], mx[3];
        arr(r.origin, o);
        arr(r.direction, d);
        arr(b.min, mn);
        arr(b.max, mx);
        return oracle::ray_box_epick(o, d, mn, mx);
    };
    line("ray x triangle, random", rays, tris, epick_rt);
    line("ray x triangle, edge hits (exact)", near_rays, near_tris, epick_rt);
    line("ray x aabb, random", boxes, rays, epick_rb);
    std::printf("\n(The full benchmark suite: ./run.sh bench, timings in bench.json.)\n");
    return mismatches == 0 ? 0 : 1;
}
