// tetrahedron3 against tetrahedron3 (closed solids; coplanar vertices give their hull).
// Semantics: touching at a vertex, along an edge or on a face counts.
// Method (exact tiers): bounding boxes apart reject (comparisons, exact; Ericson, Real-Time
// Collision Detection (2005), section 4.2.1). Then: each one's vertices against the other's face
// planes (orient3d signs, degree 3): a vertex inside the other solid says yes, all four strictly
// beyond one face plane say no. Otherwise neither lies inside the other, so they meet iff a face of
// one meets a face of the other (the 16 triangle_triangle tests). In a filter pass at run time the
// rounded stage of point_tetrahedron.cppm comes first (face planes, an edge clearly through a face,
// the edge axes; each value widened by a proven error bound).
// Source: the boundary-plus-inside decomposition of point_tetrahedron.cppm; Ganovelli, Ponchio
// and Rocchini, "Fast tetrahedron-tetrahedron overlap algorithm", JGT 7(2), 2002 use the same
// face-plane rejections first.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/tetrahedron_tetrahedron.cpp).
export module incidence.query:tetrahedron_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :segment_segment;
import :triangle_triangle;
import :point_tetrahedron;

export namespace incidence::pair {

// One canonical order (lexicographic on the twelve numbers), so every tier is symmetric.
[[nodiscard]] constexpr bool before(const tetrahedron3& s, const tetrahedron3& t) {
    const double x[12] = {s.a.x, s.a.y, s.a.z, s.b.x, s.b.y, s.b.z, s.c.x, s.c.y, s.c.z, s.d.x, s.d.y, s.d.z};
    const double y[12] = {t.a.x, t.a.y, t.a.z, t.b.x, t.b.y, t.b.z, t.c.x, t.c.y, t.c.z, t.d.x, t.d.y, t.d.z};
    return lex_compare(x, y, 12) <= 0;
}

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const tetrahedron3& s0, const tetrahedron3& t0) {
    if (!finite(s0) || !finite(t0)) return false;
    if (boxes_apart(k, s0, t0)) return false; // exact, and cheap on the commonest no
    const bool keep = before(s0, t0);
    const tetrahedron3 s = keep ? s0 : t0, t = keep ? t0 : s0;
    const point3 vs[4] = {s.a, s.b, s.c, s.d}, vt[4] = {t.a, t.b, t.c, t.d};
    if (arith::rounded_stage_applies<K>()) { // the rounded face planes of each, first
        // t's vertices against s's planes decide alone often enough that t's planes wait for them
        const tetra::rounded_located in_s = tetra::rounded_locate(s, vt, 4);
        if (const int d = tetra::rounded_verdict(in_s, 4); d >= 0) return d == 1;
        const tetra::rounded_located in_t = tetra::rounded_locate(t, vs, 4);
        if (const int d = tetra::rounded_verdict(in_t, 4); d >= 0) return d == 1;
        for (int p = 0; p < 4; ++p) // an edge of one clearly through a face of the other
            for (int q = p + 1; q < 4; ++q)
                if (tetra::rounded_crossing(in_s, p, q) || tetra::rounded_crossing(in_t, p, q)) return true;
        if (tetra::rounded_edge_axes_apart(vs, 4, vt, 4)) return false;
    }
    if (const sign o = tetra::orientation(k, s); o != sign::zero) {
        const auto l = tetra::locate(k, s, o, vt, 4, true);
        if (l != tetra::located::unknown) return l == tetra::located::inside;
    }
    if (const sign o = tetra::orientation(k, t); o != sign::zero) {
        const auto l = tetra::locate(k, t, o, vs, 4, true);
        if (l != tetra::located::unknown) return l == tetra::located::inside;
    }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (intersects(k, s.face(i), t.face(j))) return true;
    return false;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const tetrahedron3&, const tetrahedron3&);
} // namespace incidence::pair
