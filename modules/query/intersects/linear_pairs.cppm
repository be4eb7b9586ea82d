// intersects: linear_pairs
module;
#include <cstddef>
export module incidence.detail:intersects.linear_pairs;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :exactly;

export namespace incidence::detail {

// segment3 against segment3, and the body every pair of linear objects shares: points, segments,
// rays and lines against each other (line_line, line_point, line_ray, line_segment, point_point,
// point_ray, point_segment, ray_ray, ray_segment, segment_segment), the linear object of
// ray_triangle, segment_triangle and line_triangle, and the same ten pairs in the plane
// (line2_line2 ... segment2_segment2, where the projection below is the identity).
// Semantics: closed sets. A segment includes its end points, a ray its origin; a segment with
// equal end points, a ray or a line with a zero direction, is its one point. Touching at an end
// point counts; collinear overlaps (even in one point) count.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const segment3& s, const segment3& t) {
    if (before(t, s)) return linear_pair(k, t, s);
    return linear_pair(k, s, t);
}

// line2 against line2.
// Semantics: Two lines in the plane (a zero direction: the origin point); they meet unless parallel and distinct.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line2& l, const line2& m) {
    if (before(m, l)) return linear_linear(k, as_linear(m), as_linear(l));
    return linear_linear(k, as_linear(l), as_linear(m));
}

// line2 against point2.
// Semantics: A line and a point in the plane: the point lies on the line.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line2& l, const point2& p) {
    return linear_linear(k, as_linear(l), as_linear(p));
}

// line2 against segment2.
// Semantics: A line and a closed segment (end points included; equal end points: a point) in the plane.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line2& l, const segment2& s) {
    return linear_linear(k, as_linear(l), as_linear(s));
}

// line2 against ray2.
// Semantics: A line and a closed ray (origin included) in the plane.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line2& l, const ray2& r) {
    return linear_linear(k, as_linear(l), as_linear(r));
}

// line3 against line3.
// Semantics: Two lines (a zero direction: the line is its origin point). Lines meet iff they are coplanar and not parallel, or the same line.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const line3& m) {
    if (before(m, l)) return linear_linear(k, as_linear(m), as_linear(l));
    return linear_linear(k, as_linear(l), as_linear(m));
}

// line3 against point3.
// Semantics: A line (a zero direction: its origin point) and a point: the point lies on the line.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const point3& p) {
    if (!finite(l) || !finite(p)) return false;
    const point3 o = l.origin;
    const vec3 d = l.direction;
    if (d.x == 0.0 && d.y == 0.0 && d.z == 0.0)
        return arith::compare(k, p.x, o.x) == sign::zero && arith::compare(k, p.y, o.y) == sign::zero &&
               arith::compare(k, p.z, o.z) == sign::zero;
    // component i of (p - o) x d: (p - o)_j d_l - (p - o)_l d_j, (i, j, l) cyclic; a line and a
    // point in one plane z = c make the first two zero by structure (hint::structural)
    if (!arith::is_zero<arith::hint::structural>(k, [=](auto L) { return (L(p.y) - L(o.y)) * L(d.z) - (L(p.z) - L(o.z)) * L(d.y); }))
        return false;
    if (!arith::is_zero<arith::hint::structural>(k, [=](auto L) { return (L(p.z) - L(o.z)) * L(d.x) - (L(p.x) - L(o.x)) * L(d.z); }))
        return false;
    return arith::is_zero(k, [=](auto L) { return (L(p.x) - L(o.x)) * L(d.y) - (L(p.y) - L(o.y)) * L(d.x); });
}

// line3 against ray3.
// Semantics: A line and a closed ray (origin included); a zero direction is the origin point.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const ray3& r) {
    return linear_linear(k, as_linear(l), as_linear(r));
}

// line3 against segment3.
// Semantics: A line and a closed segment (end points included; equal end points: a point).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const segment3& s) {
    return linear_linear(k, as_linear(l), as_linear(s));
}

// segment2 against segment2.
// Semantics: Two closed segments in the plane; touching at an end point and collinear overlaps (even in one point) count.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const segment2& s, const segment2& t) {
    if (!finite(s.a) || !finite(s.b) || !finite(t.a) || !finite(t.b)) return false; // no shape
    if (boxes_apart(k, s, t)) return false;                                         // exact, and cheap on the commonest no
    // In the filter pass an unproven sign (an end point on the other's line, often exactly) is
    // settled where it arises (hint::often_zero) rather than by rerunning the pair.
    auto orient = [&](point2 p, point2 q, point2 r) {
        return arith::sgn<arith::hint::often_zero>(k, [=](auto L) { return poly::orient2d(L, p, q, r); });
    };
    // r, on the line p q, lies on the closed segment p q iff it lies in its bounding box
    auto within = [](point2 p, point2 q, point2 r) {
        return (p.x <= q.x ? p.x <= r.x && r.x <= q.x : q.x <= r.x && r.x <= p.x) &&
               (p.y <= q.y ? p.y <= r.y && r.y <= q.y : q.y <= r.y && r.y <= p.y);
    };
    const point2 a = s.a, b = s.b, c = t.a, d = t.b;
    const sign o1 = orient(a, b, c), o2 = orient(a, b, d);
    if (o1 == o2 && o1 != sign::zero) return false;
    const sign o3 = orient(c, d, a), o4 = orient(c, d, b);
    if (o3 == o4 && o3 != sign::zero) return false;
    if (o1 != sign::zero && o2 != sign::zero && o3 != sign::zero && o4 != sign::zero) return true;
    return (o1 == sign::zero && within(a, b, c)) || (o2 == sign::zero && within(a, b, d)) || (o3 == sign::zero && within(c, d, a)) ||
           (o4 == sign::zero && within(c, d, b));
}

// point2 against point2.
// Semantics: Two points meet iff both coordinates are equal (NaN is never equal, and an infinite
// coordinate is no point).

// Comparisons alone decide it, in every tier: query.cppm's decide_pair runs the body once, with
// no filter pass around it (by_comparisons).
[[nodiscard]] consteval bool decided_by_comparisons(const point2*, const point2*) { return true; }
template <class K>
[[nodiscard]] constexpr bool intersects(K&, const point2& p, const point2& q) {
    return finite(p) && p.x == q.x && p.y == q.y; // an infinite point is no shape
}

// point2 against ray2.
// Semantics: A point and a closed ray in the plane: the origin, or a point of the half-line.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point2& p, const ray2& r) {
    return linear_pair(k, p, r);
}

// point2 against segment2.
// Semantics: A point and a closed segment in the plane: between the end points, both included.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point2& p, const segment2& s) {
    return linear_pair(k, p, s);
}

// point3 against point3.
// Semantics: Two points meet iff all three coordinates are equal (compared exactly; NaN is never
// equal, and an infinite coordinate is no point).

// Comparisons alone decide it, in every tier: query.cppm's decide_pair runs the body once, with
// no filter pass around it (by_comparisons).
[[nodiscard]] consteval bool decided_by_comparisons(const point3*, const point3*) { return true; }
template <class K>
[[nodiscard]] constexpr bool intersects(K&, const point3& p, const point3& q) {
    return finite(p) && p.x == q.x && p.y == q.y && p.z == q.z; // an infinite point is no shape
}

// point3 against ray3.
// Semantics: A point and a closed ray: the point is the origin or lies on the ray's half-line.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point3& p, const ray3& r) {
    return linear_pair(k, p, r);
}

// point3 against segment3.
// Semantics: A point and a closed segment: the point lies between the end points, both included.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point3& p, const segment3& s) {
    return linear_pair(k, p, s);
}

// ray2 against segment2.
// Semantics: A closed ray and a closed segment in the plane; touching at the origin or an end point counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray2& r, const segment2& s) {
    return linear_pair(k, r, s);
}

// ray2 against ray2.
// Semantics: Two closed rays in the plane; collinear rays meet when one origin lies on the other ray.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray2& r, const ray2& q) {
    if (before(q, r)) return linear_pair(k, q, r);
    return linear_pair(k, r, q);
}

// ray3 against ray3.
// Semantics: Two closed rays (origins included); collinear rays meet when one origin lies on the other ray.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray3& r, const ray3& q) {
    if (before(q, r)) return linear_pair(k, q, r);
    return linear_pair(k, r, q);
}

// ray3 against segment3.
// Semantics: A closed ray and a closed segment; touching at the origin or at an end point counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray3& r, const segment3& s) {
    return linear_pair(k, r, s);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const segment3&, const segment3&);
extern template bool exactly<intersects_body>(const line2&, const line2&);
extern template bool exactly<intersects_body>(const line2&, const point2&);
extern template bool exactly<intersects_body>(const line2&, const segment2&);
extern template bool exactly<intersects_body>(const line2&, const ray2&);
extern template bool exactly<intersects_body>(const line3&, const line3&);
extern template bool exactly<intersects_body>(const line3&, const point3&);
extern template bool exactly<intersects_body>(const line3&, const ray3&);
extern template bool exactly<intersects_body>(const line3&, const segment3&);
extern template bool exactly<intersects_body>(const segment2&, const segment2&);
extern template bool exactly<intersects_body>(const point2&, const point2&);
extern template bool exactly<intersects_body>(const point2&, const ray2&);
extern template bool exactly<intersects_body>(const point2&, const segment2&);
extern template bool exactly<intersects_body>(const point3&, const point3&);
extern template bool exactly<intersects_body>(const point3&, const ray3&);
extern template bool exactly<intersects_body>(const point3&, const segment3&);
extern template bool exactly<intersects_body>(const ray2&, const segment2&);
extern template bool exactly<intersects_body>(const ray2&, const ray2&);
extern template bool exactly<intersects_body>(const ray3&, const ray3&);
extern template bool exactly<intersects_body>(const ray3&, const segment3&);
} // namespace incidence::detail
