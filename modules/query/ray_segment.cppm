// ray3 against segment3.
// Semantics: A closed ray and a closed segment; touching at the origin or at an end point counts.
// Method (exact tiers): the linear pairs' shared body, linear_linear in segment_segment.cppm
// (skew test det(D, E, w), then the coplanar crossing's parameter bounds as signs of products,
// or the collinear overlap along D); every sign of degree <= 4.
// Source: Schneider and Eberly, Geometric Tools for Computer Graphics (2003), section 11.1.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/ray_segment.cpp).
export module incidence.query:ray_segment;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray3& r, const segment3& s) {
    return linear_pair(k, r, s);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const ray3&, const segment3&);
} // namespace incidence::pair
