// A box, an oriented box, a triangle, a tetrahedron or a frustum against a scene of triangles
// (scene3), either argument order, and every triangle a shape meets:
// - intersects<Tier>(s, scene): does s meet some triangle? The scalar intersects<Tier>(s, triangle)
//   of the triangles the hierarchy cannot rule out: in the exact and aggressive tiers the brute
//   force's answer (the scalar tier looped over every triangle); conservative never says no where s
//   meets a triangle, and yes only where the brute force does; approximate ORs the plain-double
//   answers of at least the triangles whose boxes meet s's box.
// - intersecting<Tier>(s, scene, out): the caller's indices of every triangle the scalar tier
//   calls met, among those the hierarchy cannot rule out, appended to out in the hierarchy's
//   order; how many. For a line, a ray or a segment as well (linear_scene.cppm's shapes).
// Method: depth-first traversal; a node is skipped where its box (exact bounds of its vertices)
// and s's box do not meet, by comparisons: s's box is exact for a box, a triangle and a
// tetrahedron, rounded outward (interval arithmetic) for an oriented box; a frustum (culling) is
// tested against the node's box itself by the conservative tier of the frustum-box pair. So no node
// whose triangles s meets is skipped (Ericson, Real-Time Collision Detection, 2005, section 6.3.2:
// a hierarchy's descent by bounding-volume overlap). Non-finite input meets nothing.
module;
#include <cstddef>
#include <type_traits>
#include <vector>
export module incidence.scene:solid_scene;
import incidence.core;
import incidence.shapes;
import :scene3;
import :linear_scene;

export namespace incidence {

template <class S>
concept scene_solid = std::is_same_v<S, aabb3> || std::is_same_v<S, obb3> || std::is_same_v<S, triangle3> ||
                      std::is_same_v<S, tetrahedron3> || std::is_same_v<S, frustum3>;

} // namespace incidence

namespace incidence::detail {
// Compiled once in the library (traversal.cpp), for each tier and shape.
template <class Tier, class S>
[[nodiscard]] bool scene_solid_any(const S& s, const scene3& scene);
template <class Tier, class S>
std::size_t scene_every_hit(const S& s, const scene3& scene, std::vector<std::size_t>& out);
} // namespace incidence::detail

export namespace incidence {

template <tier Tier = exact, scene_solid S>
[[nodiscard]] bool intersects(const S& s, const scene3& scene) {
    return detail::scene_solid_any<Tier>(s, scene);
}
template <tier Tier = exact, scene_solid S>
[[nodiscard]] bool intersects(const scene3& scene, const S& s) {
    return detail::scene_solid_any<Tier>(s, scene);
}
template <tier Tier = exact, class S>
requires scene_solid<S> || scene_linear<S>
std::size_t intersecting(const S& s, const scene3& scene, std::vector<std::size_t>& out) {
    return detail::scene_every_hit<Tier>(s, scene, out);
}

} // namespace incidence
