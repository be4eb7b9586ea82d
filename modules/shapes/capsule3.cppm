// capsule3{a, b, radius}: the closed set of points within `radius` of the segment ab (a segment
// swept by a ball); a = b is a ball, a zero radius the segment itself.
export module incidence.shapes:capsule3;
import incidence.core;

export namespace incidence {

struct capsule3 {
    point3 a, b;
    double radius;

    // Refuses non-finite values and negative (or NaN) radii.
    [[nodiscard]] static constexpr result<capsule3> make(point3 a, point3 b, double radius) {
        if (!is_finite(a) || !is_finite(b) || !is_finite(radius)) return error{errc::not_finite};
        if (radius < 0.0) return error{errc::negative_radius};
        return capsule3{a, b, radius};
    }
};

} // namespace incidence
