// polygon3 against ray3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed ray o + t d, t >= 0 (a zero
// direction: its origin). Touching an edge or a vertex counts.
// Method (exact tiers): the ray meets an edge (segment_segment.cppm), or crosses the plane at
// one point V / D inside the polygon (the homogeneous crossing test of point_polygon.cppm), or lies
// in the plane with its origin inside: signs of degree <= 6.
// Source: point_polygon.cppm (Haines, Graphics Gems IV, 1994).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/polygon_ray.cpp).
export module incidence.query:polygon_ray;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :point_polygon;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& g, const ray3& s) {
    if (!finite(s.origin) || !finite(s.direction) || !planeq::usable(k, g)) return false;
    return planeq::linear_meets(k, g, as_linear(s));
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const polygon3&, const ray3&);
} // namespace incidence::pair
