// tetrahedron3{a, b, c, d}: the closed solid tetrahedron, the convex hull of its four vertices
// (interior, faces, edges and vertices), in either orientation. Aggregate construction accepts
// coplanar vertices and queries then use the hull (a polygon, a segment or a point); make()
// refuses them, deciding coplanarity exactly.
export module incidence.shapes:tetrahedron3;
import incidence.core;
import incidence.arith;
import :triangle3;

export namespace incidence {

struct tetrahedron3 {
    point3 a, b, c, d;

    // The four faces, each opposite the vertex of its index (d, c, b, a).
    [[nodiscard]] constexpr triangle3 face(int i) const {
        switch (i) {
        case 0: return {a, b, c};
        case 1: return {a, b, d};
        case 2: return {a, c, d};
        default: return {b, c, d};
        }
    }
    // true when a, b, c, d are exactly coplanar (det(b - a, c - a, d - a) is exactly zero).
    [[nodiscard]] constexpr bool is_degenerate() const {
        arith::exact_kernel k;
        const auto A = a, B = b, C = c, D = d;
        return k.sgn([=](auto L) {
            const auto o = arith::lift(L, A);
            return arith::det3(arith::lift(L, B) - o, arith::lift(L, C) - o, arith::lift(L, D) - o);
        }) == sign::zero;
    }
    // Refuses non-finite coordinates and coplanar (zero-volume) vertices.
    [[nodiscard]] static constexpr result<tetrahedron3> make(point3 a, point3 b, point3 c, point3 d) {
        if (!is_finite(a) || !is_finite(b) || !is_finite(c) || !is_finite(d)) return error{errc::not_finite};
        const tetrahedron3 t{a, b, c, d};
        if (t.is_degenerate()) return error{errc::degenerate_tetrahedron};
        return t;
    }
};

} // namespace incidence
