// intersects: obb_pairs
export module incidence.detail:intersects.obb_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.separating_axes;
import :engines.tetrahedron;
import :intersects.linear_pairs;
import :intersects.tetrahedron_pairs;
import :exactly;

export namespace incidence::detail {

// aabb3 against obb3 (closed boxes; a box of zero extent is a rectangle, a segment or a point, and
// an obb3's axes are read exactly as given: it is the parallelepiped they span).
// Semantics: touching at a corner, along an edge or on a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& a, const obb3& b) {
    if (!sat::well_formed(a) || !sat::well_formed(b)) return false;
    const sat::zonotope z = sat::zonotope_of(a);
    // b read in place (as obb_obb reads both); batch::detail::box_obb_gammas reads its filter's
    // types from this same pair of arguments
    if (const certainty f = sat::box_box_fast(k, z, b); f != certainty::uncertain) return f == certainty::yes;
    return sat::zonotopes_intersect_general(k, z, sat::zonotope_of(b));
}

// obb3 against point3 (closed box, read as the parallelepiped its axes span).
// Semantics: a point on the boundary counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& a, const point3& b) {
    return sat::well_formed(a) && sat::zonotopes_intersect(k, sat::zonotope_of(a), sat::zonotope_of(b));
}

// obb3 against triangle3 (closed box read as the parallelepiped its axes span; closed triangle, a
// collinear triangle is its hull).
// Semantics: touching at a vertex, along an edge or on a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& a, const triangle3& b) {
    return sat::well_formed(a) && sat::zonotope_triangle_intersect(k, sat::zonotope_of(a), b);
}

// obb3 against tetrahedron3 (closed box, read as the parallelepiped its axes span; closed solid
// tetrahedron, coplanar vertices give their hull).
// Semantics: touching at a vertex, along an edge or on a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& b, const tetrahedron3& t) {
    if (!sat::well_formed(b) || !finite(b) || !finite(t)) return false;
    const point3 pts[1] = {b.center};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, b, face); }, pts, 1, false);
}

// line3 against obb3 (the line o + t d for every real t; closed box read as the parallelepiped its
// axes span).
// Semantics: a line touching an edge or a corner, or lying in a face's plane through the box, counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& a, const obb3& b) {
    return sat::well_formed(b) && sat::zonotopes_intersect(k, sat::zonotope_of(b), sat::zonotope_of(a));
}

// obb3 against obb3 (closed boxes; the axes are read exactly as given, so a box is the
// parallelepiped they span, and a box of zero extent is a rectangle, a segment or a point).
// Semantics: touching at a corner, along an edge or on a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& a, const obb3& b) {
    if (!sat::well_formed(a) || !sat::well_formed(b)) return false;
    const bool before = obb_before(a, b);
    const obb3& p = before ? a : b;
    const obb3& q = before ? b : a;
    if (const certainty f = sat::box_box_fast(k, p, q); f != certainty::uncertain) return f == certainty::yes; // the boxes read in place
    return sat::zonotopes_intersect_general(k, sat::zonotope_of(p), sat::zonotope_of(q));
}

// obb3 against plane3 (closed box read as the parallelepiped its axes span; the plane
// n . p = offset, a zero normal is everything when the offset is 0 and nothing otherwise).
// Semantics: a plane touching a corner, an edge or a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& b, const plane3& pl) {
    if (!sat::well_formed(b)) return false;
    const sat::zonotope z = sat::zonotope_of(b);
    const vec3 n = pl.normal;
    const double d = pl.offset;
    return k.sgn([=](auto L) {
        const auto w = arith::lift(L, n);
        return L(1.0) * sat::magnitude(arith::dot(w, sat::centre2(L, z)) - L(1.0) * (L(d) + L(d))) - sat::radius2(L, z, w);
    }) != sign::positive;
}

// obb3 against segment3 (closed box read as the parallelepiped its axes span; closed segment, a
// segment with equal end points is a point).
// Semantics: touching a face, an edge or a corner counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& a, const segment3& b) {
    return sat::well_formed(a) && sat::zonotopes_intersect(k, sat::zonotope_of(a), sat::zonotope_of(b));
}

// obb3 against ray3 (closed box read as the parallelepiped its axes span; the ray o + t d, t >= 0).
// Semantics: a ray starting inside, on the boundary, or grazing an edge counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& a, const ray3& b) {
    return sat::well_formed(a) && sat::zonotopes_intersect(k, sat::zonotope_of(a), sat::zonotope_of(b));
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const aabb3&, const obb3&);
extern template bool exactly<intersects_body>(const obb3&, const point3&);
extern template bool exactly<intersects_body>(const obb3&, const triangle3&);
extern template bool exactly<intersects_body>(const obb3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const line3&, const obb3&);
extern template bool exactly<intersects_body>(const obb3&, const obb3&);
extern template bool exactly<intersects_body>(const obb3&, const plane3&);
extern template bool exactly<intersects_body>(const obb3&, const segment3&);
extern template bool exactly<intersects_body>(const obb3&, const ray3&);
} // namespace incidence::detail
