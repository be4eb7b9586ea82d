// segment2{a, b}: the closed segment { a + t (b - a) : 0 <= t <= 1 } in the plane. a == b (a
// point) is accepted by aggregate construction; make() refuses it.
export module incidence.shapes:segment2;
import incidence.core;
import incidence.arith;

export namespace incidence {

struct segment2 {
    point2 a;
    point2 b;

    // Refuses non-finite coordinates and coincident end points.
    [[nodiscard]] static constexpr result<segment2> make(point2 a, point2 b) {
        if (!is_finite(a) || !is_finite(b)) return error{errc::not_finite};
        if (a == b) return error{errc::degenerate_segment};
        return segment2{a, b};
    }
};

} // namespace incidence
