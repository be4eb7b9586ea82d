// circle2{center, radius}: the closed disk in the plane, so touching counts as intersecting.
// A zero radius is a point and is accepted.
export module incidence.shapes:circle2;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct circle2 {
    point2 center;
    double radius;

    // Refuses non-finite values and negative radii.
    [[nodiscard]] static constexpr result<circle2> make(point2 center, double radius) {
        if (!is_finite(center) || !is_finite(radius)) return error{errc::not_finite};
        if (radius < 0.0) return error{errc::negative_radius};
        return circle2{center, radius};
    }
};

} // namespace incidence
