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

// contains(polygon2, circle2): the closed disk in the polygon's set (shapes/polygon2.cppm). A zero
// radius is the point c (intersects(circle2, polygon2)). Otherwise the crossing parity changes only
// across boundary covered an odd number of times (polygon2d::any_odd_piece: every edge, for simple
// rings), so the disk is held iff no such piece comes strictly within r of the centre (the
// closest-feature signs of ball_flat.cppm, each final sign strict, degree <= 4) and the parity at
// the centre is odd (polygon2d::inside, degree 2): the open disk then lies in one odd region and
// the closed disk in its closure, whose boundary is edges. A centre on evenly covered edges gets
// the parity of the points just above it (the half-open rule; those edges give orientation zero
// and count for nothing, as their crossings there cancel in pairs). Edges whose box misses the
// disk's box (rounded outward) are skipped.
// Semantics: the disk |x - c| <= |r|; the polygon's set of edges and odd crossing parity, for any
// rings (crossing, overlapping); a NaN or infinite number, or a malformed polygon: not held.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.1.2 (closest point on a
// segment); Haines, "Point in polygon strategies", Graphics Gems IV (1994) (the crossings test).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const polygon2& g, const circle2& c) {
    if (!usable(c) || !polygon2d::well_formed(g)) return false;
    const double r = reach(c);
    if (r == 0.0) return intersects(k, c, g);
    if (!polygon2d::in_box(polygon2d::bounds(g), c.center)) return false;
    const polygon2d::box2 xb = ball_flat::reach_box(c.center, r);
    const auto enters = [&](point2 u, point2 v) { return ball_flat::meets<true>(k, as_linear(segment2{u, v}), c.center, r); };
    const bool crossed = polygon2d::any_edge(g, [&](point2 p, point2 q) {
        if (p.x == q.x && p.y == q.y) return false; // a point: no boundary between regions
        const point2 v[2] = {p, q};
        if (!polygon2d::boxes_meet(polygon2d::bounds(v, 2), xb)) return false;
        return enters(p, q) && polygon2d::any_odd_piece(k, g, p, q, enters);
    });
    return !crossed && polygon2d::odd_crossings(k, g, c.center); // the box was tested above
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const circle2&, const point2&);
extern template bool exactly<contains_body>(const circle2&, const segment2&);
extern template bool exactly<contains_body>(const circle2&, const circle2&);
extern template bool exactly<contains_body>(const circle2&, const polygon2&);
extern template bool exactly<contains_body>(const polygon2&, const circle2&);
} // namespace incidence::detail
