// contains: obb_pairs
export module incidence.detail:contains.obb_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.separating_axes;
import :engines.tetrahedron;
import :intersects.linear_pairs;
import :intersects.tetrahedron_pairs;
import :contains.tetrahedron_pairs;
import :intersects.obb_pairs;
import :exactly;

export namespace incidence::detail {

// aabb3 against obb3 (closed boxes; a box of zero extent is a rectangle, a segment or a point, and
// an obb3's axes are read exactly as given: it is the parallelepiped they span).
// Semantics: touching at a corner, along an edge or on a face counts.
// Malformed boxes (inverted, NaN or negative extents) contain nothing and lie in nothing.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& a, const obb3& b) {
    return sat::well_formed(a) && sat::well_formed(b) && sat::zonotope_contains(k, sat::zonotope_of(a), sat::zonotope_of(b));
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& a, const aabb3& b) {
    return sat::well_formed(a) && sat::well_formed(b) && sat::zonotope_contains(k, sat::zonotope_of(a), sat::zonotope_of(b));
}

// obb3 against point3 (closed box, read as the parallelepiped its axes span).
// Semantics: a point on the boundary counts.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& a, const point3& b) {
    return intersects(k, a, b);
}

// obb3 against triangle3 (closed box read as the parallelepiped its axes span; closed triangle, a
// collinear triangle is its hull).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Is the triangle inside the box? Its three vertices are (the box is convex).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& a, const triangle3& b) {
    return contains(k, a, b.a) && contains(k, a, b.b) && contains(k, a, b.c);
}

// obb3 against tetrahedron3 (closed box, read as the parallelepiped its axes span; closed solid
// tetrahedron, coplanar vertices give their hull).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Is the tetrahedron inside the box? Its four vertices are (the box is convex).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& b, const tetrahedron3& t) {
    return contains(k, b, t.a) && contains(k, b, t.b) && contains(k, b, t.c) && contains(k, b, t.d);
}

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
                if (is_point)
                    return arith::is_zero(k, [=](auto L) { return arith::dot(normal(L), arith::lift(L, x) - arith::lift(L, q0)); });
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

// obb3 against obb3 (closed boxes; the axes are read exactly as given, so a box is the
// parallelepiped they span, and a box of zero extent is a rectangle, a segment or a point).
// Semantics: touching at a corner, along an edge or on a face counts.
// Is b inside a? Malformed boxes (NaN or negative extents) contain nothing and lie in nothing.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& a, const obb3& b) {
    return sat::well_formed(a) && sat::well_formed(b) && sat::zonotope_contains(k, sat::zonotope_of(a), sat::zonotope_of(b));
}

// obb3 against segment3 (closed box read as the parallelepiped its axes span; closed segment, a
// segment with equal end points is a point).
// Semantics: touching a face, an edge or a corner counts.
// Is the segment inside the box? Its two end points are (the box is convex).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& a, const segment3& b) {
    return contains(k, a, b.a) && contains(k, a, b.b);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const aabb3&, const obb3&);
extern template bool exactly<contains_body>(const obb3&, const aabb3&);
extern template bool exactly<contains_body>(const obb3&, const point3&);
extern template bool exactly<contains_body>(const obb3&, const triangle3&);
extern template bool exactly<contains_body>(const obb3&, const tetrahedron3&);
extern template bool exactly<contains_body>(const tetrahedron3&, const obb3&);
extern template bool exactly<contains_body>(const obb3&, const obb3&);
extern template bool exactly<contains_body>(const obb3&, const segment3&);
} // namespace incidence::detail
