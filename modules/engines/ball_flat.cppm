// sphere3 against the flat shapes and the tetrahedron (and circle2 against the plane's segment, ray
// and line: the same signs in two coordinates, intersects/circle2_pairs.cppm): segment3, line3, plane3, triangle3,
// tetrahedron3 and polygon3 (ray3 has its own body in sphere_pairs.cppm, with its first hit; the
// solid mesh3 is a triangle or the centre inside, in mesh_pairs.cppm).
// Semantics: the closed ball |x - c| <= |r| (an unchecked negative radius acts as |r|, as in
// point_sphere); a closed segment (a = b is a point), a line (a zero direction is its origin), a
// plane (a zero normal is everything when its offset is 0 and nothing otherwise), a closed triangle
// (a collinear one is its hull), a closed solid tetrahedron (coplanar vertices give their hull).
// Touching counts.
// Method (exact tiers): the squared distance from c to the shape against r^2, through the
// closest-feature case analysis; with m = o - c, D the direction (b - a for a segment), a = D . D,
// b = m . D, c' = m . m - r^2 (degree 2 each):
//   segment: an end in the ball (c' <= 0, or |b_end - c|^2 <= r^2): yes; the nearest point of the
//            supporting line before a (b >= 0) or beyond b (a + b <= 0): no; else b^2 - a c' >= 0
//            decides (degree 4). A ray: its origin, then b >= 0 says no, then b^2 - a c' >= 0.
//   line:    c' <= 0 or b^2 - a c' >= 0 (a zero direction: c' <= 0 alone).
//   r may be the exact sum of two radii (a capsule's and a ball's), squared inside the signs.
//   plane:   (n . c - d 1)^2 <= r^2 |n|^2 (degree 4).
//   triangle: with n = (b - a) x (c - a) != 0: the ball apart from the plane,
//            (n . (c - a))^2 > r^2 |n|^2 (degree 6): no; c's projection in the closed triangle,
//            n . ((v - u) x (c - u)) >= 0 for each edge uv (degree 4): yes; else the ball meets one
//            of the three edges (the nearest point is on the boundary). n = 0: the three edges.
//   tetrahedron: c in the closed solid, or the ball meets a face (tetra::tetrahedron_meets with c).
//   polygon3 (usable, engines/polygon3.cppm): the ball apart from the plane H (as the triangle,
//            degree 6): no; the foot of c on H, V / D with V = c |n|^2 - (n . (c - a)) n and
//            D = |n|^2 > 0, inside by crossing parity (polygon3d::inside, signs of degree <= 6):
//            yes; else the ball meets an edge of a ring, or no. Complete: the ball cuts H in a
//            disk around the foot; a disk meeting the polygon's set contains a point of its
//            boundary or lies inside it with its centre (a foot on the boundary is found by its
//            edge).
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.2 (closest point on a
// segment), 5.1.5 (closest point on a triangle, by Voronoi regions), 5.2.7 (sphere against a
// triangle); Akenine-Moeller et al., Real-Time Rendering, 4th ed. (2018), section 22.13.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/intersects/sphere_triangle.cpp and the other pairs' tests).
module;
#include <array>
#include <cstddef>
export module incidence.detail:engines.ball_flat;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.polygon3;
import :engines.tetrahedron;

export namespace incidence::detail {

namespace ball_flat {

// A radius: one double, or the exact sum of two (a capsule's and a ball's, both >= 0), squared
// inside a sign.
struct radii {
    double a, b;
};
template <class L>
[[nodiscard]] constexpr auto squared(L l, double r) {
    return l(r) * l(r);
}
template <class L>
[[nodiscard]] constexpr auto squared(L l, radii r) {
    const auto s = l(r.a) + l(r.b);
    return s * s;
}

// The sign of r^2 - |x - c|^2 that puts x in the closed ball (>= 0) or, `open`, in the open one (> 0).
template <bool open>
[[nodiscard]] constexpr bool within(sign s) {
    return open ? s == sign::positive : s != sign::negative;
}

// Is p in the ball (in space, or the disk in the plane; `open`: strictly inside)?
template <bool open = false, class K, class P, class R>
[[nodiscard]] constexpr bool holds(K& k, P p, P c, R r) {
    return within<open>(k.sgn([=](auto L) {
        const auto m = arith::lift(L, p) - arith::lift(L, c);
        return squared(L, r) - arith::dot(m, m);
    }));
}

// A segment, a ray or a line (finite) against the ball, in space or in the plane (the disk);
// `open`: a point of it strictly inside (the same case analysis, each final sign strict).
template <bool open = false, class K, class P, class V, class R>
[[nodiscard]] constexpr bool meets(K& k, const basic_linear<P, V>& s, P c, R r) {
    if (holds<open>(k, s.o, c, r)) return true;
    if (s.is_point()) return false;
    const auto lb = [=](auto L) { return arith::dot(s.O(L) - arith::lift(L, c), s.D(L)); };
    if (s.kind != extent::line && k.sgn(lb) != sign::negative) return false; // the origin is nearest
    if (s.kind == extent::segment) {
        if (holds<open>(k, s.q, c, r)) return true;
        if (k.sgn([=](auto L) {
                const auto D = s.D(L);
                return arith::dot(D, D) + lb(L);
            }) != sign::positive)
            return false;
    }
    return within<open>(k.sgn([=](auto L) {
        const auto m = s.O(L) - arith::lift(L, c);
        const auto D = s.D(L);
        const auto b = arith::dot(m, D);
        return b * b - arith::dot(D, D) * (arith::dot(m, m) - squared(L, r));
    }));
}

template <class K, class R>
[[nodiscard]] constexpr bool meets(K& k, const plane3& p, point3 c, R r) {
    const vec3 n = p.normal;
    if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0) return p.offset == 0.0;
    return k.sgn([=](auto L) {
        const auto N = arith::lift(L, n);
        const auto e = arith::dot(N, arith::lift(L, c)) - L(p.offset) * L(1.0);
        return squared(L, r) * arith::dot(N, N) - e * e;
    }) != sign::negative;
}

template <class K, class R>
[[nodiscard]] constexpr bool meets(K& k, const triangle3& t, point3 c, R r) {
    const auto normal = [=](auto L) {
        const auto A = arith::lift(L, t.a);
        return arith::cross(arith::lift(L, t.b) - A, arith::lift(L, t.c) - A);
    };
    const auto edges = [&] {
        return meets(k, as_linear(segment3{t.a, t.b}), c, r) || meets(k, as_linear(segment3{t.b, t.c}), c, r) ||
               meets(k, as_linear(segment3{t.c, t.a}), c, r);
    };
    if (arith::is_zero<arith::hint::often_zero>(k, [=](auto L) {
            const auto n = normal(L);
            return arith::dot(n, n);
        }))
        return edges(); // collinear: the hull is the union of the edges
    if (k.sgn([=](auto L) {
            const auto n = normal(L);
            const auto e = arith::dot(n, arith::lift(L, c) - arith::lift(L, t.a));
            return e * e - squared(L, r) * arith::dot(n, n);
        }) == sign::positive)
        return false; // apart from the plane
    const std::array<point3, 3> v{t.a, t.b, t.c};
    bool inside = true;
    for (unsigned i = 0; i < 3 && inside; ++i) {
        const point3 u = v[i], w = v[(i + 1) % 3];
        inside = k.sgn([=](auto L) {
            const auto U = arith::lift(L, u);
            return arith::dot(normal(L), arith::cross(arith::lift(L, w) - U, arith::lift(L, c) - U));
        }) != sign::negative;
    }
    return inside || edges();
}

template <class K, class R>
[[nodiscard]] constexpr bool meets(K& k, const tetrahedron3& t, point3 c, R r) {
    const point3 pts[1] = {c};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return meets(k, face, c, r); }, pts, 1, false);
}

// The polygon (usable) against the ball.
template <class K, class R>
[[nodiscard]] constexpr bool meets(K& k, const polygon3& g, point3 c, R r) {
    const point3 a = g.vertices[g.plane_vertices[0]];
    const auto lift_e = [=, &g](auto L) { return arith::dot(polygon3d::normal(L, g), arith::lift(L, c) - arith::lift(L, a)); };
    if (k.sgn([=, &g](auto L) {
            const auto n = polygon3d::normal(L, g);
            const auto e = lift_e(L);
            return e * e - squared(L, r) * arith::dot(n, n);
        }) == sign::positive)
        return false; // apart from the plane
    const auto D = [&g](auto L) {
        const auto n = polygon3d::normal(L, g);
        return arith::dot(n, n);
    };
    const auto V = [=, &g](auto L) {
        const auto n = polygon3d::normal(L, g);
        const auto d = arith::dot(n, n);
        const auto e = lift_e(L);
        const auto C = arith::lift(L, c);
        using T = decltype(C.x * d - e * n.x);
        return arith::v3<T>{C.x * d - e * n.x, C.y * d - e * n.y, C.z * d - e * n.z};
    };
    if (polygon3d::inside(k, g, polygon3d::at_homogeneous<decltype(V), decltype(D)>{V, D, sign::positive})) return true;
    return polygon3d::any_edge(g, [&](const segment3& e) { return meets(k, as_linear(e), c, r); });
}

// x + s r (s = +-1, r >= 0) rounded outward (moved past its rounding error of at most half an
// ulp; an overflow gives an infinity).
[[nodiscard]] constexpr double away(double x, double s, double r) {
    const double y = x + s * r;
    return y + s * (arith::abs(y) * 0x1p-52 + 0x1p-1074);
}
// A box around the points within r (>= 0) of the n points p, rounded outward.
[[nodiscard]] constexpr aabb3 reach_box(const point3* p, std::size_t n, double r) {
    const aabb3 b = bounds(p, n);
    return {{away(b.min.x, -1, r), away(b.min.y, -1, r), away(b.min.z, -1, r)},
            {away(b.max.x, 1, r), away(b.max.y, 1, r), away(b.max.z, 1, r)}};
}
// The disk's box in the plane, rounded outward.
[[nodiscard]] constexpr box2 reach_box(point2 c, double r) {
    return {{away(c.x, -1, r), away(c.y, -1, r)}, {away(c.x, 1, r), away(c.y, 1, r)}};
}

} // namespace ball_flat

} // namespace incidence::detail
