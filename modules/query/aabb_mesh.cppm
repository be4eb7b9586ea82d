// aabb3 against mesh3 (closed box; an inverted box is empty), and contains(mesh, box).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the bounding boxes, then any mesh triangle meeting the box (the 13-axis aabb_triangle
// test; a mesh inside the box has its triangles inside it), else the parity of a corner.
// contains: every point of the box in the set. A flat box is its rectangle's two triangles, a
// segment or a point (contains(mesh, triangle | segment | point)). A full box B lies in the set
// iff its interior does, and its interior off the surface is cut into cells whose parities differ
// across a wall only where the surface there is covered an odd number of times: so B lies in the
// set iff (1) no plane holds an odd part of the surface inside B, and (2) one point of B's
// interior off the surface has odd parity. (1): the non-collinear triangles reaching B's interior
// (the 13 axes with touching counted as separated, aabb_triangle's meets_interior) are grouped by
// plane (orient3d, degree 3); a plane with one of them is odd there. With several (coplanar
// triangles of one surface side by side, or of two shells glued face to face), their coverage is
// odd somewhere inside B iff their edges, added up modulo 2 along each line (collinearity seen
// along an axis the plane is not parallel to, degree 2; end points ordered by one coordinate),
// leave an odd piece reaching B's interior (a segment p q as the triangle p q q), or else the
// coverage, constant inside B, is odd at one point: where a diagonal of B whose corners lie
// strictly on either side crosses the plane, X = (s' k - s k') / (s' - s) with s = orient3d at
// the corners (degree 4 over 3), counted in each triangle seen along that axis and moved by
// eps e_u + eps^2 e_v off any edge through it (degree 5, then coordinate comparisons). (2): the
// parity at B's centre, V / W = (0.5 (min + max)) / 1 (mesh_point.cppm; the ray from a point on the
// surface counts the crossings of the point just ahead of it, inside B; degree 4).
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm (Haines,
// Graphics Gems IV, 1994); the cells of a polyhedral subdivision and the parity change across a
// wall as in Edelsbrunner, Algorithms in Combinatorial Geometry (1987), ch. 7; the perturbed
// point as in Edelsbrunner and Muecke, "Simulation of Simplicity", ACM TOG 9(1), 1990.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/aabb_mesh.cpp); contains of a flat box (through contains(mesh,
// triangle), degree up to 10) also when a deciding sign's permanent leaves [2^-900, 2^900],
// from inputs beyond about 2^+-90 on.
module;
#include <array>
#include <cstddef>
#include <utility>
#include <vector>
export module incidence.query:aabb_mesh;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.predicates;
import :segment_segment;
import :mesh_point;
import :mesh_segment;
import :mesh_triangle;
import :segment_pieces;
import :aabb_triangle;
import :aabb_tetrahedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const mesh3& m) {
    if (!meshq::well_formed(m) || !well_formed_finite(b) || !meshq::boxes_meet(meshq::bounds(m), b)) return false;
    return meshq::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, b, f); }, b.min, &b);
}

namespace meshq {

// The centre of the full box `box`, V / W = (0.5 (min + max)) / 1, both lifted as inputs so the
// parity's signs stay homogeneous (degree 4).
struct box_centre : in_segment_box {
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto h = lift(0.5);
        const auto lo = arith::lift(lift, box.min), hi = arith::lift(lift, box.max);
        using T = decltype(h * (lo.x + hi.x));
        return std::pair{arith::v3<T>{h * (lo.x + hi.x), h * (lo.y + hi.y), h * (lo.z + hi.z)}, lift(1.0)};
    }
};

// Where the diagonal from the corner k to the corner kk crosses the plane of t: with s and s' the
// orient3d values of k and kk, X = (s' k - s kk) / (s' - s), V of degree 4 and W of degree 3.
struct diagonal_point {
    triangle3 t;
    point3 k, kk;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto s = poly::orient3d(lift, t.a, t.b, t.c, k), s2 = poly::orient3d(lift, t.a, t.b, t.c, kk);
        const auto K = arith::lift(lift, k), KK = arith::lift(lift, kk);
        using T = decltype(s2 * K.x - s * KK.x);
        return std::pair{arith::v3<T>{s2 * K.x - s * KK.x, s2 * K.y - s * KK.y, s2 * K.z - s * KK.z}, s2 - s};
    }
};

[[nodiscard]] constexpr double coord(const point3& p, int i) { return i == 0 ? p.x : (i == 1 ? p.y : p.z); }

// The sign of the k-th component of t's normal (b - a) x (c - a).
template <class K>
[[nodiscard]] constexpr sign normal_sign(K& k, const triangle3& t, int axis) {
    return k.sgn([=](auto L) {
        const auto a = arith::lift(L, t.a);
        return cross_along(axis, arith::lift(L, t.b) - a, arith::lift(L, t.c) - a);
    });
}
[[nodiscard]] constexpr bool same(const point3& p, const point3& q) { return p.x == q.x && p.y == q.y && p.z == q.z; }
// An axis along which t's normal is nonzero, or -1 for a collinear triangle. A triangle in a
// coordinate plane can only have that axis (comparisons); otherwise an axis the filter proves
// nonzero comes first, then exact signs (a zero component is often exact, which only those settle).
template <class K>
[[nodiscard]] constexpr int normal_axis(K& k, const triangle3& t) {
    for (int axis = 0; axis < 3; ++axis)
        if (coord(t.a, axis) == coord(t.b, axis) && coord(t.a, axis) == coord(t.c, axis))
            return normal_sign(k, t, axis) != sign::zero ? axis : -1;
    for (int axis = 0; axis < 3; ++axis)
        if (arith::probe(k, [=](auto L) {
                const auto a = arith::lift(L, t.a);
                return cross_along(axis, arith::lift(L, t.b) - a, arith::lift(L, t.c) - a);
            }) != sign::zero)
            return axis;
    for (int axis = 0; axis < 3; ++axis)
        if (normal_sign(k, t, axis) != sign::zero) return axis;
    return -1;
}
// Does the plane of r hold the triangle f? (A vertex of r's lies in it.)
template <class K>
[[nodiscard]] constexpr bool coplanar(K& k, const triangle3& r, const triangle3& f) {
    for (const point3& p : {f.a, f.b, f.c})
        if (!same(p, r.a) && !same(p, r.b) && !same(p, r.c) && !arith::is_zero(k, [=](auto L) { return poly::orient3d(L, r.a, r.b, r.c, p); }))
            return false;
    return true;
}

// Does the triangle f, seen along `axis` in the plane, hold the point q = V / W (W of sign
// `w`) moved by eps e_u + eps^2 e_v, (axis, u, v) cyclic? Off every edge line, so strictly.
template <class K, class Q>
[[nodiscard]] constexpr bool holds_nudged(K& k, const triangle3& f, int axis, const Q& q, sign w) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const sign turn = normal_sign(k, f, axis);
    const point3 p[3] = {f.a, f.b, f.c};
    for (int i = 0; i < 3; ++i) {
        const point3 a = p[i], c = p[(i + 1) % 3];
        sign e = k.sgn([=, &q](auto L) { // (c - a) x (V - W a) along the axis
            const auto [V, W] = q.weighted(L);
            const auto A = arith::lift(L, a);
            using T = decltype(V.x - W * A.x);
            return cross_along(axis, arith::lift(L, c) - A, arith::v3<T>{V.x - W * A.x, V.y - W * A.y, V.z - W * A.z});
        });
        if (w == sign::negative) e = e == sign::positive ? sign::negative : (e == sign::negative ? sign::positive : sign::zero);
        // on the edge's line: (c - a) x e_u = -(c - a)_v, then (c - a) x e_v = (c - a)_u
        if (e == sign::zero) e = arith::compare(k, coord(a, v), coord(c, v));
        if (e == sign::zero) e = arith::compare(k, coord(c, u), coord(a, u));
        if (e != turn) return false;
    }
    return true;
}

// The triangles `group` (indices into m, at least two, all in the plane of the first, each reaching
// the interior of the full box b): is their coverage odd somewhere inside b? See the top comment.
template <class K>
[[nodiscard]] constexpr bool odd_inside(K& k, const mesh3& m, const aabb3& b, const std::vector<std::size_t>& group) {
    const triangle3 r = m.triangle(group[0]);
    const int axis = normal_axis(k, r);
    if (axis < 0) return false; // (a collinear triangle is never grouped; an inexact kernel's guess)
    auto side = [&](point3 x0, point3 x1, point3 y) {
        return k.sgn([=](auto L) {
            const auto X = arith::lift(L, x0);
            return cross_along(axis, arith::lift(L, x1) - X, arith::lift(L, y) - X);
        });
    };
    // The edges, by line: each line's end points in the order of a coordinate that changes along it.
    struct end {
        double at;
        point3 p;
    };
    std::vector<std::array<point3, 2>> edges;
    for (const std::size_t i : group) {
        const triangle3 f = m.triangle(i);
        edges.push_back({f.a, f.b}), edges.push_back({f.b, f.c}), edges.push_back({f.c, f.a});
    }
    std::vector<unsigned char> done(edges.size(), 0);
    std::vector<end> ends;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (done[i] != 0) continue;
        const point3 p = edges[i][0], q = edges[i][1];
        const int c = p.x != q.x ? 0 : (p.y != q.y ? 1 : 2);
        ends.clear();
        for (std::size_t j = i; j < edges.size(); ++j) {
            if (done[j] != 0) continue;
            auto on_line = [&](const point3& y) { return same(y, p) || same(y, q) || side(p, q, y) == sign::zero; };
            if (j != i && (!on_line(edges[j][0]) || !on_line(edges[j][1]))) continue;
            done[j] = 1;
            ends.push_back({coord(edges[j][0], c), edges[j][0]}), ends.push_back({coord(edges[j][1], c), edges[j][1]});
        }
        pieces::merge_sort(ends, [](const end& x, const end& y) { return x.at < y.at; });
        // between two consecutive distinct points, the parity of the end points up to the first
        std::size_t below = 0;
        for (std::size_t n = 0; n < ends.size();) {
            std::size_t next = n;
            while (next < ends.size() && ends[next].at == ends[n].at) ++next;
            below += next - n;
            if (next < ends.size() && below % 2 == 1 && meets_interior(k, b, triangle3{ends[n].p, ends[next].p, ends[next].p})) return true;
            n = next;
        }
    }
    // No odd piece of an edge inside b: the coverage is constant there. A diagonal k kk of b with
    // its corners strictly on either side of the plane crosses it inside b.
    const box_corners corner(b);
    for (int i = 0; i < 4; ++i) {
        const point3 c0 = corner.p[i], c1 = corner.p[7 - i];
        const sign s0 = k.sgn([=](auto L) { return poly::orient3d(L, r.a, r.b, r.c, c0); });
        const sign s1 = k.sgn([=](auto L) { return poly::orient3d(L, r.a, r.b, r.c, c1); });
        if (s0 == sign::zero || s1 == sign::zero || s0 == s1) continue;
        const diagonal_point X{r, c0, c1};
        const sign w = s1 == sign::positive ? sign::positive : sign::negative; // s' - s
        bool odd = false;
        for (const std::size_t f : group) odd = odd != holds_nudged(k, m.triangle(f), axis, X, w);
        return odd;
    }
    return false; // (every plane reaching b's interior has such a diagonal; an inexact kernel's guess)
}

} // namespace meshq

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const mesh3& m, const aabb3& b) {
    if (!meshq::well_formed(m) || !well_formed_finite(b)) return false;
    const aabb3 mb = meshq::bounds(m);
    if (!meshq::in_box(mb, b.min) || !meshq::in_box(mb, b.max)) return false; // the set lies in the vertices' box
    const bool flat[3] = {b.min.x == b.max.x, b.min.y == b.max.y, b.min.z == b.max.z};
    if (int(flat[0]) + int(flat[1]) + int(flat[2]) >= 2) return contains(k, m, segment3{b.min, b.max}); // a segment or a point
    for (int i = 0; i < 3; ++i)
        if (flat[i]) { // a rectangle: its two triangles
            const int j = (i + 1) % 3;
            const point3 c10 = box_triangle_detail::with(b.min, j, meshq::coord(b.max, j));
            const point3 c01 = box_triangle_detail::with(b.max, j, meshq::coord(b.min, j));
            return contains(k, m, triangle3{b.min, c10, b.max}) && contains(k, m, triangle3{b.min, b.max, c01});
        }
    // The walls: non-collinear triangles reaching the interior (a triangle whose box does not
    // overlap the interior's cannot).
    std::vector<std::size_t> walls;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 f = m.triangle(i);
        const point3 v[3] = {f.a, f.b, f.c};
        const aabb3 fb = meshq::bounds(v, 3);
        if (!(fb.min.x < b.max.x && b.min.x < fb.max.x && fb.min.y < b.max.y && b.min.y < fb.max.y && fb.min.z < b.max.z &&
              b.min.z < fb.max.z))
            continue;
        if (meets_interior(k, b, f) && meshq::normal_axis(k, f) >= 0) walls.push_back(i);
    }
    if (meshq::gave_up(k)) return false; // (the filter's answer is discarded: the exact kernel decides)
    // By plane: a plane with one wall is odd inside the box; several are added up.
    std::vector<unsigned char> grouped(walls.size(), 0);
    std::vector<std::size_t> group;
    for (std::size_t i = 0; i < walls.size(); ++i) {
        if (grouped[i] != 0) continue;
        const triangle3 r = m.triangle(walls[i]);
        group.assign(1, walls[i]);
        for (std::size_t j = i + 1; j < walls.size(); ++j)
            if (grouped[j] == 0 && meshq::coplanar(k, r, m.triangle(walls[j]))) grouped[j] = 1, group.push_back(walls[j]);
        if (group.size() == 1 || meshq::odd_inside(k, m, b, group) || meshq::gave_up(k)) return false;
    }
    return meshq::inside_at(k, m, meshq::at_weighted<meshq::box_centre>{{{b}}});
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const mesh3&);
extern template bool contains(arith::exact_kernel&, const mesh3&, const aabb3&);
} // namespace incidence::pair
