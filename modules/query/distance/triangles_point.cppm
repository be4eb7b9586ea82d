// distance: point3 and tetrahedron3, mesh3 and point3: the squared distance and the signed
// distance from a point to a solid bounded by triangles.
// Semantics: the closed solid tetrahedron (coplanar vertices give their hull) and the solid mesh
// (shapes/mesh3.cppm: its triangles and the points of odd crossing parity). signed_distance: the
// distance to the surface, negative inside the solid, zero on it; squared_distance: the square of
// the positive part (zero inside). A NaN or an infinite number, or a mesh that is not well formed
// (an index out of range, no triangle): NaN.
// Method (exact tiers): the surface's feature nearest p over the four faces (the mesh's triangles),
// by Ericson's region walk on each and exact comparisons of the candidates
// (engines/nearest_feature.cppm: signs of degree <= 4 in a triangle, 10 between two), its squared
// distance P / S; inside or outside by the pair's own point test (engines/tetrahedron.cppm,
// orient3d signs of degree 3; engines/mesh.cppm, crossing parity); then sqrt(P / S) or
// -sqrt(P / S), roots of S t^2 - P, correctly rounded; P = 0 (p on the surface) gives 0 exactly.
// The nearest point of a convex solid from outside, and of any solid's boundary, lies on a face,
// so one walk serves both sides. A mesh costs a walk per triangle (no hierarchy).
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.5 (closest point on a
// triangle) and 5.1.6 (on a tetrahedron: the nearest of its faces).
// Approximate tier: the same walk and roots in plain double (candidates compared by their
// quotients' values). Error bound: where no deciding sign lies within 2^-40 of its permanent (the yes/no
// pairs' measure: the active set or feature is then plain double's too), for inputs whose nonzero
// magnitudes lie in [2^-120, 2^120], |d~ - d| <= 2^-40 M + 2^-140 for the signed distance and 2^-40 M^2 + 2^-280 for the squared one, M
// the largest magnitude among the inputs' numbers (a row's |d_i| / max |n_i|); the absolute terms
// cover numerators that underflow where nearly equal inputs differ by ulps (tests/query/distance/triangles_point.cpp,
// testkit/distance_checks.hpp).
module;
#include <cstddef>
export module incidence.detail:distance.triangles_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.nearest_feature;
import :engines.tetrahedron;
import :engines.mesh;
import :exactly;

export namespace incidence::detail {

namespace triangles_distance {

// From the nearest feature x and the side: the signed (or squared) distance.
template <class K>
[[nodiscard]] constexpr arith::value_t<K> from(K& k, const nearest::feature& x, point3 p, bool inside, bool squared) {
    if (squared && inside) return arith::exact_value(k, 0.0);
    if (nearest::distance_sign(k, x, p) == sign::zero) return arith::exact_value(k, 0.0);
    return nearest::with_distance(x, p, [&](auto q) -> arith::value_t<K> {
        if (squared) return arith::value(k, q);
        return nearest::root_distance(k, q, inside);
    });
}

template <class K>
[[nodiscard]] constexpr arith::value_t<K> of(K& k, const tetrahedron3& t, point3 p, bool squared) {
    if (!is_finite(p) || !finite(t)) return arith::exact_value(k, __builtin_nan(""));
    const point3 pts[1] = {p};
    const bool inside = tetra::contains_all(k, t, pts, 1);
    const nearest::feature x = nearest::of_triangles(k, p, 4, [&](std::size_t i) { return t.face(static_cast<int>(i)); });
    return from(k, x, p, inside, squared);
}

template <class K>
[[nodiscard]] constexpr arith::value_t<K> of(K& k, const mesh3& m, point3 p, bool squared) {
    if (!is_finite(p) || !solid_mesh::well_formed(m)) return arith::exact_value(k, __builtin_nan(""));
    const bool inside = solid_mesh::inside(k, m, p);
    const nearest::feature x = nearest::of_triangles(k, p, m.triangles.size(), [&](std::size_t i) { return m.triangle(i); });
    return from(k, x, p, inside, squared);
}

} // namespace triangles_distance

template <class K>
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const point3& p, const tetrahedron3& t) {
    return triangles_distance::of(k, t, p, true);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> signed_distance(K& k, const point3& p, const tetrahedron3& t) {
    return triangles_distance::of(k, t, p, false);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> squared_distance(K& k, const mesh3& m, const point3& p) {
    return triangles_distance::of(k, m, p, true);
}
template <class K>
[[nodiscard]] constexpr arith::value_t<K> signed_distance(K& k, const mesh3& m, const point3& p) {
    return triangles_distance::of(k, m, p, false);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template double exactly<nearest_body>(const point3&, const tetrahedron3&);
extern template double exactly<signed_body>(const point3&, const tetrahedron3&);
extern template double exactly<nearest_body>(const mesh3&, const point3&);
extern template double exactly<signed_body>(const mesh3&, const point3&);
} // namespace incidence::detail
