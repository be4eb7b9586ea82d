// convex_polyhedron3 against mesh3, and the test of a mesh against a half-space set that
// frustum_mesh and kdop_mesh share.
// Semantics: the closed half-space set of convex_polyhedron_point.cppm (possibly empty or
// unbounded; a non-finite number or a count outside [0, capacity]: no set) and the mesh's point
// set (shapes/mesh3.cppm: its triangles and the points of odd crossing parity); touching a
// triangle counts.
// Method (exact tiers): a plane of the set with every mesh vertex beyond it says no; a mesh
// triangle meeting the set (the triangle test of convex_polyhedron_triangle.cppm) says yes; else
// the convex set lies wholly off the surface, inside the mesh or outside it, and one of its points
// decides by the crossing parity of mesh_point.cppm: a vertex of the set (first_vertex of
// aabb_convex_polyhedron.cppm), the rational point V / D, whose parity signs times D are
// u . (D (x x y) + (y - x) x V) (degree 5) and n . (D a - V) (degree 6) for a triangle a b c of
// normal n (all of them flip with D's sign, which leaves their agreements as they are). A nonempty
// set without a vertex is unbounded, so it is not inside.
// Source: the boundary-plus-inside decomposition and crossing parity of mesh_point.cppm (Haines,
// Graphics Gems IV, 1994); Schrijver, Theory of Linear and Integer Programming, 1986, section 8.5.
// Approximate tier: the same signs in plain double. Error bound: for inputs whose nonzero
// magnitudes lie in [2^-500, 2^500], wrong only when a deciding sign is within 2^-36 of its
// permanent (tests/query/convex_polyhedron_mesh.cpp).
module;
#include <cstddef>
#include <utility>
export module incidence.query:convex_polyhedron_mesh;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import :mesh_point;
import :convex_polyhedron_point;
import :aabb_convex_polyhedron;
import :convex_polyhedron_triangle;

export namespace incidence::pair {

namespace polyq {

// The vertex of a half-space set where planes a, c and e meet, V / D, as meshq::inside_at reads a
// point (meshq::at_weighted: each parity sign times D).
struct set_vertex_point {
    plane3 a, c, e;
    template <class L>
    [[nodiscard]] constexpr auto weighted(L lift) const {
        return std::pair{vertex_numerator(lift, a, c, e), arith::det3(arith::lift(lift, a.normal), arith::lift(lift, c.normal), arith::lift(lift, e.normal))};
    }
    [[nodiscard]] constexpr bool near(const aabb3&) const { return true; }
    [[nodiscard]] constexpr bool x_ray_misses(const aabb3&) const { return false; }
};

// Does the mesh m meet the m <= convex_polyhedron3::capacity half-spaces n_i . x <= c_i?
template <class K>
[[nodiscard]] constexpr bool mesh_meets(K& k, const mesh3& m, const plane3* planes, int count) {
    if (!well_formed(planes, count, convex_polyhedron3::capacity) || !meshq::well_formed(m) || m.triangles.empty()) return false;
    if (beyond_one_plane(k, planes, count, [&](std::size_t j) { return m.vertices[j]; }, m.vertices.size())) return false;
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
        if (triangle_meets(k, m.triangle(i), planes, count)) return true;
    const set_vertex v = first_vertex(k, planes, static_cast<unsigned>(count));
    if (!v.found) return false;
    return meshq::inside_at(k, m, meshq::at_weighted<set_vertex_point>{{v.i, v.j, v.l}});
}

} // namespace polyq

template <class K>
[[nodiscard]] constexpr bool intersects(K& k, const convex_polyhedron3& c, const mesh3& m) {
    return polyq::mesh_meets(k, m, c.planes.data(), c.count);
}

} // namespace incidence::pair

// The exact tier's fallback, compiled once in the library (see query.cppm): an importer calls it.
namespace incidence::pair {
extern template bool intersects(arith::exact_kernel&, const convex_polyhedron3&, const mesh3&);
} // namespace incidence::pair
