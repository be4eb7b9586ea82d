// segment2 against segment2.
// Semantics: Two closed segments in the plane; touching at an end point and collinear overlaps (even in one point) count.
// Method (exact tiers): bounding boxes apart reject (comparisons, exact). Then the four orient2d
// signs of each segment's end points against the other's line: both end points strictly on one
// side rejects; all four nonzero (so each straddles the other) is a proper crossing; otherwise the
// segments meet iff an end point on the other's line lies in that segment's bounding box (for a
// point on the line, on the segment: coordinate comparisons, exact). The four signs are the same
// for (s, t) and (t, s), so every tier answers both orders alike. Every sign of degree 2.
// Source: Cormen, Leiserson, Rivest and Stein, Introduction to Algorithms, 3rd ed. (2009),
// section 33.1 (SEGMENTS-INTERSECT); O'Rourke, Computational Geometry in C, 2nd ed. (1998), 1.5;
// Ericson, Real-Time Collision Detection (2005), section 4.2.1 (the bounding boxes).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-48 of its
// permanent (tests/query/segment2_segment2.cpp).
export module incidence.query:segment2_segment2;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.predicates;
import :segment_segment;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const segment2& s, const segment2& t) {
    if (!finite(s.a) || !finite(s.b) || !finite(t.a) || !finite(t.b)) return false; // no shape
    if (boxes_apart(k, s, t)) return false; // exact, and cheap on the commonest no
    // In the filter pass an unproven sign (an end point on the other's line, often exactly) is
    // settled where it arises (arith::settled) rather than by rerunning the pair.
    auto orient = [&](point2 p, point2 q, point2 r) { return arith::settled(k, [=](auto L) { return poly::orient2d(L, p, q, r); }); };
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

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const segment2&, const segment2&);
} // namespace incidence::pair
