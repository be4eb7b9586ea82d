// frustum3 against ray3.
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the closed ray; grazing a face, an edge or a corner counts; a zero
// direction is the point `origin`.
// Method (exact tiers): the generalised slab test (convex_polyhedron_point.cppm) on the six
// planes over t >= 0: signs of degree <= 4.
// Source: Cyrus and Beck, Computers & Graphics 3(1), 1978 (clipping against a convex polyhedron).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/frustum_ray.cpp).
export module incidence.query:frustum_ray;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_ray;
import :convex_polyhedron_point;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const ray3& r) {
    return polyq::halfspaces<slab_extent::ray>(k, f.planes.data(), 6, r.origin, r.direction, r.origin);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const frustum3&, const ray3&);
} // namespace incidence::pair
