// ray3 against ray3.
// Semantics: Two closed rays (origins included); collinear rays meet when one origin lies on the other ray.
// Method (exact tiers): the linear pairs' shared body, linear_linear in segment_segment.cppm
// (skew test det(D, E, w), then the coplanar crossing's parameter bounds as signs of products,
// or the collinear overlap along D); every sign of degree <= 4.
// Source: Schneider and Eberly, Geometric Tools for Computer Graphics (2003), section 11.1.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/ray_ray.cpp).
export module incidence.query:ray_ray;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray3& r, const ray3& q) {
    if (before(q, r)) return linear_pair(k, q, r);
    return linear_pair(k, r, q);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const ray3&, const ray3&);
} // namespace incidence::pair
