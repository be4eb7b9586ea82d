// convex_polyhedron3 against polygon3, and the test of a polygon against a half-space set that
// frustum_polygon and kdop_polygon share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded) and the polygon's point set (shapes/polygon3.cppm). Touching counts.
// Method (exact tiers): an edge of the polygon meets the set (the generalised slab test of
// convex_polyhedron_segment.cppm), or else the set's section Q by the polygon's plane H lies
// wholly inside the polygon or outside it, and one vertex of Q decides: two planes of the set
// whose normals are independent of H's normal n cross H at v = V / D (D = det(n_i, n_j, n),
// V = c_i n_j x n + c_j n x n_i + (n . a) n_i x n_j, as in convex_polyhedron_triangle.cppm), the
// first such v in every half-space (degree 6) is tested by the homogeneous crossing test of
// point_polygon.cppm (degree <= 7); in a filter pass, first by planeq::rounded_inside (v in double
// within a proven radius from the filter's values of V and D). A Q that lies inside the polygon is bounded, so it has a
// vertex; an unbounded Q lies outside, and its vertex (if any) says so.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5; the
// boundary-plus-inside decomposition of point_polygon.cppm.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_polygon.cpp).
module;
#include <array>
export module incidence.query:convex_polyhedron_polygon;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :aabb_ray;
import :convex_polyhedron_point;
import :aabb_convex_polyhedron;
import :point_polygon;

export namespace incidence::pair {

namespace polyq {

// Does the polygon g meet the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i?
template <class K>
[[nodiscard]] constexpr bool polygon_meets(K& k, const polygon3& g, const plane3* planes, int m) {
    if (!well_formed(planes, m, convex_polyhedron3::capacity) || !planeq::usable(k, g)) return false;
    if (planeq::any_edge(g, [&](const segment3& e) { return halfspaces<slab_extent::segment>(k, planes, m, e.a, vec3{0, 0, 0}, e.b); }))
        return true;
    const point3 a = g.vertices[g.plane_vertices[0]];
    for (int i = 0; i < m; ++i) {
        for (int j = i + 1; j < m; ++j) {
            if (zero_normal(planes, static_cast<unsigned>(i)) || zero_normal(planes, static_cast<unsigned>(j)) ||
                parallel_normals(planes, static_cast<unsigned>(i), static_cast<unsigned>(j)))
                continue;
            const plane3 pi = planes[i], pj = planes[j];
            auto D = [=](auto L) { return arith::det3(arith::lift(L, pi.normal), arith::lift(L, pj.normal), planeq::normal(L, g)); };
            auto V = [=](auto L) {
                const auto n = planeq::normal(L, g);
                const auto ni = arith::lift(L, pi.normal), nj = arith::lift(L, pj.normal);
                const auto one = L(1.0);
                const auto ci = L(pi.offset) * one, cj = L(pj.offset) * one;
                const auto h = arith::dot(n, arith::lift(L, a));
                const auto x = arith::cross(nj, n), y = arith::cross(n, ni);
                const auto z = arith::cross(ni, nj);
                using T = decltype(ci * x.x + cj * y.x + h * z.x);
                return arith::v3<T>{ci * x.x + cj * y.x + h * z.x, ci * x.y + cj * y.y + h * z.y, ci * x.z + cj * y.z + h * z.z};
            };
            const sign d = settled(k, D);
            if (d == sign::zero) continue; // no single point
            // D and V lifted into the filter once for every condition
            const arith::lifted_once<K, decltype(D)> Dl{D};
            const arith::lifted_once<K, decltype(V)> Vl{V};
            auto in_plane = [=, &Dl, &Vl](int r) {
                const plane3 h = planes[r];
                return [=, &Dl, &Vl](auto L) { return L(h.offset) * L(1.0) * Dl(L) - arith::dot(arith::lift(L, h.normal), Vl(L)); };
            };
            bool out = false; // a condition the filter proves violated skips the pair
            for (int r = 0; r < m && !out; ++r)
                if (r != i && r != j) out = arith::probe(k, in_plane(r)) == -d;
            if (out) continue;
            bool in = true;
            for (int r = 0; r < m && in; ++r) {
                if (r == i || r == j) continue;
                const sign x = k.sgn(in_plane(r));
                in = x == sign::zero || x == d;
            }
            if (!in) continue;
            if (arith::rounded_stage_applies<K>())
                if (const int s = planeq::rounded_inside(g, Vl.kept, Dl.kept); s >= 0) return s == 1;
            return planeq::inside(k, g, planeq::at_homogeneous<decltype(V), decltype(D)>{V, D, d});
        }
    }
    return false;
}

} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const polygon3& g) {
    return polyq::polygon_meets(k, g, c.planes.data(), c.count);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const polygon3&);
} // namespace incidence::pair
