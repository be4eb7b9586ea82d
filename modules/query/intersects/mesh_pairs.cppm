// intersects: mesh_pairs
module;
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>
export module incidence.detail:intersects.mesh_pairs;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :engines.separating_axes;
import :engines.triangle;
import :engines.tetrahedron;
import :engines.box;
import :intersects.triangle_pairs;
import :intersects.box_pairs;
import :intersects.linear_pairs;
import :intersects.tetrahedron_pairs;
import :engines.mesh;
import :engines.polygon3;
import :engines.sphere;
import :engines.ball_flat;
import :engines.plane;
import :intersects.obb_pairs;
import :intersects.plane_pairs;
import :intersects.polygon_pairs;
import :exactly;

export namespace incidence::detail {

// mesh3 against point3, contains(mesh, point), and the engine every mesh pair shares.
// Semantics: the mesh's point set is its triangles together with the points from which a ray
// crosses the surface an odd number of times (shapes/mesh3.cppm); a point on a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const point3& p) {
    if (!solid_mesh::well_formed(m) || !finite(p) || !solid_mesh::in_box(solid_mesh::bounds(m), p)) return false;
    const aabb3 xb{p, p};
    return solid_mesh::mesh_meets(k, m, [&](const triangle3& f) { return linear_triangle(k, as_linear(p), f); }, p, &xb);
}

// mesh3 against segment3 (a point when a == b), and contains(mesh, segment).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const segment3& s) {
    if (!solid_mesh::well_formed(m) || !finite(s)) return false;
    const point3 pts[2] = {s.a, s.b};
    const aabb3 xb = solid_mesh::bounds(pts, 2);
    if (!solid_mesh::boxes_meet(solid_mesh::bounds(m), xb)) return false;
    return solid_mesh::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, s, f); }, s.a, &xb);
}

// mesh3 against triangle3 (a collinear triangle is its hull), and contains(mesh, triangle).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const triangle3& t) {
    if (!solid_mesh::well_formed(m) || !finite(t)) return false;
    const point3 pts[3] = {t.a, t.b, t.c};
    const aabb3 xb = solid_mesh::bounds(pts, 3);
    if (!solid_mesh::boxes_meet(solid_mesh::bounds(m), xb)) return false;
    return solid_mesh::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, f, t); }, t.a, &xb);
}

// aabb3 against mesh3 (closed box; an inverted box is empty), and contains(mesh, box).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const mesh3& m) {
    if (!solid_mesh::well_formed(m) || !well_formed_finite(b) || !solid_mesh::boxes_meet(solid_mesh::bounds(m), b)) return false;
    return solid_mesh::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, b, f); }, b.min, &b);
}

// line3 against mesh3 (a point when the direction is zero).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const mesh3& m) {
    if (!solid_mesh::well_formed(m) || !finite(l)) return false;
    return solid_mesh::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, l, f); }, l.origin);
}

// mesh3 against mesh3.
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& a, const mesh3& b) {
    if (!solid_mesh::well_formed(a) || !solid_mesh::well_formed(b) || !solid_mesh::boxes_meet(solid_mesh::bounds(a), solid_mesh::bounds(b)))
        return false;
    // Every triangle pair is tested in both orders' evaluation, so (a, b) and (b, a) agree in every tier.
    for (std::size_t i = 0; i < a.triangles.size(); ++i) {
        const triangle3 f = a.triangle(i);
        const point3 fv[3] = {f.a, f.b, f.c};
        const aabb3 fb = solid_mesh::bounds(fv, 3);
        for (std::size_t j = 0; j < b.triangles.size(); ++j) {
            const triangle3 g = b.triangle(j);
            const point3 gv[3] = {g.a, g.b, g.c};
            if (solid_mesh::boxes_meet(fb, solid_mesh::bounds(gv, 3)) && intersects(k, f, g)) return true;
        }
    }
    return solid_mesh::inside(k, a, b.vertices[b.triangles[0][0]]) || solid_mesh::inside(k, b, a.vertices[a.triangles[0][0]]);
}

// mesh3 against obb3 (closed box read as the parallelepiped its axes span).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const obb3& b) {
    if (!solid_mesh::well_formed(m) || !sat::well_formed(b) || !finite(b)) return false;
    return solid_mesh::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, b, f); }, b.center);
}

// mesh3 against plane3 (n . p = offset; a zero normal is everything (offset 0) or nothing).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const plane3& pl) {
    if (!solid_mesh::well_formed(m)) return false;
    // Every vertex is read, so a NaN or infinite plane gives no in the exact tier.
    bool pos = false, neg = false, zero = false;
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
        const sign s = plane_side(k, pl, m.vertices[i]);
        pos = pos || s == sign::positive;
        neg = neg || s == sign::negative;
        zero = zero || s == sign::zero;
    }
    return zero || (pos && neg);
}

// mesh3 against polygon3.
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity) and the polygon's (shapes/polygon3.cppm). Touching counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const polygon3& g) {
    if (!solid_mesh::well_formed(m) || !polygon3d::usable(k, g)) return false;
    const aabb3 gb = solid_mesh::bounds(g.vertices.data(), g.vertices.size());
    if (!solid_mesh::boxes_meet(solid_mesh::bounds(m), gb)) return false;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 t = m.triangle(i);
        const point3 v[3] = {t.a, t.b, t.c};
        if (solid_mesh::boxes_meet(solid_mesh::bounds(v, 3), gb) && intersects(k, g, t)) return true;
    }
    for (std::size_t r = 0; r < g.rings(); ++r)
        if (solid_mesh::inside(k, m, g.vertices[g.ring_begin(r)])) return true;
    return false;
}

// mesh3 against sphere3 (the closed ball; unchecked negative radii act as |r|).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts. Method: the ball meets a triangle
// (ball_flat.cppm, degree <= 6), or its centre is inside (a ball that meets the solid and no
// triangle lies wholly inside it); the triangles whose boxes miss the ball's box (rounded
// outward) are skipped.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const sphere3& s) {
    if (!solid_mesh::well_formed(m) || !ball::usable(s)) return false;
    const double r = ball::magnitude(s.radius);
    const aabb3 xb = ball_flat::reach_box(&s.center, 1, r);
    if (!solid_mesh::boxes_meet(solid_mesh::bounds(m), xb)) return false;
    return solid_mesh::mesh_meets(k, m, [&](const triangle3& f) { return ball_flat::meets(k, f, s.center, r); }, s.center, &xb);
}

// mesh3 against ray3 (a point when the direction is zero).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const ray3& r) {
    if (!solid_mesh::well_formed(m) || !finite(r)) return false;
    return solid_mesh::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, r, f); }, r.origin);
}

// mesh3 against tetrahedron3 (closed solid; coplanar vertices give their hull).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const mesh3& m, const tetrahedron3& t) {
    if (!solid_mesh::well_formed(m) || !finite(t)) return false;
    const point3 pts[4] = {t.a, t.b, t.c, t.d};
    const aabb3 xb = solid_mesh::bounds(pts, 4);
    if (!solid_mesh::boxes_meet(solid_mesh::bounds(m), xb)) return false;
    return solid_mesh::mesh_meets(k, m, [&](const triangle3& f) { return intersects(k, t, f); }, t.a, &xb);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const mesh3&, const point3&);
extern template bool exactly<intersects_body>(const mesh3&, const segment3&);
extern template bool exactly<intersects_body>(const mesh3&, const triangle3&);
extern template bool exactly<intersects_body>(const mesh3&, const sphere3&);
extern template bool exactly<intersects_body>(const aabb3&, const mesh3&);
extern template bool exactly<intersects_body>(const line3&, const mesh3&);
extern template bool exactly<intersects_body>(const mesh3&, const mesh3&);
extern template bool exactly<intersects_body>(const mesh3&, const obb3&);
extern template bool exactly<intersects_body>(const mesh3&, const plane3&);
extern template bool exactly<intersects_body>(const mesh3&, const polygon3&);
extern template bool exactly<intersects_body>(const mesh3&, const ray3&);
extern template bool exactly<intersects_body>(const mesh3&, const tetrahedron3&);
} // namespace incidence::detail
