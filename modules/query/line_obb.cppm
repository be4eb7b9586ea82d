// line3 against obb3 (the line o + t d for every real t; closed box read as the parallelepiped its
// axes span).
// Semantics: a line touching an edge or a corner, or lying in a face's plane through the box, counts.
// Method (exact tiers): only axes perpendicular to d can separate a line: the three box axes crossed
// with d (an axis w with w . d != 0 is skipped by that sign). Each test is one sign of degree 4.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.3.3 (the segment-box axes, with
// the segment's extent taken to infinity).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when some axis sign is within 2^-40 of its
// permanent (the sets touch or nearly touch); tests/query/line_obb.cpp checks it.
export module incidence.query:line_obb;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :separating_axes;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& a, const obb3& b) {
    return sat::well_formed(b) && sat::zonotopes_intersect(k, sat::of(b), sat::of(a));
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const line3&, const obb3&);
} // namespace incidence::pair
