// intersects: sphere_pairs
module;
#include <array>
#include <optional>
export module incidence.detail:intersects.sphere_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.sphere;
import :engines.kdop;
import :engines.halfspace_slabs;
import :engines.ball_halfspaces;
import :engines.ball_obb;
import :engines.ball_flat;
import :engines.linear;
import :engines.polygon3;
import :engines.separating_axes;
import :engines.tetrahedron;
import :exactly;

export namespace incidence::detail {

// aabb3 against sphere3 (closed box, closed ball): intersects, contains(aabb3, sphere3) and
// contains(sphere3, aabb3).
// Semantics: touching counts; a box contains a ball it touches from inside. Unchecked negative
// radii act as |r| (as in point_sphere); inverted, infinite or NaN input meets and holds nothing.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const sphere3& s) {
    if (!ball::usable(b) || !ball::usable(s)) return false;
    const double c[3] = {s.center.x, s.center.y, s.center.z};
    const double mn[3] = {b.min.x, b.min.y, b.min.z}, mx[3] = {b.max.x, b.max.y, b.max.z};
    // the nearest point's gap on each axis: from the centre up to min, from max up to the centre, or none
    double lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
        if (c[i] < mn[i]) lo[i] = c[i], hi[i] = mn[i];
        else if (c[i] > mx[i]) lo[i] = mx[i], hi[i] = c[i];
        else lo[i] = hi[i] = 0.0;
    }
    const double r = s.radius;
    return k.sgn([=](auto L) {
        auto g = [&](int i) { return L(hi[i]) - L(lo[i]); };
        const auto g0 = g(0), g1 = g(1), g2 = g(2);
        return L(r) * L(r) - (g0 * g0 + g1 * g1 + g2 * g2);
    }) != sign::negative;
}

// point3 against sphere3 (the closed ball).
// Semantics: the point intersects the ball iff |p - c| <= r (on the sphere counts).

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point3& p, const sphere3& s) {
    return k.sgn([=](auto L) {
        const auto d = arith::lift(L, p) - arith::lift(L, s.center);
        const auto r = L(s.radius);
        return r * r - arith::dot(d, d);
    }) != sign::negative;
}

// ray3 against sphere3 (closed ball): intersects, and intersection = the first point with t >= 0.
// Semantics: a ray that starts inside or on the ball hits at t = 0; a ray tangent to the sphere
// hits at the tangent point; a zero direction is the point `origin`.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray3& r, const sphere3& s) {
    const auto m_of = [=](auto L) { return arith::lift(L, r.origin) - arith::lift(L, s.center); };
    const sign c = k.sgn([=](auto L) {
        const auto m = m_of(L);
        const auto rr = L(s.radius);
        return arith::dot(m, m) - rr * rr;
    });
    // the origin in the ball: a hit, if the ray is one (a non-finite direction: no, as every pair
    // answers for a non-finite input; intersection() agrees)
    if (c != sign::positive) return is_finite(r.direction);
    const sign b = k.sgn([=](auto L) { return arith::dot(m_of(L), arith::lift(L, r.direction)); });
    if (b != sign::negative) return false;
    return k.sgn([=](auto L) {
        const auto m = m_of(L);
        const auto d = arith::lift(L, r.direction);
        const auto rr = L(s.radius);
        const auto bb = arith::dot(m, d);
        return bb * bb - arith::dot(d, d) * (arith::dot(m, m) - rr * rr);
    }) != sign::negative;
}
// The approximate tier of intersects(ray3, sphere3) is the optimized geometric method.
[[nodiscard]] constexpr bool intersects_approximate(const ray3& r, const sphere3& s) { return ray_sphere_geometric(r, s).has_value(); }

// sphere3 against sphere3 (closed balls).
// Semantics: intersects iff |c1 - c2| <= r1 + r2 (tangent balls intersect);
// contains(a, b) iff ball b lies inside ball a: r_a >= r_b and |ca - cb| <= r_a - r_b
// (internally tangent counts; equal balls contain each other). Unchecked negative radii act as
// |r|, as in every other pair of the ball.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const sphere3& a, const sphere3& b) {
    return k.sgn([=](auto L) {
        const auto d = arith::lift(L, a.center) - arith::lift(L, b.center);
        const auto r = L(ball::magnitude(a.radius)) + L(ball::magnitude(b.radius));
        return r * r - arith::dot(d, d);
    }) != sign::negative;
}

// segment3, line3, plane3, triangle3 and tetrahedron3 against sphere3 (closed shapes, the closed
// ball): ball_flat.cppm's closest features. Semantics: touching counts; a segment whose ends agree
// is a point, a line with a zero direction its origin, a plane with a zero normal everything when
// its offset is 0 and nothing otherwise, a collinear triangle or a flat tetrahedron its hull;
// unchecked negative radii act as |r|; a NaN or infinite number: no shape, so no.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const segment3& g, const sphere3& s) {
    return finite(g) && ball::usable(s) && ball_flat::meets(k, as_linear(g), s.center, s.radius);
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& g, const sphere3& s) {
    return finite(g) && ball::usable(s) && ball_flat::meets(k, as_linear(g), s.center, s.radius);
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const plane3& p, const sphere3& s) {
    return finite(p.normal) && finite(p.offset) && ball::usable(s) && ball_flat::meets(k, p, s.center, s.radius);
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const sphere3& s, const triangle3& t) {
    return finite(t) && ball::usable(s) && ball_flat::meets(k, t, s.center, s.radius);
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const sphere3& s, const tetrahedron3& t) {
    return finite(t) && ball::usable(s) && ball_flat::meets(k, t, s.center, s.radius);
}

// polygon3 against sphere3 (the polygon's point set, shapes/polygon3.cppm; the closed ball):
// ball_flat.cppm's plane, foot and edges. Semantics: touching counts; a polygon that is no set
// (bad indices, non-finite vertices, a plane normal with no component along its axis) meets
// nothing; for vertices that are not coplanar the answer is that of the procedure (the plane of
// the three plane vertices, then the edges), as in every polygon pair. Unchecked negative radii
// act as |r|.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const polygon3& g, const sphere3& s) {
    return ball::usable(s) && polygon3d::usable(k, g) && ball_flat::meets(k, g, s.center, s.radius);
}

// obb3 against sphere3 (closed box read as the parallelepiped its axes span, closed ball):
// ball_obb.cppm's box coordinates. Semantics: touching at a face, an edge or a corner counts; a box
// with dependent axes is the flat set they span; unchecked negative radii act as |r|; NaN,
// infinite or negative extents and non-finite input: no box, so no.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& b, const sphere3& s) {
    if (!sat::well_formed(b) || !finite(b) || !ball::usable(s)) return false;
    return ball_obb::meets(k, b, s);
}

// convex_polyhedron3, frustum3 and kdop<K> against sphere3 (the closed ball): the half-space rows
// of ball_halfspaces.cppm (a k-DOP's slabs as its 2 x K/2 rows, read exactly).
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded), the frustum's view volume, the closed k-DOP; a non-finite number, a count outside
// [0, capacity] or an empty k-DOP slab: no set, so no. Unchecked negative radii act as |r|.
// Touching at a face, an edge or a vertex counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& p, const sphere3& s) {
    if (!halfspaces::well_formed(p.planes.data(), p.count, convex_polyhedron3::capacity) || !ball::usable(s)) return false;
    return ball_rows::meets(k, p.planes.data(), p.count, s);
}
template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const sphere3& s) {
    if (!halfspaces::well_formed(f.planes.data(), 6, 6) || !ball::usable(s)) return false;
    return ball_rows::meets(k, f.planes.data(), 6, s);
}
template <class K, int N>
[[nodiscard]] constexpr bool intersects(K& k, const kdop<N>& b, const sphere3& s) {
    if (!kdop_slabs::well_formed(b) || !ball::usable(s)) return false;
    const std::array<plane3, N> rows = kdop_slabs::halfspaces(b);
    return ball_rows::meets(k, rows.data(), N, s);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const aabb3&, const sphere3&);
extern template bool exactly<intersects_body>(const point3&, const sphere3&);
extern template bool exactly<intersects_body>(const ray3&, const sphere3&);
extern template bool exactly<intersects_body>(const sphere3&, const sphere3&);
extern template bool exactly<intersects_body>(const obb3&, const sphere3&);
extern template bool exactly<intersects_body>(const segment3&, const sphere3&);
extern template bool exactly<intersects_body>(const line3&, const sphere3&);
extern template bool exactly<intersects_body>(const plane3&, const sphere3&);
extern template bool exactly<intersects_body>(const sphere3&, const triangle3&);
extern template bool exactly<intersects_body>(const sphere3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const polygon3&, const sphere3&);
extern template bool exactly<intersects_body>(const convex_polyhedron3&, const sphere3&);
extern template bool exactly<intersects_body>(const frustum3&, const sphere3&);
extern template bool exactly<intersects_body>(const kdop<6>&, const sphere3&);
extern template bool exactly<intersects_body>(const kdop<14>&, const sphere3&);
extern template bool exactly<intersects_body>(const kdop<18>&, const sphere3&);
extern template bool exactly<intersects_body>(const kdop<26>&, const sphere3&);
} // namespace incidence::detail
