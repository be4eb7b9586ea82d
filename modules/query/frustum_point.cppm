// frustum3 against point3, and contains(frustum3, point3).
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the point; a point on a face, an edge or a corner counts. contains: the
// same set.
// Method (exact tiers): the half-space signs of the generalised slab test
// (convex_polyhedron_point.cppm) on the frustum's six planes: signs of degree <= 2.
// Source: Cyrus and Beck, Computers & Graphics 3(1), 1978 (clipping against a convex polyhedron).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/frustum_point.cpp).
export module incidence.query:frustum_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_ray;
import :convex_polyhedron_point;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const point3& p) {
    return polyq::halfspaces<slab_extent::segment>(k, f.planes.data(), 6, p, vec3{0, 0, 0}, p);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const point3& p) { return intersects(k, f, p); }

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const frustum3&, const point3&);
extern template bool contains(arith::exact_kernel&, const frustum3&, const point3&);
} // namespace incidence::pair
