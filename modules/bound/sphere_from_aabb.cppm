// Spheres from the bounding box. sphere_from_aabb: centre of the box, radius its half diagonal
// (the box's corners are inside); sphere_from_aabb_farthest: the same centre, radius to the
// farthest input point (the second pass that tightens it). Radii are rounded outward against
// exact tests. Source: Ericson, Real-Time Collision Detection (2005), section 4.3.2.
module;
#include <span>
export module incidence.bound:sphere_from_aabb;
import incidence.core;
import incidence.shapes;
import :outward;
import :aabb_of;

export namespace incidence::bound {

[[nodiscard]] constexpr point3 centre_of(const aabb3& b) {
    return {0.5 * b.min.x + 0.5 * b.max.x, 0.5 * b.min.y + 0.5 * b.max.y, 0.5 * b.min.z + 0.5 * b.max.z};
}

// The ball around the box's centre through its corners (contains the whole box).
[[nodiscard]] constexpr result<sphere3> sphere_from_aabb(const aabb3& b) {
    if (!is_finite(b.min) || !is_finite(b.max)) return error{errc::not_finite};
    if (b.min.x > b.max.x || b.min.y > b.max.y || b.min.z > b.max.z) return error{errc::inverted_box};
    const point3 corners[8] = {b.min,
                               {b.max.x, b.min.y, b.min.z},
                               {b.min.x, b.max.y, b.min.z},
                               {b.max.x, b.max.y, b.min.z},
                               {b.min.x, b.min.y, b.max.z},
                               {b.max.x, b.min.y, b.max.z},
                               {b.min.x, b.max.y, b.max.z},
                               b.max};
    const point3 c = centre_of(b);
    const auto r = enclosing_radius(c, std::span<const point3>(corners));
    if (!r) return r.error();
    return sphere3{c, r.value()};
}

[[nodiscard]] constexpr result<sphere3> sphere_from_aabb(std::span<const point3> points) {
    const auto b = aabb_of(points);
    if (!b) return b.error();
    return sphere_from_aabb(b.value());
}

[[nodiscard]] constexpr result<sphere3> sphere_from_aabb_farthest(std::span<const point3> points) {
    const auto b = aabb_of(points);
    if (!b) return b.error();
    const point3 c = centre_of(b.value());
    const auto r = enclosing_radius(c, points);
    if (!r) return r.error();
    return sphere3{c, r.value()};
}

} // namespace incidence::bound
