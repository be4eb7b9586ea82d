// polygon3 against polygon3.
// Semantics: the two polygons' point sets (shapes/polygon3.cppm). Touching counts.
// Method (exact tiers): an edge of either meets the other (polygon_segment.cppm). Complete: where
// they meet and no edge of the second touches the first, the first's section by the second's
// plane (segments, or the first itself when coplanar) that holds a common point lies inside the
// second, and its ends are on the first's edges.
// Source: the boundary-plus-inside decomposition of point_polygon.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/polygon_polygon.cpp).
export module incidence.query:polygon_polygon;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :point_polygon;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& a, const polygon3& b) {
    if (!planeq::usable(k, a) || !planeq::usable(k, b)) return false;
    return planeq::any_edge(a, [&](const segment3& e) { return planeq::linear_meets(k, b, as_linear(e)); }) ||
           planeq::any_edge(b, [&](const segment3& e) { return planeq::linear_meets(k, a, as_linear(e)); });
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const polygon3&, const polygon3&);
} // namespace incidence::pair
