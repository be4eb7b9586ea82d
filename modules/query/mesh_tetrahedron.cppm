// mesh3 against tetrahedron3 (closed solid; coplanar vertices give their hull).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the bounding boxes, then any mesh triangle meeting the tetrahedron
// (tetrahedron_triangle; a mesh inside the tetrahedron has its triangles inside it), else the
// parity of a vertex.
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/mesh_tetrahedron.cpp).
export module incidence.query:mesh_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :mesh_point;
import :tetrahedron_triangle;
import :point_tetrahedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const tetrahedron3& t) {
    if (!meshq::well_formed(m) || !finite(t)) return false;
    const point3 pts[4] = {t.a, t.b, t.c, t.d};
    const aabb3 xb = meshq::bounds(pts, 4);
    if (!meshq::boxes_meet(meshq::bounds(m), xb)) return false;
    return meshq::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, t, f); }, t.a, &xb);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const mesh3&, const tetrahedron3&);
} // namespace incidence::pair
