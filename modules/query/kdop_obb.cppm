// kdop<K> against obb3, and contains(kdop, obb3).
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the closed box
// read as the parallelepiped its axes span. Touching at a face, an edge or a corner counts.
// contains: the whole box in the k-DOP.
// Method (exact tiers): the k-DOP is its K half-spaces (kdop_plane.cppm: integer directions, so
// exact), and the pair is the test of a box against a half-space set (convex_polyhedron_obb.cppm):
// a half-space with the whole box beyond it says no (the slab test on the box's extent along each
// direction), the centre inside every slab says yes, else the vertex search on the K half-spaces
// and the box's faces in the box's own coordinates: homogeneous signs of degree <= 9.
// Source: Klosowski et al., IEEE TVCG 4(1), 1998, section 4 (the directions); Schrijver, Theory
// of Linear and Integer Programming, 1986, section 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/kdop_obb.cpp).
export module incidence.query:kdop_obb;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :kdop_point;
import :kdop_plane;
import :convex_polyhedron_obb;

export namespace incidence::pair {

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& d, const obb3& b) {
    if (!kdopq::well_formed(d.min.data(), d.max.data(), N / 2)) return false;
    const auto rows = kdopq::halfspaces(d);
    return polyq::obb_meets(k, b, rows.data(), N);
}
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& d, const obb3& b) {
    if (!kdopq::well_formed(d.min.data(), d.max.data(), N / 2)) return false;
    const auto rows = kdopq::halfspaces(d);
    return polyq::obb_inside(k, b, rows.data(), N);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const obb3&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const obb3&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const obb3&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const obb3&);
extern template bool contains(arith::exact_kernel&, const kdop<6>&, const obb3&);
extern template bool contains(arith::exact_kernel&, const kdop<14>&, const obb3&);
extern template bool contains(arith::exact_kernel&, const kdop<18>&, const obb3&);
extern template bool contains(arith::exact_kernel&, const kdop<26>&, const obb3&);
} // namespace incidence::pair
