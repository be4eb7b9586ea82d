// obb3 against tetrahedron3 (closed box, read as the parallelepiped its axes span; closed solid
// tetrahedron, coplanar vertices give their hull).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Method (exact tiers): the box centre inside the solid (four orient3d signs) says yes; otherwise
// the box meets the tetrahedron iff it meets one of its four faces (the 13-axis obb_triangle
// test), since it cannot then lie inside.
// contains(box, tetrahedron): the four vertices in the box. contains(tetrahedron, box): with
// o = orient3d != 0, for each face plane N . (x - q) (N the face's normal, degree 2) the box's
// least value tau N . (c - q) - sum_j h_j |N . a_j| >= 0, tau the side of the opposite vertex
// (degree 4, the support function of the box, so no corner is ever formed). A coplanar tetrahedron
// is its planar hull: the box must lie in the plane (N . (c - q) = 0, h_j N . a_j = 0) and within
// each line through two vertices that has the other two on one side, m = N x (v - u) (degree 5);
// collinear vertices give a segment, one point a point.
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Gottschalk, Lin and
// Manocha, "OBBTree", SIGGRAPH 1996, section 5, for the face tests.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/obb_tetrahedron.cpp).
export module incidence.query:obb_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :separating_axes;
import :obb_triangle;
import :obb_point;
import :point_tetrahedron;

export namespace incidence::pair {

[[nodiscard]] constexpr bool finite(const obb3& b) {
    return finite(b.center) && finite(b.axes[0]) && finite(b.axes[1]) && finite(b.axes[2]) && finite(b.half_extents[0]) &&
           finite(b.half_extents[1]) && finite(b.half_extents[2]);
}

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& b, const tetrahedron3& t) {
    if (!sat::well_formed(b) || !finite(b) || !finite(t)) return false;
    const point3 pts[1] = {b.center};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, b, face); }, pts, 1, false);
}
// Is the tetrahedron inside the box? Its four vertices are (the box is convex).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& b, const tetrahedron3& t) {
    return contains(k, b, t.a) && contains(k, b, t.b) && contains(k, b, t.c) && contains(k, b, t.d);
}

namespace tetra {
// Is the box on the closed side tau f >= 0 of the affine function f(x) = n . (x - q), n(L) a lifted
// vector? Its least value there is tau n . (c - q) - sum_j h_j |n . a_j| (both terms of one degree).
template <class K, class Normal>
[[nodiscard]] constexpr bool box_on_side(K& k, const obb3& b, const Normal& normal, point3 q, double tau) {
    const point3 c = b.center;
    const vec3 a0 = b.axes[0], a1 = b.axes[1], a2 = b.axes[2];
    const double h0 = b.half_extents[0], h1 = b.half_extents[1], h2 = b.half_extents[2];
    return k.sgn([=](auto L) {
               const auto n = normal(L);
               const auto reach = L(h0) * sat::magnitude(arith::dot(n, arith::lift(L, a0))) +
                                  L(h1) * sat::magnitude(arith::dot(n, arith::lift(L, a1))) +
                                  L(h2) * sat::magnitude(arith::dot(n, arith::lift(L, a2)));
               return L(tau) * arith::dot(n, arith::lift(L, c) - arith::lift(L, q)) - reach;
           }) != sign::negative;
}
// Does the box lie in the zero set of the affine function f? zero(x, true) says f(x) = 0 for a
// point, zero(x, false) that f's linear part vanishes on the vector x: the centre, and each axis
// of nonzero extent.
template <class Zero>
[[nodiscard]] constexpr bool box_on_zero(const obb3& b, const Zero& zero) {
    if (!zero(b.center, true)) return false;
    for (unsigned j = 0; j < 3; ++j)
        if (b.half_extents[j] != 0.0 && !zero(point3{b.axes[j].x, b.axes[j].y, b.axes[j].z}, false)) return false;
    return true;
}
} // namespace tetra

// Is the box inside the closed tetrahedron (a coplanar one: its hull)?
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const obb3& b) {
    if (!sat::well_formed(b) || !finite(b) || !finite(t)) return false;
    const point3 v[4] = {t.a, t.b, t.c, t.d};
    const sign o = tetra::orientation(k, t);
    // The face opposite vertex i: the other three in order; N_i . (v_i - q_i) has the sign
    // (+o, -o, +o, -o) for i = 0..3 (orient3d is minus that product, with the vertices rotated).
    auto face_normal = [&](int i) { // (q_i1 - q_i0) x (q_i2 - q_i0), a lifted vector of degree 2
        const point3 q0 = v[i == 0 ? 1 : 0], q1 = v[i <= 1 ? 2 : 1], q2 = v[i <= 2 ? 3 : 2];
        return [=](auto L) {
            const auto Q0 = arith::lift(L, q0);
            return arith::cross(arith::lift(L, q1) - Q0, arith::lift(L, q2) - Q0);
        };
    };
    if (o != sign::zero) {
        for (int i = 0; i < 4; ++i) {
            const double tau = (o == sign::positive) == (i % 2 == 0) ? 1.0 : -1.0;
            if (!tetra::box_on_side(k, b, face_normal(i), v[i == 0 ? 1 : 0], tau)) return false;
        }
        return true;
    }
    // Coplanar vertices: a face with a nonzero normal spans the plane.
    for (int i = 0; i < 4; ++i) {
        const point3 q0 = v[i == 0 ? 1 : 0];
        const auto normal = face_normal(i);
        bool zero = true;
        for (int c = 0; c < 3; ++c)
            zero = zero && arith::is_zero(k, [=](auto L) {
                                const auto n = normal(L);
                                return c == 0 ? n.x : (c == 1 ? n.y : n.z);
                            });
        if (zero) continue;
        // In the plane: N . (c - q0) = 0 and N . a_j = 0 for each used axis.
        if (!tetra::box_on_zero(b, [&](point3 x, bool is_point) {
                if (is_point) return arith::is_zero(k, [=](auto L) { return arith::dot(normal(L), arith::lift(L, x) - arith::lift(L, q0)); });
                return arith::is_zero(k, [=](auto L) { return arith::dot(normal(L), arith::lift(L, vec3{x.x, x.y, x.z})); });
            }))
            return false;
        // Within each line through two vertices that has the other two on one side of it.
        for (int u = 0; u < 4; ++u)
            for (int w = u + 1; w < 4; ++w) {
                const point3 pu = v[u], pw = v[w];
                if (pu.x == pw.x && pu.y == pw.y && pu.z == pw.z) continue;
                auto m = [=](auto L) { return arith::cross(normal(L), arith::lift(L, pw) - arith::lift(L, pu)); };
                bool pos = false, neg = false;
                for (int r = 0; r < 4; ++r) {
                    if (r == u || r == w) continue;
                    const point3 pr = v[r];
                    const sign s = k.sgn([=](auto L) { return arith::dot(m(L), arith::lift(L, pr) - arith::lift(L, pu)); });
                    pos = pos || s == sign::positive;
                    neg = neg || s == sign::negative;
                }
                if (!pos && !tetra::box_on_side(k, b, m, pu, -1.0)) return false;
                if (!neg && !tetra::box_on_side(k, b, m, pu, 1.0)) return false;
            }
        return true;
    }
    // Collinear vertices: two distinct ones span the line; none, one point.
    int far = -1;
    for (int i = 1; i < 4 && far < 0; ++i)
        if (v[i].x != v[0].x || v[i].y != v[0].y || v[i].z != v[0].z) far = i;
    const point3 u = v[0];
    if (far < 0) { // a point: the box's centre on it and every used axis zero
        if (b.center.x != u.x || b.center.y != u.y || b.center.z != u.z) return false;
        for (unsigned j = 0; j < 3; ++j)
            if (b.half_extents[j] != 0.0 && (b.axes[j].x != 0.0 || b.axes[j].y != 0.0 || b.axes[j].z != 0.0)) return false;
        return true;
    }
    const point3 w = v[far];
    for (int c = 0; c < 3; ++c) // on the line: d x (c - u) = 0 and d x a_j = 0
        if (!tetra::box_on_zero(b, [&](point3 x, bool is_point) {
                return arith::is_zero(k, [=](auto L) {
                           const auto d = arith::lift(L, w) - arith::lift(L, u);
                           const auto e = is_point ? arith::lift(L, x) - arith::lift(L, u) : arith::lift(L, x) - arith::lift(L, point3{0, 0, 0});
                           const auto n = arith::cross(d, e);
                           return c == 0 ? n.x : (c == 1 ? n.y : n.z);
                       });
            }))
            return false;
    // Along the line, t(x) = d . x: some vertex at or below the box's least t, some at or above its
    // greatest (d padded to degree 2, as the box's reach h_j |d . a_j| is).
    auto d2 = [=](auto L) {
        const auto one = L(1.0);
        const auto d = arith::lift(L, w) - arith::lift(L, u);
        return arith::v3<decltype(one * d.x)>{one * d.x, one * d.y, one * d.z};
    };
    bool below = false, above = false;
    for (const point3& p : v) {
        below = below || tetra::box_on_side(k, b, d2, p, 1.0);
        above = above || tetra::box_on_side(k, b, d2, p, -1.0);
    }
    return below && above;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const obb3&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const obb3&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const tetrahedron3&, const obb3&);
} // namespace incidence::pair
