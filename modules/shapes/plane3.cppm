// plane3{normal, offset}: the points p with dot(normal, p) == offset (exactly, in the reals).
export module incidence.shapes:plane3;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct plane3 {
    vec3 normal;
    double offset;

    // Refuses non-finite values and the zero normal.
    [[nodiscard]] static constexpr result<plane3> make(vec3 normal, double offset) {
        if (!is_finite(normal) || !is_finite(offset)) return error{errc::not_finite};
        if (normal.x == 0.0 && normal.y == 0.0 && normal.z == 0.0) return error{errc::zero_normal};
        return plane3{normal, offset};
    }
};

} // namespace incidence
