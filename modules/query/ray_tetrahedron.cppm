// ray3 against tetrahedron3 (a ray from its origin, a point when the direction is zero; closed
// solid tetrahedron, coplanar vertices give their hull).
// Semantics: touching a face, an edge or a vertex counts; an origin inside counts.
// Method (exact tiers): bounding boxes apart reject (comparisons, exact; Ericson, Real-Time
// Collision Detection (2005), section 4.2.1). Then: the origin inside the solid (four orient3d
// signs, degree 3) says yes; otherwise the ray meets the tetrahedron iff it meets one of its four
// faces (the ray_triangle sign algorithm). In a filter pass at run time the same question first
// rounded, with proven error bounds: the ray's side of each of the six edges and the origin's side
// of each face plane (tetra::rounded_line_meets); the signs decide what that leaves.
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Ericson, Real-Time
// Collision Detection (2005), section 5.4.2.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/ray_tetrahedron.cpp).
export module incidence.query:ray_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :ray_triangle;
import :point_tetrahedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray3& r, const tetrahedron3& t) {
    if (!finite(r) || !finite(t)) return false;
    if (boxes_apart(k, r, t)) return false; // exact, and cheap on the commonest no
    // In a filter pass, the rounded edge and face values first (tetra::rounded_line_meets).
    if (arith::rounded_stage_applies<K>())
        if (const int m = tetra::rounded_line_meets(t, r.origin, r.direction, true); m >= 0) return m == 1;
    const point3 pts[1] = {r.origin};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, r, face); }, pts, 1, false);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const ray3&, const tetrahedron3&);
} // namespace incidence::pair
