// contains: polygon_pairs
module;
#include <cstddef>
#include <type_traits>
#include <utility>
export module incidence.detail:contains.polygon_pairs;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :intersects.triangle_pairs;
import :intersects.linear_pairs;
import :engines.polygon2;
import :engines.polygon3;
import :intersects.polygon2_pairs;
import :intersects.polygon_pairs;
import :contains.polygon2_pairs;
import :exactly;

export namespace incidence::detail {

// point3 against polygon3, contains(polygon3, point3), and the engine every 3D polygon pair shares.
// Semantics: the polygon's point set (shapes/polygon3.cppm): the points of its plane whose
// projection along its axis lies in the projected polygon2 (edges, and odd crossing parity).
// contains(polygon3, point3): the same set.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const polygon3& g, const point3& p) {
    return intersects(k, p, g);
}

// polygon3 against segment3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed segment (equal ends: a
// point). Touching an edge or a vertex counts.

// contains(polygon, segment): both ends in the polygon's plane, and the projected segment in the
// projected polygon.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const polygon3& g, const segment3& s) {
    if (!finite(s.a) || !finite(s.b) || !polygon3d::usable(k, g)) return false;
    if (polygon3d::side(k, g, s.a) != sign::zero || polygon3d::side(k, g, s.b) != sign::zero) return false;
    const point2 a = g.projected(s.a), b = g.projected(s.b);
    if (a.x == b.x && a.y == b.y) return contains(k, g, s.a);
    return polygon2d::segment_inside(k, polygon3d::projected_edges(g), a, b);
}

// polygon3 against triangle3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed solid triangle
// (collinear corners: the segments between them). Touching counts.

// contains(polygon, triangle): see the top of the file.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const polygon3& g, const triangle3& t) {
    if (!finite(t.a) || !finite(t.b) || !finite(t.c) || !polygon3d::usable(k, g)) return false;
    if (!contains(k, g, segment3{t.a, t.b}) || !contains(k, g, segment3{t.b, t.c}) || !contains(k, g, segment3{t.c, t.a})) return false;
    const point2 a = g.projected(t.a), b = g.projected(t.b), c = g.projected(t.c);
    const sign o = k.sgn([=](auto L) { return poly::orient2d(L, a, b, c); });
    if (o == sign::zero) return true; // collinear: the union of its edges
    const point2 corners[3] = {a, b, c};
    const polygon2d::box2 tb = polygon2d::bounds(corners, 3);
    const auto edges = polygon3d::projected_edges(g);
    if (edges([&](point2 p, point2 q) {
            const point2 v[2] = {p, q};
            return polygon2d::boxes_meet(polygon2d::bounds(v, 2), tb) && polygon2d::meets_open_triangle(k, a, b, c, o, p, q);
        }))
        return false;
    return polygon2d::inside_weighted(k, edges, polygon2d::centroid2{a, b, c});
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const polygon3&, const point3&);
extern template bool exactly<contains_body>(const polygon3&, const segment3&);
extern template bool exactly<contains_body>(const polygon3&, const triangle3&);
} // namespace incidence::detail
