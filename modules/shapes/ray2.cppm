// ray2{origin, direction}: the closed half-line { origin + t direction : t >= 0 } in the plane.
// The direction need not be normalised; t is measured in units of it.
export module incidence.shapes:ray2;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct ray2 {
    point2 origin;
    vec2 direction;

    // Refuses non-finite coordinates and the zero direction.
    [[nodiscard]] static constexpr result<ray2> make(point2 origin, vec2 direction) {
        if (!is_finite(origin) || !is_finite(direction)) return error{errc::not_finite};
        if (direction.x == 0.0 && direction.y == 0.0) return error{errc::zero_direction};
        return ray2{origin, direction};
    }
    [[nodiscard]] constexpr point2 at(double t) const { return origin + t * direction; }
};

} // namespace incidence
