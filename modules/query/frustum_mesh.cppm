// frustum3 against mesh3.
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the test of a mesh against a half-space set
// (convex_polyhedron_mesh.cppm): a plane with every mesh vertex beyond it says no; a mesh triangle
// meeting the frustum says yes; else one vertex of the frustum, where three of its planes meet,
// decides by exact crossing parity: homogeneous signs of degree <= 8.
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm (Haines,
// Graphics Gems IV, 1994); Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/frustum_mesh.cpp).
export module incidence.query:frustum_mesh;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :convex_polyhedron_mesh;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const mesh3& m) {
    return polyq::mesh_meets(k, m, f.planes.data(), 6);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const frustum3&, const mesh3&);
} // namespace incidence::pair
