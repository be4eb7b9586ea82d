// convex_polyhedron3 against kdop<K>.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed k-DOP
// (an empty slab or a non-finite bound: no set, so no). Touching at a vertex, an edge or a face counts.
// Method (exact tiers): the k-DOP is its K half-spaces (kdop_plane.cppm: integer directions, so
// exact), and the pair is the test of two half-space sets (convex_polyhedron_convex_polyhedron.cppm):
// a face of either with the other wholly beyond it (a Farkas certificate) says no, a point proven
// strictly inside both says yes, else the exact feasibility test of all the half-spaces together:
// signs of degree <= 5.
// Source: Klosowski et al., IEEE TVCG 4(1), 1998, section 4 (the directions); Schrijver, Theory
// of Linear and Integer Programming, 1986, sections 7.3 and 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_kdop.cpp).
export module incidence.query:convex_polyhedron_kdop;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :kdop_point;
import :kdop_plane;
import :convex_polyhedron_convex_polyhedron;

export namespace incidence::pair {

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const kdop<N>& b) {
    if (!kdopq::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdopq::halfspaces(b);
    return polyq::sets_meet(k, c.planes.data(), c.count, rows.data(), N);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const kdop<6>&);
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const kdop<14>&);
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const kdop<18>&);
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const kdop<26>&);
} // namespace incidence::pair
