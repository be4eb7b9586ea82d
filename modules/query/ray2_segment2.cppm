// ray2 against segment2.
// Semantics: A closed ray and a closed segment in the plane; touching at the origin or an end point counts.
// Method (exact tiers): the linear pairs' shared body in the plane, linear_linear(linear2) in
// segment_segment.cppm: with c = cross(D, E) != 0 the crossing's parameters t and u are checked
// against each object's bounds as signs of products (t c = cross(w, E), u c = cross(w, D)); with
// c == 0, cross(D, w) == 0 (on one line) and the 1D overlap along D. Every sign of degree <= 2.
// Source: O'Rourke, Computational Geometry in C, 2nd ed. (1998), section 1.5 (segment
// intersection from orientations), extended to rays and lines by their parameter bounds.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-48 of its
// permanent (tests/query/ray2_segment2.cpp).
export module incidence.query:ray2_segment2;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray2& r, const segment2& s) {
    return linear_pair(k, r, s);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const ray2&, const segment2&);
} // namespace incidence::pair
