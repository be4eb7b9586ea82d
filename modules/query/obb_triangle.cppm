// obb3 against triangle3 (closed box read as the parallelepiped its axes span; closed triangle, a
// collinear triangle is its hull).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Method (exact tiers): the 13 separating axes (three face normals, the triangle's normal, the nine
// box axes crossed with the triangle's edges); along each axis the triangle's vertices are compared
// with the box's interval as signs of degree 4 (separating_axes covers flat boxes and triangles).
// Source: Akenine-Moeller, "Fast 3D triangle-box overlap testing", JGT 6(1), 2001 (13 axes);
// Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when some axis sign is within 2^-40 of its
// permanent (the sets touch or nearly touch); tests/query/obb_triangle.cpp checks it.
export module incidence.query:obb_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :separating_axes;
import :obb_point;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& a, const triangle3& b) {
    return sat::well_formed(a) && sat::zonotope_triangle_intersect(k, sat::of(a), b);
}
// Is the triangle inside the box? Its three vertices are (the box is convex).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& a, const triangle3& b) {
    return contains(k, a, b.a) && contains(k, a, b.b) && contains(k, a, b.c);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const obb3&, const triangle3&);
extern template bool contains(arith::exact_kernel&, const obb3&, const triangle3&);
} // namespace incidence::pair
