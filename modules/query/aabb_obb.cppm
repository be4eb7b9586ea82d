// aabb3 against obb3 (closed boxes; a box of zero extent is a rectangle, a segment or a point, and
// an obb3's axes are read exactly as given: it is the parallelepiped they span).
// Semantics: touching at a corner, along an edge or on a face counts.
// Method (exact tiers): the 15 separating axes of two boxes (three face normals of each, the nine
// cross products of an axis of one with an axis of the other), the aabb3 as the zonotope with
// centre (min + max) / 2 and the unit axes, so no rounded centre is ever compared. Each axis is one
// sign of degree 4: |w . (2 c_b - 2 c_a)| against the sum of twice the projected radii
// (see separating_axes for the flat cases). Before them the three coordinate axes, and each sign
// first against a bound from the inputs' largest magnitudes, as in obb_obb.
// contains(aabb3, obb3) and contains(obb3, aabb3): the support functions compared on the same axes
// (sat::zonotope_contains), signs of degree 4.
// Source: Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5.
// Approximate tier: the same signs (coordinate axes included) in plain double. Error bound: for
// inputs whose nonzero magnitudes lie in [2^-500, 2^500], wrong only when some axis sign is within
// 2^-40 of its permanent (the sets touch or nearly touch); tests/query/aabb_obb.cpp checks it.
export module incidence.query:aabb_obb;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :separating_axes;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& a, const obb3& b) {
    return sat::well_formed(a) && sat::well_formed(b) && sat::zonotopes_intersect(k, sat::of(a), sat::of(b));
}
// Malformed boxes (inverted, NaN or negative extents) contain nothing and lie in nothing.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& a, const obb3& b) {
    return sat::well_formed(a) && sat::well_formed(b) && sat::zonotope_contains(k, sat::of(a), sat::of(b));
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& a, const aabb3& b) {
    return sat::well_formed(a) && sat::well_formed(b) && sat::zonotope_contains(k, sat::of(a), sat::of(b));
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const obb3&);
extern template bool contains(arith::exact_kernel&, const aabb3&, const obb3&);
extern template bool contains(arith::exact_kernel&, const obb3&, const aabb3&);
} // namespace incidence::pair
