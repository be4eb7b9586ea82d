// plane3 against tetrahedron3 (the plane n . p = offset; closed solid tetrahedron, coplanar
// vertices give their hull). A zero normal is every point (offset 0) or none.
// Semantics: a vertex on the plane counts.
// Method (exact tiers): the signs of n . v - offset at the four vertices (degree 2); the
// tetrahedron meets the plane iff they are not all strictly positive or all strictly negative.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.2.3 (the plane against a
// polytope by the signed distances of its vertices), as signs.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a sign is within 2^-48 of its permanent
// (tests/query/plane_tetrahedron.cpp).
export module incidence.query:plane_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_plane;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const tetrahedron3& t) {
    // Every vertex is read before answering, so a NaN or infinite one gives no in the exact tier.
    const sign s[4] = {plane_side(k, pl, t.a), plane_side(k, pl, t.b), plane_side(k, pl, t.c), plane_side(k, pl, t.d)};
    return !((s[0] == sign::positive || s[0] == sign::negative) && s[1] == s[0] && s[2] == s[0] && s[3] == s[0]);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const plane3&, const tetrahedron3&);
} // namespace incidence::pair
