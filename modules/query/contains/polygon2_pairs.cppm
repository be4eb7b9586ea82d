// contains: polygon2_pairs
module;
#include <cstddef>
#include <utility>
#include <vector>
export module incidence.detail:contains.polygon2_pairs;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :intersects.linear_pairs;
import :engines.polygon2;
import :intersects.polygon2_pairs;
import :exactly;

export namespace incidence::detail {

// point2 against polygon2, contains(polygon, point), and the engine every polygon pair shares.
// Semantics: the polygon's point set is its edges together with the points of odd crossing
// parity (shapes/polygon2.cppm); a point on an edge counts.
// contains(polygon, point): the same set.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const polygon2& g, const point2& p) {
    return intersects(k, p, g);
}

// polygon2 against segment2.
// Semantics: the polygon's edges and the points of odd crossing parity (shapes/polygon2.cppm)
// against the closed segment; touching an edge or a vertex counts.

// contains(polygon, segment): every point of the segment in the polygon's set.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const polygon2& g, const segment2& s) {
    if (!polygon2d::well_formed(g) || !finite(s.a) || !finite(s.b)) return false;
    const polygon2d::box2 gb = polygon2d::bounds(g);
    if (!polygon2d::in_box(gb, s.a) || !polygon2d::in_box(gb, s.b)) return false; // the set lies in the vertices' box
    if (s.a.x == s.b.x && s.a.y == s.b.y) return contains(k, g, s.a);
    return polygon2d::segment_inside(k, [&](const auto& f) { return polygon2d::any_edge(g, f); }, s.a, s.b);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const polygon2&, const point2&);
extern template bool exactly<contains_body>(const polygon2&, const segment2&);
} // namespace incidence::detail
