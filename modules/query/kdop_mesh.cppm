// kdop<K> against mesh3.
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the mesh's point
// set (shapes/mesh3.cppm: its triangles and the points of odd crossing parity); touching a
// triangle counts.
// Method (exact tiers): the k-DOP is its K half-spaces (kdop_plane.cppm: integer directions, so
// exact), and the pair is the test of a mesh against a half-space set
// (convex_polyhedron_mesh.cppm): a half-space with every mesh vertex beyond it says no; a mesh
// triangle meeting the k-DOP says yes; else one vertex of the k-DOP, where three slab planes meet,
// decides by exact crossing parity: homogeneous signs of degree <= 8.
// Source: Klosowski et al., IEEE TVCG 4(1), 1998, section 4 (the directions); the
// boundary-plus-inside decomposition and crossing parity of mesh_point.cppm (Haines, Graphics Gems
// IV, 1994).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/kdop_mesh.cpp).
export module incidence.query:kdop_mesh;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :kdop_point;
import :kdop_plane;
import :convex_polyhedron_mesh;

export namespace incidence::pair {

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const mesh3& m) {
    if (!kdopq::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdopq::halfspaces(b);
    return polyq::mesh_meets(k, m, rows.data(), N);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const mesh3&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const mesh3&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const mesh3&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const mesh3&);
} // namespace incidence::pair
