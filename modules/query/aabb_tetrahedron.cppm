// aabb3 against tetrahedron3 (closed box; closed solid tetrahedron, coplanar vertices give their
// hull), contains(box, tetrahedron) and contains(tetrahedron, box).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Method (exact tiers): the box's three face normals first (all four vertices beyond one box
// face: no; a vertex in the box: yes; coordinate comparisons), then a box corner inside the
// solid says yes, all eight strictly beyond one face plane say no (orient3d signs, degree 3);
// otherwise the box meets the tetrahedron iff it meets
// one of its four faces (the 13-axis aabb_triangle test), since it cannot then lie inside.
// contains: every vertex of the inner shape inside the outer one (coordinate comparisons for the
// box, orient3d signs for the tetrahedron).
// At run time the filter pass first tries the 25 separating axes (3 box normals, 4 face normals,
// 6 edges x 3 box axes) rounded, each widened by a proven error bound
// (box_triangle_detail::rounded_hull_axes_decide); the signs above decide what that leaves.
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Akenine-Moeller,
// "Fast 3D triangle-box overlap testing", JGT 6(1), 2001 for the face tests; Gottschalk, Lin and
// Manocha, "OBBTree", SIGGRAPH 1996, section 5 (the separating axis theorem).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/aabb_tetrahedron.cpp).
export module incidence.query:aabb_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :aabb_point;
import :aabb_triangle;
import :point_tetrahedron;

export namespace incidence::pair {

// A box is a set when its bounds are ordered finite numbers (an inverted box is empty).
[[nodiscard]] constexpr bool well_formed_finite(const aabb3& b) {
    return b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z && finite(b.min) && finite(b.max);
}
struct box_corners {
    point3 p[8];
    constexpr explicit box_corners(const aabb3& b) : p{} {
        for (int i = 0; i < 8; ++i) p[i] = point3{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
    }
};
// The box corner least along n (where a component of n is zero, either bound would do).
[[nodiscard]] constexpr point3 least_corner(const aabb3& b, const vec3& n) {
    return {n.x > 0 ? b.min.x : b.max.x, n.y > 0 ? b.min.y : b.max.y, n.z > 0 ? b.min.z : b.max.z};
}

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const tetrahedron3& t) {
    if (!well_formed_finite(b) || !finite(t)) return false;
    const point3 v[4] = {t.a, t.b, t.c, t.d};
    // In a filter pass (arith::rounded_stage_applies) the 25 separating axes rounded with proven
    // error bounds first (box_triangle_detail::rounded_hull_axes_decide); the signs where they are
    // not clear.
    if (arith::rounded_stage_applies<K>()) {
        constexpr int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
        constexpr int faces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
        if (const int r = box_triangle_detail::rounded_hull_axes_decide(b, v, edges, faces); r >= 0) return r == 1;
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
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return box_triangle_detail::box_meets<box_reach::closed, false>(k, b, face); }, c.p, 8, true);
}

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& b, const tetrahedron3& t) {
    if (!well_formed_finite(b) || !finite(t)) return false;
    return contains(k, b, t.a) && contains(k, b, t.b) && contains(k, b, t.c) && contains(k, b, t.d);
}

// contains(tetrahedron, box): the eight corners in the closed tetrahedron.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const aabb3& b) {
    if (!well_formed_finite(b)) return false;
    const box_corners c(b);
    return tetra::contains_all(k, t, c.p, 8);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const aabb3&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const tetrahedron3&, const aabb3&);
} // namespace incidence::pair
