// aabb3 against segment3 (closed box, closed segment; a segment with equal end points is a point).
// Semantics: touching a face, an edge or a corner counts.
// Method (exact tiers): the slab method on t in [0, 1] with d = b - a taken exactly from the end
// points, its quotient comparisons rewritten as signs of products (see slabs in aabb_ray): degree
// 2 for each pair of axes, coordinate comparisons for the rest. Seen as a separating-axis test
// these are the six axes of the segment-box test (three box normals, three box axis x segment).
// Source: Kay and Kajiya, "Ray tracing complex scenes", SIGGRAPH 1986 (slabs); Ericson, Real-Time
// Collision Detection (2005), section 5.3.3 (segment-box, the six axes).
// Approximate tier: the same slab test in plain double with reciprocal directions. Error bound:
// for inputs whose nonzero magnitudes lie in [2^-500, 2^500], wrong only when some pairwise slab
// sign or end-point comparison is within 2^-40 of its permanent (tests/query/aabb_segment.cpp).
module;
#include <optional>
export module incidence.query:aabb_segment;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_ray;
import :aabb_point;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const segment3& s) {
    return slabs<slab_extent::segment>(k, b, s.a, vec3{0, 0, 0}, s.b);
}
// Is the segment inside the box? Both end points are (coordinate comparisons, exact in every tier).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& b, const segment3& s) {
    return contains(k, b, s.a) && contains(k, b, s.b);
}

// The slab method in plain double on [0, 1] (approximate tier).
[[nodiscard]] constexpr bool aabb_segment_slab(const aabb3& b, const segment3& s) {
    const auto h = aabb_ray_slab(b, ray3{s.a, s.b - s.a});
    return h.has_value() && h->t_enter <= 1.0;
}
[[nodiscard]] constexpr bool intersects_approximate(const aabb3& b, const segment3& s) { return aabb_segment_slab(b, s); }

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const segment3&);
extern template bool contains(arith::exact_kernel&, const aabb3&, const segment3&);
} // namespace incidence::pair
