// capsule3 (a segment swept by a ball) against the shapes: the segment's distance to the shape
// against the radius. The engine every capsule pair shares.
// Semantics: the closed capsule, the points within |r| of the closed segment ab (a = b: a ball;
// an unchecked negative radius acts as |r|); two capsules, or a capsule and a ball, meet when the
// segments (or the segment and the centre) lie within |r1| + |r2| (the sum formed exactly, inside
// the signs). Touching counts.
// Method (exact tiers): the minimum of |x - y| over x on the segment and y on the shape is reached
// at an end of the segment, or with x inside the segment and y on an edge of the shape, or at an
// intersection (distance 0): with x and y both inside a segment and a face, x - y is normal to both,
// so the segment is parallel to the face and sliding along it keeps the distance until x reaches an
// end or y an edge. So a capsule meets
//   a point, ball, flat shape or solid S: iff an end's ball meets S (ball_flat.cppm, ball_obb.cppm,
//            sphere.cppm), or the segment meets S, or the segment lies within R of an edge of S;
//   a linear shape (two linear shapes, linear_within): an end of either (a segment's two, a ray's
//            origin) within R of the other (ball_flat's segment, ray and line test), or, for lines
//            that are not parallel (den = |d1 x d2|^2 > 0, degree 4), the closest points of the two
//            lines inside both parameter ranges (0 <= b e - c d <= den and 0 <= a e - b d <= den for
//            segments, one-sided for rays, degree 4, with a = d1 . d1, b = d1 . d2, c = d2 . d2,
//            d = d1 . w, e = d2 . w, w = o1 - o2) and (w . (d1 x d2))^2 <= R^2 den (degree 6); two
//            parallel lines: the distance of one's origin to the other.
//   a plane: the ends on both sides of it or on it (two signs of degree 2), or an end's ball meets it.
// Source: Ericson, Real-Time Collision Detection (2005), sections 4.5.1 (capsules), 5.1.8-5.1.9
// (closest points of two lines, of two segments) and 5.3.x (segment against the shapes);
// Eberly, Geometric Tools, "Distance between two line segments" (2020) for the parameter ranges.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/intersects/capsule_capsule.cpp and the other capsule pairs' tests).
module;
#include <array>
export module incidence.detail:engines.capsule;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.ball_flat;

export namespace incidence::detail {

namespace swept {

// The ends of a linear shape: a segment's two, a ray's origin, a line's none.
struct ends {
    std::array<point3, 2> p{};
    int n = 0;
};
[[nodiscard]] constexpr ends ends_of(const linear3& s) {
    if (s.kind == extent::segment) return {{s.o, s.q}, 2};
    if (s.kind == extent::ray) return {{s.o, s.o}, 1};
    return {};
}

// Does the linear shape s lie within R of the linear shape t (both finite)? s_ends_apart: the
// caller knows that s's ends lie farther than R from t (it tested them against a shape holding t).
template <class K, class R>
[[nodiscard]] constexpr bool linear_within(K& k, const linear3& s, const linear3& t, R rad, bool s_ends_apart = false) {
    const ends es = ends_of(s), et = ends_of(t);
    for (int i = 0; i < es.n && !s_ends_apart; ++i)
        if (ball_flat::meets(k, t, es.p[static_cast<unsigned>(i)], rad)) return true;
    for (int i = 0; i < et.n; ++i)
        if (ball_flat::meets(k, s, et.p[static_cast<unsigned>(i)], rad)) return true;
    if (s.is_point()) return ball_flat::meets(k, t, s.o, rad);
    if (t.is_point()) return ball_flat::meets(k, s, t.o, rad);
    const auto normal = [=](auto L) { return arith::cross(s.D(L), t.D(L)); };
    const auto den = [=](auto L) {
        const auto n = normal(L);
        return arith::dot(n, n);
    };
    if (arith::is_zero<arith::hint::often_zero>(k, den)) {
        // parallel: with an end on either, sliding reaches it (tried above); two lines: one's origin
        return es.n == 0 && et.n == 0 && ball_flat::meets(k, t, s.o, rad);
    }
    // the closest points' parameters times den: s* den = b e - c d, t* den = a e - b d
    const auto terms = [=](auto L) {
        const auto d1 = s.D(L), d2 = t.D(L);
        const auto w = s.O(L) - t.O(L);
        const auto b = arith::dot(d1, d2), d = arith::dot(d1, w), e = arith::dot(d2, w);
        return std::array{b * e - arith::dot(d2, d2) * d, arith::dot(d1, d1) * e - b * d};
    };
    const linear3* shapes[2] = {&s, &t};
    for (unsigned x = 0; x < 2; ++x) {
        const linear3& g = *shapes[x];
        if (g.bounded_below() && k.sgn([=](auto L) { return terms(L)[x]; }) == sign::negative) return false;
        if (g.bounded_above() && k.sgn([=](auto L) { return den(L) - terms(L)[x]; }) == sign::negative) return false;
    }
    return k.sgn([=](auto L) {
        const auto g = arith::dot(s.O(L) - t.O(L), normal(L));
        return ball_flat::squared(L, rad) * den(L) - g * g;
    }) != sign::negative;
}

// Does the plane p (finite) come within R of the segment ab?
template <class K, class R>
[[nodiscard]] constexpr bool plane_within(K& k, const plane3& p, point3 a, point3 b, R rad) {
    const vec3 n = p.normal;
    if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0) return p.offset == 0.0;
    const auto side = [&](point3 x) {
        return k.sgn([=](auto L) { return arith::dot(arith::lift(L, n), arith::lift(L, x)) - L(p.offset) * L(1.0); });
    };
    const sign sa = side(a), sb = side(b);
    if (sa == sign::zero || sb == sign::zero || sa != sb) return true; // the segment meets the plane
    return ball_flat::meets(k, p, a, rad) || ball_flat::meets(k, p, b, rad);
}

// Does the segment ab come within R of one of the n edges (pairs of points)? The caller has found
// a and b farther than R from the shape the edges bound.
template <class K, class R>
[[nodiscard]] constexpr bool near_edges(K& k, point3 a, point3 b, const point3 (*edges)[2], int n, R rad) {
    const linear3 s = as_linear(segment3{a, b});
    for (int i = 0; i < n; ++i)
        if (linear_within(k, s, as_linear(segment3{edges[i][0], edges[i][1]}), rad, true)) return true;
    return false;
}

} // namespace swept

} // namespace incidence::detail
