// frustum3 against triangle3, and contains(frustum3, triangle3).
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the closed solid triangle (collinear corners: the segments between them). Touching
// at a vertex, an edge or a face counts. contains: the three corners in the frustum (convex).
// Method (exact tiers): the test of a triangle against a half-space set
// (convex_polyhedron_triangle.cppm): a plane with the three corners beyond it says no; an edge
// meeting the set (the generalised slab test) says yes; else a vertex of the set's section by the
// triangle's plane, where two of the planes cross it, inside the six half-spaces and the triangle:
// homogeneous signs of degree <= 8.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5; Cyrus and Beck,
// Computers & Graphics 3(1), 1978, for the edges.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/frustum_triangle.cpp).
export module incidence.query:frustum_triangle;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :frustum_point;
import :convex_polyhedron_triangle;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const triangle3& t) {
    return polyq::triangle_meets(k, t, f.planes.data(), 6);
}
// contains(frustum3, triangle3): the three corners in the frustum (every corner read).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const triangle3& t) {
    const bool a = intersects(k, f, t.a);
    const bool b = intersects(k, f, t.b);
    const bool e = intersects(k, f, t.c);
    return a && b && e;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const frustum3&, const triangle3&);
extern template bool contains(arith::exact_kernel&, const frustum3&, const triangle3&);
} // namespace incidence::pair
