// Benchmarks: segment-triangle, triangle-triangle, box-triangle, box-segment and box-line, the plane pairs and box-box, with CGAL and FCL beside.
#include "bench.hpp"

namespace bench {
void register_classic_sat(bool near) {
    const std::string dist = near ? "near_degenerate" : "random";
    {
        // segment x triangle: the ray sets, with the segment ending at origin + 1.5 direction
        struct st {
            segment3 s;
            triangle3 t;
        };
        std::vector<st> cs;
        for (const auto& c : ray_triangle_set(near)) cs.push_back({segment3{c.r.origin, c.r.at(near ? 1.0 : 1.5)}, c.t});
        auto truth = [](const st& c) {
            double p[3], q[3], a[3], b[3], cc[3];
            arr(c.s.a, p);
            arr(c.s.b, q);
            arr(c.t.a, a);
            arr(c.t.b, b);
            arr(c.t.c, cc);
            return oracle::segment_triangle(p, q, a, b, cc);
        };
        tiers("segment_triangle", dist, cs, truth, [](auto tier, const st& c) { return intersects<decltype(tier)>(c.s, c.t); });
    }
    {
        // triangle x triangle: the second triangle has the segment above as an edge (so on the
        // near set it ends on the first triangle's edge or vertex); CGAL needs both non-degenerate.
        struct tt {
            triangle3 p, q;
        };
        std::vector<tt> cs;
        for (const auto& c : ray_triangle_set(near)) {
            const triangle3 q{c.r.origin, c.r.at(near ? 1.0 : 1.5), c.r.origin + vec3{0.5, -0.25, 0.125}};
            double a[3], b[3], cc[3];
            arr(q.a, a);
            arr(q.b, b);
            arr(q.c, cc);
            if (!oracle::triangle_is_degenerate(a, b, cc)) cs.push_back({c.t, q});
        }
        auto truth = [](const tt& c) {
            double a[3], b[3], cc[3], d[3], e[3], f[3];
            arr(c.p.a, a);
            arr(c.p.b, b);
            arr(c.p.c, cc);
            arr(c.q.a, d);
            arr(c.q.b, e);
            arr(c.q.c, f);
            return oracle::triangle_triangle(a, b, cc, d, e, f);
        };
        tiers("triangle_triangle", dist, cs, truth, [](auto tier, const tt& c) { return intersects<decltype(tier)>(c.p, c.q); });
        std::vector<bool> t;
        for (const auto& c : cs) t.push_back(truth(c));
        reg("sat/intersects/triangle_triangle/" + dist, cs, t, check::approximate,
            [](const tt& c) { return method::triangle_triangle_sat(c.p, c.q); });
        reg("cgal_epick/intersects/triangle_triangle/" + dist, cs, t, check::approximate, [](const tt& c) {
            double a[3], b[3], cc[3], d[3], e[3], f[3];
            arr(c.p.a, a);
            arr(c.p.b, b);
            arr(c.p.c, cc);
            arr(c.q.a, d);
            arr(c.q.b, e);
            arr(c.q.c, f);
            return oracle::triangle_triangle_epick(a, b, cc, d, e, f);
        });
        reg("fcl/intersects/triangle_triangle/" + dist, cs, t, check::approximate, [](const tt& c) {
            double a[3], b[3], cc[3], d[3], e[3], f[3];
            arr(c.p.a, a);
            arr(c.p.b, b);
            arr(c.p.c, cc);
            arr(c.q.a, d);
            arr(c.q.b, e);
            arr(c.q.c, f);
            return fcl_peer::triangle_triangle(a, b, cc, d, e, f);
        });
    }
    {
        // box x triangle: near cases touch the unit box at its corner, along a face, or with
        // the triangle's plane through the corner; random cases are random boxes and triangles
        struct bt {
            aabb3 b;
            triangle3 t;
        };
        std::vector<bt> cs;
        while (cs.size() < set_size) {
            const point3 c{small(), small(), small()};
            const aabb3 b = near ? box(c, point3{c.x + 1, c.y + 1, c.z + 1}) : box(rp(), rp());
            const point3 m = b.max;
            triangle3 t{rp(), rp(), rp()};
            if (near) {
                const int kind = int(cs.size() % 3);
                const vec3 u{1 + 0.25 * double(cs.size() % 4), 0.5, 2}, w{0.5, 1.5, 1 + 0.125 * double(cs.size() % 5)};
                if (kind == 0) t = {m, m + u, m + w};                                            // the corner
                else if (kind == 1) t = {m + vec3{0.5, -0.5, 0}, m + vec3{-0.5, 0.5, 0}, m + u}; // across the top corner
                else t = {m + vec3{2, -1, -1}, m + vec3{-1, 2, -1}, m + vec3{-1, -1, 2}};        // plane x+y+z through the corner
            }
            double a[3], bb3[3], cc[3];
            arr(t.a, a);
            arr(t.b, bb3);
            arr(t.c, cc);
            if (!oracle::triangle_is_degenerate(a, bb3, cc)) cs.push_back({b, t});
        }
        auto truth = [](const bt& c) {
            double mn[3], mx[3], a[3], b[3], cc[3];
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            arr(c.t.a, a);
            arr(c.t.b, b);
            arr(c.t.c, cc);
            return oracle::box_triangle(mn, mx, a, b, cc);
        };
        tiers("aabb_triangle", dist, cs, truth, [](auto tier, const bt& c) { return intersects<decltype(tier)>(c.b, c.t); });
        std::vector<bool> t;
        for (const auto& c : cs) t.push_back(truth(c));
        reg("sign_algorithm_double/intersects/aabb_triangle/" + dist, cs, t, check::approximate, [](const bt& c) {
            arith::approx_kernel k;
            return detail::intersects(k, c.b, c.t);
        });
        reg("cgal_epick/intersects/aabb_triangle/" + dist, cs, t, check::approximate, [](const bt& c) {
            double mn[3], mx[3], a[3], b[3], cc[3];
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            arr(c.t.a, a);
            arr(c.t.b, b);
            arr(c.t.c, cc);
            return oracle::box_triangle_epick(mn, mx, a, b, cc);
        });
    }
    {
        // box x segment and box x line: the ray cases, the segment ending at origin + direction
        struct bs {
            aabb3 b;
            segment3 s;
            line3 l;
        };
        std::vector<bs> cs;
        for (const auto& c : aabb_ray_set(near)) cs.push_back({c.b, segment3{c.r.origin, c.r.at(1.0)}, line3{c.r.origin, c.r.direction}});
        auto seg_truth = [](const bs& c) {
            double p[3], q[3], mn[3], mx[3];
            arr(c.s.a, p);
            arr(c.s.b, q);
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            return oracle::box_segment(mn, mx, p, q);
        };
        auto line_truth = [](const bs& c) {
            double p[3], d[3], mn[3], mx[3];
            arr(c.l.origin, p);
            arr(c.l.direction, d);
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            return oracle::box_line(mn, mx, p, d);
        };
        tiers("aabb_segment", dist, cs, seg_truth, [](auto tier, const bs& c) { return intersects<decltype(tier)>(c.b, c.s); });
        tiers("aabb_line", dist, cs, line_truth, [](auto tier, const bs& c) { return intersects<decltype(tier)>(c.b, c.l); });
        std::vector<bool> ts, tl;
        for (const auto& c : cs) ts.push_back(seg_truth(c)), tl.push_back(line_truth(c));
        reg("cgal_epick/intersects/aabb_segment/" + dist, cs, ts, check::approximate, [](const bs& c) {
            double p[3], q[3], mn[3], mx[3];
            arr(c.s.a, p);
            arr(c.s.b, q);
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            return oracle::box_segment_epick(mn, mx, p, q);
        });
        reg("cgal_epick/intersects/aabb_line/" + dist, cs, tl, check::approximate, [](const bs& c) {
            double p[3], d[3], mn[3], mx[3];
            arr(c.l.origin, p);
            arr(c.l.direction, d);
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            return oracle::box_line_epick(mn, mx, p, d);
        });
    }
    {
        // planes: through the box's extreme corner / a segment end / a triangle vertex when near
        struct pc {
            aabb3 b;
            segment3 s;
            triangle3 t;
            plane3 p;
        };
        std::vector<pc> cs;
        for (const auto& c : ray_triangle_set(near)) {
            const aabb3 bx = box(c.t.a, c.t.b);
            const vec3 n = near ? vec3{double(irand(-3, 3)), double(irand(-3, 3)), 1} : vec3{uni(-1, 1), uni(-1, 1), uni(-1, 1)};
            const point3 q = near ? c.t.a : rp();
            cs.push_back({bx, segment3{c.r.origin, c.t.a}, c.t, plane3{n, dot(n, q - point3{0, 0, 0})}});
        }
        auto n3 = [](const pc& c, double* n) { arr(c.p.normal, n); };
        auto tb = [&](const pc& c) {
            double mn[3], mx[3], n[3];
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            n3(c, n);
            return oracle::box_plane(mn, mx, n, c.p.offset);
        };
        auto ts = [&](const pc& c) {
            double a[3], q[3], n[3];
            arr(c.s.a, a);
            arr(c.s.b, q);
            n3(c, n);
            return oracle::plane_segment(n, c.p.offset, a, q);
        };
        auto tt3 = [&](const pc& c) {
            double a[3], q[3], w[3], n[3];
            arr(c.t.a, a);
            arr(c.t.b, q);
            arr(c.t.c, w);
            n3(c, n);
            return oracle::plane_triangle(n, c.p.offset, a, q, w);
        };
        tiers("aabb_plane", dist, cs, tb, [](auto tier, const pc& c) { return intersects<decltype(tier)>(c.b, c.p); });
        tiers("plane_segment", dist, cs, ts, [](auto tier, const pc& c) { return intersects<decltype(tier)>(c.p, c.s); });
        tiers("plane_triangle", dist, cs, tt3, [](auto tier, const pc& c) { return intersects<decltype(tier)>(c.p, c.t); });
        std::vector<bool> t1, t2, t3;
        for (const auto& c : cs) t1.push_back(tb(c)), t2.push_back(ts(c)), t3.push_back(tt3(c));
        reg("cgal_epick/intersects/aabb_plane/" + dist, cs, t1, check::approximate, [n3](const pc& c) {
            double mn[3], mx[3], n[3];
            arr(c.b.min, mn);
            arr(c.b.max, mx);
            n3(c, n);
            return oracle::box_plane_epick(mn, mx, n, c.p.offset);
        });
        reg("cgal_epick/intersects/plane_segment/" + dist, cs, t2, check::approximate, [n3](const pc& c) {
            double a[3], q[3], n[3];
            arr(c.s.a, a);
            arr(c.s.b, q);
            n3(c, n);
            return oracle::plane_segment_epick(n, c.p.offset, a, q);
        });
        reg("cgal_epick/intersects/plane_triangle/" + dist, cs, t3, check::approximate, [n3](const pc& c) {
            double a[3], q[3], w[3], n[3];
            arr(c.t.a, a);
            arr(c.t.b, q);
            arr(c.t.c, w);
            n3(c, n);
            return oracle::plane_triangle_epick(n, c.p.offset, a, q, w);
        });
    }
    {
        const auto cs = aabb_aabb_set(near);
        auto truth = [](const bb& c) {
            double a0[3], a1[3], b0[3], b1[3];
            arr(c.a.min, a0);
            arr(c.a.max, a1);
            arr(c.b.min, b0);
            arr(c.b.max, b1);
            return oracle::box_box(a0, a1, b0, b1);
        };
        tiers("aabb_aabb", dist, cs, truth, [](auto tier, const bb& c) { return intersects<decltype(tier)>(c.a, c.b); });
    }
}
} // namespace bench
