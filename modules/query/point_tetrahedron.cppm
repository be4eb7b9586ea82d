// point3 against tetrahedron3 (a closed solid tetrahedron; coplanar vertices give their hull),
// contains(tetrahedron, point | segment | triangle | tetrahedron), and the engine every
// tetrahedron pair shares.
// Semantics: a point on a face, an edge or a vertex counts.
// Method (exact tiers): p beyond the tetrahedron's bounding box rejects (comparisons, exact;
// Ericson, Real-Time Collision Detection (2005), section 4.2.1). Then, with
// o = orient3d(a, b, c, d) != 0, p lies in the closed solid iff each of the four orient3d values
// with p in place of one vertex (p's barycentric coordinates times o) has the sign of o or is
// zero; degree 3 each. With o = 0 the hull of the four coplanar points is
// the union of the four faces (Caratheodory's theorem in the plane), so p is tested against each
// face with point_triangle.
// The other pairs (tetrahedron_meets below): a convex set X meets the closed solid T iff X meets
// one of T's faces or X lies inside T, which one point of X then decides; the boundary triangles
// plus the inside test, the method for a closed mesh. When X has vertices, first the signs of its
// vertices against T's face planes: a vertex inside T says yes, all vertices strictly outside one
// face plane says no (that face's normal separates).
// Source: Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates" (1997) for orient3d; Ericson, Real-Time Collision Detection (2005), section 5.4.2
// (point in tetrahedron by the four face orientations); CGAL's Tetrahedron_3 do_intersect
// structures its pairs the same way (a point inside, else a face meets).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/point_tetrahedron.cpp).
export module incidence.query:point_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :segment_segment;
import :ray_triangle;

export namespace incidence::pair {


namespace tetra {

[[nodiscard]] constexpr point3 vertex(const tetrahedron3& t, int i) { return i == 0 ? t.a : (i == 1 ? t.b : (i == 2 ? t.c : t.d)); }

// orient3d(a, b, c, d): positive, negative, or zero for coplanar vertices.
template <class K>
[[nodiscard]] constexpr sign orientation(K& k, const tetrahedron3& t) {
    const point3 a = t.a, b = t.b, c = t.c, d = t.d;
    return k.sgn([=](auto L) { return poly::orient3d(L, a, b, c, d); });
}
// orient3d with p in place of vertex i: the sign of o when p is on vertex i's side of face i.
template <class K>
[[nodiscard]] constexpr sign side(K& k, const tetrahedron3& t, int i, point3 p) {
    point3 v[4] = {t.a, t.b, t.c, t.d};
    v[i] = p;
    const point3 a = v[0], b = v[1], c = v[2], d = v[3];
    return k.sgn([=](auto L) { return poly::orient3d(L, a, b, c, d); });
}
// p in the closed solid t of orientation o != 0.
template <class K>
[[nodiscard]] constexpr bool in_solid(K& k, const tetrahedron3& t, sign o, point3 p) {
    for (int i = 0; i < 4; ++i) {
        const sign s = side(k, t, i, p);
        if (s != o && s != sign::zero) return false;
    }
    return true;
}
enum class located { inside, outside, unknown };
// The points pts[0..n) against the solid t (orientation o != 0): inside when one of them lies in
// t; outside when `hull` (the points span the other shape) and all of them lie strictly beyond one
// face plane; else unknown.
template <class K>
[[nodiscard]] constexpr located locate(K& k, const tetrahedron3& t, sign o, const point3* pts, int n, bool hull) {
    const sign beyond = o == sign::positive ? sign::negative : sign::positive;
    bool all_beyond[4] = {true, true, true, true};
    for (int j = 0; j < n; ++j) {
        bool in = true;
        for (int i = 0; i < 4; ++i) {
            const sign s = side(k, t, i, pts[j]);
            if (s != beyond) all_beyond[i] = false;
            if (s != o && s != sign::zero) in = false;
        }
        if (in) return located::inside;
    }
    if (hull)
        for (bool b : all_beyond)
            if (b) return located::outside;
    return located::unknown;
}

// The closed convex set x (finite, checked by the caller) against the closed tetrahedron t
// (finite): pts[0..n) are points of x, its vertices when `hull`; meets(f) says whether x meets
// the triangle f.
template <class K, class Meets>
[[nodiscard]] constexpr bool tetrahedron_meets(K& k, const tetrahedron3& t, const Meets& meets, const point3* pts, int n, bool hull) {
    const sign o = orientation(k, t);
    if (o != sign::zero) {
        const located l = locate(k, t, o, pts, n, hull);
        if (l != located::unknown) return l == located::inside;
    }
    for (int i = 0; i < 4; ++i)
        if (meets(t.face(i))) return true;
    return false;
}

} // namespace tetra

namespace tetra {
// p in the closed tetrahedron t of orientation o (its faces when o is zero).
template <class K>
[[nodiscard]] constexpr bool in_closed(K& k, const tetrahedron3& t, sign o, point3 p) {
    if (o != sign::zero) return in_solid(k, t, o, p);
    for (int i = 0; i < 4; ++i)
        if (linear_triangle(k, as_linear(p), t.face(i))) return true;
    return false;
}
// Every point of pts[0..n) in the closed tetrahedron t: by convexity, t contains their hull.
template <class K>
[[nodiscard]] constexpr bool contains_all(K& k, const tetrahedron3& t, const point3* pts, int n) {
    if (!finite(t)) return false;
    for (int j = 0; j < n; ++j)
        if (!finite(pts[j]) || boxes_apart(k, pts[j], t)) return false; // a point beyond t's box
    const sign o = orientation(k, t);
    for (int j = 0; j < n; ++j)
        if (!in_closed(k, t, o, pts[j])) return false;
    return true;
}
} // namespace tetra

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point3& p, const tetrahedron3& t) {
    const point3 pts[1] = {p};
    return tetra::contains_all(k, t, pts, 1);
}

// contains(tetrahedron, x): every vertex of x in the closed tetrahedron (convexity), so the
// same orient3d signs; a coplanar tetrahedron contains what lies in its hull.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const point3& p) {
    const point3 pts[1] = {p};
    return tetra::contains_all(k, t, pts, 1);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const segment3& s) {
    const point3 pts[2] = {s.a, s.b};
    return tetra::contains_all(k, t, pts, 2);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const triangle3& f) {
    const point3 pts[3] = {f.a, f.b, f.c};
    return tetra::contains_all(k, t, pts, 3);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const tetrahedron3& u) {
    const point3 pts[4] = {u.a, u.b, u.c, u.d};
    return tetra::contains_all(k, t, pts, 4);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const point3&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const tetrahedron3&, const point3&);
extern template bool contains(arith::exact_kernel&, const tetrahedron3&, const segment3&);
extern template bool contains(arith::exact_kernel&, const tetrahedron3&, const triangle3&);
extern template bool contains(arith::exact_kernel&, const tetrahedron3&, const tetrahedron3&);
} // namespace incidence::pair
