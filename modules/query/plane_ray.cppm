// plane3 against ray3.
// Semantics: a closed ray (its origin included) meets the plane when its origin is on it or it
// heads towards it; a ray in the plane counts. A zero normal is everything when the offset is 0
// and nothing otherwise; a zero direction is the origin point.
// Method (exact tiers): the sign of n . o - offset, then the sign of n . d (both degree 2); see
// line_plane.cppm, whose body this pair shares.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.3.1, as signs instead of t.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a sign is within 2^-48 of its permanent
// (tests/query/plane_ray.cpp).
export module incidence.query:plane_ray;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :line_plane;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const ray3& r) {
    return plane_linear(k, pl, as_linear(r));
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const plane3&, const ray3&);
} // namespace incidence::pair
