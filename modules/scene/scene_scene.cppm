// A scene against a scene: does some triangle of one meet some triangle of the other, and every
// such pair (the contacts of two meshes, a mesh against a moved copy of itself):
// - intersects<Tier>(a, b): the scalar intersects<Tier>(triangle, triangle) of the pairs the two
//   hierarchies cannot rule out: in the exact and aggressive tiers the brute force's answer (the
//   scalar tier over every pair); conservative never says no where two triangles meet, and yes
//   only where the brute force does; approximate ORs the plain-double answers of at least the
//   pairs whose triangles' boxes meet.
// - intersecting<Tier>(a, b, out): every pair (the caller's index in a, in b) the scalar tier calls
//   met, among those the hierarchies cannot rule out, appended to out; how many.
// Method: simultaneous descent of the two hierarchies (Gottschalk, Lin and Manocha, "OBBTree",
// SIGGRAPH 1996, section 5, with axis-aligned boxes): a pair of nodes is skipped where their
// boxes (exact bounds of their vertices) do not meet, by comparisons, so no pair of triangles that
// meet is skipped; the node with the larger box descends first. The triangles' own test: the
// scalar triangle-triangle pair (its separating axes and coplanar case, exact in the exact tier).
module;
#include <cstddef>
#include <utility>
#include <vector>
export module incidence.scene:scene_scene;
import incidence.core;
import incidence.shapes;
import :scene3;

namespace incidence::detail {
// Compiled once in the library (traversal.cpp), for each tier.
template <class Tier>
[[nodiscard]] bool scene_pairs(const scene3& a, const scene3& b, std::vector<std::pair<std::size_t, std::size_t>>* out, std::size_t& met);
} // namespace incidence::detail

export namespace incidence {

template <tier Tier = exact>
[[nodiscard]] bool intersects(const scene3& a, const scene3& b) {
    std::size_t met = 0;
    return detail::scene_pairs<Tier>(a, b, nullptr, met);
}
template <tier Tier = exact>
std::size_t intersecting(const scene3& a, const scene3& b, std::vector<std::pair<std::size_t, std::size_t>>& out) {
    std::size_t met = 0;
    (void)detail::scene_pairs<Tier>(a, b, &out, met);
    return met;
}

} // namespace incidence
