// obb_min_volume: a minimum-volume oriented box, found by local minimisation of the box volume
// over rotations, from several starting frames (the covariance frame, the axes, and frames flush
// with the largest hull faces); each start is refined by Powell's direction-set method with golden-
// section line searches over a rotation vector. The volume is evaluated on the hull's vertices.
// The best frame's box is then widened until every point is provably inside (see obb_fit).
// Source: Eberly, "Minimum-volume box" (Geometric Tools, 2015), the sampled-start +
// minimisation approach; Powell, The Computer Journal 7(2), 1964; golden section: Press et al.,
// Numerical Recipes, 3rd ed., section 10.2.
module;
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>
export module incidence.bound:obb_min_volume;
import incidence.core;
import incidence.shapes;
import :obb_fit;
import :obb_covariance;
import :convex_hull;

export namespace incidence::bound {

namespace minvol_detail {
using frame = std::array<vec3, 3>;
// R(w) * f: rotate every axis by the rotation vector w (Rodrigues).
inline frame rotated(const frame& f, vec3 w) {
    const double t = std::sqrt(dot(w, w));
    if (t == 0) return f;
    const vec3 k = w * (1 / t);
    const double c = std::cos(t), s = std::sin(t);
    frame r;
    for (int i = 0; i < 3; ++i) {
        const vec3 v = f[std::size_t(i)];
        r[std::size_t(i)] = v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
    }
    return r;
}
inline double box_volume(const frame& f, const std::vector<point3>& pts) {
    double v = 1;
    for (const vec3& a : f) {
        double lo = 1e308, hi = -1e308;
        for (const point3& p : pts) {
            const double s = dot(a, p - point3{0, 0, 0});
            lo = std::min(lo, s), hi = std::max(hi, s);
        }
        v *= hi - lo;
    }
    return v;
}
inline frame powell(frame f, const std::vector<point3>& pts, double& best) {
    std::array<vec3, 3> dirs{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
    vec3 w{0, 0, 0};
    auto f_at = [&](vec3 x) { return box_volume(rotated(f, x), pts); };
    best = f_at(w);
    for (int iter = 0; iter < 12; ++iter) {
        const vec3 start = w;
        const double start_value = best;
        double biggest = 0;
        int biggest_i = 0;
        for (int i = 0; i < 4; ++i) {
            const vec3 d = i < 3 ? dirs[std::size_t(i)] : w - start;
            if (i == 3 && dot(d, d) == 0) break;
            // golden-section search for t in [-0.6, 0.6] along d
            double a = -0.6, b = 0.6;
            const double g = 0.6180339887498949;
            double x1 = b - g * (b - a), x2 = a + g * (b - a);
            double f1 = f_at(w + d * x1), f2 = f_at(w + d * x2);
            for (int k = 0; k < 40; ++k) {
                if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = f_at(w + d * x1);
                else a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = f_at(w + d * x2);
            }
            const double t = f1 < f2 ? x1 : x2, value = std::min(f1, f2);
            if (value < best) {
                if (i < 3 && best - value > biggest) biggest = best - value, biggest_i = i;
                w = w + d * t, best = value;
            }
        }
        const vec3 net = w - start;
        if (dot(net, net) > 0 && biggest > 0) dirs[std::size_t(biggest_i)] = net * (1 / std::sqrt(dot(net, net)));
        if (start_value - best <= 1e-12 * start_value) break;
    }
    return rotated(f, w);
}
} // namespace minvol_detail

[[nodiscard]] inline result<obb3> obb_min_volume(std::span<const point3> points) {
    const auto h = convex_hull(points);
    if (!h) return h.error();
    const auto& hv = h.value();
    const auto cov = obb_covariance(points);
    if (!cov) return cov.error();
    if (hv.dimension < 3) return cov; // flat: the covariance frame already spans the polygon
    std::vector<minvol_detail::frame> starts = {cov.value().axes, {vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}};
    // frames flush with the largest hull faces: the face normal and its longest edge
    std::vector<std::pair<double, std::size_t>> faces;
    for (std::size_t i = 0; i < hv.triangles.size(); ++i) {
        const auto& t = hv.triangles[i];
        faces.push_back({squared_length(cross(hv.vertices[t[1]] - hv.vertices[t[0]], hv.vertices[t[2]] - hv.vertices[t[0]])), i});
    }
    std::sort(faces.rbegin(), faces.rend());
    for (std::size_t k = 0; k < std::min<std::size_t>(4, faces.size()); ++k) {
        const auto& t = hv.triangles[faces[k].second];
        const vec3 e = hv.vertices[t[1]] - hv.vertices[t[0]], n = cross(e, hv.vertices[t[2]] - hv.vertices[t[0]]);
        const vec3 a = e * (1 / std::sqrt(dot(e, e))), c = n * (1 / std::sqrt(dot(n, n)));
        starts.push_back({a, cross(c, a), c});
    }
    double best = 1e308;
    minvol_detail::frame frame = starts[0];
    for (const auto& s : starts) {
        double v = 0;
        const auto f = minvol_detail::powell(s, hv.vertices, v);
        if (v < best) best = v, frame = f;
    }
    // re-orthonormalise the rotated frame
    auto unit = [](vec3 x) { return x * (1.0 / std::sqrt(dot(x, x))); };
    frame[0] = unit(frame[0]);
    frame[1] = unit(frame[1] - frame[0] * dot(frame[0], frame[1]));
    frame[2] = cross(frame[0], frame[1]);
    return fit_box(frame, std::span<const point3>(hv.vertices.data(), hv.vertices.size()));
}

} // namespace incidence::bound
