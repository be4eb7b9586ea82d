// contains: mesh_pairs
module;
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>
export module incidence.detail:contains.mesh_pairs;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :engines.tetrahedron;
import :engines.box;
import :intersects.triangle_pairs;
import :engines.box_triangle;
import :intersects.box_pairs;
import :intersects.linear_pairs;
import :intersects.tetrahedron_pairs;
import :contains.tetrahedron_pairs;
import :contains.box_pairs;
import :engines.segment_pieces;
import :engines.mesh;
import :intersects.mesh_pairs;
import :exactly;

export namespace incidence::detail {

// mesh3 against point3, contains(mesh, point), and the engine every mesh pair shares.
// Semantics: the mesh's point set is its triangles together with the points from which a ray
// crosses the surface an odd number of times (shapes/mesh3.cppm); a point on a triangle counts.
// contains(mesh, point): the same set.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const mesh3& m, const point3& p) {
    return intersects(k, m, p);
}

// mesh3 against segment3 (a point when a == b), and contains(mesh, segment).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const mesh3& m, const segment3& s) {
    using solid_mesh::segment_param;
    if (!solid_mesh::well_formed(m) || !finite(s)) return false;
    const aabb3 mb = solid_mesh::bounds(m);
    if (!solid_mesh::in_box(mb, s.a) || !solid_mesh::in_box(mb, s.b)) return false; // the set lies in the vertices' box
    if (s.a.x == s.b.x && s.a.y == s.b.y && s.a.z == s.b.z) return contains(k, m, s.a);
    const point3 pts[2] = {s.a, s.b};
    const aabb3 sb = solid_mesh::bounds(pts, 2);
    // An axis along which the segment moves, for the parameters of points (det(e_j+1, e_j+2, x - a) = (x - a)_j).
    const int j = s.a.x != s.b.x ? 0 : (s.a.y != s.b.y ? 1 : 2);
    const point3 u1 = solid_mesh::unit((j + 1) % 3), u2 = solid_mesh::unit((j + 2) % 3);
    auto fraction = [s](auto L, const segment_param& p) { return p.fraction(L, s); };
    std::vector<segment_param> params;
    std::vector<std::size_t> in_plane; // triangles that may hold a piece of the segment
    bool met = false;
    auto keep = [&](const segment_param& p) { return pieces::keep(k, fraction, p, params); };
    auto at_point = [&](point3 x) { (void)keep(segment_param{x, solid_mesh::origin, u1, solid_mesh::origin, u2}); };
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 t = m.triangle(i);
        const point3 v[3] = {t.a, t.b, t.c};
        if (!solid_mesh::boxes_meet(solid_mesh::bounds(v, 3), sb) || !intersects(k, s, t)) continue;
        met = true;
        const sign oa = k.sgn([=](auto L) { return poly::orient3d(L, t.a, t.b, t.c, s.a); });
        const sign ob = k.sgn([=](auto L) { return poly::orient3d(L, t.a, t.b, t.c, s.b); });
        if (oa != sign::zero || ob != sign::zero) { // across the plane: one point
            (void)keep(segment_param{t.a, t.a, t.b, t.a, t.c});
            continue;
        }
        in_plane.push_back(i);
        for (int e = 0; e < 3; ++e) {
            const point3 p = v[e], q = v[(e + 1) % 3];
            bool crossed = false;
            for (int axis = 0; axis < 3 && !crossed; ++axis)
                crossed = keep(segment_param{p, p, q, solid_mesh::origin, solid_mesh::unit(axis)});
            if (!crossed) at_point(p), at_point(q); // parallel to the segment
        }
    }
    if (!met) return solid_mesh::inside(k, m, s.a); // wholly off the surface
    // t = (a - a)_j / (b - a)_j = 0 and (b - a)_j / (b - a)_j = 1, D made positive
    const bool flip = s.b.x != s.a.x ? s.b.x < s.a.x : (s.b.y != s.a.y ? s.b.y < s.a.y : s.b.z < s.a.z);
    const segment_param start{s.a, solid_mesh::origin, u1, solid_mesh::origin, u2, flip},
        end{s.b, solid_mesh::origin, u1, solid_mesh::origin, u2, flip};
    // a piece on a triangle in its plane, or else inside
    auto decide = [&](const auto& q) {
        for (std::size_t n = 0; n < in_plane.size(); ++n)
            if (solid_mesh::on_triangle(k, m.triangle(in_plane[n]), q)) return true;
        return solid_mesh::inside_at(k, m, q);
    };
    return pieces::all_pieces(
        k, params, start, end, fraction, [&](double t) { return decide(solid_mesh::at_weighted<solid_mesh::segment_at>{{{sb}, s, t}}); },
        [&](const segment_param& lo, const segment_param& hi) {
            return decide(solid_mesh::at_weighted<solid_mesh::segment_point>{{{sb}, s, lo, hi}});
        });
}

// mesh3 against triangle3 (a collinear triangle is its hull), and contains(mesh, triangle).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const mesh3& m, const triangle3& t) {
    if (!solid_mesh::well_formed(m) || !finite(t)) return false;
    const aabb3 mb = solid_mesh::bounds(m);
    if (!solid_mesh::in_box(mb, t.a) || !solid_mesh::in_box(mb, t.b) || !solid_mesh::in_box(mb, t.c))
        return false; // the set lies in the vertices' box
    int axis = -1;
    for (int ax = 0; ax < 3 && axis < 0; ++ax)
        if (!arith::is_zero(k, [=](auto L) {
                const auto A = arith::lift(L, t.a);
                const auto n = arith::cross(arith::lift(L, t.b) - A, arith::lift(L, t.c) - A);
                return ax == 0 ? n.x : (ax == 1 ? n.y : n.z);
            }))
            axis = ax;
    if (axis < 0) // collinear: the union of its edges
        return contains(k, m, segment3{t.a, t.b}) && contains(k, m, segment3{t.b, t.c}) && contains(k, m, segment3{t.c, t.a});
    if (!contains(k, m, t.a) || !contains(k, m, t.b) || !contains(k, m, t.c)) return false;
    const point3 v[3] = {t.a, t.b, t.c};
    const aabb3 tb = solid_mesh::bounds(v, 3);
    std::vector<std::size_t> near;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 f = m.triangle(i);
        const point3 w[3] = {f.a, f.b, f.c};
        if (solid_mesh::boxes_meet(solid_mesh::bounds(w, 3), tb) && intersects(k, f, t)) near.push_back(i);
    }
    if (near.empty()) return true; // wholly off the surface, and a vertex is inside
    bool on[3] = {false, false, false};
    for (int j = 0; j < 3; ++j)
        for (std::size_t n = 0; n < near.size() && !on[j]; ++n) on[j] = intersects(k, v[j], m.triangle(near[n]));
    for (int pass = 0; pass < 2; ++pass)
        for (int j = 0; j < 3; ++j) {
            if (pass == 0 && on[j]) continue;
            const solid_mesh::sweep_frame fr{v[j], v[(j + 1) % 3], v[(j + 2) % 3], axis};
            const solid_mesh::sweep_result r = solid_mesh::sweep(k, m, fr, pass == 0, near);
            if (r != solid_mesh::sweep_result::retry) return r == solid_mesh::sweep_result::inside;
            if (solid_mesh::gave_up(k)) return false;
        }
    return false; // see the top comment
}

// aabb3 against mesh3 (closed box; an inverted box is empty), and contains(mesh, box).
// Semantics: the mesh's point set (shapes/mesh3.cppm: its triangles and the points of odd
// crossing parity); touching a triangle counts.

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const mesh3& m, const aabb3& b) {
    if (!solid_mesh::well_formed(m) || !well_formed_finite(b)) return false;
    const aabb3 mb = solid_mesh::bounds(m);
    if (!solid_mesh::in_box(mb, b.min) || !solid_mesh::in_box(mb, b.max)) return false; // the set lies in the vertices' box
    const bool flat[3] = {b.min.x == b.max.x, b.min.y == b.max.y, b.min.z == b.max.z};
    if (int(flat[0]) + int(flat[1]) + int(flat[2]) >= 2) return contains(k, m, segment3{b.min, b.max}); // a segment or a point
    for (int i = 0; i < 3; ++i)
        if (flat[i]) { // a rectangle: its two triangles
            const int j = (i + 1) % 3;
            const point3 c10 = box_triangle::with(b.min, j, solid_mesh::coord(b.max, j));
            const point3 c01 = box_triangle::with(b.max, j, solid_mesh::coord(b.min, j));
            return contains(k, m, triangle3{b.min, c10, b.max}) && contains(k, m, triangle3{b.min, b.max, c01});
        }
    // The walls: non-collinear triangles reaching the interior (a triangle whose box does not
    // overlap the interior's cannot).
    std::vector<std::size_t> walls;
    for (std::size_t i = 0; i < m.triangles.size(); ++i) {
        const triangle3 f = m.triangle(i);
        const point3 v[3] = {f.a, f.b, f.c};
        const aabb3 fb = solid_mesh::bounds(v, 3);
        if (!(fb.min.x < b.max.x && b.min.x < fb.max.x && fb.min.y < b.max.y && b.min.y < fb.max.y && fb.min.z < b.max.z &&
              b.min.z < fb.max.z))
            continue;
        if (meets_interior(k, b, f) && solid_mesh::normal_axis(k, f) >= 0) walls.push_back(i);
    }
    if (solid_mesh::gave_up(k)) return false; // (the filter's answer is discarded: the exact kernel decides)
    // By plane: a plane with one wall is odd inside the box; several are added up.
    std::vector<unsigned char> grouped(walls.size(), 0);
    std::vector<std::size_t> group;
    for (std::size_t i = 0; i < walls.size(); ++i) {
        if (grouped[i] != 0) continue;
        const triangle3 r = m.triangle(walls[i]);
        group.assign(1, walls[i]);
        for (std::size_t j = i + 1; j < walls.size(); ++j)
            if (grouped[j] == 0 && solid_mesh::coplanar(k, r, m.triangle(walls[j]))) grouped[j] = 1, group.push_back(walls[j]);
        if (group.size() == 1 || solid_mesh::odd_inside(k, m, b, group) || solid_mesh::gave_up(k)) return false;
    }
    return solid_mesh::inside_at(k, m, solid_mesh::at_weighted<solid_mesh::box_centre>{{{b}}});
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const mesh3&, const point3&);
extern template bool exactly<contains_body>(const mesh3&, const segment3&);
extern template bool exactly<contains_body>(const mesh3&, const triangle3&);
extern template bool exactly<contains_body>(const mesh3&, const aabb3&);
} // namespace incidence::detail
