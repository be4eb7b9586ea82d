// contains: capsule_pairs
module;
#include <array>
export module incidence.detail:contains.capsule_pairs;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :engines.linear;
import :engines.sphere;
import :engines.ball_flat;
import :engines.separating_axes;
import :engines.tetrahedron;
import :engines.capsule_obb;
import :intersects.capsule_pairs;
import :contains.sphere_pairs;
import :exactly;

export namespace incidence::detail {

// contains(capsule3, point3 | segment3 | triangle3 | tetrahedron3 | aabb3): the capsule is
// convex, so it holds the hull of the vertices (a box's eight corners) iff each vertex lies within
// |r| of its segment (ball_flat.cppm's segment test, degree <= 4; holds_vertices, sphere_pairs.cppm).
// Semantics: a vertex on the capsule's boundary counts; unchecked negative radii act as |r|; a NaN
// or infinite number, or an inverted box, holds or is held by nothing.

template <class K, std::size_t N>
[[nodiscard]] constexpr bool holds_all(K& k, const capsule3& c, const std::array<point3, N>& v) {
    return usable(c) && holds_vertices(v, [&](point3 p) { return ball_flat::meets(k, core(c), p, reach(c)); });
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const capsule3& c, const point3& p) {
    return holds_all(k, c, std::array{p});
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const capsule3& c, const segment3& g) {
    return holds_all(k, c, std::array{g.a, g.b});
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const capsule3& c, const triangle3& t) {
    return holds_all(k, c, std::array{t.a, t.b, t.c});
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const capsule3& c, const tetrahedron3& t) {
    return holds_all(k, c, std::array{t.a, t.b, t.c, t.d});
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const capsule3& c, const aabb3& b) {
    if (!ball::usable(b)) return false;
    const point3 lo = b.min, hi = b.max;
    return holds_all(k, c,
                     std::array{lo, point3{hi.x, lo.y, lo.z}, point3{lo.x, hi.y, lo.z}, point3{hi.x, hi.y, lo.z}, point3{lo.x, lo.y, hi.z},
                                point3{hi.x, lo.y, hi.z}, point3{lo.x, hi.y, hi.z}, hi});
}

// contains(capsule3, obb3): the box's eight corners o + sum +-h_j a_j, exact rationals of degree 2,
// each within |r| of the segment (capsule_obb.cppm's corner test, degree <= 6). Semantics: the
// closed box read as the parallelepiped its axes span; NaN, infinite or negative extents hold
// nothing and are held by nothing.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const capsule3& c, const obb3& b) {
    if (!usable(c) || !sat::well_formed(b) || !finite(b)) return false;
    const double r = reach(c);
    for (int m = 0; m < 8; ++m) {
        double f[3]; // the corner's signed extents
        for (unsigned j = 0; j < 3; ++j) f[j] = (m >> j & 1) ? b.half_extents[j] : -b.half_extents[j];
        if (!swept_obb::corner_within(k, b, f, c.a, c.b, r)) return false;
    }
    return true;
}

// contains(capsule3, sphere3): the ball lies within |r_c| of the segment iff |r_s| <= |r_c| and its
// centre lies within |r_c| - |r_s| of the segment (ball_flat.cppm's segment test with the
// difference of the radii formed exactly inside the signs, degree <= 4).
// Semantics: a ball touching the capsule from inside lies in it; unchecked negative radii act as
// |r|; a NaN or infinite number holds or is held by nothing.

template <class K>
[[nodiscard]] constexpr bool contains(K& k, const capsule3& c, const sphere3& s) {
    if (!usable(c) || !ball::usable(s)) return false;
    const double rc = reach(c), rs = ball::magnitude(s.radius);
    return rs <= rc && ball_flat::meets(k, core(c), s.center, ball_flat::radii{rc, -rs});
}

// contains(aabb3 | obb3 | sphere3 | capsule3 | convex_polyhedron3 | frustum3 | kdop<K>, capsule3):
// the capsule is the hull of its two end balls, so a convex set holds it iff it holds both
// (contains(X, sphere3): sphere_pairs.cppm, and the capsule's own above).
// Semantics: a capsule touching the set from inside lies in it; as contains(X, sphere3) otherwise.

template <class K, class X>
[[nodiscard]] constexpr bool holds_ends(K& k, const X& x, const capsule3& c) {
    if (!usable(c)) return false;
    const double r = reach(c);
    return contains(k, x, sphere3{c.a, r}) && contains(k, x, sphere3{c.b, r});
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const aabb3& b, const capsule3& c) {
    return holds_ends(k, b, c);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const obb3& b, const capsule3& c) {
    return holds_ends(k, b, c);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const sphere3& s, const capsule3& c) {
    return holds_ends(k, s, c); // contains(sphere3, sphere3) reads both radii as |r|
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const capsule3& a, const capsule3& b) {
    return holds_ends(k, a, b);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& p, const capsule3& c) {
    return holds_ends(k, p, c);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const frustum3& f, const capsule3& c) {
    return holds_ends(k, f, c);
}
template <class K, int N>
[[nodiscard]] constexpr bool contains(K& k, const kdop<N>& b, const capsule3& c) {
    return holds_ends(k, b, c);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const capsule3&, const point3&);
extern template bool exactly<contains_body>(const capsule3&, const segment3&);
extern template bool exactly<contains_body>(const capsule3&, const triangle3&);
extern template bool exactly<contains_body>(const capsule3&, const tetrahedron3&);
extern template bool exactly<contains_body>(const capsule3&, const aabb3&);
extern template bool exactly<contains_body>(const capsule3&, const obb3&);
extern template bool exactly<contains_body>(const aabb3&, const capsule3&);
extern template bool exactly<contains_body>(const obb3&, const capsule3&);
extern template bool exactly<contains_body>(const capsule3&, const sphere3&);
extern template bool exactly<contains_body>(const sphere3&, const capsule3&);
extern template bool exactly<contains_body>(const capsule3&, const capsule3&);
extern template bool exactly<contains_body>(const convex_polyhedron3&, const capsule3&);
extern template bool exactly<contains_body>(const frustum3&, const capsule3&);
extern template bool exactly<contains_body>(const kdop<6>&, const capsule3&);
extern template bool exactly<contains_body>(const kdop<14>&, const capsule3&);
extern template bool exactly<contains_body>(const kdop<18>&, const capsule3&);
extern template bool exactly<contains_body>(const kdop<26>&, const capsule3&);
} // namespace incidence::detail
