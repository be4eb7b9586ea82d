// line3{origin, direction}: the full line { origin + t direction : t real }.
export module incidence.shapes:line3;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct line3 {
    point3 origin;
    vec3 direction;

    // Refuses non-finite coordinates and the zero direction.
    [[nodiscard]] static constexpr result<line3> make(point3 origin, vec3 direction) {
        if (!is_finite(origin) || !is_finite(direction)) return error{errc::not_finite};
        if (direction.x == 0.0 && direction.y == 0.0 && direction.z == 0.0) return error{errc::zero_direction};
        return line3{origin, direction};
    }
};

} // namespace incidence
