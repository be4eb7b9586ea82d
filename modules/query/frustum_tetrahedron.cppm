// frustum3 against tetrahedron3, and contains(frustum3, tetrahedron3).
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the closed solid tetrahedron (coplanar vertices: their hull). Touching at a vertex,
// an edge or a face counts. contains: the four vertices in the frustum (convex).
// Method (exact tiers): the test of a tetrahedron against a half-space set
// (convex_polyhedron_tetrahedron.cppm): a plane with the four vertices beyond it says no; a face
// meeting the frustum (the triangle test of convex_polyhedron_triangle.cppm) says yes; else the
// frustum lies inside the tetrahedron or outside it, and one of its vertices, where three of the
// planes meet, decides: homogeneous signs of degree <= 8.
// Source: the boundary-plus-inside decomposition (point_tetrahedron.cppm); Schrijver, Theory of
// Linear and Integer Programming, 1986, section 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/frustum_tetrahedron.cpp).
export module incidence.query:frustum_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :frustum_point;
import :convex_polyhedron_tetrahedron;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const tetrahedron3& t) {
    return polyq::tetrahedron_meets(k, t, f.planes.data(), 6);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const tetrahedron3& t) {
    const bool a = intersects(k, f, t.a);
    const bool b = intersects(k, f, t.b);
    const bool e = intersects(k, f, t.c);
    const bool d = intersects(k, f, t.d);
    return a && b && e && d;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const frustum3&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const frustum3&, const tetrahedron3&);
} // namespace incidence::pair
