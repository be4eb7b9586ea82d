// line3 against triangle3.
// Semantics: closed triangle (edges and vertices count); a line in the triangle's plane meets it
// when it crosses or touches it in 2D; a collinear triangle is its hull (a segment or a point); a
// zero direction is the line's origin point.
// Method (exact tiers): the ray_triangle sign algorithm without the bound t >= 0 (see
// ray_triangle.cppm for the case table): with n.d != 0 the line meets the triangle iff the three
// Pluecker edge values det(d, b - o, c - o), ... have the sign of n.d or are zero; n.d == 0 is the
// coplanar 2D test or no. Every sign of degree <= 3.
// Source: the Pluecker-coordinate test of Moeller and Trumbore / Amanatides and Choi, as the
// orientation-only structure of CGAL's Line_3/Triangle_3 do_intersect.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/line_triangle.cpp).
export module incidence.query:line_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :ray_triangle;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const triangle3& t) {
    return linear_triangle(k, as_linear(l), t);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const line3&, const triangle3&);
} // namespace incidence::pair
