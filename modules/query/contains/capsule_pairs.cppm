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
import :intersects.capsule_pairs;
import :contains.sphere_pairs;
import :exactly;

export namespace incidence::detail {

// contains(capsule3, point3 | segment3 | triangle3 | tetrahedron3 | aabb3): the capsule is
// convex, so it holds the hull of the vertices (a box's eight corners) iff each vertex lies within
// |r| of its segment (ball_flat.cppm's segment test, degree <= 4).
// Semantics: a vertex on the capsule's boundary counts; unchecked negative radii act as |r|; a NaN
// or infinite number, or an inverted box, holds or is held by nothing.

template <class K, std::size_t N>
[[nodiscard]] constexpr bool holds_all(K& k, const capsule3& c, const std::array<point3, N>& v) {
    if (!usable(c)) return false;
    for (const point3& p : v)
        if (!finite(p) || !ball_flat::meets(k, core(c), p, reach(c))) return false;
    return true;
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

// contains(aabb3 | obb3, capsule3): the capsule is the hull of its two end balls, so a
// convex set holds it iff it holds both (contains(X, sphere3), sphere_pairs.cppm).
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

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const capsule3&, const point3&);
extern template bool exactly<contains_body>(const capsule3&, const segment3&);
extern template bool exactly<contains_body>(const capsule3&, const triangle3&);
extern template bool exactly<contains_body>(const capsule3&, const tetrahedron3&);
extern template bool exactly<contains_body>(const capsule3&, const aabb3&);
extern template bool exactly<contains_body>(const aabb3&, const capsule3&);
extern template bool exactly<contains_body>(const obb3&, const capsule3&);
} // namespace incidence::detail
