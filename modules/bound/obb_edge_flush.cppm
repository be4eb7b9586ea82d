// obb_edge_flush: the minimum-volume oriented box searched over O'Rourke's candidate set. A
// minimum-volume box of a convex polytope has two adjacent faces each flush with an edge of the
// hull. So: for every hull edge e, the box face flush with e has its normal n on e's arc of
// supporting directions (between the normals of the two hull faces at e); for a given n the box is
// n's width times the minimum-area rectangle of the hull projected along n, and that rectangle has
// a side flush with an edge of the projected polygon (Freeman and Shapira), which is the second
// flush edge. Every edge's arc is sampled, the best arcs are refined by golden-section search, and
// the best frame's box is widened until every point is provably inside (see obb_fit).
// The combinatorial search is complete; only the one-parameter minimisation along each arc is
// numerical (sampled, then refined to about 1e-10 of the arc), so the result is the global
// optimum up to that tolerance. It costs about (hull edges) x (hull vertices) log: a hull with
// more than `max_hull_vertices` vertices is refused (errc::too_large), not searched for minutes.
// Source: O'Rourke, "Finding minimal enclosing boxes", Int. J. Computer and Information Sciences
// 14(3), 1985 (the two-flush-edges theorem); Freeman and Shapira, "Determining the minimum-area
// encasing rectangle for an arbitrary closed curve", CACM 18(7), 1975.
module;
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>
export module incidence.bound:obb_edge_flush;
import incidence.core;
import incidence.shapes;
import :obb_fit;
import :obb_covariance;
import :convex_hull;

export namespace incidence::bound {

namespace flush_detail {
struct frame_value {
    double volume = __builtin_huge_val();
    std::array<vec3, 3> frame{};
};
inline vec3 unit(vec3 v) { return v * (1.0 / std::sqrt(dot(v, v))); }

// For the face normal n: the hull's width along n times the minimum-area rectangle of its
// projection onto the plane orthogonal to n; the frame (n, rectangle side, n x side).
inline frame_value best_for_normal(vec3 n, const std::vector<point3>& hv, std::vector<std::array<double, 2>>& proj,
                                   std::vector<std::array<double, 2>>& ring) {
    n = unit(n);
    const vec3 helper = std::abs(n.x) < 0.6 ? vec3{1, 0, 0} : vec3{0, 1, 0};
    const vec3 p = unit(cross(n, helper)), q = cross(n, p);
    double lo = __builtin_huge_val(), hi = -__builtin_huge_val();
    proj.clear();
    for (const point3& v : hv) {
        const vec3 d = v - point3{0, 0, 0};
        const double s = dot(n, d);
        lo = std::min(lo, s), hi = std::max(hi, s);
        proj.push_back({dot(p, d), dot(q, d)});
    }
    // 2D convex hull of the projection (monotone chain; rounding only affects the search)
    std::sort(proj.begin(), proj.end());
    ring.clear();
    auto turn = [](const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    };
    for (int pass = 0; pass < 2; ++pass) {
        const std::size_t base = ring.size();
        for (std::size_t k = 0; k < proj.size(); ++k) {
            const auto& pt = pass == 0 ? proj[k] : proj[proj.size() - 1 - k];
            while (ring.size() >= base + 2 && turn(ring[ring.size() - 2], ring.back(), pt) <= 0) ring.pop_back();
            ring.push_back(pt);
        }
        ring.pop_back();
    }
    frame_value best;
    const std::size_t m = ring.size();
    if (m < 3) return best;
    for (std::size_t k = 0; k < m; ++k) { // a rectangle side flush with each polygon edge
        const auto& a = ring[k];
        const auto& b = ring[(k + 1) % m];
        double ux = b[0] - a[0], uy = b[1] - a[1];
        const double len = std::sqrt(ux * ux + uy * uy);
        if (len == 0) continue;
        ux /= len, uy /= len;
        double s0 = __builtin_huge_val(), s1 = -__builtin_huge_val(), t0 = __builtin_huge_val(), t1 = -__builtin_huge_val();
        for (const auto& c : ring) {
            const double s = c[0] * ux + c[1] * uy, t = -c[0] * uy + c[1] * ux;
            s0 = std::min(s0, s), s1 = std::max(s1, s), t0 = std::min(t0, t), t1 = std::max(t1, t);
        }
        const double v = (hi - lo) * (s1 - s0) * (t1 - t0);
        if (v < best.volume) {
            const vec3 side = unit(p * ux + q * uy);
            best = {v, {n, side, cross(n, side)}};
        }
    }
    return best;
}
} // namespace flush_detail

inline constexpr std::size_t max_hull_vertices = 1024;

[[nodiscard]] inline result<obb3> obb_edge_flush(std::span<const point3> points, std::size_t hull_vertex_limit = max_hull_vertices) {
    using namespace flush_detail;
    const auto h = convex_hull(points);
    if (!h) return h.error();
    const auto& hv = h.value();
    if (hv.dimension < 3) return obb_covariance(points); // flat: the covariance frame spans the polygon
    if (hv.vertices.size() > hull_vertex_limit) return error{errc::too_large};
    // Each undirected hull edge with the outward normals of its two triangles.
    std::vector<vec3> normal(hv.triangles.size());
    for (std::size_t i = 0; i < hv.triangles.size(); ++i) {
        const auto& t = hv.triangles[i];
        normal[i] = unit(cross(hv.vertices[t[1]] - hv.vertices[t[0]], hv.vertices[t[2]] - hv.vertices[t[0]]));
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::array<std::size_t, 2>> edges;
    for (std::size_t i = 0; i < hv.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = hv.triangles[i][std::size_t(k)], b = hv.triangles[i][std::size_t((k + 1) % 3)];
            if (a > b) std::swap(a, b);
            auto [it, fresh] = edges.try_emplace({a, b}, std::array<std::size_t, 2>{i, i});
            if (!fresh) it->second[1] = i;
        }
    // Sample every arc, then refine the most promising arcs around their best sample.
    constexpr int samples = 8;
    std::vector<std::array<double, 2>> proj, ring;
    struct arc {
        vec3 a, b;
        double t;
        frame_value best;
    };
    std::vector<arc> arcs;
    for (const auto& [key, faces] : edges) {
        const vec3 a = normal[faces[0]], b = normal[faces[1]];
        arc best_arc{a, b, 0, {}};
        const bool flat = dot(a - b, a - b) < 1e-24; // a diagonal of a planar face: one direction
        for (int k = 0; k <= (flat ? 0 : samples); ++k) {
            const double t = double(k) / samples;
            const auto f = best_for_normal(a * (1 - t) + b * t, hv.vertices, proj, ring);
            if (f.volume < best_arc.best.volume) best_arc.best = f, best_arc.t = t;
        }
        if (!flat) arcs.push_back(best_arc);
        else arcs.push_back(best_arc), arcs.back().b = a;
    }
    std::sort(arcs.begin(), arcs.end(), [](const arc& x, const arc& y) { return x.best.volume < y.best.volume; });
    frame_value best = arcs.empty() ? frame_value{} : arcs.front().best;
    const std::size_t refine = std::min<std::size_t>(arcs.size(), 24);
    for (std::size_t i = 0; i < refine; ++i) {
        const arc& r = arcs[i];
        auto f_at = [&](double t) { return best_for_normal(r.a * (1 - t) + r.b * t, hv.vertices, proj, ring); };
        double lo = std::max(0.0, r.t - 1.0 / samples), hi = std::min(1.0, r.t + 1.0 / samples);
        const double g = 0.6180339887498949;
        double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
        frame_value f1 = f_at(x1), f2 = f_at(x2);
        for (int k = 0; k < 44 && hi - lo > 1e-12; ++k) {
            if (f1.volume < f2.volume) hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f_at(x1);
            else lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f_at(x2);
        }
        for (const auto* f : {&f1, &f2})
            if (f->volume < best.volume) best = *f;
    }
    if (!(best.volume < __builtin_huge_val())) return obb_covariance(points);
    auto& frame = best.frame; // re-orthonormalise
    frame[0] = unit(frame[0]);
    frame[1] = unit(frame[1] - frame[0] * dot(frame[0], frame[1]));
    frame[2] = cross(frame[0], frame[1]);
    return fit_box(frame, std::span<const point3>(hv.vertices.data(), hv.vertices.size()));
}

} // namespace incidence::bound
