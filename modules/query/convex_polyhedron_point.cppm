// convex_polyhedron3 against point3, contains(convex_polyhedron3, point3), and the generalised
// slab test every half-space pair shares (convex_polyhedron_segment, _ray, _line, and the frustum
// pairs, whose six planes are one such set).
// Semantics: the closed set { p : n_i . p <= c_i } (shapes/convex_polyhedron3.cppm), possibly
// empty or unbounded; a non-finite number or a count outside [0, capacity] makes no set: every
// query says no. A point on a face, an edge or a vertex counts.
// Method (exact tiers): the generalised slab method (Kay and Kajiya, SIGGRAPH 1986; Cyrus and
// Beck, Computers & Graphics 3(1), 1978, for clipping against any convex polyhedron) with its
// comparisons of quotients rewritten as signs of products. The object o + t u (t >= 0 for a ray,
// t in [0, 1] with u = e - o for a segment, every t for a line, u = 0 for a point) lies in
// half-space i for t <= (c_i - a_i) / b_i when b_i > 0 and t >= (c_i - a_i) / b_i when b_i < 0,
// where a_i = n_i . o, b_i = n_i . u; with b_i = 0 the origin must lie in it (a_i <= c_i). The
// sets meet iff every lower bound is <= every upper bound, sign((c_i - a_i) b_j - (c_j - a_j) b_i)
// >= 0 for every lower i and upper j, and the upper bounds lie at t >= 0 (ray, segment:
// c_j - a_j >= 0) and the lower ones at t <= 1 (segment: c_i - n_i . e >= 0). Every sign is a
// polynomial of degree <= 4 in the inputs, no quotient is rounded; each offset is multiplied by
// a lifted 1 so every polynomial is homogeneous (degree 2 or 4), which lets the exact fallback
// use expansions instead of big integers.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_point.cpp).
module;
#include <array>
export module incidence.query:convex_polyhedron_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :aabb_ray;

export namespace incidence::pair {

namespace polyq {

// Every plane finite (a zero normal is a half-space too: all of space or nothing).
[[nodiscard]] constexpr bool well_formed(const plane3* planes, int m, int capacity) {
    if (m < 0 || m > capacity) return false;
    for (int i = 0; i < m; ++i)
        if (!finite(planes[i].normal) || !finite(planes[i].offset)) return false;
    return true;
}

// The generalised slab test for o + t u (X: ray, segment with end point e, or line) against the
// m <= capacity half-spaces n_i . x <= c_i: one instantiation per kernel and extent.
template <slab_extent X, class K>
[[nodiscard]] constexpr bool halfspaces(K& k, const plane3* planes, int m, point3 o, vec3 u, point3 e) {
    constexpr int capacity = convex_polyhedron3::capacity;
    if (!well_formed(planes, m, capacity) || !finite(o) || !finite(u) || !finite(e)) return false;
    std::array<sign, capacity> s{}; // the sign of b_i: which bound half-space i gives
    for (int i = 0; i < m; ++i) {
        const auto ui = static_cast<unsigned>(i);
        const vec3 n = planes[i].normal;
        const double c = planes[i].offset;
        // no movement across the plane when every coordinate n reads stays put (comparisons: a
        // point, a zero direction, a zero normal, an axis-parallel object), else the sign of n . u
        const bool still = X == slab_extent::segment
                               ? (n.x == 0.0 || e.x == o.x) && (n.y == 0.0 || e.y == o.y) && (n.z == 0.0 || e.z == o.z)
                               : (n.x == 0.0 || u.x == 0.0) && (n.y == 0.0 || u.y == 0.0) && (n.z == 0.0 || u.z == 0.0);
        if (still) s[ui] = sign::zero;
        else if constexpr (X == slab_extent::segment)
            s[ui] = k.sgn([=](auto L) { return arith::dot(arith::lift(L, n), arith::lift(L, e) - arith::lift(L, o)); });
        else s[ui] = k.sgn([=](auto L) { return arith::dot(arith::lift(L, n), arith::lift(L, u)); });
        // c - n . o: the origin's side (needed when parallel, or for an upper bound at t >= 0)
        auto inside_at_origin = [&] { return k.sgn([=](auto L) { return L(c) * L(1.0) - arith::dot(arith::lift(L, n), arith::lift(L, o)); }); };
        if (s[ui] == sign::zero) {
            if (inside_at_origin() == sign::negative) return false;
            continue;
        }
        if constexpr (X != slab_extent::line) // an upper bound (c - a) / b >= 0: the half-space is not behind the origin
            if (s[ui] == sign::positive && inside_at_origin() == sign::negative) return false;
        if constexpr (X == slab_extent::segment) // a lower bound (c - a) / b <= 1: the end point lies in the half-space
            if (s[ui] == sign::negative &&
                k.sgn([=](auto L) { return L(c) * L(1.0) - arith::dot(arith::lift(L, n), arith::lift(L, e)); }) == sign::negative)
                return false;
    }
    for (int i = 0; i < m; ++i) {
        if (s[static_cast<unsigned>(i)] != sign::negative) continue;
        for (int j = 0; j < m; ++j) {
            if (s[static_cast<unsigned>(j)] != sign::positive) continue;
            // lower bound i <= upper bound j: (c_i - a_i) b_j - (c_j - a_j) b_i >= 0
            const plane3 pi = planes[i], pj = planes[j];
            const sign v = k.sgn([=](auto L) {
                const auto O = arith::lift(L, o);
                const auto ni = arith::lift(L, pi.normal), nj = arith::lift(L, pj.normal);
                const auto U = [&] {
                    if constexpr (X == slab_extent::segment) return arith::lift(L, e) - O;
                    else return arith::lift(L, u);
                }();
                const auto one = L(1.0);
                return (L(pi.offset) * one - arith::dot(ni, O)) * arith::dot(nj, U) - (L(pj.offset) * one - arith::dot(nj, O)) * arith::dot(ni, U);
            });
            if (v == sign::negative) return false;
        }
    }
    return true;
}
template <slab_extent X, class K>
[[nodiscard]] constexpr bool halfspaces(K& k, const convex_polyhedron3& c, point3 o, vec3 u, point3 e) {
    return halfspaces<X>(k, c.planes.data(), c.count, o, u, e);
}

} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const point3& p) {
    return polyq::halfspaces<slab_extent::segment>(k, c, p, vec3{0, 0, 0}, p);
}
// contains(convex_polyhedron3, point): the same set.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const point3& p) { return intersects(k, c, p); }

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const point3&);
extern template bool contains(arith::exact_kernel&, const convex_polyhedron3&, const point3&);
} // namespace incidence::pair
