// convex_polyhedron3 against ray3.
// Semantics: the closed set of the half-spaces (possibly empty or unbounded; a non-finite number:
// no set) and the closed ray; grazing a face, an edge or a vertex counts; a zero direction is the
// point `origin`.
// Method (exact tiers): the generalised slab test (convex_polyhedron_point.cppm) over t >= 0:
// signs of degree <= 4.
// Source: Cyrus and Beck, Computers & Graphics 3(1), 1978; Haines, "Fast ray-convex polyhedron
// intersection", Graphics Gems II (1991), section V.1.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_ray.cpp).
export module incidence.query:convex_polyhedron_ray;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_ray;
import :convex_polyhedron_point;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const ray3& r) {
    return polyq::halfspaces<slab_extent::ray>(k, c, r.origin, r.direction, r.origin);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const ray3&);
} // namespace incidence::pair
