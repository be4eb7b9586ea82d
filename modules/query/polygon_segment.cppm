// polygon3 against segment3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed segment (equal ends: a
// point). Touching an edge or a vertex counts.
// Method (exact tiers): the segment meets an edge (segment_segment.cppm), or crosses the plane at
// one point V / D inside the polygon (the homogeneous crossing test of point_polygon.cppm), or lies
// in the plane with its first end inside: signs of degree <= 6.
// contains: both ends in the plane (n . (x - a) = 0), then the segment's projection against the
// projected polygon (one to one on the plane, and exact: a coordinate dropped) by the 2D engine
// of polygon2_segment2.cppm (split where it meets an edge, one point of each piece decides).
// Source: point_polygon.cppm (Haines, Graphics Gems IV, 1994).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/polygon_segment.cpp).
export module incidence.query:polygon_segment;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :point_polygon;
import :point2_polygon2;
import :polygon2_segment2;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& g, const segment3& s) {
    if (!finite(s.a) || !finite(s.b) || !planeq::usable(k, g)) return false;
    return planeq::linear_meets(k, g, as_linear(s));
}

// contains(polygon, segment): both ends in the polygon's plane, and the projected segment in the
// projected polygon.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const polygon3& g, const segment3& s) {
    if (!finite(s.a) || !finite(s.b) || !planeq::usable(k, g)) return false;
    if (planeq::side(k, g, s.a) != sign::zero || planeq::side(k, g, s.b) != sign::zero) return false;
    const point2 a = g.projected(s.a), b = g.projected(s.b);
    if (a.x == b.x && a.y == b.y) return contains(k, g, s.a);
    return polyq::segment_inside(k, planeq::projected_edges(g), a, b);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const polygon3&, const segment3&);
extern template bool contains(arith::exact_kernel&, const polygon3&, const segment3&);
} // namespace incidence::pair
