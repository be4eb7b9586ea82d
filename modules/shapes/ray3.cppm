// ray3{origin, direction}: the closed half-line { origin + t direction : t >= 0 }.
// The direction need not be normalised; t is measured in units of it.
export module incidence.shapes:ray3;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct ray3 {
    point3 origin;
    vec3 direction;

    // Refuses non-finite coordinates and the zero direction.
    [[nodiscard]] static constexpr result<ray3> make(point3 origin, vec3 direction) {
        if (!is_finite(origin) || !is_finite(direction)) return error{errc::not_finite};
        if (direction.x == 0.0 && direction.y == 0.0 && direction.z == 0.0) return error{errc::zero_direction};
        return ray3{origin, direction};
    }
    [[nodiscard]] constexpr point3 at(double t) const { return origin + t * direction; }
};

} // namespace incidence
