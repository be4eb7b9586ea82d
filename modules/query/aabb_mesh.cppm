// aabb3 against mesh3 (closed box; an inverted box is empty).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the bounding boxes, then any mesh triangle meeting the box (the 13-axis aabb_triangle
// test; a mesh inside the box has its triangles inside it), else the parity of a corner.
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/aabb_mesh.cpp).
export module incidence.query:aabb_mesh;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :mesh_point;
import :aabb_triangle;
import :aabb_tetrahedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const mesh3& m) {
    if (!meshq::well_formed(m) || !well_formed_finite(b) || !meshq::boxes_meet(meshq::bounds(m), b)) return false;
    return meshq::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, b, f); }, b.min, &b);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const mesh3&);
} // namespace incidence::pair
