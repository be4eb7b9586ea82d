// line2 against polygon2.
// Semantics: the line against the polygon's edges and the points of odd crossing parity
// (shapes/polygon2.cppm); touching an edge or a vertex counts; a zero direction is the point
// `origin`.
// Method (exact tiers): the polygon engine (point2_polygon2.cppm): an edge meets the line
// (line2_segment2's signs, degree <= 2), or else the line lies off the boundary and its origin
// decides by exact crossing parity (a nonzero line meets every ring's edges when it meets the
// inside, so this is reached only for a zero direction). No bounding-box skip.
// Source: Haines, "Point in polygon strategies", Graphics Gems IV (1994), the crossings test.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-44 of its
// permanent (tests/query/line2_polygon2.cpp).
export module incidence.query:line2_polygon2;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :line2_segment2;
import :point2_polygon2;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line2& l, const polygon2& g) {
    if (!polyq::well_formed(g) || !finite(l.origin) || !finite(l.direction)) return false;
    return polyq::polygon_meets(k, g, [&](const segment2& e) { return intersects(k, l, e); }, l.origin);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const line2&, const polygon2&);
} // namespace incidence::pair
