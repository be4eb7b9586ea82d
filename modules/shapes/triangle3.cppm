// triangle3{a, b, c}: the closed 2-simplex (interior, edges and vertices).
// Aggregate construction accepts collinear vertices and queries then use the convex hull (a
// segment or a point); make() refuses them, deciding collinearity exactly.
export module incidence.shapes:triangle3;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct triangle3 {
    point3 a, b, c;

    // true when a, b, c are exactly collinear (the cross product of the edges is exactly zero).
    [[nodiscard]] constexpr bool is_degenerate() const {
        arith::exact_kernel k;
        const auto A = a, B = b, C = c;
        for (int axis = 0; axis < 3; ++axis) {
            const sign s = k.sgn([=](auto L) {
                const auto n = arith::cross(arith::lift(L, B) - arith::lift(L, A), arith::lift(L, C) - arith::lift(L, A));
                return axis == 0 ? n.x : (axis == 1 ? n.y : n.z);
            });
            if (s != sign::zero) return false;
        }
        return true;
    }
    // Refuses non-finite coordinates and collinear (zero-area) triangles.
    [[nodiscard]] static constexpr result<triangle3> make(point3 a, point3 b, point3 c) {
        if (!is_finite(a) || !is_finite(b) || !is_finite(c)) return error{errc::not_finite};
        const triangle3 t{a, b, c};
        if (t.is_degenerate()) return error{errc::degenerate_triangle};
        return t;
    }
};

} // namespace incidence
