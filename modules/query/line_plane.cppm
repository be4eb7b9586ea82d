// line3 against plane3, and the body shared by every linear object against a plane.
// Semantics: a line meets a plane unless it is parallel to it and off it; a line in the plane
// counts. The plane n . p = offset with a zero normal is everything when the offset is 0 and
// nothing otherwise; a zero direction is the line's origin point.
// Method (exact tiers): s0 = sign(n . o - offset) (degree 2): zero means the origin is on the
// plane. Otherwise a line meets it iff n . d != 0, a ray iff sign(n . d) == -s0 (it heads
// towards the plane), a segment iff its end point's side differs from s0.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.3.1 (intersecting a segment or
// ray against a plane), with the parameter t = (offset - n . o) / (n . d) replaced by the signs
// of its numerator and denominator.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a sign is within 2^-48 of its permanent
// (tests/query/line_plane.cpp).
export module incidence.query:line_plane;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_plane;
import :segment_segment;

export namespace incidence::pair {

// Does the linear object s meet the plane?
template <class K>
[[nodiscard]] constexpr bool plane_linear(K& k, const plane3& pl, const linear3& s) {
    const sign s0 = plane_side(k, pl, s.o);
    if (s0 == sign::zero) return s.kind == extent::segment ? finite(s.q) : finite(s.d); // the rest unread
    if (s.is_point()) return false;
    if (s.kind == extent::segment) return plane_side(k, pl, s.q) != s0;
    const vec3 n = pl.normal;
    const sign nd = k.sgn([=](auto L) { return arith::dot(arith::lift(L, n), s.D(L)); });
    if (s.kind == extent::line) return nd != sign::zero;
    return nd == -s0; // a ray: heading towards the plane
}

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const plane3& pl) {
    return plane_linear(k, pl, as_linear(l));
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const line3&, const plane3&);
} // namespace incidence::pair
