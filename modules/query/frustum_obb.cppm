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
export module incidence.query:frustum_obb;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :separating_axes;
import :obb_tetrahedron;
import :convex_polyhedron_point;
import :aabb_frustum;
import :convex_polyhedron_obb;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const frustum3& f, const obb3& b) {
    return polyq::obb_meets(k, b, f.planes.data(), 6);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const obb3& b) {
    return polyq::obb_inside(k, b, f.planes.data(), 6);
}

// The separating-axis test in plain double (the catalog's first alternative); where a frustum
// corner does not exist, the box test above in double decides.
[[nodiscard]] constexpr bool frustum_obb_sat(const frustum3& f, const obb3& b) {
    if (!sat::well_formed(b) || !finite(b) || !polyq::well_formed(f.planes.data(), 6, 6)) return false;
    point3 corner[8];
    if (!frustum_corners(f, corner)) {
        arith::approx_kernel k;
        return polyq::obb_meets(k, b, f.planes.data(), 6);
    }
    const box_frame e{b.center, {b.axes[0], b.axes[1], b.axes[2]}, {b.half_extents[0], b.half_extents[1], b.half_extents[2]}};
    return box_frustum_sat(e, f, corner);
}
// The decomposition test in plain double (the catalog's second alternative): six tetrahedra
// against the box; where a corner does not exist, the box test above in double decides.
[[nodiscard]] constexpr bool frustum_obb_decomposition(const frustum3& f, const obb3& b) {
    if (!sat::well_formed(b) || !finite(b) || !polyq::well_formed(f.planes.data(), 6, 6)) return false;
    arith::approx_kernel k;
    point3 corner[8];
    if (!frustum_corners(f, corner)) return polyq::obb_meets(k, b, f.planes.data(), 6);
    return box_frustum_decomposition([&](const tetrahedron3& t) { return intersects(k, b, t); }, corner);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const frustum3&, const obb3&);
extern template bool contains(arith::exact_kernel&, const frustum3&, const obb3&);
} // namespace incidence::pair
