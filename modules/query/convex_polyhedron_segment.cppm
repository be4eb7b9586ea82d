// convex_polyhedron3 against segment3, and contains(convex_polyhedron3, segment3).
// Semantics: the closed set of the half-spaces (possibly empty or unbounded; a non-finite number:
// no set) and the closed segment (a point when a == b); touching a face, an edge or a vertex
// counts. contains: both end points in the set (it is convex).
// Method (exact tiers): the generalised slab test (convex_polyhedron_point.cppm) over t in [0, 1],
// the direction taken exactly as n_i . (b - a): signs of degree <= 4.
// Source: Cyrus and Beck, Computers & Graphics 3(1), 1978 (clipping against a convex polyhedron).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_segment.cpp).
export module incidence.query:convex_polyhedron_segment;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_ray;
import :convex_polyhedron_point;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const segment3& s) {
    return polyq::halfspaces<slab_extent::segment>(k, c, s.a, vec3{0, 0, 0}, s.b);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const segment3& s) {
    const bool a = intersects(k, c, s.a); // both read, so a NaN end point gives no in the exact tier
    const bool b = intersects(k, c, s.b);
    return a && b;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const segment3&);
extern template bool contains(arith::exact_kernel&, const convex_polyhedron3&, const segment3&);
} // namespace incidence::pair
