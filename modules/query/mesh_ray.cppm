// mesh3 against ray3 (a point when the direction is zero).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): any triangle meeting the ray (the ray_triangle sign algorithm), else the parity of its origin.
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/mesh_ray.cpp).
export module incidence.query:mesh_ray;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :mesh_point;
import :ray_triangle;
import :point_tetrahedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const ray3& r) {
    if (!meshq::well_formed(m) || !finite(r)) return false;
    return meshq::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, r, f); }, r.origin);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const mesh3&, const ray3&);
} // namespace incidence::pair
