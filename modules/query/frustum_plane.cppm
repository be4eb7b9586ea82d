// frustum3 against plane3.
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the plane n . x = offset (a zero normal is everything when the offset is 0
// and nothing otherwise). Touching at a corner, an edge or a face counts.
// Method (exact tiers): the frustum's points on both closed sides of the plane, two half-space
// feasibility tests of seven planes each (convex_polyhedron_plane.cppm): homogeneous signs of
// degree <= 5.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5 (minimal faces).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/frustum_plane.cpp).
export module incidence.query:frustum_plane;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :convex_polyhedron_plane;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const plane3& p) {
    return polyq::plane_meets(k, f.planes.data(), 6, p);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const frustum3&, const plane3&);
} // namespace incidence::pair
