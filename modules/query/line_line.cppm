// line3 against line3.
// Semantics: Two lines (a zero direction: the line is its origin point). Lines meet iff they are coplanar and not parallel, or the same line.
// Method (exact tiers): the linear pairs' shared body, linear_linear in segment_segment.cppm
// (skew test det(D, E, w), then the coplanar crossing's parameter bounds as signs of products,
// or the collinear overlap along D); every sign of degree <= 4.
// Source: Schneider and Eberly, Geometric Tools for Computer Graphics (2003), section 11.1.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/line_line.cpp).
export module incidence.query:line_line;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const line3& m) {
    if (before(m, l)) return linear_linear(k, as_linear(m), as_linear(l));
    return linear_linear(k, as_linear(l), as_linear(m));
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const line3&, const line3&);
} // namespace incidence::pair
