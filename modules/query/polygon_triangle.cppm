// polygon3 against triangle3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed solid triangle
// (collinear corners: the segments between them). Touching counts.
// Method (exact tiers): an edge of the polygon meets the triangle (segment_triangle.cppm), or an
// edge of the triangle crosses the polygon inside (planeq::crossing_inside: a triangle edge
// through a polygon edge was found by the first test). Complete: where the two meet and
// no polygon edge touches the triangle, the triangle's section by the polygon's plane (a segment,
// or the triangle itself when coplanar) lies inside the polygon, and its ends are on the
// triangle's edges.
// Source: the boundary-plus-inside decomposition of point_polygon.cppm; Moeller, "A fast
// triangle-triangle intersection test", JGT 2(2), 1997 (edges against faces).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/polygon_triangle.cpp).
export module incidence.query:polygon_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :segment_triangle;
import :point_polygon;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& g, const triangle3& t) {
    if (!finite(t.a) || !finite(t.b) || !finite(t.c) || !planeq::usable(k, g)) return false;
    if (planeq::any_edge(g, [&](const segment3& e) { return intersects(k, e, t); })) return true;
    return planeq::crossing_inside(k, g, as_linear(segment3{t.a, t.b})) || planeq::crossing_inside(k, g, as_linear(segment3{t.b, t.c})) ||
           planeq::crossing_inside(k, g, as_linear(segment3{t.c, t.a}));
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const polygon3&, const triangle3&);
} // namespace incidence::pair
