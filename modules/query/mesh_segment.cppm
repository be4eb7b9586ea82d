// mesh3 against segment3 (a point when a == b), and contains(mesh, segment).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the bounding boxes, then any triangle meeting the segment (segment_triangle), else the parity of an end point.
// contains: every point of the segment a + t (b - a), 0 <= t <= 1, in the set. The parameters
// where the segment meets the surface form closed intervals; their end points are breakpoints: a
// triangle met across its plane gives t = det(b0 - a0, c0 - a0, a0 - a) / det(b0 - a0, c0 - a0,
// b - a); a triangle whose plane holds the segment (or a collinear one) gives, for each edge p q,
// where the segment's line meets the plane through p q along a coordinate axis e_k (where the
// edge's line crosses it), or, for an edge parallel to the segment, the parameters of p and q. All
// are det(E, F, x - a) / det(E, F, b - a) for two difference vectors E, F (edges, or unit axes
// lifted as L(1) - L(0), an input of degree 1), of degree 3 over degree 3; extra breakpoints
// only split an interval in two. Between two consecutive breakpoints (sorted exactly, degree 6)
// the segment lies wholly on one triangle in its plane or wholly off the surface, where parity is
// constant: one point of the piece decides, on such a triangle or by the crossing parity of
// mesh_point.cppm: a + t (b - a) for a double t proven between the two (degree 4), or else the
// exact midpoint V / W (V of degree 7, W = 2 D1 D2 > 0; degree 8 on the triangle, 9 for the
// parity). No triangle meeting the segment: the parity of an end point. The breakpoints are kept in a std::vector (an allocation
// only when the segment meets the surface).
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm (Haines,
// Graphics Gems IV, 1994); the segment split at its crossings, as in point-in-polyhedron segment
// classification (O'Rourke, Computational Geometry in C, 2nd ed., 7.5).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent, or (contains) when a deciding sign's permanent leaves [2^-900, 2^900], where plain
// double under- or overflows: its signs have degree up to 9, so from inputs beyond about 2^+-90
// on (tests/query/mesh_segment.cpp).
module;
#include <cstddef>
#include <utility>
#include <vector>
export module incidence.query:mesh_segment;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :mesh_point;
import :segment_triangle;
import :point_tetrahedron;
import :segment_pieces;
import incidence.predicates;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const segment3& s) {
    if (!meshq::well_formed(m) || !finite(s)) return false;
    const point3 pts[2] = {s.a, s.b};
    const aabb3 xb = meshq::bounds(pts, 2);
    if (!meshq::boxes_meet(meshq::bounds(m), xb)) return false;
    return meshq::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, s, f); }, s.a, &xb);
}

namespace meshq {

// A parameter along the segment s, t = N / D with N = det(E, F, x - a) and D = det(E, F, b - a),
// E = e1 - e0 and F = f1 - f0; both negated when `flip`, so that D > 0.
struct segment_param {
    point3 x, e0, e1, f0, f1;
    bool flip = false;
    template <class L>
    [[nodiscard]] constexpr auto fraction(L lift, const segment3& s) const {
        const auto E = arith::lift(lift, e1) - arith::lift(lift, e0), F = arith::lift(lift, f1) - arith::lift(lift, f0);
        const auto A = arith::lift(lift, s.a);
        const auto n = arith::det3(E, F, arith::lift(lift, x) - A), d = arith::det3(E, F, arith::lift(lift, s.b) - A);
        return flip ? std::pair{-n, -d} : std::pair{n, d};
    }
};
inline constexpr point3 origin{0.0, 0.0, 0.0};
[[nodiscard]] constexpr point3 unit(int axis) { return {axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0}; }

// A point of the segment s, inside its bounding box `box`: along +x the ray from it misses a
// triangle whose box the ray from any point of `box` misses.
struct in_segment_box {
    aabb3 box;
    [[nodiscard]] constexpr bool near(const aabb3&) const { return true; } // the caller checked the segment's box
    [[nodiscard]] constexpr bool x_ray_misses(const aabb3& tb) const {
        return tb.max.x < box.min.x || box.max.y < tb.min.y || box.min.y > tb.max.y || box.max.z < tb.min.z || box.min.z > tb.max.z;
    }
};
// The point a + t (b - a) for a double t, V / W with W = L(1) (a constant lifted as an input, so
// the signs stay homogeneous: degree 4 for the parity).
struct segment_at : in_segment_box {
    segment3 s;
    double t;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto W = lift(1.0), T = lift(t);
        const auto A = arith::lift(lift, s.a);
        const auto D = arith::lift(lift, s.b) - A;
        using U = decltype(W * A.x + T * D.x);
        return std::pair{arith::v3<U>{W * A.x + T * D.x, W * A.y + T * D.y, W * A.z + T * D.z}, W};
    }
};
// The point of s midway between the parameters lo and hi, V / W with W = 2 D_lo D_hi > 0 (degree
// 9 for the parity), where no double lies provably between them.
struct segment_point : in_segment_box {
    segment3 s;
    segment_param lo, hi;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto [n1, d1] = lo.fraction(lift, s);
        const auto [n2, d2] = hi.fraction(lift, s);
        const auto W = d1 * d2 + d1 * d2;
        const auto M = n1 * d2 + n2 * d1;
        const auto A = arith::lift(lift, s.a);
        const auto D = arith::lift(lift, s.b) - A;
        using T = decltype(W * A.x + M * D.x);
        return std::pair{arith::v3<T>{W * A.x + M * D.x, W * A.y + M * D.y, W * A.z + M * D.z}, W};
    }
};

// Is the midpoint q (of a segment in t's plane, or along a collinear t) on the triangle t?
template <class K, class Q>
[[nodiscard]] constexpr bool on_triangle(K& k, const triangle3& t, const Q& q) {
    const point3 v[3] = {t.a, t.b, t.c};
    auto normal = [&](int axis) {
        return k.sgn([=](auto L) {
            const auto a = arith::lift(L, v[0]);
            const auto n = arith::cross(arith::lift(L, v[1]) - a, arith::lift(L, v[2]) - a);
            return axis == 0 ? n.x : (axis == 1 ? n.y : n.z);
        });
    };
    // (y - x) x (V - W x), one component or all
    auto edge = [&](point3 x, point3 y, int axis) {
        return k.sgn([=, &q](auto L) {
            const auto [V, W] = q.weighted(L);
            const auto X = arith::lift(L, x);
            using T = decltype(V.x - W * X.x);
            const auto c = arith::cross(arith::lift(L, y) - X, arith::v3<T>{V.x - W * X.x, V.y - W * X.y, V.z - W * X.z});
            return axis == 0 ? c.x : (axis == 1 ? c.y : c.z);
        });
    };
    for (int axis = 0; axis < 3; ++axis)
        if (const sign n = normal(axis); n != sign::zero) { // the plane seen along this axis
            for (int i = 0; i < 3; ++i)
                if (const sign e = edge(v[i], v[(i + 1) % 3], axis); e != sign::zero && e != n) return false;
            return true;
        }
    // a collinear triangle: the union of its edges; (V - W x) . (y - x) >= 0 from both ends
    for (int i = 0; i < 3; ++i) {
        const point3 x = v[i], y = v[(i + 1) % 3];
        if (x.x == y.x && x.y == y.y && x.z == y.z) continue; // a point holds no piece
        if (edge(x, y, 0) != sign::zero || edge(x, y, 1) != sign::zero || edge(x, y, 2) != sign::zero) continue;
        auto from = [&](point3 p, point3 r) {
            return k.sgn([=, &q](auto L) {
                const auto [V, W] = q.weighted(L);
                const auto P = arith::lift(L, p);
                using T = decltype(V.x - W * P.x);
                return arith::dot(arith::v3<T>{V.x - W * P.x, V.y - W * P.y, V.z - W * P.z}, arith::lift(L, r) - P);
            });
        };
        if (from(x, y) != sign::negative && from(y, x) != sign::negative) return true;
    }
    return false;
}

} // namespace meshq

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const mesh3& m, const segment3& s) {
    using meshq::segment_param;
    if (!meshq::well_formed(m) || !finite(s)) return false;
    const aabb3 mb = meshq::bounds(m);
    if (!meshq::in_box(mb, s.a) || !meshq::in_box(mb, s.b)) return false; // the set lies in the vertices' box
    if (s.a.x == s.b.x && s.a.y == s.b.y && s.a.z == s.b.z) return contains(k, m, s.a);
    const point3 pts[2] = {s.a, s.b};
    const aabb3 sb = meshq::bounds(pts, 2);
    // An axis along which the segment moves, for the parameters of points (det(e_j+1, e_j+2, x - a) = (x - a)_j).
    const int j = s.a.x != s.b.x ? 0 : (s.a.y != s.b.y ? 1 : 2);
    const point3 u1 = meshq::unit((j + 1) % 3), u2 = meshq::unit((j + 2) % 3);
    auto fraction = [s](auto L, const segment_param& p) { return p.fraction(L, s); };
    std::vector<segment_param> params;
    std::vector<std::size_t> in_plane; // triangles that may hold a piece of the segment
    bool met = false;
    auto keep = [&](const segment_param& p) { return pieces::keep(k, fraction, p, params); };
    auto at_point = [&](point3 x) { (void)keep(segment_param{x, meshq::origin, u1, meshq::origin, u2}); };
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 t = m.triangle(i);
        const point3 v[3] = {t.a, t.b, t.c};
        if (!meshq::boxes_meet(meshq::bounds(v, 3), sb) || !intersects(k, s, t)) continue;
        met = true;
        const sign oa = k.sgn([=](auto L) { return poly::orient3d(L, t.a, t.b, t.c, s.a); });
        const sign ob = k.sgn([=](auto L) { return poly::orient3d(L, t.a, t.b, t.c, s.b); });
        if (oa != sign::zero || ob != sign::zero) { // across the plane: one point
            (void)keep(segment_param{t.a, t.a, t.b, t.a, t.c});
            continue;
        }
        in_plane.push_back(i);
        for (int e = 0; e < 3; ++e) {
            const point3 p = v[e], q = v[(e + 1) % 3];
            bool crossed = false;
            for (int axis = 0; axis < 3 && !crossed; ++axis) crossed = keep(segment_param{p, p, q, meshq::origin, meshq::unit(axis)});
            if (!crossed) at_point(p), at_point(q); // parallel to the segment
        }
    }
    if (!met) return meshq::inside(k, m, s.a); // wholly off the surface
    // t = (a - a)_j / (b - a)_j = 0 and (b - a)_j / (b - a)_j = 1, D made positive
    const bool flip = s.b.x != s.a.x ? s.b.x < s.a.x : (s.b.y != s.a.y ? s.b.y < s.a.y : s.b.z < s.a.z);
    const segment_param start{s.a, meshq::origin, u1, meshq::origin, u2, flip}, end{s.b, meshq::origin, u1, meshq::origin, u2, flip};
    // a piece on a triangle in its plane, or else inside
    auto decide = [&](const auto& q) {
        for (std::size_t n = 0; n < in_plane.size(); ++n)
            if (meshq::on_triangle(k, m.triangle(in_plane[n]), q)) return true;
        return meshq::inside_at(k, m, q);
    };
    return pieces::all_pieces(
        k, params, start, end, fraction, [&](double t) { return decide(meshq::at_weighted<meshq::segment_at>{{{sb}, s, t}}); },
        [&](const segment_param& lo, const segment_param& hi) { return decide(meshq::at_weighted<meshq::segment_point>{{{sb}, s, lo, hi}}); });
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const mesh3&, const segment3&);
extern template bool contains(arith::exact_kernel&, const mesh3&, const segment3&);
} // namespace incidence::pair
