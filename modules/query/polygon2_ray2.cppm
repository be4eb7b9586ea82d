// polygon2 against ray2.
// Semantics: the polygon's edges and the points of odd crossing parity (shapes/polygon2.cppm)
// against the closed ray; touching an edge or a vertex counts; a zero direction is the point
// `origin`.
// Method (exact tiers): the polygon engine (point2_polygon2.cppm): an edge meets the ray
// (ray2_segment2's signs, degree <= 2), or else the ray lies off the boundary and its origin
// decides by exact crossing parity. No bounding-box skip: the ray is unbounded.
// Source: Haines, "Point in polygon strategies", Graphics Gems IV (1994), the crossings test.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-44 of its
// permanent (tests/query/polygon2_ray2.cpp).
export module incidence.query:polygon2_ray2;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :ray2_segment2;
import :point2_polygon2;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon2& g, const ray2& r) {
    if (!polyq::well_formed(g) || !finite(r.origin) || !finite(r.direction)) return false;
    return polyq::polygon_meets(k, g, [&](const segment2& e) { return intersects(k, r, e); }, r.origin);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const polygon2&, const ray2&);
} // namespace incidence::pair
