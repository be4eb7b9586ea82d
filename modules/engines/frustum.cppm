// aabb3 against frustum3, and contains(frustum3, aabb3).
// Semantics: the closed box (bounds ordered and finite; an inverted box is empty) and the closed
// view volume of the frustum's six half-spaces (shapes/frustum3.cppm; a non-finite number: no
// set). Touching at a face, an edge or a corner counts. contains: the eight corners in the frustum.
// Method (exact tiers): the vertex test of aabb_convex_polyhedron.cppm on the frustum's six planes
// and the box's six faces (a frustum plane with the whole box beyond it first: the culling test's
// no, exact; then the triples of the twelve planes): homogeneous signs of degree 4.
// Source: vertex enumeration for LP feasibility (Schrijver, Theory of Linear and Integer
// Programming, 1986, section 8.5); the plane-box rejection of frustum culling (Assarsson and
// Moeller, "Optimized view frustum culling algorithms for bounding boxes", JGT 5(1), 2000).
// The catalog's alternatives: aabb_frustum_sat, the separating-axis test in double, and
// aabb_frustum_decomposition, the frustum as six tetrahedra in double (below). Kept for
// comparison in the benchmarks (not a catalog alternative, since it errs far from the boundary
// too): aabb_frustum_culling, the culling test alone in double (no plane has the whole
// box beyond it: yes), which answers yes for boxes beside the frustum's edges and corners.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/aabb_frustum.cpp).
//
// frustum3 against obb3, and contains(frustum3, obb3).
// Semantics: the closed view volume of six half-spaces (shapes/frustum3.cppm; a non-finite number:
// no set) and the closed box read as the parallelepiped its axes span. Touching at a face, an edge
// or a corner counts. contains: the whole box in the frustum.
// Method (exact tiers): the test of a box against a half-space set (convex_polyhedron_obb.cppm):
// a plane with the whole box beyond it says no, the centre inside every plane says yes, else the
// vertex search on the frustum's planes and the box's faces in the box's own coordinates:
// homogeneous signs of degree <= 9.
// Source: Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5; the plane-box
// rejection of frustum culling (Assarsson and Moeller, JGT 5(1), 2000).
// The catalog's alternatives, in plain double: frustum_obb_sat, the separating-axis test
// (aabb_frustum.cppm's box_frustum_sat with the box's own axes), and frustum_obb_decomposition,
// the frustum as six tetrahedra each against the box by obb_tetrahedron's approximate tier.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/frustum_obb.cpp).
export module incidence.detail:engines.frustum;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.separating_axes;
import :engines.tetrahedron;
import :engines.box;
import :engines.halfspace_slabs;
import :engines.halfspace_lp;
import :engines.halfspace_meets;

export namespace incidence::detail {
// The culling test alone, in double: no plane has the box's least corner along its normal outside.
// Source: Assarsson and Moeller, JGT 5(1), 2000, section 3 (the n-vertex of a box).
[[nodiscard]] constexpr bool aabb_frustum_culling(const aabb3& b, const frustum3& f) {
    if (!well_formed_finite(b) || !halfspaces::well_formed(f.planes.data(), 6, 6)) return false;
    for (const plane3& p : f.planes) {
        const point3 q = least_corner(b, p.normal);
        if (p.normal.x * q.x + p.normal.y * q.y + p.normal.z * q.z > p.offset) return false;
    }
    return true;
}
// The frustum's eight corners in double, where three planes meet (near or far, left or right,
// bottom or top: corner m takes planes m & 1, 2 + bit 1 and 4 + bit 2): false where one does not
// exist (parallel planes) or is not finite.
[[nodiscard]] constexpr bool frustum_corners(const frustum3& f, point3 (&corner)[8]) {
    const plane3* pl = f.planes.data();
    for (unsigned m = 0; m < 8; ++m) {
        const plane3 p = pl[m & 1u], q = pl[2 + ((m >> 1) & 1u)], r = pl[4 + ((m >> 2) & 1u)];
        const vec3 qr = cross(q.normal, r.normal), rp = cross(r.normal, p.normal), pq = cross(p.normal, q.normal);
        const double d = dot(p.normal, qr);
        const vec3 v = (qr * p.offset + rp * q.offset + pq * r.offset) * (1.0 / d);
        if (!(d != 0) || !finite(v)) return false;
        corner[m] = point3{v.x, v.y, v.z};
    }
    return true;
}
// The separating-axis test in plain double of a box (centre c, axes a_j, half extents h_j: the
// parallelepiped they span; an axis-aligned box has the unit axes) against a frustum: the box's
// three face normals (a_j x a_k, its axes when they are orthonormal), the frustum's six face
// normals and the cross products of the box axes with the frustum's twelve edge directions
// (n_i x n_j for the near and far faces with each side, and the four side edges), the frustum
// projected through its eight corners (plane triples: near or far, left or right, bottom or top),
// so the six planes must bound a frustum of a camera's shape. The box projects onto w as
// w . c +- sum_j h_j |w . a_j|. False when a corner does not exist (the caller decides then).
// Source: Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5 (the axes of two convex
// polyhedra); Ericson, Real-Time Collision Detection, 2005, section 5.2.1 (box projection radius).
struct box_frame {
    point3 c;
    vec3 a[3];
    double h[3];
};
[[nodiscard]] constexpr bool box_frustum_sat(const box_frame& b, const frustum3& f, const point3 (&corner)[8]) {
    const plane3* pl = f.planes.data();
    auto separates = [&](vec3 w) {
        double lo = __builtin_huge_val(), hi = -__builtin_huge_val();
        for (const point3& x : corner) {
            const double t = dot(w, x - b.c);
            lo = t < lo ? t : lo, hi = t > hi ? t : hi;
        }
        const double r = b.h[0] * arith::abs(dot(w, b.a[0])) + b.h[1] * arith::abs(dot(w, b.a[1])) + b.h[2] * arith::abs(dot(w, b.a[2]));
        return lo > r || hi < -r;
    };
    for (unsigned j = 0; j < 3; ++j)
        if (separates(cross(b.a[(j + 1) % 3], b.a[(j + 2) % 3]))) return false;
    for (const plane3& p : f.planes)
        if (separates(p.normal)) return false;
    constexpr unsigned edge[12][2] = {{0, 2}, {0, 3}, {0, 4}, {0, 5}, {1, 2}, {1, 3}, {1, 4}, {1, 5}, {2, 4}, {2, 5}, {3, 4}, {3, 5}};
    for (const auto& e : edge) {
        const vec3 d = cross(pl[e[0]].normal, pl[e[1]].normal);
        for (const vec3& a : b.a)
            if (separates(cross(a, d))) return false;
    }
    return true;
}
// The catalog's first alternative: box_frustum_sat on the box's centre and extents; where a
// frustum corner does not exist, the vertex test in double decides.
[[nodiscard]] constexpr bool aabb_frustum_sat(const aabb3& b, const frustum3& f) {
    if (!well_formed_finite(b) || !halfspaces::well_formed(f.planes.data(), 6, 6)) return false;
    point3 corner[8];
    if (!frustum_corners(f, corner)) {
        arith::approx_kernel k;
        return halfspaces::box_meets(k, b, f.planes.data(), 6);
    }
    const box_frame e{{0.5 * b.min.x + 0.5 * b.max.x, 0.5 * b.min.y + 0.5 * b.max.y, 0.5 * b.min.z + 0.5 * b.max.z},
                      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                      {0.5 * b.max.x - 0.5 * b.min.x, 0.5 * b.max.y - 0.5 * b.min.y, 0.5 * b.max.z - 0.5 * b.min.z}};
    return box_frustum_sat(e, f, corner);
}
// The decomposition test in plain double: the frustum's eight corners split into six tetrahedra
// around the diagonal from corner 0 to corner 7, each against the box by `meets` (the
// box-tetrahedron pair's approximate tier: aabb_tetrahedron, obb_tetrahedron).
// Source: Dompierre, Labbe, Vallet and Camarero, "How to subdivide pyramids, prisms and hexahedra
// into tetrahedra", 8th International Meshing Roundtable, 1999 (six tetrahedra around a diagonal).
template <class Meets>
[[nodiscard]] constexpr bool box_frustum_decomposition(const Meets& meets, const point3 (&corner)[8]) {
    // corner m: bit 0 near or far, bit 1 left or right, bit 2 bottom or top; the tetrahedra
    // 0, 1 << i, 1 << i | 1 << j, 7 for the six orders (i, j) of two of the three bits
    constexpr unsigned order[6][2] = {{0, 1}, {0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}};
    for (const auto& o : order) {
        const unsigned one = 1u << o[0], two = one | (1u << o[1]);
        if (meets(tetrahedron3{corner[0], corner[one], corner[two], corner[7]})) return true;
    }
    return false;
}

// The separating-axis test in plain double (the catalog's first alternative); where a frustum
// corner does not exist, the box test above in double decides.
[[nodiscard]] constexpr bool frustum_obb_sat(const frustum3& f, const obb3& b) {
    if (!sat::well_formed(b) || !finite(b) || !halfspaces::well_formed(f.planes.data(), 6, 6)) return false;
    point3 corner[8];
    if (!frustum_corners(f, corner)) {
        arith::approx_kernel k;
        return halfspaces::obb_meets(k, b, f.planes.data(), 6);
    }
    const box_frame e{b.center, {b.axes[0], b.axes[1], b.axes[2]}, {b.half_extents[0], b.half_extents[1], b.half_extents[2]}};
    return box_frustum_sat(e, f, corner);
}

} // namespace incidence::detail
