// point2 against polygon2, contains(polygon, point), and the engine every polygon pair shares.
// Semantics: the polygon's point set is its edges together with the points of odd crossing
// parity (shapes/polygon2.cppm); a point on an edge counts.
// Method (exact tiers): any other shape X (connected) meets that set iff it meets an edge, or
// else lies wholly off the boundary, where one point p of X decides by the parity of crossings of
// the ray from p along +x. An edge a -> b counts when exactly one end lies above p (a.y > p.y
// against b.y > p.y: the half-open rule, so a ray through a vertex counts it once or not at all,
// as the two edges there rise and fall) and p lies left of the edge directed upward: the sign of
// orient2d(a, b, p) (degree 2) is positive for a rising edge, negative for a falling one. p is
// off the boundary, so that sign is never zero for a counted edge. Edges whose bounding box
// misses the other shape's are skipped (comparisons).
// Source: Haines, "Point in polygon strategies", Graphics Gems IV (1994), the crossings test
// with the half-open rule, its comparison of a rounded crossing abscissa replaced by the exact
// orientation sign; the edges through the 2D linear pairs (segment_segment.cppm).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-44 of its
// permanent (tests/query/point2_polygon2.cpp).
//
// polygon2 against segment2.
// Semantics: the polygon's edges and the points of odd crossing parity (shapes/polygon2.cppm)
// against the closed segment; touching an edge or a vertex counts.
// Method (exact tiers): the polygon engine (point2_polygon2.cppm): an edge meets the segment
// (segment2_segment2's signs, degree <= 2), or else the segment lies off the boundary and its
// end point a decides by exact crossing parity.
// contains: every point of the segment in the set. The segment is split where it meets an edge
// (segment_pieces.cppm): t = E x (x - a) / E x (b - a) (degree 2 over 2) where an edge p q crosses
// it (E = q - p, x = p), or for an edge along the segment's line the parameters of p and q (E a
// unit axis, L(1) - L(0)); each open piece lies on such an edge or off the boundary, where one
// point decides by the crossing parity, each comparison multiplied through by the point's weight
// W > 0: a + t (b - a) for a double t (degree 3), or the exact midpoint (degree 6); in a filter
// pass the first goes through point2_polygon2's rounded_parity (the point in double within a
// proven radius) before the signs. The same
// engine serves contains(polygon3, segment3 | triangle3) in the projection (polygon_segment.cppm,
// polygon_triangle.cppm). any_odd_piece (the boundary covered an odd number of times along an
// edge) serves contains(polygon2, circle2) (contains/circle2_pairs.cppm).
// Source: Haines, "Point in polygon strategies", Graphics Gems IV (1994), the crossings test.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-44 of its
// permanent (tests/query/polygon2_segment2.cpp).
module;
#include <cstddef>
#include <utility>
#include <vector>
export module incidence.detail:engines.polygon2;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :engines.segment_pieces;

export namespace incidence::detail {

namespace polygon2d {

// Ring ends valid and every vertex finite (comparisons only).
[[nodiscard]] constexpr bool well_formed(const polygon2& g) {
    if (!g.indices_valid()) return false;
    for (std::size_t i = 0; i < g.vertices.size(); ++i)
        if (!finite(g.vertices[i])) return false;
    return true;
}
// The bounds of points and shapes, and their overlap (segment_segment.cppm), also under this name.
using detail::bounds;
using detail::box2;
using detail::boxes_meet;
[[nodiscard]] constexpr box2 bounds(const polygon2& g) { return bounds(g.vertices.data(), g.vertices.size()); }
[[nodiscard]] constexpr bool in_box(const box2& b, point2 p) { return boxes_meet(b, box2{p, p}); }

// Calls f(a, b) for every edge a -> b of every ring (a well-formed polygon) until it returns true.
template <class F>
[[nodiscard]] constexpr bool any_edge(const polygon2& g, const F& f) {
    for (std::size_t r = 0; r < g.rings(); ++r) {
        const std::size_t b = g.ring_begin(r), e = g.ring_end(r);
        for (std::size_t j = b; j < e; ++j)
            if (f(g.vertices[j], g.vertices[polygon2::next(j, b, e)])) return true;
    }
    return false;
}

// The crossing parity at p, off the boundary (odd: inside), without the bounding-box test.
template <class K>
[[nodiscard]] constexpr bool odd_crossings(K& k, const polygon2& g, point2 p) {
    bool odd = false;
    (void)any_edge(g, [&](point2 a, point2 b) {
        const bool a_above = a.y > p.y, b_above = b.y > p.y;
        if (a_above == b_above) return false;
        if (a.x < p.x && b.x < p.x) return false; // both ends left of p: the ray misses it
        const sign s = k.sgn([=](auto L) { return poly::orient2d(L, a, b, p); });
        if (s == (b_above ? sign::positive : sign::negative)) odd = !odd;
        return false;
    });
    return odd;
}

// Is p, off the boundary, inside (odd crossings)?
template <class K>
[[nodiscard]] constexpr bool inside(K& k, const polygon2& g, point2 p) {
    return in_box(bounds(g), p) && odd_crossings(k, g, p);
}

// The rounded stage of the crossing test (a filter pass at run time, arith::rounded_stage_applies):
// inside()'s test on a point P known to within (rx, ry) of (px, py), each comparison decided only
// when clear by more than its bound; edges(f) calls f(a, b) for every edge until it returns true.
// yes inside, no outside, uncertain when some comparison is not clear (or a value is not finite). Where it
// decides, P is also clearly off every edge (both ends clearly above or below it, both clearly left
// of it, or a clearly nonzero orientation). The orientation (b - a) x (P - a) is off by at most
// |b_x - a_x| ry + |b_y - a_y| rx plus 4u times its permanent (u = 2^-53), widened by 1/8 for its
// own rounding, plus 2^-1000 for underflow; a radius is at least its bound widened by 1/8, which
// also covers the rounding of a - p against it. Source: Haines, "Point in polygon strategies",
// Graphics Gems IV (1994) (the crossings test); Higham, Accuracy and Stability of Numerical
// Algorithms, 2nd ed. (2002), section 3.1 (the bounds).
template <class Edges>
[[nodiscard]] constexpr certainty rounded_parity(const Edges& edges, double px, double py, double rx, double ry) {
    bool odd = false;
    const bool unclear = edges([&](point2 a, point2 b) {
        const double da = a.y - py, db = b.y - py;
        if (!(da > ry || da < -ry) || !(db > ry || db < -ry)) return true;
        const bool a_above = da > 0.0, b_above = db > 0.0;
        if (a_above == b_above || (px - a.x > rx && px - b.x > rx)) return false;
        const double dx = b.x - a.x, dy = b.y - a.y;
        const double p1 = dx * (py - a.y), p2 = dy * (px - a.x);
        const double v = p1 - p2;
        const double ev = (arith::abs(dx) * ry + arith::abs(dy) * rx + 0x1p-50 * (arith::abs(p1) + arith::abs(p2))) * 1.125 + 0x1p-1000;
        if (!(v > ev || v < -ev)) return true;
        if ((v > 0.0) == b_above) odd = !odd;
        return false;
    });
    return unclear ? certainty::uncertain : (odd ? certainty::yes : certainty::no);
}

// The edges along the segment p q (p != q, an edge of g) cover each of its points some number of
// times, p q itself once. test(u, v) is called for the pieces u v of p q (between consecutive ends
// of those edges) covered an odd number of times, until it returns true: the boundary that
// separates odd from even crossing parity (an evenly covered piece separates nothing). Edges along
// p q: both ends on its line (orientation signs of degree 2) and an overlap beyond one point; a
// point's place along the line is one of its coordinates (x unless the line is vertical: exact).
// Only when some other edge lies along p q (never on a simple boundary) are the pieces formed: a
// scan of the edges per piece end.
template <class K, class Test>
[[nodiscard]] constexpr bool any_odd_piece(K& k, const polygon2& g, point2 p, point2 q, const Test& test) {
    const bool by_x = p.x != q.x;
    const auto key = [by_x](point2 w) { return by_x ? w.x : w.y; };
    const point2 first = key(p) < key(q) ? p : q, last = key(p) < key(q) ? q : p;
    const double lo = key(first), hi = key(last);
    const box2 pq_box = bounds(segment2{p, q}); // an edge along p q meets it where they overlap
    // f(a, b, ka, kb) for each edge along p q, ka < kb its ends' places, until f returns true
    const auto along = [&](const auto& f) {
        return any_edge(g, [&](point2 a, point2 b) {
            const double ka = key(a) < key(b) ? key(a) : key(b), kb = key(a) < key(b) ? key(b) : key(a);
            if (!(ka < hi && kb > lo)) return false;                       // no overlap beyond a point
            if (!boxes_meet(bounds(segment2{a, b}), pq_box)) return false; // off p q's box: not along p q
            const auto on_line = [&](point2 w) { return k.sgn([=](auto L) { return poly::orient2d(L, p, q, w); }) == sign::zero; };
            if (!on_line(a) || !on_line(b)) return false;
            return f(a, b, ka, kb);
        });
    };
    int edges_along = 0;
    (void)along([&](point2, point2, double, double) { return ++edges_along > 1; });
    if (edges_along <= 1) return test(p, q);
    // the piece from the end u (place ku) to the next end: tested when covered an odd number of times
    const auto piece_from = [&](double ku, point2 u) {
        double kv = hi;
        point2 v = last;
        (void)along([&](point2 a, point2 b, double, double) {
            const point2 ends[2] = {a, b};
            for (const point2 w : ends)
                if (key(w) > ku && key(w) < kv) kv = key(w), v = w;
            return false;
        });
        int cover = 0;
        (void)along([&](point2, point2, double ka, double kb) {
            cover += ka <= ku && kb >= kv;
            return false;
        });
        return cover % 2 == 1 && test(u, v);
    };
    if (piece_from(lo, first)) return true;
    return along([&](point2 a, point2 b, double, double) {
        const point2 ends[2] = {a, b};
        for (const point2 w : ends)
            if (key(w) > lo && key(w) < hi && piece_from(key(w), w)) return true;
        return false;
    });
}

// The polygon's point set against the connected shape x: an edge meets x, or p (a point of x)
// lies inside. The caller has checked the polygon well formed and x finite. With x's bounding
// box `xb` (bounded shapes), edges whose own box misses it are skipped (comparisons).
template <class K, class Meets>
[[nodiscard]] constexpr bool polygon_meets(K& k, const polygon2& g, const Meets& meets, point2 p, const box2* xb = nullptr) {
    const bool edge = any_edge(g, [&](point2 a, point2 b) {
        if (xb != nullptr) {
            const point2 v[2] = {a, b};
            if (!boxes_meet(bounds(v, 2), *xb)) return false;
        }
        return meets(segment2{a, b});
    });
    return edge || inside(k, g, p);
}

} // namespace polygon2d

namespace polygon2d {

// A parameter along a + t (b - a): N = E x (x - a), D = E x (b - a), E = e1 - e0; both negated
// when `flip`, so that D > 0.
struct param2 {
    point2 x, e0, e1;
    bool flip = false;
    template <class L>
    [[nodiscard]] constexpr auto fraction(L lift, point2 a, point2 b) const {
        const auto E = arith::lift(lift, e1) - arith::lift(lift, e0);
        const auto A = arith::lift(lift, a);
        const auto n = arith::cross(E, arith::lift(lift, x) - A), d = arith::cross(E, arith::lift(lift, b) - A);
        return flip ? std::pair{-n, -d} : std::pair{n, d};
    }
};
// The point a + t (b - a) for a double t, V / W with W = L(1) (a constant lifted as an input).
struct point2_at {
    point2 a, b;
    double t;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto W = lift(1.0), T = lift(t);
        const auto A = arith::lift(lift, a);
        const auto D = arith::lift(lift, b) - A;
        using U = decltype(W * A.x + T * D.x);
        return std::pair{arith::v2<U>{W * A.x + T * D.x, W * A.y + T * D.y}, W};
    }
    // In double, each coordinate within its radius (for rounded_parity): the difference, the
    // product and the sum, each off by at most u times its result (u = 2^-53), 2^-51 covers them.
    [[nodiscard]] constexpr bool rounded(double& px, double& py, double& rx, double& ry) const {
        const double mx = t * (b.x - a.x), my = t * (b.y - a.y);
        px = a.x + mx, py = a.y + my;
        rx = 0x1p-51 * (arith::abs(mx) + arith::abs(px)) * 1.125 + 0x1p-1000;
        ry = 0x1p-51 * (arith::abs(my) + arith::abs(py)) * 1.125 + 0x1p-1000;
        return true;
    }
};
// The midpoint of a + t (b - a) between the parameters lo and hi, V / W with W = 2 D_lo D_hi > 0.
struct point2_mid {
    point2 a, b;
    param2 lo, hi;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        const auto [n1, d1] = lo.fraction(lift, a, b);
        const auto [n2, d2] = hi.fraction(lift, a, b);
        const auto W = d1 * d2 + d1 * d2;
        const auto M = n1 * d2 + n2 * d1;
        const auto A = arith::lift(lift, a);
        const auto D = arith::lift(lift, b) - A;
        using T = decltype(W * A.x + M * D.x);
        return std::pair{arith::v2<T>{W * A.x + M * D.x, W * A.y + M * D.y}, W};
    }
};

// Is the point q = V / W (W > 0, q.weighted(L) gives {V, W}), off the boundary, inside? The
// crossing test of inside() with every comparison multiplied through by W; edges(f) calls f(p, q)
// for every edge until it returns true.
// A point that can say where it is in double (q.rounded) goes to rounded_parity first, in a filter
// pass at run time.
template <class K, class Edges, class Q>
[[nodiscard]] constexpr bool inside_weighted(K& k, const Edges& edges, const Q& q) {
    if constexpr (requires(double x) { q.rounded(x, x, x, x); })
        if (arith::rounded_stage_applies<K>()) {
            double px = 0.0, py = 0.0, rx = 0.0, ry = 0.0;
            if (q.rounded(px, py, rx, ry))
                if (const certainty s = rounded_parity(edges, px, py, rx, ry); s != certainty::uncertain) return s == certainty::yes;
        }
    bool odd = false;
    (void)edges([&](point2 a, point2 b) {
        auto above = [&](point2 w) { // w.y > V.y / W
            return k.sgn([=](auto L) {
                const auto [V, W] = q.weighted(L);
                return L(w.y) * W - V.y;
            }) == sign::positive;
        };
        const bool a_above = above(a), b_above = above(b);
        if (a_above == b_above) return false;
        auto left = [&](point2 w) { // w.x < V.x / W, proven (a skip only)
            return arith::sgn<arith::hint::optional>(k, [=](auto L) {
                       const auto [V, W] = q.weighted(L);
                       return V.x - L(w.x) * W;
                   }) == sign::positive;
        };
        if (left(a) && left(b)) return false; // both ends left of q: the ray misses the edge
        // orient2d(a, b, V / W) times W
        const sign s = k.sgn([=](auto L) {
            const auto [V, W] = q.weighted(L);
            return (L(b.x) - L(a.x)) * (V.y - L(a.y) * W) - (L(b.y) - L(a.y)) * (V.x - L(a.x) * W);
        });
        if (s == (b_above ? sign::positive : sign::negative)) odd = !odd;
        return false;
    });
    return odd;
}

// Is every point of the segment a b (a != b, finite) in the set of the polygon whose edges
// edges(f) lists (f(p, q) until it returns true)?
template <class K, class Edges>
[[nodiscard]] constexpr bool segment_inside(K& k, const Edges& edges, point2 a, point2 b) {
    const point2 ends[2] = {a, b};
    const box2 sb = bounds(ends, 2);
    auto fraction = [a, b](auto L, const param2& p) { return p.fraction(L, a, b); };
    // a unit axis u with u x (b - a) != 0: (1, 0) x d = d.y, (0, 1) x d = -d.x
    const point2 o{0.0, 0.0}, u = a.y != b.y ? point2{1.0, 0.0} : point2{0.0, 1.0};
    std::vector<param2> params;
    std::vector<std::pair<point2, point2>> along; // edges on the segment's line
    bool met = false;
    auto keep = [&](const param2& p) { return pieces::keep(k, fraction, p, params); };
    (void)edges([&](point2 p, point2 q) {
        const point2 v[2] = {p, q};
        if (!boxes_meet(bounds(v, 2), sb) || !linear_linear(k, as_linear(segment2{a, b}), as_linear(segment2{p, q}))) return false;
        met = true;
        if (!keep(param2{p, p, q})) { // parallel to the segment and meeting it: along its line
            if (p.x != q.x || p.y != q.y) along.push_back({p, q});
            (void)keep(param2{p, o, u}), (void)keep(param2{q, o, u});
        }
        return false;
    });
    if (!met) return inside_weighted(k, edges, point2_at{a, b, 0.0}); // wholly off the boundary
    const bool flip = a.y != b.y ? b.y < a.y : b.x > a.x;             // the sign of u x (b - a)
    const param2 start{a, o, u, flip}, end{b, o, u, flip};
    auto decide = [&](const auto& q) {
        for (const auto& [p, r] : along) { // on the edge p r: (V - W p) . (r - p) >= 0 and (V - W r) . (p - r) >= 0
            auto toward = [&](point2 x, point2 y) {
                return k.sgn([=](auto L) {
                    const auto [V, W] = q.weighted(L);
                    return (V.x - L(x.x) * W) * (L(y.x) - L(x.x)) + (V.y - L(x.y) * W) * (L(y.y) - L(x.y));
                });
            };
            if (toward(p, r) != sign::negative && toward(r, p) != sign::negative) return true;
        }
        return inside_weighted(k, edges, q);
    };
    return pieces::all_pieces(
        k, params, start, end, fraction, [&](double t) { return decide(point2_at{a, b, t}); },
        [&](const param2& lo, const param2& hi) { return decide(point2_mid{a, b, lo, hi}); });
}

} // namespace polygon2d

} // namespace incidence::detail
