// sphere3{center, radius}: the closed solid ball, so touching counts as intersecting.
// A zero radius is a point and is accepted.
export module incidence.shapes:sphere3;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct sphere3 {
    point3 center;
    double radius;

    // Refuses non-finite values and negative radii.
    [[nodiscard]] static constexpr result<sphere3> make(point3 center, double radius) {
        if (!is_finite(center) || !is_finite(radius)) return error{errc::not_finite};
        if (radius < 0.0) return error{errc::negative_radius};
        return sphere3{center, radius};
    }
};

} // namespace incidence
