// intersects: capsule_pairs
module;
#include <array>
#include <utility>
export module incidence.detail:intersects.capsule_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.sphere;
import :engines.tetrahedron;
import :engines.ball_flat;
import :engines.capsule;
import :engines.polygon3;
import :engines.mesh;
import :engines.capsule_rows;
import :engines.halfspace_slabs;
import :engines.kdop;
import :engines.separating_axes;
import :engines.ball_obb;
import :engines.capsule_obb;
import :engines.certificate;
import :intersects.box_pairs;
import :intersects.sphere_pairs;
import :intersects.triangle_pairs;
import :intersects.tetrahedron_pairs;
import :exactly;

export namespace incidence::detail {

// capsule3 against the point, the ball, the linear shapes, the plane, the triangle, the
// tetrahedron, the box, the oriented box, the capsule, the polygon, the solid mesh and the half-space sets: engines/capsule.cppm (the segment's distance against the
// radius: its ends' balls, the segment itself, the shape's edges). Against a capsule, a box and an
// oriented box, plain double's closest points come first (engines/certificate.cppm): a witness
// pair within the radii or a separating direction settles most inputs in a few signs, and the case
// analysis decides the rest.
// Semantics: the closed capsule (the points within |r| of the closed segment ab; a = b is a ball);
// closed shapes as in their own pairs (a collinear triangle or a flat tetrahedron is its hull, a
// segment whose ends agree a point, a zero direction the origin, a zero normal everything when the
// offset is 0 and nothing otherwise). Touching counts. Unchecked negative radii act as |r|; a NaN or
// infinite number: no shape, so no.

[[nodiscard]] constexpr bool usable(const capsule3& c) { return finite(c.a) && finite(c.b) && finite(c.radius); }
[[nodiscard]] constexpr double reach(const capsule3& c) { return c.radius < 0.0 ? -c.radius : c.radius; }
[[nodiscard]] constexpr linear3 core(const capsule3& c) { return as_linear(segment3{c.a, c.b}); }

// Lexicographic order of the coordinates, then the radius.
[[nodiscard]] constexpr bool capsule_less(const capsule3& x, const capsule3& y) {
    const double u[7] = {x.a.x, x.a.y, x.a.z, x.b.x, x.b.y, x.b.z, x.radius};
    const double w[7] = {y.a.x, y.a.y, y.a.z, y.b.x, y.b.y, y.b.z, y.radius};
    return numbers_before(u, w, 7);
}

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
    if (!usable(a) || !usable(b)) return false;
    const ball_flat::radii r{reach(a), reach(b)};
    // the guess in one order of the two, so that both argument orders settle the same cases
    const auto [p, q] = capsule_less(b, a) ? std::pair{&b, &a} : std::pair{&a, &b};
    if (const auto v = certificate::segment_segment(k, p->a, p->b, q->a, q->b, r); v != certificate::verdict::open)
        return v == certificate::verdict::meets;
    return swept::linear_within(k, core(a), core(b), r);
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
    if (const auto v = certificate::segment_box(k, c.a, c.b, b, r); v != certificate::verdict::open)
        return v == certificate::verdict::meets;
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

// An oriented box: engines/capsule_obb.cppm (a ball when a = b: ball_obb.cppm; the segment against
// the box by separating axes, then the box's coordinates and the segment's parameter). Semantics:
// the closed box read as the parallelepiped its axes span (skew, flat or a point as given); NaN,
// infinite or negative extents: no box, so no.
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const obb3& b) {
    if (!usable(c) || !sat::well_formed(b) || !finite(b)) return false;
    const double r = reach(c);
    if (c.a == c.b) return ball_obb::meets(k, b, sphere3{c.a, r});
    if (const auto v = certificate::segment_obb(k, c.a, c.b, b, r); v != certificate::verdict::open)
        return v == certificate::verdict::meets;
    if (sat::zonotopes_intersect(k, sat::zonotope_of(b), sat::zonotope_of(segment3{c.a, c.b}))) return true;
    return swept_obb::meets(k, b, c.a, c.b, r);
}

// A polygon: an end's ball meets it, the segment meets it (polygon3d::linear_meets), or the
// segment lies within the radius of an edge of a ring (the sliding argument of capsule.cppm holds
// for any closed planar set bounded by segments).
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const polygon3& g) {
    if (!usable(c) || !polygon3d::usable(k, g)) return false;
    const double r = reach(c);
    if (ball_flat::meets(k, g, c.a, r) || ball_flat::meets(k, g, c.b, r)) return true;
    const linear3 s = core(c);
    if (polygon3d::linear_meets(k, g, s)) return true;
    return polygon3d::any_edge(g, [&](const segment3& e) { return swept::linear_within(k, s, as_linear(e), r, true); });
}
// A solid mesh: the capsule meets a triangle, or its end a is inside (a capsule that meets the
// solid and no triangle lies wholly inside it); the triangles whose boxes miss the capsule's box
// (rounded outward) are skipped.
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const mesh3& m) {
    if (!usable(c) || !solid_mesh::well_formed(m)) return false;
    const point3 ends[2] = {c.a, c.b};
    const aabb3 xb = ball_flat::reach_box(ends, 2, reach(c));
    if (!solid_mesh::boxes_meet(solid_mesh::bounds(m), xb)) return false;
    return solid_mesh::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, c, f); }, c.a, &xb);
}

// The half-space sets: engines/capsule_rows.cppm (the end balls, the segment, then the rows' lines
// and vertices within the radius of the segment's inside). Semantics: the closed half-space set of
// convex_polyhedron_point.cppm (possibly empty or unbounded), the frustum's view volume, the closed
// k-DOP; a non-finite number, a count outside [0, capacity] or an empty k-DOP slab: no set, so no.
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const convex_polyhedron3& p) {
    if (!usable(c) || !halfspaces::well_formed(p.planes.data(), p.count, convex_polyhedron3::capacity)) return false;
    return swept_rows::meets(k, p.planes.data(), p.count, c.a, c.b, reach(c));
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const frustum3& f) {
    if (!usable(c) || !halfspaces::well_formed(f.planes.data(), 6, 6)) return false;
    return swept_rows::meets(k, f.planes.data(), 6, c.a, c.b, reach(c));
}
template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const capsule3& c, const kdop<N>& b) {
    if (!usable(c) || !kdop_slabs::well_formed(b)) return false;
    const std::array<plane3, N> rows = kdop_slabs::halfspaces(b);
    return swept_rows::meets(k, rows.data(), N, c.a, c.b, reach(c));
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
extern template bool exactly<intersects_body>(const capsule3&, const obb3&);
extern template bool exactly<intersects_body>(const capsule3&, const polygon3&);
extern template bool exactly<intersects_body>(const capsule3&, const mesh3&);
extern template bool exactly<intersects_body>(const capsule3&, const convex_polyhedron3&);
extern template bool exactly<intersects_body>(const capsule3&, const frustum3&);
extern template bool exactly<intersects_body>(const capsule3&, const kdop<6>&);
extern template bool exactly<intersects_body>(const capsule3&, const kdop<14>&);
extern template bool exactly<intersects_body>(const capsule3&, const kdop<18>&);
extern template bool exactly<intersects_body>(const capsule3&, const kdop<26>&);
} // namespace incidence::detail
