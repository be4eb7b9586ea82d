// line2{origin, direction}: the full line { origin + t direction : t real } in the plane.
export module incidence.shapes:line2;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct line2 {
    point2 origin;
    vec2 direction;

    // Refuses non-finite coordinates and the zero direction.
    [[nodiscard]] static constexpr result<line2> make(point2 origin, vec2 direction) {
        if (!is_finite(origin) || !is_finite(direction)) return error{errc::not_finite};
        if (direction.x == 0.0 && direction.y == 0.0) return error{errc::zero_direction};
        return line2{origin, direction};
    }
};

} // namespace incidence
