// intersects: capsule_pairs
export module incidence.detail:intersects.capsule_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.sphere;
import :engines.tetrahedron;
import :engines.ball_flat;
import :engines.capsule;
import :intersects.box_pairs;
import :intersects.sphere_pairs;
import :intersects.triangle_pairs;
import :intersects.tetrahedron_pairs;
import :exactly;

export namespace incidence::detail {

// capsule3 against the point, the ball, the linear shapes, the plane, the triangle, the
// tetrahedron, the box and the capsule: engines/capsule.cppm (the segment's distance against the
// radius: its ends' balls, the segment itself, the shape's edges).
// Semantics: the closed capsule (the points within |r| of the closed segment ab; a = b is a ball);
// closed shapes as in their own pairs (a collinear triangle or a flat tetrahedron is its hull, a
// segment whose ends agree a point, a zero direction the origin, a zero normal everything when the
// offset is 0 and nothing otherwise). Touching counts. Unchecked negative radii act as |r|; a NaN or
// infinite number: no shape, so no.

[[nodiscard]] constexpr bool usable(const capsule3& c) { return finite(c.a) && finite(c.b) && finite(c.radius); }
[[nodiscard]] constexpr double reach(const capsule3& c) { return c.radius < 0.0 ? -c.radius : c.radius; }
[[nodiscard]] constexpr linear3 core(const capsule3& c) { return as_linear(segment3{c.a, c.b}); }

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const point3& p) {
    return usable(c) && finite(p) && ball_flat::meets(k, core(c), p, reach(c));
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const sphere3& s) {
    return usable(c) && ball::usable(s) && ball_flat::meets(k, core(c), s.center, ball_flat::radii{reach(c), ball::magnitude(s.radius)});
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& a, const capsule3& b) {
    return usable(a) && usable(b) && swept::linear_within(k, core(a), core(b), ball_flat::radii{reach(a), reach(b)});
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const segment3& s) {
    return usable(c) && finite(s) && swept::linear_within(k, core(c), as_linear(s), reach(c));
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const ray3& r) {
    return usable(c) && finite(r) && swept::linear_within(k, core(c), as_linear(r), reach(c));
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const line3& l) {
    return usable(c) && finite(l) && swept::linear_within(k, core(c), as_linear(l), reach(c));
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const plane3& p) {
    return usable(c) && finite(p.normal) && finite(p.offset) && swept::plane_within(k, p, c.a, c.b, reach(c));
}
// A triangle or a tetrahedron s with its edges: an end's ball meets s, the segment meets s, or the
// segment lies within the radius of an edge.
template <class K, class S, int N>
[[nodiscard]] constexpr bool swept_near(K& k, const capsule3& c, const S& s, const point3 (&edges)[N][2]) {
    const double r = reach(c);
    if (ball_flat::meets(k, s, c.a, r) || ball_flat::meets(k, s, c.b, r)) return true;
    if (intersects(k, segment3{c.a, c.b}, s)) return true;
    return swept::near_edges(k, c.a, c.b, edges, N, r);
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const triangle3& t) {
    const point3 edges[3][2] = {{t.a, t.b}, {t.b, t.c}, {t.c, t.a}};
    return usable(c) && finite(t) && swept_near(k, c, t, edges);
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const tetrahedron3& t) {
    const point3 edges[6][2] = {{t.a, t.b}, {t.a, t.c}, {t.a, t.d}, {t.b, t.c}, {t.b, t.d}, {t.c, t.d}};
    return usable(c) && finite(t) && swept_near(k, c, t, edges);
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const capsule3& c) {
    if (!usable(c) || !ball::usable(b)) return false;
    const double r = reach(c);
    if (intersects(k, b, sphere3{c.a, r}) || intersects(k, b, sphere3{c.b, r})) return true;
    if (intersects(k, b, segment3{c.a, c.b})) return true;
    const point3 lo = b.min, hi = b.max;
    auto corner = [&](int m) { return point3{(m & 1) ? hi.x : lo.x, (m & 2) ? hi.y : lo.y, (m & 4) ? hi.z : lo.z}; };
    point3 edges[12][2];
    int n = 0;
    for (int m = 0; m < 8; ++m)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(m & bit)) edges[n][0] = corner(m), edges[n][1] = corner(m | bit), ++n;
    return swept::near_edges(k, c.a, c.b, edges, 12, r);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const capsule3&, const point3&);
extern template bool exactly<intersects_body>(const capsule3&, const sphere3&);
extern template bool exactly<intersects_body>(const capsule3&, const capsule3&);
extern template bool exactly<intersects_body>(const capsule3&, const segment3&);
extern template bool exactly<intersects_body>(const capsule3&, const ray3&);
extern template bool exactly<intersects_body>(const capsule3&, const line3&);
extern template bool exactly<intersects_body>(const capsule3&, const plane3&);
extern template bool exactly<intersects_body>(const capsule3&, const triangle3&);
extern template bool exactly<intersects_body>(const capsule3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const aabb3&, const capsule3&);
} // namespace incidence::detail
