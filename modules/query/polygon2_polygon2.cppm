// polygon2 against polygon2.
// Semantics: both polygons' sets (edges and the points of odd crossing parity,
// shapes/polygon2.cppm); touching counts.
// Method (exact tiers): an edge of one meets an edge of the other (segment2_segment2's signs,
// degree <= 2; edge pairs whose bounding boxes miss are skipped), or else the boundaries are
// disjoint and the polygons meet iff a vertex of one lies inside the other (exact crossing
// parity, point2_polygon2.cppm). Both argument orders run the same tests.
// Source: Haines, "Point in polygon strategies", Graphics Gems IV (1994), the crossings test;
// O'Rourke, Computational Geometry in C, 2nd ed. (1998), section 1.5 for the edges.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-44 of its
// permanent (tests/query/polygon2_polygon2.cpp).
module;
#include <cstddef>
export module incidence.query:polygon2_polygon2;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :segment2_segment2;
import :point2_polygon2;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon2& a, const polygon2& b) {
    if (!polyq::well_formed(a) || !polyq::well_formed(b) || !polyq::boxes_meet(polyq::bounds(a), polyq::bounds(b))) return false;
    const polyq::box2 bb = polyq::bounds(b);
    const bool edges = polyq::any_edge(a, [&](point2 p, point2 q) {
        const point2 pq[2] = {p, q};
        const polyq::box2 eb = polyq::bounds(pq, 2);
        if (!polyq::boxes_meet(eb, bb)) return false;
        const segment2 e{p, q};
        return polyq::any_edge(b, [&](point2 r, point2 s) {
            const point2 rs[2] = {r, s};
            return polyq::boxes_meet(eb, polyq::bounds(rs, 2)) && intersects(k, e, segment2{r, s});
        });
    });
    return edges || polyq::inside(k, b, a.vertices[0]) || polyq::inside(k, a, b.vertices[0]);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const polygon2&, const polygon2&);
} // namespace incidence::pair
