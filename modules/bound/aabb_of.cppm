// aabb_of: the tightest axis-aligned box of a point set (per-axis min and max, exact: no
// arithmetic), and of a set of boxes. Source: Ericson, Real-Time Collision Detection (2005),
// section 4.2.3 (computing and updating AABBs).
module;
#include <span>
export module incidence.bound:aabb_of;
import incidence.core;
import incidence.shapes;

export namespace incidence::bound {

[[nodiscard]] constexpr result<aabb3> aabb_of(std::span<const point3> points) {
    if (points.empty()) return error{errc::empty_input};
    aabb3 b{points[0], points[0]};
    for (const point3& p : points) {
        if (!is_finite(p)) return error{errc::not_finite};
        b.min = {p.x < b.min.x ? p.x : b.min.x, p.y < b.min.y ? p.y : b.min.y, p.z < b.min.z ? p.z : b.min.z};
        b.max = {p.x > b.max.x ? p.x : b.max.x, p.y > b.max.y ? p.y : b.max.y, p.z > b.max.z ? p.z : b.max.z};
    }
    return b;
}

[[nodiscard]] constexpr result<aabb3> aabb_of(std::span<const aabb3> boxes) {
    if (boxes.empty()) return error{errc::empty_input};
    aabb3 b = boxes[0];
    for (const aabb3& c : boxes) {
        if (!is_finite(c.min) || !is_finite(c.max)) return error{errc::not_finite};
        if (c.min.x > c.max.x || c.min.y > c.max.y || c.min.z > c.max.z) return error{errc::inverted_box};
        b.min = {c.min.x < b.min.x ? c.min.x : b.min.x, c.min.y < b.min.y ? c.min.y : b.min.y, c.min.z < b.min.z ? c.min.z : b.min.z};
        b.max = {c.max.x > b.max.x ? c.max.x : b.max.x, c.max.y > b.max.y ? c.max.y : b.max.y, c.max.z > b.max.z ? c.max.z : b.max.z};
    }
    return b;
}

} // namespace incidence::bound
