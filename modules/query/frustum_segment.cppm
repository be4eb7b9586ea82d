// frustum3 against segment3, and contains(frustum3, segment3).
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the closed segment (a point when a == b); touching a face, an edge or a
// corner counts. contains: both end points in the frustum (it is convex).
// Method (exact tiers): the generalised slab test (convex_polyhedron_point.cppm) on the six
// planes over t in [0, 1]: signs of degree <= 4.
// Source: Cyrus and Beck, Computers & Graphics 3(1), 1978 (clipping against a convex polyhedron).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/frustum_segment.cpp).
export module incidence.query:frustum_segment;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_ray;
import :convex_polyhedron_point;
import :frustum_point;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const segment3& s) {
    return polyq::halfspaces<slab_extent::segment>(k, f.planes.data(), 6, s.a, vec3{0, 0, 0}, s.b);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const segment3& s) {
    const bool a = intersects(k, f, s.a); // both read, so a NaN end point gives no in the exact tier
    const bool b = intersects(k, f, s.b);
    return a && b;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const frustum3&, const segment3&);
extern template bool contains(arith::exact_kernel&, const frustum3&, const segment3&);
} // namespace incidence::pair
