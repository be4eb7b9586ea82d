// polygon3 against triangle3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed solid triangle
// (collinear corners: the segments between them). Touching counts.
// Method (exact tiers): an edge of the polygon meets the triangle (segment_triangle.cppm), or an
// edge of the triangle crosses the polygon inside (planeq::crossing_inside: a triangle edge
// through a polygon edge was found by the first test). Complete: where the two meet and
// no polygon edge touches the triangle, the triangle's section by the polygon's plane (a segment,
// or the triangle itself when coplanar) lies inside the polygon, and its ends are on the
// triangle's edges.
// contains: the corners in the polygon's plane, then in the projection: the triangle's three
// edges in the polygon (polygon_segment.cppm), no polygon edge meeting the open triangle (its
// points strictly inside all three edge lines: separating lines along the triangle's edges or the
// edge's own line, orient2d signs of degree 2), and the centroid (a + b + c) / 3 inside by crossing
// parity (weight L(1) + L(1) + L(1); in a filter pass the rounded centroid within a proven radius
// first, point2_polygon2's rounded_parity). Then no boundary crosses the open triangle, which lies wholly
// inside or outside, and its centroid decides (a hole exactly the triangle has every edge in the
// set). A collinear triangle is the union of its edges.
// Source: the boundary-plus-inside decomposition of point_polygon.cppm; Moeller, "A fast
// triangle-triangle intersection test", JGT 2(2), 1997 (edges against faces).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/polygon_triangle.cpp).
module;
#include <utility>
export module incidence.query:polygon_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :segment_triangle;
import :point_polygon;
import :point2_polygon2;
import :polygon2_segment2;
import :polygon_segment;
import incidence.predicates;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& g, const triangle3& t) {
    if (!finite(t.a) || !finite(t.b) || !finite(t.c) || !planeq::usable(k, g)) return false;
    if (planeq::any_edge(g, [&](const segment3& e) { return intersects(k, e, t); })) return true;
    return planeq::crossing_inside(k, g, as_linear(segment3{t.a, t.b})) || planeq::crossing_inside(k, g, as_linear(segment3{t.b, t.c})) ||
           planeq::crossing_inside(k, g, as_linear(segment3{t.c, t.a}));
}

namespace polyq {
// The centroid (a + b + c) / 3, V / W with W = L(1) + L(1) + L(1).
struct centroid2 {
    point2 a, b, c;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto A = arith::lift(lift, a), B = arith::lift(lift, b), C = arith::lift(lift, c);
        const auto one = lift(1.0);
        return std::pair{arith::v2<decltype(A.x + B.x + C.x)>{A.x + B.x + C.x, A.y + B.y + C.y}, one + one + one};
    }
    // In double, each coordinate within its radius (for rounded_parity): two sums off by at most
    // 2u (|a| + |b| + |c|) together, a third of that after the division, which adds u |p| (u = 2^-53).
    [[nodiscard]] constexpr bool rounded(double& px, double& py, double& rx, double& ry) const {
        px = (a.x + b.x + c.x) / 3.0, py = (a.y + b.y + c.y) / 3.0;
        rx = 0x1p-51 * (arith::abs(a.x) + arith::abs(b.x) + arith::abs(c.x)) * 1.125 + 0x1p-1000;
        ry = 0x1p-51 * (arith::abs(a.y) + arith::abs(b.y) + arith::abs(c.y)) * 1.125 + 0x1p-1000;
        return true;
    }
};
// Does the segment p q meet the open triangle a b c (o = orient2d(a, b, c), not zero)?
template <class K>
[[nodiscard]] constexpr bool meets_open_triangle(K& k, point2 a, point2 b, point2 c, sign o, point2 p, point2 q) {
    auto orient = [&](point2 x, point2 y, point2 z) { return k.sgn([=](auto L) { return poly::orient2d(L, x, y, z); }); };
    auto beyond = [&](point2 x, point2 y) { return orient(x, y, p) != o && orient(x, y, q) != o; }; // p and q on the closed outer side
    if (beyond(a, b) || beyond(b, c) || beyond(c, a)) return false;
    const sign sa = orient(p, q, a), sb = orient(p, q, b), sc = orient(p, q, c);
    const bool pos = sa == sign::positive || sb == sign::positive || sc == sign::positive;
    const bool neg = sa == sign::negative || sb == sign::negative || sc == sign::negative;
    return pos && neg; // else the triangle lies on one closed side of the segment's line
}
} // namespace polyq

// contains(polygon, triangle): see the top of the file.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const polygon3& g, const triangle3& t) {
    if (!finite(t.a) || !finite(t.b) || !finite(t.c) || !planeq::usable(k, g)) return false;
    if (!contains(k, g, segment3{t.a, t.b}) || !contains(k, g, segment3{t.b, t.c}) || !contains(k, g, segment3{t.c, t.a})) return false;
    const point2 a = g.projected(t.a), b = g.projected(t.b), c = g.projected(t.c);
    const sign o = k.sgn([=](auto L) { return poly::orient2d(L, a, b, c); });
    if (o == sign::zero) return true; // collinear: the union of its edges
    const point2 corners[3] = {a, b, c};
    const polyq::box2 tb = polyq::bounds(corners, 3);
    const auto edges = planeq::projected_edges(g);
    if (edges([&](point2 p, point2 q) {
            const point2 v[2] = {p, q};
            return polyq::boxes_meet(polyq::bounds(v, 2), tb) && polyq::meets_open_triangle(k, a, b, c, o, p, q);
        }))
        return false;
    return polyq::inside_weighted(k, edges, polyq::centroid2{a, b, c});
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const polygon3&, const triangle3&);
extern template bool contains(arith::exact_kernel&, const polygon3&, const triangle3&);
} // namespace incidence::pair
