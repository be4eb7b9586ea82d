// obb3 against tetrahedron3 (closed box, read as the parallelepiped its axes span; closed solid
// tetrahedron, coplanar vertices give their hull).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Method (exact tiers): the box centre inside the solid (four orient3d signs) says yes; otherwise
// the box meets the tetrahedron iff it meets one of its four faces (the 13-axis obb_triangle
// test), since it cannot then lie inside.
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Gottschalk, Lin and
// Manocha, "OBBTree", SIGGRAPH 1996, section 5, for the face tests.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/obb_tetrahedron.cpp).
export module incidence.query:obb_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :separating_axes;
import :obb_triangle;
import :obb_point;
import :point_tetrahedron;

export namespace incidence::pair {

[[nodiscard]] constexpr bool finite(const obb3& b) {
    return finite(b.center) && finite(b.axes[0]) && finite(b.axes[1]) && finite(b.axes[2]) && finite(b.half_extents[0]) &&
           finite(b.half_extents[1]) && finite(b.half_extents[2]);
}

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& b, const tetrahedron3& t) {
    if (!sat::well_formed(b) || !finite(b) || !finite(t)) return false;
    const point3 pts[1] = {b.center};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, b, face); }, pts, 1, false);
}
// Is the tetrahedron inside the box? Its four vertices are (the box is convex).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& b, const tetrahedron3& t) {
    return contains(k, b, t.a) && contains(k, b, t.b) && contains(k, b, t.c) && contains(k, b, t.d);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const obb3&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const obb3&, const tetrahedron3&);
} // namespace incidence::pair
