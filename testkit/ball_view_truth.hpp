// The oracle for a ball or a capsule against a polygon3 or a solid mesh3 (polygon_sphere,
// capsule_polygon, mesh_sphere, capsule_mesh; the tests' cases are ball_view_cases.hpp's, and the
// spheres_boxes fuzzer uses it too): the polygon's CGAL constrained triangulation or the mesh's
// triangles, each by CGAL's squared distance from the centre over Epeck (oracle::ball_flat) or the
// exact QP between the capsule's segment and the triangle (oracle::qp_sets_within), and for the
// mesh the centre (the capsule's end a) inside by exact crossing parity (oracle::mesh_inside).
// Triangles whose boxes lie apart from the ball's or capsule's box (widened by far more than its
// rounding) are skipped. Include after lp_shapes.hpp, flat_shapes.hpp, mesh_cases.hpp and
// polygon3_cases.hpp.
#pragma once
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace support {

// The round shape's core (its centre or segment) and reach, and a box around it, widened by
// 2^-40 of its magnitude plus 2^-1000: far more than the rounding of the sums.
struct round_core {
    incidence::point3 a, b;
    double r;
    [[nodiscard]] bool misses(const std::array<double, 9>& t) const {
        const double p[2][3] = {{a.x, a.y, a.z}, {b.x, b.y, b.z}};
        for (int k = 0; k < 3; ++k) {
            const double lo = std::fmin(p[0][k], p[1][k]) - std::fabs(r), hi = std::fmax(p[0][k], p[1][k]) + std::fabs(r);
            const double slack = (std::fabs(lo) + std::fabs(hi)) * 0x1p-40 + 0x1p-1000;
            const double tlo = std::fmin(t[k], std::fmin(t[3 + k], t[6 + k])), thi = std::fmax(t[k], std::fmax(t[3 + k], t[6 + k]));
            if (thi < lo - slack || tlo > hi + slack) return true;
        }
        return false;
    }
};
inline round_core core_and_reach(const incidence::sphere3& s) { return {s.center, s.center, s.radius}; }
inline round_core core_and_reach(const incidence::capsule3& c) { return {c.a, c.b, c.radius}; }

// Some triangle within reach of the core: a ball by CGAL's squared distance over Epeck, a capsule
// by the exact QP; std::nullopt when the QP declined a triangle and none was found within reach.
template <class Round>
std::optional<bool> triangles_within(const std::vector<std::array<double, 9>>& tris, const Round& x) {
    using namespace incidence;
    const round_core c = core_and_reach(x);
    bool declined = false;
    for (const auto& t : tris) {
        if (c.misses(t)) continue;
        const triangle3 T{{t[0], t[1], t[2]}, {t[3], t[4], t[5]}, {t[6], t[7], t[8]}};
        if constexpr (std::is_same_v<Round, sphere3>) {
            if (oracle::ball_flat(to_flat(T), a3(x.center), x.radius)) return true;
        } else {
            const auto q = oracle::qp_sets_within(lp(segment3{x.a, x.b}), lp(T), x.radius);
            if (q && *q) return true;
            declined = declined || !q;
        }
    }
    if (declined) return std::nullopt;
    return false;
}
template <class Round>
std::optional<bool> round_polygon_truth(const incidence::polygon3& g, const Round& x) {
    return triangles_within(oracle::polygon3_triangles(polygon3_data_of(g)), x);
}
template <class Round>
std::optional<bool> round_mesh_truth(const incidence::mesh3& m, const Round& x) {
    const oracle::mesh_data d = mesh_data_of(m);
    const round_core c = core_and_reach(x);
    try {
        if (oracle::mesh_inside(d, a3(c.a))) return true;
    } catch (const std::runtime_error&) { // no ray for the crossing parity (a degenerate mesh): declined
        return std::nullopt;
    }
    std::vector<std::array<double, 9>> tris;
    for (const auto& t : d.t)
        tris.push_back(
            {d.v[t[0]][0], d.v[t[0]][1], d.v[t[0]][2], d.v[t[1]][0], d.v[t[1]][1], d.v[t[1]][2], d.v[t[2]][0], d.v[t[2]][1], d.v[t[2]][2]});
    return triangles_within(tris, x);
}

} // namespace support
