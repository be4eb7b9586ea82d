// aabb3 against polygon3.
// Semantics: the closed box (bounds ordered and finite; an inverted box is empty) and the
// polygon's point set (shapes/polygon3.cppm). Touching counts.
// Method (exact tiers): an edge of the polygon meets the box (aabb_segment.cppm), or one of the
// box's twelve edges crosses the polygon inside (planeq::crossing_inside: a box edge through a
// polygon edge was found by the first test). Complete: where they meet and no polygon edge
// touches the box, the box's section by the polygon's plane lies inside the polygon, and its
// corners lie on the box's edges.
// Source: the boundary-plus-inside decomposition of point_polygon.cppm; Kay and Kajiya, SIGGRAPH
// 1986 (the slabs).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/aabb_polygon.cpp).
export module incidence.query:aabb_polygon;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :aabb_ray;
import :aabb_segment;
import :aabb_tetrahedron;
import :point_polygon;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const polygon3& g) {
    if (!well_formed_finite(b) || !planeq::usable(k, g)) return false;
    if (planeq::any_edge(g, [&](const segment3& e) { return intersects(k, b, e); })) return true;
    const box_corners q(b);
    // corner m has bit i set for max along axis i: its edges go to m | 1 << i
    for (unsigned m = 0; m < 8; ++m)
        for (unsigned i = 0; i < 3; ++i)
            if ((m & (1u << i)) == 0 && planeq::crossing_inside(k, g, as_linear(segment3{q.p[m], q.p[m | (1u << i)]}))) return true;
    return false;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const polygon3&);
} // namespace incidence::pair
