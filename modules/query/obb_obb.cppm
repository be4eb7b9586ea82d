// obb3 against obb3 (closed boxes; the axes are read exactly as given, so a box is the
// parallelepiped they span, and a box of zero extent is a rectangle, a segment or a point).
// Semantics: touching at a corner, along an edge or on a face counts.
// Method (exact tiers): the 15 separating axes (the face normals of each parallelepiped, a_j x a_k,
// which are its axes when they are orthonormal, and the nine cross products a_i x b_j). Each axis
// is one sign of degree 4: |w . (2 c_b - 2 c_a)| against twice the sum of the projected radii
// h_i |w . a_i| (see separating_axes for the flat cases). Before them the three coordinate axes,
// a cheap certificate for boxes whose bounding boxes are apart; and each of the 15 signs is first
// compared with a bound from the inputs' largest magnitudes (sat::box_box_static_bounds), the
// filter's own permanents only where that bound is too coarse.
// contains(obb3, obb3): the support functions compared on the same axes (sat::zonotope_contains).
// Source: Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5 (15 axes).
// Approximate tier: the same signs (coordinate axes included) in plain double. Error bound: for
// inputs whose nonzero magnitudes lie in [2^-500, 2^500], wrong only when some axis sign is within
// 2^-40 of its permanent (the sets touch or nearly touch); tests/query/obb_obb.cpp checks it.
export module incidence.query:obb_obb;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :separating_axes;

export namespace incidence::pair {

// The boxes in a fixed order (lexicographic on their numbers), so that the plain-double tier
// also answers the same for (a, b) and (b, a).
[[nodiscard]] constexpr bool obb_before(const obb3& a, const obb3& b) {
    const double x[15] = {a.center.x, a.center.y, a.center.z, a.axes[0].x, a.axes[0].y, a.axes[0].z, a.axes[1].x, a.axes[1].y,
                          a.axes[1].z, a.axes[2].x, a.axes[2].y, a.axes[2].z, a.half_extents[0], a.half_extents[1], a.half_extents[2]};
    const double y[15] = {b.center.x, b.center.y, b.center.z, b.axes[0].x, b.axes[0].y, b.axes[0].z, b.axes[1].x, b.axes[1].y,
                          b.axes[1].z, b.axes[2].x, b.axes[2].y, b.axes[2].z, b.half_extents[0], b.half_extents[1], b.half_extents[2]};
    for (int i = 0; i < 15; ++i)
        if (x[i] != y[i]) return x[i] < y[i];
    return true;
}

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const obb3& a, const obb3& b) {
    if (!sat::well_formed(a) || !sat::well_formed(b)) return false;
    const bool before = obb_before(a, b);
    const obb3& p = before ? a : b;
    const obb3& q = before ? b : a;
    if (const int f = sat::box_box_fast(k, p, q); f >= 0) return f == 1; // the boxes read in place
    return sat::zonotopes_intersect_general(k, sat::of(p), sat::of(q));
}
// Is b inside a? Malformed boxes (NaN or negative extents) contain nothing and lie in nothing.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& a, const obb3& b) {
    return sat::well_formed(a) && sat::well_formed(b) && sat::zonotope_contains(k, sat::of(a), sat::of(b));
}

// The classic test in plain double (an alternative, compared in the audit): the rotation
// R = A^T B and the centre offset in A's frame, 15 axes with A's and B's axes as face normals
// (so it assumes orthonormal axes), and a small constant added to |R| so that nearly parallel
// edge pairs do not produce a null cross-product axis.
// Source: Gottschalk, Lin and Manocha, "OBBTree", SIGGRAPH 1996, section 5; Ericson, Real-Time
// Collision Detection (2005), section 4.4.1 (the epsilon on |R|, here 1e-6 as in FCL's obbDisjoint).
[[nodiscard]] constexpr bool obb_obb_gottschalk(const obb3& a, const obb3& b) {
    if (!sat::well_formed(a) || !sat::well_formed(b)) return false;
    double R[3][3], F[3][3];
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) {
            R[i][j] = dot(a.axes[i], b.axes[j]);
            F[i][j] = (R[i][j] < 0 ? -R[i][j] : R[i][j]) + 1e-6;
        }
    const vec3 d = b.center - a.center;
    const double t[3] = {dot(d, a.axes[0]), dot(d, a.axes[1]), dot(d, a.axes[2])};
    const auto& ha = a.half_extents;
    const auto& hb = b.half_extents;
    for (unsigned i = 0; i < 3; ++i)
        if (arith::abs(t[i]) > ha[i] + hb[0] * F[i][0] + hb[1] * F[i][1] + hb[2] * F[i][2]) return false;
    for (unsigned j = 0; j < 3; ++j)
        if (arith::abs(t[0] * R[0][j] + t[1] * R[1][j] + t[2] * R[2][j]) > ha[0] * F[0][j] + ha[1] * F[1][j] + ha[2] * F[2][j] + hb[j])
            return false;
    for (unsigned i = 0; i < 3; ++i) {
        const unsigned i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (unsigned j = 0; j < 3; ++j) {
            const unsigned j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const double ra = ha[i1] * F[i2][j] + ha[i2] * F[i1][j];
            const double rb = hb[j1] * F[i][j2] + hb[j2] * F[i][j1];
            if (arith::abs(t[i2] * R[i1][j] - t[i1] * R[i2][j]) > ra + rb) return false;
        }
    }
    return true;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const obb3&, const obb3&);
extern template bool contains(arith::exact_kernel&, const obb3&, const obb3&);
} // namespace incidence::pair
