// aabb3 against plane3 (closed box; the plane n . p = offset; a zero normal is everything when
// the offset is 0 and nothing otherwise).
// Semantics: a plane touching a corner, an edge or a face counts.
// Method (exact tiers): the box corners extreme along n are picked by the signs of n's components;
// the plane meets the box iff n . lo <= offset <= n . hi, two signs of degree 2.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.2.3 (testing box against plane,
// with the extreme corners instead of the centre-radius form, so no rounded centre is compared).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a sign is within 2^-48 of its permanent
// (tests/query/aabb_plane.cpp).
//
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
export module incidence.detail:engines.plane;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;

export namespace incidence::detail {

// sign(n . p - offset), degree 2.
template <class K>
[[nodiscard]] constexpr sign plane_side(K& k, const plane3& pl, point3 p) {
    const vec3 n = pl.normal;
    const double d = pl.offset;
    return k.sgn([=](auto L) { return arith::dot(arith::lift(L, n), arith::lift(L, p)) - L(d); });
}

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

} // namespace incidence::detail
