// plane3 against point3 (the plane n . p = offset; a zero normal is everything when the offset
// is 0 and nothing otherwise).
// Semantics: the point lies on the plane, exactly.
// Method (exact tiers): the sign of n . p - offset (degree 2) is zero.
// Source: Ericson, Real-Time Collision Detection (2005), section 3.6 (planes).
// Approximate tier: the same sign in plain double: a point off the plane by less than the
// rounding of n . p reads as on it. Error bound: for inputs whose nonzero magnitudes lie in
// [2^-500, 2^500], wrong only when the sign is within 2^-48 of its permanent
// (tests/query/plane_point.cpp).
export module incidence.query:plane_point;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_plane;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const point3& p) {
    return plane_side(k, pl, p) == sign::zero;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const plane3&, const point3&);
} // namespace incidence::pair
