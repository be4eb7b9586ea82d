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
// Kept for comparison in the benchmarks (not a catalog alternative, since it errs far from the
// boundary too): aabb_frustum_culling, the culling test alone in double (no plane has the whole
// box beyond it: yes), which answers yes for boxes beside the frustum's edges and corners.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/aabb_frustum.cpp).
export module incidence.query:aabb_frustum;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :aabb_tetrahedron;
import :convex_polyhedron_point;
import :aabb_convex_polyhedron;
import :frustum_point;

export namespace incidence::pair {

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const aabb3& b, const frustum3& f) {
    return polyq::box_meets(k, b, f.planes.data(), 6);
}
// The culling test alone, in double: no plane has the box's least corner along its normal outside.
// Source: Assarsson and Moeller, JGT 5(1), 2000, section 3 (the n-vertex of a box).
[[nodiscard]] constexpr bool aabb_frustum_culling(const aabb3& b, const frustum3& f) {
    if (!well_formed_finite(b) || !polyq::well_formed(f.planes.data(), 6, 6)) return false;
    for (const plane3& p : f.planes) {
        const point3 q = least_corner(b, p.normal);
        if (p.normal.x * q.x + p.normal.y * q.y + p.normal.z * q.z > p.offset) return false;
    }
    return true;
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const aabb3& b) {
    if (!well_formed_finite(b)) return false;
    const box_corners q(b);
    bool all = true;
    for (const point3& p : q.p) all = intersects(k, f, p) && all;
    return all;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const aabb3&, const frustum3&);
extern template bool contains(arith::exact_kernel&, const frustum3&, const aabb3&);
} // namespace incidence::pair
