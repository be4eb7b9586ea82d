// line3 against point3.
// Semantics: A line (a zero direction: its origin point) and a point: the point lies on the line.
// Method (exact tiers): p lies on the line through o with direction d != 0 iff (p - o) x d = 0:
// three signs of degree 2, the first nonzero one says no (with d = 0, p = o by comparisons).
// The linear pairs' shared body (linear_linear in segment_segment.cppm) decides the same, slower
// (12.2 ns against CGAL Epick's 42.9 on random input, measured before this body).
// Source: Schneider and Eberly, Geometric Tools for Computer Graphics (2003), section 11.1.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/line_point.cpp).
export module incidence.query:line_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const point3& p) {
    if (!finite(l) || !finite(p)) return false;
    const point3 o = l.origin;
    const vec3 d = l.direction;
    if (d.x == 0.0 && d.y == 0.0 && d.z == 0.0)
        return arith::compare(k, p.x, o.x) == sign::zero && arith::compare(k, p.y, o.y) == sign::zero &&
               arith::compare(k, p.z, o.z) == sign::zero;
    // component i of (p - o) x d: (p - o)_j d_l - (p - o)_l d_j, (i, j, l) cyclic; a line and a
    // point in one plane z = c make the first two zero by structure (arith::structural_zero)
    if (!arith::structural_zero(k, [=](auto L) { return (L(p.y) - L(o.y)) * L(d.z) - (L(p.z) - L(o.z)) * L(d.y); })) return false;
    if (!arith::structural_zero(k, [=](auto L) { return (L(p.z) - L(o.z)) * L(d.x) - (L(p.x) - L(o.x)) * L(d.z); })) return false;
    return arith::is_zero(k, [=](auto L) { return (L(p.x) - L(o.x)) * L(d.y) - (L(p.y) - L(o.y)) * L(d.x); });
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const line3&, const point3&);
} // namespace incidence::pair
