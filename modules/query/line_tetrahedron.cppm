// line3 against tetrahedron3 (a line through its origin, a point when the direction is zero;
// closed solid tetrahedron, coplanar vertices give their hull).
// Semantics: touching a face, an edge or a vertex counts.
// Method (exact tiers): a line that meets a bounded convex solid meets its boundary, so the
// line meets the tetrahedron iff it meets one of its four faces (the line_triangle sign
// algorithm); the origin inside the solid (four orient3d signs) answers first. In a filter pass
// at run time the line's side of each of the six edges first, rounded with proven error bounds
// (tetra::rounded_line_meets); the signs decide what that leaves.
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Ericson, Real-Time
// Collision Detection (2005), section 5.4.2.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/line_tetrahedron.cpp).
export module incidence.query:line_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :line_triangle;
import :point_tetrahedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const tetrahedron3& t) {
    if (!finite(l) || !finite(t)) return false;
    // In a filter pass, the rounded edge and face values first (tetra::rounded_line_meets).
    if (arith::rounded_stage_applies<K>())
        if (const int m = tetra::rounded_line_meets(t, l.origin, l.direction, false); m >= 0) return m == 1;
    const point3 pts[1] = {l.origin};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, l, face); }, pts, 1, false);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const line3&, const tetrahedron3&);
} // namespace incidence::pair
