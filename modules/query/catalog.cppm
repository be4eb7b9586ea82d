// incidence.catalog: the list of query families the library has, read by tools that must cover
// every family (the audit, the README table): a new pair is added here once, next to its file.
// Each family names its canonical argument types, its file in modules/query/, and the textbook
// algorithms kept beside the four tiers for comparison. `signs_in_double` evaluates a family's
// exact-tier sign algorithm in plain double (what the tiers cost without the filter).
module;
#include <array>
#include <cstddef>
#include <tuple>
export module incidence.catalog;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.query;
import incidence.detail;

export namespace incidence::catalog {

template <class A, class B>
struct alternative {
    const char* name;   // short identifier, e.g. "moller_trumbore"
    const char* source; // paper or book
    bool (*test)(const A&, const B&);
};

template <class A, class B, std::size_t N>
struct family {
    using first_type = A;
    using second_type = B;
    const char* name; // modules/query/<name>.cppm, tests/query/<name>.cpp
    const char* fuzzer; // fuzz/<fuzzer>.cpp runs it against the oracle
    const char* approximate_method; // what the approximate tier runs
    std::array<alternative<A, B>, N> alternatives;
};

template <class A, class B>
[[nodiscard]] constexpr bool signs_in_double(const A& a, const B& b) {
    arith::approx_kernel k;
    return detail::intersects(k, a, b);
}

inline constexpr std::tuple families{
    family<point3, sphere3, 0>{"point_sphere", "spheres_boxes", "signs in double", {}},
    family<sphere3, sphere3, 0>{"sphere_sphere", "spheres_boxes", "signs in double", {}},
    family<aabb3, point3, 0>{"aabb_point", "spheres_boxes", "signs in double", {}},
    family<aabb3, aabb3, 0>{"aabb_aabb", "spheres_boxes", "signs in double", {}},
    family<ray3, sphere3, 2>{
        "ray_sphere", "spheres_boxes",
        "geometric (Akenine-Moeller et al., Real-Time Rendering)",
        {{{"geometric", "Akenine-Moeller et al., Real-Time Rendering, optimized geometric method",
           [](const ray3& r, const sphere3& s) { return method::ray_sphere_geometric(r, s).has_value(); }},
          {"algebraic", "quadratic formula on |o + t d - c|^2 = r^2",
           [](const ray3& r, const sphere3& s) { return method::ray_sphere_algebraic(r, s).has_value(); }}}}},
    family<aabb3, ray3, 2>{"aabb_ray", "spheres_boxes",
                           "slab method (Kay and Kajiya 1986)",
                           {{{"slab", "Kay and Kajiya, SIGGRAPH 1986; Williams et al., JGT 10(1) 2005",
                              [](const aabb3& b, const ray3& r) { return method::aabb_ray_slab(b, r).has_value(); }},
                             {"woo", "Woo, Graphics Gems (1990), Fast ray-box intersection",
                              [](const aabb3& b, const ray3& r) { return method::aabb_ray_woo(b, r); }}}}},
    family<ray3, triangle3, 2>{
        "ray_triangle", "ray_triangle",
        "watertight (Woop, Benthin and Wald 2013)",
        {{{"watertight", "Woop, Benthin and Wald, JCGT 2(1), 2013",
           [](const ray3& r, const triangle3& t) { return method::ray_triangle_watertight(r, t).has_value(); }},
          {"moller_trumbore", "Moeller and Trumbore, JGT 2(1), 1997",
           [](const ray3& r, const triangle3& t) { return method::ray_triangle_moller_trumbore(r, t).has_value(); }}}}},
    family<segment3, triangle3, 0>{"segment_triangle", "ray_triangle", "signs in double", {}},
    family<triangle3, triangle3, 1>{
        "triangle_triangle", "ray_triangle",
        "signs in double",
        {{{"sat", "separating axes, Akenine-Moeller et al., Real-Time Rendering 4th ed., 22.12",
           [](const triangle3& p, const triangle3& q) { return method::triangle_triangle_sat(p, q); }}}}},
    family<aabb3, segment3, 1>{"aabb_segment", "spheres_boxes", "slab method on [0, 1] (Kay and Kajiya 1986)",
                               {{{"slab", "Kay and Kajiya, SIGGRAPH 1986; Ericson, Real-Time Collision Detection, 5.3.3",
                                  [](const aabb3& b, const segment3& s) { return method::aabb_segment_slab(b, s); }}}}},
    family<aabb3, line3, 1>{"aabb_line", "spheres_boxes", "slab method over all t (Kay and Kajiya 1986)",
                            {{{"slab", "Kay and Kajiya, SIGGRAPH 1986",
                               [](const aabb3& b, const line3& l) { return method::aabb_line_slab(b, l); }}}}},
    family<aabb3, plane3, 0>{"aabb_plane", "spheres_boxes", "signs in double", {}},
    family<plane3, segment3, 0>{"plane_segment", "ray_triangle", "signs in double", {}},
    family<plane3, triangle3, 0>{"plane_triangle", "ray_triangle", "signs in double", {}},
    family<aabb3, triangle3, 1>{
        "aabb_triangle", "ray_triangle",
        "separating axes in double (Akenine-Moeller, JGT 6(1) 2001)",
        {{{"sat", "Akenine-Moeller, Fast 3D triangle-box overlap testing, JGT 6(1), 2001",
           [](const aabb3& b, const triangle3& t) { return method::aabb_triangle_sat(b, t); }}}}},
    family<obb3, point3, 0>{"obb_point", "obb", "signs in double", {}},
    family<aabb3, obb3, 0>{"aabb_obb", "obb", "signs in double", {}},
    family<obb3, obb3, 1>{
        "obb_obb", "obb",
        "signs in double",
        {{{"gottschalk", "Gottschalk, Lin and Manocha, OBBTree, SIGGRAPH 1996; Ericson, Real-Time Collision Detection, 4.4.1",
           [](const obb3& a, const obb3& b) { return method::obb_obb_gottschalk(a, b); }}}}},
    family<obb3, segment3, 0>{"obb_segment", "obb", "signs in double", {}},
    family<obb3, ray3, 0>{"obb_ray", "obb", "signs in double", {}},
    family<line3, obb3, 0>{"line_obb", "obb", "signs in double", {}},
    family<obb3, triangle3, 0>{"obb_triangle", "obb", "signs in double", {}},
    family<obb3, plane3, 0>{"obb_plane", "obb", "signs in double", {}},
    family<segment3, segment3, 0>{"segment_segment", "flat", "signs in double", {}},
    family<line3, line3, 0>{"line_line", "flat", "signs in double", {}},
    family<line3, point3, 0>{"line_point", "flat", "signs in double", {}},
    family<line3, ray3, 0>{"line_ray", "flat", "signs in double", {}},
    family<line3, segment3, 0>{"line_segment", "flat", "signs in double", {}},
    family<point3, point3, 0>{"point_point", "flat", "coordinate comparisons (exact)", {}},
    family<point3, ray3, 0>{"point_ray", "flat", "signs in double", {}},
    family<point3, segment3, 0>{"point_segment", "flat", "signs in double", {}},
    family<ray3, ray3, 0>{"ray_ray", "flat", "signs in double", {}},
    family<ray3, segment3, 0>{"ray_segment", "flat", "signs in double", {}},
    family<line3, triangle3, 0>{"line_triangle", "flat", "signs in double", {}},
    family<point3, triangle3, 0>{"point_triangle", "flat", "signs in double", {}},
    family<plane3, point3, 0>{"plane_point", "flat", "signs in double", {}},
    family<line3, plane3, 0>{"line_plane", "flat", "signs in double", {}},
    family<plane3, ray3, 0>{"plane_ray", "flat", "signs in double", {}},
    family<plane3, plane3, 0>{"plane_plane", "flat", "signs in double", {}},
    family<point3, tetrahedron3, 0>{"point_tetrahedron", "solids", "signs in double", {}},
    family<segment3, tetrahedron3, 0>{"segment_tetrahedron", "solids", "signs in double", {}},
    family<ray3, tetrahedron3, 0>{"ray_tetrahedron", "solids", "signs in double", {}},
    family<line3, tetrahedron3, 0>{"line_tetrahedron", "solids", "signs in double", {}},
    family<plane3, tetrahedron3, 0>{"plane_tetrahedron", "solids", "signs in double", {}},
    family<tetrahedron3, triangle3, 0>{"tetrahedron_triangle", "solids", "signs in double", {}},
    family<tetrahedron3, tetrahedron3, 0>{"tetrahedron_tetrahedron", "solids", "signs in double", {}},
    family<aabb3, tetrahedron3, 0>{"aabb_tetrahedron", "solids", "signs in double", {}},
    family<obb3, tetrahedron3, 0>{"obb_tetrahedron", "solids", "signs in double", {}},
    family<segment2, segment2, 0>{"segment2_segment2", "flat", "signs in double", {}},
    family<line2, line2, 0>{"line2_line2", "flat", "signs in double", {}},
    family<line2, point2, 0>{"line2_point2", "flat", "signs in double", {}},
    family<line2, ray2, 0>{"line2_ray2", "flat", "signs in double", {}},
    family<line2, segment2, 0>{"line2_segment2", "flat", "signs in double", {}},
    family<point2, point2, 0>{"point2_point2", "flat", "coordinate comparisons (exact)", {}},
    family<point2, ray2, 0>{"point2_ray2", "flat", "signs in double", {}},
    family<point2, segment2, 0>{"point2_segment2", "flat", "signs in double", {}},
    family<ray2, ray2, 0>{"ray2_ray2", "flat", "signs in double", {}},
    family<ray2, segment2, 0>{"ray2_segment2", "flat", "signs in double", {}},
    // The k-DOP pairs: one file each for every K = 6, 14, 18, 26 (and any two K for kdop_kdop),
    // listed and audited with K = 14.
    family<kdop<14>, point3, 0>{"kdop_point", "obb", "signs in double", {}},
    family<kdop<14>, segment3, 0>{"kdop_segment", "obb", "signs in double", {}},
    family<kdop<14>, ray3, 0>{"kdop_ray", "obb", "signs in double", {}},
    family<kdop<14>, line3, 0>{"kdop_line", "obb", "signs in double", {}},
    family<kdop<14>, kdop<14>, 0>{"kdop_kdop", "obb", "signs in double", {}},
    family<aabb3, kdop<14>, 0>{"aabb_kdop", "obb", "signs in double", {}},
    // The half-space pairs: the generalised slab test on a convex polyhedron's or a frustum's planes.
    family<convex_polyhedron3, point3, 0>{"convex_polyhedron_point", "obb", "signs in double", {}},
    family<convex_polyhedron3, segment3, 0>{"convex_polyhedron_segment", "obb", "signs in double", {}},
    family<convex_polyhedron3, ray3, 0>{"convex_polyhedron_ray", "obb", "signs in double", {}},
    family<convex_polyhedron3, line3, 0>{"convex_polyhedron_line", "obb", "signs in double", {}},
    family<frustum3, point3, 0>{"frustum_point", "obb", "signs in double", {}},
    family<frustum3, segment3, 0>{"frustum_segment", "obb", "signs in double", {}},
    family<frustum3, ray3, 0>{"frustum_ray", "obb", "signs in double", {}},
    family<frustum3, line3, 0>{"frustum_line", "obb", "signs in double", {}},
    // A box against a half-space set: the vertex test on the set's and the box's planes.
    family<aabb3, convex_polyhedron3, 0>{"aabb_convex_polyhedron", "obb", "signs in double", {}},
    family<aabb3, frustum3, 2>{"aabb_frustum", "obb", "signs in double",
                               {{{"sat", "separating axes in double: Gottschalk, Lin and Manocha, OBBTree, SIGGRAPH 1996",
                                  [](const aabb3& b, const frustum3& f) { return method::aabb_frustum_sat(b, f); }},
                                 {"decomposition", "six tetrahedra in double: Dompierre et al., IMR 1999",
                                  [](const aabb3& b, const frustum3& f) { return method::aabb_frustum_decomposition(b, f); }}}}},
    // A plane against a half-space set: the set's points on both sides (two feasibility tests).
    family<convex_polyhedron3, plane3, 0>{"convex_polyhedron_plane", "obb", "signs in double", {}},
    family<frustum3, plane3, 0>{"frustum_plane", "obb", "signs in double", {}},
    family<kdop<14>, plane3, 0>{"kdop_plane", "obb", "signs in double", {}},
    // Two half-space sets: a face with the other set beyond it, a point inside both, else feasibility.
    family<convex_polyhedron3, convex_polyhedron3, 0>{"convex_polyhedron_convex_polyhedron", "obb", "signs in double", {}},
    family<convex_polyhedron3, frustum3, 0>{"convex_polyhedron_frustum", "obb", "signs in double", {}},
    family<frustum3, frustum3, 0>{"frustum_frustum", "obb", "signs in double", {}},
    // A half-space set against a k-DOP (its K half-spaces): the same test of two sets.
    family<convex_polyhedron3, kdop<14>, 0>{"convex_polyhedron_kdop", "obb", "signs in double", {}},
    family<frustum3, kdop<14>, 0>{"frustum_kdop", "obb", "signs in double", {}},
    // A triangle against a half-space set: its edges, then where the set's edges cross its plane.
    family<convex_polyhedron3, triangle3, 0>{"convex_polyhedron_triangle", "obb", "signs in double", {}},
    family<frustum3, triangle3, 0>{"frustum_triangle", "obb", "signs in double", {}},
    family<kdop<14>, triangle3, 0>{"kdop_triangle", "obb", "signs in double", {}},
    // A tetrahedron against a half-space set: its faces, then a vertex of the set inside it.
    family<convex_polyhedron3, tetrahedron3, 0>{"convex_polyhedron_tetrahedron", "obb", "signs in double", {}},
    family<frustum3, tetrahedron3, 0>{"frustum_tetrahedron", "obb", "signs in double", {}},
    family<kdop<14>, tetrahedron3, 0>{"kdop_tetrahedron", "obb", "signs in double", {}},
    // An OBB against a half-space set: the set in the box's own coordinates, then the vertex test.
    family<convex_polyhedron3, obb3, 0>{"convex_polyhedron_obb", "obb", "signs in double", {}},
    family<frustum3, obb3, 2>{"frustum_obb", "obb", "signs in double",
                              {{{"sat", "separating axes in double: Gottschalk, Lin and Manocha, OBBTree, SIGGRAPH 1996",
                                 [](const frustum3& f, const obb3& b) { return method::frustum_obb_sat(f, b); }},
                                {"decomposition", "six tetrahedra in double: Dompierre et al., IMR 1999",
                                 [](const frustum3& f, const obb3& b) { return method::frustum_obb_decomposition(f, b); }}}}},
    family<kdop<14>, obb3, 0>{"kdop_obb", "obb", "signs in double", {}},
};

inline constexpr std::size_t family_count = std::tuple_size_v<decltype(families)>;

// Calls f(family) for every family, in the order above.
template <class F>
constexpr void for_each_family(F&& f) {
    std::apply([&](const auto&... fam) { (f(fam), ...); }, families);
}

// The pairs of a mesh or a polygon: mesh3 and polygon2 are views of arrays their caller owns, so
// they are listed apart from `families`, whose shapes the audit generates, moves and nudges as
// values; the README table and the catalog test read both lists.
inline constexpr std::tuple view_families{
    family<mesh3, point3, 0>{"mesh_point", "solids", "signs in double", {}},
    family<mesh3, segment3, 0>{"mesh_segment", "solids", "signs in double", {}},
    family<mesh3, ray3, 0>{"mesh_ray", "solids", "signs in double", {}},
    family<line3, mesh3, 0>{"line_mesh", "solids", "signs in double", {}},
    family<mesh3, plane3, 0>{"mesh_plane", "solids", "signs in double", {}},
    family<mesh3, triangle3, 0>{"mesh_triangle", "solids", "signs in double", {}},
    family<mesh3, tetrahedron3, 0>{"mesh_tetrahedron", "solids", "signs in double", {}},
    family<aabb3, mesh3, 0>{"aabb_mesh", "solids", "signs in double", {}},
    family<mesh3, obb3, 0>{"mesh_obb", "solids", "signs in double", {}},
    family<mesh3, mesh3, 0>{"mesh_mesh", "solids", "signs in double", {}},
    family<convex_polyhedron3, mesh3, 0>{"convex_polyhedron_mesh", "solids", "signs in double", {}},
    family<frustum3, mesh3, 0>{"frustum_mesh", "solids", "signs in double", {}},
    family<kdop<14>, mesh3, 0>{"kdop_mesh", "solids", "signs in double", {}},
    family<point2, polygon2, 0>{"point2_polygon2", "flat", "signs in double", {}},
    family<polygon2, segment2, 0>{"polygon2_segment2", "flat", "signs in double", {}},
    family<polygon2, ray2, 0>{"polygon2_ray2", "flat", "signs in double", {}},
    family<line2, polygon2, 0>{"line2_polygon2", "flat", "signs in double", {}},
    family<polygon2, polygon2, 0>{"polygon2_polygon2", "flat", "signs in double", {}},
    family<point3, polygon3, 0>{"point_polygon", "flat", "signs in double", {}},
    family<polygon3, segment3, 0>{"polygon_segment", "flat", "signs in double", {}},
    family<polygon3, ray3, 0>{"polygon_ray", "flat", "signs in double", {}},
    family<line3, polygon3, 0>{"line_polygon", "flat", "signs in double", {}},
    family<plane3, polygon3, 0>{"plane_polygon", "flat", "signs in double", {}},
    family<polygon3, triangle3, 0>{"polygon_triangle", "flat", "signs in double", {}},
    family<polygon3, polygon3, 0>{"polygon_polygon", "flat", "signs in double", {}},
    family<aabb3, polygon3, 0>{"aabb_polygon", "flat", "signs in double", {}},
    family<obb3, polygon3, 0>{"obb_polygon", "flat", "signs in double", {}},
    family<polygon3, tetrahedron3, 0>{"polygon_tetrahedron", "flat", "signs in double", {}},
    family<mesh3, polygon3, 0>{"mesh_polygon", "flat", "signs in double", {}},
    family<convex_polyhedron3, polygon3, 0>{"convex_polyhedron_polygon", "flat", "signs in double", {}},
    family<frustum3, polygon3, 0>{"frustum_polygon", "flat", "signs in double", {}},
    family<kdop<14>, polygon3, 0>{"kdop_polygon", "flat", "signs in double", {}},
};
template <class F>
constexpr void for_each_listed_family(F&& f) {
    for_each_family(f);
    std::apply([&](const auto&... fam) { (f(fam), ...); }, view_families);
}

} // namespace incidence::catalog
