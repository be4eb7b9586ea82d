// intersects: halfspace_pairs
module;
#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
export module incidence.detail:intersects.halfspace_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.separating_axes;
import :engines.tetrahedron;
import :engines.box;
import :intersects.box_pairs;
import :intersects.linear_pairs;
import :intersects.tetrahedron_pairs;
import :engines.halfspace_slabs;
import :engines.halfspace_lp;
import :engines.halfspace_meets;
import :engines.frustum;
import :engines.kdop;
import :intersects.kdop_pairs;
import :intersects.obb_pairs;
import :intersects.polygon_pairs;
import :intersects.mesh_pairs;
import :exactly;

export namespace incidence::detail {

// convex_polyhedron3 against point3, contains(convex_polyhedron3, point3), and the generalised
// slab test every half-space pair shares (convex_polyhedron_segment, _ray, _line, and the frustum
// pairs, whose six planes are one such set).
// Semantics: the closed set { p : n_i . p <= c_i } (shapes/convex_polyhedron3.cppm), possibly
// empty or unbounded; a non-finite number or a count outside [0, capacity] makes no set: every
// query says no. A point on a face, an edge or a vertex counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const point3& p) {
    return halfspaces::halfspaces<slab_extent::segment>(k, c, p, vec3{0, 0, 0}, p);
}

// aabb3 against convex_polyhedron3, contains(convex_polyhedron3, aabb3), and the half-space
// feasibility test the other half-space pairs share: with a box (aabb_frustum), and of possibly
// unbounded sets (polyq::feasible: convex_polyhedron_plane, frustum_plane).
// Semantics: the closed box (bounds ordered and finite; an inverted box is empty) and the closed
// half-space set of convex_polyhedron_point.cppm (possibly empty or unbounded; a non-finite number
// or a count outside [0, capacity]: no set). Touching at a face, an edge or a vertex counts.
// contains(polyhedron, box): the eight corners in the set (it is convex).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const convex_polyhedron3& c) {
    return halfspaces::box_meets(k, b, c.planes.data(), c.count);
}

// frustum3 against point3, and contains(frustum3, point3).
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the point; a point on a face, an edge or a corner counts. contains: the
// same set.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const point3& p) {
    return halfspaces::halfspaces<slab_extent::segment>(k, f.planes.data(), 6, p, vec3{0, 0, 0}, p);
}

// aabb3 against frustum3, and contains(frustum3, aabb3).
// Semantics: the closed box (bounds ordered and finite; an inverted box is empty) and the closed
// view volume of the frustum's six half-spaces (shapes/frustum3.cppm; a non-finite number: no
// set). Touching at a face, an edge or a corner counts. contains: the eight corners in the frustum.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const frustum3& f) {
    return halfspaces::box_meets(k, b, f.planes.data(), 6);
}
// The catalog's second alternative: box_frustum_decomposition; where a corner does not exist, the
// vertex test in double decides.
[[nodiscard]] constexpr bool aabb_frustum_decomposition(const aabb3& b, const frustum3& f) {
    if (!well_formed_finite(b) || !halfspaces::well_formed(f.planes.data(), 6, 6)) return false;
    arith::approx_kernel k;
    point3 corner[8];
    if (!frustum_corners(f, corner)) return halfspaces::box_meets(k, b, f.planes.data(), 6);
    return box_frustum_decomposition([&](const tetrahedron3& t) { return intersects(k, b, t); }, corner);
}

// convex_polyhedron3 against plane3.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the plane
// n . x = offset (a zero normal is everything when the offset is 0 and nothing otherwise; a
// non-finite number: no set). Touching at a vertex, an edge or a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const plane3& p) {
    return halfspaces::plane_meets(k, c.planes.data(), c.count, p);
}

// convex_polyhedron3 against convex_polyhedron3, and the test of two half-space sets that
// convex_polyhedron_frustum shares.
// Semantics: two closed half-space sets of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set). Touching at a vertex,
// an edge or a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& a, const convex_polyhedron3& b) {
    const bool swap = halfspaces::before(b, a);
    const convex_polyhedron3& p = swap ? b : a;
    const convex_polyhedron3& q = swap ? a : b;
    return halfspaces::sets_meet(k, p.planes.data(), p.count, q.planes.data(), q.count);
}

// convex_polyhedron3 against frustum3.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed view
// volume of six half-spaces (shapes/frustum3.cppm). Touching at a vertex, an edge or a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& a, const frustum3& f) {
    return halfspaces::sets_meet(k, a.planes.data(), a.count, f.planes.data(), 6);
}

// convex_polyhedron3 against kdop<K>.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed k-DOP
// (an empty slab or a non-finite bound: no set, so no). Touching at a vertex, an edge or a face counts.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const kdop<N>& b) {
    if (!kdop_slabs::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdop_slabs::halfspaces(b);
    return halfspaces::sets_meet(k, c.planes.data(), c.count, rows.data(), N);
}

// convex_polyhedron3 against line3.
// Semantics: the closed set of the half-spaces (possibly empty or unbounded; a non-finite number:
// no set) and the line; grazing a face, an edge or a vertex counts; a zero direction is the point
// `origin`.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const line3& l) {
    return halfspaces::halfspaces<slab_extent::line>(k, c, l.origin, l.direction, l.origin);
}

// convex_polyhedron3 against triangle3, contains(convex_polyhedron3, triangle3), and the test of a
// triangle against a half-space set that frustum_triangle and kdop_triangle share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed solid
// triangle (collinear corners: the segments between them; a non-finite corner: no triangle).
// Touching at a vertex, an edge or a face counts. contains: the three corners in the set (convex).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const triangle3& t) {
    return halfspaces::triangle_meets(k, t, c.planes.data(), c.count);
}

// convex_polyhedron3 against mesh3, and the test of a mesh against a half-space set that
// frustum_mesh and kdop_mesh share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the mesh's point
// set (shapes/mesh3.cppm: its triangles and the points of odd crossing parity); touching a
// triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const mesh3& m) {
    return halfspaces::mesh_meets(k, m, c.planes.data(), c.count);
}

// convex_polyhedron3 against obb3, contains(convex_polyhedron3, obb3), and the test of a box
// against any half-space set that frustum_obb and kdop_obb share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded) and the closed box { c + s0 a0 + s1 a1 + s2 a2 : |s_j| <= h_j }, its axes read exactly
// as given (the parallelepiped they span; a zero extent or dependent axes give a flat box).
// Touching at a face, an edge or a corner counts. contains: the whole box in the set.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const obb3& b) {
    return halfspaces::obb_meets(k, b, c.planes.data(), c.count);
}

// convex_polyhedron3 against polygon3, and the test of a polygon against a half-space set that
// frustum_polygon and kdop_polygon share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded) and the polygon's point set (shapes/polygon3.cppm). Touching counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const polygon3& g) {
    return halfspaces::polygon_meets(k, g, c.planes.data(), c.count);
}

// convex_polyhedron3 against ray3.
// Semantics: the closed set of the half-spaces (possibly empty or unbounded; a non-finite number:
// no set) and the closed ray; grazing a face, an edge or a vertex counts; a zero direction is the
// point `origin`.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const ray3& r) {
    return halfspaces::halfspaces<slab_extent::ray>(k, c, r.origin, r.direction, r.origin);
}

// convex_polyhedron3 against segment3, and contains(convex_polyhedron3, segment3).
// Semantics: the closed set of the half-spaces (possibly empty or unbounded; a non-finite number:
// no set) and the closed segment (a point when a == b); touching a face, an edge or a vertex
// counts. contains: both end points in the set (it is convex).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const segment3& s) {
    return halfspaces::halfspaces<slab_extent::segment>(k, c, s.a, vec3{0, 0, 0}, s.b);
}

// convex_polyhedron3 against tetrahedron3, contains(convex_polyhedron3, tetrahedron3), and the test
// of a tetrahedron against a half-space set that frustum_tetrahedron and kdop_tetrahedron share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed solid
// tetrahedron (coplanar vertices: their hull; a non-finite vertex: no tetrahedron). Touching at a
// vertex, an edge or a face counts. contains: the four vertices in the set (it is convex).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const tetrahedron3& t) {
    return halfspaces::tetrahedron_meets(k, t, c.planes.data(), c.count);
}

// frustum3 against frustum3.
// Semantics: two closed view volumes of six half-spaces each (shapes/frustum3.cppm; a non-finite
// number: no set). Touching at a vertex, an edge or a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& a, const frustum3& b) {
    const bool swap = halfspaces::before(b, a);
    const frustum3& p = swap ? b : a;
    const frustum3& q = swap ? a : b;
    return halfspaces::sets_meet(k, p.planes.data(), 6, q.planes.data(), 6);
}

// frustum3 against kdop<K>.
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm) and the closed k-DOP
// (an empty slab or a non-finite bound: no set, so no). Touching at a vertex, an edge or a face counts.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const kdop<N>& b) {
    if (!kdop_slabs::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdop_slabs::halfspaces(b);
    return halfspaces::sets_meet(k, f.planes.data(), 6, rows.data(), N);
}

// frustum3 against line3.
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the line; grazing a face, an edge or a corner counts; a zero direction is
// the point `origin`.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const line3& l) {
    return halfspaces::halfspaces<slab_extent::line>(k, f.planes.data(), 6, l.origin, l.direction, l.origin);
}

// frustum3 against mesh3.
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const mesh3& m) {
    return halfspaces::mesh_meets(k, m, f.planes.data(), 6);
}

// frustum3 against obb3, and contains(frustum3, obb3).
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the closed box read as the parallelepiped its axes span. Touching at a face, an edge
// or a corner counts. contains: the whole box in the frustum.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const obb3& b) {
    return halfspaces::obb_meets(k, b, f.planes.data(), 6);
}
// The decomposition test in plain double (the catalog's second alternative): six tetrahedra
// against the box; where a corner does not exist, the box test above in double decides.
[[nodiscard]] constexpr bool frustum_obb_decomposition(const frustum3& f, const obb3& b) {
    if (!sat::well_formed(b) || !finite(b) || !halfspaces::well_formed(f.planes.data(), 6, 6)) return false;
    arith::approx_kernel k;
    point3 corner[8];
    if (!frustum_corners(f, corner)) return halfspaces::obb_meets(k, b, f.planes.data(), 6);
    return box_frustum_decomposition([&](const tetrahedron3& t) { return intersects(k, b, t); }, corner);
}

// frustum3 against plane3.
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the plane n . x = offset (a zero normal is everything when the offset is 0
// and nothing otherwise). Touching at a corner, an edge or a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const plane3& p) {
    return halfspaces::plane_meets(k, f.planes.data(), 6, p);
}

// frustum3 against polygon3.
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the polygon's point set (shapes/polygon3.cppm). Touching counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const polygon3& g) {
    return halfspaces::polygon_meets(k, g, f.planes.data(), 6);
}

// frustum3 against ray3.
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the closed ray; grazing a face, an edge or a corner counts; a zero
// direction is the point `origin`.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const ray3& r) {
    return halfspaces::halfspaces<slab_extent::ray>(k, f.planes.data(), 6, r.origin, r.direction, r.origin);
}

// frustum3 against segment3, and contains(frustum3, segment3).
// Semantics: the closed view volume of its six half-spaces (shapes/frustum3.cppm; a non-finite
// number: no set) and the closed segment (a point when a == b); touching a face, an edge or a
// corner counts. contains: both end points in the frustum (it is convex).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const segment3& s) {
    return halfspaces::halfspaces<slab_extent::segment>(k, f.planes.data(), 6, s.a, vec3{0, 0, 0}, s.b);
}

// frustum3 against tetrahedron3, and contains(frustum3, tetrahedron3).
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the closed solid tetrahedron (coplanar vertices: their hull). Touching at a vertex,
// an edge or a face counts. contains: the four vertices in the frustum (convex).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const tetrahedron3& t) {
    return halfspaces::tetrahedron_meets(k, t, f.planes.data(), 6);
}

// frustum3 against triangle3, and contains(frustum3, triangle3).
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the closed solid triangle (collinear corners: the segments between them). Touching
// at a vertex, an edge or a face counts. contains: the three corners in the frustum (convex).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const triangle3& t) {
    return halfspaces::triangle_meets(k, t, f.planes.data(), 6);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const point3&);
extern template bool exactly<intersects_body>(const aabb3&, const convex_polyhedron3&);
extern template bool exactly<intersects_body>(const frustum3&, const point3&);
extern template bool exactly<intersects_body>(const aabb3&, const frustum3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const plane3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const convex_polyhedron3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const frustum3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const kdop<6>&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const kdop<14>&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const kdop<18>&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const kdop<26>&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const line3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const triangle3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const mesh3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const obb3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const polygon3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const ray3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const segment3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const frustum3&, const frustum3&);
extern template bool exactly<intersects_body>(const frustum3&, const kdop<6>&);
extern template bool exactly<intersects_body>(const frustum3&, const kdop<14>&);
extern template bool exactly<intersects_body>(const frustum3&, const kdop<18>&);
extern template bool exactly<intersects_body>(const frustum3&, const kdop<26>&);
extern template bool exactly<intersects_body>(const frustum3&, const line3&);
extern template bool exactly<intersects_body>(const frustum3&, const mesh3&);
extern template bool exactly<intersects_body>(const frustum3&, const obb3&);
extern template bool exactly<intersects_body>(const frustum3&, const plane3&);
extern template bool exactly<intersects_body>(const frustum3&, const polygon3&);
extern template bool exactly<intersects_body>(const frustum3&, const ray3&);
extern template bool exactly<intersects_body>(const frustum3&, const segment3&);
extern template bool exactly<intersects_body>(const frustum3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const frustum3&, const triangle3&);
} // namespace incidence::detail
