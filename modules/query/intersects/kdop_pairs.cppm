// intersects: kdop_pairs
module;
#include <array>
export module incidence.detail:intersects.kdop_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.box;
import :engines.halfspace_lp;
import :engines.halfspace_meets;
import :engines.kdop;
import :exactly;

export namespace incidence::detail {

// kdop<K> against point3, contains(kdop, point), and the generalised slab test every k-DOP linear
// pair shares (kdop_segment, kdop_ray, kdop_line).
// Semantics: the closed k-DOP { p : min_i <= d_i . p <= max_i } (shapes/kdop.cppm), possibly
// empty (slabs that never meet together); a slab with min > max, or a non-finite bound, makes it
// no set: every query says no. A point on a face, edge or corner counts.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const point3& p) {
    return kdop_slabs::slabs<slab_extent::segment>(k, b, p, vec3{0, 0, 0}, p);
}

// kdop<A> against kdop<B> for any A, B in {6, 14, 18, 26}, and the exact emptiness test of a set of
// k-DOP slabs that aabb_kdop shares.
// Semantics: closed k-DOPs (possibly empty; an empty slab or a non-finite bound: no set, so no);
// touching at a face, an edge or a corner counts.

template <class K, int A, int B>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<A>& a, const kdop<B>& b) {
    return kdop_slabs::meet(k, a, b);
}

// aabb3 against kdop<K>, and contains(kdop, aabb | segment).
// Semantics: the closed box and the closed k-DOP (possibly empty; an empty slab, an inverted box
// or a non-finite bound: no set, so no); touching at a face, an edge or a corner counts.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& a, const kdop<N>& b) {
    return kdop_slabs::meet(k, kdop_slabs::as_kdop(a), b);
}

// kdop<K> against plane3.
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set, so no; slabs that are
// jointly empty: the empty set) and the plane n . x = offset (a zero normal is everything when the
// offset is 0 and nothing otherwise). Touching at a corner, an edge or a face counts.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const plane3& p) {
    if (!kdop_slabs::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdop_slabs::halfspaces(b);
    return halfspaces::plane_meets(k, rows.data(), N, p);
}

// kdop<K> against line3.
// Semantics: the closed k-DOP (possibly empty; an empty slab or a non-finite bound: no set) and
// the line; grazing a face, an edge or a corner counts; a zero direction is the point `origin`.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const line3& l) {
    return kdop_slabs::slabs<slab_extent::line>(k, b, l.origin, l.direction, l.origin);
}

// kdop<K> against mesh3.
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the mesh's point
// set (shapes/mesh3.cppm: its triangles and the points of odd crossing parity); touching a
// triangle counts.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const mesh3& m) {
    if (!kdop_slabs::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdop_slabs::halfspaces(b);
    return halfspaces::mesh_meets(k, m, rows.data(), N);
}

// kdop<K> against obb3, and contains(kdop, obb3).
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the closed box
// read as the parallelepiped its axes span. Touching at a face, an edge or a corner counts.
// contains: the whole box in the k-DOP.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& d, const obb3& b) {
    if (!kdop_slabs::well_formed(d.min.data(), d.max.data(), N / 2)) return false;
    const auto rows = kdop_slabs::halfspaces(d);
    return halfspaces::obb_meets(k, b, rows.data(), N);
}

// kdop<K> against polygon3.
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the polygon's
// point set (shapes/polygon3.cppm). Touching counts.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const polygon3& g) {
    if (!kdop_slabs::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdop_slabs::halfspaces(b);
    return halfspaces::polygon_meets(k, g, rows.data(), N);
}

// kdop<K> against ray3.
// Semantics: the closed k-DOP (possibly empty; an empty slab or a non-finite bound: no set) and
// the closed ray; grazing a face, an edge or a corner counts; a zero direction is the point
// `origin`.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const ray3& r) {
    return kdop_slabs::slabs<slab_extent::ray>(k, b, r.origin, r.direction, r.origin);
}

// kdop<K> against segment3.
// Semantics: the closed k-DOP (possibly empty; an empty slab or a non-finite bound: no set) and
// the closed segment; touching a face, an edge or a corner counts.

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const segment3& s) {
    return kdop_slabs::slabs<slab_extent::segment>(k, b, s.a, vec3{0, 0, 0}, s.b);
}

// kdop<K> against tetrahedron3, and contains(kdop, tetrahedron3).
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the closed solid
// tetrahedron (coplanar vertices: their hull). Touching at a vertex, an edge or a face counts.
// contains: the four vertices in the k-DOP (convex).

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const tetrahedron3& t) {
    if (!kdop_slabs::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdop_slabs::halfspaces(b);
    return halfspaces::tetrahedron_meets(k, t, rows.data(), N);
}

// kdop<K> against triangle3, and contains(kdop, triangle3).
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the closed solid
// triangle (collinear corners: the segments between them). Touching at a vertex, an edge or a
// face counts. contains: the three corners in the k-DOP (convex).

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const triangle3& t) {
    if (!kdop_slabs::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdop_slabs::halfspaces(b);
    return halfspaces::triangle_meets(k, t, rows.data(), N);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const kdop<6>&, const point3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const point3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const point3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const point3&);
extern template bool exactly<intersects_body>(const kdop<6>&, const kdop<6>&);
extern template bool exactly<intersects_body>(const kdop<6>&, const kdop<14>&);
extern template bool exactly<intersects_body>(const kdop<6>&, const kdop<18>&);
extern template bool exactly<intersects_body>(const kdop<6>&, const kdop<26>&);
extern template bool exactly<intersects_body>(const kdop<14>&, const kdop<6>&);
extern template bool exactly<intersects_body>(const kdop<14>&, const kdop<14>&);
extern template bool exactly<intersects_body>(const kdop<14>&, const kdop<18>&);
extern template bool exactly<intersects_body>(const kdop<14>&, const kdop<26>&);
extern template bool exactly<intersects_body>(const kdop<18>&, const kdop<6>&);
extern template bool exactly<intersects_body>(const kdop<18>&, const kdop<14>&);
extern template bool exactly<intersects_body>(const kdop<18>&, const kdop<18>&);
extern template bool exactly<intersects_body>(const kdop<18>&, const kdop<26>&);
extern template bool exactly<intersects_body>(const kdop<26>&, const kdop<6>&);
extern template bool exactly<intersects_body>(const kdop<26>&, const kdop<14>&);
extern template bool exactly<intersects_body>(const kdop<26>&, const kdop<18>&);
extern template bool exactly<intersects_body>(const kdop<26>&, const kdop<26>&);
extern template bool exactly<intersects_body>(const aabb3&, const kdop<6>&);
extern template bool exactly<intersects_body>(const aabb3&, const kdop<14>&);
extern template bool exactly<intersects_body>(const aabb3&, const kdop<18>&);
extern template bool exactly<intersects_body>(const aabb3&, const kdop<26>&);
extern template bool exactly<intersects_body>(const kdop<6>&, const plane3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const plane3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const plane3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const plane3&);
extern template bool exactly<intersects_body>(const kdop<6>&, const line3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const line3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const line3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const line3&);
extern template bool exactly<intersects_body>(const kdop<6>&, const mesh3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const mesh3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const mesh3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const mesh3&);
extern template bool exactly<intersects_body>(const kdop<6>&, const obb3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const obb3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const obb3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const obb3&);
extern template bool exactly<intersects_body>(const kdop<6>&, const polygon3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const polygon3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const polygon3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const polygon3&);
extern template bool exactly<intersects_body>(const kdop<6>&, const ray3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const ray3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const ray3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const ray3&);
extern template bool exactly<intersects_body>(const kdop<6>&, const segment3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const segment3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const segment3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const segment3&);
extern template bool exactly<intersects_body>(const kdop<6>&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const kdop<6>&, const triangle3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const triangle3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const triangle3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const triangle3&);
} // namespace incidence::detail
