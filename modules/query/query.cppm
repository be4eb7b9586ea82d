// incidence.query: the public front door. Each pair is written once, in lexicographic order
// of the shape names, as a kernel-generic body in namespace incidence::pair; the templates
// here give every tier, and serve the reversed argument order by forwarding.
//
//   intersects<Tier>(a, b) -> bool        classify(a, b) -> certainty (filter only)
//   contains<Tier>(a, b)   -> bool        intersection<Tier>(a, b) -> std::optional<hit>
//   squared_distance<Tier>(box, point), max_squared_distance<Tier>(box, point)
//   covers(a, b, c): does a u b contain the box c
// Tier is one of exact (the default), conservative, aggressive, approximate.
//
// Each pair file ends with `extern template` declarations of its body for arith::exact_kernel
// (every K of a k-DOP); the build generates their definitions (exact_instances.cpp, from those
// lines). The filter and the tiers stay inline in the caller; the exact fallback, the largest
// code of a query and rarely run, is compiled once in the library, and a file that imports
// incidence calls it instead of compiling it again (a third of a test file's code). A new pair
// adds its own lines.
module;
#include <optional>
#include <type_traits>
export module incidence.query;
export import :point_sphere;
export import :sphere_sphere;
export import :aabb_point;
export import :aabb_aabb;
export import :ray_sphere;
export import :aabb_ray;
export import :ray_triangle;
export import :segment_triangle;
export import :triangle_triangle;
export import :aabb_triangle;
export import :aabb_segment;
export import :aabb_line;
export import :aabb_plane;
export import :plane_segment;
export import :plane_triangle;
export import :separating_axes; // the engine, exported for its own test (tests/query/separating_axes.cpp)
export import :aabb_obb;
export import :obb_obb;
export import :obb_point;
export import :obb_segment;
export import :obb_ray;
export import :line_obb;
export import :obb_triangle;
export import :obb_plane;
export import :segment_segment;
export import :line_line;
export import :line_point;
export import :line_ray;
export import :line_segment;
export import :point_point;
export import :point_ray;
export import :point_segment;
export import :ray_ray;
export import :ray_segment;
export import :line_triangle;
export import :point_triangle;
export import :plane_point;
export import :line_plane;
export import :plane_ray;
export import :plane_plane;
export import :line2_line2;
export import :line2_point2;
export import :line2_ray2;
export import :line2_segment2;
export import :point2_point2;
export import :point2_ray2;
export import :point2_segment2;
export import :ray2_ray2;
export import :ray2_segment2;
export import :segment2_segment2;
export import :point_tetrahedron;
export import :segment_tetrahedron;
export import :ray_tetrahedron;
export import :line_tetrahedron;
export import :plane_tetrahedron;
export import :tetrahedron_triangle;
export import :tetrahedron_tetrahedron;
export import :aabb_tetrahedron;
export import :obb_tetrahedron;
export import :mesh_point;
export import :mesh_segment;
export import :mesh_ray;
export import :line_mesh;
export import :mesh_plane;
export import :mesh_triangle;
export import :mesh_tetrahedron;
export import :aabb_mesh;
export import :mesh_obb;
export import :mesh_mesh;
export import :point2_polygon2;
export import :polygon2_segment2;
export import :polygon2_ray2;
export import :line2_polygon2;
export import :polygon2_polygon2;
export import :kdop_point;
export import :kdop_segment;
export import :kdop_ray;
export import :kdop_line;
export import :kdop_kdop;
export import :aabb_kdop;
export import :convex_polyhedron_point;
export import :convex_polyhedron_segment;
export import :convex_polyhedron_ray;
export import :convex_polyhedron_line;
export import :frustum_point;
export import :frustum_segment;
export import :frustum_ray;
export import :frustum_line;
export import :aabb_convex_polyhedron;
export import :aabb_frustum;
export import :convex_polyhedron_plane;
export import :frustum_plane;
export import :kdop_plane;
export import :convex_polyhedron_convex_polyhedron;
export import :convex_polyhedron_frustum;
export import :convex_polyhedron_kdop;
export import :frustum_kdop;
export import :frustum_frustum;
export import :convex_polyhedron_triangle;
export import :frustum_triangle;
export import :kdop_triangle;
export import :convex_polyhedron_tetrahedron;
export import :frustum_tetrahedron;
export import :kdop_tetrahedron;
export import :convex_polyhedron_mesh;
export import :frustum_mesh;
export import :kdop_mesh;
export import :convex_polyhedron_obb;
export import :frustum_obb;
export import :kdop_obb;
export import :point_polygon;
export import :polygon_segment;
export import :polygon_ray;
export import :line_polygon;
export import :plane_polygon;
export import :polygon_triangle;
export import :polygon_polygon;
export import :aabb_polygon;
export import :obb_polygon;
export import :polygon_tetrahedron;
export import :mesh_polygon;
export import :convex_polyhedron_polygon;
export import :frustum_polygon;
export import :kdop_polygon;
export import :aabb_sphere;
export import :obb_sphere;
export import :scene_scale;
export import :segment_pieces;
import incidence.core;
import incidence.arith;
import incidence.shapes;

export namespace incidence {

template <class A, class B>
concept canonical_pair = requires(arith::filter_kernel& k, const A& a, const B& b) {
    { pair::intersects(k, a, b) };
};
template <class A, class B>
concept has_pair = canonical_pair<A, B> || canonical_pair<B, A>;

namespace detail {
template <class A, class B>
concept approximate_override = requires(const A& a, const B& b) { pair::intersects_approximate(a, b); };
// A pair whose intersects body reads its shapes through exact comparisons only, never a kernel
// sign (pair::decided_by_comparisons): every kernel gives the exact answer, so every tier runs it
// as the approximate tier does, without the filter pass around it (which cost point_point 1.2 ->
// 1.7 ns: the compiler turned its early exits into a branch-free chain there).
template <class A, class B>
concept by_comparisons = requires { requires pair::decided_by_comparisons(static_cast<const A*>(nullptr), static_cast<const B*>(nullptr)); };

// The tiers that filter (exact, conservative, aggressive) and classify, for one canonical pair:
// body(k, a, b) is the pair's kernel-generic body. When the filter cannot decide, its last
// unproven sign's error bound under- or overflowed (arith::in_trusted_range), and the pair's
// largest length is 2^60 or more, or below 2^-60, the pair is scaled towards scale 1
// (pair::scene::normalized) and filtered again before anything is exact: in a scene near 2^-500
// or 2^500 the filter's range, not the configuration, is what failed. Both filter passes go
// through one call of the body, so it is compiled (and inlined) once. A pair with a view (a mesh,
// a polygon), which is not copied, is filtered again with every input scaled as it is lifted
// (arith::scaled_filter_kernel), through a second instance of the body.
template <class A, class B>
inline constexpr bool scaled_by_inputs =
    !(pair::scene::scalable<A> && pair::scene::scalable<B>) && pair::scene::scannable<A> && pair::scene::scannable<B>;
// In 3D (signs of degree 4 to 6) such a pair that looks far from scale 1 goes to the scaled pass
// at once; in the plane (degree 2 or 3) the filter's own range reaches much further, so there the
// scaled pass only follows a first pass that failed out of range.
template <class A, class B>
inline constexpr bool scaled_first = scaled_by_inputs<A, B> && !pair::scene::shape_of<A, polygon2> && !pair::scene::shape_of<B, polygon2>;
// The pass with every input scaled by 2^-top as it is lifted, top = the exponent of the largest
// input; nullopt when the pair is near scale 1 already (or has a value that is not finite).
// Run time only (arith::lift_scaled_filter).
template <class A, class B, class Body>
[[nodiscard]] constexpr std::optional<certainty> scaled_inputs_pass(const A& a, const B& b, const Body& body) {
    const int top = pair::scene::far_input_exponent(a, b);
    if (top == 0) return std::nullopt;
    arith::scaled_filter_kernel g{arith::power_of_two(-top)};
    const bool r = body(g, a, b);
    return g.failed() ? certainty::uncertain : to_certainty(r);
}
// The filter pass's kernel: for a pair with a mesh3 or a polygon3, the one that settles exact zeros
// as they arise (arith::settling_filter_kernel). Not for polygon2: its signs (degree 2 and 3) are
// cheap to rerun exactly, and settling measured 4% slower there (geometric mean of 12 benchmarks).
template <class S>
inline constexpr bool settles_zeros = pair::scene::shape_of<S, mesh3> || pair::scene::shape_of<S, polygon3>;
template <class A, class B>
using filter_kernel_of = std::conditional_t<settles_zeros<A> || settles_zeros<B>, arith::settling_filter_kernel, arith::filter_kernel>;
template <class A, class B, class Body>
[[nodiscard]] constexpr certainty filter_passes(const A*& a, const B*& b, const Body& body,
                                                std::optional<pair::scene::scaled_pair<A, B>>& scaled) {
    // A pair with a view whose first vertex lies far from scale 1: the scaled pass first, and only
    // (where that glance misleads, the exact tier still decides).
    bool scaled_tried = false;
    if constexpr (scaled_first<A, B>)
        if (!__builtin_is_constant_evaluated() && pair::scene::looks_far(*a, *b)) {
            if (const auto c = scaled_inputs_pass(*a, *b, body)) return *c;
            scaled_tried = true; // near scale 1 after all: the plain pass, and no second scan
        }
    for (;;) {
        filter_kernel_of<A, B> f;
        const bool r = body(f, *a, *b);
        if (!f.failed()) return to_certainty(r);
        if constexpr (pair::scene::scalable<A> && pair::scene::scalable<B>) {
            if (!scaled && !arith::in_trusted_range(f.unproven))
                if (const int top = pair::scene::far_exponent(*a, *b); top != 0 && (scaled = pair::scene::normalized(*a, *b, top))) {
                    a = &scaled->a, b = &scaled->b;
                    continue;
                }
        } else if constexpr (scaled_by_inputs<A, B>) {
            if (!__builtin_is_constant_evaluated() && !scaled_tried && !arith::in_trusted_range(f.unproven))
                if (const auto c = scaled_inputs_pass(*a, *b, body)) return *c;
        }
        return certainty::uncertain;
    }
}
template <class Tier, class A, class B, class Body>
[[nodiscard]] constexpr bool decide_pair(const A& a, const B& b, const Body& body) {
    if constexpr (__is_same(Tier, approximate)) {
        arith::approx_kernel k;
        return body(k, a, b);
    } else {
        const A* pa = &a;
        const B* pb = &b;
        std::optional<pair::scene::scaled_pair<A, B>> scaled;
        const certainty c = filter_passes(pa, pb, body, scaled);
        if (c != certainty::uncertain) return c == certainty::yes;
        if constexpr (__is_same(Tier, conservative)) return true;
        else if constexpr (__is_same(Tier, aggressive)) return false;
        else return arith::decide_exactly([&](auto& k) { return body(k, *pa, *pb); });
    }
}
template <class A, class B, class Body>
[[nodiscard]] constexpr certainty classify_pair(const A& a, const B& b, const Body& body) {
    const A* pa = &a;
    const B* pb = &b;
    std::optional<pair::scene::scaled_pair<A, B>> scaled;
    return filter_passes(pa, pb, body, scaled);
}
struct intersects_body {
    template <class K, class A, class B>
    [[nodiscard]] constexpr bool operator()(K& k, const A& a, const B& b) const { return pair::intersects(k, a, b); }
};
struct contains_body {
    template <class K, class A, class B>
    [[nodiscard]] constexpr bool operator()(K& k, const A& a, const B& b) const { return pair::contains(k, a, b); }
};
} // namespace detail

// Does a meet b? Closed sets: touching counts.
template <tier Tier = exact, class A, class B>
    requires has_pair<A, B>
[[nodiscard]] constexpr bool intersects(const A& a, const B& b) {
    if constexpr (canonical_pair<A, B>) {
        if constexpr (__is_same(Tier, approximate) && detail::approximate_override<A, B>)
            return pair::intersects_approximate(a, b);
        else if constexpr (detail::by_comparisons<A, B>)
            return detail::decide_pair<approximate>(a, b, detail::intersects_body{});
        else
            return detail::decide_pair<Tier>(a, b, detail::intersects_body{});
    } else {
        return intersects<Tier>(b, a);
    }
}

// The floating-point filter's verdict alone: yes, no, or uncertain (never wrong).
template <class A, class B>
    requires has_pair<A, B>
[[nodiscard]] constexpr certainty classify(const A& a, const B& b) {
    if constexpr (canonical_pair<A, B>) {
        return detail::classify_pair(a, b, detail::intersects_body{});
    } else {
        return classify(b, a);
    }
}

// Is b inside a (closed sets)?
template <tier Tier = exact, class A, class B>
    requires requires(arith::filter_kernel& k, const A& a, const B& b) { pair::contains(k, a, b); }
[[nodiscard]] constexpr bool contains(const A& a, const B& b) {
    return detail::decide_pair<Tier>(a, b, detail::contains_body{});
}

template <class A, class B>
    requires requires(arith::filter_kernel& k, const A& a, const B& b) { pair::contains(k, a, b); }
[[nodiscard]] constexpr certainty classify_contains(const A& a, const B& b) {
    return detail::classify_pair(a, b, detail::contains_body{});
}

// Do the boxes a and b together cover the box c completely? Exact (comparisons only).
[[nodiscard]] constexpr bool covers(const aabb3& a, const aabb3& b, const aabb3& c) { return pair::covers(a, b, c); }

// Squared distance from a point to the nearest / farthest point of a box. exact: correctly
// rounded double; approximate: plain double (relative error <= gamma_4); conservative and
// aggressive: an interval that contains the exact value.
template <tier Tier = exact>
[[nodiscard]] constexpr auto squared_distance(const aabb3& b, const point3& p) {
    return pair::squared_distance_impl<Tier>(b, p, pair::distance_kind::nearest);
}
template <tier Tier = exact>
[[nodiscard]] constexpr auto squared_distance(const point3& p, const aabb3& b) { return squared_distance<Tier>(b, p); }
template <tier Tier = exact>
[[nodiscard]] constexpr auto max_squared_distance(const aabb3& b, const point3& p) {
    return pair::squared_distance_impl<Tier>(b, p, pair::distance_kind::farthest);
}
template <tier Tier = exact>
[[nodiscard]] constexpr auto max_squared_distance(const point3& p, const aabb3& b) { return max_squared_distance<Tier>(b, p); }

// --- intersection (find) -------------------------------------------------------------------
// Existence follows the tier's contract; the values of a reported hit are computed exactly
// and correctly rounded for exact, conservative and aggressive, in plain double for approximate.

template <tier Tier = exact>
[[nodiscard]] constexpr std::optional<ray_sphere_hit> intersection(const ray3& r, const sphere3& s) {
    if constexpr (__is_same(Tier, approximate)) return pair::ray_sphere_geometric(r, s);
    else if constexpr (__is_same(Tier, exact)) return pair::ray_sphere_exact(r, s);
    else {
        if (!intersects<Tier>(r, s)) return std::nullopt;
        if (auto h = pair::ray_sphere_exact(r, s)) return h;
        return ray_sphere_hit{0.0, r.origin}; // uncertain and truly missing: nearest candidate
    }
}
template <tier Tier = exact>
[[nodiscard]] constexpr std::optional<ray_sphere_hit> intersection(const sphere3& s, const ray3& r) {
    return intersection<Tier>(r, s);
}

template <tier Tier = exact>
[[nodiscard]] constexpr std::optional<aabb_ray_hit> intersection(const aabb3& b, const ray3& r) {
    if constexpr (__is_same(Tier, approximate)) return pair::aabb_ray_slab(b, r);
    else if constexpr (__is_same(Tier, exact)) return pair::aabb_ray_exact(b, r);
    else {
        if (!intersects<Tier>(b, r)) return std::nullopt;
        if (auto h = pair::aabb_ray_exact(b, r)) return h;
        return aabb_ray_hit{0.0, 0.0};
    }
}
template <tier Tier = exact>
[[nodiscard]] constexpr std::optional<aabb_ray_hit> intersection(const ray3& r, const aabb3& b) {
    return intersection<Tier>(b, r);
}

template <tier Tier = exact>
[[nodiscard]] constexpr std::optional<ray_triangle_hit> intersection(const ray3& r, const triangle3& t) {
    if constexpr (__is_same(Tier, approximate)) return pair::ray_triangle_watertight(r, t);
    else {
        if (!intersects<Tier>(r, t)) return std::nullopt;
        return pair::linear_triangle_values(pair::linear3{r.origin, r.direction, r.origin, pair::extent::ray}, t);
    }
}
template <tier Tier = exact>
[[nodiscard]] constexpr std::optional<ray_triangle_hit> intersection(const triangle3& t, const ray3& r) {
    return intersection<Tier>(r, t);
}

template <tier Tier = exact>
[[nodiscard]] constexpr std::optional<ray_triangle_hit> intersection(const segment3& s, const triangle3& t) {
    if (!intersects<Tier>(s, t)) return std::nullopt;
    const pair::linear3 l{s.a, vec3{0, 0, 0}, s.b, pair::extent::segment};
    if constexpr (__is_same(Tier, approximate)) {
        const auto h = pair::ray_triangle_watertight(ray3{s.a, s.b - s.a}, t);
        if (h && h->t <= 1.0) return h;
        return std::nullopt;
    } else {
        return pair::linear_triangle_values(l, t);
    }
}
template <tier Tier = exact>
[[nodiscard]] constexpr std::optional<ray_triangle_hit> intersection(const triangle3& t, const segment3& s) {
    return intersection<Tier>(s, t);
}

// Alternative algorithms kept for comparison (the audit charts them against the tiers).
namespace method {
[[nodiscard]] constexpr std::optional<ray_triangle_hit> ray_triangle_watertight(const ray3& r, const triangle3& t) {
    return pair::ray_triangle_watertight(r, t);
}
[[nodiscard]] constexpr std::optional<ray_triangle_hit> ray_triangle_moller_trumbore(const ray3& r, const triangle3& t) {
    return pair::ray_triangle_moller_trumbore(r, t);
}
[[nodiscard]] constexpr std::optional<aabb_ray_hit> aabb_ray_slab(const aabb3& b, const ray3& r) {
    return pair::aabb_ray_slab(b, r);
}
[[nodiscard]] constexpr bool aabb_ray_woo(const aabb3& b, const ray3& r) { return pair::aabb_ray_woo(b, r); }
[[nodiscard]] constexpr std::optional<ray_sphere_hit> ray_sphere_geometric(const ray3& r, const sphere3& s) {
    return pair::ray_sphere_geometric(r, s);
}
[[nodiscard]] constexpr std::optional<ray_sphere_hit> ray_sphere_algebraic(const ray3& r, const sphere3& s) {
    return pair::ray_sphere_algebraic(r, s);
}
[[nodiscard]] constexpr bool aabb_segment_slab(const aabb3& b, const segment3& s) { return pair::aabb_segment_slab(b, s); }
[[nodiscard]] constexpr bool aabb_line_slab(const aabb3& b, const line3& l) { return pair::aabb_line_slab(b, l); }
[[nodiscard]] constexpr bool aabb_triangle_sat(const aabb3& b, const triangle3& t) { return pair::aabb_triangle_sat(b, t); }
[[nodiscard]] constexpr bool triangle_triangle_sat(const triangle3& p, const triangle3& q) {
    return pair::triangle_triangle_sat(p, q);
}
[[nodiscard]] constexpr bool obb_obb_gottschalk(const obb3& a, const obb3& b) { return pair::obb_obb_gottschalk(a, b); }
[[nodiscard]] constexpr bool aabb_frustum_culling(const aabb3& b, const frustum3& f) { return pair::aabb_frustum_culling(b, f); }
[[nodiscard]] constexpr bool aabb_frustum_sat(const aabb3& b, const frustum3& f) { return pair::aabb_frustum_sat(b, f); }
[[nodiscard]] constexpr bool aabb_frustum_decomposition(const aabb3& b, const frustum3& f) { return pair::aabb_frustum_decomposition(b, f); }
[[nodiscard]] constexpr bool frustum_obb_sat(const frustum3& f, const obb3& b) { return pair::frustum_obb_sat(f, b); }
[[nodiscard]] constexpr bool frustum_obb_decomposition(const frustum3& f, const obb3& b) { return pair::frustum_obb_decomposition(f, b); }
} // namespace method

} // namespace incidence
