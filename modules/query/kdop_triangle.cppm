// kdop<K> against triangle3, and contains(kdop, triangle3).
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the closed solid
// triangle (collinear corners: the segments between them). Touching at a vertex, an edge or a
// face counts. contains: the three corners in the k-DOP (convex).
// Method (exact tiers): the k-DOP is its K half-spaces (kdop_plane.cppm: integer directions, so
// exact), and the pair is the test of a triangle against a half-space set
// (convex_polyhedron_triangle.cppm): a half-space with the three corners beyond it says no; an
// edge meeting the set says yes; else a vertex of the set's section by the triangle's plane, where
// two non-parallel slab planes cross it, inside every half-space and the triangle: homogeneous
// signs of degree <= 8.
// Source: Klosowski et al., IEEE TVCG 4(1), 1998, section 4 (the directions); Schrijver, Theory
// of Linear and Integer Programming, 1986, section 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/kdop_triangle.cpp).
export module incidence.query:kdop_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :kdop_point;
import :kdop_plane;
import :convex_polyhedron_triangle;

export namespace incidence::pair {

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const triangle3& t) {
    if (!kdopq::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdopq::halfspaces(b);
    return polyq::triangle_meets(k, t, rows.data(), N);
}
// contains(kdop, triangle3): the three corners in the k-DOP.
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const triangle3& t) {
    const point3 pts[3] = {t.a, t.b, t.c};
    return kdopq::contains_all(k, b, pts, 3);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const triangle3&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const triangle3&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const triangle3&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const triangle3&);
extern template bool contains(arith::exact_kernel&, const kdop<6>&, const triangle3&);
extern template bool contains(arith::exact_kernel&, const kdop<14>&, const triangle3&);
extern template bool contains(arith::exact_kernel&, const kdop<18>&, const triangle3&);
extern template bool contains(arith::exact_kernel&, const kdop<26>&, const triangle3&);
} // namespace incidence::pair
