// The bounding-volume trade-off of one point set: for every construction of incidence.bound,
// build time, volume and surface area relative to the convex hull (CGAL convex_hull_3), the
// cost of one overlap test between two volumes of that kind, and an exact check that every
// point is inside; CGAL's minimum sphere and hull beside them. Used by the audit's scene
// report and by bench/bv_table. Include after the oracle header and `import incidence;`.
#pragma once
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace audit {

using namespace incidence;

struct bv_row {
    std::string kind, source;
    double build_ms = 0, volume = 0, area = 0, volume_ratio = 0, area_ratio = 0, test_ns = 0;
    bool contains_all = false;
    bool ours = true;
    unsigned long vertices = 0; // hull rows: vertex count
    bool failed = false;        // a peer reported an error
};
struct bv_report {
    std::vector<bv_row> rows;
    double hull_volume = 0, hull_area = 0, hull_ms = 0;
    unsigned long hull_vertices = 0;
    std::string advice;
    double tightness_rule = 1.25; // candidates: volume ratio within this factor of the tightest
};

namespace bv_detail {
inline double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
template <class F>
double median_ms(int reps, F f) {
    std::vector<double> t;
    for (int i = 0; i < reps; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        t.push_back(ms_since(t0));
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}
// ns per overlap test between v and copies of v moved by random offsets of about its size.
template <class V, class Move, class Test>
double test_ns(const V& v, double size, Move move, Test test, int reps) {
    std::mt19937_64 g(7);
    std::uniform_real_distribution<double> u(-1.2 * size, 1.2 * size);
    std::vector<V> others;
    for (int i = 0; i < 4096; ++i) others.push_back(move(v, vec3{u(g), u(g), u(g)}));
    std::vector<double> t;
    volatile long sink = 0;
    for (int r = 0; r < reps; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        long hits = 0;
        for (const V& o : others) hits += test(v, o);
        t.push_back(bv_detail::ms_since(t0) * 1e6 / double(others.size()));
        sink = sink + hits;
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}
// The classic k-DOP overlap test: every slab interval overlaps (Klosowski et al. 1998).
template <int K>
bool slabs_overlap(const kdop<K>& a, const kdop<K>& b) {
    for (int i = 0; i < K / 2; ++i)
        if (a.max[std::size_t(i)] < b.min[std::size_t(i)] || b.max[std::size_t(i)] < a.min[std::size_t(i)]) return false;
    return true;
}
// The classic OBB overlap test in double: 15 separating axes (Gottschalk, Lin, Manocha 1996).
inline bool obb_overlap(const obb3& a, const obb3& b) {
    const vec3 t = b.center - a.center;
    std::array<vec3, 15> axes;
    std::size_t n = 0;
    for (const vec3& x : a.axes) axes[n++] = x;
    for (const vec3& x : b.axes) axes[n++] = x;
    for (const vec3& x : a.axes)
        for (const vec3& y : b.axes) axes[n++] = cross(x, y);
    for (const vec3& l : axes) {
        double ra = 0, rb = 0;
        for (int i = 0; i < 3; ++i) {
            ra += a.half_extents[std::size_t(i)] * std::abs(dot(a.axes[std::size_t(i)], l));
            rb += b.half_extents[std::size_t(i)] * std::abs(dot(b.axes[std::size_t(i)], l));
        }
        if (std::abs(dot(t, l)) > ra + rb) return false;
    }
    return true;
}
template <int K>
kdop<K> moved(kdop<K> k, vec3 v) {
    const auto d = kdop<K>::directions();
    for (std::size_t i = 0; i < d.size(); ++i) {
        const double s = d[i].x * v.x + d[i].y * v.y + d[i].z * v.z;
        k.min[i] += s, k.max[i] += s;
    }
    return k;
}
} // namespace bv_detail

inline bv_report measure_bounding_volumes(std::span<const point3> pts, int reps) {
    using namespace bv_detail;
    bv_report rep;
    std::vector<double> xyz;
    for (const auto& p : pts) xyz.insert(xyz.end(), {p.x, p.y, p.z});
    oracle::hull_volume_area(xyz.data(), pts.size(), rep.hull_volume, rep.hull_area);
    rep.hull_ms = 1e300;
    for (int i = 0; i < reps; ++i) rep.hull_ms = std::min(rep.hull_ms, oracle::hull_time_ms(xyz.data(), pts.size(), rep.hull_vertices));
    const aabb3 box = bound::aabb_of(pts).value();
    const double size = std::sqrt(squared_length(box.max - box.min));
    volatile double sink = 0; // keeps the timed constructions from being optimised away
    auto finish = [&](bv_row r) {
        r.volume_ratio = rep.hull_volume > 0 ? r.volume / rep.hull_volume : 0;
        r.area_ratio = rep.hull_area > 0 ? r.area / rep.hull_area : 0;
        rep.rows.push_back(r);
    };
    {
        bv_row r{"aabb", "aabb_of: min/max per axis"};
        r.build_ms = median_ms(reps, [&] { sink = bound::aabb_of(pts).value().min.x; });
        const vec3 e = box.max - box.min;
        r.volume = e.x * e.y * e.z, r.area = 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
        r.contains_all = std::all_of(pts.begin(), pts.end(), [&](point3 p) { return contains(box, p); });
        r.test_ns = test_ns(
            box, size, [](aabb3 b, vec3 v) { return aabb3{b.min + v, b.max + v}; },
            [](const aabb3& a, const aabb3& b) { return intersects(a, b); }, reps);
        finish(r);
    }
    auto kdop_row = [&]<int K>(std::integral_constant<int, K>) {
        bv_row r{std::to_string(K) + "-dop", "kdop_of<" + std::to_string(K) + ">: tightest slabs, outward rounded"};
        r.build_ms = median_ms(reps, [&] { sink = bound::kdop_of<K>(pts).value().min[0]; });
        const kdop<K> k = bound::kdop_of<K>(pts).value();
        const auto d = kdop<K>::directions();
        std::vector<double> dirs;
        for (const auto& x : d) dirs.insert(dirs.end(), {double(x.x), double(x.y), double(x.z)});
        double c[3] = {0, 0, 0};
        for (const auto& p : pts) c[0] += p.x, c[1] += p.y, c[2] += p.z;
        for (double& x : c) x /= double(pts.size());
        oracle::halfspaces_volume_area(dirs.data(), k.min.data(), k.max.data(), d.size(), c, r.volume, r.area);
        r.contains_all = std::all_of(pts.begin(), pts.end(), [&](point3 p) { return bound::contains(k, p); });
        r.test_ns = test_ns(
            k, size, [](const kdop<K>& a, vec3 v) { return bv_detail::moved(a, v); },
            [](const kdop<K>& a, const kdop<K>& b) { return slabs_overlap(a, b); }, reps);
        finish(r);
    };
    kdop_row(std::integral_constant<int, 6>{});
    kdop_row(std::integral_constant<int, 14>{});
    kdop_row(std::integral_constant<int, 18>{});
    kdop_row(std::integral_constant<int, 26>{});
    auto sphere_row = [&](const char* kind, const char* source, auto build) {
        bv_row r{kind, source};
        r.build_ms = median_ms(reps, [&] { sink = build().radius; });
        const sphere3 s = build();
        r.volume = 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius;
        r.area = 4.0 * std::numbers::pi * s.radius * s.radius;
        r.contains_all = std::all_of(pts.begin(), pts.end(), [&](point3 p) { return bound::in_ball(s.center, s.radius, p); });
        r.test_ns = test_ns(
            s, size, [](sphere3 a, vec3 v) { return sphere3{a.center + v, a.radius}; },
            [](const sphere3& a, const sphere3& b) { return intersects(a, b); }, reps);
        finish(r);
    };
    sphere_row("sphere (aabb)", "sphere_from_aabb: box centre, half diagonal", [&] { return bound::sphere_from_aabb(pts).value(); });
    sphere_row("sphere (aabb, farthest)", "sphere_from_aabb_farthest: box centre, farthest point",
               [&] { return bound::sphere_from_aabb_farthest(pts).value(); });
    sphere_row("sphere (Ritter)", "sphere_ritter: Ritter 1990", [&] { return bound::sphere_ritter(pts).value(); });
    sphere_row("sphere (Welzl, exact)", "sphere_welzl: exact minimum sphere, Welzl 1991",
               [&] { return bound::sphere_welzl(pts).value().sphere; });
    auto obb_row = [&](const char* kind, const char* source, auto build) {
        bv_row r{kind, source};
        obb3 b{};
        r.build_ms = median_ms(reps, [&] {
            b = build();
            sink = b.half_extents[0];
        });
        r.volume = bound::volume(b);
        const double e0 = 2 * b.half_extents[0], e1 = 2 * b.half_extents[1], e2 = 2 * b.half_extents[2];
        r.area = 2 * (e0 * e1 + e1 * e2 + e2 * e0);
        r.contains_all = std::all_of(pts.begin(), pts.end(), [&](point3 p) { return bound::contains(b, p); });
        r.test_ns = test_ns(
            b, size, [](obb3 a, vec3 v) { return obb3{a.center + v, a.axes, a.half_extents}; },
            [](const obb3& a, const obb3& c) { return obb_overlap(a, c); }, reps);
        finish(r);
    };
    obb_row("OBB (covariance)", "obb_covariance: Gottschalk 1996", [&] { return bound::obb_covariance(pts).value(); });
    obb_row("OBB (min volume)", "obb_min_volume: sampled starts + Powell (Eberly)", [&] { return bound::obb_min_volume(pts).value(); });
    if (rep.hull_vertices <= bound::max_hull_vertices) // the global search costs hull edges x hull vertices
        obb_row("OBB (edge-flush)", "obb_edge_flush: O'Rourke 1985 candidate set, searched",
                [&] { return bound::obb_edge_flush(pts).value(); });
    {
        bv_row r{"CGAL OBB", "CGAL oriented_bounding_box, Epick"};
        r.ours = false;
        std::vector<double> t;
        for (int i = 0; i < reps; ++i) {
            double ms = 0;
            r.volume = oracle::obb_volume_cgal(xyz.data(), pts.size(), ms);
            t.push_back(ms);
        }
        std::sort(t.begin(), t.end());
        r.build_ms = t[t.size() / 2];
        finish(r);
    }
    {
        bv_row r{"CGAL min sphere", "CGAL Min_sphere_of_spheres_d, Epick (double)"};
        r.ours = false;
        double radius = 0;
        r.build_ms = median_ms(reps, [&] { radius = oracle::min_sphere_of_spheres_epick(xyz.data(), pts.size()); });
        r.volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius, r.area = 4.0 * std::numbers::pi * radius * radius;
        finish(r);
        bv_row h{"CGAL convex hull", "CGAL convex_hull_3, Epick"};
        h.ours = false;
        h.build_ms = rep.hull_ms, h.volume = rep.hull_volume, h.area = rep.hull_area, h.vertices = rep.hull_vertices;
        finish(h);
        bv_row q{"qhull", "qhull 2020.2 (libqhull_r), default options"};
        q.ours = false;
        std::vector<double> t;
        for (int i = 0; i < reps; ++i) {
            const auto res = oracle::qhull_hull(xyz.data(), pts.size());
            t.push_back(res.ms), q.vertices = res.vertices, q.failed = res.error;
        }
        std::sort(t.begin(), t.end());
        q.build_ms = t[t.size() / 2];
        q.volume = rep.hull_volume, q.area = rep.hull_area;
        finish(q);
    }
    {
        bv_row r{"convex hull", "convex_hull: Quickhull with exact orient3d"};
        bound::hull h;
        r.build_ms = median_ms(reps, [&] {
            h = bound::convex_hull(pts).value();
            sink = double(h.vertices.size());
        });
        r.vertices = h.vertices.size();
        double v = 0, a = 0;
        for (const auto& t : h.triangles) {
            const point3 p = h.vertices[t[0]], q = h.vertices[t[1]], w = h.vertices[t[2]];
            const vec3 u = p - point3{0, 0, 0}, e1 = q - p, e2 = w - p;
            v += dot(u, cross(q - point3{0, 0, 0}, w - point3{0, 0, 0})) / 6.0;
            a += 0.5 * std::sqrt(squared_length(cross(e1, e2)));
        }
        r.volume = std::abs(v), r.area = a;
        r.contains_all = true;
        for (const auto& t : h.triangles) // every point on the inner side of every face (a sample of points)
            for (std::size_t i = 0; i < pts.size(); i += std::max<std::size_t>(1, pts.size() / 200))
                r.contains_all = r.contains_all && orient3d(h.vertices[t[0]], h.vertices[t[1]], h.vertices[t[2]], pts[i]) != sign::negative;
        r.test_ns = 0;
        finish(r);
    }
    // Advice: among our volumes within the stated factor of the tightest, the cheapest test.
    double best = 1e300;
    for (const auto& r : rep.rows)
        if (r.ours && r.test_ns > 0 && r.volume_ratio > 0) best = std::min(best, r.volume_ratio);
    const bv_row* pick = nullptr;
    for (const auto& r : rep.rows)
        if (r.ours && r.test_ns > 0 && r.volume_ratio > 0 && r.volume_ratio <= best * rep.tightness_rule &&
            (!pick || r.test_ns < pick->test_ns))
            pick = &r;
    char buf[400];
    if (pick) {
        std::snprintf(buf, sizeof buf,
                      "%s: %.2fx the convex hull's volume (the tightest kind here is %.2fx), %.1f ns per overlap "
                      "test, built in %.2f ms. Rule: the cheapest test among the kinds within %.2fx of the "
                      "tightest volume.",
                      pick->kind.c_str(), pick->volume_ratio, best, pick->test_ns, pick->build_ms, rep.tightness_rule);
        rep.advice = buf;
    } else {
        rep.advice = "no advice: the point set is flat (its convex hull has no volume)";
    }
    return rep;
}

} // namespace audit
