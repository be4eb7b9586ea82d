// segment3{a, b}: the closed segment { a + t (b - a) : 0 <= t <= 1 }. a == b (a point) is
// accepted by aggregate construction; make() refuses it.
export module incidence.shapes:segment3;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct segment3 {
    point3 a;
    point3 b;

    // Refuses non-finite coordinates and coincident end points.
    [[nodiscard]] static constexpr result<segment3> make(point3 a, point3 b) {
        if (!is_finite(a) || !is_finite(b)) return error{errc::not_finite};
        if (a == b) return error{errc::degenerate_segment};
        return segment3{a, b};
    }
};

} // namespace incidence
