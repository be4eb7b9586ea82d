// convex_polyhedron3 against frustum3.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed view
// volume of six half-spaces (shapes/frustum3.cppm). Touching at a vertex, an edge or a face counts.
// Method (exact tiers): the test of two half-space sets (convex_polyhedron_convex_polyhedron.cppm):
// a face of either with the other wholly beyond it (a Farkas certificate) says no, a point proven
// strictly inside both says yes, else the exact feasibility test of all the half-spaces together:
// signs of degree <= 5.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, sections 7.3 and 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_frustum.cpp).
export module incidence.query:convex_polyhedron_frustum;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :convex_polyhedron_convex_polyhedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& a, const frustum3& f) {
    return polyq::sets_meet(k, a.planes.data(), a.count, f.planes.data(), 6);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const frustum3&);
} // namespace incidence::pair
