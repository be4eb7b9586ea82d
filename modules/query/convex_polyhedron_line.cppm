// convex_polyhedron3 against line3.
// Semantics: the closed set of the half-spaces (possibly empty or unbounded; a non-finite number:
// no set) and the line; grazing a face, an edge or a vertex counts; a zero direction is the point
// `origin`.
// Method (exact tiers): the generalised slab test (convex_polyhedron_point.cppm) over every t:
// signs of degree <= 4.
// Source: Cyrus and Beck, Computers & Graphics 3(1), 1978 (clipping against a convex polyhedron).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_line.cpp).
export module incidence.query:convex_polyhedron_line;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_ray;
import :convex_polyhedron_point;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const line3& l) {
    return polyq::halfspaces<slab_extent::line>(k, c, l.origin, l.direction, l.origin);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const line3&);
} // namespace incidence::pair
