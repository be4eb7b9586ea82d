// polygon3 against tetrahedron3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed solid tetrahedron
// (coplanar vertices: their hull). Touching counts.
// Method (exact tiers): an edge of the polygon meets the tetrahedron (segment_tetrahedron.cppm),
// or one of its six edges crosses the polygon inside (planeq::crossing_inside: an edge through a
// polygon edge was found by the first test). Complete: where they meet and no polygon edge
// touches the solid, its section by the polygon's plane lies inside the polygon,
// and the section's corners lie on the solid's edges.
// Source: the boundary-plus-inside decomposition of point_polygon.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/polygon_tetrahedron.cpp).
export module incidence.query:polygon_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :segment_tetrahedron;
import :point_polygon;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& g, const tetrahedron3& t) {
    if (!finite(t.a) || !finite(t.b) || !finite(t.c) || !finite(t.d) || !planeq::usable(k, g)) return false;
    if (planeq::any_edge(g, [&](const segment3& e) { return intersects(k, e, t); })) return true;
    const point3 v[4] = {t.a, t.b, t.c, t.d};
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            if (planeq::crossing_inside(k, g, as_linear(segment3{v[i], v[j]}))) return true;
    return false;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const polygon3&, const tetrahedron3&);
} // namespace incidence::pair
