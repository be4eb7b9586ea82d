// contains: circle2_pairs
module;
#include <cstddef>
export module incidence.detail:contains.circle2_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.ball_flat;
import :engines.polygon2;
import :intersects.circle2_pairs;
import :exactly;

export namespace incidence::detail {

// contains(circle2, point2 | segment2 | polygon2): the disk is convex, so it holds the hull of the
// vertices (a polygon's set lies in the hull of its vertices) iff each vertex lies in it:
// |v - c|^2 <= r^2 (degree 2). contains(circle2, circle2): |r_b| <= |r_a| and the centres within
// |r_a| - |r_b|, the difference formed exactly inside the sign (degree 2).
// Semantics: a vertex on the circle counts; unchecked negative radii act as |r|; a NaN or infinite
// number, or a malformed polygon, holds or is held by nothing.
// Source: Ericson, Real-Time Collision Detection (2005), section 4.3 (a sphere around points).

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const circle2& c, const point2& p) {
    return intersects(k, c, p);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const circle2& c, const segment2& s) {
    return usable(c) && finite(s) && ball_flat::holds(k, s.a, c.center, reach(c)) && ball_flat::holds(k, s.b, c.center, reach(c));
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const circle2& a, const circle2& b) {
    if (!usable(a) || !usable(b)) return false;
    const double ra = reach(a), rb = reach(b);
    return rb <= ra && ball_flat::holds(k, b.center, a.center, ball_flat::radii{ra, -rb});
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const circle2& c, const polygon2& g) {
    if (!usable(c) || !polygon2d::well_formed(g)) return false;
    const double r = reach(c);
    for (std::size_t i = 0; i < g.vertices.size(); ++i)
        if (!ball_flat::holds(k, g.vertices[i], c.center, r)) return false;
    return true;
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const circle2&, const point2&);
extern template bool exactly<contains_body>(const circle2&, const segment2&);
extern template bool exactly<contains_body>(const circle2&, const circle2&);
extern template bool exactly<contains_body>(const circle2&, const polygon2&);
} // namespace incidence::detail
