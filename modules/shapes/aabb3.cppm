// aabb3{min, max}: the closed solid axis-aligned box. Flat and point boxes (min == max on an
// axis) are accepted; inverted boxes are not.
export module incidence.shapes:aabb3;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct aabb3 {
    point3 min;
    point3 max;

    // Refuses non-finite coordinates and min > max on any axis.
    [[nodiscard]] static constexpr result<aabb3> make(point3 min, point3 max) {
        if (!is_finite(min) || !is_finite(max)) return error{errc::not_finite};
        if (min.x > max.x || min.y > max.y || min.z > max.z) return error{errc::inverted_box};
        return aabb3{min, max};
    }
};

} // namespace incidence
