// intersects: circle2_pairs
module;
export module incidence.detail:intersects.circle2_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.ball_flat;
import :engines.polygon2;
import :exactly;

export namespace incidence::detail {

// circle2 against point2, circle2, segment2, ray2, line2 and polygon2: the squared distance from
// the centre to the shape against r^2, by the closest-feature case analysis of ball_flat.cppm in the
// plane (an end, the nearest point of the supporting line: signs of degree <= 4; two disks: the sum
// of the radii formed exactly inside the sign). A polygon: polygon2.cppm's engine with the disk as
// the connected shape: a disk meets the polygon's set iff it meets an edge, or else lies off the
// boundary with its centre inside (exact crossing parity); edges whose boxes miss the disk's box
// (rounded outward) are skipped.
// Semantics: the closed disk |x - c| <= |r| (an unchecked negative radius acts as |r|, as for
// sphere3; a zero radius is the point c); a closed segment (a = b is a point), a ray or a line (a
// zero direction is its origin), the polygon's set of shapes/polygon2.cppm. Touching counts. A NaN
// or infinite number, or a malformed polygon: no shape, so no.
// Source: Ericson, Real-Time Collision Detection (2005), sections 5.1.2 (closest point on a
// segment) and 5.2.7 (a sphere against a segment: the same signs in the plane); Haines, "Point in
// polygon strategies", Graphics Gems IV (1994) (the crossings test).
// Approximate tier: the same signs in plain double. Error bound: while the signs' terms (degree
// <= 4) stay in double's normal range, that is for inputs and their differences of magnitude in
// [2^-250, 2^250], wrong only when a deciding sign is within 2^-44 of its permanent; the tests'
// cases at scales out to 2^-500 and 2^500 leave that range, where plain double underflows or
// overflows and its answer is anything (tests/query/intersects/circle2_segment2.cpp and the other
// pairs' tests count those with the margin of zero they then have).

[[nodiscard]] constexpr bool usable(const circle2& c) { return finite(c.center) && finite(c.radius); }
[[nodiscard]] constexpr double reach(const circle2& c) { return c.radius < 0.0 ? -c.radius : c.radius; }

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const circle2& c, const point2& p) {
    return usable(c) && finite(p) && ball_flat::holds(k, p, c.center, reach(c));
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const circle2& a, const circle2& b) {
    return usable(a) && usable(b) && ball_flat::holds(k, b.center, a.center, ball_flat::radii{reach(a), reach(b)});
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const circle2& c, const segment2& s) {
    return usable(c) && finite(s) && ball_flat::meets(k, as_linear(s), c.center, reach(c));
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const circle2& c, const ray2& r) {
    return usable(c) && finite(r) && ball_flat::meets(k, as_linear(r), c.center, reach(c));
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const circle2& c, const line2& l) {
    return usable(c) && finite(l.origin) && finite(l.direction) && ball_flat::meets(k, as_linear(l), c.center, reach(c));
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const circle2& c, const polygon2& g) {
    if (!usable(c) || !polygon2d::well_formed(g)) return false;
    const double r = reach(c);
    const polygon2d::box2 xb = ball_flat::reach_box(c.center, r);
    if (!polygon2d::boxes_meet(polygon2d::bounds(g), xb)) return false;
    return polygon2d::polygon_meets(k, g, [&](const segment2& e) { return ball_flat::meets(k, as_linear(e), c.center, r); }, c.center, &xb);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const circle2&, const point2&);
extern template bool exactly<intersects_body>(const circle2&, const circle2&);
extern template bool exactly<intersects_body>(const circle2&, const segment2&);
extern template bool exactly<intersects_body>(const circle2&, const ray2&);
extern template bool exactly<intersects_body>(const circle2&, const line2&);
extern template bool exactly<intersects_body>(const circle2&, const polygon2&);
} // namespace incidence::detail
