// polygon3{vertices, ring_ends, plane_vertices, axis}: a planar polygon in space with holes,
// viewed (the caller owns both arrays): rings as in polygon2 (ring i is vertices [ring_ends[i-1],
// ring_ends[i]); no ring_ends: one ring of every vertex), every vertex in the plane of the three
// vertices `plane_vertices`. Its point set is the set of points of that plane whose projection
// along coordinate `axis` (dropped: x for 0, y for 1, z for 2) lies in the polygon2 of the
// projected rings: its edges together with the points of odd crossing parity (the even-odd rule:
// a ring inside the outer ring is a hole). Convex or not, either orientation for every ring.
// make() finds the plane and the axis (the normal's largest component) itself, and refuses no
// vertices, non-finite ones, bad ring ends, a ring of fewer than three vertices, all vertices on
// one line (degenerate_polygon), a vertex off the plane of the others by any amount, decided
// exactly (non_planar_polygon, with the largest distance off the plane measured), and a boundary
// that meets itself (self_intersecting_polygon, decided exactly in the projection). Aggregate
// construction accepts anything and queries never read out of range: bad indices, an axis outside
// 0..2, or plane vertices whose normal has a zero component along `axis` make no set (every
// query says no); for vertices that are not coplanar the queries answer for the procedure of
// modules/query/point_polygon.cppm (edges, then crossing parity in the plane), not for a set.
// Source: the dimension reduction of Haines, "Point in polygon strategies", Graphics Gems IV
// (1994), section 1 (project along the normal's largest component).
module;
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>
export module incidence.shapes:polygon3;
import incidence.core;
import incidence.arith;
import :polygon2;

export namespace incidence {

struct polygon3 {
    std::span<const point3> vertices;
    std::span<const std::uint32_t> ring_ends;
    std::array<std::uint32_t, 3> plane_vertices;
    int axis;

    [[nodiscard]] constexpr std::size_t rings() const { return ring_ends.empty() ? 1 : ring_ends.size(); }
    [[nodiscard]] constexpr std::size_t ring_begin(std::size_t i) const { return i == 0 ? 0 : ring_ends[i - 1]; }
    [[nodiscard]] constexpr std::size_t ring_end(std::size_t i) const { return ring_ends.empty() ? vertices.size() : ring_ends[i]; }
    [[nodiscard]] static constexpr std::size_t next(std::size_t j, std::size_t b, std::size_t e) { return j + 1 == e ? b : j + 1; }
    // Ring ends increase strictly up to the number of vertices, the plane vertices exist, the axis
    // is 0, 1 or 2.
    [[nodiscard]] constexpr bool indices_valid() const {
        if (vertices.empty() || axis < 0 || axis > 2) return false;
        for (const std::uint32_t i : plane_vertices)
            if (i >= vertices.size()) return false;
        std::size_t previous = 0;
        for (std::size_t i = 0; i < ring_ends.size(); ++i) {
            if (ring_ends[i] <= previous || ring_ends[i] > vertices.size()) return false;
            previous = ring_ends[i];
        }
        return ring_ends.empty() || previous == vertices.size();
    }
    // The projection that drops coordinate `axis`: (y, z), (z, x) or (x, y).
    [[nodiscard]] constexpr point2 projected(point3 p) const {
        return axis == 0 ? point2{p.y, p.z} : (axis == 1 ? point2{p.z, p.x} : point2{p.x, p.y});
    }

    [[nodiscard]] static constexpr result<polygon3> make(std::span<const point3> vertices, std::span<const std::uint32_t> ring_ends = {}) {
        if (vertices.empty()) return error{errc::empty_input};
        for (const point3& p : vertices)
            if (!is_finite(p)) return error{errc::not_finite};
        polygon3 g{vertices, ring_ends, {0, 0, 0}, 2};
        if (!g.indices_valid()) return error{errc::index_out_of_range};
        for (std::size_t i = 0; i < g.rings(); ++i)
            if (g.ring_end(i) - g.ring_begin(i) < 3) return error{errc::degenerate_polygon};
        // the plane: vertex 0, the vertex farthest from it, and the vertex farthest from their line
        // (in double), checked exactly; where rounding misled, the first vertex off the line
        const point3 a = vertices[0];
        std::uint32_t b = 0;
        double far = -1;
        for (std::uint32_t i = 0; i < vertices.size(); ++i) {
            const vec3 d = vertices[i] - a;
            if (dot(d, d) > far) far = dot(d, d), b = i;
        }
        const point3 B = vertices[b];
        auto normal_sign = [&](std::uint32_t c, int m) {
            arith::exact_kernel k;
            const point3 C = vertices[c];
            return k.sgn([=](auto L) {
                const auto n = arith::cross(arith::lift(L, B) - arith::lift(L, a), arith::lift(L, C) - arith::lift(L, a));
                return m == 0 ? n.x : (m == 1 ? n.y : n.z);
            });
        };
        std::uint32_t c = 0;
        double best = -1;
        for (std::uint32_t i = 0; i < vertices.size(); ++i) {
            const vec3 n = cross(B - a, vertices[i] - a);
            if (dot(n, n) > best) best = dot(n, n), c = i;
        }
        auto off_line = [&](std::uint32_t i) {
            return normal_sign(i, 0) != sign::zero || normal_sign(i, 1) != sign::zero || normal_sign(i, 2) != sign::zero;
        };
        if (!off_line(c)) {
            bool found = false;
            for (std::uint32_t i = 0; i < vertices.size() && !found; ++i)
                if (off_line(i)) c = i, found = true;
            if (!found) return error{errc::degenerate_polygon}; // every vertex on one line: no area
        }
        g.plane_vertices = {0, b, c};
        // the axis: the normal's largest component in double, or one that is exactly nonzero
        const vec3 n = cross(B - a, vertices[c] - a);
        const double m[3] = {std::fabs(n.x), std::fabs(n.y), std::fabs(n.z)};
        g.axis = m[0] >= m[1] && m[0] >= m[2] ? 0 : (m[1] >= m[2] ? 1 : 2);
        if (normal_sign(c, g.axis) == sign::zero)
            for (int j = 0; j < 3; ++j)
                if (normal_sign(c, j) != sign::zero) g.axis = j;
        // every vertex exactly in the plane; else the largest distance off it, measured in double
        const point3 C = vertices[c];
        double worst = 0;
        bool planar = true;
        for (const point3& p : vertices) {
            arith::exact_kernel k;
            if (k.sgn([=](auto L) {
                    const auto A = arith::lift(L, a);
                    return arith::det3(arith::lift(L, B) - A, arith::lift(L, C) - A, arith::lift(L, p) - A);
                }) != sign::zero) {
                planar = false;
                const double d = std::fabs(dot(n, p - a)) / std::sqrt(dot(n, n));
                worst = d > worst ? d : worst;
            }
        }
        if (!planar) return error{errc::non_planar_polygon, worst};
        // the boundary simple, decided in the projection (where a planar polygon keeps every
        // incidence of its edges)
        std::vector<point2> flat(vertices.size());
        for (std::size_t i = 0; i < vertices.size(); ++i) flat[i] = g.projected(vertices[i]);
        if (!polygon2{flat, ring_ends}.boundary_simple()) return error{errc::self_intersecting_polygon};
        return g;
    }
};

} // namespace incidence
