// mesh3 against plane3 (n . p = offset; a zero normal is everything (offset 0) or nothing).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.
// Method (exact tiers): the signs of n . v - offset at every vertex (degree 2): the solid lies in the hull
// of its vertices and its surface contains them, so it meets the plane iff they are not all
// strictly positive or all strictly negative.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.2.3 (a plane against a
// polytope by the signed distances of its vertices), as signs.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/mesh_plane.cpp).
module;
#include <cstddef>
#include <span>
export module incidence.query:mesh_plane;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :mesh_point;
import :aabb_plane;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const plane3& pl) {
    if (!meshq::well_formed(m)) return false;
    // Every vertex is read, so a NaN or infinite plane gives no in the exact tier.
    bool pos = false, neg = false, zero = false;
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
        const sign s = plane_side(k, pl, m.vertices[i]);
        pos = pos || s == sign::positive;
        neg = neg || s == sign::negative;
        zero = zero || s == sign::zero;
    }
    return zero || (pos && neg);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const mesh3&, const plane3&);
} // namespace incidence::pair
