// kdop<K> against plane3.
// Semantics: the closed k-DOP (an empty slab or a non-finite bound: no set, so no; slabs that are
// jointly empty: the empty set) and the plane n . x = offset (a zero normal is everything when the
// offset is 0 and nothing otherwise). Touching at a corner, an edge or a face counts.
// Method (exact tiers): the k-DOP is its K half-spaces d_i . x <= max_i and -d_i . x <= -min_i
// (integer directions: exact), so the pair is convex_polyhedron_plane's test: the k-DOP's vertices
// least and greatest along n proven on either side of the plane (or a Farkas certificate that
// nothing lies beyond), else a feasibility test of each side: signs of degree <= 5.
// Source: Klosowski et al., IEEE TVCG 4(1), 1998, section 4 (the directions); Schrijver, Theory
// of Linear and Integer Programming, 1986, sections 7.3 and 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/kdop_plane.cpp).
module;
#include <array>
export module incidence.query:kdop_plane;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :kdop_point;
import :convex_polyhedron_plane;

export namespace incidence::pair {

namespace kdopq {
// The k-DOP's K half-spaces d_i . x <= max_i and -d_i . x <= -min_i (integer directions: exact).
template <int N>
[[nodiscard]] constexpr std::array<plane3, N> halfspaces(const kdop<N>& b) {
    const auto d = kdop<N>::directions();
    std::array<plane3, N> rows{};
    for (unsigned i = 0; i < N / 2; ++i) {
        const vec3 n{double(d[i].x), double(d[i].y), double(d[i].z)};
        rows[2 * i] = plane3{n, b.max[i]};
        rows[2 * i + 1] = plane3{-n, -b.min[i]};
    }
    return rows;
}
} // namespace kdopq

template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const plane3& p) {
    if (!kdopq::well_formed(b.min.data(), b.max.data(), N / 2)) return false;
    const auto rows = kdopq::halfspaces(b);
    return polyq::plane_meets(k, rows.data(), N, p);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const kdop<6>&, const plane3&);
extern template bool intersects(arith::exact_kernel&, const kdop<14>&, const plane3&);
extern template bool intersects(arith::exact_kernel&, const kdop<18>&, const plane3&);
extern template bool intersects(arith::exact_kernel&, const kdop<26>&, const plane3&);
} // namespace incidence::pair
