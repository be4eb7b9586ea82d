// contains: halfspace_pairs
module;
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
export module incidence.detail:contains.halfspace_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.box;
import :intersects.box_pairs;
import :intersects.linear_pairs;
import :intersects.tetrahedron_pairs;
import :engines.halfspace_slabs;
import :engines.halfspace_lp;
import :engines.halfspace_meets;
import :intersects.obb_pairs;
import :intersects.halfspace_pairs;
import :exactly;

export namespace incidence::detail {

// convex_polyhedron3 against point3, contains(convex_polyhedron3, point3), and the generalised
// slab test every half-space pair shares (convex_polyhedron_segment, _ray, _line, and the frustum
// pairs, whose six planes are one such set).
// Semantics: the closed set { p : n_i . p <= c_i } (shapes/convex_polyhedron3.cppm), possibly
// empty or unbounded; a non-finite number or a count outside [0, capacity] makes no set: every
// query says no. A point on a face, an edge or a vertex counts.
// contains(convex_polyhedron3, point): the same set.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const point3& p) {
    return intersects(k, c, p);
}

// aabb3 against convex_polyhedron3, contains(convex_polyhedron3, aabb3), and the half-space
// feasibility test the other half-space pairs share: with a box (aabb_frustum), and of possibly
// unbounded sets (polyq::feasible: convex_polyhedron_plane, frustum_plane).
// Semantics: the closed box (bounds ordered and finite; an inverted box is empty) and the closed
// half-space set of convex_polyhedron_point.cppm (possibly empty or unbounded; a non-finite number
// or a count outside [0, capacity]: no set). Touching at a face, an edge or a vertex counts.
// contains(polyhedron, box): the eight corners in the set (it is convex).
// contains(convex_polyhedron3, aabb3): the eight corners in the set (every corner read, so a NaN
// bound gives no in the exact tier).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const aabb3& b) {
    if (!well_formed_finite(b)) return false;
    const box_corners q(b);
    bool all = true;
    for (const point3& p : q.p) all = intersects(k, c, p) && all;
    return all;
}

// frustum3 against point3, and contains(frustum3, point3).
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the point; a point on a face, an edge or a corner counts. contains: the
// same set.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const point3& p) {
    return intersects(k, f, p);
}

// aabb3 against frustum3, and contains(frustum3, aabb3).
// Semantics: the closed box (bounds ordered and finite; an inverted box is empty) and the closed
// view volume of the frustum's six half-spaces (shapes/frustum3.cppm; a non-finite number: no
// set). Touching at a face, an edge or a corner counts. contains: the eight corners in the frustum.

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const aabb3& b) {
    if (!well_formed_finite(b)) return false;
    const box_corners q(b);
    bool all = true;
    for (const point3& p : q.p) all = intersects(k, f, p) && all;
    return all;
}

// convex_polyhedron3 against triangle3, contains(convex_polyhedron3, triangle3), and the test of a
// triangle against a half-space set that frustum_triangle and kdop_triangle share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed solid
// triangle (collinear corners: the segments between them; a non-finite corner: no triangle).
// Touching at a vertex, an edge or a face counts. contains: the three corners in the set (convex).
// contains(convex_polyhedron3, triangle3): the three corners in the set (every corner read, so a
// NaN corner gives no in the exact tier).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const triangle3& t) {
    const bool a = intersects(k, c, t.a);
    const bool b = intersects(k, c, t.b);
    const bool e = intersects(k, c, t.c);
    return a && b && e;
}

// convex_polyhedron3 against obb3, contains(convex_polyhedron3, obb3), and the test of a box
// against any half-space set that frustum_obb and kdop_obb share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded) and the closed box { c + s0 a0 + s1 a1 + s2 a2 : |s_j| <= h_j }, its axes read exactly
// as given (the parallelepiped they span; a zero extent or dependent axes give a flat box).
// Touching at a face, an edge or a corner counts. contains: the whole box in the set.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const obb3& b) {
    return halfspaces::obb_inside(k, b, c.planes.data(), c.count);
}

// convex_polyhedron3 against segment3, and contains(convex_polyhedron3, segment3).
// Semantics: the closed set of the half-spaces (possibly empty or unbounded; a non-finite number:
// no set) and the closed segment (a point when a == b); touching a face, an edge or a vertex
// counts. contains: both end points in the set (it is convex).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const segment3& s) {
    const bool a = intersects(k, c, s.a); // both read, so a NaN end point gives no in the exact tier
    const bool b = intersects(k, c, s.b);
    return a && b;
}

// convex_polyhedron3 against tetrahedron3, contains(convex_polyhedron3, tetrahedron3), and the test
// of a tetrahedron against a half-space set that frustum_tetrahedron and kdop_tetrahedron share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed solid
// tetrahedron (coplanar vertices: their hull; a non-finite vertex: no tetrahedron). Touching at a
// vertex, an edge or a face counts. contains: the four vertices in the set (it is convex).
// contains(convex_polyhedron3, tetrahedron3): the four vertices in the set (every vertex read, so a
// NaN vertex gives no in the exact tier).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const tetrahedron3& t) {
    const bool a = intersects(k, c, t.a);
    const bool b = intersects(k, c, t.b);
    const bool e = intersects(k, c, t.c);
    const bool d = intersects(k, c, t.d);
    return a && b && e && d;
}

// frustum3 against obb3, and contains(frustum3, obb3).
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the closed box read as the parallelepiped its axes span. Touching at a face, an edge
// or a corner counts. contains: the whole box in the frustum.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const obb3& b) {
    return halfspaces::obb_inside(k, b, f.planes.data(), 6);
}

// frustum3 against segment3, and contains(frustum3, segment3).
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the closed segment (a point when a == b); touching a face, an edge or a
// corner counts. contains: both end points in the frustum (it is convex).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const segment3& s) {
    const bool a = intersects(k, f, s.a); // both read, so a NaN end point gives no in the exact tier
    const bool b = intersects(k, f, s.b);
    return a && b;
}

// frustum3 against tetrahedron3, and contains(frustum3, tetrahedron3).
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the closed solid tetrahedron (coplanar vertices: their hull). Touching at a vertex,
// an edge or a face counts. contains: the four vertices in the frustum (convex).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const tetrahedron3& t) {
    const bool a = intersects(k, f, t.a);
    const bool b = intersects(k, f, t.b);
    const bool e = intersects(k, f, t.c);
    const bool d = intersects(k, f, t.d);
    return a && b && e && d;
}

// frustum3 against triangle3, and contains(frustum3, triangle3).
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the closed solid triangle (collinear corners: the segments between them). Touching
// at a vertex, an edge or a face counts. contains: the three corners in the frustum (convex).
// contains(frustum3, triangle3): the three corners in the frustum (every corner read).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const triangle3& t) {
    const bool a = intersects(k, f, t.a);
    const bool b = intersects(k, f, t.b);
    const bool e = intersects(k, f, t.c);
    return a && b && e;
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const convex_polyhedron3&, const point3&);
extern template bool exactly<contains_body>(const convex_polyhedron3&, const aabb3&);
extern template bool exactly<contains_body>(const frustum3&, const point3&);
extern template bool exactly<contains_body>(const frustum3&, const aabb3&);
extern template bool exactly<contains_body>(const convex_polyhedron3&, const triangle3&);
extern template bool exactly<contains_body>(const convex_polyhedron3&, const obb3&);
extern template bool exactly<contains_body>(const convex_polyhedron3&, const segment3&);
extern template bool exactly<contains_body>(const convex_polyhedron3&, const tetrahedron3&);
extern template bool exactly<contains_body>(const frustum3&, const obb3&);
extern template bool exactly<contains_body>(const frustum3&, const segment3&);
extern template bool exactly<contains_body>(const frustum3&, const tetrahedron3&);
extern template bool exactly<contains_body>(const frustum3&, const triangle3&);
} // namespace incidence::detail
