// mesh3 against mesh3.
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the bounding boxes, then any two triangles meeting (triangle_triangle), else the
// parity of a vertex of each in the other (one inside the other).
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/mesh_mesh.cpp).
module;
#include <array>
#include <cstddef>
#include <span>
export module incidence.query:mesh_mesh;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :mesh_point;
import :triangle_triangle;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& a, const mesh3& b) {
    if (!meshq::well_formed(a) || !meshq::well_formed(b) || !meshq::boxes_meet(meshq::bounds(a), meshq::bounds(b))) return false;
    // Every triangle pair is tested in both orders' evaluation, so (a, b) and (b, a) agree in every tier.
    for (std::size_t i = 0; i < a.triangles.size(); ++i) {
        const triangle3 f = a.triangle(i);
        const point3 fv[3] = {f.a, f.b, f.c};
        const aabb3 fb = meshq::bounds(fv, 3);
        for (std::size_t j = 0; j < b.triangles.size(); ++j) {
            const triangle3 g = b.triangle(j);
            const point3 gv[3] = {g.a, g.b, g.c};
            if (meshq::boxes_meet(fb, meshq::bounds(gv, 3)) && intersects(k, f, g)) return true;
        }
    }
    return meshq::inside(k, a, b.vertices[b.triangles[0][0]]) || meshq::inside(k, b, a.vertices[a.triangles[0][0]]);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const mesh3&, const mesh3&);
} // namespace incidence::pair
