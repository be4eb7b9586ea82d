// intersects: polygon_pairs
module;
#include <cstddef>
#include <type_traits>
#include <utility>
export module incidence.detail:intersects.polygon_pairs;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :engines.separating_axes;
import :engines.tetrahedron;
import :engines.box;
import :intersects.triangle_pairs;
import :intersects.box_pairs;
import :intersects.linear_pairs;
import :intersects.tetrahedron_pairs;
import :engines.polygon3;
import :intersects.obb_pairs;
import :intersects.polygon2_pairs;
import :exactly;

export namespace incidence::detail {

// point3 against polygon3, contains(polygon3, point3), and the engine every 3D polygon pair shares.
// Semantics: the polygon's point set (shapes/polygon3.cppm): the points of its plane whose
// projection along its axis lies in the projected polygon2 (edges, and odd crossing parity).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point3& p, const polygon3& g) {
    if (!finite(p) || !polygon3d::usable(k, g)) return false;
    if (polygon3d::side(k, g, p) != sign::zero) return false;
    // on an edge, in the projection (one to one on H): within the edge's box (comparisons), and
    // orient2d zero
    const point2 q = g.projected(p);
    const bool on_edge = polygon3d::any_edge(g, [&](const segment3& e) {
        const point2 a = g.projected(e.a), b = g.projected(e.b);
        if (q.x < min2(a.x, b.x) || q.x > max2(a.x, b.x) || q.y < min2(a.y, b.y) || q.y > max2(a.y, b.y)) return false;
        return arith::is_zero(k, [=](auto L) { return poly::orient2d(L, a, b, q); });
    });
    return on_edge || polygon3d::inside(k, g, polygon3d::at_double{p});
}

// aabb3 against polygon3.
// Semantics: the closed box (bounds ordered and finite; an inverted box is empty) and the
// polygon's point set (shapes/polygon3.cppm). Touching counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const polygon3& g) {
    if (!well_formed_finite(b) || !polygon3d::usable(k, g)) return false;
    if (polygon3d::any_edge(g, [&](const segment3& e) { return intersects(k, b, e); })) return true;
    const box_corners q(b);
    // corner m has bit i set for max along axis i: its edges go to m | 1 << i
    for (unsigned m = 0; m < 8; ++m)
        for (unsigned i = 0; i < 3; ++i)
            if ((m & (1u << i)) == 0 && polygon3d::crossing_inside(k, g, as_linear(segment3{q.p[m], q.p[m | (1u << i)]}))) return true;
    return false;
}

// line3 against polygon3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the line o + t d (a zero direction: its
// origin). Touching an edge or a vertex counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& s, const polygon3& g) {
    if (!finite(s.origin) || !finite(s.direction) || !polygon3d::usable(k, g)) return false;
    return polygon3d::linear_meets(k, g, as_linear(s));
}

// polygon3 against segment3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed segment (equal ends: a
// point). Touching an edge or a vertex counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& g, const segment3& s) {
    if (!finite(s.a) || !finite(s.b) || !polygon3d::usable(k, g)) return false;
    return polygon3d::linear_meets(k, g, as_linear(s));
}

// polygon3 against triangle3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed solid triangle
// (collinear corners: the segments between them). Touching counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& g, const triangle3& t) {
    if (!finite(t.a) || !finite(t.b) || !finite(t.c) || !polygon3d::usable(k, g)) return false;
    if (polygon3d::any_edge(g, [&](const segment3& e) { return intersects(k, e, t); })) return true;
    return polygon3d::crossing_inside(k, g, as_linear(segment3{t.a, t.b})) ||
           polygon3d::crossing_inside(k, g, as_linear(segment3{t.b, t.c})) ||
           polygon3d::crossing_inside(k, g, as_linear(segment3{t.c, t.a}));
}

// obb3 against polygon3.
// Semantics: the closed box read as the parallelepiped its axes span (shapes/obb3.cppm) and the
// polygon's point set (shapes/polygon3.cppm). Touching counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& b, const polygon3& g) {
    if (!sat::well_formed(b) || !finite(b) || !polygon3d::usable(k, g)) return false;
    if (polygon3d::any_edge(g, [&](const segment3& e) { return intersects(k, b, e); })) return true;
    const point3 a = g.vertices[g.plane_vertices[0]];
    bool crossed = false;
    for (int e = 0; e < 3; ++e) {
        const unsigned ek = static_cast<unsigned>(e), ei = (ek + 1) % 3, ej = (ek + 2) % 3;
        auto D = [=](auto L) { return arith::dot(polygon3d::normal(L, g), arith::lift(L, b.axes[ek])); };
        const sign d = k.sgn(D);
        if (d == sign::zero) continue; // these edges are parallel to H
        crossed = true;
        for (int m = 0; m < 4; ++m) {
            const double si = (m & 1) ? b.half_extents[ei] : -b.half_extents[ei];
            const double sj = (m & 2) ? b.half_extents[ej] : -b.half_extents[ej];
            auto T = [=](auto L) {
                const auto n = polygon3d::normal(L, g);
                return arith::dot(n, arith::lift(L, a) - arith::lift(L, b.center)) * L(1.0) -
                       L(si) * arith::dot(n, arith::lift(L, b.axes[ei])) - L(sj) * arith::dot(n, arith::lift(L, b.axes[ej]));
            };
            const double hk = b.half_extents[ek];
            // |t| <= h_k: h_k D - T and h_k D + T both zero or of D's sign
            const sign hi = k.sgn([=](auto L) { return L(hk) * D(L) - T(L); });
            if (hi != sign::zero && hi != d) continue;
            const sign lo = k.sgn([=](auto L) { return L(hk) * D(L) + T(L); });
            if (lo != sign::zero && lo != d) continue;
            auto V = [=](auto L) {
                const auto dd = D(L);
                const auto t = T(L);
                const auto c = arith::lift(L, b.center);
                const auto one = L(1.0);
                const auto ai = arith::lift(L, b.axes[ei]), aj = arith::lift(L, b.axes[ej]), ak = arith::lift(L, b.axes[ek]);
                const auto Si = L(si), Sj = L(sj);
                using R = decltype((c.x * one + Si * ai.x + Sj * aj.x) * dd + t * ak.x);
                return arith::v3<R>{(c.x * one + Si * ai.x + Sj * aj.x) * dd + t * ak.x,
                                    (c.y * one + Si * ai.y + Sj * aj.y) * dd + t * ak.y,
                                    (c.z * one + Si * ai.z + Sj * aj.z) * dd + t * ak.z};
            };
            auto Dpad = [=](auto L) { return D(L) * L(1.0); };
            return polygon3d::inside(k, g, polygon3d::at_homogeneous<decltype(V), decltype(Dpad)>{V, Dpad, d});
        }
    }
    if (crossed) return false; // no edge crosses H within the box: the box misses H
    // every edge parallel to H (dependent axes): the box lies in H or off it, and its point
    // c + h_0 a_0 decides
    auto V = [=](auto L) {
        const auto c = arith::lift(L, b.center);
        const auto one = L(1.0);
        const auto a0 = arith::lift(L, b.axes[0]);
        const auto h0 = L(b.half_extents[0]);
        using R = decltype(c.x * one + h0 * a0.x);
        return arith::v3<R>{c.x * one + h0 * a0.x, c.y * one + h0 * a0.y, c.z * one + h0 * a0.z};
    };
    auto one = [](auto L) { return L(1.0); };
    const sign on = k.sgn([=](auto L) {
        const auto A = arith::lift(L, a);
        const auto v = V(L);
        const auto o = L(1.0);
        using R = decltype(v.x - A.x * o);
        return arith::dot(polygon3d::normal(L, g), arith::v3<R>{v.x - A.x * o, v.y - A.y * o, v.z - A.z * o});
    });
    if (on != sign::zero) return false;
    return polygon3d::inside(k, g, polygon3d::at_homogeneous<decltype(V), decltype(one)>{V, one, sign::positive});
}

// plane3 against polygon3.
// Semantics: the plane n . x = offset (a zero normal: all of space for a zero offset, else
// nothing) and the polygon's point set (shapes/polygon3.cppm). Touching counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const polygon3& g) {
    if (!finite(pl.normal) || !finite(pl.offset) || !polygon3d::usable(k, g)) return false;
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

// polygon3 against polygon3.
// Semantics: the two polygons' point sets (shapes/polygon3.cppm). Touching counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& a, const polygon3& b) {
    if (!polygon3d::usable(k, a) || !polygon3d::usable(k, b)) return false;
    return polygon3d::any_edge(a, [&](const segment3& e) { return polygon3d::linear_meets(k, b, as_linear(e)); }) ||
           polygon3d::any_edge(b, [&](const segment3& e) { return polygon3d::linear_meets(k, a, as_linear(e)); });
}

// polygon3 against ray3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed ray o + t d, t >= 0 (a zero
// direction: its origin). Touching an edge or a vertex counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& g, const ray3& s) {
    if (!finite(s.origin) || !finite(s.direction) || !polygon3d::usable(k, g)) return false;
    return polygon3d::linear_meets(k, g, as_linear(s));
}

// polygon3 against tetrahedron3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed solid tetrahedron
// (coplanar vertices: their hull). Touching counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& g, const tetrahedron3& t) {
    if (!finite(t.a) || !finite(t.b) || !finite(t.c) || !finite(t.d) || !polygon3d::usable(k, g)) return false;
    if (polygon3d::any_edge(g, [&](const segment3& e) { return intersects(k, e, t); })) return true;
    const point3 v[4] = {t.a, t.b, t.c, t.d};
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            if (polygon3d::crossing_inside(k, g, as_linear(segment3{v[i], v[j]}))) return true;
    return false;
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const point3&, const polygon3&);
extern template bool exactly<intersects_body>(const aabb3&, const polygon3&);
extern template bool exactly<intersects_body>(const line3&, const polygon3&);
extern template bool exactly<intersects_body>(const polygon3&, const segment3&);
extern template bool exactly<intersects_body>(const polygon3&, const triangle3&);
extern template bool exactly<intersects_body>(const obb3&, const polygon3&);
extern template bool exactly<intersects_body>(const plane3&, const polygon3&);
extern template bool exactly<intersects_body>(const polygon3&, const polygon3&);
extern template bool exactly<intersects_body>(const polygon3&, const ray3&);
extern template bool exactly<intersects_body>(const polygon3&, const tetrahedron3&);
} // namespace incidence::detail
