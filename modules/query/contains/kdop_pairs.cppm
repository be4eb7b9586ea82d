// contains: kdop_pairs
module;
#include <array>
export module incidence.detail:contains.kdop_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :intersects.box_pairs;
import :intersects.linear_pairs;
import :engines.halfspace_meets;
import :engines.kdop;
import :intersects.kdop_pairs;
import :intersects.halfspace_pairs;
import :contains.halfspace_pairs;
import :exactly;

export namespace incidence::detail {

// kdop<K> against point3, contains(kdop, point), and the generalised slab test every k-DOP linear
// pair shares (kdop_segment, kdop_ray, kdop_line).
// Semantics: the closed k-DOP { p : min_i <= d_i . p <= max_i } (shapes/kdop.cppm), possibly
// empty (slabs that never meet together); a slab with min > max, or a non-finite bound, makes it
// no set: every query says no. A point on a face, edge or corner counts.
// contains(kdop, point): the same set.
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const point3& p) {
    return intersects(k, b, p);
}

namespace kdop_slabs {
// Every one of the n points in the k-DOP: a convex shape with those vertices lies inside it.
template <class K, int N>
[[nodiscard]] constexpr bool contains_all(K& k, const kdop<N>& b, const point3* pts, int n) {
    for (int i = 0; i < n; ++i)
        if (!intersects(k, b, pts[i])) return false;
    return true;
}
} // namespace kdop_slabs

// aabb3 against kdop<K>, and contains(kdop, aabb | segment).
// Semantics: the closed box and the closed k-DOP (possibly empty; an empty slab, an inverted box
// or a non-finite bound: no set, so no); touching at a face, an edge or a corner counts.

template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const aabb3& a) {
    if (!kdop_slabs::well_formed(&a.min.x, &a.max.x, 1) || !kdop_slabs::well_formed(&a.min.y, &a.max.y, 1) ||
        !kdop_slabs::well_formed(&a.min.z, &a.max.z, 1))
        return false;
    const point3 c[8] = {{a.min.x, a.min.y, a.min.z}, {a.max.x, a.min.y, a.min.z}, {a.min.x, a.max.y, a.min.z},
                         {a.max.x, a.max.y, a.min.z}, {a.min.x, a.min.y, a.max.z}, {a.max.x, a.min.y, a.max.z},
                         {a.min.x, a.max.y, a.max.z}, {a.max.x, a.max.y, a.max.z}};
    return kdop_slabs::contains_all(k, b, c, 8);
}
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const segment3& s) {
    const point3 p[2] = {s.a, s.b};
    return kdop_slabs::contains_all(k, b, p, 2);
}

// kdop<K> against obb3, and contains(kdop, obb3).
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the closed box
// read as the parallelepiped its axes span. Touching at a face, an edge or a corner counts.
// contains: the whole box in the k-DOP.
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& d, const obb3& b) {
    if (!kdop_slabs::well_formed(d.min.data(), d.max.data(), N / 2)) return false;
    const auto rows = kdop_slabs::halfspaces(d);
    return halfspaces::obb_inside(k, b, rows.data(), N);
}

// kdop<K> against tetrahedron3, and contains(kdop, tetrahedron3).
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the closed solid
// tetrahedron (coplanar vertices: their hull). Touching at a vertex, an edge or a face counts.
// contains: the four vertices in the k-DOP (convex).
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const tetrahedron3& t) {
    const point3 pts[4] = {t.a, t.b, t.c, t.d};
    return kdop_slabs::contains_all(k, b, pts, 4);
}

// kdop<K> against triangle3, and contains(kdop, triangle3).
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the closed solid
// triangle (collinear corners: the segments between them). Touching at a vertex, an edge or a
// face counts. contains: the three corners in the k-DOP (convex).
// contains(kdop, triangle3): the three corners in the k-DOP.
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const triangle3& t) {
    const point3 pts[3] = {t.a, t.b, t.c};
    return kdop_slabs::contains_all(k, b, pts, 3);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const kdop<6>&, const point3&);
extern template bool exactly<contains_body>(const kdop<14>&, const point3&);
extern template bool exactly<contains_body>(const kdop<18>&, const point3&);
extern template bool exactly<contains_body>(const kdop<26>&, const point3&);
extern template bool exactly<contains_body>(const kdop<6>&, const aabb3&);
extern template bool exactly<contains_body>(const kdop<14>&, const aabb3&);
extern template bool exactly<contains_body>(const kdop<18>&, const aabb3&);
extern template bool exactly<contains_body>(const kdop<26>&, const aabb3&);
extern template bool exactly<contains_body>(const kdop<6>&, const segment3&);
extern template bool exactly<contains_body>(const kdop<14>&, const segment3&);
extern template bool exactly<contains_body>(const kdop<18>&, const segment3&);
extern template bool exactly<contains_body>(const kdop<26>&, const segment3&);
extern template bool exactly<contains_body>(const kdop<6>&, const obb3&);
extern template bool exactly<contains_body>(const kdop<14>&, const obb3&);
extern template bool exactly<contains_body>(const kdop<18>&, const obb3&);
extern template bool exactly<contains_body>(const kdop<26>&, const obb3&);
extern template bool exactly<contains_body>(const kdop<6>&, const tetrahedron3&);
extern template bool exactly<contains_body>(const kdop<14>&, const tetrahedron3&);
extern template bool exactly<contains_body>(const kdop<18>&, const tetrahedron3&);
extern template bool exactly<contains_body>(const kdop<26>&, const tetrahedron3&);
extern template bool exactly<contains_body>(const kdop<6>&, const triangle3&);
extern template bool exactly<contains_body>(const kdop<14>&, const triangle3&);
extern template bool exactly<contains_body>(const kdop<18>&, const triangle3&);
extern template bool exactly<contains_body>(const kdop<26>&, const triangle3&);
} // namespace incidence::detail
