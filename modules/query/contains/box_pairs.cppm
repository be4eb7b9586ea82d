// contains: box_pairs
module;
#include <optional>
export module incidence.detail:contains.box_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.tetrahedron;
import :engines.box;
import :intersects.triangle_pairs;
import :intersects.box_pairs;
import :intersects.linear_pairs;
import :intersects.tetrahedron_pairs;
import :contains.tetrahedron_pairs;
import :exactly;

export namespace incidence::detail {

// aabb3 against aabb3: intersects, contains, and covers(a, b, c): does a u b contain c?
// Semantics: closed boxes; touching faces, edges or corners intersect; a box contains itself.

template <class K>
[[nodiscard]] constexpr bool contains(K&, const aabb3& a, const aabb3& b) {
    return a.min.x <= b.min.x && b.max.x <= a.max.x && a.min.y <= b.min.y && b.max.y <= a.max.y && a.min.z <= b.min.z && b.max.z <= a.max.z;
}

// aabb3 against point3, and the point's minimum and maximum squared distance to the box.
// Semantics: closed box, so a point on a face, edge or corner intersects.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& b, const point3& p) {
    return intersects(k, b, p);
}

// aabb3 against triangle3 (closed box, closed triangle; a collinear triangle is its hull).
// Semantics: touching at a vertex, along an edge or on a face counts.

// Is the triangle inside the box? Its three vertices are (coordinate comparisons, exact in every tier).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& b, const triangle3& t) {
    return contains(k, b, t.a) && contains(k, b, t.b) && contains(k, b, t.c);
}

// aabb3 against tetrahedron3 (closed box; closed solid tetrahedron, coplanar vertices give their
// hull), contains(box, tetrahedron) and contains(tetrahedron, box).
// Semantics: touching at a vertex, along an edge or on a face counts.

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& b, const tetrahedron3& t) {
    if (!well_formed_finite(b) || !finite(t)) return false;
    return contains(k, b, t.a) && contains(k, b, t.b) && contains(k, b, t.c) && contains(k, b, t.d);
}

// contains(tetrahedron, box): the eight corners in the closed tetrahedron.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const aabb3& b) {
    if (!well_formed_finite(b)) return false;
    const box_corners c(b);
    return tetra::contains_all(k, t, c.p, 8);
}

// aabb3 against segment3 (closed box, closed segment; a segment with equal end points is a point).
// Semantics: touching a face, an edge or a corner counts.
// Is the segment inside the box? Both end points are (coordinate comparisons, exact in every tier).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& b, const segment3& s) {
    return contains(k, b, s.a) && contains(k, b, s.b);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const aabb3&, const aabb3&);
extern template bool exactly<contains_body>(const aabb3&, const point3&);
extern template bool exactly<contains_body>(const aabb3&, const triangle3&);
extern template bool exactly<contains_body>(const aabb3&, const tetrahedron3&);
extern template bool exactly<contains_body>(const tetrahedron3&, const aabb3&);
extern template bool exactly<contains_body>(const aabb3&, const segment3&);
} // namespace incidence::detail
