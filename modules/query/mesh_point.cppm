// mesh3 against point3, contains(mesh, point), and the engine every mesh pair shares.
// Semantics: the mesh's point set is its triangles together with the points from which a ray
// crosses the surface an odd number of times (shapes/mesh3.cppm); a point on a triangle counts.
// Method (exact tiers): any other shape X (connected) meets that set iff it meets a triangle, or
// else lies wholly off the surface, where one point of X decides by the parity of crossings.
// The parity: the ray from p along u_j = (1, c_j, c_j^2), c_j = 0, 1, -1, 2, -2, ..., crosses a
// triangle's interior iff the three Pluecker signs u . ((a - p) x (b - p)), ... (degree 2) are
// all strictly of one sign s and the crossing lies ahead, det(a - p, b - p, c - p) of sign s
// (degree 3; their sum is u . n, so the crossing's parameter has the sign of both). A zero
// among signs that do not disagree is a ray through an edge or a vertex ahead, or in a
// triangle's plane: that direction is dropped and the next tried. Each edge plane, triangle plane
// and vertex direction rules out at most two values of c (u_j . w is a quadratic in c), so a
// clean direction comes within 8F + V + 8 tries; collinear triangles have no interior and are
// skipped. The vertices' bounding box answers first (outside it: outside), and along +x a
// triangle whose bounding box the ray misses is skipped.
// Source: Haines, "Point in polygon strategies", Graphics Gems IV (1994), the crossings test,
// in 3D with exact orientation signs; the perturbation by a moment curve of directions follows
// Edelsbrunner and Muecke, "Simulation of Simplicity", ACM TOG 9(1), 1990, section 4 (a generic
// choice from a one-parameter family instead of a symbolic one).
// Approximate tier: the same signs in plain double (a ray may pass through an edge undetected,
// so a point near the surface may get the wrong parity). Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/mesh_point.cpp).
module;
#include <array>
#include <cstddef>
#include <span>
export module incidence.query:mesh_point;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :segment_segment;
import :ray_triangle;

export namespace incidence::pair {

namespace meshq {

// Every index names a vertex and every vertex is finite (comparisons only).
[[nodiscard]] constexpr bool well_formed(const mesh3& m) {
    if (!m.indices_valid()) return false;
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
        if (!finite(m.vertices[i])) return false;
    return true;
}
// The vertices' bounding box (a well-formed mesh).
// The bounds of points and shapes, and their overlap (segment_segment.cppm), also under this name.
using pair::bounds;
using pair::boxes_meet;
[[nodiscard]] constexpr aabb3 bounds(const mesh3& m) { return bounds(m.vertices.data(), m.vertices.size()); }
[[nodiscard]] constexpr bool in_box(const aabb3& b, const point3& p) { return boxes_meet(b, bounds(p)); }

// The point whose parity is sought: a double point p (at_point) or a rational one, V / W with
// W > 0 (the homogeneous point of a caller). pl(L, x, y) has the sign of u . ((x - p) x (y - p)),
// ahead(L, a, b, c) that of det(a - p, b - p, c - p); near(box) is false only for a point known
// outside the box (comparisons), and along +x a triangle whose box the ray misses is skipped.
struct at_point {
    point3 p;
    template <class L>
    [[nodiscard]] constexpr auto pl(L lift, const vec3& u, const point3& x, const point3& y) const {
        const auto P = arith::lift(lift, p);
        return arith::dot(arith::lift(lift, u), arith::cross(arith::lift(lift, x) - P, arith::lift(lift, y) - P));
    }
    template <class L>
    [[nodiscard]] constexpr auto ahead(L lift, const point3& a, const point3& b, const point3& c) const {
        return poly::orient3d(lift, a, b, c, p); // det(a - p, b - p, c - p)
    }
    [[nodiscard]] constexpr bool near(const aabb3& b) const { return in_box(b, p); }
    [[nodiscard]] constexpr bool x_ray_misses(const aabb3& tb) const {
        return tb.max.x < p.x || p.y < tb.min.y || p.y > tb.max.y || p.z < tb.min.z || p.z > tb.max.z;
    }
};

// A rational point V / W as inside_at reads it, for any P whose weighted(L) gives {V, W} (W of
// either sign, nonzero): each parity sign is taken times W, u . (W (x x y) + (y - x) x V) and
// n . (W a - V) for a triangle a b c of normal n. W's sign flips all of them together, which
// leaves the decisions, agreements of those signs, as they are. P also gives near and
// x_ray_misses.
template <class P>
struct at_weighted : P {
    template <class L>
    [[nodiscard]] constexpr auto pl(L lift, const vec3& u, const point3& x, const point3& y) const {
        const auto [V, W] = this->weighted(lift);
        const auto X = arith::lift(lift, x), Y = arith::lift(lift, y);
        const auto xy = arith::cross(X, Y);
        const auto r = arith::cross(Y - X, V);
        using T = decltype(W * xy.x + r.x);
        return arith::dot(arith::lift(lift, u), arith::v3<T>{W * xy.x + r.x, W * xy.y + r.y, W * xy.z + r.z});
    }
    template <class L>
    [[nodiscard]] constexpr auto ahead(L lift, const point3& a0, const point3& b0, const point3& c0) const {
        const auto [V, W] = this->weighted(lift);
        const auto A = arith::lift(lift, a0);
        const auto n = arith::cross(arith::lift(lift, b0) - A, arith::lift(lift, c0) - A);
        using T = decltype(W * A.x - V.x);
        return arith::dot(n, arith::v3<T>{W * A.x - V.x, W * A.y - V.y, W * A.z - V.z});
    }
};

// The crossings of the ray from q along direction j (u_j = (1, c_j, c_j^2)): 1 odd, 0 even, -1 not
// clean (through an edge or a vertex, or in a triangle's plane). Tentative: every sign by
// arith::probe, which may answer zero for a sign it cannot prove without touching the query's
// certainty, and any such zero that would matter makes the direction unclean.
template <class K, class Q>
[[nodiscard]] constexpr int crossings(K& k, const mesh3& m, const Q& q, std::size_t j, bool tentative) {
    const double c = j == 0 ? 0.0 : (j % 2 ? double((j + 1) / 2) : -double(j / 2));
    const vec3 u{1.0, c, c * c};
    auto sgn = [&](const auto& f) { return tentative ? arith::probe(k, f) : k.sgn(f); };
    bool odd = false;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 t = m.triangle(i);
        if (j == 0) { // the ray along +x misses a triangle whose box it misses (comparisons)
            const point3 v[3] = {t.a, t.b, t.c};
            if (q.x_ray_misses(bounds(v, 3))) continue;
        }
        auto pl = [&](point3 x, point3 y) { return sgn([=](auto L) { return q.pl(L, u, x, y); }); };
        const sign s0 = pl(t.a, t.b), s1 = pl(t.b, t.c), s2 = pl(t.c, t.a);
        const bool pos = s0 == sign::positive || s1 == sign::positive || s2 == sign::positive;
        const bool neg = s0 == sign::negative || s1 == sign::negative || s2 == sign::negative;
        if (pos && neg) continue; // the ray's line misses the triangle
        if (!pos && !neg) {       // in the triangle's plane, or a collinear triangle
            if (tentative) return -1;
            const point3 a = t.a, b = t.b, cc = t.c;
            bool collinear = true;
            for (int axis = 0; axis < 3 && collinear; ++axis)
                collinear = arith::is_zero(k, [=](auto L) {
                                const auto n = arith::cross(arith::lift(L, b) - arith::lift(L, a), arith::lift(L, cc) - arith::lift(L, a));
                                return axis == 0 ? n.x : (axis == 1 ? n.y : n.z);
                            });
            if (!collinear) return -1;
            continue;
        }
        const sign s = pos ? sign::positive : sign::negative;
        const point3 a = t.a, b = t.b, cc = t.c;
        const sign d = sgn([=](auto L) { return q.ahead(L, a, b, cc); });
        if (tentative && d == sign::zero) return -1;
        // det(a - p, b - p, c - p): the crossing lies ahead iff it has sign s
        if (d != s) continue;
        if (s0 == sign::zero || s1 == sign::zero || s2 == sign::zero) return -1; // through an edge or vertex
        odd = !odd;
    }
    return odd ? 1 : 0;
}

// Is the point q, off the surface, inside (odd crossings)? For a closed surface every clean
// direction gives the same parity, so a kernel that can probe (the filter, the exact kernel's
// filter stages) first tries a few directions on signs it proves cheaply: an axis-parallel edge
// makes the first direction unclean for every point, and the filter cannot prove that zero. Then
// every direction in turn with exact signs.
template <class K, class Q>
[[nodiscard]] constexpr bool inside_at(K& k, const mesh3& m, const Q& q) {
    if (!q.near(bounds(m))) return false;
    if constexpr (requires { k.probe([](auto L) { return L(0.0); }); })
        for (std::size_t j = 0; j < 4; ++j)
            if (const int r = crossings(k, m, q, j, true); r >= 0) return r == 1;
    const std::size_t tries = 8 * m.triangles.size() + m.vertices.size() + 8;
    for (std::size_t j = 0; j < tries; ++j) {
        if (const int r = crossings(k, m, q, j, false); r >= 0) return r == 1;
        if constexpr (requires { k.failed(); })
            if (k.failed()) return false; // a filter that failed a sign: its answer is discarded
    }
    return false; // reached only by inexact arithmetic (the approximate tier, a filter's guess)
}
template <class K>
[[nodiscard]] constexpr bool inside(K& k, const mesh3& m, point3 p) {
    return inside_at(k, m, at_point{p});
}

// The mesh's point set against the connected shape x: a triangle meets x, or p (a point of x)
// lies inside. The caller has checked the mesh well formed and x finite. With x's bounding box
// `xb` (bounded shapes), triangles whose own box misses it are skipped (comparisons).
template <class K, class Meets>
[[nodiscard]] constexpr bool mesh_meets(K& k, const mesh3& m, const Meets& meets, point3 p, const aabb3* xb = nullptr) {
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 t = m.triangle(i);
        if (xb != nullptr) {
            const point3 v[3] = {t.a, t.b, t.c};
            if (!boxes_meet(bounds(v, 3), *xb)) continue;
        }
        if (meets(t)) return true;
    }
    return inside(k, m, p);
}

} // namespace meshq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const point3& p) {
    if (!meshq::well_formed(m) || !finite(p) || !meshq::in_box(meshq::bounds(m), p)) return false;
    const aabb3 xb{p, p};
    return meshq::mesh_meets(k, m, [&](const triangle3& f) { return linear_triangle(k, as_linear(p), f); }, p, &xb);
}
// contains(mesh, point): the same set.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const mesh3& m, const point3& p) { return intersects(k, m, p); }

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const mesh3&, const point3&);
extern template bool contains(arith::exact_kernel&, const mesh3&, const point3&);
} // namespace incidence::pair
