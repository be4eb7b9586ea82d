// segment3 against tetrahedron3 (closed segment, a point when a == b; closed solid tetrahedron,
// coplanar vertices give their hull).
// Semantics: touching a face, an edge or a vertex counts.
// Method (exact tiers): bounding boxes apart reject (comparisons, exact; Ericson, Real-Time
// Collision Detection (2005), section 4.2.1). Then: an end point inside the solid says yes, both
// end points strictly beyond one face plane say no (orient3d signs, degree 3); otherwise the
// segment meets the tetrahedron iff it meets one of its four faces (segment_triangle), since it
// cannot then lie inside. In a filter pass at run time the rounded stage of point_tetrahedron.cppm
// comes first (face planes, an edge clearly through a face, the edge axes; each value widened by a
// proven error bound).
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Ericson, Real-Time
// Collision Detection (2005), section 5.4.2.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/segment_tetrahedron.cpp).
export module incidence.query:segment_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :segment_triangle;
import :point_tetrahedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const segment3& s, const tetrahedron3& t) {
    if (!finite(s) || !finite(t)) return false;
    if (boxes_apart(k, s, t)) return false; // exact, and cheap on the commonest no
    const point3 pts[2] = {s.a, s.b};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, s, face); }, pts, 2, true);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const segment3&, const tetrahedron3&);
} // namespace incidence::pair
