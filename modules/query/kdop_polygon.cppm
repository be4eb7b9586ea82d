// kdop<K> against polygon3.
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set) and the polygon's
// point set (shapes/polygon3.cppm). Touching counts.
// Method (exact tiers): the k-DOP is its K half-spaces (kdop_plane.cppm: integer directions, so
// exact), and the pair is the test of a polygon against a half-space set
// (convex_polyhedron_polygon.cppm).
// Source: Klosowski et al., IEEE TVCG 4(1), 1998, section 4 (the directions); the
// boundary-plus-inside decomposition of point_polygon.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/kdop_polygon.cpp).
export module incidence.query:kdop_polygon;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :kdop_point;
import :kdop_plane;
import :convex_polyhedron_polygon;

export namespace incidence::pair {

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const polygon3& g) {
    if (!kdopq::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdopq::halfspaces(b);
    return polyq::polygon_meets(k, g, rows.data(), N);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const polygon3&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const polygon3&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const polygon3&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const polygon3&);
} // namespace incidence::pair
