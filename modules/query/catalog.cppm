// incidence.catalog: the one list of the library's pairs (docs/DESIGN.md, "One list"). Every other
// list is generated from it or checked against it in both directions (tests/query/catalog.cpp and
// tools/pair_table: the module units and their exports, the tests, the fuzzers, the benchmarks,
// docs/pairs.md). A family names its canonical argument types, the table whose row is its body
// (modules/query/<table>.cppm), its test, its fuzzer (fuzz/<fuzzer>.cpp), the approximate tier's
// stated margin (tests read it here), the oracle its exact tier is checked against, and the textbook
// algorithms kept beside the four tiers. A new pair is added here once, next to its row.
//   families         intersects, shapes the audit generates as values
//   view_families    intersects with a mesh or a polygon (views of arrays their caller owns)
//   containments     contains(a, b)
//   value_families   intersection(a, b): where a line, a ray or a segment meets a set
//   distances        squared_distance(a, b), signed_distance(a, b)
module;
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string_view>
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
    // A culling test: it may keep a pair that misses (a yes where the answer is no) by design, far
    // from the boundary too; it never drops one that meets. Tests check only its no.
    bool keeps_misses = false;
};

template <class A, class B, std::size_t N>
struct family {
    using first_type = A;
    using second_type = B;
    const char* name;   // the pair, <shape>_<shape> in lexicographic order
    const char* table;  // its body is a row of modules/query/<table>.cppm
    const char* fuzzer; // fuzz/<fuzzer>.cpp runs it against the oracle
    // The approximate tier is wrong only where a deciding sign lies within this fraction of its
    // permanent (the sum of its monomials' magnitudes) of zero, for inputs whose nonzero magnitudes
    // lie in [2^-500, 2^500]; 0: every tier is exact (comparisons alone decide).
    double approximate_bound;
    const char* oracle;             // what the tests check the exact tier against
    const char* approximate_method; // what the approximate tier runs
    std::array<alternative<A, B>, N> alternatives;
};

template <class A, class B>
[[nodiscard]] constexpr bool signs_in_double(const A& a, const B& b) {
    arith::approx_kernel k;
    return detail::intersects(k, a, b);
}

// clang-format off: one row per family, as the table reads
inline constexpr std::tuple families{
    family<point3, sphere3, 0>{"point_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact squared distances over Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<sphere3, sphere3, 0>{"sphere_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact squared distances over Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<aabb3, point3, 0>{"aabb_point", "intersects/box_pairs", "spheres_boxes", 0, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<aabb3, sphere3, 0>{"aabb_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact squared distances over Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    // A ball against half-spaces (engines/ball_halfspaces.cppm): the projection's active set.
    family<convex_polyhedron3, sphere3, 0>{"convex_polyhedron_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, sphere3, 1>{"frustum_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double",
        {{{"plane_culling", "the ball against each plane alone (Akenine-Moeller et al., Real-Time Rendering, 4th ed., chapter 22): keeps balls near the corners that miss",
           [](const frustum3& f, const sphere3& s) { return method::frustum_sphere_planes(f, s); }, true}}}},
    // A capsule (a segment swept by a ball, engines/capsule.cppm): its segment's distance against the radius.
    family<capsule3, point3, 0>{"capsule_point", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, sphere3, 0>{"capsule_sphere", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, capsule3, 0>{"capsule_capsule", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, segment3, 0>{"capsule_segment", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, ray3, 0>{"capsule_ray", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, line3, 0>{"capsule_line", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, plane3, 0>{"capsule_plane", "intersects/capsule_pairs", "spheres_boxes", 0x1p-48, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, triangle3, 0>{"capsule_triangle", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, tetrahedron3, 0>{"capsule_tetrahedron", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<aabb3, capsule3, 0>{"aabb_capsule", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, obb3, 0>{"capsule_obb", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, convex_polyhedron3, 0>{"capsule_convex_polyhedron", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, frustum3, 0>{"capsule_frustum", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<capsule3, kdop<14>, 0>{"capsule_kdop", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance of the cores), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // A ball against a flat shape or a tetrahedron (engines/ball_flat.cppm): the nearest feature.
    family<segment3, sphere3, 0>{"segment_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<line3, sphere3, 0>{"line_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<plane3, sphere3, 0>{"plane_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-48, "exact QP (squared distance), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<sphere3, triangle3, 0>{"sphere_triangle", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<sphere3, tetrahedron3, 0>{"sphere_tetrahedron", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // A ball against a box in its own coordinates (engines/ball_obb.cppm): the projection's active set.
    family<obb3, sphere3, 1>{"obb_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double",
        {{{"closest_point", "the centre clamped along each axis, then |q - c|^2 <= r^2 (Ericson, Real-Time Collision Detection, 5.1.4 and 5.2.5): assumes orthonormal axes",
           [](const obb3& b, const sphere3& s) { return method::obb_sphere_closest_point(b, s); }}}}},
    family<kdop<14>, sphere3, 0>{"kdop_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact QP (squared distance), CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<aabb3, aabb3, 0>{"aabb_aabb", "intersects/box_pairs", "spheres_boxes", 0, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<ray3, sphere3, 2>{"ray_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "exact squared distances over Epeck (testkit/oracle/cgal_oracle.cpp)", "geometric (Akenine-Moeller et al., Real-Time Rendering)",
        {{{"geometric", "Akenine-Moeller et al., Real-Time Rendering, optimized geometric method",
           [](const ray3& r, const sphere3& s) { return method::ray_sphere_geometric(r, s).has_value(); }},
          {"algebraic", "quadratic formula on |o + t d - c|^2 = r^2",
           [](const ray3& r, const sphere3& s) { return method::ray_sphere_algebraic(r, s).has_value(); }}}}},
    family<aabb3, ray3, 2>{"aabb_ray", "intersects/box_pairs", "spheres_boxes", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "slab method (Kay and Kajiya 1986)",
                           {{{"slab", "Kay and Kajiya, SIGGRAPH 1986; Williams et al., JGT 10(1) 2005",
                              [](const aabb3& b, const ray3& r) { return method::aabb_ray_slab(b, r).has_value(); }},
                             {"woo", "Woo, Graphics Gems (1990), Fast ray-box intersection",
                              [](const aabb3& b, const ray3& r) { return method::aabb_ray_woo(b, r); }}}}},
    family<ray3, triangle3, 2>{"ray_triangle", "intersects/triangle_pairs", "ray_triangle", 0x1p-36, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "watertight (Woop, Benthin and Wald 2013)",
        {{{"watertight", "Woop, Benthin and Wald, JCGT 2(1), 2013",
           [](const ray3& r, const triangle3& t) { return method::ray_triangle_watertight(r, t).has_value(); }},
          {"moller_trumbore", "Moeller and Trumbore, JGT 2(1), 1997",
           [](const ray3& r, const triangle3& t) { return method::ray_triangle_moller_trumbore(r, t).has_value(); }}}}},
    family<segment3, triangle3, 0>{"segment_triangle", "intersects/triangle_pairs", "ray_triangle", 0x1p-36, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<triangle3, triangle3, 1>{"triangle_triangle", "intersects/triangle_pairs", "ray_triangle", 0x1p-36, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double",
        {{{"sat", "separating axes, Akenine-Moeller et al., Real-Time Rendering 4th ed., 22.12",
           [](const triangle3& p, const triangle3& q) { return method::triangle_triangle_sat(p, q); }}}}},
    family<aabb3, segment3, 1>{"aabb_segment", "intersects/box_pairs", "spheres_boxes", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "slab method on [0, 1] (Kay and Kajiya 1986)",
                               {{{"slab", "Kay and Kajiya, SIGGRAPH 1986; Ericson, Real-Time Collision Detection, 5.3.3",
                                  [](const aabb3& b, const segment3& s) { return method::aabb_segment_slab(b, s); }}}}},
    family<aabb3, line3, 1>{"aabb_line", "intersects/box_pairs", "spheres_boxes", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "slab method over all t (Kay and Kajiya 1986)",
                            {{{"slab", "Kay and Kajiya, SIGGRAPH 1986",
                               [](const aabb3& b, const line3& l) { return method::aabb_line_slab(b, l); }}}}},
    family<aabb3, plane3, 0>{"aabb_plane", "intersects/plane_pairs", "spheres_boxes", 0x1p-48, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<plane3, segment3, 0>{"plane_segment", "intersects/plane_pairs", "ray_triangle", 0x1p-48, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<plane3, triangle3, 0>{"plane_triangle", "intersects/plane_pairs", "ray_triangle", 0x1p-48, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<aabb3, triangle3, 1>{"aabb_triangle", "intersects/box_pairs", "ray_triangle", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "separating axes in double (Akenine-Moeller, JGT 6(1) 2001)",
        {{{"sat", "Akenine-Moeller, Fast 3D triangle-box overlap testing, JGT 6(1), 2001",
           [](const aabb3& b, const triangle3& t) { return method::aabb_triangle_sat(b, t); }}}}},
    family<obb3, point3, 0>{"obb_point", "intersects/obb_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<aabb3, obb3, 0>{"aabb_obb", "intersects/obb_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<obb3, obb3, 1>{"obb_obb", "intersects/obb_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double",
        {{{"gottschalk", "Gottschalk, Lin and Manocha, OBBTree, SIGGRAPH 1996; Ericson, Real-Time Collision Detection, 4.4.1",
           [](const obb3& a, const obb3& b) { return method::obb_obb_gottschalk(a, b); }}}}},
    family<obb3, segment3, 0>{"obb_segment", "intersects/obb_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<obb3, ray3, 0>{"obb_ray", "intersects/obb_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<line3, obb3, 0>{"line_obb", "intersects/obb_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<obb3, triangle3, 0>{"obb_triangle", "intersects/obb_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<obb3, plane3, 0>{"obb_plane", "intersects/obb_pairs", "obb", 0x1p-48, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<segment3, segment3, 0>{"segment_segment", "intersects/linear_pairs", "flat", 0x1p-40, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<line3, line3, 0>{"line_line", "intersects/linear_pairs", "flat", 0x1p-40, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<line3, point3, 0>{"line_point", "intersects/linear_pairs", "flat", 0x1p-40, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<line3, ray3, 0>{"line_ray", "intersects/linear_pairs", "flat", 0x1p-40, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<line3, segment3, 0>{"line_segment", "intersects/linear_pairs", "flat", 0x1p-40, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<point3, point3, 0>{"point_point", "intersects/linear_pairs", "flat", 0, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "coordinate comparisons (exact)", {}},
    family<point3, ray3, 0>{"point_ray", "intersects/linear_pairs", "flat", 0x1p-40, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<point3, segment3, 0>{"point_segment", "intersects/linear_pairs", "flat", 0x1p-40, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<ray3, ray3, 0>{"ray_ray", "intersects/linear_pairs", "flat", 0x1p-40, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<ray3, segment3, 0>{"ray_segment", "intersects/linear_pairs", "flat", 0x1p-40, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<line3, triangle3, 0>{"line_triangle", "intersects/triangle_pairs", "flat", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<point3, triangle3, 0>{"point_triangle", "intersects/triangle_pairs", "flat", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<plane3, point3, 0>{"plane_point", "intersects/plane_pairs", "flat", 0x1p-48, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<line3, plane3, 0>{"line_plane", "intersects/plane_pairs", "flat", 0x1p-48, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<plane3, ray3, 0>{"plane_ray", "intersects/plane_pairs", "flat", 0x1p-48, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<plane3, plane3, 0>{"plane_plane", "intersects/plane_pairs", "flat", 0x1p-48, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<point3, tetrahedron3, 0>{"point_tetrahedron", "intersects/tetrahedron_pairs", "solids", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<segment3, tetrahedron3, 0>{"segment_tetrahedron", "intersects/tetrahedron_pairs", "solids", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<ray3, tetrahedron3, 0>{"ray_tetrahedron", "intersects/tetrahedron_pairs", "solids", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<line3, tetrahedron3, 0>{"line_tetrahedron", "intersects/tetrahedron_pairs", "solids", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<plane3, tetrahedron3, 0>{"plane_tetrahedron", "intersects/plane_pairs", "solids", 0x1p-48, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<tetrahedron3, triangle3, 0>{"tetrahedron_triangle", "intersects/tetrahedron_pairs", "solids", 0x1p-36, "CGAL Epeck (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<tetrahedron3, tetrahedron3, 0>{"tetrahedron_tetrahedron", "intersects/tetrahedron_pairs", "solids", 0x1p-36, "CGAL Epeck (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<aabb3, tetrahedron3, 0>{"aabb_tetrahedron", "intersects/box_pairs", "solids", 0x1p-40, "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)", "signs in double", {}},
    family<obb3, tetrahedron3, 0>{"obb_tetrahedron", "intersects/obb_pairs", "solids", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // A disk (the closed circle2) against the plane's shapes: the squared distance from the centre (engines/ball_flat.cppm in two coordinates).
    family<circle2, point2, 0>{"circle2_point2", "intersects/circle2_pairs", "flat", 0x1p-44, "CGAL's squared distance over Epeck in the plane z = 0, exact rationals for two disks (testkit/circle2_cases.hpp, cgal_flat.cpp)", "signs in double", {}},
    family<circle2, circle2, 0>{"circle2_circle2", "intersects/circle2_pairs", "flat", 0x1p-44, "CGAL's squared distance over Epeck in the plane z = 0, exact rationals for two disks (testkit/circle2_cases.hpp, cgal_flat.cpp)", "signs in double", {}},
    family<circle2, segment2, 0>{"circle2_segment2", "intersects/circle2_pairs", "flat", 0x1p-44, "CGAL's squared distance over Epeck in the plane z = 0, exact rationals for two disks (testkit/circle2_cases.hpp, cgal_flat.cpp)", "signs in double", {}},
    family<circle2, ray2, 0>{"circle2_ray2", "intersects/circle2_pairs", "flat", 0x1p-44, "CGAL's squared distance over Epeck in the plane z = 0, exact rationals for two disks (testkit/circle2_cases.hpp, cgal_flat.cpp)", "signs in double", {}},
    family<circle2, line2, 0>{"circle2_line2", "intersects/circle2_pairs", "flat", 0x1p-44, "CGAL's squared distance over Epeck in the plane z = 0, exact rationals for two disks (testkit/circle2_cases.hpp, cgal_flat.cpp)", "signs in double", {}},
    family<segment2, segment2, 0>{"segment2_segment2", "intersects/linear_pairs", "flat", 0x1p-48, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<line2, line2, 0>{"line2_line2", "intersects/linear_pairs", "flat", 0x1p-48, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<line2, point2, 0>{"line2_point2", "intersects/linear_pairs", "flat", 0x1p-48, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<line2, ray2, 0>{"line2_ray2", "intersects/linear_pairs", "flat", 0x1p-48, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<line2, segment2, 0>{"line2_segment2", "intersects/linear_pairs", "flat", 0x1p-48, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<point2, point2, 0>{"point2_point2", "intersects/linear_pairs", "flat", 0, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "coordinate comparisons (exact)", {}},
    family<point2, ray2, 0>{"point2_ray2", "intersects/linear_pairs", "flat", 0x1p-48, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<point2, segment2, 0>{"point2_segment2", "intersects/linear_pairs", "flat", 0x1p-48, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<ray2, ray2, 0>{"ray2_ray2", "intersects/linear_pairs", "flat", 0x1p-48, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    family<ray2, segment2, 0>{"ray2_segment2", "intersects/linear_pairs", "flat", 0x1p-48, "CGAL Epeck do_intersect, exact rationals where CGAL errs (testkit/oracle/cgal_flat.cpp)", "signs in double", {}},
    // The k-DOP pairs: one file each for every K = 6, 14, 18, 26 (and any two K for kdop_kdop),
    // listed and audited with K = 14.
    family<kdop<14>, point3, 0>{"kdop_point", "intersects/kdop_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<kdop<14>, segment3, 0>{"kdop_segment", "intersects/kdop_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<kdop<14>, ray3, 0>{"kdop_ray", "intersects/kdop_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<kdop<14>, line3, 0>{"kdop_line", "intersects/kdop_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<kdop<14>, kdop<14>, 0>{"kdop_kdop", "intersects/kdop_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<aabb3, kdop<14>, 0>{"aabb_kdop", "intersects/kdop_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // The half-space pairs: the generalised slab test on a convex polyhedron's or a frustum's planes.
    family<convex_polyhedron3, point3, 0>{"convex_polyhedron_point", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<convex_polyhedron3, segment3, 0>{"convex_polyhedron_segment", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<convex_polyhedron3, ray3, 0>{"convex_polyhedron_ray", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<convex_polyhedron3, line3, 0>{"convex_polyhedron_line", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, point3, 0>{"frustum_point", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, segment3, 0>{"frustum_segment", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, ray3, 0>{"frustum_ray", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, line3, 0>{"frustum_line", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // A box against a half-space set: the vertex test on the set's and the box's planes.
    family<aabb3, convex_polyhedron3, 0>{"aabb_convex_polyhedron", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<aabb3, frustum3, 2>{"aabb_frustum", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double",
                               {{{"sat", "separating axes in double: Gottschalk, Lin and Manocha, OBBTree, SIGGRAPH 1996",
                                  [](const aabb3& b, const frustum3& f) { return method::aabb_frustum_sat(b, f); }},
                                 {"decomposition", "six tetrahedra in double: Dompierre et al., IMR 1999",
                                  [](const aabb3& b, const frustum3& f) { return method::aabb_frustum_decomposition(b, f); }}}}},
    // A plane against a half-space set: the set's points on both sides (two feasibility tests).
    family<convex_polyhedron3, plane3, 0>{"convex_polyhedron_plane", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, plane3, 0>{"frustum_plane", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<kdop<14>, plane3, 0>{"kdop_plane", "intersects/kdop_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // Two half-space sets: a face with the other set beyond it, a point inside both, else feasibility.
    family<convex_polyhedron3, convex_polyhedron3, 0>{"convex_polyhedron_convex_polyhedron", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<convex_polyhedron3, frustum3, 0>{"convex_polyhedron_frustum", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, frustum3, 0>{"frustum_frustum", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // A half-space set against a k-DOP (its K half-spaces): the same test of two sets.
    family<convex_polyhedron3, kdop<14>, 0>{"convex_polyhedron_kdop", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, kdop<14>, 0>{"frustum_kdop", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // A triangle against a half-space set: its edges, then where the set's edges cross its plane.
    family<convex_polyhedron3, triangle3, 0>{"convex_polyhedron_triangle", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, triangle3, 0>{"frustum_triangle", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<kdop<14>, triangle3, 0>{"kdop_triangle", "intersects/kdop_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // A tetrahedron against a half-space set: its faces, then a vertex of the set inside it.
    family<convex_polyhedron3, tetrahedron3, 0>{"convex_polyhedron_tetrahedron", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, tetrahedron3, 0>{"frustum_tetrahedron", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<kdop<14>, tetrahedron3, 0>{"kdop_tetrahedron", "intersects/kdop_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // An OBB against a half-space set: the set in the box's own coordinates, then the vertex test.
    family<convex_polyhedron3, obb3, 0>{"convex_polyhedron_obb", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, obb3, 2>{"frustum_obb", "intersects/halfspace_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double",
                              {{{"sat", "separating axes in double: Gottschalk, Lin and Manocha, OBBTree, SIGGRAPH 1996",
                                 [](const frustum3& f, const obb3& b) { return method::frustum_obb_sat(f, b); }},
                                {"decomposition", "six tetrahedra in double: Dompierre et al., IMR 1999",
                                 [](const frustum3& f, const obb3& b) { return method::frustum_obb_decomposition(f, b); }}}}},
    family<kdop<14>, obb3, 0>{"kdop_obb", "intersects/kdop_pairs", "obb", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
};
// clang-format on

inline constexpr std::size_t family_count = std::tuple_size_v<decltype(families)>;

// Calls f(family) for every family, in the order above.
template <class F>
constexpr void for_each_family(F&& f) {
    std::apply([&](const auto&... fam) { (f(fam), ...); }, families);
}

// The pairs of a mesh or a polygon: mesh3 and polygon2 are views of arrays their caller owns, so
// they are listed apart from `families`, whose shapes the audit generates, moves and nudges as
// values; the README table and the catalog test read both lists.
// clang-format off: one row per family, as the table reads
inline constexpr std::tuple view_families{
    family<mesh3, point3, 0>{"mesh_point", "intersects/mesh_pairs", "solids", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    family<mesh3, segment3, 0>{"mesh_segment", "intersects/mesh_pairs", "solids", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    family<mesh3, ray3, 0>{"mesh_ray", "intersects/mesh_pairs", "solids", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    family<line3, mesh3, 0>{"line_mesh", "intersects/mesh_pairs", "solids", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    family<mesh3, plane3, 0>{"mesh_plane", "intersects/mesh_pairs", "solids", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    family<mesh3, triangle3, 0>{"mesh_triangle", "intersects/mesh_pairs", "solids", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    family<mesh3, tetrahedron3, 0>{"mesh_tetrahedron", "intersects/mesh_pairs", "solids", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    family<aabb3, mesh3, 0>{"aabb_mesh", "intersects/mesh_pairs", "solids", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    family<mesh3, obb3, 0>{"mesh_obb", "intersects/mesh_pairs", "solids", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    family<mesh3, mesh3, 0>{"mesh_mesh", "intersects/mesh_pairs", "solids", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    // A ball or a capsule against a solid mesh: a triangle within reach, or the centre (an end) inside.
    family<mesh3, sphere3, 0>{"mesh_sphere", "intersects/mesh_pairs", "spheres_boxes", 0x1p-36, "triangles by CGAL's squared distance over Epeck, the centre inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp, cgal_flat.cpp)", "signs in double", {}},
    family<capsule3, mesh3, 0>{"capsule_mesh", "intersects/capsule_pairs", "spheres_boxes", 0x1p-36, "triangles by the exact QP of the segment (CGAL QP_solver over Gmpzf), the end inside by exact crossing parity (testkit/oracle/cgal_lp.cpp, cgal_mesh.cpp)", "signs in double", {}},
    family<convex_polyhedron3, mesh3, 0>{"convex_polyhedron_mesh", "intersects/halfspace_pairs", "solids", 0x1p-36, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, mesh3, 0>{"frustum_mesh", "intersects/halfspace_pairs", "solids", 0x1p-36, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<kdop<14>, mesh3, 0>{"kdop_mesh", "intersects/kdop_pairs", "solids", 0x1p-36, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    // A disk against a polygon: an edge within reach, or the centre inside (engines/polygon2.cppm).
    family<circle2, polygon2, 0>{"circle2_polygon2", "intersects/circle2_pairs", "flat", 0x1p-44, "CGAL Polygon_2 bounded side over Epeck for the centre, each edge by CGAL's squared distance over Epeck (testkit/circle2_cases.hpp, cgal_polygon.cpp, cgal_flat.cpp)", "signs in double", {}},
    family<point2, polygon2, 0>{"point2_polygon2", "intersects/polygon2_pairs", "flat", 0x1p-44, "CGAL Polygon_2 bounded side over Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<polygon2, segment2, 0>{"polygon2_segment2", "intersects/polygon2_pairs", "flat", 0x1p-44, "CGAL Polygon_2 bounded side over Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<polygon2, ray2, 0>{"polygon2_ray2", "intersects/polygon2_pairs", "flat", 0x1p-44, "CGAL Polygon_2 bounded side over Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<line2, polygon2, 0>{"line2_polygon2", "intersects/polygon2_pairs", "flat", 0x1p-44, "CGAL Polygon_2 bounded side over Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<polygon2, polygon2, 0>{"polygon2_polygon2", "intersects/polygon2_pairs", "flat", 0x1p-44, "CGAL Polygon_2 bounded side over Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<point3, polygon3, 0>{"point_polygon", "intersects/polygon_pairs", "flat", 0x1p-40, "CGAL constrained triangulation and Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<polygon3, segment3, 0>{"polygon_segment", "intersects/polygon_pairs", "flat", 0x1p-40, "CGAL constrained triangulation and Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<polygon3, ray3, 0>{"polygon_ray", "intersects/polygon_pairs", "flat", 0x1p-40, "CGAL constrained triangulation and Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<line3, polygon3, 0>{"line_polygon", "intersects/polygon_pairs", "flat", 0x1p-40, "CGAL constrained triangulation and Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<plane3, polygon3, 0>{"plane_polygon", "intersects/polygon_pairs", "flat", 0x1p-40, "CGAL constrained triangulation and Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<polygon3, triangle3, 0>{"polygon_triangle", "intersects/polygon_pairs", "flat", 0x1p-40, "CGAL constrained triangulation and Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<polygon3, polygon3, 0>{"polygon_polygon", "intersects/polygon_pairs", "flat", 0x1p-40, "CGAL constrained triangulation and Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<aabb3, polygon3, 0>{"aabb_polygon", "intersects/polygon_pairs", "flat", 0x1p-40, "CGAL constrained triangulation and Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<obb3, polygon3, 0>{"obb_polygon", "intersects/polygon_pairs", "flat", 0x1p-40, "CGAL constrained triangulation and Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    family<polygon3, tetrahedron3, 0>{"polygon_tetrahedron", "intersects/polygon_pairs", "flat", 0x1p-40, "CGAL constrained triangulation and Epeck (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    // A ball or a capsule against a polygon: the plane, the foot inside, the edges.
    family<polygon3, sphere3, 0>{"polygon_sphere", "intersects/sphere_pairs", "spheres_boxes", 0x1p-40, "CGAL constrained triangulation, each triangle by CGAL's squared distance over Epeck (testkit/oracle/cgal_polygon.cpp, cgal_flat.cpp)", "signs in double", {}},
    family<capsule3, polygon3, 0>{"capsule_polygon", "intersects/capsule_pairs", "spheres_boxes", 0x1p-40, "CGAL constrained triangulation, each triangle by the exact QP of the segment, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_polygon.cpp, cgal_lp.cpp)", "signs in double", {}},
    family<mesh3, polygon3, 0>{"mesh_polygon", "intersects/mesh_pairs", "flat", 0x1p-36, "triangles by CGAL Epeck, inside by exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    family<convex_polyhedron3, polygon3, 0>{"convex_polyhedron_polygon", "intersects/halfspace_pairs", "flat", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<frustum3, polygon3, 0>{"frustum_polygon", "intersects/halfspace_pairs", "flat", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
    family<kdop<14>, polygon3, 0>{"kdop_polygon", "intersects/kdop_pairs", "flat", 0x1p-40, "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)", "signs in double", {}},
};
// clang-format on
template <class F>
constexpr void for_each_listed_family(F&& f) {
    for_each_family(f);
    std::apply([&](const auto&... fam) { (f(fam), ...); }, view_families);
}

// contains(a, b): is b inside a (closed sets)? Its test is the pair's test,
// tests/query/intersects/<name>.cpp.
template <class A, class B>
using containment = family<A, B, 0>;
inline constexpr const char* lp = "exact LP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_lp.cpp)";
inline constexpr const char* epeck = "CGAL Epeck (testkit/oracle/cgal_oracle.cpp)";
inline constexpr const char* corners_rational = "the box's corners in rationals against the segment (testkit/oracle/cgal_oracle.cpp)";
inline constexpr const char* rows_rational = "the ball in each half-space, in rationals (testkit/oracle/cgal_lp.cpp)";
// clang-format off: one row per family, as the table reads
inline constexpr std::tuple containments{
    containment<aabb3, aabb3>{"aabb_aabb", "contains/box_pairs", "spheres_boxes", 0, epeck, "comparisons (exact)", {}},
    containment<aabb3, point3>{"aabb_point", "contains/box_pairs", "spheres_boxes", 0, epeck, "comparisons (exact)", {}},
    containment<aabb3, segment3>{"aabb_segment", "contains/box_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<aabb3, triangle3>{"aabb_triangle", "contains/box_pairs", "ray_triangle", 0x1p-40, epeck, "signs in double", {}},
    containment<aabb3, tetrahedron3>{"aabb_tetrahedron", "contains/box_pairs", "solids", 0x1p-40, epeck, "signs in double", {}},
    containment<aabb3, sphere3>{"aabb_sphere", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<sphere3, aabb3>{"aabb_sphere", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<aabb3, obb3>{"aabb_obb", "contains/obb_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<obb3, aabb3>{"aabb_obb", "contains/obb_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<obb3, obb3>{"obb_obb", "contains/obb_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<obb3, point3>{"obb_point", "contains/obb_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<obb3, segment3>{"obb_segment", "contains/obb_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<obb3, triangle3>{"obb_triangle", "contains/obb_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<obb3, tetrahedron3>{"obb_tetrahedron", "contains/obb_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<obb3, sphere3>{"obb_sphere", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, lp, "signs in double", {}},
    containment<sphere3, obb3>{"obb_sphere", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, lp, "signs in double", {}},
    containment<sphere3, point3>{"point_sphere", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<sphere3, sphere3>{"sphere_sphere", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<sphere3, segment3>{"segment_sphere", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<sphere3, triangle3>{"sphere_triangle", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<sphere3, tetrahedron3>{"sphere_tetrahedron", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<capsule3, point3>{"capsule_point", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<capsule3, segment3>{"capsule_segment", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<capsule3, triangle3>{"capsule_triangle", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<capsule3, tetrahedron3>{"capsule_tetrahedron", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<capsule3, aabb3>{"aabb_capsule", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<aabb3, capsule3>{"aabb_capsule", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<obb3, capsule3>{"capsule_obb", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, lp, "signs in double", {}},
    containment<capsule3, obb3>{"capsule_obb", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, corners_rational, "signs in double", {}},
    containment<capsule3, sphere3>{"capsule_sphere", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<sphere3, capsule3>{"capsule_sphere", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<capsule3, capsule3>{"capsule_capsule", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, epeck, "signs in double", {}},
    containment<convex_polyhedron3, capsule3>{"capsule_convex_polyhedron", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, rows_rational, "signs in double", {}},
    containment<frustum3, capsule3>{"capsule_frustum", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, rows_rational, "signs in double", {}},
    containment<kdop<14>, capsule3>{"capsule_kdop", "contains/capsule_pairs", "spheres_boxes", 0x1p-40, rows_rational, "signs in double", {}},
    containment<convex_polyhedron3, sphere3>{"convex_polyhedron_sphere", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, rows_rational, "signs in double", {}},
    containment<frustum3, sphere3>{"frustum_sphere", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, rows_rational, "signs in double", {}},
    containment<kdop<14>, sphere3>{"kdop_sphere", "contains/sphere_pairs", "spheres_boxes", 0x1p-40, rows_rational, "signs in double", {}},
    containment<tetrahedron3, point3>{"point_tetrahedron", "contains/tetrahedron_pairs", "solids", 0x1p-40, epeck, "signs in double", {}},
    containment<tetrahedron3, segment3>{"segment_tetrahedron", "contains/tetrahedron_pairs", "solids", 0x1p-40, epeck, "signs in double", {}},
    containment<tetrahedron3, triangle3>{"tetrahedron_triangle", "contains/tetrahedron_pairs", "solids", 0x1p-40, epeck, "signs in double", {}},
    containment<tetrahedron3, tetrahedron3>{"tetrahedron_tetrahedron", "contains/tetrahedron_pairs", "solids", 0x1p-40, epeck, "signs in double", {}},
    containment<tetrahedron3, aabb3>{"aabb_tetrahedron", "contains/box_pairs", "solids", 0x1p-40, epeck, "signs in double", {}},
    containment<tetrahedron3, obb3>{"obb_tetrahedron", "contains/obb_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<kdop<14>, point3>{"kdop_point", "contains/kdop_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<kdop<14>, segment3>{"kdop_segment", "contains/kdop_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<kdop<14>, aabb3>{"aabb_kdop", "contains/kdop_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<kdop<14>, triangle3>{"kdop_triangle", "contains/kdop_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<kdop<14>, tetrahedron3>{"kdop_tetrahedron", "contains/kdop_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<kdop<14>, obb3>{"kdop_obb", "contains/kdop_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<convex_polyhedron3, point3>{"convex_polyhedron_point", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<convex_polyhedron3, segment3>{"convex_polyhedron_segment", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<convex_polyhedron3, triangle3>{"convex_polyhedron_triangle", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<convex_polyhedron3, tetrahedron3>{"convex_polyhedron_tetrahedron", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<convex_polyhedron3, aabb3>{"aabb_convex_polyhedron", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<convex_polyhedron3, obb3>{"convex_polyhedron_obb", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<frustum3, point3>{"frustum_point", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<frustum3, segment3>{"frustum_segment", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<frustum3, triangle3>{"frustum_triangle", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<frustum3, tetrahedron3>{"frustum_tetrahedron", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<frustum3, aabb3>{"aabb_frustum", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<frustum3, obb3>{"frustum_obb", "contains/halfspace_pairs", "obb", 0x1p-40, lp, "signs in double", {}},
    containment<mesh3, point3>{"mesh_point", "contains/mesh_pairs", "solids", 0x1p-36, "exact crossing parity (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    containment<mesh3, segment3>{"mesh_segment", "contains/mesh_pairs", "solids", 0x1p-36, "exact breakpoints (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    containment<mesh3, triangle3>{"mesh_triangle", "contains/mesh_pairs", "solids", 0x1p-36, "traces and chords (testkit/oracle/cgal_mesh.cpp)", "signs in double", {}},
    containment<mesh3, aabb3>{"aabb_mesh", "contains/mesh_pairs", "solids", 0x1p-36, "odd coverage of the box's planes (testkit/oracle/cgal_mesh_box.cpp)", "signs in double", {}},
    containment<circle2, point2>{"circle2_point2", "contains/circle2_pairs", "flat", 0x1p-44, "each vertex by exact rationals, two disks by the difference of the radii (testkit/circle2_cases.hpp, cgal_oracle.cpp)", "signs in double", {}},
    containment<circle2, segment2>{"circle2_segment2", "contains/circle2_pairs", "flat", 0x1p-44, "each vertex by exact rationals, two disks by the difference of the radii (testkit/circle2_cases.hpp, cgal_oracle.cpp)", "signs in double", {}},
    containment<circle2, circle2>{"circle2_circle2", "contains/circle2_pairs", "flat", 0x1p-44, "each vertex by exact rationals, two disks by the difference of the radii (testkit/circle2_cases.hpp, cgal_oracle.cpp)", "signs in double", {}},
    containment<circle2, polygon2>{"circle2_polygon2", "contains/circle2_pairs", "flat", 0x1p-44, "each vertex by exact rationals, two disks by the difference of the radii (testkit/circle2_cases.hpp, cgal_oracle.cpp)", "signs in double", {}},
    containment<polygon2, circle2>{"circle2_polygon2", "contains/circle2_pairs", "flat", 0x1p-44, "the centre by CGAL Polygon_2 over Epeck, no edge strictly within the radius by CGAL's squared distance over Epeck (testkit/circle2_cases.hpp, cgal_polygon.cpp, cgal_flat.cpp)", "signs in double", {}},
    containment<polygon2, point2>{"point2_polygon2", "contains/polygon2_pairs", "flat", 0x1p-40, "CGAL Polygon_2 (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    containment<polygon2, segment2>{"polygon2_segment2", "contains/polygon2_pairs", "flat", 0x1p-40, "exact breakpoints (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    containment<polygon3, point3>{"point_polygon", "contains/polygon_pairs", "flat", 0x1p-40, "CGAL triangulation (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    containment<polygon3, segment3>{"polygon_segment", "contains/polygon_pairs", "flat", 0x1p-40, "CGAL triangulation (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
    containment<polygon3, triangle3>{"polygon_triangle", "contains/polygon_pairs", "flat", 0x1p-40, "CGAL triangulation (testkit/oracle/cgal_polygon.cpp)", "signs in double", {}},
};
// clang-format on

// intersection(a, b): where a line, a ray or a segment meets a set. One table, one test
// (tests/query/intersection/linear_pairs.cpp) for all; the approximate tier's stated bound is the
// conservative tier's interval (modules/query/intersection/linear_pairs.cppm), not a margin: 0 here.
template <class A, class B>
using value_family = family<A, B, 0>;
inline constexpr const char* values_oracle = "exact values over CGAL Epeck (testkit/oracle/cgal_values.cpp)";
inline constexpr const char* clip = "the same clip in double";
inline constexpr const char* contact = "the same contact in double";
// clang-format off: one row per family, as the table reads
inline constexpr std::tuple value_families{
    value_family<aabb3, ray3>{"aabb_ray", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<aabb3, segment3>{"aabb_segment", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<aabb3, line3>{"aabb_line", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<plane3, ray3>{"plane_ray", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<plane3, segment3>{"plane_segment", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<plane3, line3>{"line_plane", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<obb3, ray3>{"obb_ray", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<obb3, segment3>{"obb_segment", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<obb3, line3>{"line_obb", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<kdop<14>, ray3>{"kdop_ray", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<kdop<14>, segment3>{"kdop_segment", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<kdop<14>, line3>{"kdop_line", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<convex_polyhedron3, ray3>{"convex_polyhedron_ray", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<convex_polyhedron3, segment3>{"convex_polyhedron_segment", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<convex_polyhedron3, line3>{"convex_polyhedron_line", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<frustum3, ray3>{"frustum_ray", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<frustum3, segment3>{"frustum_segment", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<frustum3, line3>{"frustum_line", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<tetrahedron3, ray3>{"ray_tetrahedron", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<tetrahedron3, segment3>{"segment_tetrahedron", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<tetrahedron3, line3>{"line_tetrahedron", "intersection/linear_pairs", "values", 0, values_oracle, clip, {}},
    value_family<sphere3, ray3>{"ray_sphere", "intersection/linear_pairs", "values", 0, values_oracle, "the same roots in double", {}},
    value_family<sphere3, segment3>{"segment_sphere", "intersection/linear_pairs", "values", 0, values_oracle, "the same roots in double", {}},
    value_family<sphere3, line3>{"line_sphere", "intersection/linear_pairs", "values", 0, values_oracle, "the same roots in double", {}},
    value_family<triangle3, ray3>{"ray_triangle", "intersection/linear_pairs", "values", 0, values_oracle, contact, {}},
    value_family<triangle3, segment3>{"segment_triangle", "intersection/linear_pairs", "values", 0, values_oracle, contact, {}},
    value_family<triangle3, line3>{"line_triangle", "intersection/linear_pairs", "values", 0, values_oracle, contact, {}},
    value_family<polygon3, ray3>{"polygon_ray", "intersection/linear_pairs", "values", 0, values_oracle, contact, {}},
    value_family<polygon3, segment3>{"polygon_segment", "intersection/linear_pairs", "values", 0, values_oracle, contact, {}},
    value_family<polygon3, line3>{"line_polygon", "intersection/linear_pairs", "values", 0, values_oracle, contact, {}},
    value_family<mesh3, ray3>{"mesh_ray", "intersection/linear_pairs", "values", 0, values_oracle, contact, {}},
    value_family<mesh3, segment3>{"mesh_segment", "intersection/linear_pairs", "values", 0, values_oracle, contact, {}},
    value_family<mesh3, line3>{"line_mesh", "intersection/linear_pairs", "values", 0, values_oracle, contact, {}},
};
// clang-format on

// squared_distance(a, b) and signed_distance(a, b) of a point and a solid (and the box's
// max_squared_distance); squared_distance(a, b) and distance(a, b) of two points, segments, rays,
// lines or triangles (their bound: 2^-30 M^2 where no deciding sign lies within 2^-20 of its
// permanent, modules/query/distance/linear_pairs.cppm and triangle_pairs.cppm). The approximate tier's stated bound: for aabb_point gamma_5 relative on the
// squared distance (modules/query/distance/box_point.cppm), 0 here; for the others, where no deciding
// sign lies within 2^-40 of its permanent, |d~ - d| <= bound M + 2^-140 for the signed distance and
// bound M^2 + 2^-280 for the squared one, M the largest magnitude among the inputs' numbers, inputs
// in [2^-120, 2^120] (each table's head, testkit/distance_checks.hpp).
// clang-format off: one row per family, as the table reads
inline constexpr std::tuple distances{
    family<aabb3, point3, 0>{"aabb_point", "distance/box_point", "spheres_boxes", 0, "exact squared distances over Epeck (testkit/oracle/cgal_oracle.cpp); signed: exact QP and rows (testkit/oracle/cgal_distance.cpp)", "the same sum in double", {}},
    family<obb3, point3, 0>{"obb_point", "distance/box_point", "spheres_boxes", 0x1p-40, "exact QP outside, faces in rationals inside (testkit/oracle/cgal_distance.cpp)", "the same active set and roots in double", {}},
    family<point3, sphere3, 0>{"point_sphere", "distance/ball_point", "spheres_boxes", 0x1p-40, "exact squared distance of the centre over Epeck (testkit/oracle/cgal_distance.cpp)", "the same feature, sqrt(P / S) - r in double", {}},
    family<capsule3, point3, 0>{"capsule_point", "distance/ball_point", "spheres_boxes", 0x1p-40, "exact squared distance of the segment over Epeck (testkit/oracle/cgal_distance.cpp)", "the same feature, sqrt(P / S) - r in double", {}},
    family<convex_polyhedron3, point3, 0>{"convex_polyhedron_point", "distance/halfspace_point", "spheres_boxes", 0x1p-40, "exact QP outside, rows in rationals inside (testkit/oracle/cgal_distance.cpp)", "the same active set and roots in double", {}},
    family<frustum3, point3, 0>{"frustum_point", "distance/halfspace_point", "spheres_boxes", 0x1p-40, "exact QP outside, rows in rationals inside (testkit/oracle/cgal_distance.cpp)", "the same active set and roots in double", {}},
    family<kdop<14>, point3, 0>{"kdop_point", "distance/halfspace_point", "spheres_boxes", 0x1p-40, "exact QP outside, rows in rationals inside (testkit/oracle/cgal_distance.cpp)", "the same active set and roots in double", {}},
    family<point3, tetrahedron3, 0>{"point_tetrahedron", "distance/triangles_point", "spheres_boxes", 0x1p-40, "exact QP outside, faces in rationals inside (testkit/oracle/cgal_distance.cpp)", "the same region walk and roots in double", {}},
    family<mesh3, point3, 0>{"mesh_point", "distance/triangles_point", "spheres_boxes", 0x1p-40, "point-triangle distances over Epeck, crossing parity (testkit/oracle/cgal_distance.cpp)", "the same region walk and roots in double", {}},
    family<line3, line3, 0>{"line_line", "distance/linear_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same candidates and quotients in double", {}},
    family<line3, point3, 0>{"line_point", "distance/linear_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same candidates and quotients in double", {}},
    family<line3, ray3, 0>{"line_ray", "distance/linear_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same candidates and quotients in double", {}},
    family<line3, segment3, 0>{"line_segment", "distance/linear_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same candidates and quotients in double", {}},
    family<point3, point3, 0>{"point_point", "distance/linear_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same candidates and quotients in double", {}},
    family<point3, ray3, 0>{"point_ray", "distance/linear_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same candidates and quotients in double", {}},
    family<point3, segment3, 0>{"point_segment", "distance/linear_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same candidates and quotients in double", {}},
    family<ray3, ray3, 0>{"ray_ray", "distance/linear_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same candidates and quotients in double", {}},
    family<ray3, segment3, 0>{"ray_segment", "distance/linear_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same candidates and quotients in double", {}},
    family<segment3, segment3, 0>{"segment_segment", "distance/linear_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same candidates and quotients in double", {}},
    family<line3, triangle3, 0>{"line_triangle", "distance/triangle_pairs", "values", 0x1p-30, "exact QP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_distance.cpp)", "the same walk, candidates and quotients in double", {}},
    family<point3, triangle3, 0>{"point_triangle", "distance/triangle_pairs", "values", 0x1p-30, "CGAL squared_distance over Epeck (testkit/oracle/cgal_distance.cpp)", "the same walk, candidates and quotients in double", {}},
    family<ray3, triangle3, 0>{"ray_triangle", "distance/triangle_pairs", "values", 0x1p-30, "exact QP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_distance.cpp)", "the same walk, candidates and quotients in double", {}},
    family<segment3, triangle3, 0>{"segment_triangle", "distance/triangle_pairs", "values", 0x1p-30, "exact QP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_distance.cpp)", "the same walk, candidates and quotients in double", {}},
    family<triangle3, triangle3, 0>{"triangle_triangle", "distance/triangle_pairs", "values", 0x1p-30, "exact QP, CGAL QP_solver over Gmpzf (testkit/oracle/cgal_distance.cpp)", "the same walk, candidates and quotients in double", {}},
};
// clang-format on

// The approximate tier's stated margin of the yes/no pair `name` (tests read it here).
[[nodiscard]] constexpr double approximate_bound(std::string_view name) {
    double b = -1.0;
    auto look = [&](const auto& f) {
        if (std::string_view(f.name) == name) b = f.approximate_bound;
    };
    std::apply([&](const auto&... f) { (look(f), ...); }, families);
    std::apply([&](const auto&... f) { (look(f), ...); }, view_families);
    std::apply([&](const auto&... f) { (look(f), ...); }, containments);
    if (b < 0.0) throw std::invalid_argument("no such pair in the catalog");
    return b;
}

// Calls f(family) for every family of each list.
template <class F>
constexpr void for_each_containment(F&& f) {
    std::apply([&](const auto&... fam) { (f(fam), ...); }, containments);
}
template <class F>
constexpr void for_each_value_family(F&& f) {
    std::apply([&](const auto&... fam) { (f(fam), ...); }, value_families);
}
template <class F>
constexpr void for_each_distance(F&& f) {
    std::apply([&](const auto&... fam) { (f(fam), ...); }, distances);
}

} // namespace incidence::catalog
