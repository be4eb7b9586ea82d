// Benchmarks: ray-triangle, ray-box, orient3d, the sphere pairs and box-point, with the classic double methods and CGAL beside.
#include "bench.hpp"
#include "testkit/contain_cases.hpp"

namespace bench {
namespace {
// orient3d(a, b, c, d) = det[a - d; b - d; c - d] behind the semi-static filter with CGAL's error
// constant (5.1107127829973299e-15 times the largest |difference| of each coordinate, trusted
// while those lie in [1e-97, 1e102]: Pion's static filters, CGAL's Filtered_kernel
// Static_filters/Orientation_3.h), the exact tier where it is not certain. The cheapest published
// rigorous filter for orient3d: what any filter costs beside plain double, measured in one run
// with exact/ and approximate/orient3d.
[[gnu::always_inline]] inline sign orient3d_static_filter(point3 a, point3 b, point3 c, point3 d) {
    const double u[3] = {a.x - d.x, a.y - d.y, a.z - d.z}, v[3] = {b.x - d.x, b.y - d.y, b.z - d.z},
                 w[3] = {c.x - d.x, c.y - d.y, c.z - d.z};
    double m[3];
    for (int k = 0; k < 3; ++k) {
        const double x = std::abs(u[k]), y = std::abs(v[k]), z = std::abs(w[k]);
        m[k] = x < y ? (y < z ? z : y) : (x < z ? z : x);
    }
    const double det = u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
    const double eps = 5.1107127829973299e-15 * m[0] * m[1] * m[2];
    const double lo = std::min({m[0], m[1], m[2]}), hi = std::max({m[0], m[1], m[2]});
    if (lo >= 1e-97 && hi < 1e102) {
        if (det > eps) return sign::positive;
        if (det < -eps) return sign::negative;
    }
    return orient3d(a, b, c, d);
}
} // namespace

void register_classic_rays(bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    {
        const auto cs = ray_triangle_set(near);
        auto truth = [](const rt& c) {
            double o[3], d[3], a[3], b[3], cc[3];
            arr(c.r.origin, o);
            arr(c.r.direction, d);
            arr(c.t.a, a);
            arr(c.t.b, b);
            arr(c.t.c, cc);
            return oracle::ray_triangle(o, d, a, b, cc);
        };
        tiers("ray_triangle", dist, cs, truth, [](auto tier, const rt& c) { return intersects<decltype(tier)>(c.r, c.t); });
        std::vector<bool> t;
        for (const auto& c : cs) t.push_back(truth(c));
        reg("classify/intersects/ray_triangle/" + dist, cs, t, check::classify, [](const rt& c) { return classify(c.r, c.t); });
        reg("moller_trumbore/intersects/ray_triangle/" + dist, cs, t, check::approximate,
            [](const rt& c) { return method::ray_triangle_moller_trumbore(c.r, c.t).has_value(); });
        reg("sign_algorithm_double/intersects/ray_triangle/" + dist, cs, t, check::approximate, [](const rt& c) {
            arith::approx_kernel k;
            return detail::intersects(k, c.r, c.t);
        });
        reg("exact/intersection_has_value/ray_triangle/" + dist, cs, t, check::exact,
            [](const rt& c) { return intersection(c.r, c.t).has_value(); });
        // Epick builds Ray_3(point, vector) by rounding point + vector: not exact for such rays.
        reg("cgal_epick/intersects/ray_triangle/" + dist, cs, t, check::approximate, [](const rt& c) {
            double o[3], d[3], a[3], b[3], cc[3];
            arr(c.r.origin, o);
            arr(c.r.direction, d);
            arr(c.t.a, a);
            arr(c.t.b, b);
            arr(c.t.c, cc);
            return oracle::ray_triangle_epick(o, d, a, b, cc);
        });
        reg("cgal_epeck/intersects/ray_triangle/" + dist, cs, t, check::exact, truth);
    }
    {
        const auto cs = aabb_ray_set(near);
        auto truth = [](const ab& c) {
            double o[3], d[3], mn[3], mx[3];
            arr(c.r.origin, o);
            arr(c.r.direction, d);
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            return oracle::ray_box(o, d, mn, mx);
        };
        tiers("aabb_ray", dist, cs, truth, [](auto tier, const ab& c) { return intersects<decltype(tier)>(c.b, c.r); });
        std::vector<bool> t;
        for (const auto& c : cs) t.push_back(truth(c));
        reg("woo/intersects/aabb_ray/" + dist, cs, t, check::approximate, [](const ab& c) { return method::aabb_ray_woo(c.b, c.r); });
        reg("sign_algorithm_double/intersects/aabb_ray/" + dist, cs, t, check::approximate, [](const ab& c) {
            arith::approx_kernel k;
            return detail::intersects(k, c.b, c.r);
        });
        reg("cgal_epick/intersects/aabb_ray/" + dist, cs, t, check::approximate, [](const ab& c) {
            double o[3], d[3], mn[3], mx[3];
            arr(c.r.origin, o);
            arr(c.r.direction, d);
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            return oracle::ray_box_epick(o, d, mn, mx);
        });
        reg("cgal_epeck/intersects/aabb_ray/" + dist, cs, t, check::exact, truth);
    }
    {
        const auto cs = orient3d_set(near);
        std::vector<bool> t; // "truth" for orient3d: sign > 0 (the full sign is checked below)
        std::vector<int> sgn;
        for (const auto& c : cs) {
            double a[3], b[3], cc[3], d[3];
            arr(c.a, a);
            arr(c.b, b);
            arr(c.c, cc);
            arr(c.d, d);
            sgn.push_back(oracle::orient3d(a, b, cc, d));
            t.push_back(sgn.back() > 0);
        }
        reg("exact/orient3d/points/" + dist, cs, t, check::exact,
            [](const o3& c) { return orient3d(c.a, c.b, c.c, c.d) == sign::positive; });
        reg("approximate/orient3d/points/" + dist, cs, t, check::approximate,
            [](const o3& c) { return orient3d<approximate>(c.a, c.b, c.c, c.d) == sign::positive; });
        reg("static_filter_double/orient3d/points/" + dist, cs, t, check::exact,
            [](const o3& c) { return orient3d_static_filter(c.a, c.b, c.c, c.d) == sign::positive; });
        reg("cgal_epick/orient3d/points/" + dist, cs, t, check::exact, [](const o3& c) {
            double a[3], b[3], cc[3], d[3];
            arr(c.a, a);
            arr(c.b, b);
            arr(c.c, cc);
            arr(c.d, d);
            return oracle::orient3d_epick(a, b, cc, d) > 0;
        });
    }
    {
        const auto cs = ray_sphere_set(near);
        auto truth = [](const rs& c) {
            double o[3], d[3], cc[3];
            arr(c.r.origin, o);
            arr(c.r.direction, d);
            arr(c.s.center, cc);
            return oracle::ray_ball(o, d, cc, c.s.radius);
        };
        tiers("ray_sphere", dist, cs, truth, [](auto tier, const rs& c) { return intersects<decltype(tier)>(c.r, c.s); });
        std::vector<bool> t;
        for (const auto& c : cs) t.push_back(truth(c));
        reg("algebraic/intersects/ray_sphere/" + dist, cs, t, check::approximate,
            [](const rs& c) { return method::ray_sphere_algebraic(c.r, c.s).has_value(); });
        reg("cgal_epeck/intersects/ray_sphere/" + dist, cs, t, check::exact, truth);
    }
    {
        const auto cs = sphere_sphere_set(near);
        auto truth = [](const ss& c) {
            double a[3], b[3];
            arr(c.a.center, a);
            arr(c.b.center, b);
            return oracle::ball_ball(a, c.a.radius, b, c.b.radius);
        };
        tiers("sphere_sphere", dist, cs, truth, [](auto tier, const ss& c) { return intersects<decltype(tier)>(c.a, c.b); });
    }
    {
        // point x sphere: random points and balls; near: points on the sphere (3-4-5 and
        // 1-2-2 triples scaled), nudged by up to 2 ulps.
        struct ps {
            point3 p;
            sphere3 s;
        };
        std::vector<ps> cs;
        while (cs.size() < set_size) {
            if (!near) cs.push_back({rp(), sphere3{rp(), uni(0, 1)}});
            else {
                const point3 c{small(), small(), small()};
                const bool t = irand(0, 1) == 1;
                const double k = irand(1, 4);
                cs.push_back({np(c.x + k * (t ? 1 : 0), c.y + k * (t ? 2 : 3), c.z + k * (t ? 2 : 4)), sphere3{c, k * (t ? 3 : 5)}});
            }
        }
        auto truth = [](const ps& c) {
            double p[3], cc[3];
            arr(c.p, p);
            arr(c.s.center, cc);
            return oracle::point_in_ball(p, cc, c.s.radius);
        };
        tiers("point_sphere", dist, cs, truth, [](auto tier, const ps& c) { return intersects<decltype(tier)>(c.p, c.s); });
    }
    {
        struct bp {
            aabb3 b;
            point3 p;
        };
        std::vector<bp> cs;
        while (cs.size() < set_size) {
            const aabb3 b = box(rp(), rp());
            cs.push_back({b, near ? point3{b.max.x, b.min.y, (b.min.z + b.max.z) / 2} : rp()}); // on an edge when near
        }
        auto truth = [](const bp& c) {
            double p[3], mn[3], mx[3];
            arr(c.p, p);
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            return oracle::point_in_box(p, mn, mx);
        };
        tiers("aabb_point", dist, cs, truth, [](auto tier, const bp& c) { return intersects<decltype(tier)>(c.b, c.p); });
        // the squared distance on the same cases, every tier (a distance is never negative: the
        // answer the timing loop checks; its values are checked in tests/query/distance/box_point.cpp)
        tiers(
            "aabb_point", dist, cs, [](const bp&) { return true; },
            [](auto tier, const bp& c) {
                const auto d = squared_distance<decltype(tier)>(c.b, c.p);
                if constexpr (std::is_same_v<std::decay_t<decltype(d)>, double>) return d >= 0.0;
                else return d.hi >= 0.0;
            },
            "distance");
    }
    {
        // box x ball: random boxes and balls; near: the tests' balls touching a box at a face, an
        // edge or a corner, a little short of it or past it (testkit/contain_cases.hpp)
        support::rng r = set_rng(near);
        std::vector<std::pair<aabb3, sphere3>> cs;
        while (cs.size() < set_size) {
            if (near) cs.push_back(support::ball_touching_aabb(r));
            else cs.push_back({box(rp(), rp()), sphere3{rp(), uni(0, 0.5)}});
        }
        auto truth = [](const std::pair<aabb3, sphere3>& c) {
            double mn[3], mx[3], cc[3];
            arr(c.first.min, mn);
            arr(c.first.max, mx);
            arr(c.second.center, cc);
            return oracle::ball_aabb(mn, mx, cc, c.second.radius);
        };
        tiers("aabb_sphere", dist, cs, truth,
              [](auto tier, const std::pair<aabb3, sphere3>& c) { return intersects<decltype(tier)>(c.first, c.second); });
    }
}
} // namespace bench
