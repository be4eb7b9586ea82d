// tetrahedron3 against triangle3 (closed solid tetrahedron, coplanar vertices give their hull;
// closed triangle, a collinear one is its hull).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Method (exact tiers): bounding boxes apart reject (comparisons, exact; Ericson, Real-Time
// Collision Detection (2005), section 4.2.1). Then: a triangle vertex inside the solid says yes,
// all three strictly beyond one face plane say no (orient3d signs, degree 3); otherwise the
// triangle meets the tetrahedron iff it meets one of its four faces (triangle_triangle), since it
// cannot then lie inside. In a filter pass at run time the rounded stage of point_tetrahedron.cppm
// comes first (face planes, an edge clearly through a face, the edge axes; each value widened by a
// proven error bound).
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Guigue and Devillers,
// JGT 8(1), 2003 for the face tests.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/tetrahedron_triangle.cpp).
export module incidence.query:tetrahedron_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :triangle_triangle;
import :point_tetrahedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const tetrahedron3& t, const triangle3& f) {
    if (!finite(t) || !finite(f)) return false;
    if (boxes_apart(k, f, t)) return false; // exact, and cheap on the commonest no
    const point3 pts[3] = {f.a, f.b, f.c};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, face, f); }, pts, 3, true);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const tetrahedron3&, const triangle3&);
} // namespace incidence::pair
