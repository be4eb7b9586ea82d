// The textbook algorithms kept beside the tiers, in plain double, for comparison: the audit charts
// them against the tiers, the benchmarks time them, the tests check their stated margins.
module;
#include <optional>
#include <type_traits>
export module incidence.query:methods;
import incidence.core;
import incidence.arith;
import incidence.shapes;
import incidence.detail;

export namespace incidence {

// Alternative algorithms kept for comparison (the audit charts them against the tiers).
namespace method {
[[nodiscard]] constexpr std::optional<triangle_hit<double>> ray_triangle_watertight(const ray3& r, const triangle3& t) {
    return detail::ray_triangle_watertight(r, t);
}
[[nodiscard]] constexpr std::optional<triangle_hit<double>> ray_triangle_moller_trumbore(const ray3& r, const triangle3& t) {
    return detail::ray_triangle_moller_trumbore(r, t);
}
[[nodiscard]] constexpr std::optional<span_hit<double>> aabb_ray_slab(const aabb3& b, const ray3& r) { return detail::aabb_ray_slab(b, r); }
[[nodiscard]] constexpr bool aabb_ray_woo(const aabb3& b, const ray3& r) { return detail::aabb_ray_woo(b, r); }
[[nodiscard]] constexpr std::optional<span_hit<double>> ray_sphere_geometric(const ray3& r, const sphere3& s) {
    return detail::ray_sphere_geometric(r, s);
}
[[nodiscard]] constexpr std::optional<span_hit<double>> ray_sphere_algebraic(const ray3& r, const sphere3& s) {
    return detail::ray_sphere_algebraic(r, s);
}
[[nodiscard]] constexpr bool aabb_segment_slab(const aabb3& b, const segment3& s) { return detail::aabb_segment_slab(b, s); }
[[nodiscard]] constexpr bool aabb_line_slab(const aabb3& b, const line3& l) { return detail::aabb_line_slab(b, l); }
[[nodiscard]] constexpr bool aabb_triangle_sat(const aabb3& b, const triangle3& t) { return detail::aabb_triangle_sat(b, t); }
[[nodiscard]] constexpr bool triangle_triangle_sat(const triangle3& p, const triangle3& q) { return detail::triangle_triangle_sat(p, q); }
[[nodiscard]] constexpr bool obb_obb_gottschalk(const obb3& a, const obb3& b) { return detail::obb_obb_gottschalk(a, b); }
[[nodiscard]] constexpr bool aabb_frustum_culling(const aabb3& b, const frustum3& f) { return detail::aabb_frustum_culling(b, f); }
[[nodiscard]] constexpr bool aabb_frustum_sat(const aabb3& b, const frustum3& f) { return detail::aabb_frustum_sat(b, f); }
[[nodiscard]] constexpr bool aabb_frustum_decomposition(const aabb3& b, const frustum3& f) {
    return detail::aabb_frustum_decomposition(b, f);
}
[[nodiscard]] constexpr bool obb_sphere_closest_point(const obb3& b, const sphere3& s) { return detail::obb_sphere_closest_point(b, s); }
[[nodiscard]] constexpr bool frustum_sphere_planes(const frustum3& f, const sphere3& s) { return detail::frustum_sphere_planes(f, s); }
[[nodiscard]] constexpr bool frustum_obb_sat(const frustum3& f, const obb3& b) { return detail::frustum_obb_sat(f, b); }
[[nodiscard]] constexpr bool frustum_obb_decomposition(const frustum3& f, const obb3& b) { return detail::frustum_obb_decomposition(f, b); }
} // namespace method

} // namespace incidence
