// frustum3 against polygon3.
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the polygon's point set (shapes/polygon3.cppm). Touching counts.
// Method (exact tiers): the test of a polygon against a half-space set
// (convex_polyhedron_polygon.cppm): its edges through the generalised slab test, else one vertex
// of the frustum's section by the polygon's plane, by the homogeneous crossing test.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5; the
// boundary-plus-inside decomposition of point_polygon.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/frustum_polygon.cpp).
export module incidence.query:frustum_polygon;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :convex_polyhedron_polygon;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const polygon3& g) {
    return polyq::polygon_meets(k, g, f.planes.data(), 6);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const frustum3&, const polygon3&);
} // namespace incidence::pair
