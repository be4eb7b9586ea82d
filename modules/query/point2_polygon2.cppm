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
module;
#include <cstddef>
export module incidence.query:point2_polygon2;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :segment_segment;

export namespace incidence::pair {

namespace polyq {

// Ring ends valid and every vertex finite (comparisons only).
[[nodiscard]] constexpr bool well_formed(const polygon2& g) {
    if (!g.indices_valid()) return false;
    for (std::size_t i = 0; i < g.vertices.size(); ++i)
        if (!finite(g.vertices[i])) return false;
    return true;
}
// The bounds of points and shapes, and their overlap (segment_segment.cppm), also under this name.
using pair::bounds;
using pair::box2;
using pair::boxes_meet;
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

// Is p, off the boundary, inside (odd crossings)?
template <class K>
[[nodiscard]] constexpr bool inside(K& k, const polygon2& g, point2 p) {
    if (!in_box(bounds(g), p)) return false;
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

// The rounded stage of the crossing test (a filter pass at run time, arith::rounded_stage_applies):
// inside()'s test on a point P known to within (rx, ry) of (px, py), each comparison decided only
// when clear by more than its bound; edges(f) calls f(a, b) for every edge until it returns true.
// 1 inside, 0 outside, -1 when some comparison is not clear (or a value is not finite). Where it
// decides, P is also clearly off every edge (both ends clearly above or below it, both clearly left
// of it, or a clearly nonzero orientation). The orientation (b - a) x (P - a) is off by at most
// |b_x - a_x| ry + |b_y - a_y| rx plus 4u times its permanent (u = 2^-53), widened by 1/8 for its
// own rounding, plus 2^-1000 for underflow; a radius is at least its bound widened by 1/8, which
// also covers the rounding of a - p against it. Source: Haines, "Point in polygon strategies",
// Graphics Gems IV (1994) (the crossings test); Higham, Accuracy and Stability of Numerical
// Algorithms, 2nd ed. (2002), section 3.1 (the bounds).
template <class Edges>
[[nodiscard]] constexpr int rounded_parity(const Edges& edges, double px, double py, double rx, double ry) {
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
    return unclear ? -1 : (odd ? 1 : 0);
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

} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point2& p, const polygon2& g) {
    if (!polyq::well_formed(g) || !finite(p) || !polyq::in_box(polyq::bounds(g), p)) return false;
    const polyq::box2 xb{p, p};
    return polyq::polygon_meets(k, g, [&](const segment2& e) { return linear_linear(k, as_linear(p), as_linear(e)); }, p, &xb);
}
// contains(polygon, point): the same set.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const polygon2& g, const point2& p) { return intersects(k, p, g); }

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const point2&, const polygon2&);
extern template bool contains(arith::exact_kernel&, const polygon2&, const point2&);
} // namespace incidence::pair
