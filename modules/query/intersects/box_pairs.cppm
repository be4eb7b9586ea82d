// intersects: box_pairs
module;
#include <optional>
export module incidence.detail:intersects.box_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.tetrahedron;
import :engines.box;
import :engines.box_triangle;
import :exactly;

export namespace incidence::detail {

// aabb3 against aabb3: intersects, contains, and covers(a, b, c): does a u b contain c?
// Semantics: closed boxes; touching faces, edges or corners intersect; a box contains itself.

// Comparisons alone decide it, in every tier: query.cppm's decide_pair runs the body once, with
// no filter pass around it (by_comparisons).
[[nodiscard]] consteval bool decided_by_comparisons(const aabb3*, const aabb3*) { return true; }
template <class K>
[[nodiscard]] constexpr bool intersects(K&, const aabb3& a, const aabb3& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

// aabb3 against point3, and the point's minimum and maximum squared distance to the box.
// Semantics: closed box, so a point on a face, edge or corner intersects.

// Comparisons alone decide it, in every tier: query.cppm's decide_pair runs the body once, with
// no filter pass around it (by_comparisons).
[[nodiscard]] consteval bool decided_by_comparisons(const aabb3*, const point3*) { return true; }
template <class K>
[[nodiscard]] constexpr bool intersects(K&, const aabb3& b, const point3& p) {
    return b.min.x <= p.x && p.x <= b.max.x && b.min.y <= p.y && p.y <= b.max.y && b.min.z <= p.z && p.z <= b.max.z;
}

// aabb3 against triangle3 (closed box, closed triangle; a collinear triangle is its hull).
// Semantics: touching at a vertex, along an edge or on a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const triangle3& t) {
    return box_triangle::box_meets<box_reach::closed>(k, b, t);
}

// The approximate tier of intersects(aabb3, triangle3) is Akenine-Moeller's test in double.
[[nodiscard]] constexpr bool intersects_approximate(const aabb3& b, const triangle3& t) { return aabb_triangle_sat(b, t); }

// aabb3 against tetrahedron3 (closed box; closed solid tetrahedron, coplanar vertices give their
// hull), contains(box, tetrahedron) and contains(tetrahedron, box).
// Semantics: touching at a vertex, along an edge or on a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const tetrahedron3& t) {
    if (!well_formed_finite(b) || !finite(t)) return false;
    const point3 v[4] = {t.a, t.b, t.c, t.d};
    // In a filter pass (arith::rounded_stage_applies) the 25 separating axes rounded with proven
    // error bounds first (box_triangle::rounded_hull_axes_decide); the signs where they are
    // not clear.
    if (arith::rounded_stage_applies<K>()) {
        constexpr int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
        constexpr int faces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
        if (const certainty r = box_triangle::rounded_hull_axes_decide(b, v, edges, faces); r != certainty::uncertain)
            return r == certainty::yes;
    }
    // The box's face normals first: coordinate comparisons, exact in every tier.
    auto at = [](const point3& p, int i) { return i == 0 ? p.x : (i == 1 ? p.y : p.z); };
    for (int i = 0; i < 3; ++i) {
        const double lo = at(b.min, i), hi = at(b.max, i);
        if (at(v[0], i) > hi && at(v[1], i) > hi && at(v[2], i) > hi && at(v[3], i) > hi) return false;
        if (at(v[0], i) < lo && at(v[1], i) < lo && at(v[2], i) < lo && at(v[3], i) < lo) return false;
    }
    for (const point3& p : v)
        if (b.min.x <= p.x && p.x <= b.max.x && b.min.y <= p.y && p.y <= b.max.y && b.min.z <= p.z && p.z <= b.max.z) return true;
    const box_corners c(b);
    return tetra::tetrahedron_meets(
        k, t, [&](const triangle3& face) { return box_triangle::box_meets<box_reach::closed, false>(k, b, face); }, c.p, 8, true);
}

// aabb3 against ray3: intersects, and intersection = the parameter interval [t_enter, t_exit]
// of the ray inside the box (t_enter >= 0).
// Semantics: closed box; a ray grazing a face, an edge or a corner hits; a ray lying in a face
// plane hits when it meets the face; a zero direction is the point `origin`.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const ray3& r) {
    return slabs<slab_extent::ray>(k, b, r.origin, r.direction, r.origin);
}
// The approximate tier of intersects(aabb3, ray3) is the classic slab method.
[[nodiscard]] constexpr bool intersects_approximate(const aabb3& b, const ray3& r) { return aabb_ray_slab(b, r).has_value(); }

// aabb3 against line3 (closed box, the whole line; a zero direction is the point `origin`).
// Semantics: touching a face, an edge or a corner counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const line3& l) {
    return slabs<slab_extent::line>(k, b, l.origin, l.direction, l.origin);
}
[[nodiscard]] constexpr bool intersects_approximate(const aabb3& b, const line3& l) { return aabb_line_slab(b, l); }

// aabb3 against segment3 (closed box, closed segment; a segment with equal end points is a point).
// Semantics: touching a face, an edge or a corner counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const segment3& s) {
    return slabs<slab_extent::segment>(k, b, s.a, vec3{0, 0, 0}, s.b);
}
[[nodiscard]] constexpr bool intersects_approximate(const aabb3& b, const segment3& s) { return aabb_segment_slab(b, s); }

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const aabb3&, const aabb3&);
extern template bool exactly<intersects_body>(const aabb3&, const point3&);
extern template bool exactly<intersects_body>(const aabb3&, const triangle3&);
extern template bool exactly<intersects_body>(const aabb3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const aabb3&, const ray3&);
extern template bool exactly<intersects_body>(const aabb3&, const line3&);
extern template bool exactly<intersects_body>(const aabb3&, const segment3&);
} // namespace incidence::detail
