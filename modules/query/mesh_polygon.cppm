// mesh3 against polygon3.
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity) and the polygon's (shapes/polygon3.cppm). Touching counts.
// Method (exact tiers): an edge of the polygon meets the mesh (mesh_segment.cppm: its triangles,
// else the parity of a point), or a mesh triangle meets the polygon (polygon_triangle.cppm).
// Complete: where they meet and no polygon edge touches the mesh, the polygon's part there meets
// the mesh's surface (it cannot lie wholly inside without its edges).
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
import :mesh_segment;
import :point_polygon;
import :polygon_triangle;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const polygon3& g) {
    if (!meshq::well_formed(m) || !planeq::usable(k, g)) return false;
    if (planeq::any_edge(g, [&](const segment3& e) { return intersects(k, m, e); })) return true;
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
        if (intersects(k, g, m.triangle(i))) return true;
    return false;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const mesh3&, const polygon3&);
} // namespace incidence::pair
