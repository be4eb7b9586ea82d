// aabb3 against convex_polyhedron3, contains(convex_polyhedron3, aabb3), and the vertex test that
// the half-space pairs with a box share (aabb_frustum).
// Semantics: the closed box (bounds ordered and finite; an inverted box is empty) and the closed
// half-space set of convex_polyhedron_point.cppm (possibly empty or unbounded; a non-finite number
// or a count outside [0, capacity]: no set). Touching at a face, an edge or a vertex counts.
// contains(polyhedron, box): the eight corners in the set (it is convex).
// Method (exact tiers): the box is six more half-spaces, and the intersection of all of them is
// bounded, so when it is not empty it has a vertex: three of the planes, with independent normals,
// meet at a point v = V / D inside every half-space, where D = det(n_i, n_j, n_k) and
// V = c_i n_j x n_k + c_j n_k x n_i + c_k n_i x n_j; n_l . v <= c_l iff sign(c_l D - n_l . V) is
// zero or sign(D). The test tries every triple: homogeneous signs of degree 4, no division.
// First, a polyhedron plane with the whole box beyond it (the corner least along n_i outside, a
// sign of degree 2) says no.
// Source: vertex enumeration for LP feasibility (Schrijver, Theory of Linear and Integer
// Programming, 1986, section 8.5: a nonempty pointed polyhedron has a vertex).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/aabb_convex_polyhedron.cpp).
module;
#include <array>
export module incidence.query:aabb_convex_polyhedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_tetrahedron;
import :convex_polyhedron_point;

export namespace incidence::pair {

namespace polyq {

// Does the box meet the m half-spaces n_i . x <= c_i (m <= convex_polyhedron3::capacity)?
template <class K>
[[nodiscard]] constexpr bool box_meets(K& k, const aabb3& b, const plane3* planes, int m) {
    constexpr int capacity = convex_polyhedron3::capacity;
    if (!well_formed(planes, m, capacity) || !well_formed_finite(b)) return false;
    // A plane with the whole box beyond it: the box corner least along its normal is outside.
    for (int i = 0; i < m; ++i) {
        const plane3 p = planes[i];
        const point3 q{p.normal.x > 0 ? b.min.x : b.max.x, p.normal.y > 0 ? b.min.y : b.max.y, p.normal.z > 0 ? b.min.z : b.max.z};
        if (k.sgn([=](auto L) { return L(p.offset) * L(1.0) - arith::dot(arith::lift(L, p.normal), arith::lift(L, q)); }) == sign::negative)
            return false;
    }
    // The rows: the polyhedron's planes, then the box's six faces.
    std::array<plane3, capacity + 6> rows{};
    for (int i = 0; i < m; ++i) rows[static_cast<unsigned>(i)] = planes[i];
    const auto n = static_cast<unsigned>(m);
    rows[n + 0] = plane3{{1, 0, 0}, b.max.x};
    rows[n + 1] = plane3{{-1, 0, 0}, -b.min.x};
    rows[n + 2] = plane3{{0, 1, 0}, b.max.y};
    rows[n + 3] = plane3{{0, -1, 0}, -b.min.y};
    rows[n + 4] = plane3{{0, 0, 1}, b.max.z};
    rows[n + 5] = plane3{{0, 0, -1}, -b.min.z};
    const unsigned total = n + 6;
    // A zero normal, or two normals equal or opposite (the box's faces across one axis, a frustum's
    // near and far planes, a repeated plane): no single point, known without a sign (which the
    // filter could not prove zero).
    auto zero = [&rows](unsigned x) {
        const vec3 a = rows[x].normal;
        return a.x == 0 && a.y == 0 && a.z == 0;
    };
    auto parallel = [&rows](unsigned x, unsigned y) {
        const vec3 a = rows[x].normal, c = rows[y].normal;
        return (a.x == c.x && a.y == c.y && a.z == c.z) || (a.x == -c.x && a.y == -c.y && a.z == -c.z);
    };
    for (unsigned i = 0; i < total; ++i) {
        if (zero(i)) continue;
        for (unsigned j = i + 1; j < total; ++j) {
            if (zero(j) || parallel(i, j)) continue;
            for (unsigned l = j + 1; l < total; ++l) {
                if (zero(l) || parallel(i, l) || parallel(j, l)) continue;
                const plane3 a = rows[i], c = rows[j], e = rows[l];
                const sign d = k.sgn([=](auto L) { return arith::det3(arith::lift(L, a.normal), arith::lift(L, c.normal), arith::lift(L, e.normal)); });
                if (d == sign::zero) continue; // no single point
                bool vertex_inside = true;
                for (unsigned r = 0; r < total && vertex_inside; ++r) {
                    if (r == i || r == j || r == l) continue;
                    const plane3 h = rows[r];
                    const sign s = k.sgn([=](auto L) {
                        const auto na = arith::lift(L, a.normal), nc = arith::lift(L, c.normal), ne = arith::lift(L, e.normal);
                        const auto nh = arith::lift(L, h.normal);
                        // c_h D - n_h . V, with n_h . (n_j x n_k) = det(n_h, n_j, n_k)
                        return L(h.offset) * arith::det3(na, nc, ne) -
                               (L(a.offset) * arith::det3(nh, nc, ne) + L(c.offset) * arith::det3(nh, ne, na) + L(e.offset) * arith::det3(nh, na, nc));
                    });
                    vertex_inside = s == sign::zero || s == d;
                }
                if (vertex_inside) return true;
            }
        }
    }
    return false;
}

} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const convex_polyhedron3& c) {
    return polyq::box_meets(k, b, c.planes.data(), c.count);
}
// contains(convex_polyhedron3, aabb3): the eight corners in the set (every corner read, so a NaN
// bound gives no in the exact tier).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const aabb3& b) {
    if (!well_formed_finite(b)) return false;
    const box_corners q(b);
    bool all = true;
    for (const point3& p : q.p) all = intersects(k, c, p) && all;
    return all;
}

} // namespace incidence::pair
