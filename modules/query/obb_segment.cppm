// obb3 against segment3 (closed box read as the parallelepiped its axes span; closed segment, a
// segment with equal end points is a point).
// Semantics: touching a face, an edge or a corner counts.
// Method (exact tiers): the six separating axes of the segment-box test (three face normals,
// three box axes crossed with the segment direction q - p, taken exactly from the end points),
// each one sign of degree 4 with the segment as the zonotope (p + q) / 2 + t (q - p), |t| <= 1/2.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.3.3 (segment-box, six axes).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when some axis sign is within 2^-40 of its
// permanent (the sets touch or nearly touch); tests/query/obb_segment.cpp checks it.
export module incidence.query:obb_segment;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :separating_axes;
import :obb_point;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& a, const segment3& b) {
    return sat::well_formed(a) && sat::zonotopes_intersect(k, sat::of(a), sat::of(b));
}
// Is the segment inside the box? Its two end points are (the box is convex).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& a, const segment3& b) {
    return contains(k, a, b.a) && contains(k, a, b.b);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const obb3&, const segment3&);
extern template bool contains(arith::exact_kernel&, const obb3&, const segment3&);
} // namespace incidence::pair
