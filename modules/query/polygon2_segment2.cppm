// polygon2 against segment2.
// Semantics: the polygon's edges and the points of odd crossing parity (shapes/polygon2.cppm)
// against the closed segment; touching an edge or a vertex counts.
// Method (exact tiers): the polygon engine (point2_polygon2.cppm): an edge meets the segment
// (segment2_segment2's signs, degree <= 2), or else the segment lies off the boundary and its
// end point a decides by exact crossing parity.
// Source: Haines, "Point in polygon strategies", Graphics Gems IV (1994), the crossings test.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-44 of its
// permanent (tests/query/polygon2_segment2.cpp).
export module incidence.query:polygon2_segment2;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :segment2_segment2;
import :point2_polygon2;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon2& g, const segment2& s) {
    if (!polyq::well_formed(g) || !finite(s.a) || !finite(s.b)) return false;
    const point2 ends[2] = {s.a, s.b};
    const polyq::box2 xb = polyq::bounds(ends, 2);
    if (!polyq::boxes_meet(polyq::bounds(g), xb)) return false;
    return polyq::polygon_meets(k, g, [&](const segment2& e) { return intersects(k, e, s); }, s.a, &xb);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const polygon2&, const segment2&);
} // namespace incidence::pair
