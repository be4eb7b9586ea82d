// point3 against polygon3, contains(polygon3, point3), and the engine every 3D polygon pair shares.
// Semantics: the polygon's point set (shapes/polygon3.cppm): the points of its plane whose
// projection along its axis lies in the projected polygon2 (edges, and odd crossing parity).
// Method (exact tiers): the plane is H = { x : n . (x - a) = 0 } with n = (b - a) x (c - a) for
// its three plane vertices a, b, c, and the projection drops the coordinate where n is not zero,
// so a point of H is in the polygon iff its projection is in the projected polygon: the 2D
// crossing test of point2_polygon2.cppm (an edge counts when exactly one end lies above the point,
// the half-open rule, and the point lies left of it directed upward). A point of H that is not a
// double, where a line crosses H or a vertex of a convex set's section by H, is V / D
// (homogeneous), and each comparison of the 2D test becomes a sign multiplied through by D. Any
// other connected shape X meets the polygon iff it meets an edge (a segment3) or else one point
// of X in H lies inside (a connected piece of X in H that meets no edge lies wholly inside or
// outside): point2_polygon2's boundary-plus-inside decomposition, one dimension up. A point of H
// is on an edge iff its projection is in the projected edge's box with orient2d zero. In a filter
// pass, a segment, ray or line crossing H first goes through rounded_crossing (its crossing point
// in double within a proven radius, the crossing test on it with proven bounds).
// Source: Haines, "Point in polygon strategies", Graphics Gems IV (1994): the projection along the
// normal's largest component (section 1) and the crossings test with the half-open rule.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/point_polygon.cpp).
//
// polygon3 against triangle3.
// Semantics: the polygon's point set (shapes/polygon3.cppm) and the closed solid triangle
// (collinear corners: the segments between them). Touching counts.
// Method (exact tiers): an edge of the polygon meets the triangle (segment_triangle.cppm), or an
// edge of the triangle crosses the polygon inside (planeq::crossing_inside: a triangle edge
// through a polygon edge was found by the first test). Complete: where the two meet and
// no polygon edge touches the triangle, the triangle's section by the polygon's plane (a segment,
// or the triangle itself when coplanar) lies inside the polygon, and its ends are on the
// triangle's edges.
// contains: the corners in the polygon's plane, then in the projection: the triangle's three
// edges in the polygon (polygon_segment.cppm), no polygon edge meeting the open triangle (its
// points strictly inside all three edge lines: separating lines along the triangle's edges or the
// edge's own line, orient2d signs of degree 2), and the centroid (a + b + c) / 3 inside by crossing
// parity (weight L(1) + L(1) + L(1); in a filter pass the rounded centroid within a proven radius
// first, point2_polygon2's rounded_parity). Then no boundary crosses the open triangle, which lies wholly
// inside or outside, and its centroid decides (a hole exactly the triangle has every edge in the
// set). A collinear triangle is the union of its edges.
// Source: the boundary-plus-inside decomposition of point_polygon.cppm; Moeller, "A fast
// triangle-triangle intersection test", JGT 2(2), 1997 (edges against faces).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/polygon_triangle.cpp).
module;
#include <cstddef>
#include <type_traits>
#include <utility>
export module incidence.detail:engines.polygon3;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :engines.polygon2;

export namespace incidence::detail {

namespace polygon3d {

// Indices valid and every vertex finite (comparisons only).
[[nodiscard]] constexpr bool well_formed(const polygon3& g) {
    if (!g.indices_valid()) return false;
    for (std::size_t i = 0; i < g.vertices.size(); ++i)
        if (!finite(g.vertices[i])) return false;
    return true;
}
// n = (b - a) x (c - a) for the plane vertices a, b, c.
template <class L>
[[nodiscard]] constexpr auto normal(L l, const polygon3& g) {
    const auto a = arith::lift(l, g.vertices[g.plane_vertices[0]]);
    return arith::cross(arith::lift(l, g.vertices[g.plane_vertices[1]]) - a, arith::lift(l, g.vertices[g.plane_vertices[2]]) - a);
}
template <class T>
[[nodiscard]] constexpr T component(const arith::v3<T>& v, int axis) {
    return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}
// The polygon is a set: well formed, and n has a nonzero component along the axis (so the
// projection is one to one on H).
template <class K>
[[nodiscard]] constexpr bool usable(K& k, const polygon3& g) {
    if (!well_formed(g)) return false;
    const int axis = g.axis;
    return !arith::is_zero(k, [=](auto L) { return component(normal(L, g), axis); });
}
// n . (p - a): zero iff p lies in H.
template <class K>
[[nodiscard]] constexpr sign side(K& k, const polygon3& g, point3 p) {
    return k.sgn([=](auto L) { return arith::dot(normal(L, g), arith::lift(L, p) - arith::lift(L, g.vertices[g.plane_vertices[0]])); });
}

// Calls f(segment3) for every edge of every ring (a well-formed polygon) until it returns true.
template <class F>
[[nodiscard]] constexpr bool any_edge(const polygon3& g, const F& f) {
    for (std::size_t r = 0; r < g.rings(); ++r) {
        const std::size_t b = g.ring_begin(r), e = g.ring_end(r);
        for (std::size_t j = b; j < e; ++j)
            if (f(segment3{g.vertices[j], g.vertices[polygon3::next(j, b, e)]})) return true;
    }
    return false;
}

// Calls f(p, q) for the projection of every edge (a well-formed polygon) until it returns true.
[[nodiscard]] constexpr auto projected_edges(const polygon3& g) {
    return [&g](const auto& f) { return any_edge(g, [&](const segment3& e) { return f(g.projected(e.a), g.projected(e.b)); }); };
}

// The projected coordinates (u, v) of a lifted 3D vector: (y, z), (z, x) or (x, y).
template <class T>
[[nodiscard]] constexpr T u_of(const arith::v3<T>& p, int axis) {
    return axis == 0 ? p.y : (axis == 1 ? p.z : p.x);
}
template <class T>
[[nodiscard]] constexpr T v_of(const arith::v3<T>& p, int axis) {
    return axis == 0 ? p.z : (axis == 1 ? p.x : p.y);
}

// A point of H given as V / D: V(L) and D(L) lifted expressions, d the sign of D (not zero).
template <class VF, class DF>
struct at_homogeneous {
    VF V;
    DF D;
    sign d;
};
// A double point of H.
struct at_double {
    point3 p;
};

// Is the point, in H and off the boundary, inside (odd crossings in the projection)?
template <class K, class At>
[[nodiscard]] constexpr bool inside(K& k, const polygon3& g, const At& at) {
    const int axis = g.axis;
    bool odd = false;
    (void)any_edge(g, [&](const segment3& e) {
        const point2 a = g.projected(e.a), b = g.projected(e.b);
        bool a_above, b_above;
        sign s;
        if constexpr (std::is_same_v<At, at_double>) {
            const point2 p = g.projected(at.p);
            a_above = a.y > p.y, b_above = b.y > p.y;
            if (a_above == b_above) return false;
            if (a.x < p.x && b.x < p.x) return false; // both ends left of p: the ray misses it
            s = k.sgn([=](auto L) { return (L(b.x) - L(a.x)) * (L(p.y) - L(a.y)) - (L(b.y) - L(a.y)) * (L(p.x) - L(a.x)); });
        } else {
            // w.y > p.y with p = V / D: sign(w.y D - V.v) times sign(D)
            auto above = [&](point2 w) { return k.sgn([=](auto L) { return L(w.y) * at.D(L) - v_of(at.V(L), axis); }) == at.d; };
            a_above = above(a), b_above = above(b);
            if (a_above == b_above) return false;
            auto left = [&](point2 w) { return k.sgn([=](auto L) { return u_of(at.V(L), axis) - L(w.x) * at.D(L); }) == at.d; };
            if (left(a) && left(b)) return false;
            // orient2d(a, b, V / D) times D: (b - a) x (V - a D)
            const sign t = k.sgn([=](auto L) {
                const auto d = at.D(L);
                const auto v = at.V(L);
                return (L(b.x) - L(a.x)) * (v_of(v, axis) - L(a.y) * d) - (L(b.y) - L(a.y)) * (u_of(v, axis) - L(a.x) * d);
            });
            s = at.d == sign::positive ? t : -t;
        }
        if (s == (b_above ? sign::positive : sign::negative)) odd = !odd;
        return false;
    });
    return odd;
}

// How o + t u (a segment, ray or line, finite) meets H: not at all, lying in it, or crossing it at
// one point within its range (w, the sign of n . u, then nonzero).
enum class contact { none, lies_in, crosses };
template <class K>
[[nodiscard]] constexpr contact plane_contact(K& k, const polygon3& g, const linear3& x, sign& w) {
    const point3 a = g.vertices[g.plane_vertices[0]];
    // w = n . u: zero when x is parallel to H
    w = k.sgn([=](auto L) { return arith::dot(normal(L, g), x.D(L)); });
    if (w == sign::zero) return side(k, g, x.o) == sign::zero ? contact::lies_in : contact::none;
    // t = n . (a - o) / w within the object's range
    const sign t = k.sgn([=](auto L) { return arith::dot(normal(L, g), arith::lift(L, a) - x.O(L)); });
    if (x.bounded_below() && t != sign::zero && t != w) return contact::none; // t < 0
    if (x.bounded_above()) {                                                  // t <= 1: n . (a - q) zero or of the other sign than w
        const sign e = k.sgn([=](auto L) { return arith::dot(normal(L, g), arith::lift(L, a) - arith::lift(L, x.q)); });
        if (e == w) return contact::none;
    }
    return contact::crosses;
}
// For T and D off by at most eT and eD (|D| > 2 eD) and t = T / D rounded: t is off from the true
// quotient by at most (eT + |t'| eD) / |D| + u |t| with |t'| <= (|T| + eT) / (|D| - eD), the true
// quotient's bound (u = 2^-53 for the division).
[[nodiscard]] constexpr double quotient_error(double T, double eT, double D, double eD, double t) {
    const double aD = arith::abs(D);
    return (eT + (arith::abs(T) + eT) / (aD - eD) * eD) / aD + 0x1p-52 * arith::abs(t);
}

// The rounded stage of a point V / D of H given as filter values (the filter's own lift of V and D,
// each off by at most its arith::error_bound): yes inside, no outside, uncertain when a comparison is not
// clear (polygon2d::rounded_parity, with the point's projection V / D in double and its radius by
// quotient_error, widened by 1/8 for its own rounding, plus 2^-1000 for underflow), or when D is
// not clearly nonzero or a permanent is not in the filter's trusted range (arith::proven_sign).
template <int A, int B>
[[nodiscard]] constexpr certainty rounded_inside(const polygon3& g, const arith::v3<arith::filtered<A>>& V, arith::filtered<B> D) {
    const arith::filtered<A> vu = u_of(V, g.axis), vv = v_of(V, g.axis);
    if (!(D.p >= 0x1p-900 && vu.p >= 0x1p-900 && vv.p >= 0x1p-900)) return certainty::uncertain; // also NaN
    const double eD = arith::error_bound(D);
    if (!(arith::abs(D.v) > 2.0 * eD)) return certainty::uncertain;
    const double px = vu.v / D.v, py = vv.v / D.v;
    const double rx = quotient_error(vu.v, arith::error_bound(vu), D.v, eD, px) * 1.125 + 0x1p-1000;
    const double ry = quotient_error(vv.v, arith::error_bound(vv), D.v, eD, py) * 1.125 + 0x1p-1000;
    return polygon2d::rounded_parity(projected_edges(g), px, py, rx, ry);
}

// The rounded stage of a crossing (a filter pass at run time, arith::rounded_stage_applies): x
// crosses H; its crossing point P = o + (T / D) u, T = n . (a - o), D = n . u, computed in double,
// each projected coordinate off by at most a proven radius r; then the crossing test of inside on
// it, each comparison decided only when clear by more than its bound. yes inside, no outside, uncertain when
// some comparison is not clear (also for D not clearly nonzero, a value far off or not finite).
// Where it decides, P is also clearly off every edge (each edge has both ends clearly above or
// below P, both clearly left of it, or a clearly nonzero orientation), so the answer is that of
// linear_meets' edge tests and inside's signs together. Bounds (u = 2^-53): T and D are plane
// values of rounded differences, off by at most 2^-48 sum N_k X_k + 2^-700 (eT, eD; as
// tetra::rounded_triangle_side, N_k the permanent of n_k, X_k the difference's |component k|,
// every component at most 2^299); for |D^| > 2 eD, t = T / D is off by at most
// (eT + |t| eD) / |D^| + u |t^| with |t| <= (|T^| + eT) / (|D^| - eD); P_c by at most
// |u_c| dt + 2u |u_c t^| + u |P_c^| (the product, the sum), widened by 1/8 for its own rounding,
// plus 2^-1000 for underflow (an overflow leaves an infinite or NaN bound, and nothing is clear);
// the crossing test on it is polygon2d::rounded_parity. Source: Higham, Accuracy and Stability of
// Numerical Algorithms, 2nd ed. (2002), section 3.1 (the bounds).
[[nodiscard]] constexpr certainty rounded_crossing(const polygon3& g, const linear3& x) {
    const point3 a = g.vertices[g.plane_vertices[0]], b = g.vertices[g.plane_vertices[1]], c = g.vertices[g.plane_vertices[2]];
    const double e[2][3] = {{b.x - a.x, b.y - a.y, b.z - a.z}, {c.x - a.x, c.y - a.y, c.z - a.z}};
    const double w[3] = {a.x - x.o.x, a.y - x.o.y, a.z - x.o.z};
    const double u[3] = {x.kind == extent::segment ? x.q.x - x.o.x : x.d.x, x.kind == extent::segment ? x.q.y - x.o.y : x.d.y,
                         x.kind == extent::segment ? x.q.z - x.o.z : x.d.z};
    double largest = 0.0;
    for (int k = 0; k < 3; ++k)
        largest = max2(largest, max2(max2(arith::abs(e[0][k]), arith::abs(e[1][k])), max2(arith::abs(w[k]), arith::abs(u[k]))));
    if (!(largest <= 0x1p299)) return certainty::uncertain; // far off, or NaN
    double n[3], T = 0.0, D = 0.0, pT = 0.0, pD = 0.0;
    for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3, l = (k + 2) % 3;
        const double sp = e[0][j] * e[1][l], rp = e[0][l] * e[1][j];
        n[k] = sp - rp;
        const double N = arith::abs(sp) + arith::abs(rp);
        pT += N * arith::abs(w[k]);
        pD += N * arith::abs(u[k]);
    }
    for (int k = 0; k < 3; ++k) T += n[k] * w[k], D += n[k] * u[k];
    const double eT = 0x1p-48 * pT + 0x1p-700, eD = 0x1p-48 * pD + 0x1p-700;
    if (!(arith::abs(D) > 2.0 * eD)) return certainty::uncertain;
    const double t = T / D;
    const double dt = quotient_error(T, eT, D, eD, t);
    const int axis = g.axis;
    const int cu = axis == 0 ? 1 : (axis == 1 ? 2 : 0), cv = axis == 0 ? 2 : (axis == 1 ? 0 : 1);
    const double o[3] = {x.o.x, x.o.y, x.o.z};
    const double px = o[cu] + u[cu] * t, py = o[cv] + u[cv] * t;
    const double rx = (arith::abs(u[cu]) * dt + 0x1p-51 * (arith::abs(u[cu] * t) + arith::abs(px))) * 1.125 + 0x1p-1000;
    const double ry = (arith::abs(u[cv]) * dt + 0x1p-51 * (arith::abs(u[cv] * t) + arith::abs(py))) * 1.125 + 0x1p-1000;
    return polygon2d::rounded_parity(projected_edges(g), px, py, rx, ry);
}

// x crosses H (w the sign of n . u): is the crossing V / D, off the boundary, inside?
template <class K>
[[nodiscard]] constexpr bool crossing_point_inside(K& k, const polygon3& g, const linear3& x, sign w) {
    if (arith::rounded_stage_applies<K>())
        if (const certainty s = rounded_crossing(g, x); s != certainty::uncertain) return s == certainty::yes;
    const point3 a = g.vertices[g.plane_vertices[0]];
    auto T = [=](auto L) { return arith::dot(normal(L, g), arith::lift(L, a) - x.O(L)); };
    auto D = [=](auto L) { return arith::dot(normal(L, g), x.D(L)); };
    auto V = [=](auto L) {
        const auto o = x.O(L);
        const auto u = x.D(L);
        const auto d = D(L);
        const auto s = T(L);
        using R = decltype(o.x * d + u.x * s);
        return arith::v3<R>{o.x * d + u.x * s, o.y * d + u.y * s, o.z * d + u.z * s};
    };
    return inside(k, g, at_homogeneous<decltype(V), decltype(D)>{V, D, w});
}

// The polygon (usable) against o + t u (a segment, ray or line, finite) that meets no edge of the
// polygon: it crosses H at one point V / D inside, or it lies in H and its origin lies inside.
// The shape pairs call this for the edges of a shape X once every polygon edge has been tested
// against X: an edge of X through a polygon edge would have made that test true.
template <class K>
[[nodiscard]] constexpr bool crossing_inside(K& k, const polygon3& g, const linear3& x) {
    sign w = sign::zero;
    switch (plane_contact(k, g, x, w)) {
    case contact::none: return false;
    case contact::lies_in: return inside(k, g, at_double{x.o});
    default: return crossing_point_inside(k, g, x, w);
    }
}
// The polygon (usable) against o + t u (a segment, ray or line, finite): x misses H, or an edge
// meets it, or crossing_inside. An x in H meets the edges in the projection (exact: a coordinate
// dropped, one to one on H), where most orientations are not zero; an x crossing H meets an edge
// only at its crossing point.
template <class K>
[[nodiscard]] constexpr bool linear_meets(K& k, const polygon3& g, const linear3& x) {
    sign w = sign::zero;
    switch (plane_contact(k, g, x, w)) {
    case contact::none: return false;
    case contact::lies_in:
        return any_edge(g,
                        [&](const segment3& e) {
                            const linear3 s = as_linear(e);
                            // the 2D step takes a first object that is not a point
                            if (s.is_point() || x.is_point()) return linear_linear(k, s, x);
                            return linear_linear_2d(k, s, x, g.axis);
                        }) ||
               inside(k, g, at_double{x.o});
    default:
        if (arith::rounded_stage_applies<K>()) // P clearly off every edge too (rounded_crossing)
            if (const certainty s = rounded_crossing(g, x); s != certainty::uncertain) return s == certainty::yes;
        return any_edge(g, [&](const segment3& e) { return linear_linear(k, as_linear(e), x); }) || crossing_point_inside(k, g, x, w);
    }
}

} // namespace polygon3d

namespace polygon2d {
// The centroid (a + b + c) / 3, V / W with W = L(1) + L(1) + L(1).
struct centroid2 {
    point2 a, b, c;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto A = arith::lift(lift, a), B = arith::lift(lift, b), C = arith::lift(lift, c);
        const auto one = lift(1.0);
        return std::pair{arith::v2<decltype(A.x + B.x + C.x)>{A.x + B.x + C.x, A.y + B.y + C.y}, one + one + one};
    }
    // In double, each coordinate within its radius (for rounded_parity): two sums off by at most
    // 2u (|a| + |b| + |c|) together, a third of that after the division, which adds u |p| (u = 2^-53).
    [[nodiscard]] constexpr bool rounded(double& px, double& py, double& rx, double& ry) const {
        px = (a.x + b.x + c.x) / 3.0, py = (a.y + b.y + c.y) / 3.0;
        rx = 0x1p-51 * (arith::abs(a.x) + arith::abs(b.x) + arith::abs(c.x)) * 1.125 + 0x1p-1000;
        ry = 0x1p-51 * (arith::abs(a.y) + arith::abs(b.y) + arith::abs(c.y)) * 1.125 + 0x1p-1000;
        return true;
    }
};
// Does the segment p q meet the open triangle a b c (o = orient2d(a, b, c), not zero)?
template <class K>
[[nodiscard]] constexpr bool meets_open_triangle(K& k, point2 a, point2 b, point2 c, sign o, point2 p, point2 q) {
    auto orient = [&](point2 x, point2 y, point2 z) { return k.sgn([=](auto L) { return poly::orient2d(L, x, y, z); }); };
    auto beyond = [&](point2 x, point2 y) { return orient(x, y, p) != o && orient(x, y, q) != o; }; // p and q on the closed outer side
    if (beyond(a, b) || beyond(b, c) || beyond(c, a)) return false;
    const sign sa = orient(p, q, a), sb = orient(p, q, b), sc = orient(p, q, c);
    const bool pos = sa == sign::positive || sb == sign::positive || sc == sign::positive;
    const bool neg = sa == sign::negative || sb == sign::negative || sc == sign::negative;
    return pos && neg; // else the triangle lies on one closed side of the segment's line
}
} // namespace polygon2d

} // namespace incidence::detail
