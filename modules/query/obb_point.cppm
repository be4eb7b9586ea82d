// obb3 against point3 (closed box, read as the parallelepiped its axes span).
// Semantics: a point on the boundary counts.
// Method (exact tiers): the point is inside iff no face normal a_j x a_k separates it:
// |n_i . (2 p - 2 c)| <= 2 h_i |n_i . a_i|, three signs of degree 4 (separating_axes).
// Source: Ericson, Real-Time Collision Detection (2005), section 5.1.4 (point in OBB, here with
// the parallelepiped's face normals instead of a change of frame, so nothing is rounded).
// contains(obb3, point3) is the same test; a convex shape with vertices (segment, triangle,
// tetrahedron) lies in the box iff its vertices do (obb_segment, obb_triangle, obb_tetrahedron).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when some axis sign is within 2^-40 of its
// permanent (the sets touch or nearly touch); tests/query/obb_point.cpp checks it.
export module incidence.query:obb_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :separating_axes;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& a, const point3& b) {
    return sat::well_formed(a) && sat::zonotopes_intersect(k, sat::of(a), sat::of(b));
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& a, const point3& b) {
    return intersects(k, a, b);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const obb3&, const point3&);
extern template bool contains(arith::exact_kernel&, const obb3&, const point3&);
} // namespace incidence::pair
