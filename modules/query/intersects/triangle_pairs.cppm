// intersects: triangle_pairs
module;
#include <optional>
export module incidence.detail:intersects.triangle_pairs;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :engines.triangle;
import :exactly;

export namespace incidence::detail {

// ray3 against triangle3: intersects, and intersection (t, point, normal, barycentrics).
// Semantics: closed triangle, so hits on edges and vertices count; a ray lying in the
// triangle's plane hits when it meets the triangle (2D test); a collinear (degenerate)
// triangle is its convex hull, a segment or a point; a zero direction is the point `origin`.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray3& r, const triangle3& t) {
    if (boxes_apart(k, r, t)) return false; // exact, and cheap on the commonest no
    return linear_triangle(k, linear3{r.origin, r.direction, r.origin, extent::ray}, t);
}
// The approximate tier of intersects(ray3, triangle3) is the watertight algorithm.
[[nodiscard]] constexpr bool intersects_approximate(const ray3& r, const triangle3& t) { return ray_triangle_watertight(r, t).has_value(); }

// triangle3 against triangle3 (closed triangles; a collinear triangle is its hull).
// Semantics: touching at a vertex, along an edge, or coplanar overlap counts.
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const triangle3& p, const triangle3& q) {
    if (boxes_apart(k, p, q)) return false; // exact, and cheap on the commonest no
    return before(q, p) ? triangles_meet(k, q, p) : triangles_meet(k, p, q);
}

// segment3 against triangle3: intersects, and intersection (t in [0, 1] along a -> b, point,
// normal, barycentrics).
// Semantics: closed segment, closed triangle: touching at an end point, an edge or a vertex
// counts; a segment in the triangle's plane is tested in 2D; degenerate segment = a point;
// degenerate triangle = its convex hull.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const segment3& s, const triangle3& t) {
    if (boxes_apart(k, s, t)) return false; // exact, and cheap on the commonest no
    return linear_triangle(k, linear3{s.a, vec3{0, 0, 0}, s.b, extent::segment}, t);
}

// point3 against triangle3.
// Semantics: the closed triangle: a point on an edge or a vertex counts; a collinear triangle is
// its hull (a segment or a point).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point3& p, const triangle3& t) {
    if (boxes_apart(k, p, t)) return false; // exact, and cheap on the commonest no
    return point_in_triangle(k, p, t);
}

// line3 against triangle3.
// Semantics: closed triangle (edges and vertices count); a line in the triangle's plane meets it
// when it crosses or touches it in 2D; a collinear triangle is its hull (a segment or a point); a
// zero direction is the line's origin point.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const triangle3& t) {
    return linear_triangle(k, as_linear(l), t);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const ray3&, const triangle3&);
extern template bool exactly<intersects_body>(const triangle3&, const triangle3&);
extern template bool exactly<intersects_body>(const segment3&, const triangle3&);
extern template bool exactly<intersects_body>(const point3&, const triangle3&);
extern template bool exactly<intersects_body>(const line3&, const triangle3&);
} // namespace incidence::detail
