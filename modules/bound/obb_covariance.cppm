// obb_covariance: the oriented box along the principal axes of the convex hull's surface:
// area-weighted covariance of the hull's triangles (so interior and clustered points do not
// bias it), its eigenvectors by Jacobi rotations, then the tight extents along them, widened
// until every point is provably inside (see obb_fit). Flat or collinear input uses the
// covariance of the points themselves.
// Source: Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 4 (covariance of the
// convex hull's triangles); Jacobi eigenvalue method: Golub and Van Loan, Matrix Computations,
// 4th ed., section 8.5.
module;
#include <array>
#include <cmath>
#include <span>
export module incidence.bound:obb_covariance;
import incidence.core;
import incidence.shapes;
import :obb_fit;
import :convex_hull;
import :aabb_of;

export namespace incidence::bound {

namespace cov_detail {
using mat3 = std::array<std::array<double, 3>, 3>;
// Eigenvectors of a symmetric 3x3 matrix (columns of the returned matrix), cyclic Jacobi.
inline std::array<vec3, 3> eigenvectors(mat3 a) {
    mat3 v{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int sweep = 0; sweep < 50; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off <= 1e-300) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::abs(a[p][q]) < 1e-300) continue;
                const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
                const double c = 1 / std::sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 3; ++k) { // A <- J^T A J, V <- V J
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq, a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk, a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq, v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    std::array<vec3, 3> e{vec3{v[0][0], v[1][0], v[2][0]}, vec3{v[0][1], v[1][1], v[2][1]}, vec3{v[0][2], v[1][2], v[2][2]}};
    // re-orthonormalise (Gram-Schmidt) and make right-handed
    auto unit = [](vec3 x) { return x * (1.0 / std::sqrt(dot(x, x))); };
    e[0] = unit(e[0]);
    e[1] = unit(e[1] - e[0] * dot(e[0], e[1]));
    e[2] = cross(e[0], e[1]);
    return e;
}
} // namespace cov_detail

[[nodiscard]] inline result<obb3> obb_covariance(std::span<const point3> points) {
    const auto h = convex_hull(points);
    if (!h) return h.error();
    const auto& hv = h.value();
    // Work relative to the AABB centre (better conditioned far from the origin).
    const aabb3 box = aabb_of(points).value();
    const point3 o{0.5 * box.min.x + 0.5 * box.max.x, 0.5 * box.min.y + 0.5 * box.max.y, 0.5 * box.min.z + 0.5 * box.max.z};
    cov_detail::mat3 c{};
    double total = 0;
    vec3 mean{0, 0, 0};
    if (hv.dimension == 3) {
        for (const auto& t : hv.triangles) {
            const vec3 p = hv.vertices[t[0]] - o, q = hv.vertices[t[1]] - o, r = hv.vertices[t[2]] - o;
            const double area = 0.5 * std::sqrt(squared_length(cross(q - p, r - p)));
            const vec3 m = (p + q + r) * (1.0 / 3.0);
            const double pv[3] = {p.x, p.y, p.z}, qv[3] = {q.x, q.y, q.z}, rv[3] = {r.x, r.y, r.z}, mv[3] = {m.x, m.y, m.z};
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k) c[j][k] += area / 12.0 * (9 * mv[j] * mv[k] + pv[j] * pv[k] + qv[j] * qv[k] + rv[j] * rv[k]);
            mean = mean + m * area;
            total += area;
        }
    } else {
        for (const auto& pt : hv.vertices) {
            const vec3 p = pt - o;
            const double pv[3] = {p.x, p.y, p.z};
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k) c[j][k] += pv[j] * pv[k];
            mean = mean + p;
            total += 1;
        }
    }
    if (total > 0) {
        mean = mean * (1.0 / total);
        const double mv[3] = {mean.x, mean.y, mean.z};
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c[j][k] = c[j][k] / total - mv[j] * mv[k];
    }
    std::array<vec3, 3> axes{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}};
    if (total > 0 && std::isfinite(c[0][0] + c[1][1] + c[2][2])) axes = cov_detail::eigenvectors(c);
    return fit_box(axes, std::span<const point3>(hv.vertices.data(), hv.vertices.size()));
}

} // namespace incidence::bound
