// intersection<Tier>(a, b) -> std::optional<hit>: where a line, a ray or a segment meets a set
// (docs/DESIGN.md, "Values"): span_hit for a plane, a box, an oriented box, a k-DOP, a frustum, a
// convex polyhedron, a tetrahedron and a ball; triangle_hit, polygon_hit and mesh_hit (first
// contact) for a triangle, a polygon and a closed mesh. Either argument order; the hit is always
// about the linear object. The tiers (tiers.cppm, find_pair): exact values correctly rounded;
// conservative and aggressive values enclosed (a hit conservative could not exclude says
// exists == certainty::uncertain); approximate in plain double. The bodies:
// modules/query/intersection/.
module;
#include <optional>
#include <type_traits>
export module incidence.query:intersection;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.detail;
import :tiers;

namespace incidence::detail {
template <class A, class B>
concept finds = requires(arith::filter_kernel& k, const A& a, const B& b) { detail::intersection(k, a, b); };
} // namespace incidence::detail

export namespace incidence {

template <class A, class B>
concept has_intersection = detail::finds<A, B> || detail::finds<B, A>;

template <tier Tier = exact, class A, class B>
requires has_intersection<A, B>
[[nodiscard]] constexpr auto intersection(const A& a, const B& b) {
    if constexpr (detail::finds<A, B>) return detail::find_pair<Tier>(a, b, detail::intersection_body{});
    else return detail::find_pair<Tier>(b, a, detail::intersection_body{});
}

} // namespace incidence
