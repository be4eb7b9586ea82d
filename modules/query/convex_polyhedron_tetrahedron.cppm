// convex_polyhedron3 against tetrahedron3, contains(convex_polyhedron3, tetrahedron3), and the test
// of a tetrahedron against a half-space set that frustum_tetrahedron and kdop_tetrahedron share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the closed solid
// tetrahedron (coplanar vertices: their hull; a non-finite vertex: no tetrahedron). Touching at a
// vertex, an edge or a face counts. contains: the four vertices in the set (it is convex).
// Method (exact tiers): the tetrahedron T meets the set P iff one of its four faces meets P (the
// triangle test of convex_polyhedron_triangle.cppm, its six edges once, then each face's section)
// or P lies inside T. When no face meets P, the convex P does not cross T's boundary, so it lies
// inside T or outside it; inside, it is bounded and not empty, so it has a vertex (first_vertex
// of aabb_convex_polyhedron.cppm, v = V / D).
// That vertex decides: it is in T iff for every face (p, q, r) with the remaining vertex s,
// sign(det(q - p, r - p, V - p D)) is zero or sign(D) sign(det(q - p, r - p, s - p)) (degree 6).
// A flat tetrahedron is its faces. First, a plane of P with the four vertices beyond it says no.
// Source: the boundary-plus-inside decomposition (point_tetrahedron.cppm), with Schrijver, Theory
// of Linear and Integer Programming, 1986, section 8.5 (a nonempty pointed polyhedron has a
// vertex).
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-40 of its
// permanent (tests/query/convex_polyhedron_tetrahedron.cpp).
module;
#include <cstddef>
export module incidence.query:convex_polyhedron_tetrahedron;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :point_tetrahedron;
import :convex_polyhedron_point;
import :aabb_convex_polyhedron;
import :convex_polyhedron_triangle;

export namespace incidence::pair {

namespace polyq {

// Does the solid tetrahedron t meet the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i?
template <class K>
[[nodiscard]] constexpr bool tetrahedron_meets(K& k, const tetrahedron3& t, const plane3* planes, int m) {
    if (!well_formed(planes, m, convex_polyhedron3::capacity) || !finite(t)) return false;
    const point3 v[4] = {t.a, t.b, t.c, t.d};
    if (beyond_one_plane(k, planes, m, [&](std::size_t j) { return v[j]; }, 4)) return false;
    // the six edges, then each face's section (section_meets: its edges miss the set), unless the
    // face's corners lie beyond one plane
    for (int x = 0; x < 3; ++x)
        for (int y = x + 1; y < 4; ++y)
            if (halfspaces<slab_extent::segment>(k, planes, m, v[x], vec3{0, 0, 0}, v[y])) return true;
    for (int f = 0; f < 4; ++f) {
        const triangle3 face = t.face(f);
        const point3 corner[3] = {face.a, face.b, face.c};
        if (!beyond_one_plane(k, planes, m, [&](std::size_t j) { return corner[j]; }, 3) && section_meets(k, face, planes, m)) return true;
    }
    // face f is (p, q, r), the vertices other than v[f] in order; s = v[f]
    auto face_det = [=](int f, auto L, const auto& x) {
        const point3 p = v[f == 0 ? 1 : 0], q = v[f <= 1 ? 2 : 1], r = v[f <= 2 ? 3 : 2];
        const auto P = arith::lift(L, p);
        return arith::det3(arith::lift(L, q) - P, arith::lift(L, r) - P, x(P));
    };
    const sign o = k.sgn([=](auto L) { return face_det(3, L, [=](const auto& P) { return arith::lift(L, v[3]) - P; }); });
    if (o == sign::zero) return false; // flat: its faces
    const set_vertex c = first_vertex(k, planes, static_cast<unsigned>(m));
    if (!c.found) return false; // empty, or unbounded without a vertex: not inside T
    for (int f = 0; f < 4; ++f) {
        const point3 s = v[f];
        const sign side = f == 3 ? o : k.sgn([=](auto L) { return face_det(f, L, [=](const auto& P) { return arith::lift(L, s) - P; }); });
        const plane3 a = c.i, b = c.j, e = c.l;
        const sign w = k.sgn([=](auto L) {
            return face_det(f, L, [=](const auto& P) {
                const auto V = vertex_numerator(L, a, b, e);
                const auto D = arith::det3(arith::lift(L, a.normal), arith::lift(L, b.normal), arith::lift(L, e.normal));
                using T = decltype(V.x - P.x * D);
                return arith::v3<T>{V.x - P.x * D, V.y - P.y * D, V.z - P.z * D};
            });
        });
        if (w != sign::zero && w != (c.d == sign::positive ? side : -side)) return false;
    }
    return true;
}

} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const tetrahedron3& t) {
    return polyq::tetrahedron_meets(k, t, c.planes.data(), c.count);
}
// contains(convex_polyhedron3, tetrahedron3): the four vertices in the set (every vertex read, so a
// NaN vertex gives no in the exact tier).
template <class K>
[[nodiscard]] constexpr bool contains(K& k, const convex_polyhedron3& c, const tetrahedron3& t) {
    const bool a = intersects(k, c, t.a);
    const bool b = intersects(k, c, t.b);
    const bool e = intersects(k, c, t.c);
    const bool d = intersects(k, c, t.d);
    return a && b && e && d;
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const tetrahedron3&);
extern template bool contains(arith::exact_kernel&, const convex_polyhedron3&, const tetrahedron3&);
} // namespace incidence::pair
