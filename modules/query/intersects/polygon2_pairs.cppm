// intersects: polygon2_pairs
module;
#include <cstddef>
#include <utility>
#include <vector>
export module incidence.detail:intersects.polygon2_pairs;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :intersects.linear_pairs;
import :engines.polygon2;
import :exactly;

export namespace incidence::detail {

// point2 against polygon2, contains(polygon, point), and the engine every polygon pair shares.
// Semantics: the polygon's point set is its edges together with the points of odd crossing
// parity (shapes/polygon2.cppm); a point on an edge counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point2& p, const polygon2& g) {
    if (!polygon2d::well_formed(g) || !finite(p) || !polygon2d::in_box(polygon2d::bounds(g), p)) return false;
    const polygon2d::box2 xb{p, p};
    return polygon2d::polygon_meets(k, g, [&](const segment2& e) { return linear_linear(k, as_linear(p), as_linear(e)); }, p, &xb);
}

// line2 against polygon2.
// Semantics: the line against the polygon's edges and the points of odd crossing parity
// (shapes/polygon2.cppm); touching an edge or a vertex counts; a zero direction is the point
// `origin`.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line2& l, const polygon2& g) {
    if (!polygon2d::well_formed(g) || !finite(l.origin) || !finite(l.direction)) return false;
    return polygon2d::polygon_meets(k, g, [&](const segment2& e) { return intersects(k, l, e); }, l.origin);
}

// polygon2 against segment2.
// Semantics: the polygon's edges and the points of odd crossing parity (shapes/polygon2.cppm)
// against the closed segment; touching an edge or a vertex counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon2& g, const segment2& s) {
    if (!polygon2d::well_formed(g) || !finite(s.a) || !finite(s.b)) return false;
    const point2 ends[2] = {s.a, s.b};
    const polygon2d::box2 xb = polygon2d::bounds(ends, 2);
    if (!polygon2d::boxes_meet(polygon2d::bounds(g), xb)) return false;
    return polygon2d::polygon_meets(k, g, [&](const segment2& e) { return intersects(k, e, s); }, s.a, &xb);
}

// polygon2 against polygon2.
// Semantics: both polygons' sets (edges and the points of odd crossing parity,
// shapes/polygon2.cppm); touching counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon2& a, const polygon2& b) {
    if (!polygon2d::well_formed(a) || !polygon2d::well_formed(b) || !polygon2d::boxes_meet(polygon2d::bounds(a), polygon2d::bounds(b)))
        return false;
    const polygon2d::box2 bb = polygon2d::bounds(b);
    const bool edges = polygon2d::any_edge(a, [&](point2 p, point2 q) {
        const point2 pq[2] = {p, q};
        const polygon2d::box2 eb = polygon2d::bounds(pq, 2);
        if (!polygon2d::boxes_meet(eb, bb)) return false;
        const segment2 e{p, q};
        return polygon2d::any_edge(b, [&](point2 r, point2 s) {
            const point2 rs[2] = {r, s};
            return polygon2d::boxes_meet(eb, polygon2d::bounds(rs, 2)) && intersects(k, e, segment2{r, s});
        });
    });
    return edges || polygon2d::inside(k, b, a.vertices[0]) || polygon2d::inside(k, a, b.vertices[0]);
}

// polygon2 against ray2.
// Semantics: the polygon's edges and the points of odd crossing parity (shapes/polygon2.cppm)
// against the closed ray; touching an edge or a vertex counts; a zero direction is the point
// `origin`.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon2& g, const ray2& r) {
    if (!polygon2d::well_formed(g) || !finite(r.origin) || !finite(r.direction)) return false;
    return polygon2d::polygon_meets(k, g, [&](const segment2& e) { return intersects(k, r, e); }, r.origin);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const point2&, const polygon2&);
extern template bool exactly<intersects_body>(const line2&, const polygon2&);
extern template bool exactly<intersects_body>(const polygon2&, const segment2&);
extern template bool exactly<intersects_body>(const polygon2&, const polygon2&);
extern template bool exactly<intersects_body>(const polygon2&, const ray2&);
} // namespace incidence::detail
