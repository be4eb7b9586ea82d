// capsule3 against a set of half-spaces n_i . x <= d_i: the test that capsule_convex_polyhedron,
// capsule_frustum and capsule_kdop share (a k-DOP's slabs as its rows, read exactly).
// Semantics: the closed capsule (the points within |r| of the closed segment ab) and the closed
// half-space set, possibly empty or unbounded (a zero normal: all of space when its offset is >= 0,
// nothing otherwise). Touching counts.
// Method (exact tiers): the capsule meets P iff some pair (x, y), x in P and y on the segment, has
// |x - y| <= r. Take a nearest pair. If y is an end, that end's ball meets P
// (ball_halfspaces.cppm); if x = y, the segment meets P (halfspace_slabs.cppm). Otherwise y is
// inside the segment, x - y is normal to the segment's direction d, and x - y lies in minus the
// cone of the normals of the rows tight at x. With one tight row (or none), x - y = -l n and
// (x - y) . d = 0 give n . d = 0: the segment is parallel to that face, and sliding both points
// along d keeps the distance until y reaches an end or x a second row. So some nearest pair has y
// at an end, x = y, or x on the line of two rows (with d not parallel to it) or at the vertex of
// three; there x is the point of that line nearest the segment's line, or the vertex, and y the
// point of the segment's line nearest x, and both are exact rationals. The test is then:
//   a row with both end balls wholly beyond it: no (the capsule is the hull of its end balls);
//   an end's ball meets P, or the segment meets P: yes;
//   some pair of rows {i, j} (det = |n_i x n_j|^2 > 0) whose line F comes within r of the
//     segment at a point of P: with e0 = (e_i(a), e_j(a)), e_h(p) = n_h . p - d_h, e1 = (n_i . d,
//     n_j . d), G = [[|n_i|^2, n_i . n_j], [n_i . n_j, |n_j|^2]] and q(u, v) = u adj(G) v (degree
//     6): q11 > 0 (d not parallel to F); t* = -q01 / q11 in [0, 1]; x* = X / W with W = det q11,
//     X = (a q11 - d q01) det - N^T adj(G) (e0 q11 - e1 q01) (degree 11), in every other row
//     (degree 12); and r^2 det q11 - (q00 q11 - q01^2) >= 0 (degree 12): yes;
//   some triple {i, j, l} (D = det(n_i, n_j, n_l) != 0) whose vertex V / D (V as in
//     ball_halfspaces.cppm) lies in every other row (degree 5), projects inside the segment
//     (num = (V - a D) . d and D |d|^2 - num of the sign of D or zero, degree 5) and lies within r
//     of it: r^2 D^2 |d|^2 - (|V - a D|^2 |d|^2 - num^2) >= 0 (degree 10): yes;
//   else no. Each such pair and vertex is a point of P within the stated distance of a point of
//   the segment, so a yes is never wrong; the nearest pair above is among them, so a no is right.
// A pair or a triple is one of m (m - 1) / 2 and m (m - 1) (m - 2) / 6: a set of many rows costs
// more where the first tests leave it open.
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.9 (closest points of two
// lines) and 5.5 (the closest-feature case analysis); Boyd and Vandenberghe, Convex Optimization
// (2004), section 5.5.3 (the optimality conditions that give the sliding argument).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/intersects/capsule_frustum.cpp and the other two pairs' tests).
module;
#include <tuple>
export module incidence.detail:engines.capsule_rows;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.ball_halfspaces;
import :engines.halfspace_slabs;

export namespace incidence::detail {

namespace swept_rows {

using ball_rows::excess;

// A point of the line of rows i and j (det > 0) in P and within rad of the segment a + t d,
// t in [0, 1], with d not parallel to the line?
template <class K>
[[nodiscard]] constexpr bool edge_within(K& k, const ball_rows::rows& r, point3 a, point3 b, double rad, unsigned i, unsigned j) {
    const plane3 p = r[i], q = r[j];
    const auto det = [=](auto L) {
        const auto w = arith::cross(arith::lift(L, p.normal), arith::lift(L, q.normal));
        return arith::dot(w, w);
    };
    if (arith::is_zero<arith::hint::often_zero>(k, det)) return false; // parallel normals
    // q(u, v) = u adj(G) v for the 2-vectors e0 (the rows at a) and e1 (along d)
    const auto forms = [=](auto L) {
        const auto np = arith::lift(L, p.normal), nq = arith::lift(L, q.normal);
        const auto d = arith::lift(L, b) - arith::lift(L, a);
        const auto aa = arith::dot(np, np), bb = arith::dot(np, nq), gg = arith::dot(nq, nq);
        const auto u0 = excess(L, p, a), u1 = excess(L, q, a);
        const auto v0 = arith::dot(np, d), v1 = arith::dot(nq, d);
        const auto form = [&](const auto& x0, const auto& x1, const auto& y0, const auto& y1) {
            return gg * x0 * y0 - bb * (x0 * y1 + x1 * y0) + aa * x1 * y1;
        };
        return std::tuple{form(u0, u1, u0, u1), form(u0, u1, v0, v1), form(v0, v1, v0, v1)};
    };
    if (arith::is_zero<arith::hint::often_zero>(k, [=](auto L) { return std::get<2>(forms(L)); })) return false; // d parallel to the line
    if (k.sgn([=](auto L) { return std::get<1>(forms(L)); }) == sign::positive) return false;                    // t* < 0
    if (k.sgn([=](auto L) {
            const auto f = forms(L);
            return std::get<2>(f) + std::get<1>(f);
        }) == sign::negative)
        return false; // t* > 1
    // x* = X / W: X = (a q11 - d q01) det - n_p (g h0 - b h1) - n_q (a h1 - b h0), h = e0 q11 - e1 q01
    const auto point = [=](auto L) {
        const auto np = arith::lift(L, p.normal), nq = arith::lift(L, q.normal);
        const auto A = arith::lift(L, a);
        const auto d = arith::lift(L, b) - A;
        const auto aa = arith::dot(np, np), bb = arith::dot(np, nq), gg = arith::dot(nq, nq);
        const auto f = forms(L);
        const auto h0 = excess(L, p, a) * std::get<2>(f) - arith::dot(np, d) * std::get<1>(f);
        const auto h1 = excess(L, q, a) * std::get<2>(f) - arith::dot(nq, d) * std::get<1>(f);
        const auto dt = det(L);
        return arith::scaled(arith::scaled(A, std::get<2>(f)) - arith::scaled(d, std::get<1>(f)), dt) -
               arith::scaled(np, gg * h0 - bb * h1) - arith::scaled(nq, aa * h1 - bb * h0);
    };
    for (unsigned h = 0; h < r.n; ++h) {
        if (h == i || h == j) continue;
        const plane3 o = r[h];
        if (k.sgn([=](auto L) {
                return arith::dot(arith::lift(L, o.normal), point(L)) - L(o.offset) * L(1.0) * (det(L) * std::get<2>(forms(L)));
            }) == sign::positive)
            return false;
    }
    return k.sgn([=](auto L) {
        const auto f = forms(L);
        return L(rad) * L(rad) * (det(L) * std::get<2>(f)) - (std::get<0>(f) * std::get<2>(f) - std::get<1>(f) * std::get<1>(f));
    }) != sign::negative;
}

// The vertex of rows i, j and l (D != 0) in P and within rad of the segment's inside?
template <class K>
[[nodiscard]] constexpr bool vertex_within(K& k, const ball_rows::rows& r, point3 a, point3 b, double rad, unsigned i, unsigned j,
                                           unsigned l) {
    const plane3 p = r[i], q = r[j], e = r[l];
    const auto det = [=](auto L) { return arith::det3(arith::lift(L, p.normal), arith::lift(L, q.normal), arith::lift(L, e.normal)); };
    const sign sd = arith::sgn<arith::hint::often_zero>(k, det);
    if (sd == sign::zero) return false;
    const auto vertex = [=](auto L) {
        const auto np = arith::lift(L, p.normal), nq = arith::lift(L, q.normal), ne = arith::lift(L, e.normal);
        const auto one = L(1.0);
        return arith::scaled(arith::cross(nq, ne), L(p.offset) * one) + arith::scaled(arith::cross(ne, np), L(q.offset) * one) +
               arith::scaled(arith::cross(np, nq), L(e.offset) * one);
    };
    const auto rel = [=](auto L) { return vertex(L) - arith::scaled(arith::lift(L, a), det(L)); }; // (V / D - a) D
    const auto along = [=](auto L) { return arith::dot(rel(L), arith::lift(L, b) - arith::lift(L, a)); };
    const auto of_d = [sd](sign s) { return s == sign::zero || s == sd; };
    if (!of_d(k.sgn(along))) return false; // t* < 0
    if (!of_d(k.sgn([=](auto L) {
            const auto d = arith::lift(L, b) - arith::lift(L, a);
            return det(L) * arith::dot(d, d) - along(L);
        })))
        return false; // t* > 1
    for (unsigned h = 0; h < r.n; ++h) {
        if (h == i || h == j || h == l) continue;
        const plane3 o = r[h];
        if (!of_d(k.sgn([=](auto L) { return L(o.offset) * L(1.0) * det(L) - arith::dot(arith::lift(L, o.normal), vertex(L)); })))
            return false;
    }
    return k.sgn([=](auto L) {
        const auto d = arith::lift(L, b) - arith::lift(L, a);
        const auto dd = arith::dot(d, d);
        const auto D = det(L);
        const auto t = along(L);
        const auto w = rel(L);
        return L(rad) * L(rad) * (D * D) * dd - (arith::dot(w, w) * dd - t * t);
    }) != sign::negative;
}

// Does the capsule of segment ab and radius rad (>= 0) meet the set of the m half-spaces (finite:
// the caller checks)?
template <class K>
[[nodiscard]] constexpr bool meets(K& k, const plane3* planes, int m, point3 a, point3 b, double rad) {
    const ball_rows::rows r(planes, m);
    if (r.empty) return false;
    for (unsigned x = 0; x < r.n; ++x) { // both end balls wholly beyond one row
        const plane3 h = r[x];
        const auto apart = [&](point3 c) {
            return k.sgn([=](auto L) { return excess(L, h, c); }) == sign::positive && k.sgn([=](auto L) {
                const auto e = excess(L, h, c);
                const auto n = arith::lift(L, h.normal);
                return e * e - L(rad) * L(rad) * arith::dot(n, n);
            }) == sign::positive;
        };
        if (apart(a) && apart(b)) return false;
    }
    if (ball_rows::meets(k, planes, m, sphere3{a, rad}) || ball_rows::meets(k, planes, m, sphere3{b, rad})) return true;
    if (halfspaces::halfspaces<slab_extent::segment>(k, planes, m, a, vec3{0, 0, 0}, b)) return true;
    if (a == b) return false; // a ball: its one end decided
    for (unsigned i = 0; i < r.n; ++i)
        for (unsigned j = i + 1; j < r.n; ++j)
            if (edge_within(k, r, a, b, rad, i, j)) return true;
    for (unsigned i = 0; i < r.n; ++i)
        for (unsigned j = i + 1; j < r.n; ++j)
            for (unsigned l = j + 1; l < r.n; ++l)
                if (vertex_within(k, r, a, b, rad, i, j, l)) return true;
    return false;
}

} // namespace swept_rows

} // namespace incidence::detail
