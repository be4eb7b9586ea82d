// The mesh oracle's box containment (oracle::mesh_contains_box), over CGAL Epeck.
// A full box B lies in the mesh's point set iff every open cell of the surface's arrangement
// inside B has odd crossing parity (the set is closed, and B is the closure of its interior). Two
// cells that share a wall differ in parity by the number of triangles covering the wall there, so
// the cells agree iff no plane carries an odd coverage inside B; then one point of B's interior
// off the surface decides. Here each plane that cuts B's interior and holds triangles is cut
// into the cells of the arrangement of its triangles' edge lines and the traces of B's six face
// planes (lines a x + b y + c = 0 with FT coefficients in the plane's projection along an axis it
// is not parallel to, met by Cramer's rule); each such
// cell is met by a vertical line between two consecutive x-coordinates of the arrangement's
// vertices, between two consecutive lines along it, and its witness there, lifted back onto the
// plane, counts the triangles holding it when it lies inside B. Then the box's centre (or a point
// moved off the surface along (d, d^2, d^3)) decides by crossing parity. A flat box is its
// rectangle's two triangles, a segment or a point (mesh_contains_triangle, mesh_contains_segment).
#include "cgal_oracle.hpp"
#include "cgal_parity.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <algorithm>
#include <stdexcept>
#include <vector>

namespace oracle {
namespace {
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using P3 = K::Point_3;
using P2 = K::Point_2;
using FT = K::FT;

FT at(const P3& p, int i) { return i == 0 ? p.x() : (i == 1 ? p.y() : p.z()); }
FT at(const K::Vector_3& p, int i) { return i == 0 ? p.x() : (i == 1 ? p.y() : p.z()); }

// A line a x + b y + c = 0 in the plane's projection. (CGAL's Line_2 intersection reports no
// point where the point's double approximation overflows, so lines are met here by Cramer's rule
// in FT.)
struct line2 {
    FT a, b, c;
};
line2 through(const P2& p, const P2& q) { return {p.y() - q.y(), q.x() - p.x(), p.x() * q.y() - q.x() * p.y()}; }
bool same_line(const line2& l, const line2& m) { return l.a * m.b == m.a * l.b && l.a * m.c == m.a * l.c && l.b * m.c == m.b * l.c; }

// The triangles of one plane, and the plane's box cells: is some cell inside the box lo..hi
// covered an odd number of times?
bool odd_cover(const std::vector<std::array<P3, 3>>& tris, const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
    const K::Plane_3 h(tris[0][0], tris[0][1], tris[0][2]);
    const K::Vector_3 n = h.orthogonal_vector();
    const int w = n.x() != 0 ? 0 : (n.y() != 0 ? 1 : 2), u = (w + 1) % 3, v = (w + 2) % 3;
    const FT nw = at(n, w), nu = at(n, u), nv = at(n, v), d = h.d();
    auto flat = [&](const P3& p) { return P2(at(p, u), at(p, v)); };
    std::vector<line2> lines;
    auto add = [&](const line2& l) {
        for (const auto& m : lines)
            if (same_line(l, m)) return;
        lines.push_back(l);
    };
    std::vector<K::Triangle_2> in_plane;
    for (const auto& t : tris) {
        const P2 a = flat(t[0]), b = flat(t[1]), c = flat(t[2]);
        in_plane.emplace_back(a, b, c);
        add(through(a, b)), add(through(b, c)), add(through(c, a));
    }
    // the box's faces: x_u = const, x_v = const, and x_w = const where nu x_u + nv x_v + nw x_w + d = 0
    for (const double bound : {lo[static_cast<unsigned>(u)], hi[static_cast<unsigned>(u)]}) add({FT(1), FT(0), -FT(bound)});
    for (const double bound : {lo[static_cast<unsigned>(v)], hi[static_cast<unsigned>(v)]}) add({FT(0), FT(1), -FT(bound)});
    if (nu != 0 || nv != 0)
        for (const double bound : {lo[static_cast<unsigned>(w)], hi[static_cast<unsigned>(w)]}) add({nu, nv, d + nw * bound});
    std::vector<FT> xs;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const line2& l = lines[i];
        if (l.b == 0) xs.push_back(-l.c / l.a);
        for (std::size_t j = i + 1; j < lines.size(); ++j) {
            const line2& m = lines[j];
            const FT den = l.a * m.b - m.a * l.b;
            if (den != 0) xs.push_back((l.b * m.c - m.b * l.c) / den);
        }
    }
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
        const FT x = (xs[i] + xs[i + 1]) / 2;
        std::vector<FT> ys;
        for (const auto& l : lines)
            if (l.b != 0) ys.push_back(-(l.a * x + l.c) / l.b);
        std::sort(ys.begin(), ys.end());
        ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
        for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
            const FT y = (ys[j] + ys[j + 1]) / 2;
            const FT z = -(nu * x + nv * y + d) / nw;
            FT p[3];
            p[u] = x, p[v] = y, p[w] = z;
            bool inside = true;
            for (unsigned k = 0; k < 3 && inside; ++k) inside = FT(lo[k]) < p[k] && p[k] < FT(hi[k]);
            if (!inside) continue;
            const P2 q(x, y);
            int covered = 0;
            for (const auto& t : in_plane) covered += t.has_on_bounded_side(q) ? 1 : 0;
            if (covered % 2 == 1) return true;
        }
    }
    return false;
}
} // namespace

bool mesh_contains_box(const mesh_data& m, const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
    int flat_axes = 0, flat_axis = -1;
    for (unsigned k = 0; k < 3; ++k)
        if (lo[k] == hi[k]) ++flat_axes, flat_axis = static_cast<int>(k);
    if (flat_axes >= 2) return mesh_contains_segment(m, lo, hi);
    if (flat_axes == 1) {
        const auto j = static_cast<unsigned>((flat_axis + 1) % 3);
        std::array<double, 3> c10 = lo, c01 = hi;
        c10[j] = hi[j], c01[j] = lo[j];
        return mesh_contains_triangle(m, lo, c10, hi) && mesh_contains_triangle(m, lo, hi, c01);
    }
    std::array<double, 3> mlo{}, mhi{};
    vertex_box(m, mlo, mhi);
    for (unsigned k = 0; k < 3; ++k)
        if (lo[k] < mlo[k] || hi[k] > mhi[k]) return false;
    // the planes that cut the box's interior (corners strictly on both sides), each with its triangles
    std::vector<P3> corner;
    for (int i = 0; i < 8; ++i) corner.emplace_back((i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]);
    std::vector<std::vector<std::array<P3, 3>>> planes;
    for (const auto& t : m.t) {
        bool apart = false;
        for (unsigned k = 0; k < 3; ++k) {
            const double x = m.v[t[0]][k], y = m.v[t[1]][k], z = m.v[t[2]][k];
            apart = apart || std::max({x, y, z}) <= lo[k] || std::min({x, y, z}) >= hi[k];
        }
        if (apart) continue;
        const std::array<P3, 3> f{P3(m.v[t[0]][0], m.v[t[0]][1], m.v[t[0]][2]), P3(m.v[t[1]][0], m.v[t[1]][1], m.v[t[1]][2]),
                                  P3(m.v[t[2]][0], m.v[t[2]][1], m.v[t[2]][2])};
        if (CGAL::collinear(f[0], f[1], f[2])) continue; // no area: no wall
        bool pos = false, neg = false;
        for (const P3& c : corner) {
            const auto s = CGAL::orientation(f[0], f[1], f[2], c);
            pos = pos || s == CGAL::POSITIVE, neg = neg || s == CGAL::NEGATIVE;
        }
        if (!pos || !neg) continue;
        bool placed = false;
        for (auto& g : planes)
            if (CGAL::coplanar(g[0][0], g[0][1], g[0][2], f[0]) && CGAL::coplanar(g[0][0], g[0][1], g[0][2], f[1]) &&
                CGAL::coplanar(g[0][0], g[0][1], g[0][2], f[2])) {
                g.push_back(f);
                placed = true;
                break;
            }
        if (!placed) planes.push_back({f});
    }
    for (const auto& g : planes)
        if (odd_cover(g, lo, hi)) return false;
    // one point of the interior off the surface
    const P3 centre(FT(lo[0]) / 2 + FT(hi[0]) / 2, FT(lo[1]) / 2 + FT(hi[1]) / 2, FT(lo[2]) / 2 + FT(hi[2]) / 2);
    FT step(1);
    for (int attempt = 0; attempt < 200; ++attempt, step /= 2) {
        const P3 p = attempt == 0
                         ? centre
                         : P3(centre.x() + step * (FT(hi[0]) - FT(lo[0])) / 4, centre.y() + step * step * (FT(hi[1]) - FT(lo[1])) / 4,
                              centre.z() + step * step * step * (FT(hi[2]) - FT(lo[2])) / 4);
        bool on = false;
        for (const auto& t : m.t) {
            const P3 a(m.v[t[0]][0], m.v[t[0]][1], m.v[t[0]][2]), b(m.v[t[1]][0], m.v[t[1]][1], m.v[t[1]][2]),
                c(m.v[t[2]][0], m.v[t[2]][1], m.v[t[2]][2]);
            if (!CGAL::collinear(a, b, c) && CGAL::coplanar(a, b, c, p) && K::Triangle_3(a, b, c).has_on(p)) {
                on = true;
                break;
            }
        }
        if (on) continue;
        return crossing_parity<K>(m, p, {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}, mlo, mhi);
    }
    throw std::runtime_error("mesh_contains_box: no point of the box off the surface in 200 tries");
}

} // namespace oracle
