// convex_polyhedron3 against triangle3, contains(convex_polyhedron3, triangle3), and the test of a
// triangle against a half-space set that frustum_triangle and kdop_triangle share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed solid
// triangle (collinear corners: the segments between them; a non-finite corner: no triangle).
// Touching at a vertex, an edge or a face counts. contains: the three corners in the set (convex).
// Method (exact tiers): the set P meets the plane H of the triangle in a convex polygon Q. The
// triangle meets P iff one of its edges meets P (the generalised slab test of
// convex_polyhedron_segment.cppm) or Q lies inside the triangle; Q is then bounded and not empty,
// so it has a vertex, where two planes of P whose normals are independent of the triangle normal
// n = (b - a) x (c - a) cross H: v = V / D with D = det(n_i, n_j, n) and
// V = c_i n_j x n + c_j n x n_i + (n . a) n_i x n_j. Such a v is tested in every half-space,
// sign(c_l D - n_l . V) zero or sign(D) (degree 6), and in the triangle, sign(((q - p) x (V - p D))
// . n) zero or sign(D) for its edges p q in turn (degree 8); each offset times a lifted 1, so every
// sign is homogeneous. A filter-proven violated half-space skips a pair before any sign is decided.
// The first vertex of Q found decides: Q is connected and misses the triangle's edges, so it lies
// inside the triangle or apart from it.
// First, a plane of P with the three corners beyond it says no.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5 (a nonempty
// pointed polyhedron has a vertex, where rank-many constraints are tight); Cyrus and Beck,
// Computers & Graphics 3(1), 1978, for the edges.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_triangle.cpp).
module;
#include <array>
#include <cstddef>
export module incidence.query:convex_polyhedron_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_ray;
import :point_tetrahedron;
import :convex_polyhedron_point;
import :aabb_convex_polyhedron;

export namespace incidence::pair {

namespace polyq {

// One of the m planes with the n points point(0), ..., point(n - 1) all proven beyond it (by the
// filter's probe, no exact sign): their hull misses the set.
template <class K, class Points>
[[nodiscard]] constexpr bool beyond_one_plane(K& k, const plane3* planes, int m, const Points& point, std::size_t n) {
    for (int i = 0; i < m; ++i) {
        const plane3 h = planes[i];
        bool beyond = true;
        for (std::size_t v = 0; v < n && beyond; ++v) {
            const point3 x = point(v);
            beyond = arith::probe(k, [=](auto L) { return L(h.offset) * L(1.0) - arith::dot(arith::lift(L, h.normal), arith::lift(L, x)); }) ==
                     sign::negative;
        }
        if (beyond) return true;
    }
    return false;
}

// Whether the section Q of the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i by the
// plane of the finite triangle t meets t, where the caller found that t's edges miss the set.
template <class K>
[[nodiscard]] constexpr bool section_meets(K& k, const triangle3& t, const plane3* planes, int m) {
    constexpr int capacity = convex_polyhedron3::capacity;
    const point3 corner[3] = {t.a, t.b, t.c};
    // a degenerate triangle is its edges
    auto normal = [=](auto L) { return arith::cross(arith::lift(L, t.b) - arith::lift(L, t.a), arith::lift(L, t.c) - arith::lift(L, t.a)); };
    if (settled(k, [=](auto L) { return normal(L).x; }) == sign::zero && settled(k, [=](auto L) { return normal(L).y; }) == sign::zero &&
        settled(k, [=](auto L) { return normal(L).z; }) == sign::zero)
        return false;
    // the vertices of Q: planes i and j of P crossing H at v = V / D
    auto parallel = [planes](int x, int y) {
        const vec3 a = planes[x].normal, c = planes[y].normal;
        return (a.x == 0 && a.y == 0 && a.z == 0) || (c.x == 0 && c.y == 0 && c.z == 0) || (a.x == c.x && a.y == c.y && a.z == c.z) ||
               (a.x == -c.x && a.y == -c.y && a.z == -c.z);
    };
    std::array<sign, capacity> s{};
    for (int i = 0; i < m; ++i) {
        for (int j = i + 1; j < m; ++j) {
            if (parallel(i, j)) continue;
            const plane3 pi = planes[i], pj = planes[j];
            auto D = [=](auto L) { return arith::det3(arith::lift(L, pi.normal), arith::lift(L, pj.normal), normal(L)); };
            auto V = [=](auto L) {
                const auto n = normal(L);
                const auto ni = arith::lift(L, pi.normal), nj = arith::lift(L, pj.normal);
                const auto one = L(1.0);
                const auto ci = L(pi.offset) * one, cj = L(pj.offset) * one;
                const auto h = arith::dot(n, arith::lift(L, t.a));
                const auto x = arith::cross(nj, n), y = arith::cross(n, ni);
                const auto z = arith::cross(ni, nj);
                using T = decltype(ci * x.x + cj * y.x + h * z.x);
                return arith::v3<T>{ci * x.x + cj * y.x + h * z.x, ci * x.y + cj * y.y + h * z.y, ci * x.z + cj * y.z + h * z.z};
            };
            const sign d = settled(k, D);
            if (d == sign::zero) continue; // no single point
            // D and V lifted into the filter once for all the conditions of this pair
            const arith::lifted_once<K, decltype(D)> Dl{D};
            const arith::lifted_once<K, decltype(V)> Vl{V};
            // condition r < m: v in half-space r (c_r D - n_r . V); r = m + e: v on the inner side
            // of the triangle's edge e, from corner e to e + 1 (((q - p) x (V - p D)) . n)
            auto in_plane = [=, &Dl, &Vl](int r) {
                const plane3 h = planes[r];
                return [=, &Dl, &Vl](auto L) { return L(h.offset) * L(1.0) * Dl(L) - arith::dot(arith::lift(L, h.normal), Vl(L)); };
            };
            auto in_edge = [=, &Dl, &Vl](int e) {
                const point3 p = corner[e], q = corner[(e + 1) % 3];
                return [=, &Dl, &Vl](auto L) {
                    const auto P = arith::lift(L, p);
                    const auto d = Dl(L);
                    const auto v = Vl(L);
                    using T = decltype(v.x - P.x * d);
                    const arith::v3<T> w{v.x - P.x * d, v.y - P.y * d, v.z - P.z * d};
                    return arith::dot(arith::cross(arith::lift(L, q) - P, w), normal(L));
                };
            };
            // settled: a third plane through the point, or an ulp off it, is common (see first_row_vertex)
            auto decided = [&](int r) { return r < m ? settled(k, in_plane(r)) : settled(k, in_edge(r - m)); };
            // a half-space proven violated skips the pair; the proven ones are kept
            bool out = false;
            for (int r = 0; r < m && !out; ++r) {
                if (r == i || r == j) continue;
                s[static_cast<unsigned>(r)] = arith::probe(k, in_plane(r));
                out = s[static_cast<unsigned>(r)] == -d;
            }
            if (out) continue;
            bool inside = true;
            for (int r = 0; r < m && inside; ++r) {
                if (r == i || r == j || s[static_cast<unsigned>(r)] == d) continue;
                const sign x = decided(r);
                inside = x == sign::zero || x == d;
            }
            if (!inside) continue;
            // v is a vertex of Q, and the edges miss P, so Q lies inside the triangle or apart from
            // it (Q is connected and does not meet the triangle's boundary): v decides
            for (int r = m; r < m + 3; ++r)
                if (const sign x = decided(r); x != sign::zero && x != d) return false;
            return true;
        }
    }
    return false;
}

// Does the solid triangle t meet the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i?
template <class K>
[[nodiscard]] constexpr bool triangle_meets(K& k, const triangle3& t, const plane3* planes, int m) {
    if (!well_formed(planes, m, convex_polyhedron3::capacity) || !finite(t)) return false;
    const point3 corner[3] = {t.a, t.b, t.c};
    if (beyond_one_plane(k, planes, m, [&](std::size_t v) { return corner[v]; }, 3)) return false;
    // the edges
    for (int v = 0; v < 3; ++v)
        if (halfspaces<slab_extent::segment>(k, planes, m, corner[v], vec3{0, 0, 0}, corner[(v + 1) % 3])) return true;
    return section_meets(k, t, planes, m);
}

} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const triangle3& t) {
    return polyq::triangle_meets(k, t, c.planes.data(), c.count);
}
// contains(convex_polyhedron3, triangle3): the three corners in the set (every corner read, so a
// NaN corner gives no in the exact tier).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const triangle3& t) {
    const bool a = intersects(k, c, t.a);
    const bool b = intersects(k, c, t.b);
    const bool e = intersects(k, c, t.c);
    return a && b && e;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const triangle3&);
extern template bool contains(arith::exact_kernel&, const convex_polyhedron3&, const triangle3&);
} // namespace incidence::pair
