// intersects: tetrahedron_pairs
export module incidence.detail:intersects.tetrahedron_pairs;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.linear;
import :engines.triangle;
import :engines.tetrahedron;
import :intersects.triangle_pairs;
import :intersects.linear_pairs;
import :exactly;

export namespace incidence::detail {

// point3 against tetrahedron3 (a closed solid tetrahedron; coplanar vertices give their hull),
// contains(tetrahedron, point | segment | triangle | tetrahedron), and the engine every
// tetrahedron pair shares.
// Semantics: a point on a face, an edge or a vertex counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const point3& p, const tetrahedron3& t) {
    const point3 pts[1] = {p};
    return tetra::contains_all(k, t, pts, 1);
}

// line3 against tetrahedron3 (a line through its origin, a point when the direction is zero;
// closed solid tetrahedron, coplanar vertices give their hull).
// Semantics: touching a face, an edge or a vertex counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const line3& l, const tetrahedron3& t) {
    if (!finite(l) || !finite(t)) return false;
    // In a filter pass, the rounded edge and face values first (tetra::rounded_line_meets).
    if (arith::rounded_stage_applies<K>())
        if (const certainty m = tetra::rounded_line_meets(t, l.origin, l.direction, false); m != certainty::uncertain)
            return m == certainty::yes;
    const point3 pts[1] = {l.origin};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, l, face); }, pts, 1, false);
}

// tetrahedron3 against triangle3 (closed solid tetrahedron, coplanar vertices give their hull;
// closed triangle, a collinear one is its hull).
// Semantics: touching at a vertex, along an edge or on a face counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const tetrahedron3& t, const triangle3& f) {
    if (!finite(t) || !finite(f)) return false;
    if (boxes_apart(k, f, t)) return false; // exact, and cheap on the commonest no
    const point3 pts[3] = {f.a, f.b, f.c};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, face, f); }, pts, 3, true);
}

// segment3 against tetrahedron3 (closed segment, a point when a == b; closed solid tetrahedron,
// coplanar vertices give their hull).
// Semantics: touching a face, an edge or a vertex counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const segment3& s, const tetrahedron3& t) {
    if (!finite(s) || !finite(t)) return false;
    if (boxes_apart(k, s, t)) return false; // exact, and cheap on the commonest no
    const point3 pts[2] = {s.a, s.b};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, s, face); }, pts, 2, true);
}

// ray3 against tetrahedron3 (a ray from its origin, a point when the direction is zero; closed
// solid tetrahedron, coplanar vertices give their hull).
// Semantics: touching a face, an edge or a vertex counts; an origin inside counts.

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const ray3& r, const tetrahedron3& t) {
    if (!finite(r) || !finite(t)) return false;
    if (boxes_apart(k, r, t)) return false; // exact, and cheap on the commonest no
    // In a filter pass, the rounded edge and face values first (tetra::rounded_line_meets).
    if (arith::rounded_stage_applies<K>())
        if (const certainty m = tetra::rounded_line_meets(t, r.origin, r.direction, true); m != certainty::uncertain)
            return m == certainty::yes;
    const point3 pts[1] = {r.origin};
    return tetra::tetrahedron_meets(k, t, [&](const triangle3& face) { return intersects(k, r, face); }, pts, 1, false);
}

// tetrahedron3 against tetrahedron3 (closed solids; coplanar vertices give their hull).
// Semantics: touching at a vertex, along an edge or on a face counts.

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
        if (const certainty d = tetra::rounded_verdict(in_s, 4); d != certainty::uncertain) return d == certainty::yes;
        const tetra::rounded_located in_t = tetra::rounded_locate(t, vs, 4);
        if (const certainty d = tetra::rounded_verdict(in_t, 4); d != certainty::uncertain) return d == certainty::yes;
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

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<intersects_body>(const point3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const line3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const tetrahedron3&, const triangle3&);
extern template bool exactly<intersects_body>(const segment3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const ray3&, const tetrahedron3&);
extern template bool exactly<intersects_body>(const tetrahedron3&, const tetrahedron3&);
} // namespace incidence::detail
