// segment3 against triangle3: intersects, and intersection (t in [0, 1] along a -> b, point,
// normal, barycentrics).
// Semantics: closed segment, closed triangle: touching at an end point, an edge or a vertex
// counts; a segment in the triangle's plane is tested in 2D; degenerate segment = a point;
// degenerate triangle = its convex hull.
// Method: bounding boxes apart reject (comparisons, exact; Ericson, Real-Time Collision
// Detection (2005), section 4.2.1); then the ray_triangle sign algorithm with d = b - a formed exactly inside each predicate
// and the extra sign n.(b - tri.a) for t <= 1 (CGAL Segment_3/Triangle_3 uses the same
// orientation-only structure); see ray_triangle.cppm for the case table. Approximate tier:
// the same algorithm in plain double.
module;
#include <optional>
export module incidence.query:segment_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :ray_triangle;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const segment3& s, const triangle3& t) {
    if (boxes_apart(k, s, t)) return false; // exact, and cheap on the commonest no
    return linear_triangle(k, linear3{s.a, vec3{0, 0, 0}, s.b, extent::segment}, t);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const segment3&, const triangle3&);
} // namespace incidence::pair
