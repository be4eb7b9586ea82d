// mesh3 against polygon3.
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity) and the polygon's (shapes/polygon3.cppm). Touching counts.
// Method (exact tiers): a mesh triangle meets the polygon (polygon_triangle.cppm; a triangle whose
// bounding box misses the polygon's is skipped), or else the first vertex of some ring lies
// inside the solid (mesh_point.cppm). Complete: where no triangle meets the polygon, each
// connected piece of the polygon lies wholly inside or outside the solid, and each piece holds
// the vertices of the rings that bound it.
// Source: the boundary-plus-inside decompositions of mesh_point.cppm and point_polygon.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/mesh_polygon.cpp).
module;
#include <cstddef>
export module incidence.query:mesh_polygon;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :mesh_point;
import :point_polygon;
import :polygon_triangle;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const polygon3& g) {
    if (!meshq::well_formed(m) || !planeq::usable(k, g)) return false;
    const aabb3 gb = meshq::bounds(g.vertices.data(), g.vertices.size());
    if (!meshq::boxes_meet(meshq::bounds(m), gb)) return false;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 t = m.triangle(i);
        const point3 v[3] = {t.a, t.b, t.c};
        if (meshq::boxes_meet(meshq::bounds(v, 3), gb) && intersects(k, g, t)) return true;
    }
    for (std::size_t r = 0; r < g.rings(); ++r)
        if (meshq::inside(k, m, g.vertices[g.ring_begin(r)])) return true;
    return false;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const mesh3&, const polygon3&);
} // namespace incidence::pair
