// mesh3 against obb3 (closed box read as the parallelepiped its axes span).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): any mesh triangle meeting the box (the 13-axis obb_triangle test; a mesh inside the box has
// its triangles inside it), else the parity of the box centre.
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/mesh_obb.cpp).
export module incidence.query:mesh_obb;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :mesh_point;
import :separating_axes;
import :obb_triangle;
import :obb_tetrahedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const obb3& b) {
    if (!meshq::well_formed(m) || !sat::well_formed(b) || !finite(b)) return false;
    return meshq::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, b, f); }, b.center);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const mesh3&, const obb3&);
} // namespace incidence::pair
