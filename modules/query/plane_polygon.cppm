// plane3 against polygon3.
// Semantics: the plane n . x = offset (a zero normal: all of space for a zero offset, else
// nothing) and the polygon's point set (shapes/polygon3.cppm). Touching counts.
// Method (exact tiers): a plane meets a bounded planar region iff it meets its boundary, so iff
// some vertex lies on the plane or two vertices of one ring (a closed curve) lie on opposite
// sides: sign(n . v - offset) per vertex, degree 2. (Two rings apart, one on each side, are two
// pieces the plane passes between.)
// Source: the vertex-sign test of a polygon against a plane (Ericson, Real-Time Collision
// Detection, 2005, section 5.2.3, for a triangle).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/plane_polygon.cpp).
module;
#include <cstddef>
export module incidence.query:plane_polygon;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :point_polygon;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const polygon3& g) {
    if (!finite(pl.normal) || !finite(pl.offset) || !planeq::usable(k, g)) return false;
    for (std::size_t r = 0; r < g.rings(); ++r) {
        bool below = false, above = false;
        for (std::size_t i = g.ring_begin(r); i < g.ring_end(r); ++i) {
            const point3 v = g.vertices[i];
            const sign s = k.sgn([=](auto L) { return arith::dot(arith::lift(L, pl.normal), arith::lift(L, v)) - L(pl.offset) * L(1.0); });
            if (s == sign::zero) return true;
            (s == sign::positive ? above : below) = true;
            if (above && below) return true;
        }
    }
    return false;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const plane3&, const polygon3&);
} // namespace incidence::pair
