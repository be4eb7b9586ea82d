// contains: tetrahedron_pairs
export module incidence.detail:contains.tetrahedron_pairs;
import incidence.core;
import incidence.arith;
import incidence.predicates;
import incidence.shapes;
import :engines.tetrahedron;
import :intersects.tetrahedron_pairs;
import :exactly;

export namespace incidence::detail {

// point3 against tetrahedron3 (a closed solid tetrahedron; coplanar vertices give their hull),
// contains(tetrahedron, point | segment | triangle | tetrahedron), and the engine every
// tetrahedron pair shares.
// Semantics: a point on a face, an edge or a vertex counts.

// contains(tetrahedron, x): every vertex of x in the closed tetrahedron (convexity), so the
// same orient3d signs; a coplanar tetrahedron contains what lies in its hull.
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const point3& p) {
    const point3 pts[1] = {p};
    return tetra::contains_all(k, t, pts, 1);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const segment3& s) {
    const point3 pts[2] = {s.a, s.b};
    return tetra::contains_all(k, t, pts, 2);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const triangle3& f) {
    const point3 pts[3] = {f.a, f.b, f.c};
    return tetra::contains_all(k, t, pts, 3);
}
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const tetrahedron3& t, const tetrahedron3& u) {
    const point3 pts[4] = {u.a, u.b, u.c, u.d};
    return tetra::contains_all(k, t, pts, 4);
}

} // namespace incidence::detail

// The exact tier's fallback, compiled once in the library (CMakeLists.txt generates the definitions).
namespace incidence::detail {
extern template bool exactly<contains_body>(const tetrahedron3&, const point3&);
extern template bool exactly<contains_body>(const tetrahedron3&, const segment3&);
extern template bool exactly<contains_body>(const tetrahedron3&, const triangle3&);
extern template bool exactly<contains_body>(const tetrahedron3&, const tetrahedron3&);
} // namespace incidence::detail
