// intersects: plane_pairs
export module incidence.detail:intersects.plane_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.plane;
import :exactly;

export namespace incidence::detail {

// aabb3 against plane3 (closed box; the plane n . p = offset; a zero normal is everything when
// the offset is 0 and nothing otherwise).
// Semantics: a plane touching a corner, an edge or a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const plane3& pl) {
    if (!(b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z)) return false; // inverted or NaN box
    const vec3 n = pl.normal;
    const point3 lo{n.x >= 0.0 ? b.min.x : b.max.x, n.y >= 0.0 ? b.min.y : b.max.y, n.z >= 0.0 ? b.min.z : b.max.z};
    const point3 hi{n.x >= 0.0 ? b.max.x : b.min.x, n.y >= 0.0 ? b.max.y : b.min.y, n.z >= 0.0 ? b.max.z : b.min.z};
    return plane_side(k, pl, lo) != sign::positive && plane_side(k, pl, hi) != sign::negative;
}

// line3 against plane3, and the body shared by every linear object against a plane.
// Semantics: a line meets a plane unless it is parallel to it and off it; a line in the plane
// counts. The plane n . p = offset with a zero normal is everything when the offset is 0 and
// nothing otherwise; a zero direction is the line's origin point.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const plane3& pl) {
    return plane_linear(k, pl, as_linear(l));
}

// plane3 against plane3 (n . p = offset each).
// Semantics: two planes meet unless they are parallel and distinct. A zero normal is everything
// when its offset is 0 and nothing otherwise (so it meets every non-empty plane).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& p0, const plane3& q0) {
    // One canonical order (see segment_segment.cppm), so every tier is symmetric.
    const vec3 a = q0.normal, b = p0.normal;
    const bool swap = before(point3{a.x, a.y, a.z}, vec3{q0.offset, 0, 0}, point3{b.x, b.y, b.z}, vec3{p0.offset, 0, 0});
    const plane3& p = swap ? q0 : p0;
    const plane3& q = swap ? p0 : q0;
    const vec3 n = p.normal, m = q.normal;
    const double op = p.offset, oq = q.offset;
    // Crossing normals decide without the offsets: a NaN or infinite input is checked here.
    if (!finite(n) || !finite(m) || !finite(op) || !finite(oq)) return false;
    auto zero = [](vec3 v) { return v.x == 0.0 && v.y == 0.0 && v.z == 0.0; };
    auto offset_zero = [&](double o) { return k.sgn([=](auto L) { return L(o); }) == sign::zero; };
    if (zero(n) || zero(m)) {
        // A zero normal with a nonzero offset is empty; with a zero offset it is all of space,
        // which meets the other plane iff that one is not empty.
        if (zero(n) && !offset_zero(op)) return false;
        if (zero(m) && !offset_zero(oq)) return false;
        return true;
    }
    for (int i = 0; i < 3; ++i) {
        const sign c = k.sgn([=](auto L) {
            const auto x = arith::cross(arith::lift(L, n), arith::lift(L, m));
            return i == 0 ? x.x : (i == 1 ? x.y : x.z);
        });
        if (c != sign::zero) return true;
    }
    // Parallel: the same plane, or disjoint.
    for (int i = 0; i < 3; ++i) {
        const double ni = i == 0 ? n.x : (i == 1 ? n.y : n.z), mi = i == 0 ? m.x : (i == 1 ? m.y : m.z);
        if (k.sgn([=](auto L) { return L(op) * L(mi) - L(oq) * L(ni); }) != sign::zero) return false;
    }
    return true;
}

// plane3 against point3 (the plane n . p = offset; a zero normal is everything when the offset
// is 0 and nothing otherwise).
// Semantics: the point lies on the plane, exactly.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const point3& p) {
    return plane_side(k, pl, p) == sign::zero;
}

// plane3 against ray3.
// Semantics: a closed ray (its origin included) meets the plane when its origin is on it or it
// heads towards it; a ray in the plane counts. A zero normal is everything when the offset is 0
// and nothing otherwise; a zero direction is the origin point.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const ray3& r) {
    return plane_linear(k, pl, as_linear(r));
}

// plane3 against segment3 (the plane n . p = offset; a closed segment, possibly a point).
// Semantics: an end point on the plane counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const segment3& s) {
    // the two signs directly (line_plane.cppm's plane_linear, which every linear object shares,
    // decides the same: 7.4 ns against 35.8 for CGAL Epick, measured before this body)
    const sign sa = plane_side(k, pl, s.a);
    if (sa == sign::zero) return finite(s.b); // the other end unread
    return plane_side(k, pl, s.b) != sa;
}

// plane3 against tetrahedron3 (the plane n . p = offset; closed solid tetrahedron, coplanar
// vertices give their hull). A zero normal is every point (offset 0) or none.
// Semantics: a vertex on the plane counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const tetrahedron3& t) {
    // Every vertex is read before answering, so a NaN or infinite one gives no in the exact tier.
    const sign s[4] = {plane_side(k, pl, t.a), plane_side(k, pl, t.b), plane_side(k, pl, t.c), plane_side(k, pl, t.d)};
    return !((s[0] == sign::positive || s[0] == sign::negative) && s[1] == s[0] && s[2] == s[0] && s[3] == s[0]);
}

// plane3 against triangle3 (the plane n . p = offset; a closed triangle, a collinear one is its
// hull). Semantics: a vertex on the plane counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& pl, const triangle3& t) {
    // An early yes leaves vertices unread: a NaN or infinite one makes no triangle.
    const sign sa = plane_side(k, pl, t.a);
    if (sa == sign::zero) return finite(t.b) && finite(t.c);
    const sign sb = plane_side(k, pl, t.b);
    if (sb != sa) return finite(t.c);
    return plane_side(k, pl, t.c) != sa;
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const aabb3&, const plane3&);
extern template bool exactly<intersects_body>(const line3&, const plane3&);
extern template bool exactly<intersects_body>(const plane3&, const plane3&);
extern template bool exactly<intersects_body>(const plane3&, const point3&);
extern template bool exactly<intersects_body>(const plane3&, const ray3&);
extern template bool exactly<intersects_body>(const plane3&, const segment3&);
extern template bool exactly<intersects_body>(const plane3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const plane3&, const triangle3&);
} // namespace incidence::detail
