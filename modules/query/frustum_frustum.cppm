// frustum3 against frustum3.
// Semantics: two closed view volumes of six half-spaces each (shapes/frustum3.cppm; a non-finite
// number: no set). Touching at a vertex, an edge or a face counts.
// Method (exact tiers): the test of two half-space sets (convex_polyhedron_convex_polyhedron.cppm):
// a face of either with the other wholly beyond it (a Farkas certificate) says no, a point proven
// strictly inside both says yes, else the exact feasibility test of all twelve half-spaces
// together: signs of degree <= 5. The two frustums go in a fixed order, so every tier answers the
// same for both argument orders.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, sections 7.3 and 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/frustum_frustum.cpp).
export module incidence.query:frustum_frustum;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :convex_polyhedron_convex_polyhedron;

export namespace incidence::pair {

namespace polyq {
// A fixed order of two frustums: their six planes in turn.
[[nodiscard]] constexpr bool before(const frustum3& a, const frustum3& b) { return planes_before(a.planes.data(), b.planes.data(), 6); }
} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& a, const frustum3& b) {
    const bool swap = polyq::before(b, a);
    const frustum3& p = swap ? b : a;
    const frustum3& q = swap ? a : b;
    return polyq::sets_meet(k, p.planes.data(), 6, q.planes.data(), 6);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const frustum3&, const frustum3&);
} // namespace incidence::pair
