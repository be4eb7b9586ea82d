// kdop<K> against tetrahedron3, and contains(kdop, tetrahedron3).
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the closed solid
// tetrahedron (coplanar vertices: their hull). Touching at a vertex, an edge or a face counts.
// contains: the four vertices in the k-DOP (convex).
// Method (exact tiers): the k-DOP is its K half-spaces (kdop_plane.cppm: integer directions, so
// exact), and the pair is the test of a tetrahedron against a half-space set
// (convex_polyhedron_tetrahedron.cppm): a half-space with the four vertices beyond it says no; a
// face meeting the set (the triangle test of convex_polyhedron_triangle.cppm) says yes; else the
// k-DOP lies inside the tetrahedron or outside it, and one of its vertices, where three slab
// planes meet, decides: homogeneous signs of degree <= 8.
// Source: Klosowski et al., IEEE TVCG 4(1), 1998, section 4 (the directions); Schrijver, Theory
// of Linear and Integer Programming, 1986, section 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/kdop_tetrahedron.cpp).
export module incidence.query:kdop_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :kdop_point;
import :kdop_plane;
import :convex_polyhedron_tetrahedron;

export namespace incidence::pair {

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const tetrahedron3& t) {
    if (!kdopq::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdopq::halfspaces(b);
    return polyq::tetrahedron_meets(k, t, rows.data(), N);
}
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const tetrahedron3& t) {
    const point3 pts[4] = {t.a, t.b, t.c, t.d};
    return kdopq::contains_all(k, b, pts, 4);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const tetrahedron3&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const tetrahedron3&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const tetrahedron3&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const kdop<6>&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const kdop<14>&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const kdop<18>&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const kdop<26>&, const tetrahedron3&);
} // namespace incidence::pair
