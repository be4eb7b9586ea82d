// point3 against triangle3.
// Semantics: the closed triangle: a point on an edge or a vertex counts; a collinear triangle is
// its hull (a segment or a point).
// Method (exact tiers): p beyond the triangle's bounding box rejects (comparisons, exact). Then
// orient3d(a, b, c, p) == 0, then the three edge orientations in the
// projection dropping an axis where the normal (b - a) x (c - a) is nonzero, which keeps the
// triangle's orientation as the sign of that normal component; a degenerate triangle tests its
// edges (collinearity, then the dot-product bounds). Every sign of degree <= 3.
// Source: Ericson, Real-Time Collision Detection (2005), section 5.4.2 (point in triangle), with
// signs of exact orientations instead of barycentric quotients; section 4.2.1 (the box).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/point_triangle.cpp).
export module incidence.query:point_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :ray_triangle;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point3& p, const triangle3& t) {
    if (boxes_apart(k, p, t)) return false; // exact, and cheap on the commonest no
    return point_in_triangle(k, p, t);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const point3&, const triangle3&);
} // namespace incidence::pair
